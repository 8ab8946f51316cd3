#include "geomcheck/oracles/cylinder_sphere.hpp"

#include <algorithm>
#include <limits>
#include <cmath>
#include <stdexcept>

namespace geomcheck::oracle {

namespace {

int sign(const Q& v) { return v > 0 ? 1 : (v < 0 ? -1 : 0); }

// sign(dist(c, cyl) - s) for a centre outside the cylinder.
int outside_sign(const Q& ea2, const Q& rho2, bool beyond_rim, const Q& r, const Q& s) {
  if (!beyond_rim) return sign(ea2 - s * s);
  // dist^2 - s^2 = K - 2 r rho with K = ea2 + rho2 + r^2 - s^2.
  const Q k = ea2 + rho2 + r * r - s * s;
  if (r == 0) return sign(k);
  if (k <= 0) return -1;  // 2 r rho > 0 since rho > r >= 0 ... and r > 0
  return sign(k * k - 4 * r * r * rho2);
}

// Sets the verdict from the exact sign of the signed distance and makes the
// enclosure agree with it (the sign is exact; the enclosure may straddle 0).
void settle(CylinderSphereTruth& out, int sign) {
  if (sign > 0) {
    out.verdict = Verdict::Separated;
    if (out.signed_distance.lo < 0) out.signed_distance.lo = 0;
  } else if (sign == 0) {
    out.verdict = Verdict::Touching;
    out.signed_distance = point(Q(0));
  } else {
    out.verdict = Verdict::Overlapping;
    if (out.signed_distance.hi > 0) out.signed_distance.hi = 0;
  }
}

}  // namespace

CylinderSphereTruth solve_cylinder_sphere(const QCylinder& cyl, const QSphere& s) {
  CylinderSphereTruth out;
  const QVec d = cyl.q - cyl.p;
  const QVec m = s.c - cyl.p;
  const Q dd = dot(d, d);
  if (dd == 0) throw std::invalid_argument("oracle: zero-length cylinder axis");
  const Q t = dot(m, d);
  const QVec x = cross(m, d);
  const Q cr2 = dot(x, x);
  const Q r2dd = cyl.r * cyl.r * dd;
  const QInterval len = sqrt_interval(dd);

  const bool axial_in = t >= 0 && t <= dd;
  const bool radial_in = cr2 <= r2dd;
  out.centre_inside = axial_in && radial_in;
  if (out.centre_inside) {
    const Q cap_num = t < dd - t ? t : dd - t;
    const QInterval cap_gap = point(cap_num) / len;
    const QInterval rho = sqrt_interval(cr2 / dd);
    QInterval side_gap = point(cyl.r) - rho;
    if (side_gap.lo < 0) side_gap.lo = 0;  // true side gap >= 0 (radial_in is exact)
    const QInterval depth = point(s.r) + min(cap_gap, side_gap);
    out.signed_distance = -depth;
    const bool on_boundary = t == 0 || t == dd || cr2 == r2dd;
    settle(out, s.r == 0 && on_boundary ? 0 : -1);
    return out;
  }

  Q ea2 = 0;
  if (t < 0) ea2 = t * t / dd;
  else if (t > dd) ea2 = (t - dd) * (t - dd) / dd;
  const Q rho2 = cr2 / dd;
  const bool beyond_rim = !radial_in;
  const int sg = outside_sign(ea2, rho2, beyond_rim, cyl.r, s.r);

  QInterval dist2 = point(ea2);
  if (beyond_rim) {
    QInterval er = sqrt_interval(rho2) - point(cyl.r);
    if (er.lo < 0) er.lo = 0;
    dist2 = dist2 + er * er;
  }
  out.signed_distance = sqrt_interval(dist2) - point(s.r);
  settle(out, sg);
  return out;
}

CylinderSphereTruth solve_cylinder_sphere(const Cylinder& cyl, const Sphere& s) {
  return solve_cylinder_sphere(to_q(cyl), to_q(s));
}

QInterval overlap_along(const QCylinder& a, const QSphere& b, const QVec& n) {
  const QVec neg = Q(-1) * n;
  const QInterval len = sqrt_interval(dot(n, n));
  return (support(a, n) + support(b, neg)) / len;
}

}  // namespace geomcheck::oracle
