// geomcheck — closed-form exact oracle: cylinder against sphere (and point).
//
// Exact in rationals, sqrt-free for every sign decision:
//   m = c - p, d = q - p, t = m.d, X = m x d.
//   The centre is in the cylinder iff 0 <= t <= d.d and X.X <= r^2 d.d.
//   Outside, the squared distance is ea^2 + er^2 with ea^2 rational
//   (t^2/dd or (t-dd)^2/dd) and er = rho - r, rho^2 = X.X/dd. Its sign
//   against s^2 is decided as sign(K - 2 r rho), K = ea^2 + rho^2 + r^2 - s^2,
//   by comparing K^2 with 4 r^2 rho^2 (the way CGAL's compare_quotients
//   avoids square roots).
//   Inside, the penetration depth is s + min(cap gap, side gap).
// Magnitudes (signed distance, depth, overlap along a direction) are
// certified intervals (exact.hpp), exact where no square root is involved.
#pragma once

#include "geomcheck/oracles/exact.hpp"
#include "geomcheck/oracles/solids.hpp"

namespace geomcheck::oracle {

/// Exact answer for a cylinder/sphere pair.
struct CylinderSphereTruth {
  Verdict verdict = Verdict::Undecided;
  /// Signed distance: > 0 gap, < 0 minus the penetration depth.
  QInterval signed_distance;
  /// The sphere centre lies in the closed cylinder.
  bool centre_inside = false;
};

/// Exact verdict and certified signed distance. Inputs must be valid.
CylinderSphereTruth solve_cylinder_sphere(const QCylinder& cyl, const QSphere& s);
CylinderSphereTruth solve_cylinder_sphere(const Cylinder& cyl, const Sphere& s);

/// Overlap of A and B measured along unit(n): (h_A(n) + h_B(-n)) / |n|.
/// For overlapping shapes its minimum over n is the penetration depth.
QInterval overlap_along(const QCylinder& a, const QSphere& b, const QVec& n);

}  // namespace geomcheck::oracle
