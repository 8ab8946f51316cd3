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
//   What it has is continuous collision. fcl_cast runs
//   fcl::continuousCollide of an fcl::Sphered of radius 0 translated from a
//   to b (CCDM_TRANS, CCDC_CONSERVATIVE_ADVANCEMENT, GST_LIBCCD) against the
//   resting cylinder: hit = is_collide, t = time_of_contact. For this pair
//   every step uses the closed-form sphere/cylinder distance, so it is
//   scale-free, assert-free and bounded (each step advances t by at least
//   FCL's t_err = 1e-4, or stops). No contact point or normal comes back.
//
//   Measured against production's cast, 20 000 random segments against the
//   cylinder z in [-1, 1], r = 1 (A) and 20 000 against random cylinders
//   (B), Release build:
//     - t is early, never late (beyond 1e-13 rounding): FCL stops when a step
//       falls under t_err = 1e-4. |t - t_production| max 1.0e-4, mean
//       7.9e-6 (A) / 7.2e-6 (B). On the axis-parallel segment
//       (0.3,0.2,5)->(0.3,0.2,-5) the first step lands exactly: t = 0.4.
//     - by the same stopping rule, a segment that ends or passes within
//       about 1e-4 |b - a| of the surface can be reported as a hit (none in
//       the random sets).
//     - FCL DEFECT: asked once, FCL misses real hits: 203 of 20 000 (A) and
//       207 of 20 000 (B), 3% and 5.5% of the hits; never a false hit. Two
//       mechanisms, both when an advancement step lands the point on the
//       surface: (1) sphereCylinderDistance returns -1 and leaves the
//       nearest points zero, so the motion bound is (b - a).(0,0,0) + 0,
//       which is -0 when every component of b - a is negative, and the next
//       step is -1/-0 = +inf; (2) the distance is a rounding-sized positive
//       number while both nearest points round to the same point, so the
//       direction is zero, the bound 0 <= distance, and FCL concludes the
//       point is not approaching. Either way FCL jumps past t = 1 and
//       reports no collision.
//       kConservativeAdvancement (default) therefore asks again after a
//       miss, in up to three exactly equivalent frames (the scene negated,
//       and/or its coordinates cyclically permuted: no rounding in the
//       re-expression, different rounding in FCL's steps), and takes the
//       first hit. Misses drop to 0 of 20 000 (A) and 8 of 20 000 (B,
//       0.2% of the hits). kConservativeAdvancementOnce is the single
//       raw call, for measuring FCL as shipped.
//     - ~2 us per FCL call: a hit ~2 us, a miss up to 4 calls (~8 us).
//
//   Considered and rejected:
//     - a radius-0 fcl::Capsuled for the segment, hit/miss by fcl::collide
//       (libccd's MPR) and t by bisection on it: accurate for ordinary
//       scenes (hit/miss agreed 40 000/40 000, |dt| <= 9e-6, but the MPR
//       tolerance is absolute, 1e-6, so small scenes are wrong), but
//       libccd's MPR portal refinement has no iteration cap and HANGS on
//       elongated or far-from-origin scenes: in random scenes with
//       max|coordinate| / r between 2^10 and 2^20 it did not return in 3 of
//       904 cases, above 2^40 in about 1 case in 9 (e.g. the segment
//       p -> q along the axis of a cylinder of length about 2^29 and
//       radius 0.64). A harness that must never hang cannot call it.
//     - CCDC_NAIVE only samples N poses (t quantised to 1/(N-1): 0.4004
//       for 0.4 with N = 1000) and misses crossings thinner than a step.
//     - GST_INDEP: runs EPA, which can abort on FCL's asserts.
//
// ---------------------------------------------------------------------------
// Validity and safety:
//   * Shapes failing is_valid (shapes.hpp) are never passed to FCL: the call
//     returns ok = false, error = "invalid input" (fcl_overlap: false).
//   * FCL's Debian build keeps its asserts. Every path used here is free of
//     them and of unbounded loops for valid input: sphere/cylinder collide
//     and distance are closed form, the cast is conservative advancement on
//     that closed-form distance. No libccd GJK/MPR/EPA code runs.
//   * Range. collide/overlap/distance accept every valid input; overflow
//     inside FCL (relative offsets or radii beyond ~1e154, whose squares
//     overflow) shows up as a non-finite output and is reported as
//     ok = false. The cast refuses (ok = false, error = "outside FCL's
//     range") a cylinder radius, axis or segment-to-cylinder offset above
//     2^500 (~3e150) in any coordinate: FCL's bounding-volume fit for
//     continuous collision squares them, overflows, prints "eigen: too many
//     iterations in Jacobi transform." on stderr and answers garbage.
//   * Every FCL exception is caught and reported in `error`.
//   * "Garbage" (ok = false, fields still hold FCL's converted output):
//     non-finite numbers, a contact normal whose length is off 1 by more
//     than 1e-6, a negative depth, a collision with no contact, a time of
//     contact outside [0, 1].
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
  bool ok = false;         ///< false if the input was invalid, FCL threw or returned garbage
  std::string error;       ///< why not ok; empty when ok
  bool supported = false;  ///< FCL can express this query (true for segment/cylinder)
  bool hit = false;        ///< FCL says the segment touches the cylinder
  double t = 0;            ///< first-touch parameter in [0, 1] when hit: FCL's time of contact
};

/// How fcl_cast asks FCL (see the header notes).
enum class FclCastMethod {
  kConservativeAdvancement,      ///< continuousCollide; after a miss, again in up to 3 equivalent frames
  kConservativeAdvancementOnce,  ///< one continuousCollide call on the scene as given (FCL as shipped)
};

/// fcl::collide(cylinder, sphere), num_max_contacts = 1, enable_contact, GST_LIBCCD.
PeerContact fcl_collide(const Cylinder& a, const Sphere& b);

/// fcl::collide(cylinder, sphere) with enable_contact = false, GST_LIBCCD.
/// false for invalid input or when FCL throws; then `*error` (if given) says why.
bool fcl_overlap(const Cylinder& a, const Sphere& b, std::string* error = nullptr);

/// fcl::distance(cylinder, sphere), enable_nearest_points, GST_LIBCCD.
PeerDistance fcl_distance(const Cylinder& a, const Sphere& b);

/// First touch of segment `s` (from s.a towards s.b) with the cylinder, as
/// far as FCL can tell: t within 1e-4, early (see the header notes).
PeerCast fcl_cast(const Segment& s, const Cylinder& c,
                  FclCastMethod method = FclCastMethod::kConservativeAdvancement);

}  // namespace geomcheck::oracles
