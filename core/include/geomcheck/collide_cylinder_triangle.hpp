// geomcheck — collide_cylinder_triangle: cylinder (A) against triangle (B).
//
// Semantics: both shapes are closed solids (shapes.hpp); touching counts as
// overlapping. A degenerate triangle (collinear vertices) is its longest
// edge, a point triangle its point.
//
// Algorithm (engine talk "Cylinder Collision", triangle vs cylinder), with
// every position an offset from the cap centre p (so that a scene far from
// the origin adds no rounding of its own):
//   1. closest points of the axis segment pq and the triangle (Pcyl, Ptri);
//      their distance D > r: no overlap (the bounding capsule misses);
//   2. Ptri within the closed slab between the cap planes: overlap, Ptri is
//      in both shapes;
//   3. otherwise Ptri lies beyond a cap and within r of its centre, and the
//      shapes meet iff the triangle meets that cap's disc. (Proof: for x in
//      both, the segment x -> Ptri lies in the triangle, crosses the cap
//      plane, and the crossing is within r of the axis since both ends are.)
//      The triangle's section by the cap plane is a segment (the crossings
//      of its edges and its vertices on the plane), the whole triangle when
//      it lies in the plane, or nothing; the disc meets it iff it passes
//      within r of the cap centre.
//   The talk's own steps differ in three places, each a wrong answer here:
//   its slab test is open ((0, h), strict < r), so a triangle resting on a
//   cap or touching the side falls through; its "normal parallel to the
//   axis: distance > 0 means no hit" rejects a triangle lying in a cap plane
//   within the disc (and a degenerate triangle, whose normal is zero); and
//   it has no early reject. Step 3 is the talk's cap stage with its exact
//   zeros handled (a vertex on the plane, an edge in it, the whole triangle
//   in it).
//
// `collide` CLAIMS THE PENETRATION DEPTH: `depth` is the minimum
// translation distance and `normal` (unit, from the cylinder towards the
// triangle) its direction; `point` is Ptri (step 2) or the section point
// nearest the cap centre (step 3), in both shapes up to rounding. The
// minimising direction is the normal of a smooth patch of the Minkowski
// difference; the candidates are its patch families:
//   - cap x vertex: the axis, both ways;
//   - triangle face x cylinder: the triangle's normal, both ways;
//   - side x edge: axis x edge, both ways (the radial direction of the edge
//     line when the edge is parallel to the axis);
//   - side x vertex: the radial direction through each vertex within the
//     best overlap so far of the side;
//   - rim x edge (curved): the roots of a trigonometric polynomial of degree
//     2 in the rim angle (a quartic in tan(phi / 2), and a local cubic at
//     the tips of the rim's projection), for
//     edges passing within the best overlap so far of the rim circle (the
//     search shared with collide_cylinder_obb, detail/rim_edge.hpp).
// `depth` is always the overlap of the shapes along `normal`. The same
// depth is also a query of its own, penetration(Cylinder, Triangle)
// (penetration_cylinder_triangle.hpp).
//
// Reflections of the scene give bit-identical answers, except where the
// cylinder's axis lies exactly in the triangle's plane: there the scene is
// symmetric under the reflection in that plane, the minimal translations
// come in mirror pairs, and which one is returned depends on how the scene
// is oriented (the depth is the same up to rounding).
//
// Scale: the scene is rescaled by an exact power of two when its magnitude
// leaves [2^-100, 2^100], so every finite input is answered.
//
// Invalid input (is_valid) gives "no overlap".
#pragma once

#include "geomcheck/argument_order.hpp"
#include "geomcheck/results.hpp"
#include "geomcheck/shapes.hpp"

namespace geomcheck {

/// Do the closed cylinder and the closed triangle intersect?
bool overlap(const Cylinder& a, const Triangle& b);
/// Contact; normal from the cylinder towards the triangle (see the header comment).
Contact collide(const Cylinder& a, const Triangle& b);

}  // namespace geomcheck
