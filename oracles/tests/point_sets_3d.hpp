// geomcheck — helpers of the point-set tests (predicates, tetrahedralization,
// hull): degenerate 3D point sets, ulp moves, and points printed bit-exact
// in RapidCheck's counterexamples.
#pragma once

#include <cmath>
#include <cstdio>
#include <ostream>
#include <vector>

#include "geomcheck/vec3.hpp"

namespace geomcheck {
/// Counterexamples print bit-exact (hex floats).
inline void showValue(const Vec3& p, std::ostream& os) {
  char buf[128];
  std::snprintf(buf, sizeof buf, "(%a, %a, %a)", p.x, p.y, p.z);
  os << buf;
}
}  // namespace geomcheck

namespace geomcheck::test {

/// x moved by k ulps (k < 0: down).
inline double ulps(double x, int k) {
  for (; k > 0; --k) x = std::nextafter(x, INFINITY);
  for (; k < 0; ++k) x = std::nextafter(x, -INFINITY);
  return x;
}

/// The integer points of the sphere |p|^2 = 325 about the origin (168 of
/// them: 325 = 1 + 324 = 36 + 289 = 100 + 225 = ... has many
/// representations as a sum of squares).
inline std::vector<Vec3> integer_sphere_points() {
  std::vector<Vec3> p;
  for (int x = -18; x <= 18; ++x)
    for (int y = -18; y <= 18; ++y)
      for (int z = -18; z <= 18; ++z)
        if (x * x + y * y + z * z == 325) p.push_back({double(x), double(y), double(z)});
  return p;
}

}  // namespace geomcheck::test
