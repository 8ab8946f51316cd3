// geomcheck — collide_capsule_capsule: capsule (A) against capsule (B).
//
// Semantics: both shapes are closed solids (shapes.hpp); touching counts as
// overlapping. Write D for the distance of the two segments; the capsules
// meet iff D <= ra + rb. `collide` CLAIMS THE TRUE PENETRATION DEPTH:
// depth = ra + rb - D, which is the minimum translation distance for every
// configuration (crossing, parallel and overlapping segments included:
// detail/segment_pair.hpp says why). `normal` (unit, from A towards B) is
// the direction from A's closest segment point to B's; where the segments
// touch or cross (D = 0) it is their common perpendicular, and for parallel
// touching segments any perpendicular: each a minimal-translation direction.
// Where D is at the rounding level of the scene the closest points are not
// well defined and neither is that direction: the harness holds the normal
// to the claim where D >= 1e-6 * scale. `point` lies in both solids (the
// middle of their overlap along the normal through A's closest point).
//
// Algorithm: the crossing of the segments' lines when it lies inside both
// (its distance along their common normal), else the nearest of the four
// ends against the other segment, which is also the answer for parallel
// segments (no division by a vanishing determinant). Differences of input
// points are carried exactly and cancelling products formed with fma, so
// the normal's angle is good to a few eps whatever D (see the detail header).
//
// Zero radius (a segment) and zero length (a sphere) are valid and answered
// alike; argument order: collide(B, A) is the same contact with the normal
// flipped, up to rounding (the roles of the segments differ).
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

/// Do the two closed capsules intersect?
bool overlap(const Capsule& a, const Capsule& b);
/// Contact with the true penetration depth; normal from A towards B.
Contact collide(const Capsule& a, const Capsule& b);

}  // namespace geomcheck
