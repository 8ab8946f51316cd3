// geomcheck — the Delaunay construction of delaunay_2d.hpp, generic in its
// predicates (production instantiates it with the exact ones; the tests'
// teeth with plain doubles, to show what the exact ones are for).
//
// Predicates: a type with static `int orient(Vec2 a, Vec2 b, Vec2 c)` and
// `int incircle(Vec2 a, Vec2 b, Vec2 c, Vec2 d)`, signs as in predicates2d.hpp.
//
// Storage: triangle t has corners 3t, 3t+1, 3t+2; V_[c] is the vertex of
// corner c (kInf for the vertex at infinity), A_[c] the corner of the
// neighbouring triangle opposite the same edge. The edge opposite corner
// 3t+i runs from V_[3t+(i+1)%3] to V_[3t+(i+2)%3], with the triangle on its
// left. A ghost triangle (x, y, inf) closes hull edge y->x: the
// triangulation lies to the right of x->y. V_ and A_ are the data of two
// vectors of index triples shaped like the output's, 24 bytes a triangle
// in all: at the end the ghosts are compacted away in place and the two
// vectors are moved into the output. Peak heap at 10^6 points: the points
// in insertion order (16 MB), the triangles (48 MB), the input index of
// each vertex and vertex_of (4 + 4 MB); the sort before (2 x 32 MB of
// records) is freed first.
#pragma once

#include <algorithm>
#include <array>
#include <limits>
#include <cmath>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "geomcheck/delaunay_2d.hpp"

