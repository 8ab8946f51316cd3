// geomcheck — the properties, each written once as a check function.
//
// A check takes a case (and the implementation under test, production by
// default; the teeth tests pass known-wrong variants) and returns nothing
// when the property holds, or a Failure saying what broke. RapidCheck suites
// (properties/tests) and libFuzzer targets (fuzz/) call the same functions.
#pragma once

#include <any>
#include <cmath>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

#include "geomcheck/oracles/exact.hpp"
#include "geomcheck/oracles/solids.hpp"
#include "geomcheck/properties/tolerances.hpp"
#include "geomcheck/registry.hpp"
#include "geomcheck/results.hpp"

namespace geomcheck {

/// A property that does not hold, and why; a relation check (symmetry,
/// metamorphic, monotone) also gives the other case it compared the case
/// with (a QueryTraits<Q>::Case), so that the failure's page draws both.
struct Failure {
  Failure() = default;
  Failure(std::string property_, std::string detail_, std::any related_ = {})
      : property(std::move(property_)), detail(std::move(detail_)), related(std::move(related_)) {}
  std::string property;
  std::string detail;
  std::any related;  ///< the transformed case of a relation check, or empty
};
using CheckResult = std::optional<Failure>;

/// The arithmetic a subject computes in and the error it claims, from which
/// every bound it is held to derives (bounds_of; docs/semantics.md,
/// "Yardsticks"). Production's is the default: doubles, its own tight
/// bounds, every scale.
struct Precision {
  /// The unit roundoff u of the subject's working arithmetic: 2^-53 for
  /// double, 2^-24 for float.
  double unit_roundoff = 0x1p-53;
  /// The error claimed, in units of u * scale (u alone for the unit length
  /// of a normal): every bound is the larger of `ulps` * u and production's
  /// bound read as its count of double ulps and taken at this u (0:
  /// production's counts alone).
  double ulps = 0;
  /// The scenes the subject states: a case whose scale lies outside
  /// [min_scale, max_scale] is not asked (counted as not expressed), as
  /// code that squares coordinates cannot hold a scene whose squares
  /// overflow or underflow.
  double min_scale = 0;
  double max_scale = INFINITY;
  /// An exact move of the scene (sign flips, power-of-two scales) moves the
  /// answer bit for bit. false: an exact move is held like a rounded one
  /// (the verdict kept outside the band, depths within twice their bound).
  bool exact_moves = true;

