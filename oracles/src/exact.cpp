#include "geomcheck/oracles/exact.hpp"

#include <mpfr.h>

#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace geomcheck::oracle {

Q to_q(double v) {
  if (!std::isfinite(v)) throw std::invalid_argument("oracle: non-finite input");
  return Q(v);  // mpq_set_d: exact for finite doubles
}
QVec to_q(Vec3 v) { return {to_q(v.x), to_q(v.y), to_q(v.z)}; }

QVec operator+(const QVec& a, const QVec& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
QVec operator-(const QVec& a, const QVec& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
QVec operator*(const Q& s, const QVec& a) { return {s * a.x, s * a.y, s * a.z}; }
Q dot(const QVec& a, const QVec& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
QVec cross(const QVec& a, const QVec& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

QInterval point(const Q& v) { return {v, v}; }
QInterval operator+(const QInterval& a, const QInterval& b) { return {a.lo + b.lo, a.hi + b.hi}; }
QInterval operator-(const QInterval& a, const QInterval& b) { return {a.lo - b.hi, a.hi - b.lo}; }
QInterval operator-(const QInterval& a) { return {-a.hi, -a.lo}; }
QInterval operator*(const QInterval& a, const QInterval& b) {
  if (a.exact() && b.exact()) return point(a.lo * b.lo);
  Q c[4] = {a.lo * b.lo, a.lo * b.hi, a.hi * b.lo, a.hi * b.hi};
  Q lo = c[0], hi = c[0];
  for (const Q& v : c) {
    if (v < lo) lo = v;
    if (v > hi) hi = v;
  }
  return {lo, hi};
}
QInterval operator/(const QInterval& a, const QInterval& b) {
  if (b.lo <= 0 && b.hi >= 0) throw std::domain_error("oracle: interval division by zero");
  const QInterval inv = {Q(1) / b.hi, Q(1) / b.lo};
  return a * inv;
}
QInterval min(const QInterval& a, const QInterval& b) {
  return {a.lo < b.lo ? a.lo : b.lo, a.hi < b.hi ? a.hi : b.hi};
}
QInterval max(const QInterval& a, const QInterval& b) {
  return {a.lo > b.lo ? a.lo : b.lo, a.hi > b.hi ? a.hi : b.hi};
}

namespace {
Q mpfr_to_q(mpfr_t f) {
  Q out;
  mpfr_get_q(out.backend().data(), f);
  return out;
}
}  // namespace

QInterval sqrt_interval(const Q& x) {
  if (x < 0) throw std::domain_error("oracle: sqrt of a negative number");
  if (x == 0) return point(Q(0));
  mpfr_t lo, hi;
  mpfr_init2(lo, kSqrtBits);
  mpfr_init2(hi, kSqrtBits);
  mpfr_set_q(lo, x.backend().data(), MPFR_RNDD);
  mpfr_sqrt(lo, lo, MPFR_RNDD);
  mpfr_set_q(hi, x.backend().data(), MPFR_RNDU);
  mpfr_sqrt(hi, hi, MPFR_RNDU);
  QInterval out{mpfr_to_q(lo), mpfr_to_q(hi)};
  mpfr_clear(lo);
  mpfr_clear(hi);
  // Certify in rationals, independently of MPFR's rounding guarantee.
  const Q lo2 = out.lo * out.lo;
  if (lo2 == x) return point(out.lo);
  if (!(lo2 < x && out.hi * out.hi >= x))
    throw std::logic_error("oracle: square-root bracket failed its rational check");
  return out;
}

QInterval sqrt_interval(const QInterval& x) {
  if (x.lo < 0) throw std::domain_error("oracle: sqrt of an interval reaching below zero");
  if (x.exact()) return sqrt_interval(x.lo);
  return {sqrt_interval(x.lo).lo, sqrt_interval(x.hi).hi};
}

namespace {
double to_double_rounded(const Q& q, mpfr_rnd_t mode) {
  mpfr_t f;
  mpfr_init2(f, 53);
  mpfr_set_q(f, q.backend().data(), mode);
  const double d = mpfr_get_d(f, mode);
  mpfr_clear(f);
  return d;
}
}  // namespace

double to_double(const Q& q) { return to_double_rounded(q, MPFR_RNDN); }
double to_double_down(const Q& q) { return to_double_rounded(q, MPFR_RNDD); }
double to_double_up(const Q& q) { return to_double_rounded(q, MPFR_RNDU); }

double QInterval::mid() const { return to_double((lo + hi) / 2); }


std::string to_string(const QInterval& x) {
  char buf[96];
  if (x.exact()) {
    std::snprintf(buf, sizeof buf, "%.17g (exact)", to_double(x.lo));
  } else {
    std::snprintf(buf, sizeof buf, "[%.17g, %.17g]", to_double_down(x.lo), to_double_up(x.hi));
  }
  return buf;
}

QSphere to_q(const Sphere& s) { return {to_q(s.c), to_q(s.r)}; }
QSegment to_q(const Segment& s) { return {to_q(s.a), to_q(s.b)}; }
QCylinder to_q(const Cylinder& c) { return {to_q(c.p), to_q(c.q), to_q(c.r)}; }

const char* to_string(Verdict v) {
  switch (v) {
    case Verdict::Separated: return "separated";
    case Verdict::Touching: return "touching";
    case Verdict::Overlapping: return "overlapping";
    case Verdict::Undecided: return "undecided";
  }
  return "?";
}

}  // namespace geomcheck::oracle
