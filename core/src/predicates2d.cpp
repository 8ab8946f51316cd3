#include "geomcheck/predicates2d.hpp"

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <vector>

#include <boost/multiprecision/cpp_int.hpp>

namespace geomcheck {

namespace {

constexpr double kEps = 0x1p-53;  // half an ulp of 1
constexpr double kCcwErrBoundA = (3.0 + 16.0 * kEps) * kEps;
constexpr double kIccErrBoundA = (10.0 + 96.0 * kEps) * kEps;
// Below this the filter's relative bounds could be spoiled by underflow.
constexpr double kFilterFloor = 0x1p-900;

// ---- expansion arithmetic (Shewchuk 1997): components nonoverlapping, in
// increasing magnitude, zeros eliminated; the value is their exact sum.
using Expansion = std::vector<double>;

inline void two_sum(double a, double b, double& x, double& y) {
  x = a + b;
  const double bv = x - a, av = x - bv;
  y = (a - av) + (b - bv);
}
inline void fast_two_sum(double a, double b, double& x, double& y) {  // |a| >= |b|
  x = a + b;
  y = b - (x - a);
}
inline void two_prod(double a, double b, double& x, double& y) {
  x = a * b;
  y = std::fma(a, b, -x);
}

Expansion grow(const Expansion& e, double b) {
  Expansion h;
  h.reserve(e.size() + 1);
  double q = b;
  for (double ei : e) {
    double s, err;
    two_sum(q, ei, s, err);
    if (err != 0) h.push_back(err);
    q = s;
  }
  if (q != 0) h.push_back(q);
  return h;
}
Expansion sum(Expansion e, const Expansion& f) {
  for (double fi : f) e = grow(e, fi);
  return e;
}
Expansion negate(Expansion e) {
  for (double& x : e) x = -x;
  return e;
}
Expansion scale(const Expansion& e, double b) {
  Expansion h;
  if (e.empty() || b == 0) return h;
  h.reserve(2 * e.size());
  double q, hh;
  two_prod(e[0], b, q, hh);
  if (hh != 0) h.push_back(hh);
  for (std::size_t i = 1; i < e.size(); ++i) {
    double p1, p0, s;
    two_prod(e[i], b, p1, p0);
    two_sum(q, p0, s, hh);
    if (hh != 0) h.push_back(hh);
    fast_two_sum(p1, s, q, hh);
    if (hh != 0) h.push_back(hh);
  }
  if (q != 0) h.push_back(q);
  return h;
}
Expansion mult(const Expansion& e, const Expansion& f) {
  Expansion r;
  for (double fi : f) r = sum(std::move(r), scale(e, fi));
  return r;
}
Expansion diff(double a, double b) {  // a - b, exactly
  double x, y;
  two_sum(a, -b, x, y);
  Expansion e;
  if (y != 0) e.push_back(y);
  if (x != 0) e.push_back(x);
  return e;
}
int sign(const Expansion& e) { return e.empty() ? 0 : (e.back() > 0 ? 1 : -1); }

// The power of two that brings the largest coordinate into [0.5, 1), and
// whether the magnitudes span at most `max_span` binades (zeros aside).
bool scaling(std::initializer_list<double> xs, int max_span, int& shift) {
  int hi = -100000, lo = 100000;
  for (double x : xs) {
    if (x == 0) continue;
    int ex;
    std::frexp(x, &ex);
    hi = std::max(hi, ex), lo = std::min(lo, ex);
  }
  if (hi < lo) {  // all zero
    shift = 0;
    return true;
  }
  shift = -hi;
  return hi - lo <= max_span;
}

using Rational = boost::multiprecision::cpp_rational;

int sign_of(const Rational& q) { return q > 0 ? 1 : (q < 0 ? -1 : 0); }

}  // namespace

namespace detail {

int orient2d_expansion(Vec2 a, Vec2 b, Vec2 c) {
  // Degree 2: partial products stay far from underflow within 300 binades.
  int k;
  if (!scaling({a.x, a.y, b.x, b.y, c.x, c.y}, 300, k)) return 2;
  auto s = [k](double x) { return std::ldexp(x, k); };
  const Expansion acx = diff(s(a.x), s(c.x)), acy = diff(s(a.y), s(c.y));
  const Expansion bcx = diff(s(b.x), s(c.x)), bcy = diff(s(b.y), s(c.y));
  return sign(sum(mult(acx, bcy), negate(mult(acy, bcx))));
}

int incircle_expansion(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
  // Degree 4: within 120 binades no partial product comes near underflow.
  int k;
  if (!scaling({a.x, a.y, b.x, b.y, c.x, c.y, d.x, d.y}, 120, k)) return 2;
  auto s = [k](double x) { return std::ldexp(x, k); };
  const Expansion adx = diff(s(a.x), s(d.x)), ady = diff(s(a.y), s(d.y));
  const Expansion bdx = diff(s(b.x), s(d.x)), bdy = diff(s(b.y), s(d.y));
  const Expansion cdx = diff(s(c.x), s(d.x)), cdy = diff(s(c.y), s(d.y));
  const Expansion alift = sum(mult(adx, adx), mult(ady, ady));
  const Expansion blift = sum(mult(bdx, bdx), mult(bdy, bdy));
  const Expansion clift = sum(mult(cdx, cdx), mult(cdy, cdy));
  const Expansion bc = sum(mult(bdx, cdy), negate(mult(cdx, bdy)));
  const Expansion ca = sum(mult(cdx, ady), negate(mult(adx, cdy)));
  const Expansion ab = sum(mult(adx, bdy), negate(mult(bdx, ady)));
  return sign(sum(sum(mult(alift, bc), mult(blift, ca)), mult(clift, ab)));
}

int orient2d_rational(Vec2 a, Vec2 b, Vec2 c) {
  const Rational acx = Rational(a.x) - Rational(c.x), acy = Rational(a.y) - Rational(c.y);
  const Rational bcx = Rational(b.x) - Rational(c.x), bcy = Rational(b.y) - Rational(c.y);
  return sign_of(acx * bcy - acy * bcx);
}

int incircle_rational(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
  const Rational adx = Rational(a.x) - Rational(d.x), ady = Rational(a.y) - Rational(d.y);
  const Rational bdx = Rational(b.x) - Rational(d.x), bdy = Rational(b.y) - Rational(d.y);
  const Rational cdx = Rational(c.x) - Rational(d.x), cdy = Rational(c.y) - Rational(d.y);
  const Rational alift = adx * adx + ady * ady, blift = bdx * bdx + bdy * bdy, clift = cdx * cdx + cdy * cdy;
  return sign_of(alift * (bdx * cdy - cdx * bdy) + blift * (cdx * ady - adx * cdy) + clift * (adx * bdy - bdx * ady));
}

}  // namespace detail

int orient2d(Vec2 a, Vec2 b, Vec2 c) {
  const double detleft = (a.x - c.x) * (b.y - c.y);
  const double detright = (a.y - c.y) * (b.x - c.x);
  const double det = detleft - detright;
  const double detsum = std::fabs(detleft) + std::fabs(detright);
  const double bound = kCcwErrBoundA * detsum;
  if (detsum >= kFilterFloor && (det > bound || -det > bound)) return det > 0 ? 1 : -1;
  const int e = detail::orient2d_expansion(a, b, c);
  return e != 2 ? e : detail::orient2d_rational(a, b, c);
}

int incircle(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
  const double adx = a.x - d.x, bdx = b.x - d.x, cdx = c.x - d.x;
  const double ady = a.y - d.y, bdy = b.y - d.y, cdy = c.y - d.y;
  const double bdxcdy = bdx * cdy, cdxbdy = cdx * bdy;
  const double cdxady = cdx * ady, adxcdy = adx * cdy;
  const double adxbdy = adx * bdy, bdxady = bdx * ady;
  const double alift = adx * adx + ady * ady, blift = bdx * bdx + bdy * bdy, clift = cdx * cdx + cdy * cdy;
  const double det = alift * (bdxcdy - cdxbdy) + blift * (cdxady - adxcdy) + clift * (adxbdy - bdxady);
  const double permanent = (std::fabs(bdxcdy) + std::fabs(cdxbdy)) * alift +
                           (std::fabs(cdxady) + std::fabs(adxcdy)) * blift +
                           (std::fabs(adxbdy) + std::fabs(bdxady)) * clift;
  const double bound = kIccErrBoundA * permanent;
  if (permanent >= kFilterFloor && (det > bound || -det > bound)) return det > 0 ? 1 : -1;
  const int e = detail::incircle_expansion(a, b, c, d);
  return e != 2 ? e : detail::incircle_rational(a, b, c, d);
}

}  // namespace geomcheck
