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
    const double len = length(d);
    u = (1.0 / len) * d;
    half = 0.5 * len;
    mid = 0.5 * (c.p + c.q);
  }
};

}  // namespace geomcheck::detail
