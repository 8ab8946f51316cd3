// Hand cases with known answers for the FCL peer adapter.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

#include "geomcheck/oracles/fcl_adapter.hpp"
#include "geomcheck/oracles/fcl_convert.hpp"

namespace geomcheck::oracles {
namespace {

// Cylinder along z from z = -1 to z = 1, radius 1.
const Cylinder kZ{{0, 0, -1}, {0, 0, 1}, 1.0};
// The same solid with the caps swapped (axis -z): the anti-parallel rotation.
const Cylinder kZFlipped{{0, 0, 1}, {0, 0, -1}, 1.0};
// An oblique cylinder away from the origin: axis (2, 3, 6)/7, length 7.
const Cylinder kOblique{{10, -4, 3}, {12, -1, 9}, 0.5};

TEST(FclConvert, RotationTakesZToAxis) {
  for (Vec3 u : {Vec3{0, 0, 1}, Vec3{0, 0, -1}, Vec3{1, 0, 0}, Vec3{0, -1, 0}, Vec3{2.0 / 7, 3.0 / 7, 6.0 / 7},
                 Vec3{-1e-17, 1e-17, -1}}) {
    const double len = length(u);
    u = (1.0 / len) * u;
    const fcl::Matrix3d r = fcl_rotation_z_to(u);
    EXPECT_NEAR((r * fcl::Vector3d::UnitZ() - fcl::Vector3d(u.x, u.y, u.z)).norm(), 0.0, 1e-15);
    EXPECT_NEAR((r.transpose() * r - fcl::Matrix3d::Identity()).norm(), 0.0, 1e-15);
    EXPECT_NEAR(r.determinant(), 1.0, 1e-15);
  }
}

TEST(FclConvert, CylinderPose) {
  const FclCylinder c(kOblique);
  EXPECT_DOUBLE_EQ(c.shape.lz, 7.0);
  EXPECT_DOUBLE_EQ(c.shape.radius, 0.5);
  EXPECT_NEAR((c.pose.translation() - fcl::Vector3d(11, -2.5, 6)).norm(), 0.0, 1e-14);
  // The cap centres are at -+lz/2 on the local z axis.
  EXPECT_NEAR((c.pose * fcl::Vector3d(0, 0, -3.5) - fcl::Vector3d(10, -4, 3)).norm(), 0.0, 1e-14);
  EXPECT_NEAR((c.pose * fcl::Vector3d(0, 0, 3.5) - fcl::Vector3d(12, -1, 9)).norm(), 0.0, 1e-14);
}

TEST(FclPeer, DistanceSphereAboveCap) {
  // Sphere of radius 0.5 centred 2 above the top cap: distance 1.5.
  for (const Cylinder& c : {kZ, kZFlipped}) {
    const PeerDistance d = fcl_distance(c, Sphere{{0.25, -0.25, 3}, 0.5});
    ASSERT_TRUE(d.ok) << d.error;
    EXPECT_NEAR(d.distance, 1.5, 1e-14);
    EXPECT_NEAR(length(d.p_a - Vec3{0.25, -0.25, 1}), 0.0, 1e-14);
    EXPECT_NEAR(length(d.p_b - Vec3{0.25, -0.25, 2.5}), 0.0, 1e-14);
  }
  // Beside the oblique cylinder: the centre 2 from the side, radius 0.25.
  // Perpendicular to the axis (2,3,6)/7: (3,-2,0)/sqrt(13).
  const Vec3 mid{11, -2.5, 6};
  const Vec3 perp = (1.0 / std::sqrt(13.0)) * Vec3{3, -2, 0};
  const PeerDistance d = fcl_distance(kOblique, Sphere{mid + 2.5 * perp, 0.25});
  ASSERT_TRUE(d.ok) << d.error;
  EXPECT_NEAR(d.distance, 1.75, 1e-13);
}

TEST(FclPeer, DistanceWhenOverlappingIsMinusOne) {
  const PeerDistance d = fcl_distance(kZ, Sphere{{0, 0, 1.2}, 0.5});
  ASSERT_TRUE(d.ok) << d.error;
  EXPECT_EQ(d.distance, -1.0);
}

TEST(FclPeer, OverlapHitMiss) {
  EXPECT_FALSE(fcl_overlap(kZ, Sphere{{0, 0, 3}, 0.5}));
  EXPECT_TRUE(fcl_overlap(kZ, Sphere{{0, 0, 1.25}, 0.5}));
  EXPECT_TRUE(fcl_overlap(kZ, Sphere{{0, 0, 1.5}, 0.5}));    // touching the cap counts
  EXPECT_TRUE(fcl_overlap(kZ, Sphere{{0.1, 0.2, 0}, 0.0}));  // a point inside
  EXPECT_FALSE(fcl_overlap(kZ, Sphere{{1.5, 0, 1.5}, 0.7}));  // near the rim: 0.707 > 0.7
  EXPECT_TRUE(fcl_overlap(kZ, Sphere{{1.5, 0, 1.5}, 0.71}));
}

TEST(FclPeer, CollideDepthAndNormalAboveTopCap) {
  // Sphere above the top cap, penetrating by 0.25: our normal is +z (from
  // the cylinder towards the sphere), also when the caps are swapped.
  for (const Cylinder& c : {kZ, kZFlipped}) {
    const PeerContact k = fcl_collide(c, Sphere{{0.3, 0.1, 1.25}, 0.5});
    ASSERT_TRUE(k.ok) << k.error;
    ASSERT_TRUE(k.hit);
    EXPECT_NEAR(k.depth, 0.25, 1e-14);
    EXPECT_NEAR(length(k.normal - Vec3{0, 0, 1}), 0.0, 1e-14);
  }
  // Below the bottom cap: normal -z.
  const PeerContact k = fcl_collide(kZ, Sphere{{0, 0, -1.4}, 0.5});
  ASSERT_TRUE(k.ok) << k.error;
  ASSERT_TRUE(k.hit);
  EXPECT_NEAR(k.depth, 0.1, 1e-14);
  EXPECT_NEAR(length(k.normal - Vec3{0, 0, -1}), 0.0, 1e-14);
}

TEST(FclPeer, CollideBesideOblique) {
  const Vec3 mid{11, -2.5, 6};
  const Vec3 perp = (1.0 / std::sqrt(13.0)) * Vec3{3, -2, 0};
  const PeerContact k = fcl_collide(kOblique, Sphere{mid + 0.75 * perp, 0.5});
  ASSERT_TRUE(k.ok) << k.error;
  ASSERT_TRUE(k.hit);
  EXPECT_NEAR(k.depth, 0.25, 1e-13);
  EXPECT_NEAR(length(k.normal - perp), 0.0, 1e-13);
}

TEST(FclPeer, CollideCentreInside) {
  // Centre inside, nearer the top cap (gap 0.2) than the side (gap 0.9):
  // FCL pushes out through the top: depth 0.2 + r.
  const PeerContact k = fcl_collide(kZ, Sphere{{0.1, 0, 0.8}, 0.3});
  ASSERT_TRUE(k.ok) << k.error;
  ASSERT_TRUE(k.hit);
  EXPECT_NEAR(k.depth, 0.5, 1e-14);
  EXPECT_NEAR(length(k.normal - Vec3{0, 0, 1}), 0.0, 1e-14);
}

TEST(FclPeer, CollideCentreOnAxisNearerTheSide) {
  // Long thin cylinder, centre on the axis: FCL's side exit is its frame's
  // +x axis, here any_perpendicular((0,0,1)) = (0,1,0).
  const Cylinder thin{{0, 0, -2}, {0, 0, 2}, 0.5};
  const PeerContact k = fcl_collide(thin, Sphere{{0, 0, 0}, 0.25});
  ASSERT_TRUE(k.ok) << k.error;
  ASSERT_TRUE(k.hit);
  EXPECT_NEAR(k.depth, 0.75, 1e-14);
  EXPECT_NEAR(length(k.normal - any_perpendicular(Vec3{0, 0, 1})), 0.0, 1e-14);
}

TEST(FclPeer, ContactPointIsMidOverlap) {
  // Sphere z = 1.8, r = 1 over the top cap z = 1: overlap z in [0.8, 1].
  const PeerContact k = fcl_collide(kZ, Sphere{{0, 0, 1.8}, 1.0});
  ASSERT_TRUE(k.ok) << k.error;
  ASSERT_TRUE(k.hit);
  EXPECT_NEAR(length(k.point - Vec3{0, 0, 0.9}), 0.0, 1e-14);
}

TEST(FclPeer, MissHasNoContact) {
  const PeerContact k = fcl_collide(kZ, Sphere{{0, 0, 3}, 0.5});
  ASSERT_TRUE(k.ok) << k.error;
  EXPECT_FALSE(k.hit);
}

TEST(FclPeer, InvalidInputNeverReachesFcl) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  const Cylinder bad_cyls[] = {{{0, 0, 0}, {0, 0, 0}, 1}, {{0, 0, 0}, {0, 0, 1}, -1}, {{nan, 0, 0}, {0, 0, 1}, 1},
                               {{0, 0, 0}, {0, 0, 1}, inf}};
  for (const Cylinder& c : bad_cyls) {
    const PeerContact k = fcl_collide(c, Sphere{{0, 0, 0}, 1});
    EXPECT_FALSE(k.ok);
    EXPECT_EQ(k.error, "invalid input");
    std::string err;
    EXPECT_FALSE(fcl_overlap(c, Sphere{{0, 0, 0}, 1}, &err));
    EXPECT_EQ(err, "invalid input");
    EXPECT_FALSE(fcl_distance(c, Sphere{{0, 0, 0}, 1}).ok);
    EXPECT_FALSE(fcl_cast(Segment{{0, 0, -5}, {0, 0, 5}}, c).ok);
  }
  EXPECT_FALSE(fcl_collide(kZ, Sphere{{0, 0, 0}, -1}).ok);
  EXPECT_FALSE(fcl_collide(kZ, Sphere{{0, inf, 0}, 1}).ok);
  EXPECT_FALSE(fcl_cast(Segment{{0, 0, nan}, {0, 0, 5}}, kZ).ok);
}

TEST(FclPeer, ExtremeButValidInputDoesNotCrash) {
  // Far from the origin: valid, FCL's closed form copes (or says it did not).
  const Cylinder far{{1e300, 0, 0}, {1e300, 0, 1}, 1};
  const PeerContact k = fcl_collide(far, Sphere{{1e300, 0, 0.5}, 0.1});
  if (k.ok) {
    EXPECT_TRUE(k.hit);
    EXPECT_NEAR(k.depth, 0.6, 1e-12);
  }
  const PeerCast fc = fcl_cast(Segment{{1e300, 0, -5}, {1e300, 0, 5}}, far);
  if (fc.ok) {
    EXPECT_TRUE(fc.hit);
    EXPECT_NEAR(fc.t, 0.5, 1e-4);
  }
  // Huge extent with a squared length that still fits in a double.
  const Cylinder huge{{0, 0, -1e150}, {0, 0, 1e150}, 1e150};
  const PeerContact h = fcl_collide(huge, Sphere{{0, 0, 0}, 1});
  if (h.ok) {
    EXPECT_TRUE(h.hit);
  }
  // The cast refuses sizes whose squares overflow inside FCL.
  const PeerCast hc = fcl_cast(Segment{{0, 0, -5}, {0, 0, 5}}, Cylinder{{0, 0, 0}, {0, 0, 1}, 1e200});
  EXPECT_FALSE(hc.ok);
  EXPECT_EQ(hc.error, "outside FCL's range");
  // Tiny: conservative advancement is scale-free.
  const Cylinder tiny{{0, 0, -1e-150}, {0, 0, 1e-150}, 1e-150};
  ASSERT_TRUE(is_valid(tiny));
  const PeerContact t = fcl_collide(tiny, Sphere{{0, 0, 0}, 0});
  ASSERT_TRUE(t.ok) << t.error;
  EXPECT_TRUE(t.hit);
  const PeerCast tc = fcl_cast(Segment{{0, 0, -1e-149}, {0, 0, 1e-149}}, tiny);
  ASSERT_TRUE(tc.ok) << tc.error;
  EXPECT_TRUE(tc.hit);
  EXPECT_NEAR(tc.t, 0.45, 1e-4);
}

const FclCastMethod kBothMethods[] = {FclCastMethod::kConservativeAdvancement,
                                      FclCastMethod::kConservativeAdvancementOnce};

// Segment crossing the cylinder along z at (0.3, 0.2): enters the top cap
// at t = 0.4 exactly; FCL's first advancement step lands there.
TEST(FclPeer, CastAxisParallel) {
  const Segment s{{0.3, 0.2, 5}, {0.3, 0.2, -5}};
  for (FclCastMethod m : kBothMethods) {
    const PeerCast c = fcl_cast(s, kZ, m);
    ASSERT_TRUE(c.ok) << c.error;
    EXPECT_TRUE(c.supported);
    EXPECT_TRUE(c.hit);
    EXPECT_NEAR(c.t, 0.4, 1e-12);
  }
}

TEST(FclPeer, CastSideHitAndMiss) {
  // Along x at height 0.5, from x = -4 to x = 4: enters the side at x = -1,
  // t = 3/8. Conservative advancement approaches from below, within 1e-4.
  const PeerCast hit = fcl_cast(Segment{{-4, 0, 0.5}, {4, 0, 0.5}}, kZ);
  ASSERT_TRUE(hit.ok) << hit.error;
  EXPECT_TRUE(hit.hit);
  EXPECT_NEAR(hit.t, 0.375, 1e-4);
  EXPECT_LE(hit.t, 0.375 + 1e-15);
  for (FclCastMethod m : kBothMethods) {
    // Passing by at y = 1.5.
    const PeerCast miss = fcl_cast(Segment{{-4, 1.5, 0.5}, {4, 1.5, 0.5}}, kZ, m);
    ASSERT_TRUE(miss.ok) << miss.error;
    EXPECT_FALSE(miss.hit);
    // Stopping short of the cylinder.
    const PeerCast short_of = fcl_cast(Segment{{-4, 0, 0.5}, {-1.5, 0, 0.5}}, kZ, m);
    ASSERT_TRUE(short_of.ok) << short_of.error;
    EXPECT_FALSE(short_of.hit);
  }
  // Oblique cylinder, segment through both cap centres from outside: enters
  // the p cap at t = 1/3.
  const Vec3 p = kOblique.p, d = kOblique.q - kOblique.p;
  const PeerCast through = fcl_cast(Segment{p - 0.5 * d, p + d}, kOblique);
  ASSERT_TRUE(through.ok) << through.error;
  EXPECT_TRUE(through.hit);
  EXPECT_NEAR(through.t, 1.0 / 3, 1e-4);
}

TEST(FclPeer, CastStartInsideAndPoint) {
  for (FclCastMethod m : kBothMethods) {
    const PeerCast in = fcl_cast(Segment{{0, 0, 0}, {0, 0, 5}}, kZ, m);
    ASSERT_TRUE(in.ok) << in.error;
    EXPECT_TRUE(in.hit);
    EXPECT_EQ(in.t, 0.0);
    const PeerCast point_in = fcl_cast(Segment{{0.5, 0, 0}, {0.5, 0, 0}}, kZ, m);
    ASSERT_TRUE(point_in.ok) << point_in.error;
    EXPECT_TRUE(point_in.hit);
    const PeerCast point_out = fcl_cast(Segment{{2, 0, 0}, {2, 0, 0}}, kZ, m);
    ASSERT_TRUE(point_out.ok) << point_out.error;
    EXPECT_FALSE(point_out.hit);
  }
}

// The FCL 0.7 defect documented in fcl_adapter.hpp, on a segment whose
// b - a is negative in every component: FCL asked once misses it; the
// default method finds it (t = 0.138152 by production's cast). If the
// "Once" expectation starts failing, FCL has changed: update the header.
TEST(FclPeer, CastMissedByFclOnceFoundByDefault) {
  const Segment s{{0.21651, 0.0520333, 1.01067}, {-1.6799, -0.530865, 0.933436}};
  const PeerCast once = fcl_cast(s, kZ, FclCastMethod::kConservativeAdvancementOnce);
  ASSERT_TRUE(once.ok) << once.error;
  EXPECT_FALSE(once.hit) << "FCL no longer shows the documented defect";
  const PeerCast found = fcl_cast(s, kZ);
  ASSERT_TRUE(found.ok) << found.error;
  EXPECT_TRUE(found.hit);
  EXPECT_NEAR(found.t, 0.138152, 1e-4);
}

// The second mechanism (zero direction at a rounding-sized distance), on
// a random oblique cylinder.
TEST(FclPeer, CastMissedByFclOnceZeroDirection) {
  const Segment s{{0x1.8bf99ef28dc1ap+1, -0x1.5643a93e811dp-2, 0x1.898293df3da3ap+2},
                  {0x1.510967756c6a5p+2, -0x1.4aa5c597e6cf1p-1, 0x1.19974a850d857p+1}};
  const Cylinder c{{0x1.e73ed06a6de49p+1, 0x1.4a9e9cf9c784p-2, 0x1.aa9aba663a2b6p+1},
                   {0x1.818dd4502c7e3p+1, -0x1.bcde3a871b68cp-1, 0x1.289fd56fd6dc1p+2},
                   0x1.d505711caa2ecp+0};
  const PeerCast once = fcl_cast(s, c, FclCastMethod::kConservativeAdvancementOnce);
  ASSERT_TRUE(once.ok) << once.error;
  EXPECT_FALSE(once.hit) << "FCL no longer shows the documented defect";
  const PeerCast found = fcl_cast(s, c);
  ASSERT_TRUE(found.ok) << found.error;
  EXPECT_TRUE(found.hit);
  EXPECT_NEAR(found.t, 0.195369, 1e-4);
}


// --- cylinder/capsule ---------------------------------------------------------
// FCL runs libccd's MPR here (tolerance 1e-6, absolute): depths and normals
// of these symmetric hand cases are within about 1e-6 (normals on the side
// within 1e-3), not to rounding as for the sphere.

TEST(FclConvert, CapsulePose) {
  const FclCapsule k(Capsule{{10, -4, 3}, {12, -1, 9}, 0.25});
  EXPECT_DOUBLE_EQ(k.shape.lz, 7.0);
  EXPECT_DOUBLE_EQ(k.shape.radius, 0.25);
  EXPECT_NEAR((k.pose * fcl::Vector3d(0, 0, -3.5) - fcl::Vector3d(10, -4, 3)).norm(), 0.0, 1e-14);
  EXPECT_NEAR((k.pose * fcl::Vector3d(0, 0, 3.5) - fcl::Vector3d(12, -1, 9)).norm(), 0.0, 1e-14);
  // p == q: a sphere, still an fcl::Capsuled (lz = 0, identity rotation).
  const FclCapsule s(Capsule{{1, 2, 3}, {1, 2, 3}, 0.5});
  EXPECT_EQ(s.shape.lz, 0.0);
  EXPECT_EQ(s.shape.radius, 0.5);
  EXPECT_TRUE(s.pose.linear().isIdentity());
  EXPECT_EQ(s.pose.translation(), fcl::Vector3d(1, 2, 3));
}

TEST(FclPeerCapsule, CollideAboveCap) {
  // Vertical capsule over the top cap, its lower end 0.25 into the cylinder:
  // normal +z (from the cylinder towards the capsule), with the cylinder's
  // caps swapped and with the capsule's ends swapped too.
  for (const Cylinder& c : {kZ, kZFlipped}) {
    for (const Capsule& k : {Capsule{{0.3, 0.1, 1.25}, {0.3, 0.1, 3}, 0.5}, Capsule{{0.3, 0.1, 3}, {0.3, 0.1, 1.25}, 0.5}}) {
      const PeerContact r = fcl_collide(c, k);
      ASSERT_TRUE(r.ok) << r.error;
      ASSERT_TRUE(r.hit);
      EXPECT_NEAR(r.depth, 0.25, 1e-6);
      EXPECT_NEAR(length(r.normal - Vec3{0, 0, 1}), 0.0, 1e-6);
      EXPECT_NEAR(length(r.normal), 1.0, 1e-12);
    }
  }
  // Lying across the cap: same depth and normal.
  const PeerContact r = fcl_collide(kZ, Capsule{{-0.5, 0.1, 1.25}, {0.5, 0.1, 1.25}, 0.5});
  ASSERT_TRUE(r.ok) << r.error;
  ASSERT_TRUE(r.hit);
  EXPECT_NEAR(r.depth, 0.25, 1e-6);
  EXPECT_NEAR(length(r.normal - Vec3{0, 0, 1}), 0.0, 1e-6);
  // Below the bottom cap: normal -z.
  const PeerContact b = fcl_collide(kZ, Capsule{{0, 0, -1.4}, {0, 0, -3}, 0.5});
  ASSERT_TRUE(b.ok) << b.error;
  ASSERT_TRUE(b.hit);
  EXPECT_NEAR(b.depth, 0.1, 1e-6);
  EXPECT_NEAR(length(b.normal - Vec3{0, 0, -1}), 0.0, 1e-6);
}

TEST(FclPeerCapsule, CollideBesideSide) {
  // Parallel to the axis, 0.25 into the side.
  const PeerContact par = fcl_collide(kZ, Capsule{{1.25, 0, -0.5}, {1.25, 0, 0.5}, 0.5});
  ASSERT_TRUE(par.ok) << par.error;
  ASSERT_TRUE(par.hit);
  EXPECT_NEAR(par.depth, 0.25, 1e-6);
  EXPECT_NEAR(length(par.normal - Vec3{1, 0, 0}), 0.0, 1e-3);
  // Radial, its end 0.25 into the side.
  const PeerContact rad = fcl_collide(kZ, Capsule{{1.25, 0, 0}, {3, 0, 0}, 0.5});
  ASSERT_TRUE(rad.ok) << rad.error;
  ASSERT_TRUE(rad.hit);
  EXPECT_NEAR(rad.depth, 0.25, 1e-6);
  EXPECT_NEAR(length(rad.normal - Vec3{1, 0, 0}), 0.0, 1e-6);
  // The oblique cylinder, a capsule parallel to its axis 0.25 into its side.
  const Vec3 mid{11, -2.5, 6};
  const Vec3 perp = (1.0 / std::sqrt(13.0)) * Vec3{3, -2, 0};
  const Vec3 axis = (1.0 / 7) * Vec3{2, 3, 6};
  const Vec3 centre = mid + 0.5 * perp;
  const PeerContact ob = fcl_collide(kOblique, Capsule{centre - axis, centre + axis, 0.25});
  ASSERT_TRUE(ob.ok) << ob.error;
  ASSERT_TRUE(ob.hit);
  EXPECT_NEAR(ob.depth, 0.25, 1e-6);
  EXPECT_NEAR(length(ob.normal - perp), 0.0, 1e-3);
}

TEST(FclPeerCapsule, CollideDeepIsNotMinimal) {
  // libccd's MPR reports the overlap met along its search ray (from the
  // difference of the centres through the origin), not the minimum. A
  // capsule through the cylinder along x, centred on it: the true depth is
  // 1.2 (out through a cap or the side); the centres coincide, libccd nudges
  // its ray to x and FCL answers the overlap along x, 4.2.
  const PeerContact across = fcl_collide(kZ, Capsule{{-3, 0, 0}, {3, 0, 0}, 0.2});
  ASSERT_TRUE(across.ok) << across.error;
  ASSERT_TRUE(across.hit);
  EXPECT_NEAR(across.depth, 4.2, 1e-6) << "FCL's deep contact changed: update fcl_adapter.hpp";
  EXPECT_NEAR(std::fabs(across.normal.x), 1.0, 1e-6);
  // A short capsule inside, centred: true depth 1.3 (out through the side),
  // FCL more (1.3928...), along a direction that is neither radial nor axial.
  const PeerContact inside = fcl_collide(kZ, Capsule{{0, 0, -0.5}, {0, 0, 0.5}, 0.3});
  ASSERT_TRUE(inside.ok) << inside.error;
  ASSERT_TRUE(inside.hit);
  EXPECT_GT(inside.depth, 1.3 + 0.05);
  EXPECT_LT(inside.depth, 1.8);
}

TEST(FclPeerCapsule, SphereCapsule) {
  // p == q: the ball, as an fcl::Capsuled of length 0.
  const PeerContact hit = fcl_collide(kZ, Capsule{{0.3, 0.1, 1.25}, {0.3, 0.1, 1.25}, 0.5});
  ASSERT_TRUE(hit.ok) << hit.error;
  ASSERT_TRUE(hit.hit);
  EXPECT_NEAR(hit.depth, 0.25, 1e-6);
  EXPECT_NEAR(length(hit.normal - Vec3{0, 0, 1}), 0.0, 1e-6);
  const PeerDistance d = fcl_distance(kZ, Capsule{{0, 0, 2}, {0, 0, 2}, 0.5});
  ASSERT_TRUE(d.ok) << d.error;
  EXPECT_NEAR(d.distance, 0.5, 1e-6);
}

TEST(FclPeerCapsule, Distance) {
  // Separated above the cap by 1.5 and beside the side by 1.75 (GJK,
  // tolerance 1e-6: from above, within about 1e-7 here).
  const PeerDistance above = fcl_distance(kZ, Capsule{{0.25, -0.25, 3}, {0.25, -0.25, 5}, 0.5});
  ASSERT_TRUE(above.ok) << above.error;
  EXPECT_NEAR(above.distance, 1.5, 1e-6);
  EXPECT_GE(above.distance, 1.5);
  EXPECT_NEAR(above.p_a.z, 1.0, 1e-6);
  EXPECT_NEAR(above.p_b.z, 2.5, 1e-6);
  EXPECT_NEAR(length(above.p_a - Vec3{0.25, -0.25, 1}), 0.0, 1e-4);
  const PeerDistance side = fcl_distance(kZ, Capsule{{3, 0, -0.5}, {3, 0, 0.5}, 0.25});
  ASSERT_TRUE(side.ok) << side.error;
  EXPECT_NEAR(side.distance, 1.75, 1e-6);
  EXPECT_NEAR(side.p_a.x, 1.0, 1e-6);
  EXPECT_NEAR(side.p_b.x, 2.75, 1e-6);
  // Overlapping: exactly -1, nearest points zero (as for the sphere).
  const PeerDistance over = fcl_distance(kZ, Capsule{{0, 0, 1.2}, {0, 0, 3}, 0.5});
  ASSERT_TRUE(over.ok) << over.error;
  EXPECT_EQ(over.distance, -1.0);
  EXPECT_EQ(over.p_a, Vec3{});
  EXPECT_EQ(over.p_b, Vec3{});
}

TEST(FclPeerCapsule, TouchingAndTolerance) {
  // Exact touching is "no hit" for MPR (its tolerance is 1e-6, absolute);
  // distance then answers a positive rounding-sized number.
  const PeerContact cap = fcl_collide(kZ, Capsule{{0.3, 0.1, 1.5}, {0.3, 0.1, 3}, 0.5});
  ASSERT_TRUE(cap.ok) << cap.error;
  EXPECT_FALSE(cap.hit);
  EXPECT_FALSE(fcl_overlap(kZ, Capsule{{0.3, 0.1, 1.5}, {0.3, 0.1, 3}, 0.5}));
  // Overlaps of 1e-9 are missed too; 1e-5 is found.
  EXPECT_FALSE(fcl_overlap(kZ, Capsule{{0.3, 0.1, 1.5 - 1e-9}, {0.3, 0.1, 3}, 0.5}));
  EXPECT_TRUE(fcl_overlap(kZ, Capsule{{0.3, 0.1, 1.5 - 1e-5}, {0.3, 0.1, 3}, 0.5}));
  // A radius-0 capsule ending on the cap: MPR's touching contact, depth
  // below CCD_EPS and no direction: accepted with a zero normal.
  const PeerContact seg = fcl_collide(kZ, Capsule{{0.2, 0.1, 1}, {0.2, 0.1, 3}, 0});
  ASSERT_TRUE(seg.ok) << seg.error;
  ASSERT_TRUE(seg.hit);
  EXPECT_LT(seg.depth, 2.3e-16);
  EXPECT_EQ(seg.normal, Vec3{});
}

TEST(FclPeerCapsule, OverlapHitMiss) {
  EXPECT_FALSE(fcl_overlap(kZ, Capsule{{0, 0, 3}, {0, 0, 4}, 0.5}));
  EXPECT_TRUE(fcl_overlap(kZ, Capsule{{0, 0, 1.25}, {0, 0, 4}, 0.5}));
  EXPECT_TRUE(fcl_overlap(kZ, Capsule{{-5, 0, 0.5}, {5, 0, 0.5}, 0}));      // a segment through
  EXPECT_FALSE(fcl_overlap(kZ, Capsule{{1.5, 0, 1.5}, {3, 0, 3}, 0.7}));    // near the rim: 0.707 > 0.7
  EXPECT_TRUE(fcl_overlap(kZ, Capsule{{1.5, 0, 1.5}, {3, 0, 3}, 0.71}));
  const PeerContact miss = fcl_collide(kZ, Capsule{{0, 0, 3}, {0, 0, 4}, 0.5});
  ASSERT_TRUE(miss.ok) << miss.error;
  EXPECT_FALSE(miss.hit);
}

// A scene on which libccd's MPR portal refinement does not terminate (an
// elongated cylinder, axis about 2^18 long, radius 1.2): the adapter gives
// up after its support budget, quickly. If this starts to answer, FCL or
// libccd has changed: update fcl_adapter.hpp.
TEST(FclPeerCapsule, MprBudgetStopsNonTermination) {
  const Cylinder c{{-0x1.f3f5e11123698p+11, -0x1.902fe6f2df17ap+9, -0x1.75063e0a7722ep+8},
                   {-0x1.3a120603fc50ap+18, 0x1.963fe909b89efp+18, -0x1.0b8ad18739039p+14},
                   0x1.3191473a41a5cp+0};
  const Capsule k{{0x1.0c6972a90e86p+17, -0x1.6c0dcb27722a6p+17, 0x1.bad5fafdfa9dbp+12},
                  {-0x1.52aedc96cb7b8p+18, 0x1.b68c8cc0a347ep+18, -0x1.204f67849297ep+14},
                  0x1.52998f31db8e9p-1};
  const auto start = std::chrono::steady_clock::now();
  const PeerContact r = fcl_collide(c, k);
  EXPECT_FALSE(r.ok) << "FCL no longer shows the documented non-termination";
  EXPECT_NE(r.error.find("did not terminate"), std::string::npos) << r.error;
  std::string err;
  EXPECT_FALSE(fcl_overlap(c, k, &err));
  EXPECT_NE(err.find("did not terminate"), std::string::npos) << err;
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 5.0);
  // GJK's distance has iteration caps: it answers (overlapping).
  const PeerDistance d = fcl_distance(c, k);
  ASSERT_TRUE(d.ok) << d.error;
  EXPECT_EQ(d.distance, -1.0);
}

