// geomcheck — the exact 3D predicates (core/predicates3d.hpp) against
// rationals (exact_signs_3d.hpp), on inputs built to defeat floating point:
// coplanar points on integer planes and rounded onto planes, cospherical
// points (integer points of one sphere: a cube's corners among them), a few
// ulps of jitter, power-of-two scales from 2^-600 to 2^600 per
// configuration and per point (huge beside tiny, subnormals); and the
// determinants' symmetries (a swap flips the sign, a power-of-two scale or
// an exact integer translation keeps it). Each property also counts which
// stage answered and requires both the filter and the exact stage to have
// answered some cases.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <ostream>
#include <vector>

#include "exact_signs_3d.hpp"
#include "point_sets_3d.hpp"
#include "geomcheck/predicates3d.hpp"

namespace {

using geomcheck::Vec3;
using geomcheck::test::ulps;
using Points = std::vector<Vec3>;

/// n points of one kind: "coplanar" (integer points of an integer plane, or
/// points rounded onto a random plane), "cospherical" (integer points of
/// one sphere, centred at an integer point, or a cube's corners), or
/// "random"; then a few ulps of jitter on some, one power-of-two scale for
/// all, sometimes another for each point. At full size whatever the run's
/// size (inRange scales its range by it: a small size drew one kind only).
rc::Gen<Points> degenerate_points(int n) {
  return rc::gen::resize(rc::kNominalSize, rc::gen::exec([n] {
    static const std::vector<Vec3> sphere = geomcheck::test::integer_sphere_points();
    Points pts;
    const int kind = *rc::gen::inRange(0, 5);
    if (kind == 0) {  // an integer plane: z = (u x + v y + w) / s, exactly
      const int u = *rc::gen::inRange(-5, 6), v = *rc::gen::inRange(-5, 6), w = *rc::gen::inRange(-20, 21);
      for (int i = 0; i < n; ++i) {
        const double x = *rc::gen::inRange(-30, 31), y = *rc::gen::inRange(-30, 31);
        pts.push_back({x, y, u * x + v * y + w});
      }
    } else if (kind == 1) {  // a random plane, points rounded onto it
      const Vec3 a{*rc::gen::inRange(-1000, 1001) / 997.0, *rc::gen::inRange(-1000, 1001) / 991.0,
                   *rc::gen::inRange(-1000, 1001) / 983.0};
      const Vec3 e1{*rc::gen::inRange(-1000, 1001) / 977.0, *rc::gen::inRange(-1000, 1001) / 971.0, 1};
      const Vec3 e2{1, *rc::gen::inRange(-1000, 1001) / 967.0, *rc::gen::inRange(-1000, 1001) / 953.0};
      for (int i = 0; i < n; ++i) {
        const double s = *rc::gen::inRange(-1000, 1001) / 947.0, t = *rc::gen::inRange(-1000, 1001) / 941.0;
        pts.push_back(a + s * e1 + t * e2);
      }
    } else if (kind == 2) {  // integer points of one sphere about an integer centre
      const Vec3 c{double(*rc::gen::inRange(-9, 10)), double(*rc::gen::inRange(-9, 10)),
                   double(*rc::gen::inRange(-9, 10))};
      for (int i = 0; i < n; ++i) pts.push_back(c + sphere[*rc::gen::inRange<std::size_t>(0, sphere.size())]);
    } else if (kind == 3) {  // a box's corners (cospherical), on a grid
      const double hx = *rc::gen::inRange(1, 8), hy = *rc::gen::inRange(1, 8), hz = *rc::gen::inRange(1, 8);
      for (int i = 0; i < n; ++i) {
        const int k = *rc::gen::inRange(0, 8);
        pts.push_back({k & 1 ? hx : -hx, k & 2 ? hy : -hy, k & 4 ? hz : -hz});
      }
    } else {
      for (int i = 0; i < n; ++i)
        pts.push_back({*rc::gen::inRange(-100000, 100001) / 1e4, *rc::gen::inRange(-100000, 100001) / 1e4,
                       *rc::gen::inRange(-100000, 100001) / 1e4});
    }
    if (*rc::gen::inRange(0, 3) == 0) {
      for (Vec3& p : pts) {
        if (*rc::gen::inRange(0, 2) == 0) continue;
        p = {ulps(p.x, *rc::gen::inRange(-3, 4)), ulps(p.y, *rc::gen::inRange(-3, 4)), ulps(p.z, *rc::gen::inRange(-3, 4))};
      }
    }
    const int scale = *rc::gen::element(0, 0, -600, 600, -1070, 1000, *rc::gen::inRange(-80, 81));
    const bool mixed = *rc::gen::inRange(0, 6) == 0;
    for (Vec3& p : pts) {
      const int k = mixed ? *rc::gen::inRange(-1000, 1000) : scale;
      p = {std::ldexp(p.x, k), std::ldexp(p.y, k), std::ldexp(p.z, k)};
    }
    return pts;
  }));
}

/// Counts which stage answered over a property's run.
struct Stages {
  long filter = 0, exact = 0;
};
bool filter_answers(const geomcheck::detail::FilterValue& f) {
  return f.usable && (f.value > f.bound || -f.value > f.bound);
}

}  // namespace