namespace geomcheck::detail {

/// Position of (x, y) along the Hilbert curve of order 32. The curve's
/// state (swap x and y, invert both) evolves bit by bit; a table advances it
/// four bits of each coordinate at a time.
inline std::uint64_t hilbert_index(std::uint32_t x, std::uint32_t y) {
  struct Table {
    std::uint8_t digits[4][256];  // 8 bits of index for state s, 4 bits of x (high nibble), 4 of y
    std::uint8_t state[4][256];
    Table() {
      for (unsigned s0 = 0; s0 < 4; ++s0)
        for (unsigned xy = 0; xy < 256; ++xy) {
          unsigned s = s0, d = 0;
          for (int b = 3; b >= 0; --b) {
            const unsigned swap = s & 1, inv = (s >> 1) & 1;
            const unsigned ox = (xy >> (4 + b)) & 1, oy = (xy >> b) & 1;
            const unsigned rx = (swap ? oy : ox) ^ inv, ry = (swap ? ox : oy) ^ inv;
            d = (d << 2) | ((3 * rx) ^ ry);
            if (ry == 0) s = (s ^ 1) ^ (rx ? 2u : 0u);
          }
          digits[s0][xy] = static_cast<std::uint8_t>(d);
          state[s0][xy] = static_cast<std::uint8_t>(s);
        }
    }
  };
  static const Table table;
  std::uint64_t d = 0;
  unsigned s = 0;
  for (int shift = 28; shift >= 0; shift -= 4) {
    const unsigned xy = (((x >> shift) & 15u) << 4) | ((y >> shift) & 15u);
    d = (d << 8) | table.digits[s][xy];
    s = table.state[s][xy];
  }
  return d;
}

/// The same, one bit at a time (the definition; tests compare the two).
inline std::uint64_t hilbert_index_reference(std::uint32_t x, std::uint32_t y) {
  std::uint64_t d = 0;
  for (std::uint32_t s = 1u << 31; s > 0; s >>= 1) {
    const std::uint32_t rx = (x & s) ? 1u : 0u, ry = (y & s) ? 1u : 0u;
    d += static_cast<std::uint64_t>(s) * s * ((3u * rx) ^ ry);
    if (ry == 0) {
      if (rx == 1) x = ~x, y = ~y;
      std::swap(x, y);
    }
  }
  return d;
}

/// Coordinate v in [lo, hi] as a 32-bit grid position (halved first, so
/// that hi - lo cannot overflow). Exact translations and power-of-two
/// scalings of the whole set leave it unchanged.
inline std::uint32_t grid_position(double v, double lo, double hi) {
  const double extent = hi * 0.5 - lo * 0.5;
  if (!(extent > 0)) return 0;
  const double u = (v * 0.5 - lo * 0.5) / extent;
  const double g = u * 4294967295.0;
  return g >= 4294967295.0 ? 0xFFFFFFFFu : (g > 0 ? static_cast<std::uint32_t>(g) : 0u);
}

/// The insertion order's key of a point with Hilbert index h: rounds in the
/// manner of BRIO (biased randomized insertion order), each in Hilbert
/// order. A point belongs to round r >= 1 (inserted before round r - 1)
/// with probability 8^-r, decided by a hash of h, so the order is a function
/// of the point set and is unchanged by exact translations and power-of-two
/// scalings. Inserting the last round's points among a coarser, uniformly
/// spread triangulation keeps cavities small (about four triangles each)
/// where a pure Hilbert order grows the triangulation at a frontier of long
/// thin triangles.
inline std::uint64_t insertion_key(std::uint64_t h) {
  std::uint64_t z = h + 0x9E3779B97F4A7C15ull;  // splitmix64 finaliser
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  z ^= z >> 31;
  const int zeros = z == 0 ? 63 : __builtin_ctzll(z);
  const std::uint64_t round = static_cast<std::uint64_t>(std::min(zeros / 3, 15));
  return ((15 - round) << 60) | (h >> 4);
}

/// The power of two 2^k by which the triangulation scales its points
/// (every coordinate multiplied exactly, so every predicate's sign and the
/// triangles are unchanged): the largest magnitude `big` brought into
/// [1, 2), so that the filters see the same numbers whatever the set's
/// scale (a set at 2^+-500 would otherwise overflow or underflow them and
/// fall to the exact stages), but never so far down that the smallest
/// non-zero magnitude `tiny` leaves the normal range (it would lose bits).
/// 0 for an empty or all-zero set, or a mix too wide to move.
inline int normalising_shift(double big, double tiny) {
  if (!(big > 0) || !std::isfinite(tiny)) return 0;
  int k = -std::ilogb(big);
  const int room = std::ilogb(tiny) - std::numeric_limits<double>::min_exponent + 1;  // binades above the subnormals
  if (k < 0) k = std::max(k, -std::max(room, 0));
  return k;
}

/// v * 2^k, exactly (the caller's k keeps the result normal or exact).
inline double scaled(double v, int k) { return k == 0 ? v : std::ldexp(v, k); }

template <class Pred>
class DelaunayBuilder {
 public:
  static constexpr std::uint32_t kInf = 0xFFFFFFFEu;
  static constexpr std::uint32_t kNone = DelaunayTriangulation::kNone;
  // m distinct points make 2m - 2 triangles with the ghosts, whose 6m - 6
  // corners are named by 32-bit indices below kNone: m <= 2^29.
  static constexpr std::size_t kMaxPoints = std::size_t(1) << 29;

