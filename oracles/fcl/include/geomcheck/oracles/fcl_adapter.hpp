// geomcheck — FCL (Flexible Collision Library 0.7) as an independent peer.
//
// FCL is NOT an oracle: it is a widely used engine whose answers the harness
// reports beside production and the exact oracle, so that every report also
// measures FCL. Nothing here includes FCL headers; see fcl_convert.hpp for
// the shape conversion and the pre-converted ("prepared") calls used by the
// benchmarks.
//
// ---------------------------------------------------------------------------
// Conversion (fcl_convert.hpp)
//   Cylinder{p, q, r} -> fcl::Cylinderd(radius r, lz = |q - p|) placed at
//   (p + q)/2 (computed as p/2 + q/2, which cannot overflow) with a rotation
//   taking +z to (q - p)/|q - p|, built from an orthonormal frame around the
//   axis (no special case: anti-parallel axes are as accurate as any other).
//   Sphere{c, r} -> fcl::Sphered(r) translated to c.
//   The conversion rounds (|q - p|, the unit axis, the frame, the midpoint):
//   FCL answers for a shape within a few ulps of ours, never exactly ours.
//
// Solver: every call uses GST_LIBCCD. (GST_INDEP returns negative depths and
// can abort on FCL's asserts.) For cylinder/sphere FCL 0.7 does not run GJK
// at all: with GST_LIBCCD it dispatches to its closed-form
// sphereCylinderIntersect / sphereCylinderDistance.
//
// ---------------------------------------------------------------------------
// Normal convention (checked empirically, see tests/test_fcl_adapter.cpp):
//   fcl::collide(cylinder, sphere) returns Contact::normal pointing from o1
//   (the cylinder) towards o2 (the sphere), as FCL's contact.h documents.
//   A sphere above the top cap (+z) gives normal (0, 0, +1); with the
//   arguments swapped it gives (0, 0, -1). This is geomcheck's convention
//   (from A towards B), so no flip is applied. `depth` is FCL's
//   penetration_depth; `point` is FCL's contact position: the middle of the
//   overlap along the normal (for a centre outside the cylinder, the closest
//   cylinder point moved depth/2 into the cylinder: sphere at z = 1.8, r = 1,
//   above a cap at z = 1 gives z = 0.9), NOT production's closest point.
//   Centre inside the cylinder: FCL exits through the nearer cap unless the
//   side is nearer by more than 16 eps; a centre on the axis, nearer the
//   side, gets the cylinder frame's +x axis (column 0 of
//   fcl_rotation_z_to, i.e. any_perpendicular of the axis).
//
// ---------------------------------------------------------------------------
// Distance:
//   fcl::distance with enable_nearest_points and GST_LIBCCD. When the shapes
//   are separated, `distance` > 0 and p_a (on the cylinder), p_b (on the
//   sphere) are world-frame nearest points. When they touch or overlap FCL
//   does not compute a signed distance for this pair: it returns exactly -1
//   and leaves the nearest points zero. The adapter passes that through
//   unchanged (ok = true, distance = -1): read `distance < 0` as "FCL says
//   overlapping or touching", never as a penetration depth.
//
// ---------------------------------------------------------------------------
// Cast (segment against cylinder): what FCL can and cannot answer.
//   FCL 0.7 has no ray or segment query returning a first-hit parameter.
//   Two FCL facilities can express one; `FclCastMethod` selects which.
//   Numbers below: 20 000 random segments against the cylinder z in [-1, 1],
//   r = 1 (A), and 20 000 against random cylinders (B), compared with
//   production's cast; Release build.
//
//   * kCapsuleBisection (default). The segment is an fcl::Capsuled of radius
//     0 (a == b: an fcl::Sphered of radius 0). hit/miss = fcl::collide
//     (enable_contact = false), which for capsule/cylinder runs libccd's MPR
//     intersection test. t = bisection on the same FCL predicate applied to
//     the prefix [a, a + t (b - a)] (at most 64 FCL calls; stops when the
//     bracket is two adjacent doubles): the smallest t FCL says touches.
//     FCL itself never reports t; the adapter derives it from FCL's
//     discrete test, so t inherits that test's accuracy:
//       - hit/miss agreed with production in 20 000/20 000 (A) and
//         20 000/20 000 (B) cases;
//       - |t - t_production| max 8.8e-6, mean 1.1e-7 (A, 6 719 hits);
//         max 2.1e-6, mean 6.3e-8 (B, 3 759 hits); either side;
//       - MPR's tolerance is ABSOLUTE (1e-6): the error in t is about
//         1e-6 / |b - a|, so small scenes are answered badly (a cylinder of
//         radius 1e-5: t = 0.3627 instead of 0.375 on a side hit; at 1e-150
//         a segment through the centre is reported as a miss);
//       - ~1.7 us per FCL call; a hit costs ~55 calls (~90 us), a miss one.
//   * kConservativeAdvancement. FCL's own continuous collision:
//     fcl::continuousCollide of an fcl::Sphered of radius 0 translated from a
//     to b (CCDM_TRANS, CCDC_CONSERVATIVE_ADVANCEMENT, GST_LIBCCD) against
//     the resting cylinder; t = ContinuousCollisionResult::time_of_contact.
//     The native FCL answer; closed-form distances, so scale-free. Measured:
//       - t is early (never later than exact, up to 1e-13 rounding): FCL
//         stops advancing when a step falls under its fixed t_err = 1e-4;
//         |t - t_production| max 1.0e-4, mean 7.9e-6 (A) / 7.2e-6 (B). On
//         the axis-parallel (0.3,0.2,5)->(0.3,0.2,-5) case the first step
//         lands exactly: t = 0.4, error 0. By the same stopping rule a near
//         miss can be reported as a hit (none seen in the random sets);
//       - it MISSES real hits: 203 of 20 000 (A), 207 of 20 000 (B), about
//         3% of the hits, never a false hit. Cause (FCL 0.7): when a step
//         lands the point exactly on the surface, sphereCylinderDistance
//         returns -1 with zero nearest points, the motion bound is then
//         v.0 = -0, the next step is -1/-0 = +inf, FCL advances past t = 1
//         and reports no collision;
//       - ~2-3 us per cast.
//     FCL's naive CCD (CCDC_NAIVE) only samples N poses (t quantised to
//     1/(N-1), e.g. 0.4004 for 0.4 with N = 1000; misses thin crossings)
//     and is not offered.
//   Neither method gives a contact point or normal: PeerCast has none.
//
// ---------------------------------------------------------------------------
// Validity and safety:
//   * Shapes failing is_valid (shapes.hpp) are never passed to FCL: the call
//     returns ok = false, error = "invalid input" (fcl_overlap: false).
//   * FCL's Debian build keeps its asserts. The paths used here are
//     assert-free for valid input: sphere/cylinder is closed form, the cast
//     uses only libccd's MPR intersection (no EPA, where FCL's asserts live),
//     and conservative advancement on a closed-form distance.
//   * libccd's MPR loops have no iteration cap; to keep its arithmetic away
//     from overflow, the capsule cast refuses coordinates above 2^500 in
//     magnitude (ok = false, error = "outside FCL safe range"). The closed
//     form paths accept every valid input; overflow inside FCL shows up as a
//     non-finite output and is reported as ok = false.
//   * Every FCL exception is caught and reported in `error`.
//   * "Garbage" (ok = false, fields still hold FCL's converted output):
//     non-finite numbers, a contact normal whose length is off 1 by more
//     than 1e-6, a negative depth, a collision with no contact.
#pragma once

