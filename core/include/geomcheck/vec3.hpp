// geomcheck — 3D vector of doubles used by the production queries.
//
// Plain value type; no normalisation happens implicitly. Every operation is
// the obvious IEEE-754 double expression (no fused multiply-add is relied on).
#pragma once

#include <algorithm>
#include <cmath>

namespace geomcheck {

/// A point or direction in R^3, stored as three doubles.
struct Vec3 {
  double x = 0, y = 0, z = 0;

  constexpr Vec3() = default;
  constexpr Vec3(double x_, double y_, double z_) : x(x_), y(y_), z(z_) {}

  constexpr double operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }
  double& operator[](int i) { return i == 0 ? x : (i == 1 ? y : z); }
};

constexpr Vec3 operator+(Vec3 a, Vec3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
constexpr Vec3 operator-(Vec3 a, Vec3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
constexpr Vec3 operator-(Vec3 a) { return {-a.x, -a.y, -a.z}; }
constexpr Vec3 operator*(double s, Vec3 a) { return {s * a.x, s * a.y, s * a.z}; }
constexpr Vec3 operator*(Vec3 a, double s) { return {s * a.x, s * a.y, s * a.z}; }
constexpr bool operator==(Vec3 a, Vec3 b) { return a.x == b.x && a.y == b.y && a.z == b.z; }
constexpr bool operator!=(Vec3 a, Vec3 b) { return !(a == b); }

/// Dot product.
constexpr double dot(Vec3 a, Vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
/// Cross product.
constexpr Vec3 cross(Vec3 a, Vec3 b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
/// Squared Euclidean length.
constexpr double length2(Vec3 a) { return dot(a, a); }
/// Euclidean length.
inline double length(Vec3 a) { return std::sqrt(dot(a, a)); }
/// Largest absolute component (finite input; std::max, unlike std::fmax,
/// compiles to one instruction without -ffast-math).
inline double max_abs(Vec3 a) { return std::max(std::fabs(a.x), std::max(std::fabs(a.y), std::fabs(a.z))); }
/// True when every component is finite (no NaN, no infinity).
inline bool is_finite(Vec3 a) { return std::isfinite(a.x) && std::isfinite(a.y) && std::isfinite(a.z); }

/// A unit vector perpendicular to `u` (u need not be unit; u must be non-zero).
inline Vec3 any_perpendicular(Vec3 u) {
  const double ax = std::fabs(u.x), ay = std::fabs(u.y), az = std::fabs(u.z);
  // Cross with the coordinate axis least aligned with u.
  Vec3 e = (ax <= ay && ax <= az) ? Vec3{1, 0, 0} : (ay <= az ? Vec3{0, 1, 0} : Vec3{0, 0, 1});
  Vec3 p = cross(u, e);
  return (1.0 / length(p)) * p;
}

}  // namespace geomcheck