  DelaunayTriangulation run(const Vec2* input, std::size_t n) {
    DelaunayTriangulation out;
    if (n > kMaxPoints)
      throw DelaunayInputError(kMaxPoints, "delaunay_2d: " + std::to_string(n) + " points is more than the " +
                                               std::to_string(kMaxPoints) + " this triangulation can index");
    double lox = 0, hix = 0, loy = 0, hiy = 0;
    double tiny = std::numeric_limits<double>::infinity();  // smallest non-zero |coordinate|
    for (std::size_t i = 0; i < n; ++i) {
      const Vec2 p = input[i];
      if (!std::isfinite(p.x) || !std::isfinite(p.y))
        throw DelaunayInputError(i, "delaunay_2d: point " + std::to_string(i) + " is (" + std::to_string(p.x) +
                                        ", " + std::to_string(p.y) + "): coordinates must be finite");
      if (i == 0) {
        lox = hix = p.x, loy = hiy = p.y;
      } else {
        lox = std::min(lox, p.x), hix = std::max(hix, p.x);
        loy = std::min(loy, p.y), hiy = std::max(hiy, p.y);
      }
      const double ax = std::fabs(p.x), ay = std::fabs(p.y);
      if (ax != 0) tiny = std::min(tiny, ax);
      if (ay != 0) tiny = std::min(tiny, ay);
    }
    const int shift = normalising_shift(std::max(std::max(-lox, hix), std::max(-loy, hiy)), tiny);
    out.vertex_of.resize(n);
    {
      // Merge duplicates (adjacent in the sorted order).
      const std::vector<Keyed> order = sorted_order(input, n, lox, hix, loy, hiy);
      rep_.assign(n, 0);
      pts_.assign(n, Vec2{});
      std::uint32_t* rep = rep_.data();
      Vec2* pts = pts_.data();
      std::size_t m = 0;
      for (std::size_t k = 0; k < n; ++k) {
        const Keyed& e = order[k];
        if (k == 0 || e.p != order[k - 1].p) {
          rep[m] = e.index;
          pts[m].x = scaled(e.p.x, shift), pts[m].y = scaled(e.p.y, shift);
          ++m;
        }
        out.vertex_of[e.index] = rep[m - 1];
      }
      rep_.resize(m);
      pts_.resize(m);
    }
    const std::uint32_t m = static_cast<std::uint32_t>(pts_.size());
    out.vertex_count = m;
    out.dimension = m == 0 ? DelaunayDimension::empty : (m == 1 ? DelaunayDimension::point : DelaunayDimension::line);
    if (m < 3) return out;
    std::uint32_t third = 2;
    while (third < m && Pred::orient(pts_[0], pts_[1], pts_[third]) == 0) ++third;
    if (third == m) return out;
    out.dimension = DelaunayDimension::plane;

    build(third);
    emit(out);
    return out;
  }

 private:
  struct Keyed {  // the point itself too: the sort and the merge read no input in random order
    std::uint64_t key;
    std::uint32_t index;
    Vec2 p;
  };

  // The input indices in insertion order: by insertion_key, ties by
  // coordinates (so that the order is a function of the point set), then
  // by index (so that the first of equal points is the smallest index).
  // A counting sort on the key's top bits (the round and the Hilbert
  // index's leading bits: about eight points a bucket), then each bucket
  // sorted whole; the buckets are ranges of the key, so the order is that
  // of the comparison alone.
  static std::vector<Keyed> sorted_order(const Vec2* input, std::size_t n, double lox, double hix, double loy,
                                         double hiy) {
    std::vector<Keyed> keyed(n);
    for (std::size_t i = 0; i < n; ++i)
      keyed[i] = {insertion_key(hilbert_index(grid_position(input[i].x, lox, hix), grid_position(input[i].y, loy, hiy))),
                  static_cast<std::uint32_t>(i), input[i]};
    const auto less = [](const Keyed& a, const Keyed& b) {
      if (a.key != b.key) return a.key < b.key;
      if (a.p.x != b.p.x) return a.p.x < b.p.x;
      if (a.p.y != b.p.y) return a.p.y < b.p.y;
      return a.index < b.index;
    };
    if (n < 256) {
      std::sort(keyed.begin(), keyed.end(), less);
      return keyed;
    }
    int bits = 4;
    while (bits < 16 && (std::size_t(1) << (bits + 3)) < n) ++bits;
    const int sh = 60 - bits;  // the key: 4 bits of round, then 60 of Hilbert index
    const std::size_t buckets = std::size_t(16) << bits;
    std::vector<std::uint32_t> end(buckets + 1, 0);
    for (const Keyed& k : keyed) ++end[(k.key >> sh) + 1];
    for (std::size_t b = 1; b <= buckets; ++b) end[b] += end[b - 1];
    std::vector<Keyed> order(n);
    for (const Keyed& k : keyed) order[end[k.key >> sh]++] = k;  // end[b]: now the end of bucket b
    std::vector<Keyed>().swap(keyed);
    std::uint32_t lo = 0;
    for (std::size_t b = 0; b < buckets; ++b) {
      const std::uint32_t hi = end[b];
      if (hi - lo <= 24) {
        for (std::uint32_t i = lo + 1; i < hi; ++i) {  // insertion sort
          const Keyed x = order[i];
          std::uint32_t j = i;
          for (; j > lo && less(x, order[j - 1]); --j) order[j] = order[j - 1];
          order[j] = x;
        }
      } else {
        std::sort(order.begin() + lo, order.begin() + hi, less);
      }
      lo = hi;
    }
    return order;
  }

