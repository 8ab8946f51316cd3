// geomcheck — internal: the sign filters of the cylinder/triangle query's
// exact orientation tests (the exact search's keys and the consistent
// contact's frames), in one place so that production and its tests
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

/// w . ((a + b) - (c + d)) (the sign of w against the midpoint of a and b
/// from that of c and d): each coordinate's sums and difference within
/// 3 * 2^-53 of |a_i| + |b_i| + |c_i| + |d_i|, the products and the dot
/// product's two sums within 3 * 2^-53 more of |w_i| times that; bound 2^-49
/// of sum |w_i| (|a_i| + |b_i| + |c_i| + |d_i|) (about 2.7 times that
/// analysis), plus 2^-1000 for products that underflow. Symmetric in a and
/// b and in c and d (the sums commute), and negated exactly with w and the
/// points by a reflection.
inline FilterValue sum_difference_filter(Vec3 w, Vec3 a, Vec3 b, Vec3 c, Vec3 d) {
  double v = 0, m = 0;
  for (int i = 0; i < 3; ++i) {
    v += w[i] * ((a[i] + b[i]) - (c[i] + d[i]));
    m += std::fabs(w[i]) * (std::fabs(a[i]) + std::fabs(b[i]) + std::fabs(c[i]) + std::fabs(d[i]));
  }
  return {v, 0x1p-49 * m + 0x1p-1000, true};
}

}  // namespace geomcheck::detail
