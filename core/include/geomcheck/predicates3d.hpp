// geomcheck — exact 3D predicates on doubles: orientation and in-sphere,
// the tests a 3D Delaunay tetrahedralization and a convex hull are built on.
//
// Every answer is the sign of the exact determinant of the input doubles
// (no tolerance, no perturbation), for every finite input:
//   1. a floating-point filter (Shewchuk's static bounds o3derrboundA and
//      isperrboundA, which cover the rounding of the differences as well);
//      it answers when the computed value is farther from zero than the
//      bound, nothing overflowed and no product could underflow (every
//      non-zero coordinate difference at least kOrient3dDiffFloor,
//      kInsphereDiffFloor: a product of three, or of five, is then normal);
//   (then, out of line:)
//   2. the same filter on the points scaled by one power of two, their
//      largest magnitude into [1, 2), where that scaling is exact: a set far
//      from 1 in scale answers as fast as one near it;
//   3. the determinant in doubles with every step checked error-free
//      (integer grids and other small exact coordinates: the common
//      degenerate input);
//   4. otherwise exact big integers on the coordinates scaled to integers by
//      one power of two (core/src/exact_integers.hpp, as the 2D predicates'
//      last stage), which cover any mix of magnitudes (1e300 beside 1e-300).
// Scaling every point by the same power of two changes no answer, and
// neither does translating by a vector whose sums are exact.
// The caller checks finiteness (non-finite input has no exact answer: the
// result is then unspecified but the call returns).
#pragma once

#include <cmath>
#include <limits>

#include "geomcheck/predicates2d.hpp"  // detail::FilterValue, GEOMCHECK_PREDICATE_INLINE
#include "geomcheck/vec3.hpp"

