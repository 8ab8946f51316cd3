// geomcheck — the certified convex engine: one exact oracle for every pair.
//
// Every shape of the harness is convex and is described here as
//
//     hull(points)  (+)  radius * Ball          (point, segment, sphere,
//                                                 capsule, box, triangle)
//     hull(points)  (+)  radius * Disc(axis)    (cylinder: the disc is
//                                                 perpendicular to q - p)
//
// with exact rational points. Each shape has an exact containment test for a
// rational point and an exact test of a support bound h(n) <= d, both in
// rationals, squared with sign care, no square root and no rounding.
//
// Answers are searched for in floating point (GJK for the distance and the
// witness points, EPA for the penetration) and then CERTIFIED:
//
//   Separated    a direction n with h_A(n) + h_B(-n) < 0, checked exactly
//                (the plane n.x = d separates for any d in between);
//   Overlapping  four points w_i = a_i - b_i with a_i in A, b_i in B shown to
//                hold the origin strictly inside their tetrahedron: then
//                0 is interior to A - B, the penetration depth is positive,
//                and x = sum lambda_i a_i = sum lambda_i b_i lies in both;
//   Touching     a common point (checked by exact containment in both) and a
//                direction n with h_A(n) + h_B(-n) <= 0 (exactly): the
//                signed distance is exactly zero.
//   Undecided    only when the search puts |distance| below 2^-200 * scale
//                and neither touching certificate could be built (a contact
//                at a point with no short binary expansion). The enclosure
//                is then built from what the searches found (witness pairs
//                pulled into the shapes: distance <= |a - b|; directions:
//                signed distance >= -(h_A(n) + h_B(-n)) / |n|), after a
//                512-digit search where the 384-digit one left it wider
//                than 2^-200 * scale; EngineHand.UndecidedIsNarrow holds it
//                to that width.
//
// A floating-point filter (GJK in doubles, certificates checked in interval
// arithmetic on doubles with outward rounding) runs first; the rational
// machinery runs only where the filter cannot decide. Then the search is
// repeated in about 128 and 384 binary digits (MPFR), each result again
// certified in rationals (and in 512 digits for a pair still undecided).
//
// Signed distance: positive = Euclidean distance between the shapes,
// negative = minus the penetration depth (the shortest translation that
// separates them). Intervals are certified enclosures.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "geomcheck/oracles/exact.hpp"
#include "geomcheck/shapes.hpp"

