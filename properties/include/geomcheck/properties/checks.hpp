// geomcheck — the properties, each written once as a check function.
//
// A check takes a case (and the implementation under test, production by
// default; the teeth tests pass known-wrong variants) and returns nothing
// when the property holds, or a Failure saying what broke. RapidCheck suites
// (properties/tests) and libFuzzer targets (fuzz/) call the same functions.
#pragma once

#include <cmath>
#include <optional>
#include <string>

#include "geomcheck/oracles/exact.hpp"
#include "geomcheck/registry.hpp"
#include "geomcheck/results.hpp"

namespace geomcheck {

/// A property that does not hold, and why.
struct Failure {
  std::string property;
  std::string detail;
};
using CheckResult = std::optional<Failure>;

/// A subject of a collide query (production, a known-wrong variant, another
/// engine): overlap(A, B) and collide(A, B) under a name.
template <class A, class B>
struct CollideImpl {
  const char* name;
  bool (*overlap)(const A&, const B&);
  Contact (*collide)(const A&, const B&);
};
/// A subject of a cast query: cast(A, B), A the moving segment.
template <class A, class B>
struct CastImpl {
  const char* name;
  CastHit (*cast)(const A&, const B&);
};
/// A subject of a sweep query: sweep(A, B), A the moving shape.
template <class A, class B>
struct SweepImpl {
  const char* name;
  CastHit (*sweep)(const A&, const B&);
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

extern const CylinderSphereImpl kProductionCylinderSphere;
extern const CastSegmentCylinderImpl kProductionCastSegmentCylinder;
extern const CylinderCapsuleImpl kProductionCylinderCapsule;
extern const SweepSphereCylinderImpl kProductionSweepSphereCylinder;
extern const CylinderObbImpl kProductionCylinderObb;
extern const CylinderTriangleImpl kProductionCylinderTriangle;
extern const CylinderCylinderImpl kProductionCylinderCylinder;

/// Production's subject of query Q (kProduction...), for generic code.
template <QueryId Q> const ImplOf<Q>& production_of();
#define GEOMCHECK_X(id, kind, A, B, summary) template <> const ImplOf<QueryId::id>& production_of<QueryId::id>();
GEOMCHECK_QUERY_LIST(GEOMCHECK_X)
#undef GEOMCHECK_X
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
  double t_true = NAN;           ///< casts: the oracle's first t (midpoint of its enclosure)
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
};

// `peer` (collide: a contact; cast, sweep: a t), when given, is scored into
// Evaluation::peer against the same truth (computed once).
Evaluation evaluate(const CylinderSphereCase& c, const CylinderSphereImpl& impl = kProductionCylinderSphere, const Contact* peer = nullptr);
Evaluation evaluate(const SegmentCylinderCase& c, const CastSegmentCylinderImpl& impl = kProductionCastSegmentCylinder, const double* peer_t = nullptr);
Evaluation evaluate(const CylinderCapsuleCase& c, const CylinderCapsuleImpl& impl = kProductionCylinderCapsule, const Contact* peer = nullptr);
Evaluation evaluate(const SweepCylinderCase& c, const SweepSphereCylinderImpl& impl = kProductionSweepSphereCylinder, const double* peer_t = nullptr);
Evaluation evaluate(const CylinderObbCase& c, const CylinderObbImpl& impl = kProductionCylinderObb, const Contact* peer = nullptr);
Evaluation evaluate(const CylinderTriangleCase& c, const CylinderTriangleImpl& impl = kProductionCylinderTriangle, const Contact* peer = nullptr);
Evaluation evaluate(const CylinderCylinderCase& c, const CylinderCylinderImpl& impl = kProductionCylinderCylinder, const Contact* peer = nullptr);

/// The oracle's verdict in the words of case files' `oracle-verdict`:
/// collide queries overlapping / touching / separated, casts hit / miss.
inline std::string verdict_word(QueryId id, const Evaluation& e) {
  return info(id).kind == QueryKind::Collide ? oracle::to_string(e.verdict) : (e.truth_hit ? "hit" : "miss");
}

/// Compares an evaluation with the query's tolerances (tolerances.hpp).
CheckResult judge(QueryId id, const Evaluation& e);

// --- every query, by kind (properties/src/kind_checks.cpp) ------------------
/// Any input, valid or not: no crash; invalid input gives no hit; a hit's
/// output is finite and its normal unit (a cast's or sweep's t in [0, 1]);
/// collide queries: overlap agrees with collide's hit.
template <class Case>
CheckResult check_robust(const Case& c, const ImplOfCase<Case>& impl = production_of<query_of_case<Case>>());
/// Every check of the query, in order, stopping at the first failure:
/// robust, then (valid input only) oracle, consistency, symmetry, every
/// metamorphic move, monotone.
template <class Case>
CheckResult check_all(const Case& c, const ImplOfCase<Case>& impl = production_of<query_of_case<Case>>());

// --- collide_cylinder_sphere -------------------------------------------------
/// Agreement with the exact oracle outside the band; depth, normal, point within bounds.
CheckResult check_oracle(const CylinderSphereCase& c, const CylinderSphereImpl& impl = kProductionCylinderSphere);
/// overlap == collide.hit; unit normal; depth >= 0 equals the overlap along the normal; no NaN.
CheckResult check_consistency(const CylinderSphereCase& c, const CylinderSphereImpl& impl = kProductionCylinderSphere);
/// (A,B) and (B,A) agree, normal flips; caps swapped gives the same answer (to the band).
CheckResult check_symmetry(const CylinderSphereCase& c, const CylinderSphereImpl& impl = kProductionCylinderSphere);
/// Sign flips and power-of-two scales bit-identical; axis permutations and
/// rigid motions agree outside the band.
CheckResult check_metamorphic(const CylinderSphereCase& c, int move, const CylinderSphereImpl& impl = kProductionCylinderSphere);
/// Growing the sphere or the cylinder radius never turns overlap into separation.
CheckResult check_monotone(const CylinderSphereCase& c, const CylinderSphereImpl& impl = kProductionCylinderSphere);

// --- cast_segment_cylinder ---------------------------------------------------
CheckResult check_oracle(const SegmentCylinderCase& c, const CastSegmentCylinderImpl& impl = kProductionCastSegmentCylinder);
/// t in [0,1]; point == S(t) (to the bound); starts_inside iff t == 0 from inside; unit normal.
CheckResult check_consistency(const SegmentCylinderCase& c, const CastSegmentCylinderImpl& impl = kProductionCastSegmentCylinder);
/// Segment reversed: same hit/miss outside the band; caps swapped: same answer to the bounds.
CheckResult check_symmetry(const SegmentCylinderCase& c, const CastSegmentCylinderImpl& impl = kProductionCastSegmentCylinder);
CheckResult check_metamorphic(const SegmentCylinderCase& c, int move, const CastSegmentCylinderImpl& impl = kProductionCastSegmentCylinder);
/// A wider cylinder or a longer segment never turns a hit into a miss (outside the band).
CheckResult check_monotone(const SegmentCylinderCase& c, const CastSegmentCylinderImpl& impl = kProductionCastSegmentCylinder);

// --- collide_cylinder_capsule --------------------------------------------------
/// Agreement with the engine outside the band; the depth claim (shallow
/// contacts: true depth and minimal-translation normal), point in both.
CheckResult check_oracle(const CylinderCapsuleCase& c, const CylinderCapsuleImpl& impl = kProductionCylinderCapsule);
/// overlap == collide.hit; unit normal; depth >= 0 equals the overlap along the normal; no NaN.
CheckResult check_consistency(const CylinderCapsuleCase& c, const CylinderCapsuleImpl& impl = kProductionCylinderCapsule);
/// (A,B) and (B,A) agree, normal flips; caps swapped, capsule reversed: same verdict (band), same depth.
CheckResult check_symmetry(const CylinderCapsuleCase& c, const CylinderCapsuleImpl& impl = kProductionCylinderCapsule);
CheckResult check_metamorphic(const CylinderCapsuleCase& c, int move, const CylinderCapsuleImpl& impl = kProductionCylinderCapsule);
/// Growing either radius never turns overlap into separation (outside the band).
CheckResult check_monotone(const CylinderCapsuleCase& c, const CylinderCapsuleImpl& impl = kProductionCylinderCapsule);

// --- sweep_sphere_cylinder -----------------------------------------------------
/// Hit/miss agrees with the engine (the swept capsule against the cylinder)
/// outside the band; t: the ball at t touches (to the bound) and the sweep up
/// to t stays out (bracketing, certified by the engine); point on the
/// cylinder at the ball; normal in the normal cone there.
CheckResult check_oracle(const SweepCylinderCase& c, const SweepSphereCylinderImpl& impl = kProductionSweepSphereCylinder);
/// t in [0,1]; starts_inside iff the ball meets the cylinder at t = 0
/// (overlap(Cylinder, Sphere)); the ball at t meets the cylinder and just
/// before t does not (collide(Cylinder, Sphere)); the swept capsule up to 1
/// agrees with overlap(Cylinder, Capsule) outside the band.
CheckResult check_consistency(const SweepCylinderCase& c, const SweepSphereCylinderImpl& impl = kProductionSweepSphereCylinder);
/// Caps swapped: same answer to the bounds.
CheckResult check_symmetry(const SweepCylinderCase& c, const SweepSphereCylinderImpl& impl = kProductionSweepSphereCylinder);
CheckResult check_metamorphic(const SweepCylinderCase& c, int move, const SweepSphereCylinderImpl& impl = kProductionSweepSphereCylinder);
/// A bigger ball, a wider cylinder or a longer sweep never turns a hit into a miss (outside the band).
CheckResult check_monotone(const SweepCylinderCase& c, const SweepSphereCylinderImpl& impl = kProductionSweepSphereCylinder);

// --- collide_cylinder_obb ------------------------------------------------------
/// Agreement with the engine outside the band; the depth claim (see the
/// query's header), point in both. A box whose axes are not orthonormal is
/// outside production's contract: only the robust check applies.
CheckResult check_oracle(const CylinderObbCase& c, const CylinderObbImpl& impl = kProductionCylinderObb);
/// overlap == collide.hit; unit normal; depth >= 0 equals the overlap along the normal; no NaN.
CheckResult check_consistency(const CylinderObbCase& c, const CylinderObbImpl& impl = kProductionCylinderObb);
/// (A,B) and (B,A) agree, normal flips; caps swapped, box axes permuted or
/// negated: same verdict (band), same depth to the bound.
CheckResult check_symmetry(const CylinderObbCase& c, const CylinderObbImpl& impl = kProductionCylinderObb);
CheckResult check_metamorphic(const CylinderObbCase& c, int move, const CylinderObbImpl& impl = kProductionCylinderObb);
/// A wider or longer cylinder or a bigger box never turns overlap into separation (outside the band).
CheckResult check_monotone(const CylinderObbCase& c, const CylinderObbImpl& impl = kProductionCylinderObb);
/// Axes orthonormal to 16 eps (|a_i . a_j - delta_ij|): production's contract.
bool obb_in_contract(const Obb& b);

// --- collide_cylinder_triangle -------------------------------------------------
/// Agreement with the engine outside the band; the depth claim (see the
/// query's header), point in both. Every finite triangle is in the contract
/// (a degenerate one is its longest edge or its point).
CheckResult check_oracle(const CylinderTriangleCase& c, const CylinderTriangleImpl& impl = kProductionCylinderTriangle);
/// overlap == collide.hit; unit normal; depth >= 0 equals the overlap along the normal; no NaN.
CheckResult check_consistency(const CylinderTriangleCase& c, const CylinderTriangleImpl& impl = kProductionCylinderTriangle);
/// (A,B) and (B,A) agree, normal flips; caps swapped, triangle vertices
/// rotated or reversed: same verdict (band), same depth to the bound.
CheckResult check_symmetry(const CylinderTriangleCase& c, const CylinderTriangleImpl& impl = kProductionCylinderTriangle);
/// As for the other queries, but for a reflection of a scene whose cylinder
/// axis lies exactly in the triangle's plane: there the normal is free
/// (mirror pairs), the verdict and point bit-identical, the depth to the bound.
CheckResult check_metamorphic(const CylinderTriangleCase& c, int move, const CylinderTriangleImpl& impl = kProductionCylinderTriangle);
/// A wider or longer cylinder or a bigger triangle never turns overlap into separation (outside the band).
CheckResult check_monotone(const CylinderTriangleCase& c, const CylinderTriangleImpl& impl = kProductionCylinderTriangle);

// --- collide_cylinder_cylinder -------------------------------------------------
/// Agreement with the engine outside the band; the point in both cylinders;
/// the depth never below the certified penetration depth by more than the
/// bound (it is the overlap along the returned normal, an upper bound of the
/// penetration depth, and need not equal it: see the query's header).
CheckResult check_oracle(const CylinderCylinderCase& c, const CylinderCylinderImpl& impl = kProductionCylinderCylinder);
/// overlap == collide.hit; unit normal; depth >= 0 equals the overlap along the normal; no NaN.
CheckResult check_consistency(const CylinderCylinderCase& c, const CylinderCylinderImpl& impl = kProductionCylinderCylinder);
/// (A,B) and (B,A): the same verdict (band), the normal flipped and the depth
/// equal to the bounds; caps swapped (either cylinder): same verdict (band),
/// same depth to the bound.
CheckResult check_symmetry(const CylinderCylinderCase& c, const CylinderCylinderImpl& impl = kProductionCylinderCylinder);
/// As for the other queries, but for a reflection of a scene whose two axes
/// lie exactly in one plane: there the normal may be the other of a mirror
/// pair (point bit-identical, depth to the bound); and for any reflection,
/// a tie: another normal with the point and the depth bit-identical, as good
/// as the returned one (the overlap along it, exactly, equals the depth).
CheckResult check_metamorphic(const CylinderCylinderCase& c, int move, const CylinderCylinderImpl& impl = kProductionCylinderCylinder);
/// A wider or longer cylinder (either one) never turns overlap into separation (outside the band).
CheckResult check_monotone(const CylinderCylinderCase& c, const CylinderCylinderImpl& impl = kProductionCylinderCylinder);
/// Production's depth over the certified penetration depth (Evaluation::depth_ratio):
/// NaN when the shapes do not overlap, the enclosure is wider than 1% or the
/// penetration depth is below 1e-9 * scale.
double depth_ratio(const CylinderCylinderCase& c, const CylinderCylinderImpl& impl = kProductionCylinderCylinder);

/// Number of metamorphic moves understood by check_metamorphic (0..kNumMoves-1).
inline constexpr int kNumMoves = 6;
const char* move_name(int move);

}  // namespace geomcheck
