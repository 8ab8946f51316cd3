// geomcheck — collide_cylinder_capsule: cylinder (A) against capsule (B).
//
// Semantics: both shapes are closed solids (shapes.hpp); touching counts as
// overlapping. Write S for the capsule's segment pq and D = dist(S, C) for
// its distance to the solid cylinder C; the shapes meet iff D <= capsule.r.
//
// `collide` CLAIMS THE TRUE PENETRATION DEPTH ONLY WHILE S STAYS CLEARLY
// OUTSIDE THE CYLINDER (D > 2^-20 * scene, the usual "shallow" contact):
// then depth = r - D is the minimum translation distance, `normal` (unit,
// from the cylinder towards the capsule) is the direction from the
// cylinder's closest point to S's closest point, a minimal-translation
// direction, and `point` is that closest cylinder point. That direction is
// computed from offsets of size D carrying rounding eps * scene, so its
// angle is good to about eps * scene / D, and the capsule's length turns an
// angle into excess overlap along it (first order, unlike a sphere): the
// harness holds depth and normal to the claim where D >= 1e-6 * scale.
// When S enters the cylinder or passes within 2^-20 * scene of it ("deep"),
// depth is NOT claimed minimal: `normal` is the best of a few candidate
// directions (the direction between the closest points, the two axis
// directions, the radial direction of S's closest approach to the axis,
// the common perpendicular of S and the axis) and `depth` the overlap of
// the two shapes along it, an upper bound of the penetration depth; `point`
// is a point of S inside the cylinder (or the closest cylinder point).
// In both cases translating the capsule by depth * normal leaves the shapes
// touching (to the normal's precision), and `point` lies in both.
//
// Algorithm (engine talk "Cylinder Collision", capsule vs cylinder; not
// reduced to an augmented cylinder): closest points between S and the
// cylinder axis (the capsule test rejects and accepts early), then the
// cap regions: D is the minimum of the convex function dist(S(l), C) over
// l in [0, 1], taken over its candidates — the ends of S, the crossings of
// the cap planes and of the radius, S's closest approach to the axis line,
// and, beyond a cap and outside the radius, the closest approach to the
// rim circle (safeguarded Newton on the derivative). The contact of a
// shallow pair is the sphere contact at S's closest point.
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

/// Do the closed cylinder and the closed capsule intersect?
bool overlap(const Cylinder& a, const Capsule& b);
/// Contact (see the header comment for what depth claims); normal from the
/// cylinder towards the capsule.
Contact collide(const Cylinder& a, const Capsule& b);

}  // namespace geomcheck
