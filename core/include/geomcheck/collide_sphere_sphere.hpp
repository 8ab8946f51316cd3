// geomcheck — collide_sphere_sphere: sphere (A) against sphere (B).
//
// Semantics: both shapes are closed balls (shapes.hpp); touching counts as
// overlapping. With D = |cb - ca| they meet iff D <= ra + rb. `collide`
// CLAIMS THE TRUE PENETRATION DEPTH: depth = ra + rb - D, the minimum
// translation distance; `normal` (unit, from A towards B) is (cb - ca) / D,
// and (0, 0, 1) for concentric balls (any direction is minimal then).
// `point` lies in both balls (the middle of their overlap along the normal
// through A's centre).
//
// Algorithm: the difference of the centres (carried exactly), its length
// with the squares kept in range; overlap and collide decide by the same
// D, so they agree bit for bit.
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

/// Do the two closed balls intersect?
bool overlap(const Sphere& a, const Sphere& b);
/// Contact with the true penetration depth; normal from A towards B.
Contact collide(const Sphere& a, const Sphere& b);

}  // namespace geomcheck