  std::vector<Vec2> pts_;          // distinct points, in insertion order
  std::vector<std::uint32_t> rep_; // their input indices
  // Triangles as two arrays laid out like the output (vertices, and the
  // neighbouring corners), so that they become the output in place; V_ and
  // A_ index them by corner.
  using Triple = std::array<std::uint32_t, 3>;
  static_assert(sizeof(Triple) == 3 * sizeof(std::uint32_t), "corners are contiguous");
  std::vector<Triple> tv_, ta_;
  std::uint32_t* V_ = nullptr;
  std::uint32_t* A_ = nullptr;
  std::uint32_t nt_ = 0, cap_ = 0;
  std::vector<std::uint32_t> cavity_, stack_, vstamp_;
  struct Boundary {
    std::uint32_t from, to, outside;
  };
  std::vector<Boundary> boundary_;
  std::uint32_t last_ = 0;   // a real triangle to start walks from
  std::uint32_t stamp_ = 0;

  static std::uint32_t next(std::uint32_t c) { return c % 3 == 2 ? c - 2 : c + 1; }
  static std::uint32_t prev(std::uint32_t c) { return c % 3 == 0 ? c + 2 : c - 1; }
  bool ghost(std::uint32_t t) const { return V_[3 * t] == kInf || V_[3 * t + 1] == kInf || V_[3 * t + 2] == kInf; }

  // p strictly between x and y, all three collinear.
  static bool strictly_between(Vec2 x, Vec2 y, Vec2 p) {
    if (x.x != y.x) return (x.x < p.x && p.x < y.x) || (y.x < p.x && p.x < x.x);
    return (x.y < p.y && p.y < y.y) || (y.y < p.y && p.y < x.y);
  }

  bool in_conflict(std::uint32_t t, Vec2 p) const {
    const std::uint32_t a = V_[3 * t], b = V_[3 * t + 1], c = V_[3 * t + 2];
    std::uint32_t x, y;
    if (a == kInf) x = b, y = c;
    else if (b == kInf) x = c, y = a;
    else if (c == kInf) x = a, y = b;
    else return Pred::incircle(pts_[a], pts_[b], pts_[c], p) > 0;
    // Ghost: the open half-plane beyond the hull edge, and the open edge.
    const int o = Pred::orient(pts_[x], pts_[y], p);
    return o > 0 || (o == 0 && strictly_between(pts_[x], pts_[y], p));
  }

  // A triangle in conflict with p: the real one containing it (boundary
  // included), or a ghost whose hull edge p sees strictly. A visibility
  // walk, each triangle's edges in a fixed order: on a Delaunay
  // triangulation it cannot cycle (crossing an edge towards p never raises
  // p's power with respect to the circumcircle, and where it stays equal the
  // triangles share one circle, a convex polygon whose triangles form a
  // tree across their edges), so no random choice is needed; the step
  // bound stays for predicates that are not exact.
  std::uint32_t locate(Vec2 p) {
    std::uint32_t t = last_;
    std::uint32_t entered = kNone;  // the corner of t whose edge we came through
    const std::uint64_t limit = 2ull * nt_ + 16;
    for (std::uint64_t steps = 0;; ++steps) {
      if (steps > limit) throw DelaunayFailure("delaunay_2d: point location walked in a cycle");
      std::uint32_t crossed = kNone;
      for (std::uint32_t c = 3 * t; c < 3 * t + 3; ++c) {
        if (c == entered) continue;
        if (Pred::orient(pts_[V_[next(c)]], pts_[V_[prev(c)]], p) < 0) {
          crossed = c;
          break;
        }
      }
      if (crossed == kNone) return t;
      entered = A_[crossed];
      t = entered / 3;
      if (ghost(t)) return t;
    }
  }

  std::uint32_t new_triangle() {
    if (nt_ == cap_) throw DelaunayFailure("delaunay_2d: more triangles than 2n - 2");
    return nt_++;
  }

