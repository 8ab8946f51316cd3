// geomcheck benchmarks — deterministic input generation (same numbers on
// every platform: no std:: distributions, whose output is implementation
// defined).
#pragma once

#include <cmath>
#include <cstdint>

#include "geomcheck/shapes.hpp"

namespace geomcheck::bench {

/// SplitMix64: small, fast, fully specified.
class Rng {
 public:
  explicit Rng(std::uint64_t seed) : s_(seed) {}
  std::uint64_t next() {
    std::uint64_t z = (s_ += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
  }
  /// Uniform in [0, 1).
  double unit() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }
  /// Uniform in [lo, hi).
  double uniform(double lo, double hi) { return lo + (hi - lo) * unit(); }
  Vec3 in_box(double h) { return {uniform(-h, h), uniform(-h, h), uniform(-h, h)}; }
  /// Uniform direction (rejection sampling in the unit ball).
  Vec3 direction() {
    for (;;) {
      const Vec3 v = in_box(1.0);
      const double l2 = dot(v, v);
      if (l2 > 1e-4 && l2 <= 1.0) return (1.0 / std::sqrt(l2)) * v;
    }
  }
  /// A random cylinder: base in [-10, 10]^3, length in [0.5, 4], radius in [0.1, 1.5].
  Cylinder cylinder() {
    Cylinder c;
    c.p = in_box(10.0);
    c.q = c.p + uniform(0.5, 4.0) * direction();
    c.r = uniform(0.1, 1.5);
    return c;
  }

 private:
  std::uint64_t s_;
};

}  // namespace geomcheck::bench