// FCL's capsule support function normalises the search direction; GJK's
// first direction is minus the first Minkowski support point, zero when the
// shapes' support points along x coincide exactly. FCL then computes with
// NaN and aborts the process ("A is not in region 1" assert). Here: a
// vertical capsule touching the side, its lower end at mid-height; the ball
// (p == q) touching the side. The adapter reports not ok instead. If this
// starts to answer ok, FCL has changed: update fcl_adapter.hpp.
TEST(FclPeerCapsule, DistanceZeroDirectionDoesNotAbort) {
  for (const Capsule& k : {Capsule{{1.5, 0, 0}, {1.5, 0, 2}, 0.5}, Capsule{{1.5, 0, 0}, {1.5, 0, 0}, 0.5},
                           Capsule{{1, 0, 0}, {1, 0, 0}, 0}}) {
    const PeerDistance d = fcl_distance(kZ, k);
    EXPECT_FALSE(d.ok) << "FCL no longer shows the documented defect";
    EXPECT_NE(d.error.find("non-finite point"), std::string::npos) << d.error;
    // collide (MPR) copes: exact touching is "no hit".
    const PeerContact c = fcl_collide(kZ, k);
    ASSERT_TRUE(c.ok) << c.error;
    EXPECT_FALSE(c.hit);
  }
  // Far from the origin the Minkowski points round to zero the same way
  // (offset 1e17, shapes of size 1); in a subnormal scene the directions
  // underflow.
  const PeerDistance far = fcl_distance(Cylinder{{1e17, 0, 0}, {1e17, 0, 1}, 1}, Capsule{{1e17, 0, 0.5}, {1e17, 0, 3}, 0.1});
  EXPECT_FALSE(far.ok);
  const PeerDistance sub = fcl_distance(Cylinder{{0, 0, 0}, {0, 0, 4e-320}, 4e-320}, Capsule{{0, 0, 0}, {0, 0, 0}, 0});
  EXPECT_FALSE(sub.ok);
  // Sizes beyond 2^250: GJK's products overflow (NaN, the same assert): refused.
  const PeerDistance huge = fcl_distance(Cylinder{{0, 0, -1e200}, {0, 0, 1e200}, 1e200}, Capsule{{0, 0, 0}, {0, 0, 1}, 1});
  EXPECT_FALSE(huge.ok);
  EXPECT_EQ(huge.error, "outside FCL's range");
}