  // Re-triangulates: one triangle (from, to, apex) per boundary edge, in the
  // slots of `cavity_` and new ones. The boundary is in order around the
  // cavity (each edge's `to` is the next one's `from`), so each new
  // triangle's neighbour across (to, apex) is the next one.
  void fan(std::uint32_t apex, std::size_t nc, std::size_t k) {
    if (k != nc + 2)
      throw DelaunayFailure("delaunay_2d: the conflict region is not a disc (" + std::to_string(nc) +
                            " triangles, " + std::to_string(k) + " boundary edges)");
    // Every boundary vertex once (a pinched region would give the new
    // point two edges to one vertex).
    if (k <= 16) {
      for (std::size_t i = 1; i < k; ++i)
        for (std::size_t j = 0; j < i; ++j)
          if (boundary_[i].from == boundary_[j].from)
            throw DelaunayFailure("delaunay_2d: the conflict region's boundary is not a simple cycle");
    } else {
      ++stamp_;
      if (vstamp_.empty()) vstamp_.assign(pts_.size() + 1, 0);
      for (std::size_t i = 0; i < k; ++i) {
        const Boundary& e = boundary_[i];
        std::uint32_t& s = vstamp_[e.from == kInf ? pts_.size() : e.from];
        if (s == stamp_) throw DelaunayFailure("delaunay_2d: the conflict region's boundary is not a simple cycle");
        s = stamp_;
      }
    }
    if (cavity_.size() < k) cavity_.resize(2 * k);
    cavity_[nc] = new_triangle();
    cavity_[nc + 1] = new_triangle();
    for (std::size_t j = 0; j < k; ++j) {
      const std::size_t jn = j + 1 == k ? 0 : j + 1;
      const Boundary& e = boundary_[j];
      if (e.to != boundary_[jn].from)
        throw DelaunayFailure("delaunay_2d: the conflict region's boundary is not a cycle");
      const std::uint32_t t = cavity_[j], tn = cavity_[jn];
      V_[3 * t] = e.from, V_[3 * t + 1] = e.to, V_[3 * t + 2] = apex;
      A_[3 * t + 2] = e.outside, A_[e.outside] = 3 * t + 2;
      A_[3 * t] = 3 * tn + 1, A_[3 * tn + 1] = 3 * t;  // edge (to, apex) is (apex, from) of the next
      if (e.from != kInf && e.to != kInf) last_ = t;
    }
  }

  // Bowyer-Watson: the cavity grown depth first from the located triangle,
  // each triangle's edges in counter-clockwise order, so that the boundary
  // edges come out in order around the cavity. No marks: the cavity of an
  // exact Delaunay insertion has no interior vertex, so its triangles form
  // a tree across their shared edges and none is reached twice (an outside
  // triangle on two boundary edges is tested twice, with the same answer).
  // A region with a cycle would be explored without end: bounded by the
  // triangle count.
  void insert(std::uint32_t v) {
    const Vec2 p = pts_[v];
    const std::uint32_t t0 = locate(p);
    if (!ghost(t0))
      for (int i = 0; i < 3; ++i)
        if (pts_[V_[3 * t0 + i]] == p) throw DelaunayFailure("delaunay_2d: a duplicate point reached insertion");
    std::uint32_t* stack = stack_.data();
    std::size_t sp = 0, nc = 0, nb = 0;
    cavity_[nc++] = t0;
    stack[sp++] = 3 * t0 + 2, stack[sp++] = 3 * t0 + 1, stack[sp++] = 3 * t0;
    while (sp > 0) {
      const std::uint32_t c = stack[--sp];
      const std::uint32_t o = A_[c], u = o / 3;
      if (in_conflict(u, p)) {
        if (nc == cavity_.size()) {
          if (nc > nt_)
            throw DelaunayFailure("delaunay_2d: the conflict region is not a disc (it surrounds a vertex)");
          cavity_.resize(2 * nc);
        }
        cavity_[nc++] = u;
        if (sp + 2 > stack_.size()) stack_.resize(2 * stack_.size()), stack = stack_.data();
        stack[sp++] = prev(o), stack[sp++] = next(o);  // next(o)'s edge first
      } else {
        if (nb == boundary_.size()) boundary_.resize(2 * nb);
        boundary_[nb++] = {V_[next(c)], V_[prev(c)], o};
      }
    }
    fan(v, nc, nb);
  }

