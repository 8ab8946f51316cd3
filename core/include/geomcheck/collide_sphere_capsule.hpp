// geomcheck — collide_sphere_capsule: sphere (A) against capsule (B).
//
// Semantics: both shapes are closed solids (shapes.hpp); touching counts as
// overlapping. Write D for the distance of the sphere's centre from the
// capsule's segment; they meet iff D <= ra + rb. `collide` CLAIMS THE TRUE
// PENETRATION DEPTH: depth = ra + rb - D, the minimum translation distance.
// `normal` (unit, from the sphere towards the capsule) is the direction from
// the centre to its closest segment point; with the centre on the segment
// (D = 0) any perpendicular of the segment (the z axis for a zero-length
// capsule), each a minimal-translation direction. Where D is at the
// rounding level of the scene that direction is not well defined: the
// harness holds the normal to the claim where D >= 1e-6 * scale. `point`
// lies in both solids (the middle of their overlap along the normal through
// the centre).
//
// Algorithm: the centre's projection on the segment, clamped to its ends,
// with the differences of input points carried exactly and the residual
// projected off the segment twice (detail/segment_pair.hpp): the normal's
// angle is good to a few eps whatever D.
//
// Argument order: overlap(Capsule, Sphere) and collide(Capsule, Sphere)
// below give the same verdict and the same contact with the normal flipped.
//
// Scale: the scene is rescaled by an exact power of two when its magnitude
// leaves [2^-500, 2^500], so every finite input is answered; a depth larger
// than the largest double saturates to DBL_MAX.
//
// Invalid input (is_valid) gives "no overlap".
#pragma once

#include "geomcheck/results.hpp"
#include "geomcheck/shapes.hpp"

namespace geomcheck {

/// Do the closed ball and the closed capsule intersect?
bool overlap(const Sphere& a, const Capsule& b);
/// Contact with the true penetration depth; normal from the sphere towards the capsule.
Contact collide(const Sphere& a, const Capsule& b);

/// overlap(Sphere, Capsule) in the other order: the same verdict.
inline bool overlap(const Capsule& a, const Sphere& b) { return overlap(b, a); }
/// collide(Sphere, Capsule) in the other order: the normal flipped (from
/// the capsule towards the sphere), depth and point unchanged.
inline Contact collide(const Capsule& a, const Sphere& b) { return flipped(collide(b, a)); }

}  // namespace geomcheck
