// geomcheck — certified convex engine: double-double numbers (about 106
// significant bits in two doubles, hi + lo with |lo| <= ulp(hi) / 2), the
// fast high-precision round of the search.
//
// Nothing computed in these numbers is trusted: the search only proposes
// directions and support points, and the callers certify them in rationals,
// exactly as for the software floats of 128 and 384 digits. What this type
// buys is speed (hardware doubles and fused multiply-add, no allocation);
// what it lacks is range: the exponent is a double's, so callers use it
// only when the case's scale keeps every product of the search (up to the
// sixth power of the scale) normal (dd::in_range).
#pragma once

#include <cmath>
#include <limits>

namespace geomcheck::oracle::dd {

/// An unevaluated sum hi + lo of two doubles.
struct DD {
  double hi = 0, lo = 0;
  constexpr DD() = default;
  constexpr DD(double h) : hi(h), lo(0) {}  // NOLINT: implicit, like the other number types
  constexpr DD(double h, double l) : hi(h), lo(l) {}
  /// The nearest double (hi: lo is below half an ulp of it).
  explicit operator double() const { return hi; }

  DD& operator+=(const DD& b);
  DD& operator-=(const DD& b);
  DD& operator*=(const DD& b);
  DD& operator/=(const DD& b);
};

/// s + e == a + b exactly (Knuth).
inline DD two_sum(double a, double b) {
  const double s = a + b, bb = s - a;
  return {s, (a - (s - bb)) + (b - bb)};
}
/// s + e == a + b exactly, given |a| >= |b| (Dekker).
inline DD quick_two_sum(double a, double b) {
  const double s = a + b;
  return {s, b - (s - a)};
}
/// p + e == a * b exactly (fused multiply-add).
inline DD two_prod(double a, double b) {
  const double p = a * b;
  return {p, std::fma(a, b, -p)};
}

inline DD operator+(const DD& a, const DD& b) {
  DD s = two_sum(a.hi, b.hi);
  const DD t = two_sum(a.lo, b.lo);
  s.lo += t.hi;
  s = quick_two_sum(s.hi, s.lo);
  s.lo += t.lo;
  return quick_two_sum(s.hi, s.lo);
}
inline DD operator-(const DD& a) { return {-a.hi, -a.lo}; }
inline DD operator-(const DD& a, const DD& b) { return a + (-b); }
inline DD operator*(const DD& a, const DD& b) {
  DD p = two_prod(a.hi, b.hi);
  p.lo += a.hi * b.lo + a.lo * b.hi;
  return quick_two_sum(p.hi, p.lo);
}
inline DD operator/(const DD& a, const DD& b) {
  const double q1 = a.hi / b.hi;
  DD r = a - DD(q1) * b;
  const double q2 = r.hi / b.hi;
  r = r - DD(q2) * b;
  const double q3 = r.hi / b.hi;
  return quick_two_sum(q1, q2) + DD(q3);
}
inline DD& DD::operator+=(const DD& b) { return *this = *this + b; }
inline DD& DD::operator-=(const DD& b) { return *this = *this - b; }
inline DD& DD::operator*=(const DD& b) { return *this = *this * b; }
inline DD& DD::operator/=(const DD& b) { return *this = *this / b; }

inline bool operator==(const DD& a, const DD& b) { return a.hi == b.hi && a.lo == b.lo; }
inline bool operator!=(const DD& a, const DD& b) { return !(a == b); }
inline bool operator<(const DD& a, const DD& b) { return a.hi < b.hi || (a.hi == b.hi && a.lo < b.lo); }
inline bool operator>(const DD& a, const DD& b) { return b < a; }
inline bool operator<=(const DD& a, const DD& b) { return a.hi < b.hi || (a.hi == b.hi && a.lo <= b.lo); }
inline bool operator>=(const DD& a, const DD& b) { return b <= a; }

inline DD abs(const DD& a) { return a.hi < 0 || (a.hi == 0 && a.lo < 0) ? -a : a; }
inline DD ldexp(const DD& a, int e) { return {std::ldexp(a.hi, e), std::ldexp(a.lo, e)}; }
/// Square root to about 106 bits (one Newton step from the double root);
/// 0 for 0, NaN for a negative argument.
inline DD sqrt(const DD& a) {
  if (!(a.hi > 0)) return a.hi == 0 ? DD(0) : DD(std::numeric_limits<double>::quiet_NaN());
  const double q = std::sqrt(a.hi);
  const DD r = a - two_prod(q, q);
  return quick_two_sum(q, r.hi / (2 * q));
}

/// Whether a case of this scale (largest coordinate or extent, > 0) keeps
/// the search's products normal in double-double: its sixth power and the
/// low parts below it stay between the smallest normal and the largest
/// double.
inline bool in_range(double scale) { return scale > 0x1p-100 && scale < 0x1p+100; }

}  // namespace geomcheck::oracle::dd

namespace std {
template <>
class numeric_limits<geomcheck::oracle::dd::DD> : public numeric_limits<double> {
 public:
  static constexpr int digits = 106;
  static constexpr int digits10 = 31;
};
}  // namespace std
