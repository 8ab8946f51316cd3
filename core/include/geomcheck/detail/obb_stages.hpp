// geomcheck — internal: the cylinder/box query with a chosen cap stage, so
// that the test tree can hold the stages that production does not use to
// the same properties (properties/src/teeth.cpp).
#pragma once

#include "geomcheck/results.hpp"
#include "geomcheck/shapes.hpp"

namespace geomcheck::detail {

enum class ObbCapStage {
  Capsule,   ///< no cap stage: the bounding capsule's answer (box vs capsule)
  TalkRays,  ///< the talk's step 3: one radial ray against the planes through Pbox
  Exact,     ///< production: the cap disc against the box's section
};

/// overlap(Cylinder, Obb) with the given cap stage (see collide_cylinder_obb.hpp).
bool overlap_with_stage(const Cylinder& cyl, const Obb& box, ObbCapStage stage);
/// The exact penetration contact (penetration(Cylinder, Obb)) with the given cap stage.
Contact collide_with_stage(const Cylinder& cyl, const Obb& box, ObbCapStage stage);
/// collide(Cylinder, Obb), the consistent contact; without `refine`, no EPA
/// step on the circles of normals (the best of the closed-form candidates
/// only).
Contact collide_consistent(const Cylinder& cyl, const Obb& box, bool refine = true);

}  // namespace geomcheck::detail
