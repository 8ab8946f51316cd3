// geomcheck benchmarks — the 3D point sets that bench_delaunay_3d and
// bench_convex_hull_3d share (uniform in a box, scaled by a power of two;
// rounded onto the unit sphere; the integer grid), each drawn from its own
// seeded generator, and their conversion to CGAL points.
#pragma once

#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "geomcheck/vec3.hpp"

namespace geomcheck::bench3d {

/// n points uniform in [lo, hi)^3, times 2^e.
inline std::vector<Vec3> uniform(std::size_t n, double lo, double hi, int e, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(lo, hi);
  std::vector<Vec3> p(n);
  for (Vec3& q : p) q = {std::ldexp(u(rng), e), std::ldexp(u(rng), e), std::ldexp(u(rng), e)};
  return p;
}

/// n normal directions scaled to length 1 (rounded onto the unit sphere:
/// every point on the hull, nearly every in-sphere test a near-tie).
inline std::vector<Vec3> sphere(std::size_t n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> g(0, 1);
  std::vector<Vec3> p(n);
  for (Vec3& q : p) {
    const Vec3 v{g(rng), g(rng), g(rng)};
    q = (1 / length(v)) * v;
  }
  return p;
}

/// The integer grid {0..m-1}^3 (coplanar faces; every cube's corners cospherical).
inline std::vector<Vec3> grid(int m) {
  std::vector<Vec3> p;
  p.reserve(static_cast<std::size_t>(m) * m * m);
  for (int x = 0; x < m; ++x)
    for (int y = 0; y < m; ++y)
      for (int z = 0; z < m; ++z) p.push_back({double(x), double(y), double(z)});
  return p;
}

/// The same points as CGAL points of kernel K.
template <class K>
std::vector<typename K::Point_3> cgal_points(const std::vector<Vec3>& p) {
  std::vector<typename K::Point_3> out;
  out.reserve(p.size());
  for (const Vec3& q : p) out.emplace_back(q.x, q.y, q.z);
  return out;
}

}  // namespace geomcheck::bench3d
