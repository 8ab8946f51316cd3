#include "geomcheck/oracles/cast_segment_cylinder.hpp"
#include "geomcheck/oracles/cylinder_sphere.hpp"
#include "engine_interval.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <stdexcept>

namespace geomcheck::oracle {

const char* to_string(CastFeature f) {
  switch (f) {
    case CastFeature::None: return "none";
    case CastFeature::StartInside: return "start-inside";
    case CastFeature::CapP: return "cap-p";
    case CastFeature::CapQ: return "cap-q";
    case CastFeature::Side: return "side";
  }
  return "?";
}

namespace {

// The decision of solve_cast, written once for two number types: exact
// rationals (Q) and outward-rounded double intervals (Ie, the filter). Every
// branch asks for a sign; an interval that cannot give one throws Uncertain,
// and the caller decides in rationals instead. So the filter's answer is the
// exact answer whenever it gives one.
struct Uncertain {};

// An interval of doubles whose operations on two points stay a point when
// the operation was exact (error-free transformations: the rounding error of
// a sum, product or quotient is itself computed, and is zero), and are
// widened outwards by one ulp otherwise. Aligned cases (a segment along or
// across the axis, a start on the surface) have exact zeros, which widened
// intervals could never give a sign.
struct Ie {
  double lo = 0, hi = 0;
  bool is_point() const { return lo == hi; }
};
Ie widened(double v) { return {dn(v), up(v)}; }
Ie to_ie(Iv v) { return {v.lo, v.hi}; }
Iv to_iv(Ie v) { return {v.lo, v.hi}; }
// No rounding error below this magnitude goes unseen (a product's error is
// representable when the product is at least 2^-969).
constexpr double kExactFloor = 0x1p-969;
Ie operator+(Ie a, Ie b) {
  if (a.is_point() && b.is_point()) {
    const double s = a.lo + b.lo, bb = s - a.lo;
    const double err = (a.lo - (s - bb)) + (b.lo - bb);  // TwoSum: exact, subnormals included
    if (err == 0 && std::isfinite(s)) return {s, s};
    return widened(s);
  }
  return to_ie(to_iv(a) + to_iv(b));
}
Ie operator-(Ie a) { return {-a.hi, -a.lo}; }
Ie operator-(Ie a, Ie b) { return a + -b; }
Ie operator*(Ie a, Ie b) {
  if ((a.lo == 0 && a.hi == 0) || (b.lo == 0 && b.hi == 0)) return {0, 0};  // an exact zero times anything finite
  if (a.is_point() && b.is_point()) {
    const double p = a.lo * b.lo;
    const double err = std::fma(a.lo, b.lo, -p);
    const bool exact = p == 0 ? (a.lo == 0 || b.lo == 0) : (err == 0 && std::fabs(p) >= kExactFloor);
    if (exact && std::isfinite(p)) return {p, p};
    return widened(p);
  }
  return to_ie(to_iv(a) * to_iv(b));
}
// a / b for b > 0 (certainly).
Ie positive_divide(Ie a, Ie b) {
  if (a.is_point() && b.is_point()) {
    const double q = a.lo / b.lo;
    const double err = std::fma(q, b.lo, -a.lo);
    const bool exact = q == 0 ? a.lo == 0 : (err == 0 && std::fabs(q) >= kExactFloor && std::fabs(a.lo) >= kExactFloor);
    if (exact && std::isfinite(q)) return {q, q};
    return widened(q);
  }
  return to_ie(iv_div(to_iv(a), to_iv(b)));
}
struct IE3 {
  Ie x, y, z;
};
IE3 operator+(const IE3& a, const IE3& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
IE3 operator-(const IE3& a, const IE3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
IE3 operator*(Ie s, const IE3& a) { return {s * a.x, s * a.y, s * a.z}; }
Ie dot(const IE3& a, const IE3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
IE3 cross(const IE3& a, const IE3& b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }

int sign_of(const Q& x) { return x.sign(); }
int sign_of(const Ie& x) {
  if (x.lo > 0) return 1;
  if (x.hi < 0) return -1;
  if (x.lo == 0 && x.hi == 0) return 0;  // an exact zero
  throw Uncertain{};                       // zero, or NaN: not decided here
}
// The sign of a - b.
int compare(const Q& a, const Q& b) { return a < b ? -1 : (b < a ? 1 : 0); }
int compare(const Ie& a, const Ie& b) { return sign_of(a - b); }
// a / b for b of known, nonzero sign.
Q divide(const Q& a, const Q& b) { return a / b; }
Ie divide(const Ie& a, const Ie& b) { return sign_of(b) > 0 ? positive_divide(a, b) : positive_divide(-a, -b); }
template <class N> N constant(int k);
template <> Q constant<Q>(int k) { return Q(k); }
template <> Ie constant<Ie>(int k) { return {double(k), double(k)}; }

// Where the first point of the cast is, and what solve_cast needs to enclose
// its parameter.
template <class N>
struct Decision {
  bool hit = false;
  CastFeature feature = CastFeature::None;
  enum class At { Lo, LinearRoot, QuadraticRoot } at = At::Lo;
  N lo{}, hi{}, qb{}, qc{}, disc{};
};

template <class N, class V>
Decision<N> decide(const V& a, const V& b, const V& p, const V& d, const N& k, const N& r) {
  // The cylinder from p to p + k d (k > 0): the products below are those of
  // solve_cast with the axis k d, each divided by its power of k (which
  // changes no sign), so that a segment across or along d, whose products
  // with d are exactly zero, keeps them exactly zero when k is not 1.
  Decision<N> out;
  const V m = a - p;
  const V n = b - a;
  const N dd = dot(d, d);
  if (sign_of(dd) == 0) throw std::invalid_argument("oracle: zero-length cylinder axis");
  const N kdd = k * dd;  // the axial extent of m.d
  const N md = dot(m, d), nd = dot(n, d);
  const V mxd = cross(m, d), nxd = cross(n, d);
  const N qa = dot(nxd, nxd), qb = dot(mxd, nxd), qc = dot(mxd, mxd) - r * r * dd;
  const N two = constant<N>(2);
  auto f = [&](const N& t) { return (qa * t + two * qb) * t + qc; };

  // Axial interval of t, clipped to [0, 1].
  N lo = constant<N>(0), hi = constant<N>(1);
  const int nd_sign = sign_of(nd);
  if (nd_sign == 0) {
    if (sign_of(md) < 0 || compare(md, kdd) > 0) return out;
  } else {
    N t0 = divide(-md, nd), t1 = divide(kdd - md, nd);
    if (compare(t0, t1) > 0) std::swap(t0, t1);
    if (compare(t0, lo) > 0) lo = t0;
    if (compare(t1, hi) < 0) hi = t1;
    if (compare(lo, hi) > 0) return out;
  }

  if (sign_of(f(lo)) <= 0) {
    out.hit = true;
    out.lo = lo;
    out.at = Decision<N>::At::Lo;
    if (sign_of(lo) == 0) out.feature = CastFeature::StartInside;
    else out.feature = nd_sign > 0 ? CastFeature::CapP : CastFeature::CapQ;
    return out;
  }
  // f(lo) > 0: enter through the side, if at all.
  out.qb = qb;
  out.qc = qc;
  const int qa_sign = sign_of(qa);
  if (qa_sign == 0) {
    if (sign_of(qb) >= 0) return out;                  // f constant or increasing
    const N root = divide(-qc, two * qb);              // f decreasing, f(lo) > 0 => root > lo
    if (compare(root, hi) > 0) return out;
    out.hit = true;
    out.feature = CastFeature::Side;
    out.at = Decision<N>::At::LinearRoot;
    out.lo = root;
    return out;
  }
  const N disc = qb * qb - qa * qc;
  if (sign_of(disc) < 0) return out;
  const N vertex = divide(-qb, qa);
  if (compare(lo, vertex) >= 0) return out;          // right of both roots, f(lo) > 0
  if (!(compare(hi, vertex) >= 0 || sign_of(f(hi)) <= 0)) return out;
  out.hit = true;
  out.feature = CastFeature::Side;
  out.at = Decision<N>::At::QuadraticRoot;
  out.lo = lo;
  out.hi = hi;
  out.disc = disc;
  return out;
}

Ie to_ie(const Q& x) {
  // mpq_get_d truncates: the value is within one ulp of the double, and is
  // the double when x is one.
  const double v = mpq_get_d(x.backend().data());
  if (std::isfinite(v) && Q(v) == x) return {v, v};
  return widened(v);
}
IE3 to_ie(const QVec& v) { return {to_ie(v.x), to_ie(v.y), to_ie(v.z)}; }

}  // namespace

CastTruth solve_cast(const QSegment& s, const QCylinder& c) {
  CastTruth out;
  const Decision<Q> k = decide(s.a, s.b, c.p, c.q - c.p, Q(1), c.r);
  if (!k.hit) return out;
  out.hit = true;
  out.feature = k.feature;
  switch (k.at) {
    case Decision<Q>::At::Lo: out.t = point(k.lo); break;
    case Decision<Q>::At::LinearRoot: out.t = point(k.lo); break;
    case Decision<Q>::At::QuadraticRoot: {
      // lo < vertex with lo >= 0 implies qb < 0, and f(0) > 0 (f(lo) > 0 left
      // of the roots), so qc > 0: the root qc / (-qb + sqrt(disc)) has no
      // cancellation.
      const QInterval sq = sqrt_interval(k.disc);
      out.t = point(k.qc) / (point(-k.qb) + sq);
      // The root is in (lo, hi]: tighten the enclosure with what is known exactly.
      if (out.t.lo < k.lo) out.t.lo = k.lo;
      if (out.t.hi > k.hi) out.t.hi = k.hi;
      break;
    }
  }
  return out;
}

namespace {
std::atomic<bool> g_cast_filter{true};
}  // namespace

void set_cast_filter(bool on) { g_cast_filter.store(on, std::memory_order_relaxed); }

CastFilterCounts& cast_filter_counts() {
  thread_local CastFilterCounts counts;
  return counts;
}

bool cast_hits(const QSegment& s, const QCylinder& c) {
  if (!g_cast_filter.load(std::memory_order_relaxed)) return solve_cast(s, c).hit;
  try {
    const IE3 p = to_ie(c.p);
    const bool hit = decide(to_ie(s.a), to_ie(s.b), p, to_ie(c.q) - p, constant<Ie>(1), to_ie(c.r)).hit;
    ++cast_filter_counts().decided;
    return hit;
  } catch (const Uncertain&) {
    ++cast_filter_counts().exact;
    return solve_cast(s, c).hit;
  }
}

bool cast_meets_adjusted(const QSegment& s, const QCylinder& c, const Q& delta, int sign) {
  try {
    if (!g_cast_filter.load(std::memory_order_relaxed)) throw Uncertain{};
    // grown / shrunk below, in intervals: e = delta / len, where len is the
    // lower end of sqrt_interval(d.d) (256 bits, rounded down), which lies in
    // [sqrt(d.d) (1 - 2^-255), sqrt(d.d)], inside [dn(sqrt lower), sqrt upper].
    const IE3 p = to_ie(c.p), q = to_ie(c.q), d = q - p;
    const Ie r = to_ie(c.r), dl = to_ie(delta);
    const Iv root = iv_sqrt(to_iv(dot(d, d)));
    const Ie len{dn(root.lo), root.hi};
    if (sign_of(len) <= 0) throw Uncertain{};
    const Ie e = to_ie(iv_div(to_iv(dl), to_iv(len)));
    const IE3 a = to_ie(s.a), b = to_ie(s.b);
    bool hit = false;
    // grown: from p - e d to q + e d = (p - e d) + (1 + 2e) d; shrunk alike.
    const Ie one = constant<Ie>(1), two_e = constant<Ie>(2) * e;
    if (sign > 0) hit = decide(a, b, p - e * d, d, one + two_e, r + dl).hit;
    else if (compare(r, dl) >= 0 && compare(two_e, one) < 0)
      hit = decide(a, b, p + e * d, d, one - two_e, r - dl).hit;
    ++cast_filter_counts().decided;
    return hit;
  } catch (const Uncertain&) {
    ++cast_filter_counts().exact;
    if (sign > 0) return solve_cast(s, grown(c, delta)).hit;
    const auto sh = shrunk(c, delta);
    return sh && solve_cast(s, *sh).hit;
  }
}

CastTruth solve_cast(const Segment& s, const Cylinder& c) { return solve_cast(to_q(s), to_q(c)); }

namespace {
// e >= delta / |d| (so e * d has length >= delta).
Q axis_fraction(const QCylinder& c, const Q& delta) {
  const QVec d = c.q - c.p;
  const QInterval len = sqrt_interval(dot(d, d));
  return delta / len.lo;
}
}  // namespace

QCylinder grown(const QCylinder& c, const Q& delta) {
  const Q e = axis_fraction(c, delta);
  const QVec d = c.q - c.p;
  return {c.p - e * d, c.q + e * d, c.r + delta};
}

std::optional<QCylinder> shrunk(const QCylinder& c, const Q& delta) {
  const Q e = axis_fraction(c, delta);
  if (c.r < delta || 2 * e >= 1) return std::nullopt;
  const QVec d = c.q - c.p;
  return QCylinder{c.p + e * d, c.q - e * d, c.r - delta};
}

}  // namespace geomcheck::oracle
