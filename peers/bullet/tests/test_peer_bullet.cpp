// Bullet as a peer: hand cases with known exact answers for every query it
// expresses (the converted normal's direction, the depth's sign, the point),
// and one verify() run that must complete (its failures are printed: they
// are findings, not test failures).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "geomcheck/peers/bullet.hpp"
#include "geomcheck/verify.hpp"

namespace geomcheck {
namespace {

using peers::peer_bullet;

// Bullet's GJK / EPA stop on absolute tolerances: unit scenes come back to
// about 1e-6 in depth and 1e-3 in the normal (hand case: 4e-4 off radial).
constexpr double kDepthTol = 1e-5;
constexpr double kNormalTol = 2e-3;
constexpr double kPointTol = 1e-3;

const Cylinder kUnit{{0, 0, -1}, {0, 0, 1}, 1};  // |z| <= 1, r = 1

void expect_near(Vec3 got, Vec3 want, double tol, const char* what) {
  EXPECT_LE(length(got - want), tol) << what << ": got (" << got.x << ", " << got.y << ", " << got.z << "), want ("
                                     << want.x << ", " << want.y << ", " << want.z << ")";
}

template <QueryId Q>
const ImplOf<Q>& subject_of() {
  const peers::PeerSubject<Q> p = peer_bullet<Q>();
  EXPECT_NE(p.subject, nullptr);
  EXPECT_NE(p.expresses, nullptr);
  return *p.subject;
}

/// A hit with the given depth and normal (from A towards B).
template <QueryId Q, class A, class B>
Contact expect_contact(const A& a, const B& b, double depth, Vec3 normal) {
  const auto& s = subject_of<Q>();
  const Contact c = s.collide(a, b);
  EXPECT_TRUE(c.hit);
  EXPECT_TRUE(s.overlap(a, b));
  EXPECT_GE(c.depth, 0.0);
  EXPECT_NEAR(c.depth, depth, kDepthTol);
  EXPECT_NEAR(length(c.normal), 1.0, 1e-12);
  expect_near(c.normal, normal, kNormalTol, "normal");
  return c;
}

template <QueryId Q, class A, class B>
void expect_no_contact(const A& a, const B& b) {
  const auto& s = subject_of<Q>();
  EXPECT_FALSE(s.collide(a, b).hit);
  EXPECT_FALSE(s.overlap(a, b));
}

TEST(PeerBullet, EveryQueryExpressedWithClaims) {
  for_each_query([](auto q) {
    constexpr QueryId Q = decltype(q)::value;
    const auto p = peer_bullet<Q>();
    ASSERT_NE(p.subject, nullptr) << info(Q).name;
    ASSERT_NE(p.subject->claims, nullptr) << info(Q).name;
    EXPECT_STREQ(p.subject->name, "Bullet");
    EXPECT_FALSE(p.subject->claims->exact_verdict);
    EXPECT_EQ(p.subject->claims->margin, 0.0);
    EXPECT_FALSE(p.subject->claims->touching_is_contact);
    EXPECT_EQ(p.subject->claims->depth,
              info(Q).kind == QueryKind::Collide ? Claims::Depth::Penetration : Claims::Depth::None);
    EXPECT_EQ(std::string(p.engine).rfind("Bullet 3.", 0), 0u) << p.engine;
  });
  EXPECT_STREQ(peer_bullet<QueryId::collide_cylinder_sphere>().engine, "Bullet 3.24 (double precision)");
}

// --- cylinder / sphere --------------------------------------------------------

TEST(PeerBullet, SphereIntoTheSide) {
  // Radius 1 centred 1.5 from the axis: 0.5 deep, normal +x from the cylinder.
  const Contact c =
      expect_contact<QueryId::collide_cylinder_sphere>(kUnit, Sphere{{1.5, 0, 0}, 1}, 0.5, {1, 0, 0});
  // The midpoint of the witness points (1, 0, 0) on the cylinder and (0.5, 0, 0) on the sphere.
  expect_near(c.point, {0.75, 0, 0}, kPointTol, "point");
  // The other side: the normal follows B.
  expect_contact<QueryId::collide_cylinder_sphere>(kUnit, Sphere{{0, -1.5, 0}, 1}, 0.5, {0, -1, 0});
}

TEST(PeerBullet, SphereOnTheCaps) {
  const Contact top =
      expect_contact<QueryId::collide_cylinder_sphere>(kUnit, Sphere{{0, 0, 1.8}, 1}, 0.2, {0, 0, 1});
  expect_near(top.point, {0, 0, 0.9}, 1e-9, "point");
  expect_contact<QueryId::collide_cylinder_sphere>(kUnit, Sphere{{0.3, 0, -1.5}, 1}, 0.5, {0, 0, -1});
}

TEST(PeerBullet, SphereAtTheRimIsExactWithZeroMargin) {
  // With Bullet's default 0.04 margin the rim is rounded (depth 0.2763);
  // the adapter's zero margin gives the sharp rim's 1 - 1/sqrt(2).
  expect_contact<QueryId::collide_cylinder_sphere>(kUnit, Sphere{{1.5, 0, 1.5}, 1}, 1 - std::sqrt(0.5),
                                                   {std::sqrt(0.5), 0, std::sqrt(0.5)});
}

TEST(PeerBullet, SphereCentreInside) {
  // Centre (0.3, 0, 0.1): the side is 0.7 away, the cap 0.9: depth 1.7 along +x.
  expect_contact<QueryId::collide_cylinder_sphere>(kUnit, Sphere{{0.3, 0, 0.1}, 1}, 1.7, {1, 0, 0});
}

TEST(PeerBullet, SphereSeparated) {
  expect_no_contact<QueryId::collide_cylinder_sphere>(kUnit, Sphere{{2.5, 0, 0}, 1});
  expect_no_contact<QueryId::collide_cylinder_sphere>(kUnit, Sphere{{2.01, 0, 0}, 1});
  expect_no_contact<QueryId::collide_cylinder_sphere>(kUnit, Sphere{{0, 0, 2.5}, 1});
}

TEST(PeerBullet, RotatedCylinder) {
  // Axis along (1, 1, 0)/sqrt(2) through the origin, length 4, r = 1; the
  // sphere sits 1.5 from the axis along (0, 0, 1) and along (1, -1, 0)/sqrt(2).
  const double h = std::sqrt(2.0);
  const Cylinder c{{-h, -h, 0}, {h, h, 0}, 1};
  expect_contact<QueryId::collide_cylinder_sphere>(c, Sphere{{0.5, 0.5, 1.5}, 1}, 0.5, {0, 0, 1});
  const Vec3 side{1 / h, -1 / h, 0};
  expect_contact<QueryId::collide_cylinder_sphere>(c, Sphere{1.5 * side, 1}, 0.5, side);
  // Beyond the cap at (h, h, 0): the sphere centre 0.8 further along the axis.
  const Vec3 u{1 / h, 1 / h, 0};
  expect_contact<QueryId::collide_cylinder_sphere>(c, Sphere{(2.0 + 0.8) * u, 1}, 0.2, u);
  expect_no_contact<QueryId::collide_cylinder_sphere>(c, Sphere{(2.0 + 1.5) * u, 1});
}

// --- cylinder / capsule -------------------------------------------------------

TEST(PeerBullet, Capsule) {
  // Parallel to the side, radius 0.5, axis 1.25 from the cylinder's: 0.25 deep along +x.
  expect_contact<QueryId::collide_cylinder_capsule>(kUnit, Capsule{{1.25, 0, -1}, {1.25, 0, 1}, 0.5}, 0.25,
                                                    {1, 0, 0});
  // Standing on the top cap, 0.25 deep.
  expect_contact<QueryId::collide_cylinder_capsule>(kUnit, Capsule{{0, 0, 1.25}, {0, 0, 3.25}, 0.5}, 0.25,
                                                    {0, 0, 1});
  // Lying across the bottom cap: the segment 0.3 below it, radius 0.5.
  expect_contact<QueryId::collide_cylinder_capsule>(kUnit, Capsule{{-0.5, 0.2, -1.3}, {0.5, -0.2, -1.3}, 0.5},
                                                    0.2, {0, 0, -1});
  // A ball (p == q) over the cap.
  expect_contact<QueryId::collide_cylinder_capsule>(kUnit, Capsule{{0, 0, 1.25}, {0, 0, 1.25}, 0.5}, 0.25,
                                                    {0, 0, 1});
  expect_no_contact<QueryId::collide_cylinder_capsule>(kUnit, Capsule{{2, 0, -1}, {2, 0, 1}, 0.5});
}

// --- cylinder / box -------------------------------------------------------------

TEST(PeerBullet, Box) {
  const Obb cube{{0, 0, 1.25}, {{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}}, {0.5, 0.5, 0.5}};
  const Contact c = expect_contact<QueryId::collide_cylinder_obb>(kUnit, cube, 0.25, {0, 0, 1});
  // Witness points (0, 0, 1) and (0, 0, 0.75) (Bullet's choice on the face).
  EXPECT_NEAR(c.point.z, 0.875, 1e-9);
  // Into the side, rotated 45 degrees about z (an edge first): the edge at
  // x = 1.25 - 0.5 sqrt(2) = 0.5429 is 0.4571 inside.
  const double h = std::sqrt(0.5);
  const Obb turned{{1.25, 0, 0}, {{{h, h, 0}, {-h, h, 0}, {0, 0, 1}}}, {0.5, 0.5, 0.5}};
  expect_contact<QueryId::collide_cylinder_obb>(kUnit, turned, 1 - (1.25 - std::sqrt(0.5)), {1, 0, 0});
  // A left-handed frame is the same box.
  const Obb left{{0, 0, 1.25}, {{{1, 0, 0}, {0, 1, 0}, {0, 0, -1}}}, {0.5, 0.5, 0.5}};
  expect_contact<QueryId::collide_cylinder_obb>(kUnit, left, 0.25, {0, 0, 1});
  expect_no_contact<QueryId::collide_cylinder_obb>(
      kUnit, Obb{{0, 0, 1.75}, {{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}}, {0.5, 0.5, 0.5}});
}

TEST(PeerBullet, BoxNotOrthonormalIsNotExpressed) {
  const auto p = peer_bullet<QueryId::collide_cylinder_obb>();
  const Obb sheared{{0, 0, 1.25}, {{{1, 0, 0}, {0.6, 0.8, 0.0001}, {0, 0, 1}}}, {0.5, 0.5, 0.5}};
  EXPECT_FALSE(p.expresses({kUnit, sheared}));
  EXPECT_FALSE(p.subject->collide(kUnit, sheared).hit);
  const Obb cube{{0, 0, 1.25}, {{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}}, {0.5, 0.5, 0.5}};
  EXPECT_TRUE(p.expresses({kUnit, cube}));
}

// --- cylinder / triangle ----------------------------------------------------------

TEST(PeerBullet, Triangle) {
  // A large triangle in the plane z = 0.75 cuts through the cylinder: it
  // leaves through the top cap, 0.25 away.
  expect_contact<QueryId::collide_cylinder_triangle>(kUnit, Triangle{{-3, -3, 0.75}, {6, 0, 0.75}, {0, 6, 0.75}},
                                                     0.25, {0, 0, 1});
  // A small vertical triangle whose vertex is 0.2 inside the side.
  expect_contact<QueryId::collide_cylinder_triangle>(kUnit, Triangle{{0.8, 0, 0}, {2, 0.2, 0}, {2, -0.2, 0}}, 0.2,
                                                     {1, 0, 0});
  // A point triangle 0.2 inside the side.
  expect_contact<QueryId::collide_cylinder_triangle>(kUnit, Triangle{{0.8, 0, 0}, {0.8, 0, 0}, {0.8, 0, 0}}, 0.2,
                                                     {1, 0, 0});
  expect_no_contact<QueryId::collide_cylinder_triangle>(kUnit, Triangle{{1.5, 0, 0}, {3, 1, 0}, {3, -1, 0}});
}

// --- cylinder / cylinder ------------------------------------------------------------

TEST(PeerBullet, Cylinders) {
  // Parallel, side by side: radius 0.5 at 1.25 from the axis, 0.25 deep.
  expect_contact<QueryId::collide_cylinder_cylinder>(kUnit, Cylinder{{1.25, 0, -1}, {1.25, 0, 1}, 0.5}, 0.25,
                                                     {1, 0, 0});
  // Stacked on the top cap, 0.25 deep.
  expect_contact<QueryId::collide_cylinder_cylinder>(kUnit, Cylinder{{0, 0, 0.75}, {0, 0, 2.75}, 0.5}, 0.25,
                                                     {0, 0, 1});
  // Crossed: B along x, radius 0.5, axis 1.25 above the centre: its side
  // reaches 0.25 into the top cap.
  expect_contact<QueryId::collide_cylinder_cylinder>(kUnit, Cylinder{{-2, 0, 1.25}, {2, 0, 1.25}, 0.5}, 0.25,
                                                     {0, 0, 1});
  expect_no_contact<QueryId::collide_cylinder_cylinder>(kUnit, Cylinder{{2, 0, -1}, {2, 0, 1}, 0.5});
}

// --- cast -------------------------------------------------------------------------

TEST(PeerBullet, Cast) {
  const auto& s = subject_of<QueryId::cast_segment_cylinder>();
  // Through the side from +x: t = 1/3 at (1, 0, 0), normal +x.
  CastHit h = s.cast(Segment{{3, 0, 0}, {-3, 0, 0}}, kUnit);
  ASSERT_TRUE(h.hit);
  EXPECT_FALSE(h.starts_inside);
  EXPECT_NEAR(h.t, 1.0 / 3, 1e-9);
  expect_near(h.point, {1, 0, 0}, 1e-9, "point");
  expect_near(h.normal, {1, 0, 0}, 1e-9, "normal");
  // Through the top cap: t = 0.4, normal +z.
  h = s.cast(Segment{{0.2, 0.1, 5}, {0.2, 0.1, -5}}, kUnit);
  ASSERT_TRUE(h.hit);
  EXPECT_NEAR(h.t, 0.4, 1e-9);
  expect_near(h.normal, {0, 0, 1}, 1e-9, "normal");
  // Off centre: t = (3 - sqrt(0.75)) / 3, normal (sqrt(0.75), 0.5, 0).
  h = s.cast(Segment{{3, 0.5, 0.5}, {0, 0.5, 0.5}}, kUnit);
  ASSERT_TRUE(h.hit);
  EXPECT_NEAR(h.t, (3 - std::sqrt(0.75)) / 3, 1e-6);
  expect_near(h.normal, {std::sqrt(0.75), 0.5, 0}, kNormalTol, "normal");
  // Starting inside: t = 0, the start, a zero normal.
  h = s.cast(Segment{{0, 0, 0}, {5, 0, 0}}, kUnit);
  ASSERT_TRUE(h.hit);
  EXPECT_TRUE(h.starts_inside);
  EXPECT_EQ(h.t, 0.0);
  expect_near(h.point, {0, 0, 0}, 0, "point");
  EXPECT_EQ(length(h.normal), 0.0);
  // Misses: beside the cylinder, and stopping short of it.
  EXPECT_FALSE(s.cast(Segment{{3, 2, 0}, {-3, 2, 0}}, kUnit).hit);
  EXPECT_FALSE(s.cast(Segment{{3, 0, 0}, {1.5, 0, 0}}, kUnit).hit);
  // A rotated cylinder: axis (1, 1, 0)/sqrt(2), the ray down -z onto its side.
  const double r2 = std::sqrt(2.0);
  h = s.cast(Segment{{0.5, 0.5, 4}, {0.5, 0.5, -4}}, Cylinder{{-r2, -r2, 0}, {r2, r2, 0}, 1});
  ASSERT_TRUE(h.hit);
  EXPECT_NEAR(h.t, 3.0 / 8, 1e-9);
  expect_near(h.normal, {0, 0, 1}, kNormalTol, "normal");
}

// --- sweep ------------------------------------------------------------------------

TEST(PeerBullet, Sweep) {
  const auto& s = subject_of<QueryId::sweep_sphere_cylinder>();
  // Radius 0.5 from x = 3 to x = -3: touches the side at t = 0.25, at (1, 0, 0).
  CastHit h = s.sweep(MovingSphere{{3, 0, 0}, 0.5, {-6, 0, 0}}, kUnit);
  ASSERT_TRUE(h.hit);
  EXPECT_FALSE(h.starts_inside);
  EXPECT_NEAR(h.t, 0.25, 1e-6);
  expect_near(h.point, {1, 0, 0}, kPointTol, "point");
  expect_near(h.normal, {1, 0, 0}, kNormalTol, "normal");
  // Down onto the top cap: t = 0.35, normal +z.
  h = s.sweep(MovingSphere{{0.2, 0, 5}, 0.5, {0, 0, -10}}, kUnit);
  ASSERT_TRUE(h.hit);
  EXPECT_NEAR(h.t, 0.35, 1e-6);
  expect_near(h.point, {0.2, 0, 1}, kPointTol, "point");
  expect_near(h.normal, {0, 0, 1}, kNormalTol, "normal");
  // Already overlapping, moving away: t = 0, starts_inside, zero normal,
  // the point Bullet's witness on the cylinder, (1, 0, 0), the closest to the centre.
  h = s.sweep(MovingSphere{{1.2, 0, 0}, 0.5, {4, 0, 0}}, kUnit);
  ASSERT_TRUE(h.hit);
  EXPECT_TRUE(h.starts_inside);
  EXPECT_EQ(h.t, 0.0);
  EXPECT_EQ(length(h.normal), 0.0);
  expect_near(h.point, {1, 0, 0}, kPointTol, "point");
  // The centre inside the cylinder: the point is the centre.
  h = s.sweep(MovingSphere{{0.5, 0, 0.2}, 2, {4, 0, 0}}, kUnit);
  ASSERT_TRUE(h.hit);
  EXPECT_TRUE(h.starts_inside);
  expect_near(h.point, {0.5, 0, 0.2}, 0, "point");
  // Misses.
  EXPECT_FALSE(s.sweep(MovingSphere{{3, 3, 0}, 0.5, {-6, 0, 0}}, kUnit).hit);
  EXPECT_FALSE(s.sweep(MovingSphere{{3, 0, 0}, 0.5, {0, 0, 0}}, kUnit).hit);
}

// --- invalid and unexpressible input ---------------------------------------------

TEST(PeerBullet, InvalidInputIsNotExpressedAndNoHit) {
  const Cylinder bad{{0, 0, 0}, {0, 0, 0}, 1};
  const auto p = peer_bullet<QueryId::collide_cylinder_sphere>();
  EXPECT_FALSE(p.expresses({bad, Sphere{{0, 0, 0}, 1}}));
  EXPECT_FALSE(p.subject->collide(bad, Sphere{{0, 0, 0}, 1}).hit);
  EXPECT_FALSE(p.expresses({kUnit, Sphere{{NAN, 0, 0}, 1}}));
  EXPECT_FALSE(p.subject->overlap(kUnit, Sphere{{NAN, 0, 0}, 1}));
  EXPECT_FALSE(p.expresses({kUnit, Sphere{{0, 0, 0}, -1}}));
  // q - p overflows: valid, but Bullet cannot be given its length.
  const Cylinder huge{{-1.7e308, 0, 0}, {1.7e308, 0, 0}, 1};
  EXPECT_TRUE(is_valid(huge));
  EXPECT_FALSE(p.expresses({huge, Sphere{{0, 0, 0}, 1}}));
  EXPECT_FALSE(p.subject->collide(huge, Sphere{{0, 0, 0}, 1}).hit);
  const auto cast = peer_bullet<QueryId::cast_segment_cylinder>();
  EXPECT_FALSE(cast.subject->cast(Segment{{INFINITY, 0, 0}, {0, 0, 0}}, kUnit).hit);
  const auto sweep = peer_bullet<QueryId::sweep_sphere_cylinder>();
  // c + delta overflows: invalid.
  EXPECT_FALSE(sweep.expresses({MovingSphere{{1e308, 0, 0}, 1, {1e308, 0, 0}}, kUnit}));
  EXPECT_FALSE(sweep.subject->sweep(MovingSphere{{1e308, 0, 0}, 1, {1e308, 0, 0}}, kUnit).hit);
}

// --- one verify() run -----------------------------------------------------------

TEST(PeerBullet, VerifyRunCompletes) {
  VerifyOptions opt;
  opt.cases = 200;
  opt.quiet = true;
  opt.report = false;
  opt.out = std::string(::testing::TempDir()) + "geomcheck-peer-bullet";
  const VerifyResult r = verify(*peer_bullet<QueryId::collide_cylinder_sphere>().subject, opt);
  EXPECT_EQ(r.cases, 200);
  std::printf("Bullet collide_cylinder_sphere, %d cases: %d failing\n", r.cases, r.failures);
  for (const auto& [property, n] : r.by_property) std::printf("  %-40s %d\n", property.c_str(), n);
}

// Not run by ctest: every query Bullet expresses, 500 cases each (run with
// --gtest_also_run_disabled_tests --gtest_filter='*Verify500*'); the failure
// counts by property are the figures of Bullet's findings.
TEST(PeerBullet, DISABLED_Verify500EveryQuery) {
  for_each_query([](auto q) {
    constexpr QueryId Q = decltype(q)::value;
    const auto p = peer_bullet<Q>();
    if (!p.subject) return;
    VerifyOptions opt;
    opt.cases = 500;
    opt.quiet = true;
    opt.report = false;
    opt.out = std::string(::testing::TempDir()) + "geomcheck-peer-bullet-500";
    const VerifyResult r = verify<Q>(*p.subject, opt);
    EXPECT_EQ(r.cases, 500);
    std::printf("Bullet %s, %d cases: %d failing\n", info(Q).name, r.cases, r.failures);
    for (const auto& [property, n] : r.by_property) std::printf("  %-40s %d\n", property.c_str(), n);
  });
}

}  // namespace
}  // namespace geomcheck