// Within the budget the adapter's calls are fcl::collide's and
// fcl::distance's, bit for bit.
TEST(FclPeerCapsule, GuardedCallsAreFcls) {
  std::uint64_t state = 12345;
  auto next = [&state] {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    return static_cast<double>(state >> 11) * 0x1.0p-53 * 2 - 1;  // [-1, 1)
  };
  auto vec = [&] { return Vec3{next(), next(), next()}; };
  int hits = 0;
  for (int i = 0; i < 500; ++i) {
    const Cylinder c{4 * vec(), 4 * vec(), 1.0 + next()};
    const Capsule k{2 * vec(), 2 * vec(), 0.5 + 0.5 * next()};
    const PeerContact adapter = fcl_collide(c, k);
    const PeerContact raw = fcl_collide_prepared(FclCylinderCapsule(c, k));
    ASSERT_TRUE(adapter.ok) << adapter.error;
    ASSERT_EQ(adapter.hit, raw.hit) << i;
    EXPECT_EQ(fcl_overlap(c, k), fcl_overlap_prepared(FclCylinderCapsule(c, k))) << i;
    const PeerDistance d = fcl_distance(c, k);
    const PeerDistance d_raw = fcl_distance_prepared(FclCylinderCapsule(c, k));
    ASSERT_TRUE(d.ok) << d.error;
    EXPECT_EQ(std::memcmp(&d.distance, &d_raw.distance, sizeof(double)), 0) << i;
    EXPECT_EQ(d.p_a, d_raw.p_a) << i;
    EXPECT_EQ(d.p_b, d_raw.p_b) << i;
    if (!adapter.hit) continue;
    ++hits;
    EXPECT_EQ(std::memcmp(&adapter.depth, &raw.depth, sizeof(double)), 0) << i;
    EXPECT_EQ(adapter.normal, raw.normal) << i;
    EXPECT_EQ(adapter.point, raw.point) << i;
  }
  EXPECT_GT(hits, 100);
}