namespace geomcheck {

namespace detail {
inline constexpr double kO3dErrBoundA = (7.0 + 56.0 * kPredEps) * kPredEps;
inline constexpr double kIspErrBoundA = (16.0 + 224.0 * kPredEps) * kPredEps;
/// orient3d multiplies three differences: each non-zero one at least 2^-300
/// keeps every product at least 2^-900, normal (an underflowing product's
/// absolute error is not covered by a bound relative to the permanent).
inline constexpr double kOrient3dDiffFloor = 0x1p-300;
/// insphere multiplies five: at least 2^-200 each keeps them above 2^-1000.
inline constexpr double kInsphereDiffFloor = 0x1p-200;
GEOMCHECK_PREDICATE_INLINE bool diff_at_least(double v, double floor) { return v == 0 || std::fabs(v) >= floor; }
GEOMCHECK_PREDICATE_INLINE bool diffs_at_least(Vec3 v, double floor) {
  return diff_at_least(v.x, floor) && diff_at_least(v.y, floor) && diff_at_least(v.z, floor);
}

/// orient3d's filter: det [a - d; b - d; c - d] in doubles, bound
/// o3derrboundA times its permanent; usable when the permanent is finite
/// and every non-zero difference is at least kOrient3dDiffFloor.
GEOMCHECK_PREDICATE_INLINE FilterValue orient3d_filter(Vec3 a, Vec3 b, Vec3 c, Vec3 d) {
  const Vec3 ad = a - d, bd = b - d, cd = c - d;
  const double bdxcdy = bd.x * cd.y, cdxbdy = cd.x * bd.y;
  const double cdxady = cd.x * ad.y, adxcdy = ad.x * cd.y;
  const double adxbdy = ad.x * bd.y, bdxady = bd.x * ad.y;
  const double det = ad.z * (bdxcdy - cdxbdy) + bd.z * (cdxady - adxcdy) + cd.z * (adxbdy - bdxady);
  const double permanent = (std::fabs(bdxcdy) + std::fabs(cdxbdy)) * std::fabs(ad.z) +
                           (std::fabs(cdxady) + std::fabs(adxcdy)) * std::fabs(bd.z) +
                           (std::fabs(adxbdy) + std::fabs(bdxady)) * std::fabs(cd.z);
  return {det, kO3dErrBoundA * permanent,
          permanent <= std::numeric_limits<double>::max() && diffs_at_least(ad, kOrient3dDiffFloor) &&
              diffs_at_least(bd, kOrient3dDiffFloor) && diffs_at_least(cd, kOrient3dDiffFloor)};
}

/// insphere's filter: the lifted 4x4 determinant in doubles (Shewchuk's
/// expression), bound isperrboundA times its permanent; usable when the
/// permanent is finite and every non-zero difference is at least
/// kInsphereDiffFloor.
GEOMCHECK_PREDICATE_INLINE FilterValue insphere_filter(Vec3 a, Vec3 b, Vec3 c, Vec3 d, Vec3 e) {
  const Vec3 ae = a - e, be = b - e, ce = c - e, de = d - e;
  const double aexbey = ae.x * be.y, bexaey = be.x * ae.y, bexcey = be.x * ce.y, cexbey = ce.x * be.y;
  const double cexdey = ce.x * de.y, dexcey = de.x * ce.y, dexaey = de.x * ae.y, aexdey = ae.x * de.y;
  const double aexcey = ae.x * ce.y, cexaey = ce.x * ae.y, bexdey = be.x * de.y, dexbey = de.x * be.y;
  const double ab = aexbey - bexaey, bc = bexcey - cexbey, cd = cexdey - dexcey, da = dexaey - aexdey;
  const double ac = aexcey - cexaey, bd = bexdey - dexbey;
  const double abc = ae.z * bc - be.z * ac + ce.z * ab;
  const double bcd = be.z * cd - ce.z * bd + de.z * bc;
  const double cda = ce.z * da + de.z * ac + ae.z * cd;
  const double dab = de.z * ab + ae.z * bd + be.z * da;
  const double alift = ae.x * ae.x + ae.y * ae.y + ae.z * ae.z;
  const double blift = be.x * be.x + be.y * be.y + be.z * be.z;
  const double clift = ce.x * ce.x + ce.y * ce.y + ce.z * ce.z;
  const double dlift = de.x * de.x + de.y * de.y + de.z * de.z;
  const double det = (dlift * abc - clift * dab) + (blift * cda - alift * bcd);
  const double az = std::fabs(ae.z), bz = std::fabs(be.z), cz = std::fabs(ce.z), dz = std::fabs(de.z);
  const double p_ab = std::fabs(aexbey) + std::fabs(bexaey), p_bc = std::fabs(bexcey) + std::fabs(cexbey);
  const double p_cd = std::fabs(cexdey) + std::fabs(dexcey), p_da = std::fabs(dexaey) + std::fabs(aexdey);
  const double p_ac = std::fabs(aexcey) + std::fabs(cexaey), p_bd = std::fabs(bexdey) + std::fabs(dexbey);
  const double permanent = (p_cd * bz + p_bd * cz + p_bc * dz) * alift + (p_da * cz + p_ac * dz + p_cd * az) * blift +
                           (p_ab * dz + p_bd * az + p_da * bz) * clift + (p_bc * az + p_ac * bz + p_ab * cz) * dlift;
  return {det, kIspErrBoundA * permanent,
          permanent <= std::numeric_limits<double>::max() && diffs_at_least(ae, kInsphereDiffFloor) &&
              diffs_at_least(be, kInsphereDiffFloor) && diffs_at_least(ce, kInsphereDiffFloor) &&
              diffs_at_least(de, kInsphereDiffFloor)};
}

/// The stages behind the filter (2 to 4 above; out of line: rarely reached).
int orient3d_exact(Vec3 a, Vec3 b, Vec3 c, Vec3 d);
int insphere_exact(Vec3 a, Vec3 b, Vec3 c, Vec3 d, Vec3 e);
/// The big-integer stage alone (named *_rational as the 2D predicates');
/// tests compare it with an independent exact kernel.
int orient3d_rational(Vec3 a, Vec3 b, Vec3 c, Vec3 d);
int insphere_rational(Vec3 a, Vec3 b, Vec3 c, Vec3 d, Vec3 e);
}  // namespace detail

/// Sign of det [a - d; b - d; c - d]: +1 when d lies below the plane of a,
/// b, c (seen from above that plane, a, b, c turn counter-clockwise), -1
/// above, 0 coplanar (or coincident points). The sign flips with any swap of
/// two points. Exact.
GEOMCHECK_PREDICATE_INLINE int orient3d(Vec3 a, Vec3 b, Vec3 c, Vec3 d) {
  const detail::FilterValue f = detail::orient3d_filter(a, b, c, d);
  if (f.usable && (f.value > f.bound || -f.value > f.bound)) return f.value > 0 ? 1 : -1;
  return detail::orient3d_exact(a, b, c, d);
}

/// For a, b, c, d with orient3d(a, b, c, d) > 0: +1 when e lies strictly
/// inside the sphere through them, -1 strictly outside, 0 on it; the sign
/// flips for a negatively oriented a, b, c, d. For coplanar a, b, c, d it is
/// still the exact sign of the determinant, which then has no such meaning
/// (a triangulation does not ask it). Exact.
GEOMCHECK_PREDICATE_INLINE int insphere(Vec3 a, Vec3 b, Vec3 c, Vec3 d, Vec3 e) {
  const detail::FilterValue f = detail::insphere_filter(a, b, c, d, e);
  if (f.usable && (f.value > f.bound || -f.value > f.bound)) return f.value > 0 ? 1 : -1;
  return detail::insphere_exact(a, b, c, d, e);
}

}  // namespace geomcheck
