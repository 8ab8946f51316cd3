// geomcheck — what each of production's bounds measures; each query's row
// of bounds is in its spec (GEOMCHECK_SPEC in properties/src/checks_<id>.cpp).
//
// All bounds are multiples of the case's `scale` (the largest coordinate
// magnitude or extent in the case; oracle::case_scale). They mirror the
// precision table in docs/tolerances.md; tests/test_precision.cpp asserts, on a
// fixed seed, that the worst observed error of each lies in
// [bound / 100, bound], so a bound that is far too loose fails as stale.
//
//   verdict  production's yes/no may differ from the exact verdict only when
//            the certified |signed distance| <= verdict * scale (casts: when
//            the segment comes within verdict * scale of the surface, tested
//            exactly with the cylinder grown / shrunk by that much).
//   depth    |depth - true penetration depth|
//            (collide_cylinder_cylinder: the depth is an upper bound, the
//            overlap along the normal; only its shortfall below the true
//            penetration depth is an error, and it has no normal bound)
//   normal   overlap measured along production's normal minus the true
//            penetration depth (>= 0; 0 for a minimal-translation normal);
//            casts: distance of the normal from the exact outward normals
//            (normal cone at a rim) of the features within 4 t-bounds of
//            the hit point (the side's turn by that reach / r there); sweeps: the
//            reach of the cylinder along production's normal short of the
//            ball's centre at t, compared with the centre's true distance
//            (h_C(n) - n.x + dist(x, C) >= 0, zero for the true normal).
//   point    how far production's point lies outside A or B (max of both)
//            collide_cylinder_capsule: depth and normal are held to the
//            true penetration only where the header claims it (the
//            capsule's segment outside the cylinder by more than the band).
//   point    sweeps: distance from the cylinder's surface and from the
//            ball at t (max of both)
//   t        casts: distance of S(t) from the cylinder surface, and no point
//            of S([0, t]) deeper than this inside (bracketing); sweeps: the
//            same for the ball (its gap from the cylinder at t, and its path
//            up to t certified never that deep inside, by the engine)
//   unit     | |normal| - 1 | (absolute, not scaled)
//   input    not a bound: how far a subject's working precision moves the
//            input (0 for doubles; bounds_of, docs/semantics.md)
//   depth_ratio  consistent contacts (collide_cylinder_cylinder, _obb, _triangle): depth /
//            penetration depth, where that is at least 1e-9 * scale and
//            enclosed within 1% (a ratio, not scaled; 0: no bound). A case
//            whose depth certainly exceeds it fails like any property.
// Errors below the resolution of a double output (4 x the smallest
// subnormal) are not counted: in a subnormal scene no answer is finer.
#pragma once

#include "geomcheck/registry.hpp"

namespace geomcheck {

/// The bounds of one query (multiples of scale, but `unit`).
struct Tolerances {
  double verdict;
  double depth;
  double normal;
  double point;
  double t;
  double unit;
  double depth_ratio = 0;
  /// How far the subject's working precision moves the input (a multiple
  /// of scale): 0 for doubles, the unit roundoff u for a narrower type
  /// (each coordinate rounded to it). Directions the subject derives from
  /// the input turn by it over a feature's size (a cast's cap normal by
  /// 2 input / L over an axis of length L); bounds_of sets it.
  double input = 0;
};

/// Bounds per query id.
/// Production's bounds of query `id`: the row in its spec (GEOMCHECK_SPEC,
/// at the head of properties/src/checks_<id>.cpp).
Tolerances tolerances(QueryId id);

}  // namespace geomcheck
