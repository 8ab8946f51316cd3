#include "geomcheck/collide_cylinder_mesh.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "geomcheck/collide_cylinder_triangle.hpp"
#include "geomcheck/detail/frame.hpp"
#include "geomcheck/detail/triangle_stages.hpp"

namespace geomcheck {

namespace {

// The axis segment against the boxes grown by g (r plus the margin): a
// superset of the boxes grown by the ball of radius r, so of every box the
// bounding capsule meets. Liang-Barsky clipping against the three slabs.
struct BroadPhase {
  Vec3 p, d;
  double g;
  BroadPhase(const Cylinder& c, const TriangleMesh& m) : p(c.p), d(c.q - c.p) {
    const double scene = std::max(detail::largest(c), m.magnitude());
    g = c.r + 0x1p-30 * scene;
  }
  bool meets(const detail::BvhNode& n) const {
    double t0 = 0, t1 = 1;
    for (int i = 0; i < 3; ++i) {
      const double lo = n.lo[i] - g, hi = n.hi[i] + g;
      if (d[i] == 0) {
        if (p[i] < lo || p[i] > hi) return false;
        continue;
      }
      double a = (lo - p[i]) / d[i], b = (hi - p[i]) / d[i];
      if (a > b) std::swap(a, b);
      t0 = std::max(t0, a), t1 = std::min(t1, b);
      if (t0 > t1) return false;
    }
    return true;
  }
};

// Before the triangle query, each face the broad phase reaches is tested
// against three directions that often separate it from the cylinder: the
// cylinder's axis (the face wholly beyond a cap plane), the face's normal
// (the cylinder wholly on one side of the face's plane: a cylinder above a
// surface) and the direction from the axis towards the face's centroid,
// across the axis (a face beside the cylinder). Each test rejects only with
// a margin far above its rounding, so a face it rejects is truly separated
// and the triangle query, exact in its verdict, would have said so: the
// answers stay the brute force's, bit for bit (the mesh properties and the
// mesh fuzz target compare them).
//
// A direction m, whatever its rounding, separates when the face's values
// m.(v_i - p) all lie above the cylinder's largest, or all below its
// smallest: the cylinder's values are m.d / 2 +- (|m.d| / 2 + r |m x d| / |d|)
// (d = q - p, its centre at p + d / 2). Each is computed from rounded
// differences and at most a few dozen operations; with M = |m|inf,
// V = max_i |v_i - p|inf and D = |d|inf every error is below about
// 30 * 2^-53 * M * (V + D + r), and the margin is 2^-32 * M * (V + D + r),
// 2^21 / 30 times that (FaceFilter::kMargin). Used only where that scale lies within
// [2^-900, 2^900] and d.d is a normal double (no overflow; underflow's
// absolute errors, below 2^-1070 per operation, far under the margin);
// elsewhere the face goes to the triangle query.
class FaceFilter {
 public:
  explicit FaceFilter(const Cylinder& c) : p_(c.p), d_(c.q - c.p), r_(c.r) {
    const double dd = dot(d_, d_);
    usable_ = dd >= 0x1p-1000 && dd <= 0x1p900 && c.r <= 0x1p900;
    dlen_ = std::sqrt(dd);
    dmax_ = max_abs(d_);
  }
  /// The margin a face's gap must exceed (relative to its direction's scale).
  static constexpr double kMargin = 0x1p-32;
  /// True only when the face is certainly apart from the cylinder.
  bool separated(const Triangle& t) const { return gap(t, true) > kMargin; }
  /// The largest gap between the face and the cylinder along the three
  /// directions, each over its scale M (V + D + r) (positive: apart, as
  /// computed); -inf where no direction is usable. `first`: stop at the
  /// first gap above the margin.
  double gap(const Triangle& t, bool first = false) const {
    constexpr double kNone = -std::numeric_limits<double>::infinity();
    if (!usable_) return kNone;
    const Vec3 v[3] = {t.a - p_, t.b - p_, t.c - p_};
    const double reach = std::max({max_abs(v[0]), max_abs(v[1]), max_abs(v[2])}) + dmax_ + r_;
    if (!(reach <= 0x1p900)) return kNone;
    auto along = [&](Vec3 m) {
      const double scale = max_abs(m) * reach;
      if (!(scale >= 0x1p-900 && scale <= 0x1p900)) return kNone;
      const double lo = std::min({dot(m, v[0]), dot(m, v[1]), dot(m, v[2])});
      const double hi = std::max({dot(m, v[0]), dot(m, v[1]), dot(m, v[2])});
      const double md = dot(m, d_);
      const double h = 0.5 * std::fabs(md) + r_ * (detail::safe_length(cross(m, d_)) / dlen_);
      return std::max(lo - (0.5 * md + h), (0.5 * md - h) - hi) / scale;
    };
    double best = along(d_);
    if (first && best > kMargin) return best;
    best = std::max(best, along(cross(t.b - t.a, t.c - t.a)));
    if (first && best > kMargin) return best;
    const Vec3 g = (1.0 / 3.0) * (v[0] + v[1] + v[2]);
    return std::max(best, along(g - (dot(g, d_) / (dlen_ * dlen_)) * d_));
  }

