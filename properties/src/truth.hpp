// geomcheck — the truth of the engine-backed queries, through the certified
// engine: a capsule (or a swept ball: the capsule of its path) or a polytope
// (box, triangle, cylinder) against a cylinder (internal to properties/).
#pragma once

#include <cmath>
#include <functional>
#include <optional>
#include <string>

#include "geomcheck/oracles/cylinder_sphere.hpp"
#include "geomcheck/oracles/engine.hpp"
#include "geomcheck/properties/checks.hpp"
#include "geomcheck/results.hpp"

namespace geomcheck {

/// The truth of Capsule{p, q, r} (exact rational end points) against a cylinder.
struct CapsuleTruth {
  oracle::Verdict verdict = oracle::Verdict::Undecided;
  /// Certified signed distance of the capsule from the cylinder (> 0 gap,
  /// < 0 minus the penetration depth). Narrow where it decides the band;
  /// when pq enters the cylinder deeper than that, only hi <= -r is sharp.
  oracle::QInterval signed_distance;
  /// The segment pq certified outside the cylinder: then signed_distance is
  /// D - r with D = dist(pq, cylinder), enclosed to 1e-20 * scale.
  bool core_outside = false;
  oracle::QInterval core_distance;  ///< D (when core_outside)
  std::string text;                 ///< human readable
};

/// Engine answers for the capsule: the segment pq against the cylinder
/// (distance refined to 1e-20 * scale wherever it can decide whether the
/// capsule is within `band` of touching), then, only when the capsule's
/// verdict is not decided by that distance, the capsule itself.
CapsuleTruth capsule_truth(const oracle::ConvexShape& cylinder, const oracle::QVec& p, const oracle::QVec& q,
                           const oracle::Q& r, const oracle::Q& band);

/// The truth of a polytope (box, triangle) against a cylinder.
struct PolytopeTruth {
  oracle::Verdict verdict = oracle::Verdict::Undecided;
  /// Certified signed distance (exactly 0 when touching): to 1e-20 * scale
  /// when separated, or overlapping with a first enclosure reaching above
  /// -2 band; a deeper overlap keeps that first (wide) enclosure.
  oracle::QInterval signed_distance;
  std::string text;  ///< human readable
  /// The certified penetration depth at 1e-20 * scale where the refinement
  /// above computed it (a shallow overlap): the contact's scoring takes it
  /// instead of asking the engine again.
  std::optional<oracle::PenetrationResult> penetration;
};

/// The engine's answer for `shape` against the cylinder: the verdict, and
/// the signed distance refined to 1e-20 * scale where it can decide the band
/// (always when separated: GJK to convergence is cheap; when overlapping only
/// if the depth can still be within the band, since that runs EPA).
PolytopeTruth polytope_truth(const oracle::ConvexShape& cyl, const oracle::ConvexShape& shape, const oracle::Q& band);

/// The double reported for a signed-distance enclosure: its midpoint when
/// narrow (<= 1e-6 * scale), else its end nearest to zero (a certified bound).
double nearest_to_zero(const oracle::QInterval& x, double scale);

/// Overlap of A and B measured along unit(n): (h_A(n) + h_B(-n)) / |n|, certified.
oracle::QInterval overlap_along(const oracle::ConvexShape& a, const oracle::ConvexShape& b, const oracle::QVec& n);

/// A consistent contact's depth (an overlap along a direction, never below
/// the penetration depth) against the certified enclosure `pd` of the
/// penetration depth: `shortfall`, its certain part below pd (multiples of
/// `scale`; 0 otherwise); where pd is at least 1e-9 * scale and enclosed
/// within 1%, `ratio` = depth / pd's midpoint and `ratio_lo` a certain lower
/// bound of depth / penetration depth (NaN elsewhere).
struct UpperBoundScore {
  double shortfall = 0, ratio = NAN, ratio_lo = NAN;
};
UpperBoundScore score_upper_bound(double depth, const oracle::QInterval& pd, double scale);

/// One contact (production's or a peer's) scored against a polytope pair's
/// truth (cylinder against a box or a triangle): unit-normal error; with the
/// truth overlapping, depth and normal errors against the certified EPA
/// enclosure of the penetration depth (computed once into `pd`; where it is
/// wider than 1% of `depth_bound` the errors are the distance from the
/// enclosure, a certain lower bound, and `*wide` is set); the point's error
/// from the cylinder's certified signed distance and `outside_b(point)`, an
/// upper bound of its distance outside B. Multiples of `scale`; NaN where not
/// measured. `upper_bound`: the contact is consistent, not minimal (its depth
/// the overlap along its normal, Claims::Depth::UpperBound): the depth error
/// is only its certain shortfall below the enclosure, the normal is not
/// scored, and where the penetration depth is at least 1e-9 * scale and
/// enclosed within 1%, `ratio` is depth / its midpoint and `ratio_lo` a
/// certain lower bound of depth / penetration depth.
struct ContactErrors {
  double unit = NAN, depth = NAN, normal = NAN, point = NAN, ratio = NAN, ratio_lo = NAN;
};
ContactErrors score_polytope_contact(const Contact& k, bool truth_hit, const PolytopeTruth& truth,
                                     const oracle::QCylinder& qcyl, const oracle::ConvexShape& cyl,
                                     const oracle::ConvexShape& shape, double scale, double depth_bound,
                                     std::optional<oracle::PenetrationResult>& pd,
                                     const std::function<oracle::Q(Vec3)>& outside_b, std::string* wide,
                                     bool upper_bound = false);

/// Production's contact and, when given, the peer's, each scored by
/// score_polytope_contact against the same truth (EPA at most once), into
/// e's error fields and e.peer's (and production's depth ratio into e's);
/// a wide enclosure is noted in e.truth_text.
void score_polytope_contacts(Evaluation& e, const Contact& mine, const Contact* peer, const PolytopeTruth& truth,
                             const oracle::QCylinder& qcyl, const oracle::ConvexShape& cyl,
                             const oracle::ConvexShape& shape, double depth_bound,
                             const std::function<oracle::Q(Vec3)>& outside_b, bool upper_bound = false);

/// Certified signed distance of a point from the capsule pq, r (< 0 inside).
oracle::QInterval capsule_signed_distance(const oracle::QVec& p, const oracle::QVec& q, const oracle::Q& r,
                                          const oracle::QVec& x);

}  // namespace geomcheck
