// geomcheck — the checks every query of a kind shares, written once:
// evaluate (the common start, then the query's own hold_to_truth),
// check_oracle, check_robust (by kind) and check_all (the order of the
// checks), defined or explicitly instantiated for every registered query.
#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstring>
#include <type_traits>

#include "common.hpp"
#include "contact_checks.hpp"
#include "moving_checks.hpp"
#include "geomcheck/properties/checks.hpp"

namespace geomcheck {

namespace {

CheckResult robust_contact(bool valid, bool ov, const Contact& ct, double unit) {
  if (!valid) {
    if (ov || ct.hit) return Failure{"robust-invalid-input", "invalid input reported a hit: " + describe(ct, ov)};
    return std::nullopt;
  }
  if (ct.hit && !finite_contact(ct)) return Failure{"robust-finite-output", describe(ct, ov)};
  if (ct.hit && !(std::fabs(length(ct.normal) - 1) <= unit)) return Failure{"robust-unit-normal", describe(ct, ov)};
  if (ov != ct.hit) return Failure{"robust-overlap-vs-collide", describe(ct, ov)};
  return std::nullopt;
}

CheckResult robust_hit(bool valid, const CastHit& h, double unit) {
  if (!valid) {
    if (h.hit) return Failure{"robust-invalid-input", "invalid input reported a hit: " + describe(h)};
    return std::nullopt;
  }
  if (!h.hit) return std::nullopt;
  if (!finite_hit(h) || !(h.t >= 0 && h.t <= 1)) return Failure{"robust-finite-output", describe(h)};
  if (!h.starts_inside && !(std::fabs(length(h.normal) - 1) <= unit)) return Failure{"robust-unit-normal", describe(h)};
  return std::nullopt;
}

}  // namespace

namespace {

/// check_robust: any input; a normal's length held to 100 times the
/// subject's unit bound (the consistency check holds a valid case's to the
/// bound itself; robustness asks only that no input, however wild, gives a
/// normal that is not a direction).
template <class Case>
CheckResult robust(const Case& c, const ImplOfCase<Case>& impl) {
  constexpr QueryKind kind = QueryTraits<query_of_case<Case>>::kind;
  const bool valid = is_valid(c.a) && is_valid(c.b);
  const double unit = 100 * bounds(c, impl).unit;
  if constexpr (kind == QueryKind::Collide) return robust_contact(valid, impl.overlap(c.a, c.b), impl.collide(c.a, c.b), unit);
  else if constexpr (kind == QueryKind::Cast) return robust_hit(valid, impl.cast(c.a, c.b), unit);
  else return robust_hit(valid, impl.sweep(c.a, c.b), unit);
}

/// Every check; `known`, when given, is impl's evaluation of c (judged
/// instead of evaluating again). With `every`, each failing property is
/// appended there and the checks go on (the first is returned); without,
/// they stop at the first.
template <class Case>
CheckResult all(const Case& c, const ImplOfCase<Case>& impl, const Evaluation* known = nullptr,
                std::vector<Failure>* every = nullptr) {
  CheckResult first;
  // Notes a failure; true: stop here.
  auto note = [&](CheckResult f) {
    if (!f) return false;
    if (!first) first = *f;
    if (!every) return true;
    every->push_back(std::move(*f));
    return false;
  };
  if (note(robust(c, impl))) return first;
  if (!is_valid(c.a) || !is_valid(c.b)) return first;
  if (every) {
    const Evaluation e = known ? *known : evaluate(c, impl);
    for (Failure& f : judge_every(query_of_case<Case>, e, impl.claims)) note(std::move(f));
  } else if (note(known ? judge(query_of_case<Case>, *known, impl.claims) : check_oracle(c, impl))) {
    return first;
  }
  if (note(check_consistency(c, impl))) return first;
  if (note(check_symmetry(c, impl))) return first;
  for (int m = 0; m < kNumMoves; ++m)
    if (note(check_metamorphic(c, m, impl))) return first;
  note(check_monotone(c, impl));
  return first;
}

// --- the memo of evaluations (set_evaluation_memo) ---------------------------

std::atomic<bool> g_memo{true};

bool same(double x, double y) { return std::memcmp(&x, &y, sizeof x) == 0; }
bool same(const Vec3& a, const Vec3& b) { return same(a.x, b.x) && same(a.y, b.y) && same(a.z, b.z); }
bool same(const Contact& a, const Contact& b) {
  return a.hit == b.hit && same(a.point, b.point) && same(a.normal, b.normal) && same(a.depth, b.depth);
}
bool same(const CastHit& a, const CastHit& b) {
  return a.hit == b.hit && same(a.t, b.t) && same(a.point, b.point) && same(a.normal, b.normal) &&
         a.starts_inside == b.starts_inside;
}

/// The last evaluations of one query on this thread, keyed by what an
/// evaluation is a function of (the case, bit for bit; the subject's
/// answers; the bounds it is held to).
template <class Case, class Answer>
class Memo {
  // Shapes are plain doubles: equal bits, equal case.
  static_assert(std::is_trivially_copyable_v<Case> && sizeof(Case) % sizeof(double) == 0, "a case of doubles");
  struct Entry {
    Case c;
    Answer answer;
    bool prod_hit = false;
    Tolerances tol{};
    Evaluation e;
    oracle::Stage stage = oracle::Stage::None;  // the deepest engine stage that computed e
  };
  std::array<Entry, 4> ring_{};
  int size_ = 0, next_ = 0;

