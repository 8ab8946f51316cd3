// Hand cases with known answers for the FCL peer adapter.
#include <gtest/gtest.h>

#include <cmath>
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

}  // namespace
}  // namespace geomcheck::oracles
