// geomcheck — the hand cases the engines' tests share (test_fcl_adapter,
// test_peer_ode): three cylinders whose answers are worked out by hand, and
// the tolerances a hand case is checked to.
#pragma once

#include <cmath>

#include "geomcheck/shapes.hpp"

namespace geomcheck::peers {

// Cylinder along z from z = -1 to z = 1, radius 1.
inline const Cylinder kZ{{0, 0, -1}, {0, 0, 1}, 1.0};
// The same solid with the caps swapped (axis -z): the anti-parallel rotation.
inline const Cylinder kZFlipped{{0, 0, 1}, {0, 0, -1}, 1.0};
// An oblique cylinder away from the origin: axis (2, 3, 6)/7, length 7,
// radius 0.5.
inline const Cylinder kOblique{{10, -4, 3}, {12, -1, 9}, 0.5};
// kOblique's mid-point, unit axis, and a unit perpendicular to the axis,
// (3, -2, 0)/sqrt(13).
inline const Vec3 kObliqueMid{11, -2.5, 6};
inline const Vec3 kObliqueAxis = (1.0 / 7) * Vec3{2, 3, 6};
inline const Vec3 kObliquePerp = (1.0 / std::sqrt(13.0)) * Vec3{3, -2, 0};

/// Tolerances of a hand case: on the depth and on the normal's direction.
struct Tol {
  double depth, normal;
};

}  // namespace geomcheck::peers
