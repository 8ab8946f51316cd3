// geomcheck — internal: the swept-sphere query with a chosen stage 2, so
// that the test tree can hold the stages that production does not use to
// the same properties (properties/src/teeth.cpp).
#pragma once

#include "geomcheck/results.hpp"
#include "geomcheck/shapes.hpp"

namespace geomcheck::detail {

enum class SweepStage2 {
  None,          ///< stage 1 only: every augmented-cylinder hit is accepted
  TalkRimPoint,  ///< the talk's stage 2: one sphere test at the clamped stage-1 point
  Newton,        ///< production: repeated clamps, Newton on dist(c(t), C) - s
};

/// sweep(Sphere, delta, Cylinder) with the given stage 2 (see sweep_sphere_cylinder.hpp).
CastHit sweep_with(const Sphere& s, Vec3 delta, const Cylinder& c, SweepStage2 stage2);

}  // namespace geomcheck::detail
