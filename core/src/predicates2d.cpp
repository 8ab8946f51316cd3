#include "geomcheck/predicates2d.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <initializer_list>
#include <vector>

#include "exact_integers.hpp"
#include "exact_steps.hpp"

namespace geomcheck {

namespace {

using detail::exact_integers::Int;
using detail::exact_integers::Scaled;
using detail::exact_integers::sign_of;
using detail::exact_steps::exact_add;
using detail::exact_steps::exact_diff;
using detail::exact_steps::exact_prod;
using detail::exact_steps::two_sum;

// ---- expansion arithmetic (Shewchuk 1997): components nonoverlapping, in
// increasing magnitude, zeros eliminated; the value is their exact sum.
using Expansion = std::vector<double>;

inline void fast_two_sum(double a, double b, double& x, double& y) {  // |a| >= |b|
  x = a + b;
  y = b - (x - a);
}
inline void two_prod(double a, double b, double& x, double& y) {
  x = a * b;
  y = std::fma(a, b, -x);
}

// Shewchuk's scale_expansion_zeroelim and fast_expansion_sum_zeroelim on
// arrays (inputs of at least one component; a zero result is one 0
// component). Stage B calls them on fixed-size arrays, the general stage
// through the vector wrappers below.
int scale_zeroelim(int elen, const double* e, double b, double* h) {
  double q, hh, p1, p0, s;
  two_prod(e[0], b, q, hh);
  int hi = 0;
  if (hh != 0) h[hi++] = hh;
  for (int i = 1; i < elen; ++i) {
    two_prod(e[i], b, p1, p0);
    two_sum(q, p0, s, hh);
    if (hh != 0) h[hi++] = hh;
    fast_two_sum(p1, s, q, hh);
    if (hh != 0) h[hi++] = hh;
  }
  if (q != 0 || hi == 0) h[hi++] = q;
  return hi;
}
int sum_zeroelim(int elen, const double* e, int flen, const double* f, double* h) {
  double q, qnew, hh;
  double enow = e[0], fnow = f[0];
  int ei = 0, fi = 0, hi = 0;
  if ((fnow > enow) == (fnow > -enow)) {
    q = enow;
    enow = ++ei < elen ? e[ei] : 0;
  } else {
    q = fnow;
    fnow = ++fi < flen ? f[fi] : 0;
  }
  if (ei < elen && fi < flen) {
    if ((fnow > enow) == (fnow > -enow)) {
      fast_two_sum(enow, q, qnew, hh);
      enow = ++ei < elen ? e[ei] : 0;
    } else {
      fast_two_sum(fnow, q, qnew, hh);
      fnow = ++fi < flen ? f[fi] : 0;
    }
    q = qnew;
    if (hh != 0) h[hi++] = hh;
    while (ei < elen && fi < flen) {
      if ((fnow > enow) == (fnow > -enow)) {
        two_sum(q, enow, qnew, hh);
        enow = ++ei < elen ? e[ei] : 0;
      } else {
        two_sum(q, fnow, qnew, hh);
        fnow = ++fi < flen ? f[fi] : 0;
      }
      q = qnew;
      if (hh != 0) h[hi++] = hh;
    }
  }
  while (ei < elen) {
    two_sum(q, enow, qnew, hh);
    enow = ++ei < elen ? e[ei] : 0;
    q = qnew;
    if (hh != 0) h[hi++] = hh;
  }
  while (fi < flen) {
    two_sum(q, fnow, qnew, hh);
    fnow = ++fi < flen ? f[fi] : 0;
    q = qnew;
    if (hh != 0) h[hi++] = hh;
  }
  if (q != 0 || hi == 0) h[hi++] = q;
  return hi;
}
// Vector wrappers (an empty vector is zero).
Expansion trimmed(Expansion h, int n) {
  h.resize(n == 1 && h[0] == 0 ? 0 : static_cast<std::size_t>(n));
  return h;
}
Expansion sum(const Expansion& e, const Expansion& f) {
  if (e.empty()) return f;
  if (f.empty()) return e;
  Expansion h(e.size() + f.size());
  const int n = sum_zeroelim(static_cast<int>(e.size()), e.data(), static_cast<int>(f.size()), f.data(), h.data());
  return trimmed(std::move(h), n);
}
Expansion negate(Expansion e) {
  for (double& x : e) x = -x;
  return e;
}
Expansion scale(const Expansion& e, double b) {
  if (e.empty() || b == 0) return {};
  Expansion h(2 * e.size());
  const int n = scale_zeroelim(static_cast<int>(e.size()), e.data(), b, h.data());
  return trimmed(std::move(h), n);
}
Expansion mult(const Expansion& e, const Expansion& f) {
  Expansion r;
  for (double fi : f) r = sum(r, scale(e, fi));
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

int sign_of_array(int n, const double* e) {
  const double top = e[n - 1];
  return top > 0 ? 1 : (top < 0 ? -1 : 0);
}
// a - b as one double, and whether that is exact and 0 or within
// [2^-120, 2^120] in magnitude.
inline bool exact_moderate(double a, double b, double& d) {
  double err;
  two_sum(a, -b, d, err);
  const double m = std::fabs(d);
  return err == 0 && (d == 0 || (m >= 0x1p-120 && m <= 0x1p120));
}
// e (n components) times x times x, plus the same for y: the lifted terms.
int lift_times(const double* bc, int n, double x, double y, double* out) {
  double t1[8], t2[16], t3[8], t4[16];
  const int l1 = scale_zeroelim(n, bc, x, t1);
  const int l2 = scale_zeroelim(l1, t1, x, t2);
  const int l3 = scale_zeroelim(n, bc, y, t3);
  const int l4 = scale_zeroelim(l3, t3, y, t4);
  return sum_zeroelim(l2, t2, l4, t4, out);
}
// p*q - r*s exactly (four components at most).
int two_products_diff(double p, double q, double r, double s, double* out) {
  double a[2], b[2];
  two_prod(p, q, a[1], a[0]);
  two_prod(r, s, b[1], b[0]);
  b[0] = -b[0], b[1] = -b[1];
  return sum_zeroelim(2, a, 2, b, out);
}

// ---- small grids: the six differences exact and integer multiples of one
// power of two 2^g, where 2^(g+11) <= max |difference| < 2^(g+12). Divided
// by 2^g (a power of two: exact unless the result underflows, and an
// underflowing result is zero or subnormal, so it fails the integer test
// below or is a zero from a non-zero difference, which is refused) they
// are integers k below 2^12 in magnitude, so every product is below
// 2^24, every 2x2 minor and lift below 2^25, every lift times minor below
// 2^50 and the determinant below 3 * 2^50 < 2^53: all integers that
// doubles hold exactly, so the determinant of the k's is computed exactly,
// and its sign (the determinant scaled by 2^-4g) is the answer. Integer
// grids, the common degenerate input, pass at the cost of a few operations
// per coordinate (the general check below costs several times more).
bool incircle_small_grid(Vec2 a, Vec2 b, Vec2 c, Vec2 d, int& sign) {
  double v[6];
  const double p[6] = {a.x, a.y, b.x, b.y, c.x, c.y}, q[6] = {d.x, d.y, d.x, d.y, d.x, d.y};
  double m = 0;
  for (int i = 0; i < 6; ++i) {
    double err;
    two_sum(p[i], -q[i], v[i], err);
    if (err != 0 || !std::isfinite(v[i])) return false;
    m = std::max(m, std::fabs(v[i]));
  }
  if (m == 0) return false;  // four equal points: left to the general stages
  std::uint64_t bits;
  std::memcpy(&bits, &m, sizeof bits);
  const int biased = static_cast<int>(bits >> 52);  // m >= 0: no sign bit
  if (biased == 0) return false;                    // subnormal
  const int g = biased - 1023 - 11;
  if (g < -1022 || g > 1022) return false;
  const std::uint64_t scale_bits = static_cast<std::uint64_t>(1023 - g) << 52;
  double scale;  // 2^-g
  std::memcpy(&scale, &scale_bits, sizeof scale);
  double k[6];
  for (int i = 0; i < 6; ++i) {
    const double t = v[i] * scale;  // |t| < 2^12
    const double r = (t + 0x1.8p52) - 0x1.8p52;  // t rounded to an integer (|t| < 2^51)
    if (r != t || (t == 0 && v[i] != 0)) return false;
    k[i] = t;
  }
  const double adx = k[0], ady = k[1], bdx = k[2], bdy = k[3], cdx = k[4], cdy = k[5];
  const double alift = adx * adx + ady * ady, blift = bdx * bdx + bdy * bdy, clift = cdx * cdx + cdy * cdy;
  const double det = alift * (bdx * cdy - cdx * bdy) + blift * (cdx * ady - adx * cdy) + clift * (adx * bdy - bdx * ady);
  sign = det > 0 ? 1 : (det < 0 ? -1 : 0);
  return true;
}

// ---- exact in doubles: the filter's own evaluation, each operation checked
// to be error-free (a zero fma residual or two_sum tail) and normal, so the
// computed determinant is the exact one. Catches small integer grids and
// their power-of-two scalings (the common degenerate input) at little cost.
bool orient2d_in_doubles(Vec2 a, Vec2 b, Vec2 c, int& sign) {
  double acx, acy, bcx, bcy, l, r, det;
  if (!exact_diff(a.x, c.x, acx) || !exact_diff(a.y, c.y, acy) || !exact_diff(b.x, c.x, bcx) ||
      !exact_diff(b.y, c.y, bcy) || !exact_prod(acx, bcy, l) || !exact_prod(acy, bcx, r) || !exact_add(l, -r, det))
    return false;
  sign = det > 0 ? 1 : (det < 0 ? -1 : 0);
  return true;
}
bool incircle_in_doubles(Vec2 a, Vec2 b, Vec2 c, Vec2 d, int& sign) {
  double adx, ady, bdx, bdy, cdx, cdy;
  if (!exact_diff(a.x, d.x, adx) || !exact_diff(a.y, d.y, ady) || !exact_diff(b.x, d.x, bdx) ||
      !exact_diff(b.y, d.y, bdy) || !exact_diff(c.x, d.x, cdx) || !exact_diff(c.y, d.y, cdy))
    return false;
  // One 2x2 minor and one lift, exactly.
  const auto minor = [](double p, double q, double r, double s, double& m) {
    double x, y;
    return exact_prod(p, q, x) && exact_prod(r, s, y) && exact_add(x, -y, m);
  };
  const auto lift = [](double x, double y, double& l) {
    double xx, yy;
    return exact_prod(x, x, xx) && exact_prod(y, y, yy) && exact_add(xx, yy, l);
  };
  double bc, ca, ab, al, bl, cl, t1, t2, t3, s12, det;
  if (!minor(bdx, cdy, cdx, bdy, bc) || !minor(cdx, ady, adx, cdy, ca) || !minor(adx, bdy, bdx, ady, ab) ||
      !lift(adx, ady, al) || !lift(bdx, bdy, bl) || !lift(cdx, cdy, cl) || !exact_prod(al, bc, t1) ||
      !exact_prod(bl, ca, t2) || !exact_prod(cl, ab, t3) || !exact_add(t1, t2, s12) || !exact_add(s12, t3, det))
    return false;
  sign = det > 0 ? 1 : (det < 0 ? -1 : 0);
  return true;
}

}  // namespace

namespace detail {

int orient2d_stage_b(Vec2 a, Vec2 b, Vec2 c) {
  double acx, acy, bcx, bcy;
  if (!exact_moderate(a.x, c.x, acx) || !exact_moderate(a.y, c.y, acy) || !exact_moderate(b.x, c.x, bcx) ||
      !exact_moderate(b.y, c.y, bcy))
    return 2;
  double e[4];
  const int n = two_products_diff(acx, bcy, acy, bcx, e);
  return sign_of_array(n, e);
}

int incircle_stage_b(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
  double adx, ady, bdx, bdy, cdx, cdy;
  if (!exact_moderate(a.x, d.x, adx) || !exact_moderate(a.y, d.y, ady) || !exact_moderate(b.x, d.x, bdx) ||
      !exact_moderate(b.y, d.y, bdy) || !exact_moderate(c.x, d.x, cdx) || !exact_moderate(c.y, d.y, cdy))
    return 2;
  double bc[4], ca[4], ab[4];
  const int nbc = two_products_diff(bdx, cdy, cdx, bdy, bc);
  const int nca = two_products_diff(cdx, ady, adx, cdy, ca);
  const int nab = two_products_diff(adx, bdy, bdx, ady, ab);
  double adet[32], bdet[32], cdet[32], abdet[64], fin[96];
  const int na = lift_times(bc, nbc, adx, ady, adet);
  const int nb = lift_times(ca, nca, bdx, bdy, bdet);
  const int nc = lift_times(ab, nab, cdx, cdy, cdet);
  const int nabd = sum_zeroelim(na, adet, nb, bdet, abdet);
  const int n = sum_zeroelim(nabd, abdet, nc, cdet, fin);
  return sign_of_array(n, fin);
}

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
  const double xs[] = {a.x, a.y, b.x, b.y, c.x, c.y};
  const Scaled<6> s(xs);
  const Int acx = s[0] - s[4], acy = s[1] - s[5], bcx = s[2] - s[4], bcy = s[3] - s[5];
  return sign_of(Int(acx * bcy - acy * bcx));
}

int incircle_rational(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
  const double xs[] = {a.x, a.y, b.x, b.y, c.x, c.y, d.x, d.y};
  const Scaled<8> s(xs);
  const Int adx = s[0] - s[6], ady = s[1] - s[7], bdx = s[2] - s[6], bdy = s[3] - s[7];
  const Int cdx = s[4] - s[6], cdy = s[5] - s[7];
  const Int alift = adx * adx + ady * ady, blift = bdx * bdx + bdy * bdy, clift = cdx * cdx + cdy * cdy;
  return sign_of(Int(alift * (bdx * cdy - cdx * bdy) + blift * (cdx * ady - adx * cdy) + clift * (adx * bdy - bdx * ady)));
}

// ---- the filter again on differences scaled by powers of two -------------
//
// The inline filters refuse where their products may overflow or underflow
// (differences near 2^+-255 for in-circle, determinants below 2^-900 for
// orientation): a set far from 1 in scale, or huge beside tiny points.
// Scaling a row or a column of a determinant by a power of two scales the
// determinant and leaves its sign; here each difference vector (a row) is
// scaled to a largest component in [1, 2), and the in-circle lifts (the
// third column) by the power of two that keeps the largest at most 8
// (row i's lift becomes (X_i^2 + Y_i^2) * 2^(m - k_i), k_i its row's shift,
// m the smallest of them). Every operation is then the unscaled one scaled
// exactly, except where a result falls into the subnormal range.
//
// Error: Shewchuk's relative bounds (ccwerrboundA, iccerrboundA) hold for
// the scaled computation as long as nothing underflows. Scaled, every
// coordinate is below 2 in magnitude, every product of two below 4, every
// minor and lift below 8. Underflow adds at most 2^-1075 to a scaled
// difference or lift (a result in the subnormal range) and to each
// rounded operation. Orientation: each of four scaled coordinates enters
// det = ux*vy - uy*vx with a factor below 2, and three operations follow:
// below 4 * 2 * 2^-1075 + 3 * 2^-1075 < 2^-1070. In-circle: det =
// sum L_i M_i; each of the six coordinates enters it with a factor below
// 64 (through two minors, 2 * 2 * 8, and its own lift, 4 * 8), each lift
// with a factor below 8: below (6 * 64 + 3 * 8) * 2^-1075 < 2^-1065; about
// 25 operations, each multiplied afterwards by at most 8, add below
// 25 * 8 * 2^-1075 < 2^-1067. The absolute slack below is 2^-1060 for both
// (more than 16 times the larger sum); a value that cannot exceed it is
// left to the exact stages.
constexpr double kRescaledSlack = 0x1p-1060;

// The shift that brings max(|x|, |y|) into [1, 2); false when x or y is
// not finite (a difference overflowed) or both are 0.
bool row_shift(double x, double y, int& k) {
  if (!std::isfinite(x) || !std::isfinite(y)) return false;
  const double m = std::max(std::fabs(x), std::fabs(y));
  if (m == 0) return false;
  k = -std::ilogb(m);
  return true;
}

// The rescaled filters' value and bound at one pivot (the last point).
FilterValue orient2d_rescaled_filter(Vec2 a, Vec2 b, Vec2 c) {
  double ux = a.x - c.x, uy = a.y - c.y, vx = b.x - c.x, vy = b.y - c.y;
  int ku, kv;
  if (!row_shift(ux, uy, ku) || !row_shift(vx, vy, kv)) return {0, 0, false};
  ux = std::ldexp(ux, ku), uy = std::ldexp(uy, ku), vx = std::ldexp(vx, kv), vy = std::ldexp(vy, kv);
  const double detleft = ux * vy, detright = uy * vx;
  return {detleft - detright, kCcwErrBoundA * (std::fabs(detleft) + std::fabs(detright)) + kRescaledSlack, true};
}

FilterValue incircle_rescaled_filter(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
  double adx = a.x - d.x, bdx = b.x - d.x, cdx = c.x - d.x;
  double ady = a.y - d.y, bdy = b.y - d.y, cdy = c.y - d.y;
  int ka, kb, kc;
  if (!row_shift(adx, ady, ka) || !row_shift(bdx, bdy, kb) || !row_shift(cdx, cdy, kc)) return {0, 0, false};
  adx = std::ldexp(adx, ka), ady = std::ldexp(ady, ka);
  bdx = std::ldexp(bdx, kb), bdy = std::ldexp(bdy, kb);
  cdx = std::ldexp(cdx, kc), cdy = std::ldexp(cdy, kc);
  const int m = std::min(ka, std::min(kb, kc));
  const double bdxcdy = bdx * cdy, cdxbdy = cdx * bdy;
  const double cdxady = cdx * ady, adxcdy = adx * cdy;
  const double adxbdy = adx * bdy, bdxady = bdx * ady;
  const double alift = std::ldexp(adx * adx + ady * ady, m - ka);
  const double blift = std::ldexp(bdx * bdx + bdy * bdy, m - kb);
  const double clift = std::ldexp(cdx * cdx + cdy * cdy, m - kc);
  const double det = alift * (bdxcdy - cdxbdy) + blift * (cdxady - adxcdy) + clift * (adxbdy - bdxady);
  const double permanent = (std::fabs(bdxcdy) + std::fabs(cdxbdy)) * alift +
                           (std::fabs(cdxady) + std::fabs(adxcdy)) * blift +
                           (std::fabs(adxbdy) + std::fabs(bdxady)) * clift;
  return {det, kIccErrBoundA * permanent + kRescaledSlack, true};
}

// One pivot (the last point) of the rescaled filters below; 0 where a
// difference vector is zero (two equal points: the determinant is 0).
static int orient2d_rescaled_at(Vec2 a, Vec2 b, Vec2 c) {
  if ((a.x == c.x && a.y == c.y) || (b.x == c.x && b.y == c.y)) return 0;  // a difference of doubles is 0 only when exact
  const FilterValue f = orient2d_rescaled_filter(a, b, c);
  if (f.usable && (f.value > f.bound || -f.value > f.bound)) return f.value > 0 ? 1 : -1;
  return 2;
}

static int incircle_rescaled_at(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
  if ((a.x == d.x && a.y == d.y) || (b.x == d.x && b.y == d.y) || (c.x == d.x && c.y == d.y)) return 0;  // a zero row
  const FilterValue f = incircle_rescaled_filter(a, b, c, d);
  if (f.usable && (f.value > f.bound || -f.value > f.bound)) return f.value > 0 ? 1 : -1;
  return 2;
}

// Every pivot in turn: the determinant does not depend on which point the
// differences are taken from, but its rounding does (three tiny points and
// a huge one cancel in the huge one's differences, not in a tiny one's).
// A cyclic shift of three points keeps the orientation; of four points it
// flips the in-circle sign (an odd permutation).
int orient2d_rescaled(Vec2 a, Vec2 b, Vec2 c) {
  int s = orient2d_rescaled_at(a, b, c);
  if (s == 2) s = orient2d_rescaled_at(b, c, a);
  if (s == 2) s = orient2d_rescaled_at(c, a, b);
  return s;
}

int incircle_rescaled(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
  int s = incircle_rescaled_at(a, b, c, d);
  if (s != 2) return s;
  if ((s = incircle_rescaled_at(b, c, d, a)) != 2) return -s;
  if ((s = incircle_rescaled_at(c, d, a, b)) != 2) return s;
  if ((s = incircle_rescaled_at(d, a, b, c)) != 2) return -s;
  return 2;
}

int orient2d_exact(Vec2 a, Vec2 b, Vec2 c) {
  int sd;
  if (orient2d_in_doubles(a, b, c, sd)) return sd;
  const int sr = orient2d_rescaled(a, b, c);
  if (sr != 2) return sr;
  const int sb = orient2d_stage_b(a, b, c);
  if (sb != 2) return sb;
  const int e = orient2d_expansion(a, b, c);
  return e != 2 ? e : orient2d_rational(a, b, c);
}

int incircle_exact(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
  int sd;
  if (incircle_small_grid(a, b, c, d, sd)) return sd;
  if (incircle_in_doubles(a, b, c, d, sd)) return sd;
  const int sr = incircle_rescaled(a, b, c, d);
  if (sr != 2) return sr;
  const int sb = incircle_stage_b(a, b, c, d);
  if (sb != 2) return sb;
  const int e = incircle_expansion(a, b, c, d);
  return e != 2 ? e : incircle_rational(a, b, c, d);
}

}  // namespace detail

}  // namespace geomcheck
