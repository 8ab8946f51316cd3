#include "geomcheck/cast_segment_cylinder.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "geomcheck/detail/frame.hpp"
#include "geomcheck/detail/segment_tube.hpp"

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
  // The segment is in the cylinder where it is both in the slab between the
  // cap planes and in the infinite cylinder: intersect the two parameter
  // intervals with [0, 1]. Accepting by interval rather than by feature
  // leaves no gap at the rim, where a cap test and a side test can both
  // reject by one rounding (regression 0002). The discriminant is formed so
  // that it cannot cancel (regressions 0001, 0003): see segment_tube.hpp.
  const detail::TubeInterval iv = detail::tube_interval(m, n, u, len, 0.0, cyl.r);
  if (iv.empty) return out;
  const double entry = iv.entry, exit = iv.exit;
  if (entry > 1 || exit < 0) return out;

  if (entry <= 0) {
    out.hit = true;
    out.starts_inside = true;
    out.t = 0;
    out.point = seg.a;
    return out;
  }
  const double best = entry;
  const int feature = iv.side_entry ? 1 : (iv.cap_q ? 3 : 2);  // 1 side, 2 cap p, 3 cap q
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
