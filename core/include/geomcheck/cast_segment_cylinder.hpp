// geomcheck — cast_segment_cylinder: segment cast (line query) against a cylinder.
//
// Semantics: the segment S(t) = a + t (b - a), t in [0, 1], against the
// closed solid cylinder. The result is the FIRST t at which S(t) lies in the
// cylinder. If the start a is already in the cylinder (touching included):
// t = 0, `starts_inside`, point = a, normal = zero vector. Otherwise the hit
// is on the surface: `normal` is the cylinder's outward normal there (+-axis
// on a cap, radial on the side; at a rim either is acceptable).
//
// Algorithm: Ericson, Real-Time Collision Detection, IntersectSegmentCylinder
// (p. 197), as used by the engine ("Line vs Cylinder"): the quadratic in t
// for the infinite cylinder, then the end-cap disks for hits beyond P or Q.
// Differences from the printed form, each a known weakness of it:
//   * the quadratic's coefficients are built from cross products (|n x d|^2,
//     (m x d).(n x d), |m x d|^2 - r^2 |d|^2) instead of differences of
//     products, which cancel catastrophically far from the axis origin;
//   * everything is measured along the unit axis u and the axis length L
//     (d = L u): the printed coefficients are these times L^2 with the same
//     roots, and no power of |d| is formed, so a disk far thinner than the
//     scene cannot underflow them (regression 0005);
//   * the discriminant b^2 - ac is evaluated in a form that cannot cancel:
//     b^2 + a|c| when the start is inside the infinite cylinder, and
//     r^2 |n x u|^2 - (n.(m x u))^2 (Lagrange's identity) otherwise, where
//     b^2 - ac cancels catastrophically for lines passing near the axis
//     (regressions 0001, 0003);
//   * the entry root is taken in the stable form c / (-b + sqrt(disc)), so
//     there is no absolute "parallel" epsilon and the method is scale free;
//   * a start inside the cylinder returns t = 0 (the printed form rejects the
//     negative root and reports a miss);
//   * the cap disks and the side are not accepted feature by feature: the
//     hit is the first t of the intersection of the slab between the cap
//     planes with the infinite cylinder's interval (entry = max of the two
//     entries, exit = min of the exits). The printed feature tests miss cap
//     entries whose side root lies before t = 0, use k + 2t(mn + t nn) for
//     the p cap (should be k + t(2 mn + t nn)), and leave a gap at the rim
//     where both tests can reject by one rounding (regression 0002).
//
// Invalid input (is_valid) gives "no hit".
#pragma once

#include "geomcheck/results.hpp"
#include "geomcheck/shapes.hpp"

namespace geomcheck {

/// First hit of segment `s` (from s.a towards s.b) with the solid cylinder.
CastHit cast(const Segment& s, const Cylinder& c);

}  // namespace geomcheck