TEST(FclPeerCapsule, InvalidInputNeverReachesFcl) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  const Capsule good{{0, 0, 2}, {0, 0, 3}, 0.5};
  const Capsule bad[] = {{{0, 0, 2}, {0, 0, 3}, -0.5}, {{nan, 0, 2}, {0, 0, 3}, 0.5}, {{0, 0, 2}, {0, inf, 3}, 0.5},
                         {{0, 0, 2}, {0, 0, 3}, inf}};
  for (const Capsule& k : bad) {
    const PeerContact r = fcl_collide(kZ, k);
    EXPECT_FALSE(r.ok);
    EXPECT_EQ(r.error, "invalid input");
    std::string err;
    EXPECT_FALSE(fcl_overlap(kZ, k, &err));
    EXPECT_EQ(err, "invalid input");
    EXPECT_FALSE(fcl_distance(kZ, k).ok);
  }
  const Cylinder bad_cyl{{0, 0, 0}, {0, 0, 0}, 1};
  EXPECT_EQ(fcl_collide(bad_cyl, good).error, "invalid input");
  EXPECT_FALSE(fcl_distance(bad_cyl, good).ok);
}

// --- sphere sweep against a cylinder ----------------------------------------

TEST(FclPeerSweep, TowardsCap) {
  // Ball r = 0.5 from z = 5 straight down at (0.3, 0.2): touches the top cap
  // when its centre is at z = 1.5, t = 3.5/10. The first advancement step
  // (closed-form distance 3.5 over a motion of 10) lands there exactly.
  for (FclCastMethod m : kBothMethods) {
    for (const Cylinder& c : {kZ, kZFlipped}) {
      const PeerCast r = fcl_sweep(MovingSphere{{0.3, 0.2, 5}, 0.5, {0, 0, -10}}, c, m);
      ASSERT_TRUE(r.ok) << r.error;
      EXPECT_TRUE(r.supported);
      EXPECT_TRUE(r.hit);
      EXPECT_NEAR(r.t, 0.35, 1e-12);
    }
  }
}

