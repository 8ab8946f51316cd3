// geomcheck — metamorphic moves on points and shapes (internal to properties/).
#pragma once

#include <cmath>

#include "geomcheck/shape_traits.hpp"
#include "geomcheck/shapes.hpp"

namespace geomcheck::moves {

/// A move applied to points (`pt`) and to free vectors / normals (`vec`),
/// with the factor it applies to lengths.
struct Move {
  int id;
  Vec3 pt(Vec3 v) const {
    switch (id) {
      case 0: return {-v.x, v.y, v.z};
      case 1: return {-v.x, -v.y, -v.z};
      case 2: return {std::ldexp(v.x, 8), std::ldexp(v.y, 8), std::ldexp(v.z, 8)};
      case 3: return {std::ldexp(v.x, -8), std::ldexp(v.y, -8), std::ldexp(v.z, -8)};
      case 4: return {v.y, v.z, v.x};
      default: {
        // Rotation about (1,2,2)/3 by an angle with cos = 3/5 (rounded), then a translation.
        const double c = 0.6, s = 0.8, k = 1 - c;
        const Vec3 a{1.0 / 3, 2.0 / 3, 2.0 / 3};
        const Vec3 r = c * v + s * cross(a, v) + (k * dot(a, v)) * a;
        return r + Vec3{0.25, -0.5, 0.125};
      }
    }
  }
  Vec3 vec(Vec3 v) const {
    if (id == 2 || id == 3) return v;  // directions do not scale
    if (id == 5) return pt(v) - pt(Vec3{0, 0, 0});
    return pt(v);
  }
  double len(double r) const {
    if (id == 2) return std::ldexp(r, 8);
    if (id == 3) return std::ldexp(r, -8);
    return r;
  }
  /// Moves that must give bit-identical answers.
  bool exact() const { return id <= 3; }
};

/// How far the rounded rigid motion (id 5) may move a cylinder's surface, as
/// a multiple of scale: endpoints move by a few ulps of the scene, and a
/// point of the rim moves by that times (1 + 2 r / |q - p|) since the axis
/// direction turns (a wide disk with a short axis is badly conditioned).
inline double rigid_slack(const Cylinder& c) {
  const double len = length(c.q - c.p);
  return 8 * 0x1p-52 * (1 + 2 * c.r / len);
}

/// True when v is finite, and zero or normal (not subnormal): scaling it by
/// a power of two keeps it exact.
inline bool scalable(double v, int e) {
  if (v == 0) return true;
  const double s = std::ldexp(v, e);
  return std::isnormal(v) && std::isnormal(s) && std::fabs(v) < 1e150 && std::fabs(v) > 1e-150;
}

/// Every double of a two-shape case can be scaled by 2^e exactly.
template <class Case>
bool scalable_case(const Case& c, int e) {
  double v[ShapeTraits<typename Case::ShapeA>::size + ShapeTraits<typename Case::ShapeB>::size];
  ShapeTraits<typename Case::ShapeA>::to(c.a, v);
  ShapeTraits<typename Case::ShapeB>::to(c.b, v + ShapeTraits<typename Case::ShapeA>::size);
  for (double x : v)
    if (!scalable(x, e)) return false;
  return true;
}

/// Moves whose result is compared: the power-of-two scales only when exact.
template <class Case>
bool applicable(const Case& c, int move) {
  return !((move == 2 && !scalable_case(c, 8)) || (move == 3 && !scalable_case(c, -8)));
}

/// A shape moved (shapes.hpp's mapped: points by pt, a box's axes as
/// directions (never scaled), radii and extents as lengths). The reflection
/// (move 0) makes a box's right-handed frame left-handed: the same set.
template <class Shape>
Shape apply(const Move& m, const Shape& s) {
  return mapped(s, m);
}
/// A displacement scales with the scene (unlike a normal).
inline Vec3 displacement(const Move& m, Vec3 d) { return m.id == 5 ? m.pt(d) - m.pt(Vec3{0, 0, 0}) : m.pt(d); }
inline MovingSphere apply(const Move& m, const MovingSphere& s) { return {m.pt(s.c), m.len(s.r), displacement(m, s.delta)}; }

}  // namespace geomcheck::moves