 public:
  const Entry* find(const Case& c, const Answer& answer, bool prod_hit, const Tolerances& tol) const {
    for (int i = 0; i < size_; ++i) {
      const Entry& x = ring_[i];
      if (x.prod_hit == prod_hit && std::memcmp(&x.tol, &tol, sizeof tol) == 0 && same(x.answer, answer) &&
          std::memcmp(&x.c, &c, sizeof c) == 0)
        return &x;
    }
    return nullptr;
  }
  void put(const Case& c, const Answer& answer, bool prod_hit, const Tolerances& tol, const Evaluation& e, oracle::Stage stage) {
    Entry& x = ring_[next_];
    x = Entry{c, answer, prod_hit, tol, e, stage};
    x.e.peer = Evaluation::PeerScore{};
    next_ = (next_ + 1) % static_cast<int>(ring_.size());
    size_ = std::max(size_, next_ == 0 ? static_cast<int>(ring_.size()) : next_);
  }
};

template <class Case, class Answer>
Memo<Case, Answer>& memo() {
  thread_local Memo<Case, Answer> m;
  return m;
}

/// evaluate() of every pair query: the subject's answers, then the truth
/// (hold_to_truth, the query's own) unless the memo has this evaluation.
/// The engine stages a computation reached are kept with it and noted
/// again when it is taken from the memo (a campaign's stage counts).
template <class Case, class Peer>
Evaluation evaluate_pair(const Case& c, const ImplOfCase<Case>& impl, const Peer* peer) {
  Evaluation e;
  e.tol = bounds(c, impl);
  using Answer = typename SubjectAnswerOf<QueryTraits<query_of_case<Case>>::kind>::type;
  Answer answer;
  if (!start_evaluation(e, c, impl, answer)) return e;
  auto& m = memo<Case, Answer>();
  const bool use = g_memo.load(std::memory_order_relaxed);
  if (use && !peer) {
    if (const auto* known = m.find(c, answer, e.prod_hit, e.tol)) {
      oracle::note_stage(known->stage);
      return known->e;
    }
  }
  const oracle::Stage before = oracle::deepest_stage();
  oracle::reset_deepest_stage();
  hold_to_truth(e, c, answer, peer);
  const oracle::Stage stage = oracle::deepest_stage();
  oracle::note_stage(before);  // the thread's deepest stage: the larger of the two
  if (use) m.put(c, answer, e.prod_hit, e.tol, e, stage);
  return e;
}

}  // namespace

void set_evaluation_memo(bool on) { g_memo = on; }

#define GEOMCHECK_X(id, kind, A, B, summary)                                                                   \
  Evaluation evaluate(const PairCase<A, B, QueryId::id>& c, const ImplOf<QueryId::id>& impl,                                \
                      const PeerAnswerOf<kind_of(EntryPoint::kind)>::type* peer) {                                       \
    return evaluate_pair(c, impl, peer);                                                                       \
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
  }                                                                                                          \
  std::vector<Failure> check_every(const PairCase<A, B, QueryId::id>& c, const ImplOf<QueryId::id>& impl,     \
                                   const Evaluation* e) {                                                    \
    std::vector<Failure> every;                                                                              \
    all(c, impl, e, &every);                                                                                 \
    return every;                                                                                            \
  }
GEOMCHECK_QUERY_LIST(GEOMCHECK_X)
#undef GEOMCHECK_X

}  // namespace geomcheck
