// geomcheck — sweep_sphere_cylinder: a moving sphere against a cylinder.
//
// Semantics: the closed ball of radius s centred at c(t) = c + t delta,
// t in [0, 1], against the closed solid cylinder. The result is the FIRST t
// at which the ball touches the cylinder. If the ball already meets the
// cylinder at t = 0 (touching included): t = 0, `starts_inside`, point = the
// cylinder point closest to c (collide(Cylinder, Sphere).point), normal =
// zero vector. Otherwise `point` is the contact point on the cylinder's
// surface and `normal` the cylinder's outward normal there, pointing to the
// ball's centre (+-axis on a cap, radial on the side, in between at a rim).
//
// Algorithm (engine talk "Cylinder Collision", swept sphere vs cylinder),
// two stages:
//   1. the segment c -> c + delta against the AUGMENTED cylinder (radius
//      r + s, axis extended by s at both ends), with the robust segment
//      cast of cast_segment_cylinder. No hit: no contact.
//   2. the hit is a false positive candidate when it lies in a corner
//      region (beyond a cap plane by its axial offset from the mid point,
//      and outside the radius): there the ball meets the cylinder at a rim
//      point. The rim point is the stage-1 point clamped to the cylinder's
//      radius and axial extent, and the ball is swept against it.
// Stage 2 as the talk states it (one sphere test against one rim point)
// misses grazing contacts and reports contacts late: the rim point of the
// true contact differs from the clamped stage-1 point. Here stage 2 repeats
// the clamp from the current position: Newton steps on the convex function
// g(t) = dist(c(t), cylinder) - s, each against the plane tangent to the
// ball around the current rim point. On a convex function, Newton from the
// left never passes the first root, so t never overshoots the contact; a
// non-negative slope with g > 0 proves a miss.
//
// Scale: the scene is rescaled by an exact power of two when its magnitude
// leaves [2^-100, 2^100], so every finite input is answered.
//
// Invalid input (is_valid; an end position c + delta that overflows is
// invalid) gives "no hit".
#pragma once

#include "geomcheck/results.hpp"
#include "geomcheck/shapes.hpp"

namespace geomcheck {

/// First contact of the ball `s` moving by `delta` with the solid cylinder.
CastHit sweep(const Sphere& s, Vec3 delta, const Cylinder& c);
/// The same, the moving ball given as one value.
inline CastHit sweep(const MovingSphere& m, const Cylinder& c) { return sweep(Sphere{m.c, m.r}, m.delta, c); }

}  // namespace geomcheck
