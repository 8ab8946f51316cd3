// geomcheck — collide_cylinder_obb: cylinder (A) against oriented box (B).
//
// Semantics: both shapes are closed solids (shapes.hpp); touching counts as
// overlapping. The box's axes are assumed orthonormal (either handedness);
// a box outside that contract gets an answer for some nearby box, never a
// crash.
//
// Algorithm (engine talk "Cylinder Collision", OBB vs cylinder), in box
// space (the cylinder's end points as offsets from the box centre along the
// box axes, so the box is the axis-aligned [-e, e]):
//   1. closest points of the axis segment pq and the box (Pcyl, Pbox); their
//      distance D > r: no overlap (the bounding capsule misses);
//   2. Pbox within the closed slab between the cap planes: overlap, Pbox is
//      in both shapes;
//   3. otherwise Pbox lies beyond a cap, Pcyl is that cap's centre, and the
//      shapes meet iff the box meets that cap's disc. (Proof: for x in both,
//      the segment x -> Pbox lies in the box, crosses the cap plane, and the
//      crossing is within r of the axis since both ends are.)
//   Step 3 of the talk casts one ray from Pcyl in the cap plane against the
//   three box planes through Pbox. As stated its direction (the part of
//   centre -> Pcyl across the axis) is zero, and even along Pbox's radial
//   line one ray can miss a box section that lies beside it (a false
//   "no overlap"). Here step 3 is exact instead: the box's section by the
//   cap plane is a convex polygon, its boundary is the union of the box
//   faces' sections, and the disc meets it iff the cap centre is in the box
//   or some face section passes within r of the cap centre.
//
// `collide` CLAIMS THE PENETRATION DEPTH: `depth` is the minimum
// translation distance and `normal` (unit, from the cylinder towards the
// box) its direction; `point` is Pbox (step 2) or the section point nearest
// the cap centre (step 3), in both shapes up to rounding. The penetration
// depth is the least overlap h_cyl(n) + h_box(-n) over unit n, and the
// minimising n is the normal of a smooth patch of the Minkowski difference
// (a point inside a convex body is nearest to a smooth part of its
// boundary). The patches of a cylinder and a box, hence the candidates:
//   - cap x box vertex: the axis, both ways;
//   - box face x cylinder: the box axes, both ways;
//   - side x box edge: axis x box axis, both ways;
//   - side x box vertex: the radial direction through the vertex (only for
//     vertices within the best overlap so far of the side);
//   - rim x box edge (curved): for the rim at angle theta and an edge along
//     box axis j, n(theta) is perpendicular to the rim tangent and to the
//     edge; the overlap along n(theta) has a slope proportional to a
//     trigonometric polynomial of degree 2 in theta: a quartic in
//     tan(phi / 2), whose real roots are isolated by its derivatives' and
//     refined by bracketed Newton, plus a local cubic at each tip of the
//     rim's projection where roots crowd (detail/rim_edge.hpp).
//     Only edges that pass within the best overlap so far of the rim circle
//     are searched (a minimal translation on such a patch moves that edge
//     onto the rim), and none whose own points lie that deep inside.
// `depth` is always the overlap of the shapes along `normal`. The same
// depth is also a query of its own, penetration(Cylinder, Obb)
// (penetration_cylinder_obb.hpp).
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

/// Do the closed cylinder and the closed box intersect?
bool overlap(const Cylinder& a, const Obb& b);
/// Contact; normal from the cylinder towards the box (see the header comment).
Contact collide(const Cylinder& a, const Obb& b);

}  // namespace geomcheck