namespace geomcheck {

TEST(Predicates3d, OrientAgreesWithRationals) {
  Stages st;
  const bool ok = rc::check("orient3d == the exact sign", [&] {
    const Points p = *degenerate_points(4);
    const int mine = orient3d(p[0], p[1], p[2], p[3]);
    const int exact = test::orient3d_q(p[0], p[1], p[2], p[3]);
    (filter_answers(detail::orient3d_filter(p[0], p[1], p[2], p[3])) ? st.filter : st.exact)++;
    RC_ASSERT(mine == exact);
    RC_ASSERT(detail::orient3d_rational(p[0], p[1], p[2], p[3]) == exact);
  });
  EXPECT_TRUE(ok);
  std::printf("orient3d: %ld answered by the filter, %ld by the exact stage\n", st.filter, st.exact);
  EXPECT_GT(st.filter, 0);
  EXPECT_GT(st.exact, 0);
}

TEST(Predicates3d, InsphereAgreesWithRationals) {
  Stages st;
  const bool ok = rc::check("insphere == the exact sign", [&] {
    const Points p = *degenerate_points(5);
    const int mine = insphere(p[0], p[1], p[2], p[3], p[4]);
    const int exact = test::insphere_q(p[0], p[1], p[2], p[3], p[4]);
    (filter_answers(detail::insphere_filter(p[0], p[1], p[2], p[3], p[4])) ? st.filter : st.exact)++;
    RC_ASSERT(mine == exact);
    RC_ASSERT(detail::insphere_rational(p[0], p[1], p[2], p[3], p[4]) == exact);
  });
  EXPECT_TRUE(ok);
  std::printf("insphere: %ld answered by the filter, %ld by the exact stage\n", st.filter, st.exact);
  EXPECT_GT(st.filter, 0);
  EXPECT_GT(st.exact, 0);
}

// A swap of two points flips both signs; scaling every point by one power
// of two (within range) keeps them, and so does an exact integer
// translation of integer points.
RC_GTEST_PROP(Predicates3d, Symmetries, ()) {
  const Points p = *degenerate_points(5);
  const int o = orient3d(p[0], p[1], p[2], p[3]);
  RC_ASSERT(orient3d(p[1], p[0], p[2], p[3]) == -o);
  RC_ASSERT(orient3d(p[0], p[1], p[3], p[2]) == -o);
  RC_ASSERT(orient3d(p[1], p[2], p[0], p[3]) == o);
  const int s = insphere(p[0], p[1], p[2], p[3], p[4]);
  RC_ASSERT(insphere(p[1], p[0], p[2], p[3], p[4]) == -s);
  RC_ASSERT(insphere(p[0], p[1], p[3], p[2], p[4]) == -s);
  RC_ASSERT(insphere(p[4], p[1], p[2], p[3], p[0]) == -s);
  const int k = *rc::gen::element(-3, 5, 40);
  bool in_range = true;
  Points q = p;
  for (Vec3& x : q) {
    x = {std::ldexp(x.x, k), std::ldexp(x.y, k), std::ldexp(x.z, k)};
    // exact: no overflow, and no bit lost to the subnormals
    for (double v : {x.x, x.y, x.z}) in_range &= std::isfinite(v) && (v == 0 || std::fabs(v) >= 0x1p-1000);
  }
  for (const Vec3& x : p)
    for (double v : {x.x, x.y, x.z}) in_range &= v == 0 || std::fabs(v) >= 0x1p-1000;
  if (in_range) {
    RC_ASSERT(orient3d(q[0], q[1], q[2], q[3]) == o);
    RC_ASSERT(insphere(q[0], q[1], q[2], q[3], q[4]) == s);
  }
}

// The exact stage's fixed-width limbs (core/src/exact_wide.hpp) at every
// width they switch at: cospherical (coplanar) integer points scaled by 2^60
// with one coordinate moved by 2^(64 - s), so that the coordinates span
// about s bits and the sign hangs on the last of them, s from 40 to 140
// (limbs of 4, 6, 8 and 10 words, then the arbitrary-precision integers).
RC_GTEST_PROP(Predicates3d, LimbWidthsAgreeWithRationals, ()) {
  static const std::vector<Vec3> sphere = test::integer_sphere_points();
  const int s = *rc::gen::inRange(40, 141);
  const double nudge = std::ldexp(*rc::gen::element(1.0, -1.0, 3.0), 64 - s);
  Vec3 p[5];
  for (Vec3& v : p) {
    const Vec3 q = sphere[*rc::gen::inRange<std::size_t>(0, sphere.size())];
    v = {std::ldexp(q.x, 60), std::ldexp(q.y, 60), std::ldexp(q.z, 60)};
  }
  const int who = *rc::gen::inRange(0, 5), axis = *rc::gen::inRange(0, 3);
  p[who][axis] += nudge;  // exact for a zero coordinate, rounded (another near-tie) otherwise
  RC_ASSERT(detail::insphere_rational(p[0], p[1], p[2], p[3], p[4]) == test::insphere_q(p[0], p[1], p[2], p[3], p[4]));
  // Coplanar: four points of the plane x + y + z = 2^62, exactly, one moved.
  Vec3 c[4];
  for (Vec3& v : c) {
    const double x = std::ldexp(*rc::gen::inRange(-1000, 1001), 50), y = std::ldexp(*rc::gen::inRange(-1000, 1001), 50);
    v = {x, y, 0x1p62 - x - y};
  }
  c[who % 4][axis] += nudge;
  RC_ASSERT(detail::orient3d_rational(c[0], c[1], c[2], c[3]) == test::orient3d_q(c[0], c[1], c[2], c[3]));
}

// Known answers: every cube's corners are cospherical and each face's four
// coplanar; a point just off (one ulp) decides by the side it moved to.
TEST(Predicates3d, KnownDegenerateAnswers) {
  const Vec3 c[8] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {0, 0, 1}, {1, 0, 1}, {0, 1, 1}, {1, 1, 1}};
  EXPECT_EQ(orient3d(c[0], c[1], c[2], c[3]), 0);
  EXPECT_EQ(orient3d(c[0], c[1], c[2], c[4]), -1);  // (0,0,1) above the counter-clockwise bottom face
  EXPECT_EQ(insphere(c[0], c[1], c[2], c[4], c[7]), 0);
  EXPECT_EQ(orient3d(c[0], c[1], c[2], Vec3{0.5, 0.5, -0x1p-1074}), 1) << "a subnormal below the plane";
  ASSERT_EQ(orient3d(c[0], c[1], c[2], c[4]), -1);
  // Positively oriented tetrahedron: (c0, c2, c1, c4).
  ASSERT_EQ(orient3d(c[0], c[2], c[1], c[4]), 1);
  EXPECT_EQ(insphere(c[0], c[2], c[1], c[4], Vec3{1, 1, ulps(1, -1)}), 1) << "one ulp inside the sphere";
  EXPECT_EQ(insphere(c[0], c[2], c[1], c[4], Vec3{1, 1, ulps(1, 1)}), -1) << "one ulp outside";
  // Huge beside tiny: the cube scaled by 2^1000 with a corner moved by 2^-1074.
  auto big = [](Vec3 v) { return Vec3{std::ldexp(v.x, 1000), std::ldexp(v.y, 1000), std::ldexp(v.z, 1000)}; };
  EXPECT_EQ(insphere(big(c[0]), big(c[2]), big(c[1]), big(c[4]), big(c[7])), 0);
  EXPECT_EQ(orient3d(big(c[0]), big(c[1]), big(c[2]), Vec3{1, 1, 0x1p-1074}), -1);
}

}  // namespace geomcheck
