// Hand cases with known answers for the ODE peer (peers/ode/include/
// geomcheck/peers/ode.hpp), and one short verify() run.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <string>

#include "geomcheck/peers/ode.hpp"
#include "geomcheck/verify.hpp"
#include "hand_cylinders.hpp"

namespace geomcheck::peers {
namespace {

/// ODE's native colliders (sphere, box, ray) on these cases: to rounding.
constexpr Tol kNative{1e-12, 1e-12};
/// ODE's box collider off the coordinate axes: 7.5e-9 off in depth on the
/// rotated hand case.
constexpr Tol kBoxRotated{1e-7, 1e-7};
/// ODE's trimesh collider: 2.4e-8 off in depth on a vertex case, 1.3e-7 in
/// the normal on the rotated one.
constexpr Tol kTrimesh{1e-7, 1e-6};
/// libccd's MPR inside ODE (capsule, crossed cylinders): to its tolerance.
constexpr Tol kMpr{1e-6, 1e-3};

template <QueryId Q>
const ImplOf<Q>& subject_of() {
  const PeerSubject<Q> p = peer_ode<Q>();
  if (!p.subject) throw std::logic_error("no ODE subject");
  return *p.subject;
}

/// Checks a collide answer: a hit `depth` deep along `normal` (geomcheck's
/// direction, from the cylinder towards B), overlap agreeing.
template <QueryId Q, class A, class B>
void expect_contact(const A& a, const B& b, double depth, Vec3 normal, Tol tol) {
  const auto& s = subject_of<Q>();
  const Contact c = s.collide(a, b);
  ASSERT_TRUE(c.hit);
  EXPECT_TRUE(s.overlap(a, b));
  EXPECT_GE(c.depth, 0.0);
  EXPECT_NEAR(c.depth, depth, tol.depth);
  EXPECT_NEAR(length(c.normal - normal), 0.0, tol.normal)
      << "normal (" << c.normal.x << ", " << c.normal.y << ", " << c.normal.z << ")";
  EXPECT_NEAR(length(c.normal), 1.0, 1e-12);
}

template <QueryId Q, class A, class B>
void expect_separated(const A& a, const B& b) {
  const auto& s = subject_of<Q>();
  EXPECT_FALSE(s.overlap(a, b));
  const Contact c = s.collide(a, b);
  EXPECT_FALSE(c.hit);
  EXPECT_EQ(c.depth, 0.0);
}

constexpr QueryId kSphere = QueryId::collide_cylinder_sphere;
constexpr QueryId kCast = QueryId::cast_segment_cylinder;
constexpr QueryId kCapsule = QueryId::collide_cylinder_capsule;
constexpr QueryId kSweep = QueryId::sweep_sphere_cylinder;
constexpr QueryId kObb = QueryId::collide_cylinder_obb;
constexpr QueryId kTriangle = QueryId::collide_cylinder_triangle;
constexpr QueryId kCylinder = QueryId::collide_cylinder_cylinder;

TEST(PeerOde, EngineIsDoublePrecisionOde016) {
  const std::string config = ode_configuration();
  EXPECT_NE(config.find("ODE_double_precision"), std::string::npos) << config;
  EXPECT_EQ(std::string(peer_ode<kSphere>().engine).rfind("ODE 0.16", 0), 0u) << peer_ode<kSphere>().engine;
}

TEST(PeerOde, ExpressesEveryQueryButTheSweep) {
  EXPECT_NE(peer_ode<kSphere>().subject, nullptr);
  EXPECT_NE(peer_ode<kCast>().subject, nullptr);
  EXPECT_NE(peer_ode<kCapsule>().subject, nullptr);
  EXPECT_EQ(peer_ode<kSweep>().subject, nullptr);  // ODE has no sweep
  EXPECT_NE(peer_ode<kObb>().subject, nullptr);
  EXPECT_NE(peer_ode<kTriangle>().subject, nullptr);
  EXPECT_NE(peer_ode<kCylinder>().subject, nullptr);
  EXPECT_STREQ(peer_ode<kObb>().subject->name, "ODE");
}

TEST(PeerOde, ClaimsAreAFloatingPointEnginesConsistentContact) {
  const Claims& c = *peer_ode<kSphere>().subject->claims;
  EXPECT_FALSE(c.exact_verdict);
  EXPECT_EQ(c.depth, Claims::Depth::UpperBound);
  EXPECT_FALSE(c.point_in_both);
  EXPECT_TRUE(c.touching_is_contact);
  EXPECT_EQ(c.margin, 0.0);
  EXPECT_STREQ(c.truth, spec_of<kSphere>().claims.truth);
  const Claims& cast = *peer_ode<kCast>().subject->claims;
  EXPECT_EQ(cast.depth, Claims::Depth::None);
  EXPECT_TRUE(cast.point_in_both);
  EXPECT_FALSE(peer_ode<kCylinder>().subject->claims->touching_is_contact);
}

// --- cylinder / sphere (dCollideCylinderSphere) -----------------------------

TEST(PeerOdeSphere, BesideTheSideNormalPointsFromCylinderToSphere) {
  // A ball of radius 1 centred 1.5 from the axis: 0.5 into the side. ODE's
  // own normal is (-1, 0, 0) (into the cylinder, its g1); ours is +x.
  expect_contact<kSphere>(kZ, Sphere{{1.5, 0, 0}, 1.0}, 0.5, {1, 0, 0}, kNative);
  expect_contact<kSphere>(kZ, Sphere{{-1.5, 0, 0}, 1.0}, 0.5, {-1, 0, 0}, kNative);
  // ODE's point: the ball's deepest point along the normal.
  const Contact c = subject_of<kSphere>().collide(kZ, Sphere{{1.5, 0, 0}, 1.0});
  EXPECT_NEAR(length(c.point - Vec3{0.5, 0, 0}), 0.0, 1e-12);
}

TEST(PeerOdeSphere, AboveEitherCapWhicheverWayTheAxisRuns) {
  expect_contact<kSphere>(kZ, Sphere{{0, 0, 1.8}, 1.0}, 0.2, {0, 0, 1}, kNative);
  expect_contact<kSphere>(kZFlipped, Sphere{{0, 0, 1.8}, 1.0}, 0.2, {0, 0, 1}, kNative);
  expect_contact<kSphere>(kZFlipped, Sphere{{0.3, 0, -1.8}, 1.0}, 0.2, {0, 0, -1}, kNative);
}

TEST(PeerOdeSphere, CentreInsideExitsThroughTheNearerCap) {
  // Centre (0.2, 0, 0.5): 0.5 below the top cap, 0.8 inside the side. Out
  // through the top: 1.5 along +z (the side would take 1.8).
  expect_contact<kSphere>(kZ, Sphere{{0.2, 0, 0.5}, 1.0}, 1.5, {0, 0, 1}, kNative);
  const Contact c = subject_of<kSphere>().collide(kZ, Sphere{{0.2, 0, 0.5}, 1.0});
  EXPECT_NEAR(length(c.point - Vec3{0.2, 0, -0.5}), 0.0, 1e-12);  // the ball's deepest point
}

TEST(PeerOdeSphere, RotatedCylinder) {
  // kOblique, a ball of radius 0.5 0.7 from the axis: 0.3 into the side.
  expect_contact<kSphere>(kOblique, Sphere{kObliqueMid + 0.7 * kObliquePerp, 0.5}, 0.3, kObliquePerp, kNative);
  expect_contact<kSphere>(kOblique, Sphere{kObliqueMid - 0.7 * kObliquePerp, 0.5}, 0.3, -kObliquePerp, kNative);
  // 0.3 beyond the q cap along the axis: 0.2 deep, normal +axis.
  expect_contact<kSphere>(kOblique, Sphere{kOblique.q + 0.3 * kObliqueAxis, 0.5}, 0.2, kObliqueAxis, kNative);
  expect_contact<kSphere>(kOblique, Sphere{kOblique.p - 0.3 * kObliqueAxis + 0.1 * kObliquePerp, 0.5}, 0.2,
                          -kObliqueAxis, kNative);
}

TEST(PeerOdeSphere, TouchingIsAContactOfDepthZero) {
  expect_contact<kSphere>(kZ, Sphere{{2, 0, 0}, 1.0}, 0.0, {1, 0, 0}, kNative);
}

TEST(PeerOdeSphere, Separated) {
  expect_separated<kSphere>(kZ, Sphere{{3, 0, 0}, 1.0});
  expect_separated<kSphere>(kZ, Sphere{{0, 0, 2.5}, 1.0});
  expect_separated<kSphere>(kOblique, Sphere{kObliqueMid + 1.2 * kObliquePerp, 0.5});
}

TEST(PeerOdeSphere, InvalidInputIsNoHitAndNotExpressed) {
  const auto p = peer_ode<kSphere>();
  const Sphere nan_ball{{NAN, 0, 0}, 1.0};
  EXPECT_FALSE(p.subject->overlap(kZ, nan_ball));
  EXPECT_FALSE(p.subject->collide(kZ, nan_ball).hit);
  EXPECT_FALSE(p.expresses({kZ, nan_ball}));
  EXPECT_FALSE(p.expresses({Cylinder{{1, 1, 1}, {1, 1, 1}, 1.0}, Sphere{{0, 0, 0}, 1.0}}));
  EXPECT_TRUE(p.expresses({kOblique, Sphere{{0, 0, 0}, 0.0}}));
}

// --- the cast (dCollideRayCylinder) --------------------------------------------

TEST(PeerOdeCast, HitsTheSideAndTheCapWithTheOutwardNormal) {
  const auto& s = subject_of<kCast>();
  CastHit h = s.cast(Segment{{5, 0, 0}, {-5, 0, 0}}, kZ);
  ASSERT_TRUE(h.hit);
  EXPECT_FALSE(h.starts_inside);
  EXPECT_NEAR(h.t, 0.4, 1e-15);
  EXPECT_NEAR(length(h.normal - Vec3{1, 0, 0}), 0.0, 1e-15);
  EXPECT_NEAR(length(h.point - Vec3{1, 0, 0}), 0.0, 1e-15);
  h = s.cast(Segment{{0.5, 0, 5}, {0.5, 0, -5}}, kZFlipped);
  ASSERT_TRUE(h.hit);
  EXPECT_NEAR(h.t, 0.4, 1e-15);
  EXPECT_NEAR(length(h.normal - Vec3{0, 0, 1}), 0.0, 1e-15);
  EXPECT_NEAR(length(h.point - Vec3{0.5, 0, 1}), 0.0, 1e-15);
}

TEST(PeerOdeCast, RotatedCylinder) {
  // From 3 beyond the side of kOblique straight at the axis: the side (0.5
  // from the axis) is reached after 2.5 of 6.
  const CastHit h =
      subject_of<kCast>().cast(Segment{kObliqueMid + 3.0 * kObliquePerp, kObliqueMid - 3.0 * kObliquePerp}, kOblique);
  ASSERT_TRUE(h.hit);
  EXPECT_NEAR(h.t, 2.5 / 6, 1e-14);
  EXPECT_NEAR(length(h.normal - kObliquePerp), 0.0, 1e-12);
  EXPECT_NEAR(length(h.point - (kObliqueMid + 0.5 * kObliquePerp)), 0.0, 1e-12);
}

TEST(PeerOdeCast, StartInsideIsTimeZero) {
  const auto& s = subject_of<kCast>();
  // ODE's ray alone reports the exit here; the adapter asks first whether
  // the start lies in the cylinder.
  for (const Segment& seg :
       {Segment{{0.5, 0, 0}, {5, 0, 0}}, Segment{{0.5, 0, 0}, {0.6, 0, 0}}, Segment{{1, 0, 0}, {5, 0, 0}}}) {
    const CastHit h = s.cast(seg, kZ);
    ASSERT_TRUE(h.hit);
    EXPECT_TRUE(h.starts_inside);
    EXPECT_EQ(h.t, 0.0);
    EXPECT_EQ(h.point, seg.a);
    EXPECT_EQ(h.normal, Vec3{});
  }
}

TEST(PeerOdeCast, Misses) {
  const auto& s = subject_of<kCast>();
  EXPECT_FALSE(s.cast(Segment{{5, 2, 0}, {-5, 2, 0}}, kZ).hit);  // passes beside
  EXPECT_FALSE(s.cast(Segment{{5, 0, 0}, {3, 0, 0}}, kZ).hit);   // stops short
  EXPECT_FALSE(s.cast(Segment{{5, 0, 0}, {10, 0, 0}}, kZ).hit);  // goes away
  const auto p = peer_ode<kCast>();
  const Segment point{{0.5, 0, 0}, {0.5, 0, 0}};
  EXPECT_FALSE(p.expresses({point, kZ}));  // a ray needs a direction
  EXPECT_FALSE(s.cast(point, kZ).hit);
}

// --- cylinder / capsule (dCollideCapsuleCylinder: libccd MPR) ----------------------

TEST(PeerOdeCapsule, BesideTheSideAndAboveTheCap) {
  expect_contact<kCapsule>(kZ, Capsule{{1.3, 0, -1}, {1.3, 0, 1}, 0.5}, 0.2, {1, 0, 0}, kMpr);
  expect_contact<kCapsule>(kZ, Capsule{{-1, 0, 1.3}, {1, 0, 1.3}, 0.5}, 0.2, {0, 0, 1}, kMpr);
  expect_contact<kCapsule>(kZFlipped, Capsule{{-1, 0, -1.3}, {1, 0, -1.3}, 0.5}, 0.2, {0, 0, -1}, kMpr);
}

TEST(PeerOdeCapsule, RotatedCylinder) {
  // A capsule across kOblique's q cap, its segment 0.3 beyond the cap plane
  // and 0.1 off the axis line. (On the axis line, the centres' difference
  // along the axis, ODE's MPR misses this 0.2 deep overlap: see the header.)
  const Vec3 c = kOblique.q + 0.3 * kObliqueAxis + 0.1 * cross(kObliqueAxis, kObliquePerp);
  expect_contact<kCapsule>(kOblique, Capsule{c - 0.4 * kObliquePerp, c + 0.4 * kObliquePerp, 0.5}, 0.2, kObliqueAxis,
                           kMpr);
}

TEST(PeerOdeCapsule, Separated) {
  expect_separated<kCapsule>(kZ, Capsule{{2, 0, -1}, {2, 0, 1}, 0.5});
  expect_separated<kCapsule>(
      kOblique, Capsule{kObliqueMid + 1.5 * kObliquePerp, kObliqueMid + 1.5 * kObliquePerp + kObliqueAxis, 0.5});
}

// --- cylinder / box (dCollideCylinderBox) -------------------------------------------

TEST(PeerOdeObb, OnTheCapAndBesideTheSide) {
  // A unit cube 0.25 into the top cap: ODE reports the 4 corners of its
  // bottom face, each 0.25 deep; any of them is in both shapes here.
  expect_contact<kObb>(kZ, Obb{{0, 0, 1.25}, {{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}}, {0.5, 0.5, 0.5}}, 0.25, {0, 0, 1},
                       kNative);
  const Contact c =
      subject_of<kObb>().collide(kZ, Obb{{0, 0, 1.25}, {{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}}, {0.5, 0.5, 0.5}});
  EXPECT_NEAR(c.point.z, 0.75, 1e-12);
  EXPECT_NEAR(std::fabs(c.point.x), 0.5, 1e-12);
  expect_contact<kObb>(kZ, Obb{{1.25, 0, 0}, {{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}}, {0.5, 0.5, 0.5}}, 0.25, {1, 0, 0},
                       kNative);
  expect_contact<kObb>(kZFlipped, Obb{{0, 0, -1.25}, {{{0, 1, 0}, {1, 0, 0}, {0, 0, 1}}}, {0.5, 0.5, 0.5}}, 0.25,
                       {0, 0, -1}, kNative);  // a left-handed frame too
}

TEST(PeerOdeObb, RotatedCylinderAndBox) {
  // A box aligned with kOblique's frame, half extent 0.5 along the axis,
  // its centre 0.25 beyond the q cap: 0.25 deep along +axis.
  const Vec3 e2 = cross(kObliqueAxis, kObliquePerp);
  const Obb box{kOblique.q + 0.25 * kObliqueAxis, {{kObliquePerp, e2, kObliqueAxis}}, {0.3, 0.3, 0.5}};
  expect_contact<kObb>(kOblique, box, 0.25, kObliqueAxis, kBoxRotated);
  const Obb beside{kObliqueMid + 0.75 * kObliquePerp, {{kObliquePerp, e2, kObliqueAxis}}, {0.5, 0.3, 0.3}};
  expect_contact<kObb>(kOblique, beside, 0.25, kObliquePerp, kBoxRotated);
}

TEST(PeerOdeObb, SeparatedAndRefused) {
  const std::array<Vec3, 3> id{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
  expect_separated<kObb>(kZ, Obb{{3, 0, 0}, id, {0.5, 0.5, 0.5}});
  const auto p = peer_ode<kObb>();
  // Sheared axes: not a box ODE can hold.
  const Obb sheared{{0, 0, 1.25}, {{{1, 0, 0}, {0.6, 0.8, 0.1}, {0, 0, 1}}}, {0.5, 0.5, 0.5}};
  EXPECT_FALSE(p.expresses({kZ, sheared}));
  EXPECT_FALSE(p.subject->collide(kZ, sheared).hit);
  // A flat box: ODE's box collider asserts on it; refused, answered no hit.
  const Obb flat{{0, 0, 0.9}, id, {0.5, 0.5, 0}};
  EXPECT_FALSE(p.expresses({kZ, flat}));
  EXPECT_FALSE(p.subject->collide(kZ, flat).hit);
  EXPECT_TRUE(p.expresses({kZ, Obb{{0, 0, 0.9}, id, {0.5, 0.5, 0.5}}}));
  // A subnormal side: ODE asserts on it too; refused.
  EXPECT_FALSE(p.expresses({kZ, Obb{{0, 0, 0.9}, id, {1e-320, 0.5, 0.5}}}));
}

TEST(PeerOdeObb, AnOdeAssertionThrowsInsteadOfAborting) {
  // Positive but tiny extents: expressed, and ODE's box collider trips its
  // assertion !bSafeNormalize3Fault; the adapter's handler turns it into an
  // exception (ODE would abort).
  const Obb tiny{{0, 0, 0.9}, {{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}}, {5e-301, 5e-301, 5e-301}};
  const auto p = peer_ode<kObb>();
  ASSERT_TRUE(p.expresses({kZ, tiny}));
  try {
    (void)p.subject->collide(kZ, tiny);
    ADD_FAILURE() << "ODE answered without its assertion";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("bSafeNormalize3Fault"), std::string::npos) << e.what();
  }
  // ODE still answers afterwards.
  expect_contact<kObb>(kZ, Obb{{1.25, 0, 0}, {{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}}, {0.5, 0.5, 0.5}}, 0.25, {1, 0, 0},
                       kNative);
}

// --- cylinder / triangle (dCollideCylinderTrimesh) -----------------------------------

TEST(PeerOdeTriangle, BothWindingsAreTheSameClosedTriangle) {
  // A horizontal triangle at z = 0.75 across the top of the cylinder: out
  // through the top cap, 0.25, normal +z. ODE's one-sided trimesh answers
  // only one winding of it; the adapter gives ODE both.
  const Triangle up{{-2, -2, 0.75}, {2, -2, 0.75}, {0, 3, 0.75}};
  const Triangle down{{-2, -2, 0.75}, {0, 3, 0.75}, {2, -2, 0.75}};
  expect_contact<kTriangle>(kZ, up, 0.25, {0, 0, 1}, kTrimesh);
  expect_contact<kTriangle>(kZ, down, 0.25, {0, 0, 1}, kTrimesh);
  // A vertical one at x = 0.75: out through the side, 0.25 along +x.
  expect_contact<kTriangle>(kZ, Triangle{{0.75, -2, -2}, {0.75, 2, -2}, {0.75, 0, 3}}, 0.25, {1, 0, 0}, kTrimesh);
  expect_contact<kTriangle>(kZ, Triangle{{0.75, -2, -2}, {0.75, 0, 3}, {0.75, 2, -2}}, 0.25, {1, 0, 0}, kTrimesh);
}

TEST(PeerOdeTriangle, RotatedCylinder) {
  // A triangle in the plane perpendicular to kOblique's axis, 0.2 below the
  // q cap, spanning the whole disc: 0.2 deep along +axis.
  const Vec3 e2 = cross(kObliqueAxis, kObliquePerp);
  const Vec3 c = kOblique.q - 0.2 * kObliqueAxis;
  const Triangle t{c + 2.0 * kObliquePerp, c - kObliquePerp + 2.0 * e2, c - kObliquePerp - 2.0 * e2};
  expect_contact<kTriangle>(kOblique, t, 0.2, kObliqueAxis, kTrimesh);
}

TEST(PeerOdeTriangle, SeparatedAndDegenerate) {
  expect_separated<kTriangle>(kZ, Triangle{{-2, -2, 1.25}, {2, -2, 1.25}, {0, 3, 1.25}});
  const auto p = peer_ode<kTriangle>();
  const Triangle segment{{0.5, 0, -3}, {0.5, 0, 3}, {0.5, 0, 0}};
  EXPECT_FALSE(p.expresses({kZ, segment}));  // no face for ODE
  EXPECT_FALSE(p.subject->overlap(kZ, segment));
}

// --- cylinder / cylinder (dCollideCylinderCylinder: libccd MPR) ------------------------

TEST(PeerOdeCylinder, CoaxialParallelAndCrossed) {
  expect_contact<kCylinder>(kZ, Cylinder{{0, 0, 0.75}, {0, 0, 2.75}, 1.0}, 0.25, {0, 0, 1}, kNative);
  expect_contact<kCylinder>(kZ, Cylinder{{1.75, 0, -1}, {1.75, 0, 1}, 1.0}, 0.25, {1, 0, 0}, kNative);
  expect_contact<kCylinder>(kZ, Cylinder{{-1, 0, 1.75}, {1, 0, 1.75}, 1.0}, 0.25, {0, 0, 1}, kMpr);
  expect_contact<kCylinder>(kZFlipped, Cylinder{{-1, 0, -1.75}, {1, 0, -1.75}, 1.0}, 0.25, {0, 0, -1}, kMpr);
}

TEST(PeerOdeCylinder, RotatedCylinders) {
  // A cylinder across kOblique's q cap (axis kObliquePerp), 0.2 into it, 0.1 off
  // the axis line (on it ODE's MPR misses, as for the capsule).
  const Vec3 c = kOblique.q + 0.3 * kObliqueAxis + 0.1 * cross(kObliqueAxis, kObliquePerp);
  expect_contact<kCylinder>(kOblique, Cylinder{c - kObliquePerp, c + kObliquePerp, 0.5}, 0.2, kObliqueAxis, kMpr);
}

TEST(PeerOdeCylinder, CylindersTooShortForLibccdAreRefused) {
  // ODE's ccdGeomToCyl stops with its fatal error "Invalid cylinder" when
  // half the length is below DBL_EPSILON: refused, answered no hit.
  const Cylinder wafer{{0, 0, 0}, {0, 0, 1e-16}, 0.5};
  const auto p = peer_ode<kCylinder>();
  EXPECT_FALSE(p.expresses({wafer, kZ}));
  EXPECT_FALSE(p.expresses({kZ, wafer}));
  EXPECT_FALSE(p.subject->collide(kZ, wafer).hit);
  EXPECT_FALSE(peer_ode<kCapsule>().expresses({wafer, Capsule{{0, 0, -1}, {0, 0, 1}, 1.0}}));
  // 2^-51 long is taken (half of it is DBL_EPSILON).
  const Cylinder thin{{0, 0, 0}, {0, 0, std::ldexp(1.0, -51)}, 0.5};
  EXPECT_TRUE(p.expresses({thin, kZ}));
  EXPECT_TRUE(p.subject->collide(thin, kZ).hit);
  // The sphere's and the box's colliders are native: no such bound.
  EXPECT_TRUE(peer_ode<kSphere>().expresses({wafer, Sphere{{0, 0, 0}, 1.0}}));
}

TEST(PeerOdeCylinder, Separated) {
  expect_separated<kCylinder>(kZ, Cylinder{{0, 0, 3}, {0, 0, 5}, 1.0});
  expect_separated<kCylinder>(kZ, Cylinder{{-1, 0, 2.5}, {1, 0, 2.5}, 1.0});
}

// --- verify() ------------------------------------------------------------------------------

TEST(PeerOdeVerify, TwoHundredCasesOfCylinderBoxComplete) {
  // The box: ODE's native separating-axis collider, with real
  // disagreements (see the header's "Observed"); a few seconds.
  VerifyOptions opt;
  opt.cases = 200;
  opt.quiet = true;
  opt.report = false;
  opt.max_saved = 2;
  opt.out = std::filesystem::path(::testing::TempDir()) / "geomcheck-peer-ode-verify";
  const VerifyResult r = verify(*peer_ode<kObb>().subject, opt);
  EXPECT_EQ(r.cases, 200);
  // Disagreements are findings, not test failures: printed, not asserted.
  std::printf("ODE collide_cylinder_obb: %d of %d cases failed a property\n", r.failures, r.cases);
  for (const auto& [property, n] : r.by_property) std::printf("  %5d %s\n", n, property.c_str());
  std::error_code ec;
  std::filesystem::remove_all(opt.out, ec);
}

}  // namespace
}  // namespace geomcheck::peers