#include <string>

#include "geomcheck/shapes.hpp"
#include "geomcheck/vec3.hpp"

namespace geomcheck::oracles {

/// FCL's contact for cylinder (A) against sphere (B), in geomcheck's
/// convention (normal from A towards B).
struct PeerContact {
  bool ok = false;    ///< false if the input was invalid, FCL threw or returned garbage
  std::string error;  ///< why not ok; empty when ok
  bool hit = false;   ///< FCL says the shapes intersect (touching included)
  Vec3 point;         ///< FCL's contact position (world frame)
  Vec3 normal;        ///< unit, from the cylinder towards the sphere
  double depth = 0;   ///< FCL's penetration depth
};

/// FCL's separation distance for cylinder (A) against sphere (B).
struct PeerDistance {
  bool ok = false;    ///< false if the input was invalid, FCL threw or returned garbage
  std::string error;  ///< why not ok; empty when ok
  double distance = 0;  ///< > 0 separated; exactly -1 when FCL sees overlap/touching
  Vec3 p_a;           ///< nearest point on the cylinder (zero when distance < 0)
  Vec3 p_b;           ///< nearest point on the sphere (zero when distance < 0)
};

/// FCL's answer to a segment cast.
struct PeerCast {
  bool ok = false;         ///< false if the input was invalid or rejected, FCL threw or returned garbage
  std::string error;       ///< why not ok; empty when ok
  bool supported = false;  ///< FCL can express this query (true for segment/cylinder)
  bool hit = false;        ///< FCL says the segment touches the cylinder
  double t = 0;            ///< first-touch parameter in [0, 1] when hit (see header notes for accuracy)
};

/// Which FCL facility answers a cast (see the header notes).
enum class FclCastMethod {
  kCapsuleBisection,         ///< radius-0 capsule, MPR test; t by bisection on it
  kConservativeAdvancement,  ///< fcl::continuousCollide, conservative advancement
};

/// fcl::collide(cylinder, sphere), num_max_contacts = 1, enable_contact, GST_LIBCCD.
PeerContact fcl_collide(const Cylinder& a, const Sphere& b);

/// fcl::collide(cylinder, sphere) with enable_contact = false, GST_LIBCCD.
/// false for invalid input or when FCL throws; then `*error` (if given) says why.
bool fcl_overlap(const Cylinder& a, const Sphere& b, std::string* error = nullptr);

/// fcl::distance(cylinder, sphere), enable_nearest_points, GST_LIBCCD.
PeerDistance fcl_distance(const Cylinder& a, const Sphere& b);

/// First touch of segment `s` (from s.a towards s.b) with the cylinder, as
/// far as FCL can tell (see the header notes for both methods' accuracy).
PeerCast fcl_cast(const Segment& s, const Cylinder& c,
                  FclCastMethod method = FclCastMethod::kCapsuleBisection);

}  // namespace geomcheck::oracles
