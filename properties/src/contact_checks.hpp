// geomcheck — the consistency and same-solid checks of the collide queries
// whose contacts are held against the certified engine (capsule, box,
// triangle, cylinder), written once (internal to properties/).
#pragma once

#include <algorithm>
#include <cmath>
#include <functional>
#include <optional>
#include <string>

#include "truth.hpp"
#include "common.hpp"
#include "geomcheck/properties/checks.hpp"
#include "geomcheck/properties/tolerances.hpp"
#include "moves.hpp"

namespace geomcheck {

/// The start of a collide query's evaluate: the subject's overlap and
/// contact into `e` and `ct`, and the case's scale into `e`; false, with `e`
/// complete, on invalid input (where the only truth is "no overlap").
template <class Case, class Impl>
bool start_evaluation(Evaluation& e, const Case& c, const Impl& impl, Contact& ct) {
  const bool ov = impl.overlap(c.a, c.b);
  ct = impl.collide(c.a, c.b);
  e.prod_hit = ov;
  e.prod_text = describe(ct, ov);
  e.valid = is_valid(c.a) && is_valid(c.b);
  if (!e.valid) {
    e.truth_text = "invalid input: no overlap";
    e.disagree = ov || ct.hit;
  } else {
    e.scale = oracle::case_scale(c.a, c.b);
  }
  return e.valid;
}

/// The engine's verdict into `e` (e.scale set): the verdict, the reported
/// signed distance (nearest_to_zero), the disagreement and whether it lies
/// within `band` of touching, its margin (|reported distance| / scale, or
/// with `certain_margin` only the part of the enclosure certainly on one
/// side of zero), and the certified distance where separated and enclosed
/// within 1e-12 * scale.
template <class Truth>
void settle_verdict(Evaluation& e, const Truth& truth, const oracle::Q& band, bool certain_margin = false) {
  e.verdict = truth.verdict;
  e.truth_hit = truth.verdict != oracle::Verdict::Separated;
  e.signed_distance = nearest_to_zero(truth.signed_distance, e.scale);
  e.truth_text = truth.text;
  e.disagree = e.prod_hit != e.truth_hit;
  e.near_boundary = !(truth.signed_distance.lo > band || truth.signed_distance.hi < -band);
  if (e.disagree) {
    if (certain_margin) {
      const oracle::QInterval& sd = truth.signed_distance;
      const oracle::Q certain = sd.lo > 0 ? sd.lo : (sd.hi < 0 ? oracle::Q(-sd.hi) : oracle::Q(0));
      e.margin = oracle::to_double(certain) / e.scale;
    } else {
      e.margin = std::fabs(e.signed_distance) / e.scale;
    }
    e.excused = e.near_boundary;
  }
  if (truth.verdict == oracle::Verdict::Separated &&
      truth.signed_distance.hi - truth.signed_distance.lo <= times_scale(1e-12, e.scale))
    e.distance = truth.signed_distance.mid();
}

/// The body of check_consistency: overlap agrees with collide's hit; a hit
/// is finite, its normal unit (the query's `unit` bound) and its depth >= 0;
/// and where `exact` (a valid case the engine can judge) the depth is within
/// `depth_bound` * scale of the certified overlap of the shapes along the
/// returned normal (a bound of the subject's: bounds()).
template <class Case, class Impl>
CheckResult consistent_contact(QueryId id, const Case& c, const Impl& impl, bool exact, double depth_bound) {
  const bool ov = impl.overlap(c.a, c.b);
  const Contact ct = impl.collide(c.a, c.b);
  if (ov != ct.hit) return Failure{"consistency-overlap-vs-collide", describe(ct, ov)};
  if (!ct.hit) return std::nullopt;
  if (!finite_contact(ct)) return Failure{"consistency-finite", describe(ct, ov)};
  if (std::fabs(length(ct.normal) - 1) > bounds(c, impl).unit) return Failure{"consistency-unit-normal", describe(ct, ov)};
  if (!(ct.depth >= 0)) return Failure{"consistency-depth-nonnegative", describe(ct, ov)};
  if (!exact) return std::nullopt;
  const oracle::QInterval along =
      overlap_along(oracle::make_shape(c.a), oracle::make_shape(c.b), oracle::to_q(ct.normal));
  if (!std::isfinite(oracle::to_double(along.hi))) return std::nullopt;  // beyond the doubles: saturated depth
  const double err = rel_error(along, ct.depth, oracle::case_scale(c.a, c.b));
  if (err > depth_bound)
    return Failure{"consistency-depth-along-normal",
                   fmt("|depth - overlap along normal| = %.3g * scale > %.3g; ", err, depth_bound) + describe(ct, ov)};
  return std::nullopt;
}

/// Same solid, other representation (check_symmetry): the verdicts of c0 and
/// c1 agree unless either is within the verdict band (the engine is asked
/// only when they differ); two hits' depths agree within `depth_bound` *
/// scale (c0's scale; a bound of the subject's: bounds()) wherever
/// `held(c0)` says c0's depth is held to a bound at all (asked only when
/// they differ).
template <class Case, class Impl, class Held>
CheckResult same_answer(const char* what, const Case& c0, const Case& c1, const Impl& impl, double depth_bound,
                        Held&& held) {
  if (!subject_states(c1, impl)) return std::nullopt;  // a case the subject does not state
  const bool o0 = impl.overlap(c0.a, c0.b), o1 = impl.overlap(c1.a, c1.b);
  if (o0 != o1) {
    const Evaluation e0 = evaluate(c0, impl), e1 = evaluate(c1, impl);
    if (e0.near_boundary || e1.near_boundary) return std::nullopt;
    return Failure{what, std::string("overlap ") + (o0 ? "yes" : "no") + " becomes " + (o1 ? "yes" : "no") +
                             "; oracle: " + e0.truth_text, c1};
  }
  if (!o0) return std::nullopt;
  const Contact k0 = impl.collide(c0.a, c0.b), k1 = impl.collide(c1.a, c1.b);
  const double d = std::fabs(k0.depth - k1.depth) / oracle::case_scale(c0.a, c0.b);
  if (d > depth_bound && held(c0))
    return Failure{std::string(what) + "-depth",
                   fmt("depth differs by %.3g * scale; ", d) + describe(k0, o0) + " vs " + describe(k1, o1), c1};
  return std::nullopt;
}

/// same_answer with every depth held to the bound.
template <class Case, class Impl>
CheckResult same_answer(const char* what, const Case& c0, const Case& c1, const Impl& impl, double depth_bound) {
  return same_answer(what, c0, c1, impl, depth_bound, [](const Case&) { return true; });
}

/// The body of hold_to_truth for a cylinder A against a polytope-like convex
/// B judged by the engine: the truth at the query's verdict band, the verdict
/// settled, and the subject's and the peer's contacts scored against that
/// one truth (score_polytope_contacts: EPA at most once). `outside_b(shape,
/// x)` bounds from above how far x lies outside B (`shape` is B's).
template <class Case, class OutsideB>
void hold_to_polytope_truth(Evaluation& e, const Case& c, const Contact& ct, const Contact* peer,
                            OutsideB&& outside_b) {
  const Tolerances& tol = e.tol;
  const oracle::ConvexShape cyl = oracle::make_shape(c.a), shape = oracle::make_shape(c.b);
  const oracle::Q band = times_scale(tol.verdict, e.scale);
  const PolytopeTruth truth = polytope_truth(cyl, shape, band);
  settle_verdict(e, truth, band);
  const std::function<oracle::Q(Vec3)> outside = [&](Vec3 x) { return outside_b(shape, x); };
  const bool upper_bound = spec_of<query_of_case<Case>>().claims.depth == Claims::Depth::UpperBound;
  score_polytope_contacts(e, ct, peer, truth, oracle::to_q(c.a), cyl, shape, tol.depth, outside, upper_bound);
}

/// check_monotone's test: `bigger`, a superset of c, lost c's overlap, with
/// neither case within the subject's band of touching.
template <class Case, class Impl>
bool overlap_lost(const Case& c, const Case& bigger, const Impl& impl) {
  return subject_states(bigger, impl) && !impl.overlap(bigger.a, bigger.b) && !evaluate(c, impl).near_boundary &&
         !evaluate(bigger, impl).near_boundary;
}

/// check_monotone for the cylinder A of an overlapping case: its radius one
/// ulp larger, and doubled, never loses the overlap (overlap_lost).
template <class Case, class Impl>
CheckResult cylinder_a_radius_kept(const Case& c, const Impl& impl) {
  const double rc[] = {std::nextafter(c.a.r, INFINITY), c.a.r * 2 + 1e-300};
  for (double r : rc) {
    const Case bigger{Cylinder{c.a.p, c.a.q, r}, c.b};
    if (std::isfinite(r) && overlap_lost(c, bigger, impl))
      return Failure{"monotone-cylinder-radius", fmt("overlap with cylinder radius %.17g but not with %.17g", c.a.r, r),
                     bigger};
  }
  return std::nullopt;
}

/// check_monotone for the cylinder A of an overlapping case: A extended
/// beyond q by q - p never loses the overlap (overlap_lost), checked only
/// where that is exact (else the axis direction rounds and the result is no
/// superset).
template <class Case, class Impl>
CheckResult cylinder_a_length_kept(const Case& c, const Impl& impl) {
  const Vec3 d = c.a.q - c.a.p, q2 = c.a.q + d;
  const Case longer{Cylinder{c.a.p, q2, c.a.r}, c.b};
  if (is_finite(q2) && d + c.a.p == c.a.q && q2 - c.a.q == d && overlap_lost(c, longer, impl))
    return Failure{"monotone-cylinder-length", "overlap lost when the cylinder is extended beyond q", longer};
  return std::nullopt;
}

/// check_metamorphic's verdict test for a move that is not exact (an axis
/// permutation, the rigid motion): the moved case t is rounded, so it is
/// another case, and a change of verdict (ov of c, ov2 of t) is a failure
/// only when neither case is within the verdict band of touching. The rigid
/// motion (move 5) also moves a solid by up to `rigid_slack` * scale, taken at
/// the larger of the two scales (the motion translates, and the moved
/// coordinates round at the moved scene's magnitude).
template <class Case, class Impl>
CheckResult verdict_kept(QueryId id, const std::string& what, const Case& c, const Case& t, int move,
                         double rigid_slack, const Impl& impl, const Contact& ct, bool ov, const Contact& ct2,
                         bool ov2) {
  if (ov == ov2) return std::nullopt;
  const Evaluation e0 = evaluate(c, impl), e1 = evaluate(t, impl);
  // The band at the larger of the two scales: the subject answers each case
  // to its band at that case's scale.
  const double larger = std::max(e0.scale, e1.scale);
  const double slack = move == 5 ? rigid_slack * larger : 0.0;
  const double band = std::max(bounds(c, impl).verdict, bounds(t, impl).verdict);
  auto near = [&](const Evaluation& e) {
    return e.near_boundary || std::fabs(e.signed_distance) <= band * larger + slack;
  };
  if (!near(e0) && !near(e1))
    return Failure{what, "verdict changed outside the band: " + describe(ct, ov) + " vs " + describe(ct2, ov2), t};
  return std::nullopt;
}

/// (A, B) and (B, A) agree and the normal flips: production's two entry
/// points held to each other ((B, A) is production's wrapper; a subject
/// other than production has no swapped entry point and is not checked).
template <class Case, class Impl>
CheckResult argument_order(const Case& c, const Impl& impl) {
  if (&impl != &production_of<query_of_case<Case>>()) return std::nullopt;
  const bool ov = impl.overlap(c.a, c.b);
  const Contact ct = impl.collide(c.a, c.b);
  const Contact sw = production_contact<query_of_case<Case>>(c.b, c.a);
  const bool sov = overlap(c.b, c.a);
  if (sov != ov || sw.hit != ct.hit || (ct.hit && !(sw.normal == -ct.normal)))
    return Failure{"symmetry-argument-order", describe(ct, ov) + " vs swapped " + describe(sw, sov)};
  return std::nullopt;
}

/// check_symmetry of a cylinder A against a polytope B (a box, a triangle),
/// written once: argument_order; then, for a case `in_contract`, the same
/// solids in other representations agree (same_answer, depths within
/// 2 * depth + normal of bounds()): the cylinder with its caps swapped, then
/// the representations of B that `other_b(bound)` checks.
template <class Case, class Impl, class OtherB>
CheckResult cylinder_polytope_symmetry(const Case& c, const Impl& impl, bool in_contract, OtherB&& other_b) {
  if (auto f = argument_order(c, impl)) return f;
  // Same solid, other representation.
  const Tolerances tol = bounds(c, impl);
  const double bound = 2 * tol.depth + tol.normal;
  if (!in_contract) return std::nullopt;
  if (auto f = same_answer("symmetry-caps-swapped", c, {{c.a.q, c.a.p, c.a.r}, c.b}, impl, bound)) return f;
  return other_b(bound);
}

/// The answers of a case and its moved copy, for a rule that judges them.
struct MovedAnswers {
  const moves::Move& m;
  const std::string& what;  ///< the property's name
  const Contact &ct, &ct2;  ///< before and after the move (both hits)
  bool ov, ov2;
  /// The moved point, normal and depth, bit for bit.
  bool identical() const { return m.pt(ct.point) == ct2.point && m.vec(ct.normal) == ct2.normal && m.len(ct.depth) == ct2.depth; }
  Failure not_identical() const { return {what, "answer not bit-identical: " + describe(ct, ov) + " vs " + describe(ct2, ov2)}; }
};

/// check_metamorphic of a collide query, written once. A move that does not
/// apply is skipped, and so is a moved case outside `in_contract` (a rounded
/// move can destroy a degenerate shape: an axis one ulp long collapses to
/// p == q, no longer the same solid). An exact move (sign flips,
/// power-of-two scales, axis permutations of an exact scene) keeps the
/// verdict, and `kept(t, answers)` judges the two hits by the query's rule
/// (bit-identical, or another answer where a tie or a free normal allows
/// one); a rounded move keeps the verdict outside the band, the rigid motion
/// with `rigid_slack(c)` * scale more. A subject that does not claim exact
/// moves (Precision::exact_moves) has every move held like a rounded one.
template <class Case, class Impl, class InContract, class Slack, class Kept>
CheckResult collide_metamorphic(const Case& c, int move, const Impl& impl, InContract in_contract, Slack rigid_slack,
                                Kept kept) {
  if (!in_contract(c)) return std::nullopt;
  const moves::Move m{move};
  if (!moves::applicable(c, move)) return std::nullopt;
  const Case t{moves::apply(m, c.a), moves::apply(m, c.b)};
  if (!in_contract(t) || !subject_states(t, impl)) return std::nullopt;
  const bool ov = impl.overlap(c.a, c.b), ov2 = impl.overlap(t.a, t.b);
  const Contact ct = impl.collide(c.a, c.b), ct2 = impl.collide(t.a, t.b);
  const std::string what = std::string("metamorphic-") + move_name(move);
  if (m.exact() && exact_moves(impl)) {
    if (ov != ov2 || ct.hit != ct2.hit)
      return Failure{what, "verdict changed: " + describe(ct, ov) + " vs " + describe(ct2, ov2), t};
    if (!ct.hit) return std::nullopt;
    CheckResult r = kept(t, MovedAnswers{m, what, ct, ct2, ov, ov2});
    if (r && !r->related.has_value()) r->related = t;  // the moved case, for the page
    return r;
  }
  return verdict_kept(query_of_case<Case>, what, c, t, move, rigid_slack(c), impl, ct, ov, ct2, ov2);
}

/// The rule of most queries: an exact move moves the answer bit for bit.
template <class Case>
CheckResult bit_identical(const Case&, const MovedAnswers& a) {
  if (a.identical()) return std::nullopt;
  return a.not_identical();
}

}  // namespace geomcheck

