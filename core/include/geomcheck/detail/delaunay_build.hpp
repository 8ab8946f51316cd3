// geomcheck — the Delaunay construction of delaunay_2d.hpp, generic in its
// predicates (production instantiates it with the exact ones; the tests'
// teeth with plain doubles, to show what the exact ones are for).
//
// Predicates: a type with static `int orient(Vec2 a, Vec2 b, Vec2 c)` and
// `int incircle(Vec2 a, Vec2 b, Vec2 c, Vec2 d)`, signs as in predicates2d.hpp.
//
// Storage: triangle t has corners 3t, 3t+1, 3t+2; vx(c) is the vertex of
// corner c (kInf for the vertex at infinity), ax(c) the corner of the
// neighbouring triangle opposite the same edge. The edge opposite corner
// 3t+i runs from vx(3t+(i+1)%3) to vx(3t+(i+2)%3), with the triangle on its
// left. A ghost triangle (x, y, inf) closes hull edge y->x: the
// triangulation lies to the right of x->y.
#pragma once

#include <algorithm>
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
  static constexpr std::size_t kMaxPoints = std::size_t(1) << 30;

  DelaunayTriangulation run(const Vec2* input, std::size_t n) {
    DelaunayTriangulation out;
    // Marks are 2*stamp+1 with two stamps per point: 2^30 points at most.
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
    // Spatial sort (insertion_key); ties by coordinates, so that the order
    // is a function of the point set, then by index, so that the first of
    // equal points is the smallest index.
    struct Keyed {
      std::uint64_t key;
      std::uint32_t index;
    };
    std::vector<Keyed> keyed(n), order(n);
    for (std::size_t i = 0; i < n; ++i)
      keyed[i] = {insertion_key(hilbert_index(grid_position(input[i].x, lox, hix), grid_position(input[i].y, loy, hiy))),
                  static_cast<std::uint32_t>(i)};
    // Counting sort on the top 16 bits of the key, then each bucket sorted
    // whole (most buckets hold a handful of points); a small set is sorted
    // whole at once (the same order: the buckets are ranges of the key).
    {
      const auto less = [input](const Keyed& a, const Keyed& b) {
        if (a.key != b.key) return a.key < b.key;
        const Vec2 p = input[a.index], q = input[b.index];
        if (p.x != q.x) return p.x < q.x;
        if (p.y != q.y) return p.y < q.y;
        return a.index < b.index;
      };
      if (n < (std::size_t(1) << 14)) {
        order = keyed;
        std::sort(order.begin(), order.end(), less);
      } else {
        std::vector<std::uint32_t> start(65537, 0);
        for (const Keyed& k : keyed) ++start[(k.key >> 48) + 1];
        for (std::size_t b = 1; b <= 65536; ++b) start[b] += start[b - 1];
        std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
        for (const Keyed& k : keyed) order[fill[k.key >> 48]++] = k;
        for (std::size_t b = 0; b < 65536; ++b)
          if (start[b + 1] - start[b] > 1) std::sort(order.begin() + start[b], order.begin() + start[b + 1], less);
      }
    }
    std::vector<Keyed>().swap(keyed);
    // Merge duplicates (adjacent after the sort).
    out.vertex_of.resize(n);
    rep_.clear();
    pts_.clear();
    rep_.reserve(n);
    pts_.reserve(n);
    for (std::size_t k = 0; k < n; ++k) {
      const std::uint32_t i = order[k].index;
      if (k == 0 || input[i] != input[rep_.back()]) {
        rep_.push_back(i);
        pts_.push_back({scaled(input[i].x, shift), scaled(input[i].y, shift)});
      }
      out.vertex_of[i] = rep_.back();
    }
    std::vector<Keyed>().swap(order);
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
  std::vector<Vec2> pts_;          // distinct points, in insertion order
  std::vector<std::uint32_t> rep_; // their input indices
  // One triangle per 32 bytes: its corners' vertices and neighbours, and a
  // mark: 2*stamp (in the current cavity), 2*stamp+1 (tested, outside).
  struct Tri {
    std::uint32_t v[3], a[3], mark, pad;
  };
  std::vector<Tri> tri_;
  std::uint32_t& vx(std::uint32_t c) { return tri_[c / 3].v[c % 3]; }
  std::uint32_t vx(std::uint32_t c) const { return tri_[c / 3].v[c % 3]; }
  std::uint32_t& ax(std::uint32_t c) { return tri_[c / 3].a[c % 3]; }
  std::uint32_t ax(std::uint32_t c) const { return tri_[c / 3].a[c % 3]; }
  std::vector<std::uint32_t> fan_corner_, fan_stamp_;  // per vertex (+ inf): the new triangle leaving it
  std::vector<std::uint32_t> cavity_, stack_, fan_;
  struct Boundary {
    std::uint32_t from, to, outside;
  };
  std::vector<Boundary> boundary_;
  std::uint32_t last_ = 0;   // a real triangle to start walks from
  std::uint32_t stamp_ = 0;
  std::uint32_t rng_ = 0x9E3779B9u;

  static std::uint32_t next(std::uint32_t c) { return c % 3 == 2 ? c - 2 : c + 1; }
  static std::uint32_t prev(std::uint32_t c) { return c % 3 == 0 ? c + 2 : c - 1; }
  bool ghost(std::uint32_t t) const { return tri_[t].v[0] == kInf || tri_[t].v[1] == kInf || tri_[t].v[2] == kInf; }
  std::uint32_t triangles() const { return static_cast<std::uint32_t>(tri_.size()); }
  // Index into the per-vertex arrays: the vertex, or the last slot for infinity.
  std::uint32_t slot(std::uint32_t v) const { return v == kInf ? static_cast<std::uint32_t>(pts_.size()) : v; }

  // p strictly between x and y, all three collinear.
  static bool strictly_between(Vec2 x, Vec2 y, Vec2 p) {
    if (x.x != y.x) return (x.x < p.x && p.x < y.x) || (y.x < p.x && p.x < x.x);
    return (x.y < p.y && p.y < y.y) || (y.y < p.y && p.y < x.y);
  }

  bool in_conflict(std::uint32_t t, Vec2 p) const {
    const std::uint32_t a = vx(3 * t), b = vx(3 * t + 1), c = vx(3 * t + 2);
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
  // included), or a ghost whose hull edge p sees strictly.
  std::uint32_t locate(Vec2 p) {
    std::uint32_t t = last_;
    std::uint32_t entered = kNone;  // the corner of t whose edge we came through
    const std::uint64_t limit = 2ull * triangles() + 16;
    for (std::uint64_t steps = 0;; ++steps) {
      if (steps > limit) throw DelaunayFailure("delaunay_2d: point location walked in a cycle");
      rng_ ^= rng_ << 13, rng_ ^= rng_ >> 17, rng_ ^= rng_ << 5;
      const std::uint32_t r = rng_ % 3;
      std::uint32_t crossed = kNone;
      for (std::uint32_t k = 0; k < 3; ++k) {
        const std::uint32_t c = 3 * t + (r + k) % 3;
        if (c == entered) continue;
        if (Pred::orient(pts_[vx(next(c))], pts_[vx(prev(c))], p) < 0) {
          crossed = c;
          break;
        }
      }
      if (crossed == kNone) return t;
      entered = ax(crossed);
      t = entered / 3;
      if (ghost(t)) return t;
    }
  }

  std::uint32_t new_triangle() {
    tri_.push_back(Tri{{0, 0, 0}, {0, 0, 0}, 0, 0});
    return triangles() - 1;
  }

  // Re-triangulates: one triangle (from, to, apex) per boundary edge, in the
  // slots of `cavity_` and new ones; links the fan and the outside.
  void fan(std::uint32_t apex) {
    if (boundary_.size() != cavity_.size() + 2)
      throw DelaunayFailure("delaunay_2d: the conflict region is not a disc (" + std::to_string(cavity_.size()) +
                            " triangles, " + std::to_string(boundary_.size()) + " boundary edges)");
    ++stamp_;
    fan_.clear();
    for (std::size_t j = 0; j < boundary_.size(); ++j) {
      const std::uint32_t t = j < cavity_.size() ? cavity_[j] : new_triangle();
      fan_.push_back(t);
      const Boundary& e = boundary_[j];
      vx(3 * t) = e.from, vx(3 * t + 1) = e.to, vx(3 * t + 2) = apex;
      ax(3 * t + 2) = e.outside, ax(e.outside) = 3 * t + 2;
      const std::uint32_t s = slot(e.from);
      if (fan_stamp_[s] == stamp_) throw DelaunayFailure("delaunay_2d: the conflict region's boundary is not a cycle");
      fan_stamp_[s] = stamp_, fan_corner_[s] = 3 * t + 1;  // edge (apex, from) is opposite corner 1
      if (e.from != kInf && e.to != kInf) last_ = t;
    }
    for (const std::uint32_t t : fan_) {
      const std::uint32_t s = slot(vx(3 * t + 1));
      if (fan_stamp_[s] != stamp_) throw DelaunayFailure("delaunay_2d: the conflict region's boundary is not a cycle");
      const std::uint32_t other = fan_corner_[s];  // edge (to, apex) is opposite corner 0
      ax(3 * t) = other, ax(other) = 3 * t;
    }
  }

  void insert(std::uint32_t v) {
    const Vec2 p = pts_[v];
    const std::uint32_t t0 = locate(p);
    if (!ghost(t0))
      for (int i = 0; i < 3; ++i)
        if (pts_[vx(3 * t0 + i)] == p) throw DelaunayFailure("delaunay_2d: a duplicate point reached insertion");
    ++stamp_;
    const std::uint32_t in = 2 * stamp_, out = 2 * stamp_ + 1;
    cavity_.clear(), boundary_.clear(), stack_.clear();
    tri_[t0].mark = in;
    cavity_.push_back(t0), stack_.push_back(t0);
    while (!stack_.empty()) {
      const std::uint32_t t = stack_.back();
      stack_.pop_back();
      for (std::uint32_t c = 3 * t; c < 3 * t + 3; ++c) {
        const std::uint32_t o = ax(c), u = o / 3;
        if (tri_[u].mark == in) continue;
        if (tri_[u].mark != out && in_conflict(u, p)) {
          tri_[u].mark = in;
          cavity_.push_back(u), stack_.push_back(u);
        } else {
          tri_[u].mark = out;
          boundary_.push_back({vx(next(c)), vx(prev(c)), o});
        }
      }
    }
    fan(v);
  }

  void build(std::uint32_t third) {
    const std::uint32_t m = static_cast<std::uint32_t>(pts_.size());
    tri_.clear();
    tri_.reserve(2 * std::size_t(m) + 8);
    fan_corner_.assign(std::size_t(m) + 1, 0);
    fan_stamp_.assign(std::size_t(m) + 1, 0);
    stamp_ = 0;
    // The first triangle, counter-clockwise, and its three ghosts (a fan
    // around the vertex at infinity).
    std::uint32_t a = 0, b = 1, c = third;
    if (Pred::orient(pts_[a], pts_[b], pts_[c]) < 0) std::swap(b, c);
    const std::uint32_t t = new_triangle();
    vx(0) = a, vx(1) = b, vx(2) = c;
    cavity_.clear(), boundary_.clear();
    for (std::uint32_t i = 0; i < 3; ++i) boundary_.push_back({vx(prev(i)), vx(next(i)), i});
    // fan() expects boundary = cavity + 2: one ghost slot comes from the
    // cavity list, which here is a fresh triangle.
    cavity_.push_back(new_triangle());
    fan(kInf);
    last_ = t;
    // Points 2..third-1 (collinear with the first two) go in after the
    // triangle, like the rest.
    for (std::uint32_t v = 2; v < m; ++v) {
      if (v == third) continue;
      insert(v);
    }
  }

  void emit(DelaunayTriangulation& out) const {
    const std::uint32_t nt = triangles();
    std::vector<std::uint32_t> index(nt, kNone);
    std::uint32_t real = 0;
    for (std::uint32_t t = 0; t < nt; ++t)
      if (!ghost(t)) index[t] = real++;
    out.triangles.resize(real);
    out.neighbors.resize(real);
    out.hull_edges = nt - real;
    for (std::uint32_t t = 0; t < nt; ++t) {
      if (index[t] == kNone) continue;
      for (int i = 0; i < 3; ++i) {
        out.triangles[index[t]][i] = rep_[vx(3 * t + i)];
        out.neighbors[index[t]][i] = index[ax(3 * t + i) / 3];
      }
    }
  }
};

}  // namespace geomcheck::detail
