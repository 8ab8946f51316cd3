// geomcheck — the checks of the moving queries (a cast's segment, a sweep's
// ball against a shape B), written once for both kinds (internal to properties/).
#pragma once

#include <cmath>
#include <optional>
#include <string>

#include "common.hpp"
#include "geomcheck/properties/checks.hpp"
#include "geomcheck/properties/tolerances.hpp"
#include "moves.hpp"

namespace geomcheck {

/// The subject's answer to a moving query's case: cast or sweep.
template <class Case, class Impl>
CastHit moving_answer(const Case& c, const Impl& impl) {
  if constexpr (QueryTraits<query_of_case<Case>>::kind == QueryKind::Cast) return impl.cast(c.a, c.b);
  else return impl.sweep(c.a, c.b);
}

/// The start of a moving query's evaluate: the subject's hit into `e` and
/// `h`, and the case's scale into `e`; false, with `e` complete, on invalid
/// input (where the only truth is "no hit").
template <class Case, class Impl>
bool start_evaluation(Evaluation& e, const Case& c, const Impl& impl, CastHit& h) {
  h = moving_answer(c, impl);
  e.prod_hit = h.hit;
  e.prod_text = describe(h);
  e.valid = valid_case(c);
  if (!e.valid) {
    e.truth_text = "invalid input: no hit";
    e.disagree = h.hit;
  } else {
    e.scale = oracle::case_scale(c.a, c.b);
  }
  return e.valid;
}

/// check_consistency's test of a hit on its own (none on a miss): finite, t
/// in [0, 1], starting inside only with t == 0 and a zero normal, otherwise a
/// unit normal (the `unit` bound of a subject with these claims).
inline CheckResult consistent_hit(QueryId id, const CastHit& h, const Claims* claims) {
  if (!h.hit) return std::nullopt;
  if (!finite_hit(h)) return Failure{"consistency-finite", describe(h)};
  if (!(h.t >= 0 && h.t <= 1)) return Failure{"consistency-t-range", describe(h)};
  if (h.starts_inside && (h.t != 0 || !(h.normal == Vec3{})))
    return Failure{"consistency-starts-inside", "starts_inside needs t == 0 and a zero normal: " + describe(h)};
  if (!h.starts_inside && std::fabs(length(h.normal) - 1) > bounds_of(id, claims).unit)
    return Failure{"consistency-unit-normal", describe(h)};
  return std::nullopt;
}

/// Same path, other representation: hit or miss agree unless either case is
/// within the verdict band of touching (the truth is asked only when they differ).
template <class Case, class Impl>
CheckResult same_verdict(const char* what, const Case& c0, const Case& c1, const Impl& impl) {
  if (!subject_states(c1, impl)) return std::nullopt;  // a case the subject does not state
  const CastHit h0 = moving_answer(c0, impl), h1 = moving_answer(c1, impl);
  if (h0.hit == h1.hit) return std::nullopt;
  const Evaluation e0 = evaluate(c0, impl), e1 = evaluate(c1, impl);
  if (e0.near_boundary || e1.near_boundary) return std::nullopt;
  return Failure{what, describe(h0) + " vs " + describe(h1) + "; oracle: " + e0.truth_text + " / " + e1.truth_text, c1};
}

/// B's caps swapped (B a cylinder): the same verdict, and the same answer to
/// "does it start inside" unless the case is within the band of touching or
/// the start is within the t bound (then t_err is not even measured).
template <class Case, class Impl>
CheckResult caps_swapped(const Case& c, const Impl& impl) {
  const Case sw{c.a, {c.b.q, c.b.p, c.b.r}};
  if (!subject_states(sw, impl)) return std::nullopt;
  if (auto f = same_verdict("symmetry-caps-swapped", c, sw, impl)) return f;
  const CastHit h0 = moving_answer(c, impl), h1 = moving_answer(sw, impl);
  if (h0.hit && h1.hit && h0.starts_inside != h1.starts_inside) {
    const Evaluation e = evaluate(c, impl);
    if (!e.near_boundary && !(e.t_err <= e.tol.t))
      return Failure{"symmetry-caps-swapped-start", describe(h0) + " vs " + describe(h1), sw};
  }
  return std::nullopt;
}

/// An exact move (sign flips, power-of-two scales) moves the answer bit for
/// bit: the same t and start, the moved point and (unless `free_normal`: a
/// cylinder thinner than the rounding level, whose side normal is any
/// perpendicular) the moved normal.
template <class Case, class Impl>
CheckResult exact_move_kept(const std::string& what, const moves::Move& m, const Case& c, const Case& t,
                            const Impl& impl, bool free_normal) {
  const CastHit h0 = moving_answer(c, impl), h1 = moving_answer(t, impl);
  if (h0.hit != h1.hit) return Failure{what, "verdict changed: " + describe(h0) + " vs " + describe(h1), t};
  if (h0.hit && !(h0.t == h1.t && h0.starts_inside == h1.starts_inside && m.pt(h0.point) == h1.point &&
                  (free_normal || m.vec(h0.normal) == h1.normal)))
    return Failure{what, "answer not bit-identical: " + describe(h0) + " vs " + describe(h1), t};
  return std::nullopt;
}

/// check_monotone's test: `bigger`, a superset of c's moving shape or of B,
/// lost c's hit, with neither case within the band of touching.
template <class Case, class Impl>
bool hit_lost(const Case& c, const Case& bigger, const Impl& impl) {
  return subject_states(bigger, impl) && !moving_answer(bigger, impl).hit && !evaluate(c, impl).near_boundary &&
         !evaluate(bigger, impl).near_boundary;
}

/// check_monotone for the cylinder B of a hitting case: its radius doubled
/// (plus 2^-20 of its length) never loses the hit (hit_lost).
template <class Case, class Impl>
CheckResult cylinder_b_radius_kept(const Case& c, const Impl& impl) {
  const double wider = c.b.r * 2 + 0x1p-20 * length(c.b.q - c.b.p);
  const Case bigger{c.a, {c.b.p, c.b.q, wider}};
  if (std::isfinite(wider) && hit_lost(c, bigger, impl))
    return Failure{"monotone-cylinder-radius",
                   "hit with radius " + fmt("%.17g", c.b.r) + " but not with " + fmt("%.17g", wider), bigger};
  return std::nullopt;
}

/// The body of a moving query's check_metamorphic: the move applied to both
/// shapes (skipped where it is not applicable or leaves the case invalid: a
/// rounded move can collapse an axis one ulp long); an exact move keeps the
/// answer bit for bit (exact_move_kept; the side normal is free on a
/// cylinder B thinner than the rounding level; a subject that does not claim
/// exact moves, Precision::exact_moves, has them held like rounded ones), a
/// rounded one keeps the
/// verdict outside the band (same_verdict), and the rigid motion (move 5),
/// which also moves the solids by rigid_slack, changes the verdict only where
/// `rigid_certain(t, what, h0, h1)` says that change is a failure.
template <class Case, class Impl, class RigidCertain>
CheckResult moving_metamorphic(const Case& c, int move, const Impl& impl, RigidCertain&& rigid_certain) {
  if (!valid_case(c)) return std::nullopt;
  const moves::Move m{move};
  if (!moves::applicable(c, move)) return std::nullopt;
  const Case t{moves::apply(m, c.a), moves::apply(m, c.b)};
  if (!valid_case(t) || !subject_states(t, impl)) return std::nullopt;
  const std::string what = std::string("metamorphic-") + move_name(move);
  if (m.exact() && exact_moves(impl)) return exact_move_kept(what, m, c, t, impl, !(c.b.r > 64 * 0x1p-52 * oracle::case_scale(c.a, c.b)));
  if (move != 5) return same_verdict(what.c_str(), c, t, impl);
  const CastHit h0 = moving_answer(c, impl), h1 = moving_answer(t, impl);
  if (h0.hit == h1.hit) return std::nullopt;
  CheckResult r = rigid_certain(t, what, h0, h1);
  if (r && !r->related.has_value()) r->related = t;  // the moved case, for the page
  return r;
}

}  // namespace geomcheck