  void build(std::uint32_t third) {
    const std::uint32_t m = static_cast<std::uint32_t>(pts_.size());
    cap_ = 2 * m - 2;  // with the ghosts: 2(m + 1) - 4
    tv_.assign(cap_, Triple{});
    ta_.assign(cap_, Triple{});
    V_ = tv_.data()->data();
    A_ = ta_.data()->data();
    nt_ = 0;
    stamp_ = 0;
    // The first triangle, counter-clockwise, and its three ghosts (a fan
    // around the vertex at infinity).
    std::uint32_t a = 0, b = 1, c = third;
    if (Pred::orient(pts_[a], pts_[b], pts_[c]) < 0) std::swap(b, c);
    const std::uint32_t t = new_triangle();
    V_[0] = a, V_[1] = b, V_[2] = c;
    cavity_.clear(), boundary_.clear();
    cavity_.assign(64, 0);
    stack_.assign(64, 0);
    boundary_.assign(64, Boundary{});
    // Its edges seen from outside, in order: c->b, b->a, a->c; fan()
    // expects boundary = cavity + 2: one ghost slot comes from the cavity
    // list, which here is a fresh triangle.
    std::size_t nb = 0;
    for (const std::uint32_t i : {0u, 2u, 1u}) boundary_[nb++] = {V_[prev(i)], V_[next(i)], i};
    cavity_[0] = new_triangle();
    fan(kInf, 1, nb);
    last_ = t;
    // Points 2..third-1 (collinear with the first two) go in after the
    // triangle, like the rest.
    for (std::uint32_t v = 2; v < m; ++v) {
      if (v == third) continue;
      insert(v);
    }
  }

  // The output in place: the ghosts' slots filled with the last real
  // triangles (their neighbours' links moved along), the hull edges' links
  // set to kNone, vertices to input indices, corners to triangles; the two
  // arrays then become the output.
  void emit(DelaunayTriangulation& out) {
    std::vector<Vec2>().swap(pts_);
    std::vector<std::uint32_t>().swap(vstamp_);
    const std::uint32_t nt = nt_;
    std::uint32_t ghosts = 0;
    for (std::uint32_t t = 0; t < nt; ++t)
      if (ghost(t)) {
        ++ghosts;
        for (std::uint32_t i = 3 * t; i < 3 * t + 3; ++i)
          if (V_[i] == kInf) A_[A_[i]] = kNone;  // the real side of the hull edge
      }
    const std::uint32_t real = nt - ghosts;
    std::uint32_t src = real;
    for (std::uint32_t g = 0; g < real; ++g) {
      if (!ghost(g)) continue;
      while (src < nt && ghost(src)) ++src;
      if (src == nt) throw DelaunayFailure("delaunay_2d: ghost count mismatch");
      for (std::uint32_t i = 0; i < 3; ++i) {
        V_[3 * g + i] = V_[3 * src + i];
        const std::uint32_t c = A_[3 * src + i];
        A_[3 * g + i] = c;
        if (c != kNone) A_[c] = 3 * g + i;
      }
      ++src;
    }
    for (std::uint32_t i = 0; i < 3 * real; ++i) {
      V_[i] = rep_[V_[i]];
      A_[i] = A_[i] == kNone ? kNone : A_[i] / 3;
    }
    std::vector<std::uint32_t>().swap(rep_);
    tv_.resize(real);
    ta_.resize(real);
    if (real < tv_.capacity() / 8 * 7) {  // many hull edges: give the slack back
      tv_.shrink_to_fit();
      ta_.shrink_to_fit();
    }
    V_ = A_ = nullptr;
    out.triangles = std::move(tv_);
    out.neighbors = std::move(ta_);
    out.hull_edges = ghosts;
  }
};

}  // namespace geomcheck::detail
