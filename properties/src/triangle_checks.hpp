// geomcheck — the checks of a cylinder and a triangle, written once for the two queries over
// that pair: collide_cylinder_triangle and penetration_cylinder_triangle (their
// checks_<id>.cpp files call these; internal to properties/).
//
// check_oracle: Agreement with the engine outside the band; the depth claim
// (see the query's header), point in both. Every finite triangle is in the
// contract (a degenerate one is its longest edge or its point).
// check_consistency: overlap == collide.hit; unit normal; depth >= 0 equals
// the overlap along the normal; no NaN.
// check_symmetry: (A,B) and (B,A) agree, normal flips; caps swapped, triangle
// vertices rotated or reversed: same verdict (band), same depth to the bound.
// check_metamorphic: As for the other queries, but for a reflection of a scene
// whose cylinder axis lies exactly in the triangle's plane: there the normal
// is free (mirror pairs), the verdict and point bit-identical, the depth to
// the bound.
// check_monotone: A wider or longer cylinder or a bigger triangle never turns
// overlap into separation (outside the band).
#pragma once

#include <cmath>
#include <optional>
#include <utility>

#include "common.hpp"
#include "contact_checks.hpp"
#include "geomcheck/oracles/cylinder_sphere.hpp"
#include "geomcheck/properties/checks.hpp"
#include "geomcheck/properties/tolerances.hpp"
#include "moves.hpp"
#include "truth.hpp"

