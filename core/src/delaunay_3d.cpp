#include "geomcheck/delaunay_3d.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "geomcheck/detail/delaunay_build.hpp"  // grid_position, insertion_key, normalising_shift, scaled
#include "geomcheck/predicates2d.hpp"
#include "geomcheck/predicates3d.hpp"

namespace geomcheck {

namespace {

using Quad = std::array<std::uint32_t, 4>;
static_assert(sizeof(Quad) == 4 * sizeof(std::uint32_t), "corners are contiguous");

constexpr std::uint32_t kInf = 0xFFFFFFFEu;
constexpr std::uint32_t kNone = DelaunayTetrahedralization::kNone;
constexpr std::uint32_t kDead = 0xFFFFFFFDu;  // V of a freed tetrahedron's first corner

// The facet opposite corner i of a positively oriented tetrahedron
// (v0, v1, v2, v3), its vertices ordered so that v_i lies on its positive
// side: (f0, f1, f2, v_i) is positively oriented too.
constexpr int kFacet[4][3] = {{1, 3, 2}, {0, 2, 3}, {0, 3, 1}, {0, 1, 2}};

/// The right-handed orientation: +1 when d is on the side of plane abc
/// that (b - a) x (c - a) points to.
inline int orient(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) { return -orient3d(a, b, c, d); }

/// Position along the 3D Hilbert curve of order 21 (Skilling's transpose
/// algorithm), 63 bits.
std::uint64_t hilbert_index_3d(std::uint32_t x, std::uint32_t y, std::uint32_t z) {
  constexpr int kBits = 21;
  std::uint32_t X[3] = {x, y, z};
  for (std::uint32_t q = 1u << (kBits - 1); q > 1; q >>= 1) {
    const std::uint32_t p = q - 1;
    for (int i = 0; i < 3; ++i) {
      if (X[i] & q) {
        X[0] ^= p;
      } else {
        const std::uint32_t t = (X[0] ^ X[i]) & p;
        X[0] ^= t, X[i] ^= t;
      }
    }
  }
  X[1] ^= X[0], X[2] ^= X[1];
  std::uint32_t t = 0;
  for (std::uint32_t q = 1u << (kBits - 1); q > 1; q >>= 1)
    if (X[2] & q) t ^= q - 1;
  for (std::uint32_t& c : X) c ^= t;
  std::uint64_t h = 0;
  for (int b = kBits - 1; b >= 0; --b)
    for (int i = 0; i < 3; ++i) h = (h << 1) | ((X[i] >> b) & 1u);
  return h;
}

bool collinear(const Vec3& a, const Vec3& b, const Vec3& c) {
  return orient2d({a.x, a.y}, {b.x, b.y}, {c.x, c.y}) == 0 && orient2d({a.y, a.z}, {b.y, b.z}, {c.y, c.z}) == 0 &&
         orient2d({a.z, a.x}, {b.z, b.x}, {c.z, c.x}) == 0;
}

class Builder {
 public:
  // The tetrahedra and infinite ones number about 6.7 per point in a
  // uniform cloud, and at most O(m^2) (points on two skew lines): 32-bit
  // corners below kDead bound the count.
  static constexpr std::size_t kMaxPoints = std::size_t(1) << 26;

