// geomcheck benchmarks — deterministic input generation (same numbers on
// every platform: no std:: distributions, whose output is implementation
// defined), and the batches made from it: balanced or all hitting, shuffled
// so that branches are not predictable.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

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
  /// A random segment and radius: first end in [-10, 10]^3, length in
  /// [min_length, 4], radius in [0.1, 1.5], drawn in that order.
  Capsule segment_and_radius(double min_length) {
    Capsule c;
    c.p = in_box(10.0);
    c.q = c.p + uniform(min_length, 4.0) * direction();
    c.r = uniform(0.1, 1.5);
    return c;
  }
  /// A random cylinder: base in [-10, 10]^3, length in [0.5, 4], radius in [0.1, 1.5].
  Cylinder cylinder() {
    const Capsule s = segment_and_radius(0.5);
    return {s.p, s.q, s.r};
  }
  /// A point uniform in the cube of half side reach + margin around `c`'s
  /// middle, reach being half its length plus its radius.
  Vec3 around(const Cylinder& c, double margin) {
    const Vec3 mid = 0.5 * c.p + 0.5 * c.q;
    const double reach = 0.5 * length(c.q - c.p) + c.r;
    return mid + in_box(reach + margin);
  }
  /// The same around a capsule (its segment's middle; half its length plus
  /// its radius) and a sphere (its centre and radius).
  Vec3 around(const Capsule& c, double margin) { return around(Cylinder{c.p, c.q, c.r}, margin); }
  Vec3 around(const Sphere& s, double margin) { return s.c + in_box(s.r + margin); }
  /// A random sphere: centre in [-10, 10]^3, radius in [0.1, 1.5].
  Sphere sphere() {
    Sphere s;
    s.c = in_box(10.0);
    s.r = uniform(0.1, 1.5);
    return s;
  }
  /// A random capsule: first end in [-10, 10]^3, length in [0, 4], radius in [0.1, 1.5].
  Capsule capsule() { return segment_and_radius(0.0); }
  /// A random first shape of a pair benchmark.
  template <class A>
  A first();
  /// A uniform unit quaternion {w, x, y, z}: rejection in the 4-ball,
  /// keeping squared norms in [min_norm2, 1], then normalised.
  std::array<double, 4> unit_quaternion(double min_norm2) {
    double w, x, y, z, n;
    do {
      w = uniform(-1, 1), x = uniform(-1, 1), y = uniform(-1, 1), z = uniform(-1, 1);
      n = w * w + x * x + y * y + z * z;
    } while (n > 1 || n < min_norm2);
    n = 1 / std::sqrt(n);
    return {w * n, x * n, y * n, z * n};
  }

 private:
  std::uint64_t s_;
};

/// The columns of the rotation matrix of a unit quaternion {w, x, y, z}
/// (orthonormal to rounding).
template <>
inline Cylinder Rng::first<Cylinder>() { return cylinder(); }
template <>
inline Sphere Rng::first<Sphere>() { return sphere(); }
template <>
inline Capsule Rng::first<Capsule>() { return capsule(); }

inline std::array<Vec3, 3> rotation_columns(const std::array<double, 4>& q) {
  const auto [w, x, y, z] = q;
  return {Vec3{1 - 2 * (y * y + z * z), 2 * (x * y + w * z), 2 * (x * z - w * y)},
          Vec3{2 * (x * y - w * z), 1 - 2 * (x * x + z * z), 2 * (y * z + w * x)},
          Vec3{2 * (x * z + w * y), 2 * (y * z - w * x), 1 - 2 * (x * x + y * y)}};
}

/// Shuffles `v` in place (Fisher-Yates, one draw per position).
template <class T>
void shuffle(std::vector<T>& v, Rng& rng) {
  for (std::size_t i = v.size(); i > 1; --i) std::swap(v[i - 1], v[rng.next() % i]);
}

/// Draws (`draw()`) until `n` are kept, exactly half of them hitting
/// according to `verdict` (1 hitting, 0 not, -1 undecided: skipped, and
/// counted in `*undecided` when given); in the order drawn.
template <class Draw, class Verdict>
auto half_hitting(std::size_t n, Draw&& draw, Verdict&& verdict, std::size_t* undecided = nullptr) {
  std::vector<decltype(draw())> out;
  std::size_t n_hit = 0, n_miss = 0;
  while (out.size() < n) {
    const auto x = draw();
    const int hit = verdict(x);
    if (hit < 0) {
      if (undecided) ++*undecided;
      continue;
    }
    if (hit ? n_hit >= n / 2 : n_miss >= n / 2) continue;
    (hit ? n_hit : n_miss)++;
    out.push_back(x);
  }
  return out;
}

/// Draws until `n` hitting ones (verdict 1, as for half_hitting) are kept;
/// `draws` counts the draws, `*undecided` (when given) the undecided ones.
template <class Draw, class Verdict>
auto all_hitting(std::size_t n, Draw&& draw, Verdict&& verdict, std::size_t& draws, std::size_t* undecided = nullptr) {
  std::vector<decltype(draw())> out;
  while (out.size() < n) {
    const auto x = draw();
    const int hit = verdict(x);
    ++draws;
    if (hit < 0 && undecided) ++*undecided;
    if (hit > 0) out.push_back(x);
  }
  return out;
}

// ---- the shapes B of the pair benchmarks, in random poses near a first
// shape A (the query programs and bench_collide_many draw the same way) ----

/// A random pose: the sphere's centre within reach + 1.5 of A's middle,
/// radius in [0.05, 1.5].
template <class A>
Sphere random_sphere(Rng& rng, const A& a) {
  Sphere b;
  b.c = rng.around(a, 1.5);
  b.r = rng.uniform(0.05, 1.5);
  return b;
}

/// A random pose: the capsule's first end within reach + 1.5 of A's
/// middle, its segment up to 3 long, radius in [0.05, 1.5].
template <class A>
Capsule random_capsule(Rng& rng, const A& a) {
  Capsule b;
  b.p = rng.around(a, 1.5);
  b.q = b.p + rng.uniform(0.0, 3.0) * rng.direction();
  b.r = rng.uniform(0.05, 1.5);
  return b;
}

/// A random rotation (unit quaternion to matrix, then Gram-Schmidt: the
/// axes are orthonormal to a few ulps, inside the contract).
inline std::array<Vec3, 3> random_frame(Rng& rng) {
  const std::array<Vec3, 3> m = rotation_columns(rng.unit_quaternion(0.01));
  Vec3 a0 = m[0], a1 = m[1];
  a0 = (1 / length(a0)) * a0;
  a1 = a1 - dot(a1, a0) * a0;
  a1 = (1 / length(a1)) * a1;
  return {a0, a1, cross(a0, a1)};
}

/// A random pose: the box's centre within reach + 1.5 of the cylinder's
/// middle, half extents in [0.05, 1.5], a random rotation.
inline Obb random_box(Rng& rng, const Cylinder& a) {
  Obb b;
  b.c = rng.around(a, 1.5);
  b.axes = random_frame(rng);
  b.e = {rng.uniform(0.05, 1.5), rng.uniform(0.05, 1.5), rng.uniform(0.05, 1.5)};
  return b;
}

}  // namespace geomcheck::bench
