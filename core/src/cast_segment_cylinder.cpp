#include "geomcheck/cast_segment_cylinder.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "geomcheck/detail/frame.hpp"

namespace geomcheck {

namespace {

CastHit cast_scaled(const Segment& seg, const Cylinder& cyl);

}  // namespace

CastHit cast(const Segment& seg_in, const Cylinder& cyl_in) {
  if (!is_valid(seg_in) || !is_valid(cyl_in)) return {};
  // Run on the scene scaled by an exact power of two (the quadratic's
  // coefficients are fourth powers of lengths); scale the point back.
  const detail::SceneScale sc(std::max(detail::largest(seg_in), detail::largest(cyl_in)));
  CastHit out = cast_scaled(sc.in(seg_in), sc.in(cyl_in));
  out.point = sc.out(out.point);
  return out;
}

namespace {

CastHit cast_scaled(const Segment& seg, const Cylinder& cyl) {
  CastHit out;
  if (!is_valid(cyl)) return out;  // an axis far below the scene's magnitude vanishes
  // Everything is measured along the unit axis u and the axis length L
  // (d = L u): the coefficients of the printed form are these times L^2,
  // with the same roots, and no power of |d| is ever formed, so an axis far
  // shorter than the scene (a disk of subnormal thickness) cannot underflow
  // them (regression 0005).
  const detail::UnitAndLength axis(cyl.q - cyl.p);
  const Vec3 u = axis.u;
  const double len = axis.len;
  const Vec3 m = seg.a - cyl.p;
  const Vec3 n = seg.b - seg.a;
  const double mu = dot(m, u);
  const double nu = dot(n, u);
  const Vec3 mxu = cross(m, u);
  const Vec3 nxu = cross(n, u);
  // |perp(S(t))|^2 - r^2 = qa t^2 + 2 qb t + qc
  const double qa = dot(nxu, nxu);
  const double qb = dot(mxu, nxu);
  const double qc = dot(mxu, mxu) - cyl.r * cyl.r;

  // The segment is in the cylinder where it is both in the slab between the
  // cap planes and in the infinite cylinder: intersect the two parameter
  // intervals with [0, 1]. Accepting by interval rather than by feature
  // leaves no gap at the rim, where a cap test and a side test can both
  // reject by one rounding (regression 0002).
  const double inf = std::numeric_limits<double>::infinity();
  double slab_lo = -inf, slab_hi = inf;
  if (nu == 0) {
    if (mu < 0 || mu > len) return out;
  } else {
    slab_lo = -mu / nu;
    slab_hi = (len - mu) / nu;
    if (slab_lo > slab_hi) std::swap(slab_lo, slab_hi);
  }
  double cyl_lo = -inf, cyl_hi = inf;
  if (qa == 0) {
    if (qc > 0) return out;  // parallel to the axis and outside the radius
  } else {
    // disc = qb^2 - qa qc, in the form that cannot cancel:
    //  * qc <= 0 (start inside the infinite cylinder): qb^2 + qa |qc|, a sum
    //    of non-negative terms (regression 0003: a segment parallel to the
    //    axis to 1e-15 rad, where |n x u| is rounding noise);
    //  * qc > 0: r^2 |n x u|^2 - (n.(m x u))^2 by Lagrange's identity, the
    //    triple product being the lines' offset (regression 0001: the
    //    textbook form cancels when the line passes near the axis).
    double sq;
    if (qc <= 0) {
      sq = std::sqrt(qb * qb - qa * qc);
    } else {
      const double triple = dot(n, mxu);
      const double disc = cyl.r * cyl.r * qa - triple * triple;
      if (disc < 0) return out;
      sq = std::sqrt(disc);
    }
    // Roots without cancellation: k / qa and qc / k with k = -(qb + sign(qb) sq).
    const double k = -(qb + std::copysign(sq, qb));
    if (k == 0) {
      cyl_lo = cyl_hi = 0;
    } else {
      cyl_lo = k / qa;
      cyl_hi = qc / k;
      if (cyl_lo > cyl_hi) std::swap(cyl_lo, cyl_hi);
    }
  }
  const double entry = std::max(slab_lo, cyl_lo);
  const double exit = std::min(slab_hi, cyl_hi);
  if (!(entry <= exit) || entry > 1 || exit < 0) return out;

  if (entry <= 0) {
    out.hit = true;
    out.starts_inside = true;
    out.t = 0;
    out.point = seg.a;
    return out;
  }
  const double best = entry;
  const int feature = slab_lo >= cyl_lo ? (nu > 0 ? 2 : 3) : 1;  // 1 side, 2 cap p, 3 cap q
  out.hit = true;
  out.t = best;
  out.point = seg.a + best * n;
  if (feature == 2) {
    out.normal = -u;
  } else if (feature == 3) {
    out.normal = u;
  } else {
    const Vec3 x = m + best * n;
    out.normal = detail::unit_perpendicular_part(x, u);
  }
  return out;
}

}  // namespace

}  // namespace geomcheck
