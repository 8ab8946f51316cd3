// geomcheck — generic description of each shape as a named list of doubles.
//
// Used by case files, fuzz decoding and reports: a shape is its kind name and
// fields, each field one or three doubles, in the order stored.
#pragma once

#include <array>
#include <cstddef>

#include "geomcheck/shapes.hpp"

namespace geomcheck {

/// A named field of a shape: `arity` is 1 (scalar) or 3 (vector).
struct ShapeField {
  const char* name;
  int arity;
};

template <class S> struct ShapeTraits;

template <> struct ShapeTraits<Segment> {
  static constexpr const char* kind = "segment";
  static constexpr std::array<ShapeField, 2> fields{{{"a", 3}, {"b", 3}}};
  static constexpr std::size_t size = 6;
  static void to(const Segment& s, double* v) { put(s.a, v); put(s.b, v + 3); }
  static Segment from(const double* v) { return {get(v), get(v + 3)}; }
  static void put(Vec3 a, double* v) { v[0] = a.x; v[1] = a.y; v[2] = a.z; }
  static Vec3 get(const double* v) { return {v[0], v[1], v[2]}; }
};
template <> struct ShapeTraits<Sphere> {
  static constexpr const char* kind = "sphere";
  static constexpr std::array<ShapeField, 2> fields{{{"c", 3}, {"r", 1}}};
  static constexpr std::size_t size = 4;
  static void to(const Sphere& s, double* v) { ShapeTraits<Segment>::put(s.c, v); v[3] = s.r; }
  static Sphere from(const double* v) { return {ShapeTraits<Segment>::get(v), v[3]}; }
};
/// The fields of a solid around a segment: its ends p and q and its radius r
/// (Capsule, Cylinder); the specialisations add the kind.
template <class S> struct AxisRadiusTraits {
  static constexpr std::array<ShapeField, 3> fields{{{"p", 3}, {"q", 3}, {"r", 1}}};
  static constexpr std::size_t size = 7;
  /// Stores p, q and r into v[0..7).
  static void to(const S& s, double* v) {
    ShapeTraits<Segment>::put(s.p, v); ShapeTraits<Segment>::put(s.q, v + 3); v[6] = s.r;
  }
  /// The solid of v[0..7) as stored by to().
  static S from(const double* v) {
    return {ShapeTraits<Segment>::get(v), ShapeTraits<Segment>::get(v + 3), v[6]};
  }
};
template <> struct ShapeTraits<Capsule> : AxisRadiusTraits<Capsule> {
  static constexpr const char* kind = "capsule";
};
template <> struct ShapeTraits<Cylinder> : AxisRadiusTraits<Cylinder> {
  static constexpr const char* kind = "cylinder";
};
template <> struct ShapeTraits<Obb> {
  static constexpr const char* kind = "obb";
  static constexpr std::array<ShapeField, 5> fields{{{"c", 3}, {"u0", 3}, {"u1", 3}, {"u2", 3}, {"e", 3}}};
  static constexpr std::size_t size = 15;
  static void to(const Obb& s, double* v) {
    ShapeTraits<Segment>::put(s.c, v);
    for (int i = 0; i < 3; ++i) ShapeTraits<Segment>::put(s.axes[i], v + 3 + 3 * i);
    ShapeTraits<Segment>::put(s.e, v + 12);
  }
  static Obb from(const double* v) {
    Obb o;
    o.c = ShapeTraits<Segment>::get(v);
    for (int i = 0; i < 3; ++i) o.axes[i] = ShapeTraits<Segment>::get(v + 3 + 3 * i);
    o.e = ShapeTraits<Segment>::get(v + 12);
    return o;
  }
};
template <> struct ShapeTraits<Triangle> {
  static constexpr const char* kind = "triangle";
  static constexpr std::array<ShapeField, 3> fields{{{"a", 3}, {"b", 3}, {"c", 3}}};
  static constexpr std::size_t size = 9;
  static void to(const Triangle& s, double* v) {
    ShapeTraits<Segment>::put(s.a, v); ShapeTraits<Segment>::put(s.b, v + 3); ShapeTraits<Segment>::put(s.c, v + 6);
  }
  static Triangle from(const double* v) {
    return {ShapeTraits<Segment>::get(v), ShapeTraits<Segment>::get(v + 3), ShapeTraits<Segment>::get(v + 6)};
  }
};

template <> struct ShapeTraits<MovingSphere> {
  static constexpr const char* kind = "moving_sphere";
  static constexpr std::array<ShapeField, 3> fields{{{"c", 3}, {"r", 1}, {"delta", 3}}};
  static constexpr std::size_t size = 7;
  static void to(const MovingSphere& s, double* v) {
    ShapeTraits<Segment>::put(s.c, v); v[3] = s.r; ShapeTraits<Segment>::put(s.delta, v + 4);
  }
  static MovingSphere from(const double* v) {
    return {ShapeTraits<Segment>::get(v), v[3], ShapeTraits<Segment>::get(v + 4)};
  }
};

}  // namespace geomcheck
