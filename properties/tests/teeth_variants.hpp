// geomcheck — known-wrong variants of production (test tree only).
#pragma once

#include "geomcheck/properties/checks.hpp"

namespace geomcheck::teeth {

/// collide_cylinder_sphere computed as sphere vs capsule (round caps).
extern const CylinderSphereImpl kCapsuleForCylinder;
/// cast_segment_cylinder against the infinite cylinder, no cap test.
extern const CastSegmentCylinderImpl kInfiniteCylinder;
/// cast_segment_cylinder as printed in the book (known errata).
extern const CastSegmentCylinderImpl kEricsonPrinted;

}  // namespace geomcheck::teeth
