#include "geomcheck/collide_cylinder_sphere.hpp"

#include <algorithm>
#include <cmath>

#include "geomcheck/detail/frame.hpp"

namespace geomcheck {

namespace {

// Offsets of the sphere centre from the cylinder, shared by overlap() and
// collide() so that the two take the same decision bit for bit.
struct Offsets {
  detail::AxisFrame f;
  Vec3 w;       // radial vector from the axis to the centre
  double ax;    // axial offset from the mid point
  double rho;   // |w|
  double ea;    // beyond a cap plane (>= 0)
  double er;    // beyond the side (>= 0)
  explicit Offsets(const Cylinder& cyl, const Sphere& s) : f(cyl) {
    const Vec3 v = s.c - f.mid;
    ax = dot(v, f.u);
    w = v - ax * f.u;
    rho = detail::safe_length(w);
    ea = std::max(std::fabs(ax) - f.half, 0.0);
    er = std::max(rho - cyl.r, 0.0);
  }
  // ea^2 + er^2 <= r^2, scaled by an exact power of two so that squares of
  // huge values do not overflow (bit-identical to the plain form otherwise).
  bool within(double r) const {
    const double m = std::max({ea, er, r});
    if (m == 0) return true;
    if (!std::isfinite(m)) return false;
    const int e = std::ilogb(m);
    const double a = std::ldexp(ea, -e), b = std::ldexp(er, -e), c = std::ldexp(r, -e);
    return a * a + b * b <= c * c;
  }
};

Contact collide_scaled(const Cylinder& cyl, const Sphere& s);

}  // namespace

bool overlap(const Cylinder& cyl_in, const Sphere& s_in) {
  if (!is_valid(cyl_in) || !is_valid(s_in)) return false;
  const detail::SceneScale sc(std::fmax(detail::largest(cyl_in), detail::largest(s_in)));
  const Cylinder cyl = sc.in(cyl_in);
  const Sphere s = sc.in(s_in);
  if (!is_valid(cyl)) return false;  // an axis far below the scene's magnitude vanishes
  return Offsets(cyl, s).within(s.r);
}

Contact collide(const Cylinder& cyl_in, const Sphere& s_in) {
  Contact out;
  if (!is_valid(cyl_in) || !is_valid(s_in)) return out;
  // Run on the scene scaled by an exact power of two; scale the answer back.
  const detail::SceneScale sc(std::fmax(detail::largest(cyl_in), detail::largest(s_in)));
  out = collide_scaled(sc.in(cyl_in), sc.in(s_in));
  out.point = sc.out(out.point);
  out.depth = sc.out(out.depth);
  return out;
}

namespace {

Contact collide_scaled(const Cylinder& cyl, const Sphere& s) {
  Contact out;
  if (!is_valid(cyl)) return out;
  const Offsets o(cyl, s);
  const detail::AxisFrame& f = o.f;
  const double ax = o.ax, rho = o.rho;
  const Vec3 w = o.w;
  const double aax = std::fabs(ax);
  // Offsets at the rounding level of the case carry no direction
  // (regression 0002): a radial offset below it gives no radial direction.
  const double noise = 16 * 0x1p-52 * std::max({max_abs(cyl.p), max_abs(cyl.q), max_abs(s.c), cyl.r, f.half});
  const Vec3 rad_dir = rho > noise ? detail::unit_perpendicular_part(w, f.u) : any_perpendicular(f.u);

  if (aax <= f.half && rho <= cyl.r) {
    // Centre inside the cylinder: leave through the nearer cap or the side.
    const double cap_gap = f.half - aax;
    const double side_gap = cyl.r - rho;
    out.hit = true;
    out.point = s.c;
    if (cap_gap <= side_gap) {
      out.normal = ax >= 0 ? f.u : -f.u;
      out.depth = s.r + cap_gap;
    } else {
      out.normal = rad_dir;
      out.depth = s.r + side_gap;
    }
    return out;
  }

  // Centre outside: closest point of the cylinder by clamping both offsets.
  const double cax = std::clamp(ax, -f.half, f.half);
  const Vec3 radial = rho > cyl.r ? (cyl.r / rho) * w : w;
  const Vec3 x = f.mid + cax * f.u + radial;
  const double ea = o.ea, er = o.er;
  // The same predicate as overlap(), so that the two never disagree.
  if (!o.within(s.r)) return out;
  const double dist = detail::safe_length(Vec3{ea, er, 0});
  out.hit = true;
  out.point = x;
  // Direction from the closest point to the centre, built from the offsets
  // (exact directions of the cap normal and the radial direction) so that a
  // tiny gap does not lose the direction to cancellation.
  // Drop offsets at the rounding level; if both vanish the centre is on the
  // surface and the normal of the face it is farther out of is valid.
  const double ean = ea > noise ? ea : 0.0, ern = er > noise ? er : 0.0;
  Vec3 n;
  if (ean == 0 && ern == 0) n = ea >= er ? (ax >= 0 ? f.u : -f.u) : rad_dir;
  else {
    const double big = std::max(ean, ern);  // scaled so that huge offsets do not overflow
    n = (ax >= 0 ? ean / big : -ean / big) * f.u + (ern / big) * rad_dir;
  }
  out.normal = detail::normalized(n);
  out.depth = std::max(s.r - dist, 0.0);
  return out;
}

}  // namespace

}  // namespace geomcheck
