#include "geomcheck/collide_cylinder_sphere.hpp"

#include <algorithm>
#include <cmath>

#include "geomcheck/detail/frame.hpp"

namespace geomcheck {

namespace {

// The overlap predicate, shared by overlap() and collide() so that the two
// take the same decision bit for bit. With d = q - p, m = c - p:
//   beyond a cap:  en = max(-m.d, m.d - d.d, 0),  ea^2 = en^2 / d.d
//   off the axis:  |m x d|^2 = rho^2 d.d,         er = max(rho - r, 0)
// and the sphere meets the cylinder iff ea^2 + er^2 <= s^2. Inside the
// radius this is en^2 <= s^2 d.d (no division, no square root). An axis too
// short for its square (d.d < 2^-600) goes through the frame instead.
bool meets(const Cylinder& cyl, const Sphere& s);

// Offsets of the sphere centre in the cylinder's frame (mid point, unit
// axis): robust for any axis length, used for contacts and thin axes.
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
  // ea^2 + er^2 <= r^2; outside the safe range of squares, scaled by an
  // exact power of two (bit-identical to the plain form wherever both apply).
  bool within(double r) const {
    const double m = std::max({ea, er, r});
    if (m <= detail::kSafeHi && (m >= detail::kSafeLo || m == 0)) return ea * ea + er * er <= r * r;
    if (!std::isfinite(m)) return false;
    const int e = std::ilogb(m);
    const double a = std::ldexp(ea, -e), b = std::ldexp(er, -e), c = std::ldexp(r, -e);
    return a * a + b * b <= c * c;
  }
};

bool meets(const Cylinder& cyl, const Sphere& s) {
  const Vec3 d = cyl.q - cyl.p, m = s.c - cyl.p;
  const double dd = dot(d, d);
  if (!(dd >= 0x1p-600)) return Offsets(cyl, s).within(s.r);
  const double t = dot(m, d);
  const Vec3 x = cross(m, d);
  const double cr2 = dot(x, x);
  const double en = t < 0 ? -t : (t > dd ? t - dd : 0.0);
  if (cr2 <= cyl.r * cyl.r * dd) return en * en <= s.r * s.r * dd;
  const double er = std::sqrt(cr2 / dd) - cyl.r;
  return en * en / dd + er * er <= s.r * s.r;
}

Contact collide_scaled(const Cylinder& cyl, const Sphere& s, double largest);

}  // namespace

bool overlap(const Cylinder& cyl_in, const Sphere& s_in) {
  if (!is_valid(cyl_in) || !is_valid(s_in)) return false;
  const detail::SceneScale sc(std::max(detail::largest(cyl_in), detail::largest(s_in)));
  if (sc.e == 0) return meets(cyl_in, s_in);
  const Cylinder cyl = sc.in(cyl_in);
  const Sphere s = sc.in(s_in);
  if (!is_valid(cyl)) return false;  // an axis far below the scene's magnitude vanishes
  return meets(cyl, s);
}

Contact collide(const Cylinder& cyl_in, const Sphere& s_in) {
  Contact out;
  if (!is_valid(cyl_in) || !is_valid(s_in)) return out;
  // Run on the scene scaled by an exact power of two; scale the answer back.
  const double largest = std::max(detail::largest(cyl_in), detail::largest(s_in));
  const detail::SceneScale sc(largest);
  if (sc.e == 0) return collide_scaled(cyl_in, s_in, largest);
  out = collide_scaled(sc.in(cyl_in), sc.in(s_in), sc.in(largest));
  out.point = sc.out(out.point);
  out.depth = sc.out(out.depth);
  return out;
}

namespace {

Contact collide_scaled(const Cylinder& cyl, const Sphere& s, double largest) {
  Contact out;
  if (!is_valid(cyl)) return out;
  // The same predicate as overlap(), so that the two never disagree.
  if (!meets(cyl, s)) return out;
  const Offsets o(cyl, s);
  const detail::AxisFrame& f = o.f;
  const double ax = o.ax, rho = o.rho, aax = std::fabs(ax);
  // Offsets at the rounding level of the case carry no direction
  // (regression 0002): a radial offset below it gives no radial direction.
  const double noise = 16 * 0x1p-52 * std::max(largest, f.half);
  auto radial_dir = [&] { return rho > noise ? detail::unit_perpendicular_part(o.w, f.u) : any_perpendicular(f.u); };
  out.hit = true;

  if (aax <= f.half && rho <= cyl.r) {
    // Centre inside the cylinder: leave through the nearer cap or the side.
    const double cap_gap = f.half - aax;
    const double side_gap = cyl.r - rho;
    out.point = s.c;
    if (cap_gap <= side_gap) {
      out.normal = ax >= 0 ? f.u : -f.u;
      out.depth = s.r + cap_gap;
    } else {
      out.normal = radial_dir();
      out.depth = s.r + side_gap;
    }
    return out;
  }

  // Centre outside: the closest point of the cylinder clamps both offsets.
  const double cax = std::clamp(ax, -f.half, f.half);
  out.point = f.mid + cax * f.u + (rho > cyl.r ? (cyl.r / rho) * o.w : o.w);
  // The normal is built from the offsets along the exact cap and radial
  // directions, so that a tiny gap does not lose it to cancellation. Offsets
  // at the rounding level are dropped; if both vanish the centre is on the
  // surface and the normal of the face it is farther out of is valid.
  const double ea = o.ea, er = o.er;
  const double ean = ea > noise ? ea : 0.0, ern = er > noise ? er : 0.0;
  const Vec3 cap = ax >= 0 ? f.u : -f.u;
  Vec3 n;
  if (ern == 0) n = ean > 0 || ea >= er ? cap : radial_dir();
  else if (ean == 0) n = radial_dir();
  else {
    const double big = std::max(ean, ern);  // scaled so that huge offsets do not overflow
    n = detail::normalized((ean / big) * cap + (ern / big) * radial_dir());
  }
  out.normal = n;
  out.depth = std::max(s.r - detail::safe_length(Vec3{ea, er, 0}), 0.0);
  return out;
}

}  // namespace

}  // namespace geomcheck
