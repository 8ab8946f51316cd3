// geomcheck — penetration_cylinder_triangle: the exact penetration depth of a
// cylinder (A) and a triangle (B), and its direction.
//
// A query of its own beside collide_cylinder_triangle, over the same two
// shapes: the minimum over every Minkowski patch, the closed roots of the
// curved ones included, asked and verified by that name (its own cases,
// checks, case files, fuzz target and report rows). collide(Cylinder,
// Triangle) is a consistent contact instead (at most 1 + 1/64 times this
// depth, and faster), but for a degenerate triangle, where it answers this
// contact bit for bit.
//
// Semantics: as collide_cylinder_triangle.hpp (closed solids, touching counts,
// the same overlap and the same contact point); `overlap` is that query's.
//
// `penetration` CLAIMS THE PENETRATION DEPTH: `depth` is the minimum
// translation distance and `normal` (unit, from the cylinder towards the
// triangle) its direction; `point` is collide's: Ptri (its step 2) or the section
// point nearest the cap centre (its step 3), in both shapes up to rounding. The
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
//     search shared with penetration_cylinder_obb, detail/rim_edge.hpp).
// `depth` is always the overlap of the shapes along `normal`.
//
// Scale: the scene is rescaled by an exact power of two when its magnitude
// leaves [2^-100, 2^100], so every finite input is answered.
//
// Reflections of the scene give bit-identical answers, except where the
// cylinder's axis lies exactly in the triangle's plane: there the scene is
// symmetric under the reflection in that plane, the minimal translations
// come in mirror pairs, and which one is returned depends on how the scene
// is oriented (the depth is the same up to rounding).
//
//
// Invalid input (is_valid) gives "no overlap".
#pragma once

#include "geomcheck/argument_order.hpp"
#include "geomcheck/collide_cylinder_triangle.hpp"
#include "geomcheck/results.hpp"
#include "geomcheck/shapes.hpp"

namespace geomcheck {

/// The penetration depth of the cylinder and the triangle, with its direction
/// (unit, from the cylinder towards the triangle) and a point in both shapes;
/// no hit when they do not overlap (see the header comment).
Contact penetration(const Cylinder& a, const Triangle& b);

}  // namespace geomcheck
