// geomcheck — tests of the exact oracles themselves: hand cases with exact
// answers worked out on paper, cross-checks between the two oracles, and
// the certification of square-root brackets.
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "geomcheck/properties/generators.hpp"
#include "geomcheck/oracles/cast_segment_cylinder.hpp"
#include "geomcheck/oracles/cylinder_sphere.hpp"

namespace geomcheck::oracle {
namespace {

const Cylinder kUnit{{0, 0, 0}, {0, 0, 2}, 1};  // radius 1, caps at z = 0 and z = 2

/// The first `count` cases of query Q's targeted generator from seed `seed`
/// (each from the next split of the random stream, at size 50).
template <QueryId Q>
std::vector<typename QueryTraits<Q>::Case> targeted_cases(std::uint64_t seed, int count) {
  const auto gen = gen::targeted<Q>();
  rc::Random random(seed);
  std::vector<typename QueryTraits<Q>::Case> cases;
  for (int i = 0; i < count; ++i) cases.push_back(gen(random.split(), 50).value().first);
  return cases;
}

TEST(oracle_cylinder_sphere, hand_cases) {
  // Beside the side: distance 3 - 1 - 1 = 1, exactly.
  auto t = solve_cylinder_sphere(kUnit, Sphere{{3, 0, 1}, 1});
  EXPECT_EQ(t.verdict, Verdict::Separated);
  EXPECT_TRUE(t.signed_distance.exact());
  EXPECT_EQ(t.signed_distance.lo, Q(1));
  // Centre inside: depth = 0.25 + min(cap gap 0.5, side gap 1) = 0.75.
  t = solve_cylinder_sphere(kUnit, Sphere{{0, 0, 0.5}, 0.25});
  EXPECT_EQ(t.verdict, Verdict::Overlapping);
  EXPECT_TRUE(t.centre_inside);
  EXPECT_EQ(t.signed_distance.lo, Q(-3) / 4);
  // Rim touch from a 3-4-5 triangle: rim point (1,0,2), centre (1+3,0,2+4), radius 5.
  t = solve_cylinder_sphere(kUnit, Sphere{{4, 0, 6}, 5});
  EXPECT_EQ(t.verdict, Verdict::Touching);
  EXPECT_EQ(t.signed_distance.lo, Q(0));
  EXPECT_EQ(solve_cylinder_sphere(kUnit, Sphere{{4, 0, 6}, std::nextafter(5.0, 0.0)}).verdict, Verdict::Separated);
  EXPECT_EQ(solve_cylinder_sphere(kUnit, Sphere{{4, 0, 6}, std::nextafter(5.0, 9.0)}).verdict, Verdict::Overlapping);
  // Capsule-shaped false positive: near the rim diagonal, outside the flat cap.
  // Distance from (1.5, 0, 2.5) to the rim point (1, 0, 2) is sqrt(0.5) ~ 0.7071 > 0.7.
  t = solve_cylinder_sphere(kUnit, Sphere{{1.5, 0, 2.5}, 0.7});
  EXPECT_EQ(t.verdict, Verdict::Separated);
  EXPECT_LT(t.signed_distance.hi, Q(72) / 10000);  // sqrt(0.5) - 0.7 = 0.0071068
  EXPECT_GT(t.signed_distance.lo, Q(71) / 10000);
  // Centre beyond the rim, overlapping deeply (the K <= 0 branch of the sign
  // test): centre (1.5, 0, 2.5), rim point (1, 0, 2), distance sqrt(0.5);
  // with s = 2, K = ea^2 + rho^2 + r^2 - s^2 = 0.25 + 2.25 + 1 - 4 < 0.
  t = solve_cylinder_sphere(kUnit, Sphere{{1.5, 0, 2.5}, 2});
  EXPECT_EQ(t.verdict, Verdict::Overlapping);
  EXPECT_FALSE(t.centre_inside);
  EXPECT_LT(t.signed_distance.hi, Q(-129) / 100);  // sqrt(0.5) - 2 = -1.2929
  EXPECT_GT(t.signed_distance.lo, Q(-130) / 100);
  // Beyond the rim with K > 0 but still overlapping: s = 0.75 > sqrt(0.5).
  EXPECT_EQ(solve_cylinder_sphere(kUnit, Sphere{{1.5, 0, 2.5}, 0.75}).verdict, Verdict::Overlapping);
  // Cap-plane touch and a point on the surface.
  EXPECT_EQ(solve_cylinder_sphere(kUnit, Sphere{{0.5, 0.5, 3}, 1}).verdict, Verdict::Touching);
  EXPECT_EQ(solve_cylinder_sphere(kUnit, Sphere{{0, 1, 1}, 0}).verdict, Verdict::Touching);
  EXPECT_EQ(solve_cylinder_sphere(kUnit, Sphere{{0, 1.0000000000000002, 1}, 0}).verdict, Verdict::Separated);
  // Zero-radius cylinder (a segment).
  EXPECT_EQ(solve_cylinder_sphere(Cylinder{{0, 0, 0}, {0, 0, 2}, 0}, Sphere{{3, 4, 1}, 5}).verdict, Verdict::Touching);
}

TEST(oracle_cylinder_sphere, overlap_along_true_normal_is_the_depth) {
  // Sphere pushing into the top cap by 0.25: depth 0.25 along +z.
  const auto qa = to_q(kUnit);
  const auto qb = to_q(Sphere{{0.2, 0.1, 2.5}, 0.75});
  const auto t = solve_cylinder_sphere(qa, qb);
  EXPECT_EQ(t.signed_distance.lo, Q(-1) / 4);
  const QInterval along = overlap_along(qa, qb, to_q(Vec3{0, 0, 1}));
  EXPECT_EQ(along.lo, Q(1) / 4);
  EXPECT_EQ(along.hi, Q(1) / 4);
  // Any other direction measures more.
  EXPECT_GT(overlap_along(qa, qb, to_q(Vec3{0.1, 0, 1})).lo, Q(1) / 4);
}

TEST(oracle_cast, hand_cases) {
  // Down the axis into the p cap at t = 1/4 (exact).
  auto t = solve_cast(Segment{{0, 0, -1}, {0, 0, 3}}, kUnit);
  ASSERT_TRUE(t.hit);
  EXPECT_EQ(t.feature, CastFeature::CapP);
  EXPECT_EQ(t.t.lo, Q(1) / 4);
  EXPECT_TRUE(t.t.exact());
  // Across the side: enters x = -1 at t = 1/3, a perfect-square root.
  t = solve_cast(Segment{{-3, 0, 1}, {3, 0, 1}}, kUnit);
  ASSERT_TRUE(t.hit);
  EXPECT_EQ(t.feature, CastFeature::Side);
  EXPECT_EQ(t.t.lo, Q(1) / 3);
  EXPECT_EQ(t.t.hi, Q(1) / 3);
  // Irrational root: y = 0.5 line enters at x = -sqrt(3)/2; t = (3 - sqrt(3)/2) / 6.
  t = solve_cast(Segment{{-3, 0.5, 1}, {3, 0.5, 1}}, kUnit);
  ASSERT_TRUE(t.hit);
  EXPECT_FALSE(t.t.exact());
  EXPECT_LT(t.t.hi - t.t.lo, Q(1) / Q(boost::multiprecision::pow(boost::multiprecision::mpz_int(2), 200)));
  const double expect = (3 - std::sqrt(3.0) / 2) / 6;
  EXPECT_NEAR(t.t.mid(), expect, 1e-16);
  // Tangent to the side (x = 1) touches; one ulp further misses.
  EXPECT_TRUE(solve_cast(Segment{{1, -5, 1}, {1, 5, 1}}, kUnit).hit);
  EXPECT_FALSE(solve_cast(Segment{{1.0000000000000002, -5, 1}, {1.0000000000000002, 5, 1}}, kUnit).hit);
  // Starts inside; zero-length outside; the capsule-only corner region.
  EXPECT_EQ(solve_cast(Segment{{0, 0, 1}, {9, 9, 9}}, kUnit).feature, CastFeature::StartInside);
  EXPECT_FALSE(solve_cast(Segment{{0, 0, 3}, {0, 0, 3}}, kUnit).hit);
  EXPECT_FALSE(solve_cast(Segment{{1.2, 0, 2.5}, {2, 0, 2.1}}, kUnit).hit);
  // Enters through the q cap from above although the side root lies before t = 0.
  t = solve_cast(Segment{{0.5, 0, 4}, {0.4, 0, 0}}, kUnit);
  ASSERT_TRUE(t.hit);
  EXPECT_EQ(t.feature, CastFeature::CapQ);
  EXPECT_EQ(t.t.lo, Q(1) / 2);
}

TEST(oracle_cross, point_oracle_agrees_with_zero_length_cast) {
  // A zero-length segment hits iff its point is in the cylinder: the two
  // oracles reach that by different algebra.
  int inside = 0;
  for (const auto& c : targeted_cases<QueryId::collide_cylinder_sphere>(7, 3000)) {
    const Segment s{c.b.c, c.b.c};
    const bool in = signed_distance(to_q(c.a), to_q(c.b.c)).hi <= 0;
    const auto cast = solve_cast(s, c.a);
    ASSERT_EQ(cast.hit, solve_cylinder_sphere(c.a, Sphere{c.b.c, 0}).verdict != Verdict::Separated);
    if (cast.hit) ++inside;
    if (in) {
      ASSERT_TRUE(cast.hit);
    }
  }
  EXPECT_GT(inside, 100);
}

TEST(oracle_cross, cast_t_brackets_the_surface) {
  // At the certified t the segment point is on the surface: the signed
  // distance of S(t_lo) is >= 0 and of S(t_hi) <= 0 (for entries from outside).
  int checked = 0;
  for (const auto& c : targeted_cases<QueryId::cast_segment_cylinder>(11, 2000)) {
    const auto t = solve_cast(c.a, c.b);
    if (!t.hit || t.feature == CastFeature::StartInside) continue;
    const auto qs = to_q(c.a);
    const auto qc = to_q(c.b);
    const QVec at_lo = qs.a + t.t.lo * (qs.b - qs.a);
    const QVec at_hi = qs.a + t.t.hi * (qs.b - qs.a);
    ASSERT_GE(signed_distance(qc, at_lo).hi, Q(0));
    ASSERT_LE(signed_distance(qc, at_hi).lo, Q(0));
    ++checked;
  }
  EXPECT_GT(checked, 200);
}

TEST(oracle_exact, sqrt_bracket_is_certified) {
  for (int i = 1; i < 500; ++i) {
    const Q x = Q(i * 7919 + 13) / Q(i + 3);
    const QInterval s = sqrt_interval(x);
    EXPECT_LE(s.lo * s.lo, x);
    EXPECT_GE(s.hi * s.hi, x);
  }
  EXPECT_TRUE(sqrt_interval(Q(49) / 4).exact());
  EXPECT_EQ(sqrt_interval(Q(49) / 4).lo, Q(7) / 2);
}

TEST(oracle_exact, grown_and_shrunk_cylinders) {
  const auto c = to_q(kUnit);
  const Q delta = Q(1) / 8;
  // A point 1/16 outside the side is in the grown cylinder, not in the original.
  const QVec out{Q(17) / 16, Q(0), Q(1)};
  EXPECT_LE(signed_distance(grown(c, delta), out).hi, Q(0));
  EXPECT_GT(signed_distance(c, out).lo, Q(0));
  // A point 1/16 inside the side is not in the shrunk cylinder.
  const QVec in{Q(15) / 16, Q(0), Q(1)};
  EXPECT_GT(signed_distance(*shrunk(c, delta), in).lo, Q(0));
  EXPECT_FALSE(shrunk(c, Q(2)).has_value());
}

}  // namespace
}  // namespace geomcheck::oracle
