// geomcheck — a failing case made simpler before it is saved.
//
// A counterexample is read by a person: 0.5 says more than
// 0.49999999999999994, and a coordinate that plays no part is best 0.
// shrink() takes a failing case and simplifies its numbers one by one
// (the shapes' numbers in ShapeTraits order): each is tried as 0, then
// rounded to 1, 2, 3, 5, 8 and 12 significant digits, and the first of
// those that still fails is kept; then the next number, in two passes. A
// simplification is kept only where the case still fails, and fails the
// same property (the caller's predicate decides: check_all's first failing
// property equal to the original's), so the shrunk case is a
// counterexample of the same kind. It costs at most `budget` checks; the
// campaign and verify() shrink every case they save.
#pragma once

#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "geomcheck/shape_traits.hpp"

namespace geomcheck {

/// How a shrink went.
struct Shrunk {
  int simplified = 0;  ///< simplifications kept (a number may be simplified in both passes)
  int checks = 0;      ///< checks spent
};

/// x rounded to `digits` significant decimal digits.
inline double round_to_digits(double x, int digits) {
  char b[48];
  std::snprintf(b, sizeof b, "%.*g", digits, x);
  return std::strtod(b, nullptr);
}

/// The failing case c made simpler while `fails(case)` holds (see the
/// header comment); at most `budget` calls of `fails`. `how`, when given,
/// says how many numbers changed and how many checks it took.
template <class Case, class Fails>
Case shrink(const Case& c, Fails&& fails, int budget = 60, Shrunk* how = nullptr) {
  using TA = ShapeTraits<decltype(c.a)>;
  using TB = ShapeTraits<decltype(c.b)>;
  std::array<double, TA::size + TB::size> v{};
  TA::to(c.a, v.data());
  TB::to(c.b, v.data() + TA::size);
  auto make = [](const decltype(v)& x) { return Case{TA::from(x.data()), TB::from(x.data() + TA::size)}; };
  Shrunk s;
  static constexpr int kDigits[] = {1, 2, 3, 5, 8, 12};
  for (int pass = 0; pass < 2; ++pass) {
    bool changed = false;
    for (std::size_t i = 0; i < v.size(); ++i) {
      const double x = v[i];
      if (x == 0 || !std::isfinite(x)) continue;
      double tried[1 + std::size(kDigits)];
      int n = 0;
      tried[n++] = 0.0;
      for (int d : kDigits) tried[n++] = round_to_digits(x, d);
      for (int k = 0; k < n; ++k) {
        const double y = tried[k];
        if (y == x) break;  // x is already that simple: nothing simpler follows
        bool seen = false;
        for (int j = 0; j < k; ++j) seen = seen || tried[j] == y;
        if (seen) continue;
        if (s.checks >= budget) {
          if (how) *how = s;
          return make(v);
        }
        auto w = v;
        w[i] = y;
        ++s.checks;
        if (fails(make(w))) {
          v = w;
          ++s.simplified;
          changed = true;
          break;
        }
      }
    }
    if (!changed) break;
  }
  if (how) *how = s;
  return make(v);
}

}  // namespace geomcheck
