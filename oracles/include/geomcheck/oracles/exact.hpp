// geomcheck — exact rational arithmetic and certified intervals for the oracles.
//
// Every finite double is a dyadic rational, so converting production's inputs
// to `Q` (GMP mpq via Boost.Multiprecision) is exact. Square roots are the
// only irrational step: `sqrt_interval` brackets them with MPFR's directed
// rounding (round down for the lower end, up for the upper end) and then
// re-checks the bracket in rationals (lo^2 <= x <= hi^2), so no answer rests
// on an unchecked floating-point comparison.
#pragma once

#include <boost/multiprecision/gmp.hpp>
#include <string>

#include "geomcheck/shapes.hpp"

namespace geomcheck::oracle {

/// Exact rational number.
using Q = boost::multiprecision::mpq_rational;

/// Bits of the MPFR square-root brackets (relative width about 2^-kSqrtBits).
inline constexpr unsigned kSqrtBits = 256;

/// Exact rational vector.
struct QVec {
  Q x, y, z;
};

/// Exact conversion of a finite double / vector.
Q to_q(double v);
QVec to_q(Vec3 v);

QVec operator+(const QVec& a, const QVec& b);
QVec operator-(const QVec& a, const QVec& b);
QVec operator*(const Q& s, const QVec& a);
Q dot(const QVec& a, const QVec& b);
QVec cross(const QVec& a, const QVec& b);

/// A certified enclosure [lo, hi] of a real number.
struct QInterval {
  Q lo, hi;
  bool exact() const { return lo == hi; }
  /// True value's best double approximation (the midpoint, rounded).
  double mid() const;
};

QInterval point(const Q& v);
QInterval operator+(const QInterval& a, const QInterval& b);
QInterval operator-(const QInterval& a, const QInterval& b);
QInterval operator-(const QInterval& a);
QInterval operator*(const QInterval& a, const QInterval& b);
/// Division by an interval that does not contain zero.
QInterval operator/(const QInterval& a, const QInterval& b);
QInterval min(const QInterval& a, const QInterval& b);
QInterval max(const QInterval& a, const QInterval& b);
/// Bracket of sqrt(x) for exact x >= 0; exact when x is a square at kSqrtBits.
QInterval sqrt_interval(const Q& x);
/// Bracket of sqrt over an interval with lo >= 0 (monotone).
QInterval sqrt_interval(const QInterval& x);

/// Double nearest to q (rounded to nearest).
double to_double(const Q& q);
/// Largest double <= q and smallest double >= q.
double to_double_down(const Q& q);
double to_double_up(const Q& q);
/// Short decimal rendering for reports.
std::string to_string(const QInterval& x);

/// Exact rational shapes (inputs converted exactly, or constructed by the
/// harness, e.g. grown/shrunk cylinders for band tests).
struct QSphere { QVec c; Q r; };
struct QSegment { QVec a, b; };
struct QCylinder { QVec p, q; Q r; };

QSphere to_q(const Sphere& s);
QSegment to_q(const Segment& s);
QCylinder to_q(const Cylinder& c);

/// The verdict of an oracle.
enum class Verdict { Separated, Touching, Overlapping, Undecided };
const char* to_string(Verdict v);

}  // namespace geomcheck::oracle