  DelaunayTetrahedralization run(const Vec3* input, std::size_t n) {
    DelaunayTetrahedralization out;
    if (n > kMaxPoints)
      throw DelaunayInputError(kMaxPoints, "delaunay_3d: " + std::to_string(n) + " points is more than the " +
                                               std::to_string(kMaxPoints) + " this tetrahedralization can index");
    double lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
    double tiny = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < n; ++i) {
      const Vec3 p = input[i];
      for (int k = 0; k < 3; ++k) {
        const double c = p[k];
        if (!std::isfinite(c))
          throw DelaunayInputError(i, "delaunay_3d: point " + std::to_string(i) + " is (" + std::to_string(p.x) +
                                          ", " + std::to_string(p.y) + ", " + std::to_string(p.z) +
                                          "): coordinates must be finite");
        if (i == 0) lo[k] = hi[k] = c;
        lo[k] = std::min(lo[k], c), hi[k] = std::max(hi[k], c);
        if (c != 0) tiny = std::min(tiny, std::fabs(c));
      }
    }
    double big = 0;
    for (int k = 0; k < 3; ++k) big = std::max(big, std::max(-lo[k], hi[k]));
    const int shift = detail::normalising_shift(big, tiny);
    out.vertex_of.resize(n);
    {
      std::vector<Keyed> order(n);
      for (std::size_t i = 0; i < n; ++i) {
        const Vec3 p = input[i];
        const std::uint64_t h = hilbert_index_3d(detail::grid_position(p.x, lo[0], hi[0]) >> 11,
                                                 detail::grid_position(p.y, lo[1], hi[1]) >> 11,
                                                 detail::grid_position(p.z, lo[2], hi[2]) >> 11);
        order[i] = {detail::insertion_key(h << 1), static_cast<std::uint32_t>(i), p};
      }
      std::sort(order.begin(), order.end(), [](const Keyed& a, const Keyed& b) {
        if (a.key != b.key) return a.key < b.key;
        if (a.p.x != b.p.x) return a.p.x < b.p.x;
        if (a.p.y != b.p.y) return a.p.y < b.p.y;
        if (a.p.z != b.p.z) return a.p.z < b.p.z;
        return a.index < b.index;
      });
      pts_.reserve(n), rep_.reserve(n);
      for (std::size_t k = 0; k < n; ++k) {
        const Keyed& e = order[k];
        if (k == 0 || !(e.p.x == order[k - 1].p.x && e.p.y == order[k - 1].p.y && e.p.z == order[k - 1].p.z)) {
          rep_.push_back(e.index);
          pts_.push_back({detail::scaled(e.p.x, shift), detail::scaled(e.p.y, shift), detail::scaled(e.p.z, shift)});
        }
        out.vertex_of[e.index] = rep_.back();
      }
    }
    using D = DelaunayTetrahedralization::Dimension;
    const std::uint32_t m = static_cast<std::uint32_t>(pts_.size());
    out.vertex_count = m;
    out.dimension = m == 0 ? D::empty : m == 1 ? D::point : D::line;
    if (m < 3) return out;
    std::uint32_t third = 2;
    while (third < m && collinear(pts_[0], pts_[1], pts_[third])) ++third;
    if (third == m) return out;
    out.dimension = D::plane;
    std::uint32_t fourth = third + 1;
    while (fourth < m && orient3d(pts_[0], pts_[1], pts_[third], pts_[fourth]) == 0) ++fourth;
    if (fourth == m) return out;
    out.dimension = D::solid;
    build(third, fourth);
    emit(out);
    return out;
  }

 private:
  struct Keyed {
    std::uint64_t key;
    std::uint32_t index;
    Vec3 p;
  };
  struct Face {  // a facet of the cavity's boundary, seen from inside
    std::uint32_t f[3];
    std::uint32_t outside;  // the corner across it, outside the cavity
  };
  struct Slot {
    std::uint64_t key;
    std::uint32_t corner, stamp;
  };

  std::vector<Vec3> pts_;
  std::vector<std::uint32_t> rep_;
  struct Tet {  // one cache line holds two: a test and the walk across its facets read both halves
    Quad v;  // vertices (kInf for the vertex at infinity; v[0] == kDead once freed)
    Quad a;  // a[i]: the corner of the neighbour across the facet opposite v[i]
  };
  std::vector<Tet> tets_;
  std::vector<std::uint32_t> mark_, free_, cavity_, stack_;
  std::vector<Face> boundary_;
  std::vector<Slot> edges_;
  std::uint32_t stamp_ = 0, edge_stamp_ = 0, last_ = 0, walk_ = 0;

  std::uint32_t& V(std::uint32_t c) { return tets_[c >> 2].v[c & 3]; }
  std::uint32_t& A(std::uint32_t c) { return tets_[c >> 2].a[c & 3]; }
  int inf_corner(std::uint32_t t) const {
    const Quad& q = tets_[t].v;
    for (int i = 0; i < 4; ++i)
      if (q[i] == kInf) return i;
    return -1;
  }

  bool in_conflict(std::uint32_t t, const Vec3& p) {
    const Quad& q = tets_[t].v;
    const int k = inf_corner(t);
    if (k < 0) return insphere(pts_[q[1]], pts_[q[0]], pts_[q[2]], pts_[q[3]], p) > 0;
    const Vec3& a = pts_[q[kFacet[k][0]]];
    const Vec3& b = pts_[q[kFacet[k][1]]];
    const Vec3& c = pts_[q[kFacet[k][2]]];
    const int o = orient(a, b, c, p);
    if (o != 0) return o > 0;
    // On the hull facet's plane: in conflict strictly inside its
    // circumcircle, which is where the plane cuts the circumsphere of the
    // finite tetrahedron behind it (d on the negative side of abc).
    const Vec3& d = pts_[V(A(4 * t + k))];
    return insphere(a, b, c, d, p) > 0;
  }

