// geomcheck — internal: the sign filters of the cylinder/triangle query's
// exact orientation tests, in one place so that production and its tests
// (oracles/tests/test_filters.cpp) evaluate the same expressions.
//
// Each gives the rounded value and a bound of its rounding error: wherever
// |value| > bound, the sign of `value` is the exact sign; elsewhere the
// caller decides with exact expansion arithmetic.
#pragma once

#include <cmath>

#include "geomcheck/predicates2d.hpp"  // detail::FilterValue
#include "geomcheck/vec3.hpp"

namespace geomcheck::detail {

/// w . (x - y): each difference within 2^-53 of itself, the dot product
/// within 3 * 2^-53 of the sum of its terms' magnitudes; bound 2^-50 of that
/// sum, plus 2^-1020 for products that underflow.
inline FilterValue dot_difference_filter(Vec3 w, Vec3 x, Vec3 y) {
  const Vec3 d = x - y;
  const double mag = std::fabs(w[0] * d[0]) + std::fabs(w[1] * d[1]) + std::fabs(w[2] * d[2]);
  return {dot(w, d), 0x1p-50 * mag + 0x1p-1020, true};
}

/// q . (a x b) with max-norm magnitudes mq, |a|, |b|: bound 2^-46 mq |a| |b|
/// (the rounding of the cross product's minors and of the dot product is
/// below 2^-49 of that product), plus 2^-1020 (1 + mq) for underflow: a
/// minor's two products lose at most 2^-1075 each, which q multiplies, and
/// the three products q_i m_i at most 2^-1075 each (subnormal sums are
/// exact). Without that term the bound itself underflowed to 0 for
/// coordinates near 2^-350 while the value, a few subnormal ulps, had the
/// wrong sign (oracles/tests/test_filters.cpp).
inline FilterValue triple_filter(Vec3 q, Vec3 a, Vec3 b) {
  const double mq = max_abs(q);
  return {dot(q, cross(a, b)), 0x1p-46 * (mq * max_abs(a) * max_abs(b)) + 0x1p-1020 * (1 + mq), true};
}

}  // namespace geomcheck::detail