 private:
  Vec3 p_, d_;
  double r_, dlen_ = 0, dmax_ = 0;
  bool usable_ = false;
};

// Visits the faces of every leaf the broad phase reaches, depth first; stops
// when visit returns true.
template <class Visit>
void traverse(const Cylinder& c, const TriangleMesh& m, Visit&& visit) {
  const detail::Bvh& h = m.bvh();
  if (h.nodes.empty()) return;
  const BroadPhase bp(c, m);
  std::uint32_t stack[64];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const detail::BvhNode& n = h.nodes[stack[--top]];
    if (!bp.meets(n)) continue;
    if (n.count > 0) {
      for (std::uint32_t i = n.first; i < n.first + n.count; ++i)
        if (visit(h.order[i])) return;
      continue;
    }
    const std::uint32_t self = static_cast<std::uint32_t>(&n - h.nodes.data());
    stack[top++] = n.right;
    stack[top++] = self + 1;
  }
}

// The deepest contact so far; the smallest index among equal depths.
struct Deepest {
  Contact best;
  std::uint32_t index = 0;
  void consider(const Contact& c, std::uint32_t i) {
    if (!c.hit) return;
    if (!best.hit || c.depth > best.depth || (c.depth == best.depth && i < index)) best = c, index = i;
  }
};

}  // namespace

bool overlap(const Cylinder& a, const TriangleMesh& b) {
  if (!is_valid(a) || !is_valid(b)) return false;
  bool hit = false;
  const FaceFilter filter(a);
  traverse(a, b, [&](std::uint32_t i) {
    const Triangle t = b.triangle(i);
    return hit = !filter.separated(t) && overlap(a, t);
  });
  return hit;
}

Contact collide(const Cylinder& a, const TriangleMesh& b, std::uint32_t* triangle) {
  if (!is_valid(a) || !is_valid(b)) return {};
  // The faces the filter keeps, each with a cheap upper bound of its depth
  // should it overlap (the overlap along +-u, +-the face normal and +-u x
  // each edge; no verdict yet), then the full collide (verdict and contact)
  // in decreasing order of the bound until the bound falls below the
  // deepest depth found: the faces skipped cannot be deeper, so the answer
  // is the brute force's, bit for bit. Most overlapping faces are never
  // decided at all.
  struct Cand {
    double bound;
    std::uint32_t index;
  };
  std::vector<Cand> cands;
  const FaceFilter filter(a);
  traverse(a, b, [&](std::uint32_t i) {
    const Triangle t = b.triangle(i);
    double bound;
    if (!filter.separated(t) && detail::depth_bound(a, t, &bound)) cands.push_back({bound, i});
    return false;
  });
  std::sort(cands.begin(), cands.end(), [](const Cand& x, const Cand& y) {
    return x.bound > y.bound || (x.bound == y.bound && x.index < y.index);
  });
  Deepest d;
  for (const Cand& c : cands) {
    if (d.best.hit && c.bound < d.best.depth) break;
    d.consider(collide(a, b.triangle(c.index)), c.index);
  }
  if (d.best.hit && triangle) *triangle = d.index;
  return d.best;
}

namespace detail {

double mesh_face_gap(const Cylinder& a, const Triangle& t) { return FaceFilter(a).gap(t); }
double mesh_face_margin() { return FaceFilter::kMargin; }

bool overlap_brute_force(const Cylinder& a, const TriangleMesh& b) {
  if (!is_valid(a) || !is_valid(b)) return false;
  for (std::size_t i = 0; i < b.size(); ++i)
    if (overlap(a, b.triangle(i))) return true;
  return false;
}

Contact collide_brute_force(const Cylinder& a, const TriangleMesh& b, std::uint32_t* triangle) {
  if (!is_valid(a) || !is_valid(b)) return {};
  Deepest d;
  for (std::size_t i = 0; i < b.size(); ++i) d.consider(collide(a, b.triangle(i)), static_cast<std::uint32_t>(i));
  if (d.best.hit && triangle) *triangle = d.index;
  return d.best;
}

}  // namespace detail

}  // namespace geomcheck
