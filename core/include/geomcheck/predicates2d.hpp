// geomcheck — exact 2D predicates on doubles: orientation and in-circle.
//
// Every answer is the sign of the exact determinant of the input doubles
// (no tolerance, no perturbation), for every finite input:
//   1. a floating-point filter (Shewchuk's static bounds ccwerrboundA and
//      iccerrboundA, which cover the rounding of the differences as well);
//      it answers when the computed value is farther from zero than the
//      bound and nothing overflowed or underflowed;
//   (then, out of line, evaluations in doubles where they are shown to be
//   exact: the in-circle differences small integer multiples of one power
//   of two, or every operation of the filter's evaluation error-free;)
//   2. the same filter on each difference vector scaled by its own power of
//      two (and the in-circle lifts by one more), every pivot in turn, with
//      an absolute slack for underflow, so that a set's scale and
//      huge-beside-tiny mixes do not send every test to the exact stages;
//   3. when the filter fails and the coordinate differences are exact and of
//      moderate magnitude (integer grids, nearby points: the common
//      degenerate input), Shewchuk's stage B on fixed-size expansions, which
//      is then exact;
//   4. otherwise exact expansion arithmetic (error-free sums and products,
//      products by fma) on the points scaled by one power of two, when the
//      magnitudes of the involved coordinates span few enough binades that
//      no partial product can overflow or lose bits to underflow;
//   5. otherwise exact big integers (boost::multiprecision::cpp_int) on the
//      coordinates scaled to integers by one power of two,
//      which cover any mix of magnitudes (1e300 beside 1e-300).
// The caller checks finiteness (non-finite input has no exact answer: the
// result is then unspecified but the call returns).
#pragma once

#include <cmath>

// The filters sit in the inner loops of the triangulation: inlined there.
#if defined(__GNUC__)
#define GEOMCHECK_PREDICATE_INLINE inline __attribute__((always_inline))
#else
#define GEOMCHECK_PREDICATE_INLINE inline
#endif

