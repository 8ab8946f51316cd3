// geomcheck — the shapes, with the exact meaning of their stored doubles.
//
// Every shape is a CLOSED solid defined exactly by the doubles it stores
// (each finite double is an exact dyadic rational, so the exact oracles see
// exactly what production sees). Touching counts as overlapping.
//
//   Segment{a, b}      the closed segment ab; a == b is a point.
//   Sphere{c, r}       the closed ball |x - c| <= r, r >= 0.
//   Capsule{p, q, r}   segment pq swept by a ball of radius r.
//   Cylinder{p, q, r}  { x : 0 <= (x-p).(q-p) <= |q-p|^2  and
//                            |(x-p) x (q-p)|^2 <= r^2 |q-p|^2 }
//                      flat caps, sharp rims; p == q is invalid; r == 0 is
//                      the segment pq.
//   Obb{c, axes, e}    { c + sum_i t_i e_i axes_i : |t_i| <= 1 }, the
//                      parallelepiped spanned by the stored axes (production
//                      may assume them orthonormal).
//   Triangle{a, b, c}  the closed triangle; a degenerate one is its segment
//                      or point.
//   MovingSphere{c, r, delta}  the first argument of a sweep: the ball
//                      Sphere{c, r} moving to c + delta (positions
//                      c + t delta, t in [0, 1], computed exactly).
//
// `is_valid` is the single gate: non-finite values, negative radii or
// extents and a zero-length cylinder axis are invalid, and every query
// answers "no overlap / no hit" for invalid input.
#pragma once

#include <array>
#include <cstddef>
#include <cmath>

#include "geomcheck/vec3.hpp"

namespace geomcheck {

/// Closed segment from `a` to `b`.
struct Segment { Vec3 a, b; };
/// Closed ball of centre `c` and radius `r`.
struct Sphere { Vec3 c; double r = 0; };
/// Segment `pq` swept by a ball of radius `r`.
struct Capsule { Vec3 p, q; double r = 0; };
/// Flat-capped cylinder with cap centres `p`, `q` and radius `r`.
struct Cylinder { Vec3 p, q; double r = 0; };
/// Parallelepiped with centre `c`, stored axes and half extents `e` along them.
struct Obb { Vec3 c; std::array<Vec3, 3> axes{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}}; Vec3 e; };
/// Closed triangle.
struct Triangle { Vec3 a, b, c; };
/// A ball of centre `c` and radius `r` moving by `delta` (sweep queries).
struct MovingSphere { Vec3 c; double r = 0; Vec3 delta; };

namespace detail {
/// Pairwise sum of z[Lo, Hi): dependency depth log2(n), not n. The bounds
/// are template arguments, so that the whole tree is unrolled and inlined
/// (with run-time bounds it compiled to a recursive call).
template <std::size_t Lo, std::size_t Hi, std::size_t N>
constexpr double pairwise_sum(const double (&z)[N]) {
  if constexpr (Hi - Lo == 1) {
    return z[Lo];
  } else {
    return pairwise_sum<Lo, Lo + (Hi - Lo) / 2>(z) + pairwise_sum<Lo + (Hi - Lo) / 2, Hi>(z);
  }
}
}  // namespace detail

/// True when every value is finite: 0 * x is 0 for finite x and NaN for
/// +-inf or NaN, and the pairwise sum of those is 0 exactly when all are
/// finite (two instructions a value, no branch, short dependency chains).
template <class... T>
constexpr bool all_finite(T... v) {
  const double z[] = {(0.0 * v)...};
  return detail::pairwise_sum<0, sizeof...(T)>(z) == 0.0;
}
inline bool all_finite(Vec3 a) { return all_finite(a.x, a.y, a.z); }

/// Valid: both endpoints finite.
inline bool is_valid(const Segment& s) { return all_finite(s.a.x, s.a.y, s.a.z, s.b.x, s.b.y, s.b.z); }
/// Valid: finite centre, finite radius >= 0.
inline bool is_valid(const Sphere& s) { return all_finite(s.c.x, s.c.y, s.c.z, s.r) && s.r >= 0; }
/// Valid: finite endpoints, finite radius >= 0.
inline bool is_valid(const Capsule& s) {
  return all_finite(s.p.x, s.p.y, s.p.z, s.q.x, s.q.y, s.q.z, s.r) && s.r >= 0;
}
/// Valid: finite endpoints, p != q, finite radius >= 0. (Lengths whose
/// squares overflow or underflow are valid: the queries rescale the scene.)
inline bool is_valid(const Cylinder& s) {
  return all_finite(s.p.x, s.p.y, s.p.z, s.q.x, s.q.y, s.q.z, s.r) && s.r >= 0 && s.p != s.q;
}
/// Valid: finite centre, axes and extents, extents >= 0.
inline bool is_valid(const Obb& s) {
  return all_finite(s.c) && all_finite(s.axes[0]) && all_finite(s.axes[1]) && all_finite(s.axes[2]) &&
         all_finite(s.e) && s.e.x >= 0 && s.e.y >= 0 && s.e.z >= 0;
}
/// Valid: finite vertices.
inline bool is_valid(const Triangle& s) { return all_finite(s.a) && all_finite(s.b) && all_finite(s.c); }

/// A shape under a map of space `m` (any object with Vec3 pt(Vec3) for
/// points, Vec3 vec(Vec3) for directions and double len(double) for
/// lengths): points move by pt, a box's axes by vec, radii and a box's
/// extents (in the box's own frame) by len. Written once per shape, for
/// every map: the checks' metamorphic moves and FCL's exact re-expressions
/// of a scene.
template <class M> Segment mapped(const Segment& s, const M& m) { return {m.pt(s.a), m.pt(s.b)}; }
template <class M> Sphere mapped(const Sphere& s, const M& m) { return {m.pt(s.c), m.len(s.r)}; }
template <class M> Capsule mapped(const Capsule& c, const M& m) { return {m.pt(c.p), m.pt(c.q), m.len(c.r)}; }
template <class M> Cylinder mapped(const Cylinder& c, const M& m) { return {m.pt(c.p), m.pt(c.q), m.len(c.r)}; }
template <class M> Obb mapped(const Obb& b, const M& m) {
  return {m.pt(b.c), {{m.vec(b.axes[0]), m.vec(b.axes[1]), m.vec(b.axes[2])}}, {m.len(b.e.x), m.len(b.e.y), m.len(b.e.z)}};
}
template <class M> Triangle mapped(const Triangle& t, const M& m) { return {m.pt(t.a), m.pt(t.b), m.pt(t.c)}; }
/// Valid: finite centre, radius >= 0 and displacement, and a finite end
/// position c + delta (so that every position of the sweep is finite).
inline bool is_valid(const MovingSphere& s) {
  return all_finite(s.c.x, s.c.y, s.c.z, s.r, s.delta.x, s.delta.y, s.delta.z) && s.r >= 0 && all_finite(s.c + s.delta);
}

}  // namespace geomcheck