  /// Ordinary double code: doubles, `ulps` of the scene (default 1024: a
  /// few ulps per operation over some tens of operations, amplified by a
  /// feature's distance from the origin; docs/semantics.md), scenes whose
  /// scale lies in [2^-250, 2^250] (squares of coordinates stay normal).
  static Precision double_precision(double ulps = 1024) { return {0x1p-53, ulps, 0x1p-250, 0x1p250, false}; }
  /// Float code: u = 2^-24, `ulps` of the scene (default 1024, as for
  /// double), scenes whose scale lies in [2^-60, 2^60] (squares of
  /// coordinates stay normal floats).
  static Precision single_precision(double ulps = 1024) { return {0x1p-24, ulps, 0x1p-60, 0x1p60, false}; }
};

/// What a subject claims about its answers. The checks hold it to these
/// claims and the report prints them beside the figures.
struct Claims {
  /// What a collide query's depth is.
  enum class Depth {
    None,         ///< cast and sweep queries: no depth
    Penetration,  ///< the true penetration depth (minimal translation)
    Shallow,      ///< the true penetration depth while the contact is shallow (see the query's header)
    UpperBound,   ///< a consistent contact: the overlap along the normal, an upper bound of the penetration depth
  };
  bool exact_verdict = true;  ///< the verdict is exact outside the verdict band
  Depth depth = Depth::None;
  bool point_in_both = true;  ///< collide: the point lies in both shapes (cast, sweep: on B)
  const char* normal = "";    ///< the normal's convention, in words
  const char* truth = "";     ///< what the truth is computed by
  bool touching_is_contact = true;  ///< shapes exactly touching count as a contact (closed solids)
  double margin = 0;                ///< answers claimed to within margin * scale (see judge)
  /// Any input is answered safely, valid or not (NaN, infinities, negative
  /// radii: no crash, no hit): the fuzz door's raw mode holds the subject to
  /// it (check_robust). false: raw inputs are not asked.
  bool any_input = true;
  Precision precision{};            ///< the arithmetic and the claimed error every bound derives from
};

/// The bounds a subject with these claims is held to (null: production's),
/// every check's and the report's: tolerances(id), production's, taken at
/// the subject's precision (Precision::ulps * u, or production's count of
/// double ulps at the subject's u), then every scaled bound widened by the
/// claimed margin. Derivation: docs/semantics.md, "Yardsticks".
Tolerances bounds_of(QueryId id, const Claims* claims);
/// Whether a subject claiming `claims` states a case of this scale (its
/// precision's range; always, for production).
bool states_scale(const Claims* claims, double scale);

/// A subject's entry point: a callable of signature R(Args...). A plain
/// function (a function pointer, or a lambda without captures) is held as a
/// pointer: no allocation, and a subject made only of plain functions is
/// initialized before any code runs. Any other callable (a lambda with
/// captures, an object with state, std::ref of one) is held by a shared
/// std::function: copies of the subject share it.
template <class Sig>
class Callable;
template <class R, class... Args>
class Callable<R(Args...)> {
 public:
  using Pointer = R (*)(Args...);
  constexpr Callable() = default;
  /// A plain function.
  constexpr Callable(Pointer p) : ptr_(p) {}
  /// A lambda without captures: held as its function pointer.
  template <class F, std::enable_if_t<std::is_convertible_v<F, Pointer> && !std::is_same_v<F, Pointer>, int> = 0>
  constexpr Callable(F f) : ptr_(static_cast<Pointer>(f)) {}
  /// Any other callable with this signature.
  template <class F, std::enable_if_t<!std::is_convertible_v<F, Pointer> && !std::is_same_v<std::decay_t<F>, Callable> &&
                                          std::is_invocable_r_v<R, F&, Args...>,
                                      int> = 0>
  Callable(F f) : fn_(std::make_shared<const std::function<R(Args...)>>(std::move(f))) {}

  R operator()(Args... args) const { return ptr_ ? ptr_(args...) : (*fn_)(args...); }
  explicit operator bool() const { return ptr_ || fn_; }

