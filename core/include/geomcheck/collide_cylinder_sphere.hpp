// geomcheck — collide_cylinder_sphere: cylinder (A) against sphere (B).
//
// Semantics: both shapes are closed solids (shapes.hpp); touching counts as
// overlapping. `collide` CLAIMS THE TRUE PENETRATION DEPTH: when the shapes
// overlap, `depth` is the minimum translation distance and `normal` (unit,
// from the cylinder towards the sphere) is a minimal-translation direction;
// `point` lies in both solids (the closest cylinder point to the sphere
// centre, or the centre itself when it is inside the cylinder).
//
// Algorithm (engine talk "Cylinder Collision", sphere vs cylinder): axial
// and radial offsets of the sphere centre from the cylinder's mid point;
// branch on inside the slab / beyond a cap / beyond the rim. Outside, the
// closest cylinder point gives distance and normal; inside, the nearer of
// the cap and side exits gives the depth.
//
// Scale: the scene is rescaled by an exact power of two when its magnitude
// leaves [2^-100, 2^100], so every finite input is answered; a depth larger
// than the largest double saturates to DBL_MAX.
//
// Invalid input (is_valid) gives "no overlap".
#pragma once

#include "geomcheck/argument_order.hpp"
#include "geomcheck/results.hpp"
#include "geomcheck/shapes.hpp"

namespace geomcheck {

/// Do the closed cylinder and the closed ball intersect?
bool overlap(const Cylinder& a, const Sphere& b);
/// Contact with true penetration depth; normal from the cylinder to the sphere.
Contact collide(const Cylinder& a, const Sphere& b);

}  // namespace geomcheck
