// geomcheck — penetration_cylinder_obb: the exact penetration depth of a
// cylinder (A) and an oriented box (B), and its direction.
//
// A query of its own beside collide_cylinder_obb, over the same two
// shapes: the minimum over every Minkowski patch, the closed roots of the
// curved ones included, asked and verified by that name (its own cases,
// checks, case files, fuzz target and report rows). collide(Cylinder, Obb)
// answers a consistent contact instead (the overlap along a normal near
// this one, at most 1 + 1/64 times this depth), several times faster.
//
// Semantics: as collide_cylinder_obb.hpp (closed solids, touching counts,
// the same overlap and the same contact point); `overlap` is that query's.
//
// `penetration` CLAIMS THE PENETRATION DEPTH: `depth` is the minimum
// translation distance and `normal` (unit, from the cylinder towards the
// box) its direction; `point` is collide's: Pbox (its step 2) or the section
// point nearest the cap centre (its step 3), in both shapes up to rounding. The penetration
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
// `depth` is always the overlap of the shapes along `normal`.
//
// Scale: the scene is rescaled by an exact power of two when its magnitude
// leaves [2^-100, 2^100], so every finite input is answered.
//
// Invalid input (is_valid) gives "no overlap".
#pragma once

#include "geomcheck/argument_order.hpp"
#include "geomcheck/collide_cylinder_obb.hpp"
#include "geomcheck/results.hpp"
#include "geomcheck/shapes.hpp"

namespace geomcheck {

/// The penetration depth of the cylinder and the box, with its direction
/// (unit, from the cylinder towards the box) and a point in both shapes;
/// no hit when they do not overlap (see the header comment).
Contact penetration(const Cylinder& a, const Obb& b);

}  // namespace geomcheck
