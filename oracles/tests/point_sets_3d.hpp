// geomcheck — degenerate 3D point sets shared by the predicate and
// tetrahedralization tests.
#pragma once

#include <vector>

#include "geomcheck/vec3.hpp"

namespace geomcheck::test {

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