TEST(FclPeerSweep, SideRimAndMiss) {
  // Along x at height 0.5 from x = -4: touches the side at x = -1.5, t = 2.5/8.
  const PeerCast side = fcl_sweep(MovingSphere{{-4, 0, 0.5}, 0.5, {8, 0, 0}}, kZ);
  ASSERT_TRUE(side.ok) << side.error;
  EXPECT_TRUE(side.hit);
  EXPECT_NEAR(side.t, 0.3125, 1e-4);
  EXPECT_LE(side.t, 0.3125 + 1e-15);
  // Aimed at the rim point (1, 0, 1) along (-1, 0, -1) from (3, 0, 3):
  // touches it when the centre is 0.5 from it, t = (2 sqrt 2 - 0.5) / (4 sqrt 2).
  const PeerCast rim = fcl_sweep(MovingSphere{{3, 0, 3}, 0.5, {-4, 0, -4}}, kZ);
  ASSERT_TRUE(rim.ok) << rim.error;
  EXPECT_TRUE(rim.hit);
  const double t_rim = (2 * std::sqrt(2.0) - 0.5) / (4 * std::sqrt(2.0));
  EXPECT_NEAR(rim.t, t_rim, 1e-4);
  EXPECT_LE(rim.t, t_rim + 1e-15);
  for (FclCastMethod m : kBothMethods) {
    // Passing by, 1e-3 away; stopping short.
    const PeerCast by = fcl_sweep(MovingSphere{{-4, 1.501, 0.5}, 0.5, {8, 0, 0}}, kZ, m);
    ASSERT_TRUE(by.ok) << by.error;
    EXPECT_FALSE(by.hit);
    const PeerCast short_of = fcl_sweep(MovingSphere{{-4, 0, 0.5}, 0.5, {2, 0, 0}}, kZ, m);
    ASSERT_TRUE(short_of.ok) << short_of.error;
    EXPECT_FALSE(short_of.hit);
  }
}

