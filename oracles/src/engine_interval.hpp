// geomcheck — certified convex engine: interval arithmetic on doubles.
// Every operation is rounded to nearest and then widened outwards by one ulp
// (nextafter), so the exact result of each operation on any values inside
// the operands lies inside the result, whatever the rounding of the
// operation was (including underflow). A NaN poisons an interval; every
// decision is a strict comparison, false on NaN.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

#include "geomcheck/vec3.hpp"

namespace geomcheck::oracle {

inline double dn(double x) { return std::nextafter(x, -std::numeric_limits<double>::infinity()); }
inline double up(double x) { return std::nextafter(x, std::numeric_limits<double>::infinity()); }

struct Iv {
  double lo = 0, hi = 0;
  static Iv exact(double v) { return {v, v}; }
  bool certainly_neg() const { return hi < 0; }
  bool certainly_pos() const { return lo > 0; }
};
inline Iv operator+(Iv a, Iv b) { return {dn(a.lo + b.lo), up(a.hi + b.hi)}; }
inline Iv operator-(Iv a, Iv b) { return {dn(a.lo - b.hi), up(a.hi - b.lo)}; }
inline Iv operator-(Iv a) { return {-a.hi, -a.lo}; }
inline Iv operator*(Iv a, Iv b) {
  const double p[4] = {a.lo * b.lo, a.lo * b.hi, a.hi * b.lo, a.hi * b.hi};
  double lo = p[0], hi = p[0];
  for (double v : p) {
    lo = v < lo ? v : lo;
    hi = v > hi ? v : hi;
  }
  for (double v : p)
    if (v != v) lo = hi = v;  // NaN poisons the interval
  return {dn(lo), up(hi)};
}
inline Iv iv_sqrt(Iv a) {  // for values known to be >= 0
  const double lo = a.lo <= 0 ? 0 : dn(std::sqrt(a.lo));
  return {lo, up(std::sqrt(a.hi))};
}
inline Iv iv_max(Iv a, Iv b) { return {std::max(a.lo, b.lo), std::max(a.hi, b.hi)}; }
inline Iv iv_div(Iv a, Iv b) {  // b certainly positive
  const double p[4] = {a.lo / b.lo, a.lo / b.hi, a.hi / b.lo, a.hi / b.hi};
  double lo = p[0], hi = p[0];
  for (double v : p) {
    lo = v < lo ? v : lo;
    hi = v > hi ? v : hi;
  }
  return {dn(lo), up(hi)};
}

struct IV3 {
  Iv x, y, z;
};
inline IV3 operator+(const IV3& a, const IV3& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline IV3 operator-(const IV3& a, const IV3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline IV3 operator*(Iv s, const IV3& a) { return {s * a.x, s * a.y, s * a.z}; }
inline Iv dot(const IV3& a, const IV3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline IV3 cross(const IV3& a, const IV3& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline IV3 iv3(Vec3 v) { return {Iv::exact(v.x), Iv::exact(v.y), Iv::exact(v.z)}; }
inline IV3 iv3(Vec3 lo, Vec3 hi) { return {{lo.x, hi.x}, {lo.y, hi.y}, {lo.z, hi.z}}; }

}  // namespace geomcheck::oracle
