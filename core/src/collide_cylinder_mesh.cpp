#include "geomcheck/collide_cylinder_mesh.hpp"

#include <algorithm>
#include <cmath>
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
  traverse(a, b, [&](std::uint32_t i) { return hit = overlap(a, b.triangle(i)); });
  return hit;
}

Contact collide(const Cylinder& a, const TriangleMesh& b, std::uint32_t* triangle) {
  if (!is_valid(a) || !is_valid(b)) return {};
  // The overlapping faces with a cheap upper bound of their depth (the
  // overlap along +-u, +-the face normal and +-u x each edge), then the full collide in
  // decreasing order of the bound until the bound falls below the deepest
  // depth found: the faces skipped cannot be deeper, so the answer is the
  // brute force's, bit for bit.
  struct Cand {
    double bound;
    std::uint32_t index;
  };
  std::vector<Cand> cands;
  traverse(a, b, [&](std::uint32_t i) {
    double bound;
    if (detail::overlap_with_depth_bound(a, b.triangle(i), &bound)) cands.push_back({bound, i});
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