namespace geomcheck::oracle {

/// A convex shape of the engine (see the header comment).
struct ConvexShape {
  enum class Kind { Point, Segment, Sphere, Capsule, Cylinder, Box, Triangle, Hull };
  enum class Round { None, Ball, Disc };
  Kind kind = Kind::Point;
  Round round = Round::None;
  std::vector<QVec> points;  // core polytope: its hull
  Q radius = 0;              // ball or disc radius
  QVec axis;                 // disc normal (cylinder: q - p)
  // Box: centre and spans (e_i * axes_i), for exact containment.
  QVec centre;
  std::array<QVec, 3> spans;
  // Double enclosures of the exact data (for the filter and the search).
  std::vector<Vec3> lo, hi;  // per point, coordinate-wise
  double radius_hi = 0;
  Vec3 axis_d;               // nearest double of the axis
};

ConvexShape make_point(Vec3 x);
ConvexShape make_shape(const Segment& s);
ConvexShape make_shape(const Sphere& s);
ConvexShape make_shape(const Capsule& c);
ConvexShape make_shape(const Cylinder& c);
ConvexShape make_shape(const Obb& b);
ConvexShape make_shape(const Triangle& t);
/// The capsule (segment when r == 0) of exact rational end points p, q and
/// radius r >= 0: for shapes the harness constructs (a sweep's path, its
/// prefix up to a time t), which doubles cannot hold.
ConvexShape make_capsule(const QVec& p, const QVec& q, const Q& r);
/// The shape translated by an exact vector (same kind).
ConvexShape translated(const ConvexShape& s, const QVec& t);
/// The shape swept along [0, delta]: s (+) segment(0, delta). Kind Hull:
/// support function and support bound only (no containment test).
ConvexShape swept(const ConvexShape& s, const QVec& delta);
/// Short description ("cylinder", "box", ...).
const char* kind_name(ConvexShape::Kind k);

// ---- exact primitives -------------------------------------------------------

/// Exact containment of a rational point (closed shapes). Throws
/// std::logic_error for Kind::Hull.
bool contains(const ConvexShape& s, const QVec& x);
/// Exact sign of h_s(n) - d (h = support function).
int support_sign(const ConvexShape& s, const QVec& n, const Q& d);
/// Certified enclosure of h_s(n).
QInterval support_value(const ConvexShape& s, const QVec& n);
/// Exact sign of h_A(n) + h_B(-n): < 0 proves separation, <= 0 (with a common
/// point) proves touching.
int separation_sign(const ConvexShape& a, const ConvexShape& b, const QVec& n);
/// A point of the shape's relative interior (the centroid of its core).
QVec inner_point(const ConvexShape& s);

/// Certificates, as returned and as checked.
struct SeparationCertificate {
  QVec n;                  // h_A(n) + h_B(-n) < 0 (or <= 0 for touching)
};
struct OverlapCertificate {
  std::array<QVec, 4> a;   // points of A
  std::array<QVec, 4> b;   // points of B
};
/// Checks (exactly) a separation certificate; `strict` demands < 0.
bool check_separation(const ConvexShape& a, const ConvexShape& b, const SeparationCertificate& c, bool strict);
/// Checks (exactly) that every a_i is in A, every b_i in B, and the origin is
/// strictly inside the tetrahedron of the a_i - b_i.
bool check_overlap(const ConvexShape& a, const ConvexShape& b, const OverlapCertificate& c);
/// Checks (exactly) that x lies in both shapes.
bool check_common_point(const ConvexShape& a, const ConvexShape& b, const QVec& x);

// ---- queries -----------------------------------------------------------------

/// Scale of a pair: the largest coordinate magnitude, radius or extent.
Q pair_scale(const ConvexShape& a, const ConvexShape& b);

/// The default of EngineOptions::double_double and of penetration()'s and
/// time_of_impact()'s `double_double` (true; false gives the engine as it
/// was before that round: bench_checks times both in one run).
bool double_double_default();
void set_double_double_default(bool on);

struct EngineOptions {
  bool filter = true;        // run the double filter first
  /// Search in doubles and certify in rationals before the software
  /// floats, where the double-double round does not run (off, or the scale
  /// out of its range); where it runs, it does this round's work.
  bool exact_small = true;
  /// Also build the rational certificate objects when the interval filter
  /// decided (the verdict is certified either way; for curved shapes the
  /// objects cost more than the verdict).
  bool certificates = true;
  /// Distance interval wanted, relative to scale (0: the verdict suffices).
  double rel_width = 0;
  /// Search in double-double (106 bits) before the 128- and 384-digit
  /// software floats, where the scale allows it (between 2^-100 and 2^100).
  /// Only the speed depends on it: every answer is certified in rationals.
  bool double_double = double_double_default();
  /// With rel_width: refine an overlap's distance (by penetration(), EPA)
  /// only where the overlap may be at most this deep (-distance.hi <= it;
  /// negative: never); unset: always. One call then does what a verdict
  /// call followed by a refining call would.
  std::optional<Q> refine_overlap_within;
  /// An undecided pair's enclosure narrowed from the searches (and a
  /// 512-digit search where 384 digits left it wider than 2^-200 * scale).
  /// Off for callers that read only the verdict (time_of_impact): the
  /// enclosure is then the loose one, from the inner points.
  bool narrow_undecided = true;
};

struct DistanceResult {
  Verdict verdict = Verdict::Undecided;
  QInterval distance;                 // signed distance enclosure
  std::optional<SeparationCertificate> separation;
  std::optional<OverlapCertificate> overlap;
  std::optional<QVec> common_point;   // in both (overlapping or touching)
  std::optional<QVec> witness_a, witness_b;  // in A / in B, |a - b| >= distance
  int bits = 0;                       // 53 (filter/doubles), 128 or 384
  bool by_filter = false;             // decided by the interval filter
  std::string note;                   // how the answer was reached
};

/// Certified verdict and signed-distance enclosure of A against B.
DistanceResult classify(const ConvexShape& a, const ConvexShape& b, const EngineOptions& opt = {});

/// Lower bound of a penetration depth: points a_i of A and b_i of B whose
/// differences span a closed, consistently oriented triangulated surface
/// (faces outward) with the origin strictly inside every face; then every
/// ray from the origin meets the surface inside A - B, and the depth is at
/// least the smallest face distance.
struct DepthCertificate {
  std::vector<QVec> a, b;
  std::vector<std::array<int, 3>> faces;
};
/// Checks (exactly: containment of every point, closedness, orientation
/// signs, face distances squared) that the certificate proves depth >= lo.
bool check_depth(const ConvexShape& a, const ConvexShape& b, const DepthCertificate& c, const Q& lo);

struct PenetrationResult {
  bool overlapping = false;   // certified; false = not certified overlapping
  QInterval depth;            // certified enclosure of the penetration depth
  QVec direction;             // translate B by depth*direction/|direction| to touch
  int faces = 0;              // faces of the certified inner polytope
  std::optional<DepthCertificate> certificate;  // proves depth >= depth.lo
  std::string note;
};
/// Penetration depth of overlapping shapes, enclosed to rel_width * scale
/// where the search can reach it (the enclosure is always certified).
/// `double_double`: search in double-double first (as EngineOptions).
PenetrationResult penetration(const ConvexShape& a, const ConvexShape& b, double rel_width = 1e-30,
                              bool double_double = double_double_default());

struct ImpactResult {
  enum class Kind { NoHit, Hit, StartsInside, Undecided } kind = Kind::Undecided;
  QInterval t;   // Hit: A swept over [0, t.lo] certified separated from B,
                 // A + t.hi*delta certified to meet B (overlapping or touching)
  std::string note;
};
/// First time t in [0, 1] at which A + t*delta meets B, certified.
/// `double_double`: advance in double-double where the scale allows (as
/// EngineOptions; the certificates are the same).
ImpactResult time_of_impact(const ConvexShape& moving, const QVec& delta, const ConvexShape& b,
                            bool double_double = double_double_default());

const char* to_string(ImpactResult::Kind k);

/// The stages of the engine's cascade, cheapest first: what decided a
/// classify() (and refined its distance), or enclosed a penetration depth.
enum class Stage : int {
  None = 0,      ///< no engine call (a closed-form truth)
  Filter,        ///< interval doubles (the filter)
  Double,        ///< a search in doubles, certified in rationals
  DoubleDouble,  ///< a search in double-double, certified in rationals
  Soft128,       ///< a search in 128-digit software floats, certified in rationals
  Soft384,       ///< the same in 384 digits
  Soft512,       ///< the same in 512 digits: only for a pair still undecided, whose
                 ///< enclosure the earlier searches left wider than 2^-200 * scale
  Touching,      ///< exact touching, found among snapped candidates
  Undecided,     ///< no stage decided: a loose certified enclosure
};
const char* to_string(Stage s);
/// Forgets the deepest stage of this thread's engine calls.
void reset_deepest_stage();
/// The deepest stage any engine call of this thread reached since
/// reset_deepest_stage() (a campaign's share of cases per stage).
Stage deepest_stage();
/// Counts stage s as reached by this thread's engine calls (deepest_stage()
/// keeps the deepest): a truth computed earlier and taken again from a
/// memo notes the stage that computed it.
void note_stage(Stage s);

}  // namespace geomcheck::oracle
