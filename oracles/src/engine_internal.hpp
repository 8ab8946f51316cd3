// geomcheck — certified convex engine: internals shared by its translation units.
#pragma once

#include <array>
#include <optional>

#include "geomcheck/oracles/engine.hpp"

namespace geomcheck::oracle {

inline bool is_zero(const QVec& v) { return v.x == 0 && v.y == 0 && v.z == 0; }

/// Double bracket [lo, hi] of a rational (one-ulp wide unless exact).
void bracket(const Q& q, double& lo, double& hi);

/// Exact sign of alpha + beta*sqrt(u) + gamma*sqrt(v) (beta, gamma, u, v >= 0).
int sign_sqrt2(const Q& alpha, const Q& beta, const Q& u, const Q& gamma, const Q& v);
/// max over the core points of n.p.
Q core_max(const ConvexShape& s, const QVec& n);
/// h(n) = core_max(n) + beta*sqrt(u).
void round_term(const ConvexShape& s, const QVec& n, Q& beta, Q& u);
/// det(p1 - p0, p2 - p0, p3 - p0).
Q signed_volume(const QVec& p0, const QVec& p1, const QVec& p2, const QVec& p3);
/// Origin strictly inside the tetrahedron w (exact).
bool origin_strictly_inside(const std::array<QVec, 4>& w);
/// check_overlap; `trust_members` skips containment (points built inside by
/// construction, e.g. of a swept hull which has no containment test).
bool check_overlap_impl(const ConvexShape& a, const ConvexShape& b, const OverlapCertificate& c, bool trust_members);

/// The point s.points[i] + radius * v built for a support point whose
/// radial direction the search gave as w = hi + lo (two doubles a
/// coordinate), exactly inside the shape: |v| <= 1 checked exactly, and for
/// a disc v = a x t, exactly perpendicular to the axis a. Integer arithmetic
/// on `bits`-bit approximations (no rational canonicalisation); nothing when
/// the shape's data is not dyadic or the exact norm check fails (the caller
/// then builds the point in rationals).
std::optional<QVec> radial_point_dyadic(const ConvexShape& s, int i, const Vec3& hi, const Vec3& lo, int bits);

}  // namespace geomcheck::oracle
