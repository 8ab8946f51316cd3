#include "geomcheck/oracles/cast_segment_cylinder.hpp"
#include "geomcheck/oracles/cylinder_sphere.hpp"

#include <algorithm>
#include <stdexcept>

namespace geomcheck::oracle {

const char* to_string(CastFeature f) {
  switch (f) {
    case CastFeature::None: return "none";
    case CastFeature::StartInside: return "start-inside";
    case CastFeature::CapP: return "cap-p";
    case CastFeature::CapQ: return "cap-q";
    case CastFeature::Side: return "side";
  }
  return "?";
}

CastTruth solve_cast(const QSegment& s, const QCylinder& c) {
  CastTruth out;
  const QVec d = c.q - c.p;
  const QVec m = s.a - c.p;
  const QVec n = s.b - s.a;
  const Q dd = dot(d, d);
  if (dd == 0) throw std::invalid_argument("oracle: zero-length cylinder axis");
  const Q md = dot(m, d), nd = dot(n, d);
  const QVec mxd = cross(m, d), nxd = cross(n, d);
  const Q qa = dot(nxd, nxd), qb = dot(mxd, nxd), qc = dot(mxd, mxd) - c.r * c.r * dd;
  auto f = [&](const Q& t) { return (qa * t + 2 * qb) * t + qc; };

  // Axial interval of t, clipped to [0, 1].
  Q lo = 0, hi = 1;
  if (nd == 0) {
    if (md < 0 || md > dd) return out;
  } else {
    Q t0 = -md / nd, t1 = (dd - md) / nd;
    if (t0 > t1) std::swap(t0, t1);
    if (t0 > lo) lo = t0;
    if (t1 < hi) hi = t1;
    if (lo > hi) return out;
  }

  if (f(lo) <= 0) {
    out.hit = true;
    out.t = point(lo);
    if (lo == 0) out.feature = CastFeature::StartInside;
    else out.feature = nd > 0 ? CastFeature::CapP : CastFeature::CapQ;
    return out;
  }
  // f(lo) > 0: enter through the side, if at all.
  if (qa == 0) {
    if (qb >= 0) return out;                 // f constant or increasing
    const Q root = -qc / (2 * qb);           // f decreasing, f(lo) > 0 => root > lo
    if (root > hi) return out;
    out.hit = true;
    out.feature = CastFeature::Side;
    out.t = point(root);
    return out;
  }
  const Q disc = qb * qb - qa * qc;
  if (disc < 0) return out;
  const Q vertex = -qb / qa;
  if (lo >= vertex) return out;              // right of both roots, f(lo) > 0
  if (!(hi >= vertex || f(hi) <= 0)) return out;
  out.hit = true;
  out.feature = CastFeature::Side;
  // lo < vertex with lo >= 0 implies qb < 0, and f(0) > 0 (f(lo) > 0 left of
  // the roots), so qc > 0: the root qc / (-qb + sqrt(disc)) has no cancellation.
  const QInterval sq = sqrt_interval(disc);
  out.t = point(qc) / (point(-qb) + sq);
  // The root is in (lo, hi]: tighten the enclosure with what is known exactly.
  if (out.t.lo < lo) out.t.lo = lo;
  if (out.t.hi > hi) out.t.hi = hi;
  return out;
}

CastTruth solve_cast(const Segment& s, const Cylinder& c) { return solve_cast(to_q(s), to_q(c)); }

namespace {
// e >= delta / |d| (so e * d has length >= delta).
Q axis_fraction(const QCylinder& c, const Q& delta) {
  const QVec d = c.q - c.p;
  const QInterval len = sqrt_interval(dot(d, d));
  return delta / len.lo;
}
}  // namespace

QCylinder grown(const QCylinder& c, const Q& delta) {
  const Q e = axis_fraction(c, delta);
  const QVec d = c.q - c.p;
  return {c.p - e * d, c.q + e * d, c.r + delta};
}

std::optional<QCylinder> shrunk(const QCylinder& c, const Q& delta) {
  const Q e = axis_fraction(c, delta);
  if (c.r < delta || 2 * e >= 1) return std::nullopt;
  const QVec d = c.q - c.p;
  return QCylinder{c.p + e * d, c.q - e * d, c.r - delta};
}

}  // namespace geomcheck::oracle
