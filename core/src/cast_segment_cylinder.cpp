#include "geomcheck/cast_segment_cylinder.hpp"

#include <cmath>
#include <limits>

#include "geomcheck/detail/frame.hpp"

namespace geomcheck {

CastHit cast(const Segment& seg, const Cylinder& cyl) {
  CastHit out;
  if (!is_valid(seg) || !is_valid(cyl)) return out;
  const Vec3 d = cyl.q - cyl.p;
  const Vec3 m = seg.a - cyl.p;
  const Vec3 n = seg.b - seg.a;
  const double dd = dot(d, d);
  const double md = dot(m, d);
  const double nd = dot(n, d);
  const double r2dd = cyl.r * cyl.r * dd;
  const Vec3 mxd = cross(m, d);
  const Vec3 nxd = cross(n, d);
  // |perp(S(t))|^2 |d|^2 - r^2 |d|^2 = qa t^2 + 2 qb t + qc
  const double qa = dot(nxd, nxd);
  const double qb = dot(mxd, nxd);
  const double qc = dot(mxd, mxd) - r2dd;

  if (md >= 0 && md <= dd && qc <= 0) {
    out.hit = true;
    out.starts_inside = true;
    out.t = 0;
    out.point = seg.a;
    return out;
  }

  double best = std::numeric_limits<double>::infinity();
  int feature = 0;  // 1 side, 2 cap p, 3 cap q

  // Side: entering the infinite cylinder from outside it.
  if (qc > 0 && qb < 0) {
    // disc = qb^2 - qa qc = dd (r^2 |n x d|^2 - (n.(m x d))^2) by Lagrange's
    // identity: the triple product is the lines' offset, so no large terms cancel.
    const double triple = dot(n, mxd);
    const double disc_dd = cyl.r * cyl.r * qa - triple * triple;
    if (disc_dd >= 0) {
      const double t = qc / (-qb + std::sqrt(dd) * std::sqrt(disc_dd));
      const double axial = md + t * nd;
      if (t >= 0 && t <= 1 && axial >= 0 && axial <= dd) {
        best = t;
        feature = 1;
      }
    }
  }
  // Cap at p: crossing the plane (x-p).d = 0 in the +d direction.
  if (md < 0 && nd > 0) {
    const double t = -md / nd;
    if (t <= 1 && t < best) {
      const Vec3 x = m + t * n;
      const Vec3 xd = cross(x, d);
      if (dot(xd, xd) <= r2dd) { best = t; feature = 2; }
    }
  }
  // Cap at q: crossing the plane (x-p).d = dd in the -d direction.
  if (md > dd && nd < 0) {
    const double t = (dd - md) / nd;
    if (t <= 1 && t < best) {
      const Vec3 x = m + t * n;
      const Vec3 xd = cross(x, d);
      if (dot(xd, xd) <= r2dd) { best = t; feature = 3; }
    }
  }
  if (feature == 0) return out;

  out.hit = true;
  out.t = best;
  out.point = seg.a + best * n;
  const Vec3 u = detail::normalized(d);
  if (feature == 2) {
    out.normal = -u;
  } else if (feature == 3) {
    out.normal = u;
  } else {
    const Vec3 x = m + best * n;
    const Vec3 radial = x - (dot(x, u)) * u;
    out.normal = max_abs(radial) > 0 ? detail::normalized(radial) : any_perpendicular(u);
  }
  return out;
}

}  // namespace geomcheck
