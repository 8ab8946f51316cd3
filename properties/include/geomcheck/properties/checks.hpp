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

/// The implementation under test of collide_cylinder_sphere.
struct CylinderSphereImpl {
  const char* name;
  bool (*overlap)(const Cylinder&, const Sphere&);
  Contact (*collide)(const Cylinder&, const Sphere&);
};
/// The implementation under test of cast_segment_cylinder.
struct CastSegmentCylinderImpl {
  const char* name;
  CastHit (*cast)(const Segment&, const Cylinder&);
};

extern const CylinderSphereImpl kProductionCylinderSphere;
extern const CastSegmentCylinderImpl kProductionCastSegmentCylinder;

using CylinderSphereCase = QueryTraits<QueryId::collide_cylinder_sphere>::Case;
using SegmentCylinderCase = QueryTraits<QueryId::cast_segment_cylinder>::Case;

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
};

Evaluation evaluate(const CylinderSphereCase& c, const CylinderSphereImpl& impl = kProductionCylinderSphere);
Evaluation evaluate(const SegmentCylinderCase& c, const CastSegmentCylinderImpl& impl = kProductionCastSegmentCylinder);

/// Compares an evaluation with the query's tolerances (tolerances.hpp).
CheckResult judge(QueryId id, const Evaluation& e);

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
/// Any input, valid or not: no crash, invalid gives no hit, valid gives finite output.
CheckResult check_robust(const CylinderSphereCase& c, const CylinderSphereImpl& impl = kProductionCylinderSphere);
/// Every check above (metamorphic over all moves).
CheckResult check_all(const CylinderSphereCase& c, const CylinderSphereImpl& impl = kProductionCylinderSphere);

// --- cast_segment_cylinder ---------------------------------------------------
CheckResult check_oracle(const SegmentCylinderCase& c, const CastSegmentCylinderImpl& impl = kProductionCastSegmentCylinder);
/// t in [0,1]; point == S(t) (to the bound); starts_inside iff t == 0 from inside; unit normal.
CheckResult check_consistency(const SegmentCylinderCase& c, const CastSegmentCylinderImpl& impl = kProductionCastSegmentCylinder);
/// Segment reversed: same hit/miss outside the band; caps swapped: same answer to the bounds.
CheckResult check_symmetry(const SegmentCylinderCase& c, const CastSegmentCylinderImpl& impl = kProductionCastSegmentCylinder);
CheckResult check_metamorphic(const SegmentCylinderCase& c, int move, const CastSegmentCylinderImpl& impl = kProductionCastSegmentCylinder);
/// A wider cylinder or a longer segment never turns a hit into a miss (outside the band).
CheckResult check_monotone(const SegmentCylinderCase& c, const CastSegmentCylinderImpl& impl = kProductionCastSegmentCylinder);
CheckResult check_robust(const SegmentCylinderCase& c, const CastSegmentCylinderImpl& impl = kProductionCastSegmentCylinder);
CheckResult check_all(const SegmentCylinderCase& c, const CastSegmentCylinderImpl& impl = kProductionCastSegmentCylinder);

/// Number of metamorphic moves understood by check_metamorphic (0..kNumMoves-1).
inline constexpr int kNumMoves = 6;
const char* move_name(int move);

}  // namespace geomcheck
