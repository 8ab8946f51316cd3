// geomcheck — internal helpers shared by the production cylinder queries.
#pragma once

#include <cmath>

#include "geomcheck/shapes.hpp"

namespace geomcheck::detail {

/// Unit vector along v, scaled first so that tiny or huge vectors neither
/// underflow nor overflow. v must be non-zero and finite.
inline Vec3 normalized(Vec3 v) {
  // Scale by an exact power of two (1/m itself overflows for subnormal m).
  const int e = std::ilogb(max_abs(v));
  const Vec3 s{std::ldexp(v.x, -e), std::ldexp(v.y, -e), std::ldexp(v.z, -e)};
  return (1.0 / length(s)) * s;
}

/// Length of v without overflow or underflow of its square.
inline double safe_length(Vec3 v) {
  const double m = max_abs(v);
  if (m == 0 || !std::isfinite(m)) return m;
  const int e = std::ilogb(m);
  return std::ldexp(length(Vec3{std::ldexp(v.x, -e), std::ldexp(v.y, -e), std::ldexp(v.z, -e)}), e);
}

/// The direction of the part of v perpendicular to unit u, as a unit vector
/// that is perpendicular to u to rounding whatever v is: it is built from
/// v's components in an orthonormal frame (e1, e2) around u, not by
/// subtracting v's component along u (which cancels to noise when v is
/// almost parallel to u). Any unit perpendicular when that part vanishes.
inline Vec3 unit_perpendicular_part(Vec3 v, Vec3 u) {
  const Vec3 e1 = any_perpendicular(u);
  const Vec3 e2 = cross(u, e1);
  const double a = dot(v, e1), b = dot(v, e2);
  const double m = std::fmax(std::fabs(a), std::fabs(b));
  if (!(m > 0) || !std::isfinite(m)) return e1;
  const int e = std::ilogb(m);
  const double as = std::ldexp(a, -e), bs = std::ldexp(b, -e);
  const double l = std::sqrt(as * as + bs * bs);
  return (as / l) * e1 + (bs / l) * e2;
}

/// The cylinder's mid point, unit axis and half height.
struct AxisFrame {
  Vec3 mid;
  Vec3 u;
  double half;
  explicit AxisFrame(const Cylinder& c) {
    const Vec3 d = c.q - c.p;
    u = normalized(d);
    half = 0.5 * safe_length(d);
    mid = 0.5 * (c.p + c.q);
  }
};

/// An exact power-of-two rescaling of a whole scene: the queries run on the
/// scene scaled so that its largest magnitude is in [1, 2), which keeps
/// squares and fourth powers far from overflow and underflow, and is
/// bit-identical to the unscaled computation wherever that one does not
/// overflow or underflow (scaling by 2^k commutes with rounding).
struct SceneScale {
  int e = 0;
  explicit SceneScale(double largest) {
    e = largest > 0 && std::isfinite(largest) ? std::ilogb(largest) : 0;
  }
  double in(double v) const { return std::ldexp(v, -e); }
  Vec3 in(Vec3 v) const { return {in(v.x), in(v.y), in(v.z)}; }
  double out(double v) const { return std::ldexp(v, e); }
  Vec3 out(Vec3 v) const { return {out(v.x), out(v.y), out(v.z)}; }
  Cylinder in(const Cylinder& c) const { return {in(c.p), in(c.q), in(c.r)}; }
  Sphere in(const Sphere& s) const { return {in(s.c), in(s.r)}; }
  Segment in(const Segment& s) const { return {in(s.a), in(s.b)}; }
};

inline double largest(const Cylinder& c) { return std::fmax(std::fmax(max_abs(c.p), max_abs(c.q)), c.r); }
inline double largest(const Sphere& s) { return std::fmax(max_abs(s.c), s.r); }
inline double largest(const Segment& s) { return std::fmax(max_abs(s.a), max_abs(s.b)); }

}  // namespace geomcheck::detail
