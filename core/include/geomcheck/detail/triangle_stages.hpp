// geomcheck — internal: the cylinder/triangle query with a chosen cap stage,
// so that the test tree can hold the stages that production does not use to
// the same properties (properties/src/teeth.cpp).
#pragma once

#include "geomcheck/results.hpp"
#include "geomcheck/shapes.hpp"

namespace geomcheck::detail {

enum class TriCapStage {
  None,   ///< no cap stage: Ptri beyond a cap means "no overlap" (the talk's steps 1 and 2 only)
  Exact,  ///< production: the cap disc against the triangle's section by the cap plane
};

/// overlap(Cylinder, Triangle) with the given cap stage (see collide_cylinder_triangle.hpp).
bool overlap_with_stage(const Cylinder& cyl, const Triangle& tri, TriCapStage stage);
/// The exact penetration contact (penetration(Cylinder, Triangle)) with the given cap stage.
Contact collide_with_stage(const Cylinder& cyl, const Triangle& tri, TriCapStage stage);
/// collide(Cylinder, Triangle), the consistent contact; without `refine`,
/// no EPA step on the circles of normals (the best of the closed-form
/// candidates only).
Contact collide_consistent(const Cylinder& cyl, const Triangle& tri, bool refine = true);

/// For valid shapes (false otherwise), in *bound a value never below
/// collide(cyl, tri).depth where they overlap, bit for bit (the least
/// overlap along +-u, +-the triangle's normal and +-u x each edge,
/// candidates collide itself takes, computed and scaled back the same way;
/// clamped to >= 0; collide's depth never exceeds it). The verdict is not decided here: the mesh query runs
/// the full collide in decreasing order of the bound and skips every face
/// whose bound is below the deepest depth already found.
bool depth_bound(const Cylinder& cyl, const Triangle& tri, double* bound);

}  // namespace geomcheck::detail
