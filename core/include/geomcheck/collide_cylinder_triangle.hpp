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
// `collide` is a CONSISTENT CONTACT, not the minimal translation: `depth`
// is the overlap of the shapes along `normal` (unit, from the cylinder
// towards the triangle), h_cyl(n) + h_tri(-n), so it is never below the
// penetration depth, and by construction at most (1 + 1/64) times it (to
// rounding); `point` is Ptri (step 2) or the section point nearest the cap
// centre (step 3), in both shapes up to rounding. The penetration depth is
// the least overlap over unit n, taken at a boundary point of the Minkowski
// difference with a single normal; such normals are
//   - cap x vertex: the axis, both ways;
//   - side x vertex: the radial direction through the vertex;
//   - every other one is perpendicular to an edge e (the triangle's face,
//     side x edge, rim x edge).
// The first two are offered exactly. On the circle n . e = 0 the overlap
// is the support function of the shapes' projection along e (the
// triangle's projection, a segment, plus the hull of the caps' two
// ellipses: a convex body containing the origin), so its least value there
// is the distance from the origin to that body's boundary, found as EPA
// finds it in the plane: the support points along the face's normal, the
// edge's normal in the face and the directions across u span a polygon
// inside the body, whose nearest edge bounds the distance from below, and
// the support along that edge's normal is a new vertex and an overlap (from
// above). A circle is refined until (1 + 1/64) times its lower bound
// reaches the least overlap found (at most 64 steps per circle); each
// circle is refined against the same bound and its frame is made from its
// edge alone, so rotating or reversing the vertices, or swapping the caps,
// changes no depth, and a reflection of the scene reflects the answer bit
// for bit (as below). A degenerate triangle (collinear vertices, to 2^-30
// of their offsets) has no circle frames; its contact is the exact minimum.
// The exact minimum, with its direction, is the query
// penetration(Cylinder, Triangle) (penetration_cylinder_triangle.hpp): the
// same candidates but the circles, whose rim x edge minima it finds as the
// roots of a trigonometric polynomial of degree 2 in the rim angle (a
// quartic in tan(phi / 2), and a local cubic at the tips of the rim's
// projection), for edges passing within the best overlap so far of the rim
// circle (the search shared with penetration_cylinder_obb,
// detail/rim_edge.hpp).
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
