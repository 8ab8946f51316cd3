// geomcheck — the checks of the moving queries (a cast's segment, a sweep's
// ball against a shape B), written once for both kinds (internal to properties/).
#pragma once

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

/// Same path, other representation: hit or miss agree unless either case is
/// within the verdict band of touching (the truth is asked only when they differ).
template <class Case, class Impl>
CheckResult same_verdict(const char* what, const Case& c0, const Case& c1, const Impl& impl) {
  const CastHit h0 = moving_answer(c0, impl), h1 = moving_answer(c1, impl);
  if (h0.hit == h1.hit) return std::nullopt;
  const Evaluation e0 = evaluate(c0, impl), e1 = evaluate(c1, impl);
  if (e0.near_boundary || e1.near_boundary) return std::nullopt;
  return Failure{what, describe(h0) + " vs " + describe(h1) + "; oracle: " + e0.truth_text + " / " + e1.truth_text};
}

/// B's caps swapped (B a cylinder): the same verdict, and the same answer to
/// "does it start inside" unless the case is within the band of touching or
/// the start is within the t bound (then t_err is not even measured).
template <class Case, class Impl>
CheckResult caps_swapped(const Case& c, const Impl& impl) {
  const Case sw{c.a, {c.b.q, c.b.p, c.b.r}};
  if (auto f = same_verdict("symmetry-caps-swapped", c, sw, impl)) return f;
  const CastHit h0 = moving_answer(c, impl), h1 = moving_answer(sw, impl);
  if (h0.hit && h1.hit && h0.starts_inside != h1.starts_inside) {
    const Evaluation e = evaluate(c, impl);
    if (!e.near_boundary && !(e.t_err <= tolerances(query_of_case<Case>).t))
      return Failure{"symmetry-caps-swapped-start", describe(h0) + " vs " + describe(h1)};
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
  if (h0.hit != h1.hit) return Failure{what, "verdict changed: " + describe(h0) + " vs " + describe(h1)};
  if (h0.hit && !(h0.t == h1.t && h0.starts_inside == h1.starts_inside && m.pt(h0.point) == h1.point &&
                  (free_normal || m.vec(h0.normal) == h1.normal)))
    return Failure{what, "answer not bit-identical: " + describe(h0) + " vs " + describe(h1)};
  return std::nullopt;
}

}  // namespace geomcheck