namespace geomcheck {

struct Vec2 {
  double x = 0, y = 0;
};
inline bool operator==(Vec2 a, Vec2 b) { return a.x == b.x && a.y == b.y; }
inline bool operator!=(Vec2 a, Vec2 b) { return !(a == b); }

namespace detail {
inline constexpr double kPredEps = 0x1p-53;  // half an ulp of 1
inline constexpr double kCcwErrBoundA = (3.0 + 16.0 * kPredEps) * kPredEps;
inline constexpr double kIccErrBoundA = (10.0 + 96.0 * kPredEps) * kPredEps;
// orient2d: below this sum the filter's relative bound could be spoiled by
// an underflowing product (whose absolute error, under 2^-1075, is then
// far below the bound).
inline constexpr double kFilterFloor = 0x1p-900;
// incircle: products of differences are multiplied again by lifts, so an
// underflowing product is not negligible however large the permanent; the
// filter answers only when every non-zero difference is at least this
// large, which keeps every product of four of them normal.
inline constexpr double kIncircleDiffFloor = 0x1p-255;
inline bool incircle_filter_safe(double v) { return v == 0 || std::fabs(v) >= kIncircleDiffFloor; }
/// The exact stages behind the filter (out of line: rarely reached).
int orient2d_exact(Vec2 a, Vec2 b, Vec2 c);
int incircle_exact(Vec2 a, Vec2 b, Vec2 c, Vec2 d);
}  // namespace detail

namespace detail {
/// A filter's rounded value and the bound of its rounding error: wherever
/// `usable` and |value| > bound, the sign of `value` is the exact sign. The
/// predicates below answer from it there and go to the exact stages
/// otherwise; tests drive inputs towards the bound (oracles/tests/test_filters.cpp).
struct FilterValue {
  double value = 0;
  double bound = 0;
  bool usable = true;
};

/// orient2d's filter: det = (a - c)_x (b - c)_y - (a - c)_y (b - c)_x in
/// doubles, bound ccwerrboundA * (|detleft| + |detright|); usable when that
/// sum is at least kFilterFloor (no product underflowed to spoil it).
GEOMCHECK_PREDICATE_INLINE FilterValue orient2d_filter(Vec2 a, Vec2 b, Vec2 c) {
  const double detleft = (a.x - c.x) * (b.y - c.y);
  const double detright = (a.y - c.y) * (b.x - c.x);
  const double detsum = std::fabs(detleft) + std::fabs(detright);
  return {detleft - detright, kCcwErrBoundA * detsum, detsum >= kFilterFloor};
}

/// incircle's filter: the lifted determinant in doubles, bound iccerrboundA
/// times its permanent; usable when every non-zero difference is at least
/// kIncircleDiffFloor.
GEOMCHECK_PREDICATE_INLINE FilterValue incircle_filter(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
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
  return {det, kIccErrBoundA * permanent,
          incircle_filter_safe(adx) && incircle_filter_safe(ady) && incircle_filter_safe(bdx) &&
              incircle_filter_safe(bdy) && incircle_filter_safe(cdx) && incircle_filter_safe(cdy)};
}
}  // namespace detail

/// Sign of det [b - a, c - a]: +1 when a, b, c turn counter-clockwise, -1
/// clockwise, 0 collinear (or coincident points). Exact.
GEOMCHECK_PREDICATE_INLINE int orient2d(Vec2 a, Vec2 b, Vec2 c) {
  const detail::FilterValue f = detail::orient2d_filter(a, b, c);
  if (f.usable && (f.value > f.bound || -f.value > f.bound)) return f.value > 0 ? 1 : -1;
  return detail::orient2d_exact(a, b, c);
}

/// For a, b, c counter-clockwise: +1 when d is strictly inside their
/// circumcircle, -1 strictly outside, 0 on it (the sign flips for a
/// clockwise triangle; 0 for collinear a, b, c means d is on their line or
/// the determinant vanishes). Exact.
GEOMCHECK_PREDICATE_INLINE int incircle(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
  const detail::FilterValue f = detail::incircle_filter(a, b, c, d);
  if (f.usable && (f.value > f.bound || -f.value > f.bound)) return f.value > 0 ? 1 : -1;
  return detail::incircle_exact(a, b, c, d);
}

namespace detail {
/// Stage B alone (2 = not applicable: a difference is inexact or its
/// magnitude is outside [2^-120, 2^120]).
int orient2d_stage_b(Vec2 a, Vec2 b, Vec2 c);
int incircle_stage_b(Vec2 a, Vec2 b, Vec2 c, Vec2 d);
/// The exact stages alone (tests compare them with each other and with an
/// independent exact kernel): expansions (nullopt-like 2 when the range of
/// magnitudes does not allow them), and the big-integer stage (named
/// *_rational: the exact stage that covers every finite input).
int orient2d_expansion(Vec2 a, Vec2 b, Vec2 c);  ///< 2 = not applicable
int incircle_expansion(Vec2 a, Vec2 b, Vec2 c, Vec2 d);  ///< 2 = not applicable
/// The filter again on the difference vectors each scaled by a power of two
/// (largest component in [1, 2)), every pivot in turn, for sets far from 1
/// in scale or mixing huge and tiny points; 2 = cannot decide.
int orient2d_rescaled(Vec2 a, Vec2 b, Vec2 c);
int incircle_rescaled(Vec2 a, Vec2 b, Vec2 c, Vec2 d);
/// The rescaled filters' value and bound with the last point as the pivot
/// (its sign is the determinant's); not usable where a difference is not
/// finite or a difference vector is zero.
FilterValue orient2d_rescaled_filter(Vec2 a, Vec2 b, Vec2 c);
FilterValue incircle_rescaled_filter(Vec2 a, Vec2 b, Vec2 c, Vec2 d);
int orient2d_rational(Vec2 a, Vec2 b, Vec2 c);
int incircle_rational(Vec2 a, Vec2 b, Vec2 c, Vec2 d);
}  // namespace detail

}  // namespace geomcheck
