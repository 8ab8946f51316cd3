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
// `collide` is a CONSISTENT CONTACT, not the minimal translation: `depth`
// is the overlap of the shapes along `normal` (unit, from the cylinder
// towards the box), h_cyl(n) + h_box(-n), so it is never below the
// penetration depth, and by construction at most (1 + 1/64) times it (to
// rounding); `point` is Pbox (step 2) or the section point nearest the cap
// centre (step 3), in both shapes up to rounding. The penetration depth is
// the least overlap over unit n, taken at a boundary point of the Minkowski
// difference with a single normal; such normals are
//   - cap x box vertex: the axis, both ways;
//   - side x box vertex: the radial direction through the vertex;
//   - every other one lies on a circle n_j = 0 of a box axis j (box face,
//     side x box edge, rim x box edge).
// The first two are offered exactly. On the circle n_j = 0 the overlap is
// the support function of the shapes' projection along box axis j (the
// box's rectangle plus the hull of the caps' two ellipses, a convex body
// containing the origin), so its least value there is the distance from the
// origin to that body's boundary, found as EPA finds it in the plane: the
// support points along the axis directions and the directions across u
// span a polygon inside the body, whose nearest edge bounds the distance
// from below, and the support along that edge's normal is a new vertex and
// an overlap (from above). A circle is refined until (1 + 1/64) times its
// lower bound reaches the least overlap found (at most 64 steps per
// circle); each circle is refined against the same bound, so the box axes'
// order changes no answer. The exact minimum, with its direction, is the
// query penetration(Cylinder, Obb) (penetration_cylinder_obb.hpp).
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
