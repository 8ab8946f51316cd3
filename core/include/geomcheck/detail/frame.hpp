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

/// The part of v perpendicular to unit u, as a unit vector; any unit
/// perpendicular when that part is zero or not finite.
inline Vec3 unit_perpendicular_part(Vec3 v, Vec3 u) {
  const Vec3 w = v - dot(v, u) * u;
  const double m = max_abs(w);
  if (!(m > 0) || !std::isfinite(m)) return any_perpendicular(u);
  const Vec3 r = normalized(w);
  const Vec3 r2 = r - dot(r, u) * u;  // once more: w may carry rounding along u
  const Vec3 out = max_abs(r2) > 0 ? normalized(r2) : any_perpendicular(u);
  return is_finite(out) ? out : any_perpendicular(u);
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
