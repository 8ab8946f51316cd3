// geomcheck — internal: error-free steps in doubles shared by the
// predicates (predicates2d.cpp, predicates3d.cpp): Knuth's two-sum, and a
// difference, product or sum checked to be exact (so that a determinant
// evaluated from such steps is the exact one).
#pragma once

#include <cmath>

namespace geomcheck::detail::exact_steps {

/// x + y == a + b exactly, x the rounded sum (Knuth).
inline void two_sum(double a, double b, double& x, double& y) {
  x = a + b;
  const double bv = x - a, av = x - bv;
  y = (a - av) + (b - bv);
}

inline bool exact_diff(double a, double b, double& d) {
  double err;
  two_sum(a, -b, d, err);
  return err == 0 && std::isfinite(d);
}
inline bool exact_prod(double a, double b, double& p) {
  p = a * b;
  // Zero only from a zero factor; otherwise the residual must vanish and p
  // be large enough that a non-zero residual would have been representable.
  return p == 0 ? (a == 0 || b == 0) : (std::fma(a, b, -p) == 0 && std::fabs(p) >= 0x1p-960);
}
inline bool exact_add(double a, double b, double& s) {
  double err;
  two_sum(a, b, s, err);
  return err == 0 && std::isfinite(s);
}

}  // namespace geomcheck::detail::exact_steps