 private:
  Pointer ptr_ = nullptr;
  std::shared_ptr<const std::function<R(Args...)>> fn_;
};

/// A subject of a collide query (production, a known-wrong variant, another
/// engine, a user's implementation): overlap(A, B) and collide(A, B) under a
/// name.
template <class A, class B>
struct CollideImpl {
  const char* name;
  Callable<bool(const A&, const B&)> overlap;
  Callable<Contact(const A&, const B&)> collide;
  const Claims* claims = nullptr;  ///< what the subject claims; null: what production claims
  /// The cases the subject can state at all (another engine's limits: a
  /// shape its model refuses); empty: every case. verify() does not ask the
  /// subject the others and counts them apart (not_expressed).
  Callable<bool(const A&, const B&)> expresses{};
};
/// A subject of a cast query: cast(A, B), A the moving segment.
template <class A, class B>
struct CastImpl {
  const char* name;
  Callable<CastHit(const A&, const B&)> cast;
  const Claims* claims = nullptr;  ///< what the subject claims; null: what production claims
  /// The cases the subject can state at all (another engine's limits: a
  /// shape its model refuses); empty: every case. verify() does not ask the
  /// subject the others and counts them apart (not_expressed).
  Callable<bool(const A&, const B&)> expresses{};
};
/// A subject of a sweep query: sweep(A, B), A the moving shape.
template <class A, class B>
struct SweepImpl {
  const char* name;
  Callable<CastHit(const A&, const B&)> sweep;
  const Claims* claims = nullptr;  ///< what the subject claims; null: what production claims
  /// The cases the subject can state at all (another engine's limits: a
  /// shape its model refuses); empty: every case. verify() does not ask the
  /// subject the others and counts them apart (not_expressed).
  Callable<bool(const A&, const B&)> expresses{};
};

/// The subject type of a query kind over shapes A and B.
template <QueryKind K, class A, class B> struct ImplFor;
template <class A, class B> struct ImplFor<QueryKind::Collide, A, B> { using type = CollideImpl<A, B>; };
template <class A, class B> struct ImplFor<QueryKind::Cast, A, B> { using type = CastImpl<A, B>; };
template <class A, class B> struct ImplFor<QueryKind::Sweep, A, B> { using type = SweepImpl<A, B>; };
/// The subject type of query Q.
template <QueryId Q>
using ImplOf = typename ImplFor<QueryTraits<Q>::kind, typename QueryTraits<Q>::ShapeA, typename QueryTraits<Q>::ShapeB>::type;

using CylinderSphereImpl = ImplOf<QueryId::collide_cylinder_sphere>;
using CastSegmentCylinderImpl = ImplOf<QueryId::cast_segment_cylinder>;
using CylinderCapsuleImpl = ImplOf<QueryId::collide_cylinder_capsule>;
using SweepSphereCylinderImpl = ImplOf<QueryId::sweep_sphere_cylinder>;
using CylinderObbImpl = ImplOf<QueryId::collide_cylinder_obb>;
using CylinderTriangleImpl = ImplOf<QueryId::collide_cylinder_triangle>;
using CylinderCylinderImpl = ImplOf<QueryId::collide_cylinder_cylinder>;


/// Production's contact of Collide query Q, its shapes in either order:
/// collide(x, y), or penetration(x, y) for the queries that answer it
/// (answers_penetration, registry.hpp).
template <QueryId Q, class X, class Y>
Contact production_contact(const X& x, const Y& y) {
  if constexpr (answers_penetration(Q)) return penetration(x, y);
  else return collide(x, y);
}

/// Production's subject of query Q, made from its entry points in core/
/// (overlap and collide or penetration, cast, or sweep, found by the shapes'
/// types; every query's header comes with registry.hpp).
template <QueryId Q>
const ImplOf<Q>& production_of() {
  using A = typename QueryTraits<Q>::ShapeA;
  using B = typename QueryTraits<Q>::ShapeB;
  if constexpr (QueryTraits<Q>::kind == QueryKind::Collide) {
    static const ImplOf<Q> subject{"production", [](const A& a, const B& b) { return overlap(a, b); },
                                   [](const A& a, const B& b) { return production_contact<Q>(a, b); }};
    return subject;
  } else if constexpr (QueryTraits<Q>::kind == QueryKind::Cast) {
    static const ImplOf<Q> subject{"production", [](const A& a, const B& b) { return cast(a, b); }};
    return subject;
  } else {
    static const ImplOf<Q> subject{"production", [](const A& a, const B& b) { return sweep(a, b); }};
    return subject;
  }
}

/// Words for a depth claim, for reports.
inline const char* to_string(Claims::Depth d) {
  switch (d) {
    case Claims::Depth::None: return "none";
    case Claims::Depth::Penetration: return "penetration depth";
    case Claims::Depth::Shallow: return "penetration depth while shallow";
    case Claims::Depth::UpperBound: return "overlap along the normal (upper bound)";
  }
  return "?";
}

/// The facts of query Q that are not code: what production claims, how many
/// cases a default campaign runs, and the known-wrong variants (teeth.hpp),
/// each of which the suites must catch.
template <QueryId Q>
struct QuerySpec {
  Claims claims;
  Tolerances bounds;  ///< production's bounds (tolerances.hpp says what each measures)
  int default_cases = 0;
  std::vector<const ImplOf<Q>*> variants;
};
/// Query Q's spec (defined by GEOMCHECK_SPEC at the head of
/// properties/src/checks_<id>.cpp).
template <QueryId Q> const QuerySpec<Q>& spec_of();
#define GEOMCHECK_X(id, kind, A, B, summary) template <> const QuerySpec<QueryId::id>& spec_of<QueryId::id>();
GEOMCHECK_QUERY_LIST(GEOMCHECK_X)
#undef GEOMCHECK_X

/// Defines spec_of<QueryId::id>() from the query's default case count, its
/// Claims, production's bounds (a Tolerances row) and its known-wrong
/// variants (pointers into teeth.hpp, possibly none), and names the query
/// `kId` in the file's anonymous namespace. Used once, at the head of
/// properties/src/checks_<id>.cpp, inside namespace geomcheck.
#define GEOMCHECK_SPEC(id, default_cases, claims, bounds, ...)                               \
  template <>                                                                                \
  const QuerySpec<QueryId::id>& spec_of<QueryId::id>() {                                     \
    static const QuerySpec<QueryId::id> spec{claims, bounds, default_cases, {__VA_ARGS__}}; \
    return spec;                                                                     \
  }                                                                                  \
  namespace {                                                                        \
  [[maybe_unused]] constexpr QueryId kId = QueryId::id;                              \
  }

/// Whether subject `impl` states case c: its expresses() (a throw: no);
/// for a valid case, its precision's range of scales (Precision::min_scale,
/// max_scale); an invalid case only when it claims any input
/// (Claims::any_input). verify() and the fuzz door ask the
/// subject only the cases it states.
template <class Case, class Impl>
bool subject_states(const Case& c, const Impl& impl) {
  const bool valid = is_valid(c.a) && is_valid(c.b);
  if (!valid && impl.claims && !impl.claims->any_input) return false;
  if (valid && !states_scale(impl.claims, oracle::case_scale(c.a, c.b))) return false;
  if (!impl.expresses) return true;
  try {
    return impl.expresses(c.a, c.b);
  } catch (...) {
    return false;
  }
}

/// The subject type of the query whose case type is Case.
template <class Case>
using ImplOfCase = ImplOf<query_of_case<Case>>;

using CylinderSphereCase = QueryTraits<QueryId::collide_cylinder_sphere>::Case;
using SegmentCylinderCase = QueryTraits<QueryId::cast_segment_cylinder>::Case;
using CylinderCapsuleCase = QueryTraits<QueryId::collide_cylinder_capsule>::Case;
using SweepCylinderCase = QueryTraits<QueryId::sweep_sphere_cylinder>::Case;
using CylinderObbCase = QueryTraits<QueryId::collide_cylinder_obb>::Case;
using CylinderTriangleCase = QueryTraits<QueryId::collide_cylinder_triangle>::Case;
using CylinderCylinderCase = QueryTraits<QueryId::collide_cylinder_cylinder>::Case;

/// Production held against the oracle on one case: everything a report or a
/// check needs. Errors are multiples of `scale`; NaN where not applicable.
struct Evaluation {
  bool valid = false;            ///< both shapes valid
  double scale = 1;
  bool prod_hit = false;         ///< overlap() / cast().hit
  bool truth_hit = false;        ///< exact verdict: overlapping or touching / hit
  oracle::Verdict verdict = oracle::Verdict::Undecided;
  double signed_distance = NAN;  ///< certified midpoint (collide); NaN for casts
  bool disagree = false;         ///< prod_hit != truth_hit
  bool excused = false;          ///< disagreement inside the verdict band
  bool near_boundary = false;    ///< the exact answer is within the verdict band of touching
  double margin = NAN;           ///< how far from touching a disagreement is, / scale
                                 ///< (collide: |signed distance|; cast: see disagreement_margin)
  double depth_err = NAN;
  double normal_err = NAN;
  double point_err = NAN;
  double t_err = NAN;
  double t_true = NAN;           ///< casts: the oracle's first t (midpoint of its enclosure); sweeps: NaN (exact_first_touch)
  double unit_err = NAN;
  std::string extra_failure;     ///< a non-numeric failure found while evaluating
  std::string truth_text;        ///< oracle answer, human readable
  std::string prod_text;         ///< production answer, human readable
  /// Collide queries, separated: the certified distance (midpoint of an
  /// enclosure at most 1e-12 * scale wide); NaN otherwise.
  double distance = NAN;
  /// Another engine's contact (FCL's), held to the same yardstick as
  /// production's when evaluate() is given one: depth, normal (overlap
  /// along it beyond the true depth) and point (outside either shape)
  /// errors, multiples of `scale`; NaN where not measured (no hit, no truth
  /// precise enough, a zero normal). Casts and sweeps: t error as for
  /// production (the gap of the segment point or ball at the peer's t, or,
  /// starting inside, how far it moved before t).
  struct PeerScore {
    double depth_err = NAN, normal_err = NAN, point_err = NAN, unit_err = NAN, t_err = NAN;
  } peer;
  /// Collide queries whose depth is an upper bound rather than the
  /// penetration depth (collide_cylinder_cylinder): production's depth over
  /// the certified penetration depth, where the shapes overlap, the
  /// engine's enclosure of it is within 1% (relative) and it is at least
  /// 1e-9 * scale (below that, rounding decides the ratio); NaN otherwise.
  double depth_ratio = NAN;
  /// Where depth_ratio is measured: depth over the enclosure's upper end,
  /// rounded down, a certain lower bound of the ratio (what the depth-ratio
  /// bound of a consistent contact is held to, tolerances.hpp).
  double depth_ratio_lo = NAN;
  /// Collide queries, where the truth encloses the penetration depth PD
  /// (the shapes overlapping or touching): how far production's depth
  /// certainly lies below PD (depth_short) and above it (depth_over), as
  /// multiples of `scale`, 0 where it may lie inside; NaN where not
  /// measured. They judge a subject whose depth claim differs from
  /// production's (judge()): an upper bound is held by depth_short alone,
  /// the true penetration depth on a query whose production claims only an
  /// upper bound also by depth_over.
  double depth_short = NAN, depth_over = NAN;
  /// The bounds the subject is held to (bounds_of its claims): the band of
  /// touching the truth is settled at, and every error's bound.
  Tolerances tol{};
};

/// The oracle's verdict in the words of case files' `oracle-verdict`:
/// collide queries overlapping / touching / separated, casts hit / miss.
inline std::string verdict_word(QueryId id, const Evaluation& e) {
  return info(id).kind == QueryKind::Collide ? oracle::to_string(e.verdict) : (e.truth_hit ? "hit" : "miss");
}

/// Compares an evaluation with the query's tolerances (tolerances.hpp) and
/// what production claims, or, given a subject's `claims`, with what that
/// subject claims: an inexact verdict (disagreements reported, not failed),
/// touching not counted as contact (a miss where the truth is touching
/// passes), no depth or no point-in-both claim (those errors not judged), a
/// margin (a disagreement within margin * scale of touching passes; every
/// error bound grows by the margin), and the depth's meaning: a subject
/// claiming an upper bound (a consistent contact) where production claims
/// the penetration depth is held only to not falling below it
/// (depth_short); one claiming the true penetration depth where production
/// claims an upper bound (collide_cylinder_cylinder) is held to it from
/// both sides (depth_over too), a stronger claim than production's.
CheckResult judge(QueryId id, const Evaluation& e, const Claims* claims = nullptr);
/// judge(), every failing property of the evaluation (empty: none), in the
/// order judge() tries them.
std::vector<Failure> judge_every(QueryId id, const Evaluation& e, const Claims* claims = nullptr);

// --- every query, by kind (properties/src/kind_checks.cpp) ------------------
// Declared for every registered query as plain overloads (not templates), so
// that their names link the same from any compiler:
//   check_robust  any input, valid or not: no crash; invalid input gives no
//                 hit; a hit's output is finite and its normal unit (a
//                 cast's or sweep's t in [0, 1]); collide queries: overlap
//                 agrees with collide's hit.
//   check_all     every check of the query, in order, stopping at the first
//                 failure: robust, then (valid input only) oracle,
//                 consistency, symmetry, every metamorphic move, monotone.
//   check_every   every check of the query, not stopping: each failing
//                 property of the case (empty: none), in check_all's order;
//                 `e`, when given, is impl's evaluation of c.
//   check_all(c, e, impl)  the same, given `e`, impl's evaluation of c
//                 (evaluate(c, impl, peer) for any peer): the oracle check
//                 judges e, so the truth is not asked for again (a campaign
//                 evaluates every case for its report anyway).
#define GEOMCHECK_X(id, kind, A, B, summary)                                                                    \
  CheckResult check_robust(const PairCase<A, B, QueryId::id>& c, const ImplOf<QueryId::id>& impl = production_of<QueryId::id>()); \
  CheckResult check_all(const PairCase<A, B, QueryId::id>& c, const ImplOf<QueryId::id>& impl = production_of<QueryId::id>()); \
  CheckResult check_all(const PairCase<A, B, QueryId::id>& c, const Evaluation& e,                                           \
                        const ImplOf<QueryId::id>& impl = production_of<QueryId::id>());                               \
  std::vector<Failure> check_every(const PairCase<A, B, QueryId::id>& c,                                                      \
                                   const ImplOf<QueryId::id>& impl = production_of<QueryId::id>(),                     \
                                   const Evaluation* e = nullptr);
GEOMCHECK_QUERY_LIST(GEOMCHECK_X)
#undef GEOMCHECK_X

/// evaluate() keeps this thread's last four evaluations of each query and
/// gives one back when asked again with the same case, the same subject
/// answers (overlap and contact, or the hit) and the same claimed margin,
/// all compared bit for bit: an evaluation is a function of these alone, so
/// the checks that compare a case with a moved copy (metamorphic, monotone)
/// do not ask the engine for the case's truth again. The subject is still
/// asked every time. On by default; off: every evaluation computed (the
/// "before" of bench_checks). A peer's evaluation is computed every time
/// and kept without the peer's scores.
void set_evaluation_memo(bool on);

// --- every query: the checks that are the query's own ----------------------
// Declared here for every registered query; each defined in
// properties/src/checks_<id>.cpp, whose head says what it means there.
//   evaluate           the subject held against the truth on one case (a peer's
//                      answer, when given, scored against the same truth);
//   check_oracle       agreement with the truth outside the verdict band, and
//                      every error within its bound (tolerances.hpp);
//   check_consistency  the answer agrees with itself (overlap and collide, t and
//                      point, a unit normal, the depth along the normal);
//   check_symmetry     the same solids stated another way give the same answer;
//   check_metamorphic  move `move` (0..kNumMoves-1) of the scene moves the answer;
//   check_monotone     a superset never loses the hit (outside the band).

/// What a peer's answer is, by query kind: a contact (collide) or a first t.
template <QueryKind K> struct PeerAnswerOf { using type = Contact; };
template <> struct PeerAnswerOf<QueryKind::Cast> { using type = double; };
template <> struct PeerAnswerOf<QueryKind::Sweep> { using type = double; };

#define GEOMCHECK_X(id, kind, A, B, summary)                                                                     \
  Evaluation evaluate(const PairCase<A, B, QueryId::id>& c, const ImplOf<QueryId::id>& impl = production_of<QueryId::id>(),    \
                      const PeerAnswerOf<kind_of(EntryPoint::kind)>::type* peer = nullptr);                               \
  CheckResult check_oracle(const PairCase<A, B, QueryId::id>& c, const ImplOf<QueryId::id>& impl = production_of<QueryId::id>()); \
  CheckResult check_consistency(const PairCase<A, B, QueryId::id>& c,                                                        \
                                const ImplOf<QueryId::id>& impl = production_of<QueryId::id>());               \
  CheckResult check_symmetry(const PairCase<A, B, QueryId::id>& c, const ImplOf<QueryId::id>& impl = production_of<QueryId::id>()); \
  CheckResult check_metamorphic(const PairCase<A, B, QueryId::id>& c, int move,                                              \
                                const ImplOf<QueryId::id>& impl = production_of<QueryId::id>());               \
  CheckResult check_monotone(const PairCase<A, B, QueryId::id>& c, const ImplOf<QueryId::id>& impl = production_of<QueryId::id>());
GEOMCHECK_QUERY_LIST(GEOMCHECK_X)
#undef GEOMCHECK_X

// --- helpers of single queries ------------------------------------------------
/// Axes orthonormal to 16 eps (|a_i . a_j - delta_ij|): production's contract.
bool obb_in_contract(const Obb& b);
/// Production's depth over the certified penetration depth (Evaluation::depth_ratio):
/// NaN when the shapes do not overlap, the enclosure is wider than 1% or the
/// penetration depth is below 1e-9 * scale.
double depth_ratio(const CylinderCylinderCase& c, const CylinderCylinderImpl& impl = production_of<QueryId::collide_cylinder_cylinder>());

/// Sweeps: the ball's exact first touch of the cylinder, the midpoint of the
/// engine's time of impact when that is enclosed to 1e-12 (0 when the ball
/// starts inside); NaN otherwise. Costly (the engine's conservative
/// advancement, several certified distances): evaluate() does not ask it;
/// campaigns ask it for FCL's |t - t_exact| on their first cases.
double exact_first_touch(const SweepCylinderCase& c);
/// Number of metamorphic moves understood by check_metamorphic (0..kNumMoves-1).
inline constexpr int kNumMoves = 6;
const char* move_name(int move);

}  // namespace geomcheck
