// geomcheck — the checks every query of a kind shares, written once:
// evaluate (the common start, then the query's own hold_to_truth),
// check_oracle, check_robust (by kind) and check_all (the order of the
// checks), defined or explicitly instantiated for every registered query.
#include <cmath>
#include <type_traits>

#include "common.hpp"
#include "contact_checks.hpp"
#include "moving_checks.hpp"
#include "geomcheck/properties/checks.hpp"

namespace geomcheck {

namespace {

CheckResult robust_contact(bool valid, bool ov, const Contact& ct) {
  if (!valid) {
    if (ov || ct.hit) return Failure{"robust-invalid-input", "invalid input reported a hit: " + describe(ct, ov)};
    return std::nullopt;
  }
  if (ct.hit && !finite_contact(ct)) return Failure{"robust-finite-output", describe(ct, ov)};
  if (ct.hit && !(std::fabs(length(ct.normal) - 1) <= 1e-12)) return Failure{"robust-unit-normal", describe(ct, ov)};
  if (ov != ct.hit) return Failure{"robust-overlap-vs-collide", describe(ct, ov)};
  return std::nullopt;
}

CheckResult robust_hit(bool valid, const CastHit& h) {
  if (!valid) {
    if (h.hit) return Failure{"robust-invalid-input", "invalid input reported a hit: " + describe(h)};
    return std::nullopt;
  }
  if (!h.hit) return std::nullopt;
  if (!finite_hit(h) || !(h.t >= 0 && h.t <= 1)) return Failure{"robust-finite-output", describe(h)};
  if (!h.starts_inside && !(std::fabs(length(h.normal) - 1) <= 1e-12)) return Failure{"robust-unit-normal", describe(h)};
  return std::nullopt;
}

}  // namespace

namespace {

template <class Case>
CheckResult robust(const Case& c, const ImplOfCase<Case>& impl) {
  constexpr QueryKind kind = QueryTraits<query_of_case<Case>>::kind;
  const bool valid = is_valid(c.a) && is_valid(c.b);
  if constexpr (kind == QueryKind::Collide) return robust_contact(valid, impl.overlap(c.a, c.b), impl.collide(c.a, c.b));
  else if constexpr (kind == QueryKind::Cast) return robust_hit(valid, impl.cast(c.a, c.b));
  else return robust_hit(valid, impl.sweep(c.a, c.b));
}

/// Every check; `known`, when given, is impl's evaluation of c (judged
/// instead of evaluating again).
template <class Case>
CheckResult all(const Case& c, const ImplOfCase<Case>& impl, const Evaluation* known = nullptr) {
  if (auto f = robust(c, impl)) return f;
  if (!is_valid(c.a) || !is_valid(c.b)) return std::nullopt;
  if (auto f = known ? judge(query_of_case<Case>, *known, impl.claims) : check_oracle(c, impl)) return f;
  if (auto f = check_consistency(c, impl)) return f;
  if (auto f = check_symmetry(c, impl)) return f;
  for (int m = 0; m < kNumMoves; ++m)
    if (auto f = check_metamorphic(c, m, impl)) return f;
  return check_monotone(c, impl);
}

}  // namespace

#define GEOMCHECK_X(id, kind, A, B, summary)                                                                   \
  Evaluation evaluate(const PairCase<A, B, QueryId::id>& c, const ImplOf<QueryId::id>& impl,                                \
                      const PeerAnswerOf<QueryKind::kind>::type* peer) {                                       \
    Evaluation e;                                                                                              \
    SubjectAnswerOf<QueryKind::kind>::type answer;                                                             \
    if (start_evaluation(e, c, impl, answer)) {                                                                \
      hold_to_truth(e, c, answer, peer);                                                                       \
      widen_band(e, claimed_margin(impl));                                                                     \
    }                                                                                                          \
    return e;                                                                                                  \
  }                                                                                                            \
  CheckResult check_oracle(const PairCase<A, B, QueryId::id>& c, const ImplOf<QueryId::id>& impl) {                         \
    return judge(QueryId::id, evaluate(c, impl), impl.claims);                                                 \
  }
GEOMCHECK_QUERY_LIST(GEOMCHECK_X)
#undef GEOMCHECK_X

#define GEOMCHECK_X(id, kind, A, B, summary)                                                          \
  CheckResult check_robust(const PairCase<A, B, QueryId::id>& c, const ImplOf<QueryId::id>& impl) { return robust(c, impl); } \
  CheckResult check_all(const PairCase<A, B, QueryId::id>& c, const ImplOf<QueryId::id>& impl) { return all(c, impl); }    \
  CheckResult check_all(const PairCase<A, B, QueryId::id>& c, const Evaluation& e, const ImplOf<QueryId::id>& impl) {     \
    return all(c, impl, &e);                                                                                 \
  }
GEOMCHECK_QUERY_LIST(GEOMCHECK_X)
#undef GEOMCHECK_X

}  // namespace geomcheck