  // A tetrahedron in conflict with p: the finite one containing it
  // (boundary included; p is no vertex, so p is strictly inside its
  // circumsphere), or an infinite one whose hull facet p sees strictly.
  std::uint32_t locate(const Vec3& p) {
    std::uint32_t t = last_;
    if (tets_[t].v[0] == kDead || inf_corner(t) >= 0)
      throw DelaunayFailure("delaunay_3d: the walk's start is not a live finite tetrahedron");
    std::uint32_t from = kNone;
    const std::uint64_t limit = 4ull * tets_.size() + 16;
    for (std::uint64_t steps = 0;; ++steps) {
      if (steps > limit) throw DelaunayFailure("delaunay_3d: point location walked in a cycle");
      const Quad& q = tets_[t].v;
      walk_ = walk_ * 1103515245u + 12345u;
      const std::uint32_t off = (walk_ >> 16) & 3;
      std::uint32_t next = kNone;
      for (std::uint32_t r = 0; r < 4; ++r) {
        const std::uint32_t j = (r + off) & 3;
        const std::uint32_t across = tets_[t].a[j] >> 2;
        if (across == from) continue;
        if (orient(pts_[q[kFacet[j][0]]], pts_[q[kFacet[j][1]]], pts_[q[kFacet[j][2]]], p) < 0) {
          next = across;
          break;
        }
      }
      if (next == kNone) return t;
      from = t;
      t = next;
      if (inf_corner(t) >= 0) return t;
    }
  }

  std::uint32_t new_tet() {
    if (!free_.empty()) {
      const std::uint32_t t = free_.back();
      free_.pop_back();
      return t;
    }
    if (tets_.size() >= (kDead >> 2))
      throw DelaunayFailure("delaunay_3d: more tetrahedra than 32-bit corners can name");
    tets_.push_back({}), mark_.push_back(0);
    return static_cast<std::uint32_t>(tets_.size() - 1);
  }

  // Pairs the facet through directed edge (from, to) with the one through
  // (to, from): both contain the new point.
  void pair_edge(std::uint32_t from, std::uint32_t to, std::uint32_t corner) {
    const std::size_t mask = edges_.size() - 1;
    const std::uint64_t want = (std::uint64_t(to) << 32) | from;
    std::size_t h = static_cast<std::size_t>((want * 0x9E3779B97F4A7C15ull) >> 40) & mask;
    for (;; h = (h + 1) & mask) {
      Slot& s = edges_[h];
      if (s.stamp != edge_stamp_) break;
      if (s.key == want) {
        A(corner) = s.corner, A(s.corner) = corner;
        s.key = ~0ull;  // each edge pairs once; the slot stays occupied so that no probe chain ends early
        return;
      }
    }
    const std::uint64_t key = (std::uint64_t(from) << 32) | to;
    h = static_cast<std::size_t>((key * 0x9E3779B97F4A7C15ull) >> 40) & mask;
    while (edges_[h].stamp == edge_stamp_) h = (h + 1) & mask;
    edges_[h] = {key, corner, edge_stamp_};
  }

  void insert(std::uint32_t v) {
    const Vec3 p = pts_[v];
    // In conflict without a test: p lies in the closed finite tetrahedron
    // and is none of its vertices (duplicates are merged), so strictly
    // inside its circumsphere; or strictly beyond an infinite one's facet.
    const std::uint32_t t0 = locate(p);
    const std::uint32_t in = ++stamp_, out = ++stamp_;
    cavity_.clear(), stack_.clear(), boundary_.clear();
    mark_[t0] = in;
    cavity_.push_back(t0), stack_.push_back(t0);
    while (!stack_.empty()) {
      const std::uint32_t t = stack_.back();
      stack_.pop_back();
      for (std::uint32_t j = 0; j < 4; ++j) {
        const std::uint32_t c = 4 * t + j, o = A(c), u = o >> 2;
        if (mark_[u] == in) continue;
        if (mark_[u] != out) {
          if (in_conflict(u, p)) {
            mark_[u] = in;
            cavity_.push_back(u), stack_.push_back(u);
            continue;
          }
          mark_[u] = out;
        }
        const Quad& q = tets_[t].v;
        boundary_.push_back({{q[kFacet[j][0]], q[kFacet[j][1]], q[kFacet[j][2]]}, o});
      }
    }
    for (std::uint32_t t : cavity_) tets_[t].v[0] = kDead, free_.push_back(t);
    std::size_t need = 16;
    while (need < 4 * boundary_.size()) need *= 2;
    if (edges_.size() < need) edges_.assign(need, Slot{0, 0, 0}), edge_stamp_ = 0;
    if (++edge_stamp_ == 0) {
      for (Slot& s : edges_) s.stamp = 0;
      edge_stamp_ = 1;
    }
    for (const Face& f : boundary_) {
      const std::uint32_t t = new_tet();
      tets_[t].v = {f.f[0], f.f[1], f.f[2], v};
      mark_[t] = 0;
      A(4 * t + 3) = f.outside, A(f.outside) = 4 * t + 3;
      // The facet opposite f[k] holds p and the edge f[k+1] -> f[k+2].
      pair_edge(f.f[1], f.f[2], 4 * t + 0);
      pair_edge(f.f[2], f.f[0], 4 * t + 1);
      pair_edge(f.f[0], f.f[1], 4 * t + 2);
      if (f.f[0] != kInf && f.f[1] != kInf && f.f[2] != kInf) last_ = t;
    }
  }

