// geomcheck — Bullet (3.24, the double-precision build of Debian's
// libbullet-dev) as a peer subject of every registered query: its answers
// held to the same truth and properties as production's, under the claims
// below. This header includes no Bullet header; the sources do, with
// BT_USE_DOUBLE_PRECISION (peers/bullet/CMakeLists.txt; the single-precision
// build is the fallback, and the engine string says which).
//
// ---------------------------------------------------------------------------
// What Bullet is asked
//   Collide queries (cylinder/sphere, /capsule, /box, /triangle, /cylinder;
//   sphere/sphere, sphere/capsule, capsule/capsule: every registered pair of
//   shapes Bullet has): btCollisionWorld::contactPairTest(A, B, callback) on
//   two btCollisionObjects that are not in the world, in a per-thread
//   btCollisionWorld built from btDefaultCollisionConfiguration,
//   btCollisionDispatcher and btDbvtBroadphase. For the cylinder's pairs and
//   sphere/capsule the dispatcher picks btConvexConvexAlgorithm: GJK
//   (btGjkPairDetector) on the shapes' cores (without their margins) and,
//   when the cores meet, EPA (btGjkEpaPenetrationDepthSolver); the margins
//   are then subtracted. Two spheres go to btSphereSphereCollisionAlgorithm
//   and two capsules (both btCapsuleShapeZ) to btConvexConvexAlgorithm's
//   capsule/capsule special case: closed forms of Bullet's own. The callback keeps the deepest manifold
//   point it is given (always one in the hand cases). overlap(A, B) is
//   collide(A, B).hit (the same call), so the two always agree.
//   Cast: is the segment's start in the cylinder? (contactPairTest of a
//   zero-radius btSphereShape at a; a hit is t = 0, starts_inside, point a,
//   normal zero). Otherwise btCollisionWorld::rayTest(a, b) with a
//   ClosestRayResultCallback, the cylinder in the world for the call; the
//   default ray flags, i.e. btSubsimplexConvexCast. Bullet's ray test reports
//   surface entries only: a ray starting inside a convex shape is a miss (a
//   ray from the centre of the unit cylinder: no hit), hence the start test.
//   Sweep: does the ball meet the cylinder at t = 0? (contactPairTest;
//   a hit is t = 0, starts_inside, normal zero, and the point of both that
//   production reports, the cylinder point closest to c, read from Bullet's
//   answer: its witness on the cylinder while the depth is below r (the
//   centre outside), the centre itself once the depth reaches r).
//   Otherwise btCollisionWorld::convexSweepTest of the btSphereShape from c
//   to c + delta (no rotation, allowedCcdPenetration 0) with a
//   ClosestConvexResultCallback (btContinuousConvexCollision: conservative
//   advancement on GJK distances). Bullet's own sweep answers a ball that
//   starts overlapping inconsistently (moving in: t = 0 with an arbitrary
//   normal; moving out or not moving: no hit), hence the start test.
//
// Conventions (checked on hand cases, tests/test_peer_bullet.cpp)
//   Manifold point: m_normalWorldOnB points from B towards A (a sphere at
//   +x of the cylinder gives (-1, 0, 0)); getDistance() < 0 is penetration;
//   getPositionWorldOnA lies on A's surface, getPositionWorldOnB on B's,
//   OnA = OnB + normal * distance. geomcheck's contact: hit when
//   getDistance() <= 0, depth = -getDistance() (>= 0), normal =
//   -m_normalWorldOnB (from A towards B, as geomcheck's), point
//   = the midpoint of the two witness points (Bullet promises no point in
//   both shapes).
//   Ray: m_closestHitFraction is t along a -> b; m_hitPointWorld is a + t (b
//   - a) (setInterpolate3); m_hitNormalWorld the cylinder's outward normal,
//   used as is.
//   Sweep: m_closestHitFraction is t; m_hitPointWorld Bullet's closest point
//   on the cylinder at t; m_hitNormalWorld the cylinder's normal towards the
//   ball, used as is.
//   Touching: exact touching comes back as a GJK distance of either sign
//   near zero (a unit sphere touching the unit cylinder's side: +7e-11, no
//   contact), so touching is not claimed to be contact.
//
// Margins
//   btCylinderShape and btBoxShape keep a collision margin (default 0.04,
//   at most a tenth of the smallest half extent) INSIDE the given extents:
//   the core is the shape shrunk by the margin and the margin sphere-swept
//   back, which rounds every edge and rim by the margin (a unit sphere at
//   (1.5, 0, 1.5) against the unit cylinder: depth 0.2763 with the default
//   margin, 0.29289 with none; true 1 - 1/sqrt(2) = 0.29289). The adapter
//   sets the cylinder's, the box's and the triangle's margin to 0 (and the
//   implicit dimensions to the exact half extents, since setMargin(0) alone
//   recomputes them as (h - 0.04) + 0.04, which rounds); GJK and EPA then
//   run on the exact shapes. A btSphereShape is a point with margin r, a
//   btCapsuleShape a segment with margin r: their margins are their radii,
//   the shapes themselves, not a widening. So no margin widens an answer:
//   Claims::margin is 0.
//
// Shapes
//   Cylinder{p, q, r}  btCylinderShapeZ, half extents (r, r, |q - p| / 2)
//                      (the length from q - p scaled by its largest
//                      component), placed at p/2 + q/2 with the rotation
//                      whose columns are any_perpendicular(u), u x that, u
//                      (u the unit axis). r = 0 is accepted (a segment).
//   Sphere{c, r}       btSphereShape(r) at c (r = 0: a point).
//   Capsule{p, q, r}   btCapsuleShapeZ, radius r, half height |q - p| / 2, in
//                      the cylinder's frame; p == q: half height 0, identity
//                      rotation.
//   Obb{c, axes, e}    btBoxShape, half extents e, basis columns the axes
//                      (a left-handed frame gets axes[2] negated: the same
//                      box); axes not orthonormal to 1e-12 are not
//                      expressed. Zero extents are accepted.
//   Triangle{a, b, c}  btTriangleShape(a, b, c) in world coordinates,
//                      identity pose; degenerate triangles are accepted.
//   Segment{a, b}      the ray from a to b.
//   MovingSphere       btSphereShape(r) moved from c to c + delta.
//   Not expressed (expresses() false; the callables answer no hit): invalid
//   shapes (is_valid), boxes whose axes are not orthonormal, and axes whose
//   length leaves the doubles (q - p overflowing).
//
// Claims (every query): exact_verdict false (GJK / EPA and the casts stop
// on absolute tolerances); touching_is_contact false; margin 0. Collide:
// depth Penetration (EPA's, or GJK's distance minus the radii; Bullet
// offers it as the penetration depth), point_in_both false. Cast and sweep:
// depth None, point_in_both true (the ray's point is a + t (b - a); the
// sweep's is Bullet's hit point on the cylinder).
//
// Observed (hand cases, and 500 verify() cases of each query; Bullet's
// findings, not the adapter's):
//   - Scenes of size 0.25 to 16: depth errors (over the scale) median
//     4e-14, 90th percentile 2e-8, worst 4e-5 (cylinder/sphere; a unit
//     sphere 0.5 into the side: depth 0.49999968, the normal 4e-4 off
//     radial); verdicts right beyond about 1e-8 of touching. Bullet's
//     tolerances are absolute, so small scenes go wrong (the same sphere
//     scaled by 1e-6: depth 0.375e-6 instead of 0.5e-6, the normal 23
//     degrees off; at 1e-20 depth 0; the false verdicts farther than 1e-3
//     of the scale from touching, up to 0.3, were all in scenes below
//     0.02) and large ones too (scaled by 1e6 or more: depth = the
//     sphere's radius, normal (0, 1, 0)).
//   - Near touching: a unit sphere 1e-7 into the side gets depth 2.7e-8,
//     1e-8 into it no contact.
//   - Deep contacts far from the origin: cylinder (48685.48, 56211.36,
//     63054.20) -> (223600.46, 56211.36, 63054.20), r 82687.45, against
//     the sphere (163223.16, 27870.81, 58730.73), r 129209.50 (centre
//     inside): depth 158806 instead of 183228.5; the scene moved to the
//     origin or scaled by 1/16 is right.
//   - Cylinder/cylinder, argument order: A (0, 0, 0) -> (-4k, 0, 0), r 2k,
//     against B (0, 0, 0) -> (0, 0, 4k), r 3k (the axes cross at a common
//     end): for k >= 1e4 (A, B) is NO contact, (B, A) depth 2k; right for
//     k <= 1e3.
//   - Cast: a segment starting less than about 1e-8 outside the unit
//     cylinder (or up to 1e-9 inside its side) and crossing all of it is
//     missed: the start test's GJK sees no containment and rayTest drops a
//     hit at t = 0. Elsewhere t's error (the gap of S(t), over the scale)
//     has median 2e-15, 90th percentile 7e-8.
//   - Sweep: convexSweepTest's conservative advancement stops once the gap
//     is below its absolute 1e-3: t comes early (a ball of radius 0.5 at
//     (3, 0.9, 0) moved by (-6, 0, 0) against the unit cylinder: t
//     0.2998036, true 0.3, a gap of 9.4e-4 left), and a ball starting
//     within 1e-3 of the cylinder and moving towards it is a hit at t = 0
//     that did not start inside. Head-on approaches land exactly.
//   - No crash, abort or hang on finite input (scenes from 1e-310 to
//     1.7e308 tried by hand; none in the verify() runs).
#pragma once

#include "geomcheck/peers/peer.hpp"

/// peer_bullet<Q>(): Bullet's subject of query Q (null where Bullet cannot
/// express Q: found from the query's entry point and shapes, so a new query
/// needs no code here), its expresses() test and the engine string
/// ("Bullet 3.24 (double precision)"); instantiated for every registered
/// query in src/bullet_peer.cpp.
GEOMCHECK_DECLARE_PEER(bullet)