namespace geomcheck::triangle_checks {

inline bool same_point(const QVec& u, const QVec& v) { return u.x == v.x && u.y == v.y && u.z == v.z; }

// The distance from x to the triangle, exactly squared (rounded up at the
// square root only): the projection y of x onto the plane, when the
// triangle is not degenerate and y lies on the inner side of (or on) all
// three edges; otherwise the nearest of the edges' exactly clamped closest
// points (a zero-length edge: its end point). A degenerate triangle is the
// hull of its edges, so the edges alone give its distance.
inline Q triangle_distance_up(const Triangle& t, Vec3 x) {
  const QVec v[3] = {oracle::to_q(t.a), oracle::to_q(t.b), oracle::to_q(t.c)};
  const QVec xq = oracle::to_q(x);
  auto d2 = [&](const QVec& y) {
    const QVec d = xq - y;
    return oracle::dot(d, d);
  };
  const QVec n = oracle::cross(v[1] - v[0], v[2] - v[0]);
  const Q nn = oracle::dot(n, n);
  if (nn != 0) {
    const QVec y = xq - (oracle::dot(n, xq - v[0]) / nn) * n;
    bool inside = true;
    for (int i = 0; i < 3 && inside; ++i)
      inside = oracle::dot(n, oracle::cross(v[(i + 1) % 3] - v[i], y - v[i])) >= 0;
    if (inside) return oracle::sqrt_interval(d2(y)).hi;
  }
  Q best;
  for (int i = 0; i < 3; ++i) {
    const QVec& p = v[i];
    const QVec e = v[(i + 1) % 3] - p;
    const Q ee = oracle::dot(e, e);
    Q s = ee > 0 ? oracle::dot(xq - p, e) / ee : Q(0);
    if (s < 0) s = 0;
    if (s > 1) s = 1;
    const Q di = d2(p + s * e);
    if (i == 0 || di < best) best = di;
  }
  return oracle::sqrt_interval(best).hi;
}

// The cylinder's axis and the triangle in one plane, decided exactly: every
// orient3d (p, q, v_i, v_j) over the pairs of vertices is zero. With p != q
// that is exactly "a, b, c, p, q coplanar" (a vertex off the line pq spans
// the plane with it, and the zero orientations put the other two in it; if
// none is off the line, all five are collinear). The reflection in that
// plane maps the cylinder (axis in it) and the triangle (in it) onto
// themselves, so the minimal translations come in mirror pairs and a
// reflected scene may pick the other one (the header's exception). For a
// proper triangle this is the header's "axis in the triangle's plane"; a
// degenerate triangle (a segment coplanar with the axis, or a point: always)
// has the same symmetry, so the same rule covers it.
template <class Case>
bool scene_coplanar(const Case& c) {
  const QVec p = oracle::to_q(c.a.p), u = oracle::to_q(c.a.q) - p;
  const QVec v[3] = {oracle::to_q(c.b.a) - p, oracle::to_q(c.b.b) - p, oracle::to_q(c.b.c) - p};
  for (int i = 0; i < 3; ++i)
    for (int j = i + 1; j < 3; ++j)
      if (oracle::dot(oracle::cross(u, v[i]), v[j]) != 0) return false;
  return true;
}


template <class Case>
void hold_to_truth(Evaluation& e, const Case& c, const Contact& ct, const Contact* peer) {
  // Every finite triangle is in the contract (degenerate ones included).
  hold_to_polytope_truth(e, c, ct, peer,
                         [&](const oracle::ConvexShape&, Vec3 x) { return triangle_distance_up(c.b, x); });
}

template <class Case, class Impl>
CheckResult consistency(const Case& c, const Impl& impl) {
  const bool exact = valid_case(c);
  return consistent_contact(query_of_case<Case>, c, impl, exact, bounds(c, impl).depth);
}

template <class Case, class Impl>
CheckResult symmetry(const Case& c, const Impl& impl) {
  // Same solid, other representation (contact_checks.hpp).
  return cylinder_polytope_symmetry(c, impl, valid_case(c), [&](double bound) {
    // The same triangle with its vertices rotated, and reversed (the other
    // orientation): exactly the same set.
    const Triangle& t = c.b;
    if (auto f = same_answer("symmetry-triangle-rotated", c, {c.a, Triangle{t.b, t.c, t.a}}, impl, bound)) return f;
    return same_answer("symmetry-triangle-reversed", c, {c.a, Triangle{t.a, t.c, t.b}}, impl, bound);
  });
}

template <class Case, class Impl>
CheckResult metamorphic(const Case& c, int move, const Impl& impl) {
  auto kept = [&](const Case&, const MovedAnswers& a) -> CheckResult {
    if (!((move == 0 || move == 1) && scene_coplanar(c))) return bit_identical(c, a);
    // A reflection of a scene symmetric in the plane of the axis and the
    // triangle: the normal may be the other of a mirror pair (and the
    // depth, computed along it, differ by rounding). The point does not
    // depend on the normal: still bit-identical.
    if (!(a.m.pt(a.ct.point) == a.ct2.point))
      return Failure{a.what, "point not bit-identical (axis in the triangle's plane): " + describe(a.ct, a.ov) +
                                 " vs " + describe(a.ct2, a.ov2)};
    const double d = std::fabs(a.m.len(a.ct.depth) - a.ct2.depth) / oracle::case_scale(c.a, c.b);
    if (!(d <= 2 * bounds(c, impl).depth))
      return Failure{a.what + "-depth", fmt("depth differs by %.3g * scale (axis in the triangle's plane); ", d) +
                                            describe(a.ct, a.ov) + " vs " + describe(a.ct2, a.ov2)};
    return std::nullopt;
  };
  return collide_metamorphic(
      c, move, impl, valid_case<Case>, [](const Case& x) { return moves::rigid_slack(x.a); }, kept);
}

template <class Case, class Impl>
CheckResult monotone(const Case& c, const Impl& impl) {
  if (!valid_case(c) || !impl.overlap(c.a, c.b)) return std::nullopt;
  // A superset never loses the overlap, except within the band of touching.
  if (auto f = cylinder_a_radius_kept(c, impl)) return f;
  auto lost = [&](const Case& bigger) { return overlap_lost(c, bigger, impl); };
  // A bigger triangle: scaled by 2 about a vertex (which it keeps; the
  // triangle is star-shaped from it, so the original lies inside), each
  // vertex in turn, only where the doubled edges are exact (checked in
  // rationals).
  const Triangle& t = c.b;
  const Triangle rotations[3] = {t, {t.b, t.c, t.a}, {t.c, t.a, t.b}};
  for (const Triangle& r : rotations) {
    const Triangle g{r.a, r.a + 2.0 * (r.b - r.a), r.a + 2.0 * (r.c - r.a)};
    if (!is_finite(g.b) || !is_finite(g.c)) continue;
    const QVec a = oracle::to_q(r.a);
    if (!same_point(oracle::to_q(g.b) - a, Q(2) * (oracle::to_q(r.b) - a)) ||
        !same_point(oracle::to_q(g.c) - a, Q(2) * (oracle::to_q(r.c) - a)))
      continue;
    if (lost({c.a, g}))
      return Failure{"monotone-triangle-scaled",
                     "overlap lost when the triangle is scaled by 2 about its vertex " + vec(r.a), Case{c.a, g}};
  }
  // A longer cylinder (contact_checks.hpp).
  return cylinder_a_length_kept(c, impl);
}

}  // namespace geomcheck::triangle_checks
