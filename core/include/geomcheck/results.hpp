// geomcheck — result types shared by every query.
#pragma once

#include "geomcheck/vec3.hpp"

namespace geomcheck {

/// Result of a full ("collide") query between solids A and B.
///
/// When `hit`: `normal` is unit and points from A towards B; translating B by
/// `depth * normal` leaves the shapes touching; `depth >= 0` is the overlap
/// of A and B measured along `normal` (max over A of n.x - min over B of n.x);
/// `point` lies in A and B. When not `hit` the other fields are zero.
struct Contact {
  bool hit = false;
  Vec3 point;
  Vec3 normal;
  double depth = 0;
};

/// Result of a cast (moving segment start) or sweep (moving sphere) query.
///
/// When `hit`: `t` in [0, 1] is the first parameter at which the moving thing
/// touches B; `point` is the contact point; `normal` is B's outward surface
/// normal there; `starts_inside` when t == 0 because the start already
/// overlaps B (then `normal` is the zero vector: there is no single surface).
struct CastHit {
  bool hit = false;
  double t = 0;
  Vec3 point;
  Vec3 normal;
  bool starts_inside = false;
};

/// B's contact seen from the other side: the normal flips.
inline Contact flipped(Contact c) {
  c.normal = -c.normal;
  return c;
}

}  // namespace geomcheck