/// Defines query kId's hold_to_truth and its four own checks as calls of the
/// templates of namespace geomcheck::`ns` (box_checks.hpp,
/// triangle_checks.hpp: the checks of a pair of shapes, written once for its
/// queries). Used after GEOMCHECK_SPEC, inside namespace geomcheck.
#define GEOMCHECK_PAIR_CHECKS(ns)                                                                              \
  void hold_to_truth(Evaluation& e, const QueryTraits<kId>::Case& c, const Contact& ct, const Contact* peer) { \
    ns::hold_to_truth(e, c, ct, peer);                                                                         \
  }                                                                                                            \
  CheckResult check_consistency(const QueryTraits<kId>::Case& c, const ImplOf<kId>& impl) {                  \
    return ns::consistency(c, impl);                                                                           \
  }                                                                                                            \
  CheckResult check_symmetry(const QueryTraits<kId>::Case& c, const ImplOf<kId>& impl) {                     \
    return ns::symmetry(c, impl);                                                                              \
  }                                                                                                            \
  CheckResult check_metamorphic(const QueryTraits<kId>::Case& c, int move, const ImplOf<kId>& impl) {        \
    return ns::metamorphic(c, move, impl);                                                                     \
  }                                                                                                            \
  CheckResult check_monotone(const QueryTraits<kId>::Case& c, const ImplOf<kId>& impl) {                     \
    return ns::monotone(c, impl);                                                                              \
  }
