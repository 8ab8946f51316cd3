// geomcheck — the consistency and same-solid checks of the collide queries
// whose contacts are held against the certified engine (capsule, box,
// triangle, cylinder), written once (internal to properties/).
#pragma once

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

#include "truth.hpp"
#include "common.hpp"
#include "geomcheck/properties/checks.hpp"
#include "geomcheck/properties/tolerances.hpp"

namespace geomcheck {

/// The body of check_consistency: overlap agrees with collide's hit; a hit
/// is finite, its normal unit (the query's `unit` bound) and its depth >= 0;
/// and where `exact` (a valid case the engine can judge) the depth is within
/// `depth_bound` * scale of the certified overlap of the shapes along the
/// returned normal.
template <class Case, class Impl>
CheckResult consistent_contact(QueryId id, const Case& c, const Impl& impl, bool exact, double scale,
                               double depth_bound) {
  const bool ov = impl.overlap(c.a, c.b);
  const Contact ct = impl.collide(c.a, c.b);
  if (ov != ct.hit) return Failure{"consistency-overlap-vs-collide", describe(ct, ov)};
  if (!ct.hit) return std::nullopt;
  if (!finite_contact(ct)) return Failure{"consistency-finite", describe(ct, ov)};
  if (std::fabs(length(ct.normal) - 1) > tolerances(id).unit) return Failure{"consistency-unit-normal", describe(ct, ov)};
  if (!(ct.depth >= 0)) return Failure{"consistency-depth-nonnegative", describe(ct, ov)};
  if (!exact) return std::nullopt;
  const oracle::QInterval along =
      overlap_along(oracle::make_shape(c.a), oracle::make_shape(c.b), oracle::to_q(ct.normal));
  if (!std::isfinite(oracle::to_double(along.hi))) return std::nullopt;  // beyond the doubles: saturated depth
  const double err = rel_error(along, ct.depth, scale);
  if (err > depth_bound)
    return Failure{"consistency-depth-along-normal",
                   fmt("|depth - overlap along normal| = %.3g * scale > %.3g; ", err, depth_bound) + describe(ct, ov)};
  return std::nullopt;
}

/// Same solid, other representation (check_symmetry): the verdicts of c0 and
/// c1 agree unless either is within the verdict band (the engine is asked
/// only when they differ); two hits' depths agree within `depth_bound` *
/// scale (c0's scale) wherever `held(c0)` says c0's depth is held to a bound
/// at all (asked only when they differ).
template <class Case, class Impl, class Held>
CheckResult same_answer(const char* what, const Case& c0, const Case& c1, const Impl& impl, double scale,
                        double depth_bound, Held&& held) {
  const bool o0 = impl.overlap(c0.a, c0.b), o1 = impl.overlap(c1.a, c1.b);
  if (o0 != o1) {
    const Evaluation e0 = evaluate(c0, impl), e1 = evaluate(c1, impl);
    if (e0.near_boundary || e1.near_boundary) return std::nullopt;
    return Failure{what, std::string("overlap ") + (o0 ? "yes" : "no") + " becomes " + (o1 ? "yes" : "no") +
                             "; oracle: " + e0.truth_text};
  }
  if (!o0) return std::nullopt;
  const Contact k0 = impl.collide(c0.a, c0.b), k1 = impl.collide(c1.a, c1.b);
  const double d = std::fabs(k0.depth - k1.depth) / scale;
  if (d > depth_bound && held(c0))
    return Failure{std::string(what) + "-depth",
                   fmt("depth differs by %.3g * scale; ", d) + describe(k0, o0) + " vs " + describe(k1, o1)};
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
  const double slack = move == 5 ? rigid_slack * std::max(e0.scale, e1.scale) : 0.0;
  auto near = [&](const Evaluation& e) {
    return e.near_boundary || std::fabs(e.signed_distance) <= tolerances(id).verdict * e.scale + slack;
  };
  if (!near(e0) && !near(e1))
    return Failure{what, "verdict changed outside the band: " + describe(ct, ov) + " vs " + describe(ct2, ov2)};
  return std::nullopt;
}

}  // namespace geomcheck