  void build(std::uint32_t third, std::uint32_t fourth) {
    const std::size_t m = pts_.size();
    tets_.reserve(7 * m), mark_.reserve(7 * m);
    std::uint32_t a = 0, b = 1, c = third, d = fourth;
    if (orient(pts_[a], pts_[b], pts_[c], pts_[d]) < 0) std::swap(a, b);
    const std::uint32_t t0 = new_tet();
    tets_[t0].v = {a, b, c, d};
    for (std::uint32_t j = 0; j < 4; ++j) {  // one infinite tetrahedron on each facet, seen from outside
      const std::uint32_t t = new_tet();
      const Quad& q = tets_[t0].v;
      tets_[t].v = {q[kFacet[j][0]], q[kFacet[j][2]], q[kFacet[j][1]], kInf};
    }
    for (std::uint32_t s = 0; s < 5; ++s)  // pair the 20 facets by their vertex sets
      for (std::uint32_t i = 0; i < 4; ++i)
        for (std::uint32_t u = s + 1; u < 5; ++u)
          for (std::uint32_t k = 0; k < 4; ++k) {
            std::array<std::uint32_t, 3> x{}, y{};
            for (int e = 0; e < 3; ++e) x[e] = tets_[s].v[kFacet[i][e]], y[e] = tets_[u].v[kFacet[k][e]];
            std::sort(x.begin(), x.end()), std::sort(y.begin(), y.end());
            if (x == y) tets_[s].a[i] = 4 * u + k, tets_[u].a[k] = 4 * s + i;
          }
    last_ = t0;
    for (std::uint32_t v = 2; v < m; ++v)
      if (v != third && v != fourth) insert(v);
  }

  // The finite tetrahedra, compacted, with input indices; links to
  // infinite ones become kNone.
  void emit(DelaunayTetrahedralization& out) {
    const std::uint32_t nt = static_cast<std::uint32_t>(tets_.size());
    std::vector<std::uint32_t> index(nt, kNone);
    std::uint32_t finite = 0, infinite = 0;
    for (std::uint32_t t = 0; t < nt; ++t) {
      if (tets_[t].v[0] == kDead) continue;
      if (inf_corner(t) >= 0) ++infinite;
      else index[t] = finite++;
    }
    out.tetrahedra.resize(finite);
    out.neighbors.resize(finite);
    for (std::uint32_t t = 0; t < nt; ++t) {
      if (index[t] == kNone) continue;
      auto& tv = out.tetrahedra[index[t]];
      auto& ta = out.neighbors[index[t]];
      for (int i = 0; i < 4; ++i) {
        tv[i] = rep_[tets_[t].v[i]];
        ta[i] = index[tets_[t].a[i] >> 2];
      }
    }
    out.hull_facets = infinite;
  }
};

}  // namespace

const char* to_string(DelaunayTetrahedralization::Dimension d) {
  using D = DelaunayTetrahedralization::Dimension;
  switch (d) {
    case D::empty: return "empty";
    case D::point: return "point";
    case D::line: return "line";
    case D::plane: return "plane";
    case D::solid: return "solid";
  }
  return "?";
}

std::string DelaunayTetrahedralization::summary() const {
  const std::size_t n = vertex_of.size();
  const std::size_t merged = n - vertex_count;
  const std::string dups =
      merged == 0 ? std::string() : " (" + std::to_string(merged) + (merged == 1 ? " duplicate" : " duplicates") + " merged)";
  const std::string of = std::to_string(vertex_count) + " distinct points of " + std::to_string(n) + dups;
  switch (dimension) {
    case Dimension::empty: return "empty: no points, no tetrahedra";
    case Dimension::point:
      return "point: " + std::to_string(n) + (n == 1 ? " point" : " coincident points") + ", no tetrahedra";
    case Dimension::line: return "line: all " + of + " are collinear, no tetrahedra";
    case Dimension::plane: return "plane: all " + of + " are coplanar, no tetrahedra";
    case Dimension::solid:
      return "solid: " + of + ", " + std::to_string(tetrahedra.size()) + " tetrahedra, " + std::to_string(hull_facets) +
             " hull facets";
  }
  return "?";
}

DelaunayTetrahedralization delaunay_3d(const Vec3* points, std::size_t n) { return Builder().run(points, n); }

}  // namespace geomcheck
