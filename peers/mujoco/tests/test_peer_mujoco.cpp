// geomcheck — MuJoCo's peer on hand cases with known answers: the
// converted normal's direction, the depth's sign and size, the point, the
// rotation of a cylinder whose axis is not a coordinate axis, what the
// engine cannot express; and one verify() run that must complete.
#include <gtest/gtest.h>
#include <mujoco/mujoco.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <thread>

#include "geomcheck/peers/mujoco.hpp"
#include "geomcheck/verify.hpp"

namespace geomcheck {
namespace {

using peers::peer_mujoco;

/// MPR refines to 1e-6 (absolute); the hand cases below are symmetric,
/// where it lands within that.
constexpr double kDepthTol = 2e-6;
constexpr double kNormalTol = 1e-6;

/// The unit cylinder: axis z, caps at z = -1 and z = 1, radius 1.
const Cylinder kUnit{{0, 0, -1}, {0, 0, 1}, 1};

const double kS = std::sqrt(0.5);
/// A unit cylinder whose axis is (1, 1, 0) / sqrt 2, centred at (1, 2, 3).
const Vec3 kCentre{1, 2, 3};
const Vec3 kAxis{kS, kS, 0};
const Cylinder kTilted{kCentre - kAxis, kCentre + kAxis, 1};

template <QueryId Q>
const ImplOf<Q>& subject_of() {
  const auto p = peer_mujoco<Q>();
  EXPECT_NE(p.subject, nullptr);
  return *p.subject;
}

void expect_near(const Vec3& got, const Vec3& want, double tol) {
  EXPECT_NEAR(got.x, want.x, tol);
  EXPECT_NEAR(got.y, want.y, tol);
  EXPECT_NEAR(got.z, want.z, tol);
}

/// Inside (or within tol of) the closed cylinder.
bool in_cylinder(const Cylinder& c, const Vec3& x, double tol) {
  const Vec3 d = c.q - c.p;
  const double l = length(d);
  const Vec3 u = (1 / l) * d;
  const double s = dot(x - c.p, u);
  const Vec3 radial = (x - c.p) - s * u;
  return s >= -tol && s <= l + tol && length(radial) <= c.r + tol;
}

// --- what MuJoCo expresses ------------------------------------------------------

TEST(PeerMujoco, ExpressesTheFourCollidesAndTheCastOnly) {
  EXPECT_NE(peer_mujoco<QueryId::collide_cylinder_sphere>().subject, nullptr);
  EXPECT_NE(peer_mujoco<QueryId::collide_cylinder_capsule>().subject, nullptr);
  EXPECT_NE(peer_mujoco<QueryId::collide_cylinder_obb>().subject, nullptr);
  EXPECT_NE(peer_mujoco<QueryId::collide_cylinder_cylinder>().subject, nullptr);
  EXPECT_NE(peer_mujoco<QueryId::cast_segment_cylinder>().subject, nullptr);
  // No flat mesh (the triangle), no continuous collision (the sweep).
  EXPECT_EQ(peer_mujoco<QueryId::collide_cylinder_triangle>().subject, nullptr);
  EXPECT_EQ(peer_mujoco<QueryId::sweep_sphere_cylinder>().subject, nullptr);
}

TEST(PeerMujoco, NamesTheEngineAndItsVersion) {
  EXPECT_EQ(mj_version(), 222);
  EXPECT_STREQ(peer_mujoco<QueryId::collide_cylinder_sphere>().engine, "MuJoCo 2.2.2");
  EXPECT_STREQ(peer_mujoco<QueryId::collide_cylinder_sphere>().subject->name, "MuJoCo");
}

TEST(PeerMujoco, ClaimsAnInexactVerdictAPenetrationDepthAndNoMargin) {
  const Claims& c = *peer_mujoco<QueryId::collide_cylinder_obb>().subject->claims;
  EXPECT_FALSE(c.exact_verdict);
  EXPECT_EQ(c.depth, Claims::Depth::Penetration);
  EXPECT_TRUE(c.point_in_both);
  EXPECT_FALSE(c.touching_is_contact);
  EXPECT_EQ(c.margin, 0.0);
  const Claims& k = *peer_mujoco<QueryId::cast_segment_cylinder>().subject->claims;
  EXPECT_FALSE(k.exact_verdict);
  EXPECT_EQ(k.depth, Claims::Depth::None);
  EXPECT_EQ(k.margin, 0.0);
}

TEST(PeerMujoco, RefusesWhatItsCompilerRefuses) {
  const auto sphere = peer_mujoco<QueryId::collide_cylinder_sphere>();
  EXPECT_TRUE(sphere.expresses({kUnit, {{2, 0, 0}, 1}}));
  EXPECT_FALSE(sphere.expresses({kUnit, {{2, 0, 0}, 0}}));                 // a point
  EXPECT_FALSE(sphere.expresses({{{0, 0, -1}, {0, 0, 1}, 0}, {{2, 0, 0}, 1}}));  // a segment cylinder
  EXPECT_FALSE(sphere.expresses({kUnit, {{NAN, 0, 0}, 1}}));
  const auto capsule = peer_mujoco<QueryId::collide_cylinder_capsule>();
  EXPECT_TRUE(capsule.expresses({kUnit, {{2, 0, 0}, {2, 0, 0}, 1}}));   // a ball: MuJoCo's sphere
  EXPECT_FALSE(capsule.expresses({kUnit, {{2, 0, 0}, {3, 0, 0}, 0}}));  // a segment
  const auto box = peer_mujoco<QueryId::collide_cylinder_obb>();
  Obb b{{0, 0, 3}, {{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}}, {1, 1, 1}};
  EXPECT_TRUE(box.expresses({kUnit, b}));
  Obb left = b;
  left.axes[2] = {0, 0, -1};  // left-handed: the same box
  EXPECT_TRUE(box.expresses({kUnit, left}));
  Obb flat = b;
  flat.e.z = 0;
  EXPECT_FALSE(box.expresses({kUnit, flat}));
  Obb skew = b;
  skew.axes[1] = {0.1, 1, 0};
  EXPECT_FALSE(box.expresses({kUnit, skew}));
  const auto cast = peer_mujoco<QueryId::cast_segment_cylinder>();
  EXPECT_TRUE(cast.expresses({{{0, 0, 5}, {0, 0, 5}}, kUnit}));  // a point segment is a point
}

// --- cylinder / sphere --------------------------------------------------------------

TEST(PeerMujoco, SphereBesideTheSideGetsTheOutwardRadialAndItsDepth) {
  const auto& m = subject_of<QueryId::collide_cylinder_sphere>();
  const Sphere s{{1.5, 0, 0}, 1};  // 0.5 into the side
  const Contact c = m.collide(kUnit, s);
  ASSERT_TRUE(c.hit);
  EXPECT_TRUE(m.overlap(kUnit, s));
  EXPECT_NEAR(c.depth, 0.5, kDepthTol);
  EXPECT_GT(c.depth, 0);
  expect_near(c.normal, {1, 0, 0}, kNormalTol);  // from the cylinder towards the sphere
  expect_near(c.point, {0.75, 0, 0}, 1e-6);      // the middle of the overlap
  EXPECT_TRUE(in_cylinder(kUnit, c.point, 1e-12));
  EXPECT_LE(length(c.point - s.c), s.r);
  // The other side: the normal follows.
  const Contact o = m.collide(kUnit, {{-1.5, 0, 0}, 1});
  ASSERT_TRUE(o.hit);
  expect_near(o.normal, {-1, 0, 0}, kNormalTol);
}

TEST(PeerMujoco, SphereOverEitherCapGetsTheCapAxis) {
  const auto& m = subject_of<QueryId::collide_cylinder_sphere>();
  const Contact top = m.collide(kUnit, {{0, 0, 1.8}, 1});
  ASSERT_TRUE(top.hit);
  EXPECT_NEAR(top.depth, 0.2, kDepthTol);
  expect_near(top.normal, {0, 0, 1}, kNormalTol);
  expect_near(top.point, {0, 0, 0.9}, 1e-6);
  const Contact bottom = m.collide(kUnit, {{0.25, 0, -1.8}, 1});
  ASSERT_TRUE(bottom.hit);
  EXPECT_NEAR(bottom.depth, 0.2, kDepthTol);
  // Off the axis the normal is the sphere's (mjc_fixNormal): from its centre
  // to MPR's contact point, whose lateral position MPR leaves about 1e-4 off.
  expect_near(bottom.normal, {0, 0, -1}, 1e-3);
}

// A defect of MuJoCo 2.2.2, pinned (the header's "Conventions", Normal):
// 0.5 deep into a cap, the contact point (the middle of the overlap, 0.25
// inside the cap) is not 4x nearer the cap's plane than the curved side, so
// mjc_fixNormal takes the cylinder's normal for radial; on the axis the
// radial direction is the zero vector, which mju_normalize3 turns into the
// local x axis, and the average with the sphere's (right) normal comes out
// 45 degrees off. The depth is right.
TEST(PeerMujoco, DeepCapContactOnTheAxisGetsAFortyFiveDegreeNormal) {
  const auto& m = subject_of<QueryId::collide_cylinder_sphere>();
  const Contact c = m.collide(kUnit, {{0, 0, 1.5}, 1});
  ASSERT_TRUE(c.hit);
  EXPECT_NEAR(c.depth, 0.5, kDepthTol);
  // The true normal is (0, 0, 1); MuJoCo's: (x + z) / sqrt 2, x being the
  // cylinder frame's local x axis (any_perpendicular of z: (0, 1, 0) x ...).
  const Vec3 x = any_perpendicular({0, 0, 1});
  expect_near(c.normal, kS * (x + Vec3{0, 0, 1}), kNormalTol);
}

TEST(PeerMujoco, SeparatedAndTouchingSpheresAreNoContact) {
  const auto& m = subject_of<QueryId::collide_cylinder_sphere>();
  const Contact far = m.collide(kUnit, {{3, 0, 0}, 1});
  EXPECT_FALSE(far.hit);
  EXPECT_FALSE(m.overlap(kUnit, {{3, 0, 0}, 1}));
  EXPECT_EQ(far.depth, 0);
  // Exact touching: MPR's zero direction, dropped by MuJoCo.
  EXPECT_FALSE(m.collide(kUnit, {{0, 0, 2}, 1}).hit);
  EXPECT_FALSE(m.collide(kUnit, {{2, 0, 0}, 1}).hit);
}

TEST(PeerMujoco, TiltedCylinderIsRotatedIntoMujocosFrame) {
  const auto& m = subject_of<QueryId::collide_cylinder_sphere>();
  // 0.2 beyond the q cap along the axis.
  const Contact cap = m.collide(kTilted, {kCentre + 1.8 * kAxis, 1});
  ASSERT_TRUE(cap.hit);
  EXPECT_NEAR(cap.depth, 0.2, kDepthTol);
  expect_near(cap.normal, kAxis, kNormalTol);
  expect_near(cap.point, kCentre + 0.9 * kAxis, 1e-6);
  // 0.5 into the side, along z (perpendicular to the axis).
  const Contact side = m.collide(kTilted, {kCentre + Vec3{0, 0, 1.5}, 1});
  ASSERT_TRUE(side.hit);
  EXPECT_NEAR(side.depth, 0.5, kDepthTol);
  expect_near(side.normal, {0, 0, 1}, kNormalTol);
  // Swapping the caps is the same solid.
  const Cylinder swapped{kTilted.q, kTilted.p, 1};
  const Contact again = m.collide(swapped, {kCentre + Vec3{0, 0, 1.5}, 1});
  ASSERT_TRUE(again.hit);
  EXPECT_NEAR(again.depth, 0.5, kDepthTol);
  expect_near(again.normal, {0, 0, 1}, kNormalTol);
}

// --- cylinder / capsule -----------------------------------------------------------

TEST(PeerMujoco, CapsuleContactsPointFromTheCylinderTowardsTheCapsule) {
  const auto& m = subject_of<QueryId::collide_cylinder_capsule>();
  // Parallel to the axis, 0.5 into the side.
  const Contact side = m.collide(kUnit, {{1.5, 0, -0.5}, {1.5, 0, 0.5}, 1});
  ASSERT_TRUE(side.hit);
  EXPECT_NEAR(side.depth, 0.5, kDepthTol);
  expect_near(side.normal, {1, 0, 0}, kNormalTol);
  EXPECT_TRUE(in_cylinder(kUnit, side.point, 1e-9));
  // Lying over the top cap, 0.25 into it.
  const Capsule over{{-0.5, 0, 1.5}, {0.5, 0, 1.5}, 0.75};
  const Contact top = m.collide(kUnit, over);
  ASSERT_TRUE(top.hit);
  EXPECT_NEAR(top.depth, 0.25, kDepthTol);
  expect_near(top.normal, {0, 0, 1}, kNormalTol);
  // Under the bottom cap.
  const Contact bottom = m.collide(kUnit, {{-0.5, 0, -1.5}, {0.5, 0, -1.5}, 0.75});
  ASSERT_TRUE(bottom.hit);
  expect_near(bottom.normal, {0, 0, -1}, kNormalTol);
  // A ball (p == q) is MuJoCo's sphere.
  const Contact ball = m.collide(kUnit, {{1.5, 0, 0}, {1.5, 0, 0}, 1});
  ASSERT_TRUE(ball.hit);
  EXPECT_NEAR(ball.depth, 0.5, kDepthTol);
  expect_near(ball.normal, {1, 0, 0}, kNormalTol);
  EXPECT_FALSE(m.collide(kUnit, {{3, 0, -0.5}, {3, 0, 0.5}, 1}).hit);
  // The tilted cylinder, a capsule beyond its q cap along the axis.
  const Contact tilted = m.collide(kTilted, {kCentre + 1.5 * kAxis, kCentre + 3.0 * kAxis, 0.75});
  ASSERT_TRUE(tilted.hit);
  EXPECT_NEAR(tilted.depth, 0.25, kDepthTol);
  expect_near(tilted.normal, kAxis, kNormalTol);
}

// --- cylinder / box -------------------------------------------------------------------

TEST(PeerMujoco, BoxContactsKeepMujocosNormal) {
  const auto& m = subject_of<QueryId::collide_cylinder_obb>();
  // A unit box 0.25 into the top cap: MuJoCo's geom 1 is the cylinder.
  const Obb over{{0, 0, 1.75}, {{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}}, {1, 1, 1}};
  const Contact top = m.collide(kUnit, over);
  ASSERT_TRUE(top.hit);
  EXPECT_NEAR(top.depth, 0.25, kDepthTol);
  expect_near(top.normal, {0, 0, 1}, kNormalTol);
  expect_near(top.point, {0, 0, 0.875}, 1e-6);
  // Beside the side, 0.25 into it.
  const Obb side{{1.75, 0, 0}, {{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}}, {1, 0.5, 0.5}};
  const Contact s = m.collide(kUnit, side);
  ASSERT_TRUE(s.hit);
  EXPECT_NEAR(s.depth, 0.25, kDepthTol);
  expect_near(s.normal, {1, 0, 0}, kNormalTol);
  // Left-handed frame: the same box, the same answer.
  Obb left = over;
  left.axes[2] = {0, 0, -1};
  const Contact l = m.collide(kUnit, left);
  ASSERT_TRUE(l.hit);
  EXPECT_NEAR(l.depth, 0.25, kDepthTol);
  expect_near(l.normal, {0, 0, 1}, kNormalTol);
  // Under the bottom cap of the tilted cylinder, the box rotated with it.
  const Vec3 y{-kS, kS, 0};
  const Obb tilted{kCentre - 1.75 * kAxis, {{kAxis, y, {0, 0, 1}}}, {1, 1, 1}};
  const Contact t = m.collide(kTilted, tilted);
  ASSERT_TRUE(t.hit);
  EXPECT_NEAR(t.depth, 0.25, kDepthTol);
  expect_near(t.normal, -1.0 * kAxis, kNormalTol);
  EXPECT_FALSE(m.collide(kUnit, {{0, 0, 2.5}, {{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}}, {1, 1, 1}}).hit);
}

// --- cylinder / cylinder ---------------------------------------------------------------

TEST(PeerMujoco, CylinderPairsPointFromTheFirstTowardsTheSecond) {
  const auto& m = subject_of<QueryId::collide_cylinder_cylinder>();
  const Cylinder above{{0, 0, 0.75}, {0, 0, 3}, 1};
  const Contact top = m.collide(kUnit, above);
  ASSERT_TRUE(top.hit);
  EXPECT_NEAR(top.depth, 0.25, kDepthTol);
  expect_near(top.normal, {0, 0, 1}, kNormalTol);
  // The arguments swapped: the normal flips.
  const Contact swapped = m.collide(above, kUnit);
  ASSERT_TRUE(swapped.hit);
  EXPECT_NEAR(swapped.depth, 0.25, kDepthTol);
  expect_near(swapped.normal, {0, 0, -1}, kNormalTol);
  // Side by side, parallel, 0.5 apart in depth.
  const Contact side = m.collide(kUnit, {{1.5, 0, -1}, {1.5, 0, 1}, 1});
  ASSERT_TRUE(side.hit);
  EXPECT_NEAR(side.depth, 0.5, kDepthTol);
  expect_near(side.normal, {1, 0, 0}, kNormalTol);
  EXPECT_TRUE(in_cylinder(kUnit, side.point, 1e-9));
  // Tilted, a coaxial neighbour beyond the p cap.
  const Contact t = m.collide(kTilted, {kCentre - 0.75 * kAxis, kCentre - 3.0 * kAxis, 1});
  ASSERT_TRUE(t.hit);
  EXPECT_NEAR(t.depth, 0.25, kDepthTol);
  expect_near(t.normal, -1.0 * kAxis, kNormalTol);
  EXPECT_FALSE(m.collide(kUnit, {{3, 0, -1}, {3, 0, 1}, 1}).hit);
}

// --- cast ---------------------------------------------------------------------------------

TEST(PeerMujoco, CastHitsTheCapAndTheSideFirst) {
  const auto& m = subject_of<QueryId::cast_segment_cylinder>();
  const CastHit cap = m.cast({{0.5, 0, 5}, {0.5, 0, -5}}, kUnit);
  ASSERT_TRUE(cap.hit);
  EXPECT_FALSE(cap.starts_inside);
  EXPECT_NEAR(cap.t, 0.4, 1e-15);
  expect_near(cap.point, {0.5, 0, 1}, 1e-14);
  expect_near(cap.normal, {0, 0, 1}, 1e-15);
  const CastHit side = m.cast({{5, 0, 0.5}, {-5, 0, 0.5}}, kUnit);
  ASSERT_TRUE(side.hit);
  EXPECT_NEAR(side.t, 0.4, 1e-15);
  expect_near(side.point, {1, 0, 0.5}, 1e-14);
  expect_near(side.normal, {1, 0, 0}, 1e-15);
  const CastHit bottom = m.cast({{0, 0.5, -3}, {0, 0.5, 1}}, kUnit);
  ASSERT_TRUE(bottom.hit);
  EXPECT_NEAR(bottom.t, 0.5, 1e-15);
  expect_near(bottom.normal, {0, 0, -1}, 1e-15);
}

TEST(PeerMujoco, CastStartingInsideIsTZero) {
  const auto& m = subject_of<QueryId::cast_segment_cylinder>();
  // mju_rayGeom alone would return the exit (x = 1 here).
  const CastHit in = m.cast({{0, 0, 0}, {5, 0, 0}}, kUnit);
  ASSERT_TRUE(in.hit);
  EXPECT_TRUE(in.starts_inside);
  EXPECT_EQ(in.t, 0);
  expect_near(in.point, {0, 0, 0}, 0);
  expect_near(in.normal, {0, 0, 0}, 0);
  // A point segment inside, and one outside.
  EXPECT_TRUE(m.cast({{0.5, 0.5, 0.5}, {0.5, 0.5, 0.5}}, kUnit).starts_inside);
  EXPECT_FALSE(m.cast({{0.5, 0.5, 1.5}, {0.5, 0.5, 1.5}}, kUnit).hit);
  // Starting on the cap, leaving it: touching counts (closed solid).
  EXPECT_TRUE(m.cast({{0, 0, 1}, {0, 0, 5}}, kUnit).starts_inside);
}

TEST(PeerMujoco, CastMissesShortAndPassingSegments) {
  const auto& m = subject_of<QueryId::cast_segment_cylinder>();
  EXPECT_FALSE(m.cast({{0, 0, 5}, {0, 0, 2}}, kUnit).hit);   // stops short
  EXPECT_FALSE(m.cast({{5, 5, 5}, {6, 6, 6}}, kUnit).hit);   // points away
  EXPECT_FALSE(m.cast({{2, -5, 0}, {2, 5, 0}}, kUnit).hit);  // passes by
  // Ending exactly on the cap: t = 1.
  const CastHit end = m.cast({{0, 0, 3}, {0, 0, 1}}, kUnit);
  ASSERT_TRUE(end.hit);
  EXPECT_EQ(end.t, 1);
}

TEST(PeerMujoco, CastAgainstTheTiltedCylinder) {
  const auto& m = subject_of<QueryId::cast_segment_cylinder>();
  // Along the axis towards the q cap, from 3 beyond it: t = 2/4.
  const CastHit cap = m.cast({kCentre + 3.0 * kAxis, kCentre - 1.0 * kAxis}, kTilted);
  ASSERT_TRUE(cap.hit);
  EXPECT_NEAR(cap.t, 0.5, 1e-14);
  expect_near(cap.normal, kAxis, 1e-14);
  expect_near(cap.point, kCentre + kAxis, 1e-14);
  // Down z onto the side: hits 1 above the centre.
  const CastHit side = m.cast({kCentre + Vec3{0, 0, 4}, kCentre}, kTilted);
  ASSERT_TRUE(side.hit);
  EXPECT_NEAR(side.t, 0.75, 1e-14);
  expect_near(side.normal, {0, 0, 1}, 1e-14);
}

// --- MuJoCo's absolute thresholds and rounding gaps, pinned ----------------------

// MPR refines until the depth improves by less than mpr_tolerance = 1e-6,
// in units of length: a scene 1e-6 across stops at MPR's first portals. The
// same sphere over the cap, the scene scaled by 1e-6: depth 0.908 instead
// of 0.2 (times the scale), the normal 19 degrees off. Scaled by 1e3 it is
// right.
TEST(PeerMujoco, MprToleranceIsAbsoluteSoTinyScenesGetCoarseContacts) {
  const auto& m = subject_of<QueryId::collide_cylinder_sphere>();
  auto scaled = [&](double k) {
    const Contact c = m.collide({{0, 0, -k}, {0, 0, k}, k}, {{0.25 * k, 0, 1.8 * k}, k});
    EXPECT_TRUE(c.hit);
    return c;
  };
  const Contact tiny = scaled(1e-6), big = scaled(1e3);
  EXPECT_GT(tiny.depth / 1e-6, 0.9);  // true: 0.2
  EXPECT_LT(tiny.normal.z, 0.95);     // true: 1
  EXPECT_NEAR(big.depth / 1e3, 0.2, 1e-9);
  EXPECT_NEAR(big.normal.z, 1, 1e-9);
}

// mju_rayGeom needs the side's discriminant to reach mjMINVAL = 1e-15 (with
// a unit direction: the square of the half chord, in units of length): a
// ray 0.999 r off the axis of a cylinder of radius 1e-9 (a chord of 9e-11)
// misses; the same ray scaled by 1e3 hits.
TEST(PeerMujoco, RayDiscriminantThresholdIsAbsolute) {
  const auto& m = subject_of<QueryId::cast_segment_cylinder>();
  auto scaled = [&](double k) {
    return m.cast({{5 * k, 0.999 * k, 0}, {-5 * k, 0.999 * k, 0}}, {{0, 0, -k}, {0, 0, k}, k});
  };
  EXPECT_FALSE(scaled(1e-9).hit);
  const CastHit h = scaled(1e-6);
  ASSERT_TRUE(h.hit);
  EXPECT_NEAR(h.t, (5 - std::sqrt(1 - 0.999 * 0.999)) / 10, 1e-12);
}

// A ray entering the q cap at its rim (found by verify(), case 125 of
// cast_segment_cylinder, seed 20261121): in the cylinder's frame the hit
// point rounds outside the cap's disk (p0^2 + p1^2 > r^2) and outside the
// side's slab (|z| > h), so mju_rayGeom misses it (the gap of Ericson's
// printed test, cast_segment_cylinder.hpp); the segment reversed starts
// inside.
TEST(PeerMujoco, RayMissesARimHitThroughRounding) {
  const auto& m = subject_of<QueryId::cast_segment_cylinder>();
  const Segment s{{-0x1.ab105f82ee6e8p+0, -0x1.5c58599a380fdp-1, 0x1.41a965b1d5eb6p+3},
                  {-0x1.075f6aa24127cp+1, 0x1.77cef557b3844p-3, 0x1.9919a49a34eb8p+1}};
  const Cylinder c{{0x1.7820688a189cp-3, -0x1.06137703bf28p-5, 0x1.2af54c1ce20ap+0},
                   {-0x1.7b3dbdbf7ed37p+1, 0x1.a59a66d0b837ep-4, 0x1.097cc64ba81d3p+2},
                   0x1.803594582342cp+0};
  EXPECT_FALSE(m.cast(s, c).hit);  // true: a hit of the q cap at t = 0.7027
  EXPECT_TRUE(m.cast({s.b, s.a}, c).starts_inside);
}

// --- threads, and verify() ------------------------------------------------------------

TEST(PeerMujoco, ThreadsGetTheirOwnModel) {
  const auto& m = subject_of<QueryId::collide_cylinder_sphere>();
  double depth[2] = {0, 0};
  auto run = [&](int k) {
    for (int i = 0; i < 2000; ++i) depth[k] = m.collide(kUnit, {{1.5 + 0.1 * k, 0, 0}, 1}).depth;
  };
  std::thread t0(run, 0), t1(run, 1);
  t0.join();
  t1.join();
  EXPECT_NEAR(depth[0], 0.5, kDepthTol);
  EXPECT_NEAR(depth[1], 0.4, kDepthTol);
}

TEST(PeerMujoco, VerifyCompletesOnTheSphereQuery) {
  VerifyOptions opt;
  opt.cases = 200;
  opt.quiet = true;
  opt.report = false;
  opt.out = std::filesystem::path(::testing::TempDir()) / "geomcheck-peer-mujoco";
  opt.program = "test_peer_mujoco";
  const VerifyResult r = verify(*peer_mujoco<QueryId::collide_cylinder_sphere>().subject, opt);
  EXPECT_EQ(r.cases, 200);
  // Engines disagree with the truth for real: reported, not asserted.
  std::printf("MuJoCo, collide_cylinder_sphere, %d cases: %d failing\n", r.cases, r.failures);
  for (const auto& [property, n] : r.by_property) std::printf("  %-40s %d\n", property.c_str(), n);
}

}  // namespace
}  // namespace geomcheck
