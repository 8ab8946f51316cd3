// geomcheck — collide_cylinder_cylinder: cylinder (A) against cylinder (B).
//
// Semantics: both shapes are closed solids (shapes.hpp); touching counts as
// overlapping.
//
// Algorithm (engine talk "Cylinder Collision", cylinder vs cylinder, made
// exact). Write S_A, S_B for the axis segments, u_A, u_B for the unit axes
// and theta for the angle between them.
//
//   1. The two false-positive planes: B's cap planes pushed out by A's
//      reach along u_B (r_A sin theta). Both end points of S_A beyond one of
//      them: no overlap (the plane separates). Likewise A's cap planes
//      against B. Cheap, and the early-out of most separated pairs: first
//      with r_A for r_A sin theta, before the frame is built (no square
//      root; it answers only where the exact test below would), then
//      exactly, as the cap terms of the slice test.
//   2. The frame built from both axes: z = u_B, y = u_B x u_A (the common
//      perpendicular, from a compensated cross product), x = y x z. Every
//      plane y = const contains a parallel of both axes, so it cuts A in a
//      rectangle (S_A's trace thickened by sqrt(r_A^2 - (y - y_A)^2) across
//      u_A, flat at the caps) and B in another. The engine scales x by
//      (r_A + r_B) / (r_A cos theta + r_B) so that the augmented section
//      becomes a circle and runs a segment-vs-cylinder test; that ellipse is
//      inscribed in the true section (the circle of B plus the ellipse that
//      is A's disc seen along u_B), so its answer is one-sided. Here the
//      slice is exact: the shapes meet iff some slice's two rectangles meet,
//      and by the separating axes of two rectangles that is
//          min over y of G(y) <= 0,
//      G(y) = max of four terms c_i - a_i k_A(y) - b_i k_B(y), a_i, b_i >= 0,
//      k the half widths (concave in y), so G is convex: a one-dimensional
//      convex minimisation over the y range where both slices exist. The
//      first slice tried is the engine's: where the scaled circle's section
//      is widest. The false-positive planes are the u_B terms of G.
//   3. Parallel and anti-parallel axes (the cross product exactly zero):
//      handled separately, in closed form: y = 0 through both axes, the
//      slabs along the axis and the distance between the axis lines.
//      Nearly parallel axes need no switch: the compensated cross product
//      keeps y perpendicular to both axes to rounding at every angle (a
//      plain one loses digits as 1 / theta: bench/measure/near_parallel_frame.cpp).
//
// The frame is canonical: origin B's centre, and the signs of x, y, z and
// of u_A chosen so that A's centre and direction have non-negative
// coordinates. Every representation of the same pair (caps swapped,
// reflections, point inversion, power-of-two scalings) runs the same numbers.
//
// `collide` returns a CONSISTENT contact, not the minimum translation:
// `normal` (unit, from A towards B) is the best of the fixed directions
// (-z, -x, -y, -+u_A, -+n_A towards B), the minima of the overlap on the
// two great circles of side normals (perpendicular to u_A: A's side
// against B; perpendicular to u_B: B's side against A), by safeguarded
// Newton steps on the angle (at most 8, until a step would lower the
// overlap by less than 2^-12 of it: relative to the depth, so a shallow
// contact of large cylinders is searched as far as a deep one; near the
// kink of a rim nearly across a side, a fixed step out of it first), and,
// where the common point lies within the best
// overlap so far of a cap plane of each cylinder, the rim x rim direction
// there (perpendicular to both rims' tangents: the common normal of two
// touching rims, a normal on neither circle); the best of these is then
// searched on the sphere of directions where the overlap falls off its
// circle or axis (Newton steps in the rim x rim patch, which holds the
// minimum of two rims meeting, and of stacked cylinders whose axes are
// nearly parallel; a step at most half the way to the nearer axis, where a
// side's term is a cone, and a kept step tried again doubled while it
// lowers the overlap; from the direction the rim x rim one replaced, where
// it won; for cylinders end to end, from each axis direction within 1/16
// rad of parallel, else from the axis of smaller overlap where that is
// within twice the depth so far); `depth` the overlap of the
// shapes along it (h_A(n) + h_B(-n), an upper bound of the penetration
// depth), and `point` the centre of the two rectangles' common part in the
// slice found (the corner of one least outside the other when they only
// touch), a point of both shapes up to rounding. The depth is at most 1.5
// times the penetration depth wherever that is at least 1e-9 of the scene
// (a property holds it: docs/tolerances.md; p99 1.0002 in the default
// campaign).
//
// Scale: the scene is rescaled by an exact power of two when its magnitude
// leaves [2^-100, 2^100], so every finite input is answered.
//
// Invalid input (is_valid) gives "no overlap".
#pragma once

#include "geomcheck/results.hpp"
#include "geomcheck/shapes.hpp"

namespace geomcheck {

/// Do the two closed cylinders intersect?
bool overlap(const Cylinder& a, const Cylinder& b);
/// Consistent contact (see the header comment); normal from a towards b.
Contact collide(const Cylinder& a, const Cylinder& b);

}  // namespace geomcheck