TEST(FclPeerSweep, StartsTouchingOrInside) {
  // FCL has no "starts inside": overlapping or touching at t = 0 is a hit
  // at t = 0, whatever the motion.
  for (const MovingSphere& m : {MovingSphere{{0, 0, 0}, 0.5, {0, 0, 5}}, MovingSphere{{0, 0, 1.5}, 0.5, {0, 0, 5}},
                                MovingSphere{{0, 0, 0}, 0.5, {0, 0, 0}}}) {
    const PeerCast r = fcl_sweep(m, kZ);
    ASSERT_TRUE(r.ok) << r.error;
    EXPECT_TRUE(r.hit);
    EXPECT_EQ(r.t, 0.0);
  }
  const PeerCast still = fcl_sweep(MovingSphere{{0, 0, 3}, 0.5, {0, 0, 0}}, kZ);
  ASSERT_TRUE(still.ok) << still.error;
  EXPECT_FALSE(still.hit);
}

TEST(FclPeerSweep, InvalidAndOutOfRange) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double big = std::numeric_limits<double>::max();
  for (const MovingSphere& m : {MovingSphere{{0, 0, 5}, -0.5, {0, 0, -10}}, MovingSphere{{0, 0, nan}, 0.5, {0, 0, -10}},
                                MovingSphere{{0, 0, big}, 0.5, {0, 0, big}}}) {
    const PeerCast r = fcl_sweep(m, kZ);
    EXPECT_FALSE(r.ok);
    EXPECT_EQ(r.error, "invalid input");
  }
  EXPECT_EQ(fcl_sweep(MovingSphere{{0, 0, 5}, 0.5, {0, 0, -10}}, Cylinder{{0, 0, 0}, {0, 0, 0}, 1}).error,
            "invalid input");
  // Sizes whose squares overflow inside FCL's continuous collision: refused.
  const PeerCast huge = fcl_sweep(MovingSphere{{0, 0, 5}, 1e200, {0, 0, -10}}, kZ);
  EXPECT_FALSE(huge.ok);
  EXPECT_EQ(huge.error, "outside FCL's range");
}

}  // namespace
}  // namespace geomcheck::oracles
