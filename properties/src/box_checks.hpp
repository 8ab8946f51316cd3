// geomcheck — the checks of a cylinder and a box, written once for the two queries over
// that pair: collide_cylinder_obb and penetration_cylinder_obb (their
// checks_<id>.cpp files call these; internal to properties/).
//
// check_oracle: Agreement with the engine outside the band; the depth claim
// (see the query's header), point in both. A box whose axes are not
// orthonormal is outside production's contract: only the robust check applies.
// check_consistency: overlap == collide.hit; unit normal; depth >= 0 equals
// the overlap along the normal; no NaN.
// check_symmetry: (A,B) and (B,A) agree, normal flips; caps swapped, box axes
// permuted or negated: same verdict (band), same depth to the bound.
// check_monotone: A wider or longer cylinder or a bigger box never turns
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

namespace geomcheck::box_checks {

// An upper bound of the distance from x to the box, exactly: x's
// coordinates along the stored axes (Cramer's rule in rationals; the axes
// are independent in the contract), clamped to [-e_i, e_i], give a point of
// the box exactly, and its distance from x bounds the box's.
inline Q box_distance_up(const Obb& b, Vec3 x) {
  const QVec a0 = oracle::to_q(b.axes[0]), a1 = oracle::to_q(b.axes[1]), a2 = oracle::to_q(b.axes[2]);
  const QVec w = oracle::to_q(x) - oracle::to_q(b.c);
  const Q det = oracle::dot(a0, oracle::cross(a1, a2));
  const Q t[3] = {oracle::dot(w, oracle::cross(a1, a2)) / det, oracle::dot(a0, oracle::cross(w, a2)) / det,
                  oracle::dot(a0, oracle::cross(a1, w)) / det};
  const QVec axes[3] = {a0, a1, a2};
  QVec y = oracle::to_q(b.c);
  for (int i = 0; i < 3; ++i) {
    const Q e = oracle::to_q(b.e[i]);
    const Q ti = t[i] > e ? e : (t[i] < -e ? Q(-e) : t[i]);
    y = y + ti * axes[i];
  }
  const QVec d = oracle::to_q(x) - y;
  return oracle::sqrt_interval(oracle::dot(d, d)).hi;
}


template <class Case>
void hold_to_truth(Evaluation& e, const Case& c, const Contact& ct, const Contact* peer) {
  if (!obb_in_contract(c.b)) {
    // Outside production's contract: no verdict is owed (robust checks only).
    e.truth_text = "box axes not orthonormal: outside the contract";
    e.near_boundary = true;
    return;
  }
  hold_to_polytope_truth(e, c, ct, peer, [&](const oracle::ConvexShape& box, Vec3 x) {
    return oracle::contains(box, oracle::to_q(x)) ? Q(0) : box_distance_up(c.b, x);
  });
}

template <class Case, class Impl>
CheckResult consistency(const Case& c, const Impl& impl) {
  const bool exact = valid_case(c) && obb_in_contract(c.b);
  return consistent_contact(query_of_case<Case>, c, impl, exact, bounds(c, impl).depth);
}

template <class Case, class Impl>
CheckResult symmetry(const Case& c, const Impl& impl) {
  // Same solid, other representation (contact_checks.hpp).
  return cylinder_polytope_symmetry(c, impl, valid_case(c) && obb_in_contract(c.b), [&](double bound) {
    // The same box with its axes cycled (extents with them), and with one
    // axis negated: exactly the same set.
    const Obb& b = c.b;
    const Obb cycled{b.c, {{b.axes[1], b.axes[2], b.axes[0]}}, Vec3{b.e.y, b.e.z, b.e.x}};
    if (auto f = same_answer("symmetry-box-axes-cycled", c, {c.a, cycled}, impl, bound)) return f;
    const Obb negated{b.c, {{-b.axes[0], b.axes[1], b.axes[2]}}, b.e};
    return same_answer("symmetry-box-axis-negated", c, {c.a, negated}, impl, bound);
  });
}

template <class Case, class Impl>
CheckResult metamorphic(const Case& c, int move, const Impl& impl) {
  return collide_metamorphic(
      c, move, impl, [](const Case& x) { return valid_case(x) && obb_in_contract(x.b); },
      [](const Case& x) { return moves::rigid_slack(x.a); }, bit_identical<Case>);
}

template <class Case, class Impl>
CheckResult monotone(const Case& c, const Impl& impl) {
  if (!valid_case(c) || !obb_in_contract(c.b) || !impl.overlap(c.a, c.b)) return std::nullopt;
  // A superset never loses the overlap, except within the band of touching.
  if (auto f = cylinder_a_radius_kept(c, impl)) return f;
  auto lost = [&](const Case& bigger) { return overlap_lost(c, bigger, impl); };
  for (int i = 0; i < 3; ++i) {
    Obb b = c.b;
    b.e[i] = std::nextafter(b.e[i], INFINITY);
    if (std::isfinite(b.e[i]) && lost({c.a, b}))
      return Failure{"monotone-box-extent", fmt("overlap lost when extent %d grows from %.17g", i, c.b.e[i]),
                     Case{c.a, b}};
  }
  // A longer cylinder (contact_checks.hpp).
  return cylinder_a_length_kept(c, impl);
}

}  // namespace geomcheck::box_checks
