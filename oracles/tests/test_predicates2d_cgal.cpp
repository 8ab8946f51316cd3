// geomcheck — the exact 2D predicates (core/predicates2d.hpp) against CGAL's
// exact predicates (Epick: interval filter, exact fallback), and the two
// exact stages (expansions, rationals) against each other, on inputs built
// to defeat floating point: near-collinear and near-cocircular points a few
// ulps off, integer grids, and magnitudes from 1e-300 to 1e300 mixed.
// CGAL-heavy code stays in this one translation unit.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <ostream>
#include <vector>

#include "geomcheck/predicates2d.hpp"

namespace geomcheck {
// Counterexamples print bit-exact (hex floats).
inline void showValue(const Vec2& p, std::ostream& os) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "(%a, %a)", p.x, p.y);
  os << buf;
}
}  // namespace geomcheck

namespace {

using geomcheck::Vec2;
using K = CGAL::Exact_predicates_inexact_constructions_kernel;

int cgal_orient(Vec2 a, Vec2 b, Vec2 c) {
  return static_cast<int>(CGAL::orientation(K::Point_2(a.x, a.y), K::Point_2(b.x, b.y), K::Point_2(c.x, c.y)));
}
int cgal_incircle(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
  return static_cast<int>(CGAL::side_of_oriented_circle(K::Point_2(a.x, a.y), K::Point_2(b.x, b.y),
                                                        K::Point_2(c.x, c.y), K::Point_2(d.x, d.y)));
}

double ulps(double x, int k) {
  for (; k > 0; --k) x = std::nextafter(x, INFINITY);
  for (; k < 0; ++k) x = std::nextafter(x, -INFINITY);
  return x;
}

// A point moved by a few ulps in each coordinate.
rc::Gen<Vec2> jitter(Vec2 p) {
  return rc::gen::map(rc::gen::pair(rc::gen::inRange(-3, 4), rc::gen::inRange(-3, 4)),
                      [p](std::pair<int, int> k) { return Vec2{ulps(p.x, k.first), ulps(p.y, k.second)}; });
}

// Near-degenerate configurations: collinear (a point rounded onto a line),
// cocircular (a Pythagorean circle), grid points; then a few ulps of jitter,
// a power-of-two scale per configuration, sometimes a different scale per
// point (mixes of huge and tiny).
// At full size whatever the run's size: inRange scales its range by the
// size, and at this suite's max_size 50 it drew neither "anywhere" points
// nor per-point scales above 1.
rc::Gen<std::vector<Vec2>> degenerate_points(int n) {
  return rc::gen::resize(rc::kNominalSize, rc::gen::exec([n] {
    std::vector<Vec2> pts;
    const int kind = *rc::gen::inRange(0, 4);
    const Vec2 a{*rc::gen::inRange(-1000, 1000) / 7.0, *rc::gen::inRange(-1000, 1000) / 3.0};
    const Vec2 b{*rc::gen::inRange(-1000, 1000) / 5.0, *rc::gen::inRange(-1000, 1000) / 11.0};
    static const Vec2 kCircle[] = {{5, 0}, {4, 3}, {3, 4}, {0, 5}, {-3, 4}, {-4, 3}, {-5, 0}, {-4, -3},
                                   {-3, -4}, {0, -5}, {3, -4}, {4, -3}};
    for (int i = 0; i < n; ++i) {
      Vec2 p;
      switch (kind) {
        case 0: {  // on the line ab, rounded
          const double t = *rc::gen::inRange(-200, 200) / 64.0 + 1.0 / 3.0;
          p = {a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)};
          break;
        }
        case 1: {  // on the circle of radius 5 about an exact centre
          const Vec2 c = kCircle[*rc::gen::inRange(0, 12)];
          p = {a.x + c.x, a.y + c.y};
          break;
        }
        case 2:  // integer grid
          p = {double(*rc::gen::inRange(-4, 5)), double(*rc::gen::inRange(-4, 5))};
          break;
        default:  // anywhere
          p = {*rc::gen::arbitrary<double>(), *rc::gen::arbitrary<double>()};
          if (!std::isfinite(p.x) || !std::isfinite(p.y)) p = {1, 2};
      }
      if (*rc::gen::inRange(0, 3) == 0) p = *jitter(p);
      pts.push_back(p);
    }
    const int common = *rc::gen::element(0, 0, -40, 40, -600, 600, -1000, 1000);
    const bool mixed = *rc::gen::inRange(0, 5) == 0;
    for (Vec2& p : pts) {
      const int k = mixed ? *rc::gen::inRange(-1000, 1000) : common;
      p = {std::ldexp(p.x, k), std::ldexp(p.y, k)};
      if (!std::isfinite(p.x) || !std::isfinite(p.y)) p = {0, 0};
    }
    return pts;
  }));
}

RC_GTEST_PROP(Predicates2d, OrientationIsExact, ()) {
  const auto p = *degenerate_points(3);
  // Every argument order (the pivot of the differences changes with it).
  const int want = cgal_orient(p[0], p[1], p[2]);
  RC_ASSERT(geomcheck::orient2d(p[0], p[1], p[2]) == want);
  RC_ASSERT(geomcheck::orient2d(p[1], p[2], p[0]) == want);
  RC_ASSERT(geomcheck::orient2d(p[2], p[0], p[1]) == want);
  RC_ASSERT(geomcheck::orient2d(p[1], p[0], p[2]) == -want);
  RC_ASSERT(geomcheck::detail::orient2d_rational(p[0], p[1], p[2]) == cgal_orient(p[0], p[1], p[2]));
  const int e = geomcheck::detail::orient2d_expansion(p[0], p[1], p[2]);
  RC_ASSERT(e == 2 || e == cgal_orient(p[0], p[1], p[2]));
  const int b = geomcheck::detail::orient2d_stage_b(p[0], p[1], p[2]);
  RC_CLASSIFY(b != 2, "stage B applies");
  RC_ASSERT(b == 2 || b == want);
  for (int k = 0; k < 3; ++k) {  // every pivot
    const int r = geomcheck::detail::orient2d_rescaled(p[k], p[(k + 1) % 3], p[(k + 2) % 3]);
    RC_ASSERT(r == 2 || r == want);
  }
}

RC_GTEST_PROP(Predicates2d, InCircleIsExact, ()) {
  const auto p = *degenerate_points(4);
  const int want = cgal_incircle(p[0], p[1], p[2], p[3]);
  RC_ASSERT(geomcheck::incircle(p[0], p[1], p[2], p[3]) == want);
  // The fourth point as the pivot, and the others (the sign follows the
  // permutation: moving d to the front of four is odd, so it flips).
  RC_ASSERT(geomcheck::incircle(p[1], p[2], p[0], p[3]) == want);
  RC_ASSERT(geomcheck::incircle(p[3], p[0], p[1], p[2]) == -want);
  RC_ASSERT(geomcheck::detail::incircle_rational(p[0], p[1], p[2], p[3]) == want);
  const int e = geomcheck::detail::incircle_expansion(p[0], p[1], p[2], p[3]);
  RC_ASSERT(e == 2 || e == want);
  const int b = geomcheck::detail::incircle_stage_b(p[0], p[1], p[2], p[3]);
  RC_CLASSIFY(b != 2, "stage B applies");
  RC_ASSERT(b == 2 || b == want);
  const int r = geomcheck::detail::incircle_rescaled(p[0], p[1], p[2], p[3]);
  RC_CLASSIFY(r != 2, "the rescaled filter decides");
  RC_ASSERT(r == 2 || r == want);
  const int r3 = geomcheck::detail::incircle_rescaled(p[3], p[0], p[1], p[2]);  // d first: an odd permutation
  RC_ASSERT(r3 == 2 || r3 == -want);
}

// Symmetries the exact signs must have: cyclic shifts keep them, a swap
// flips them.
RC_GTEST_PROP(Predicates2d, Symmetries, ()) {
  const auto p = *degenerate_points(4);
  const int o = geomcheck::orient2d(p[0], p[1], p[2]);
  RC_ASSERT(geomcheck::orient2d(p[1], p[2], p[0]) == o);
  RC_ASSERT(geomcheck::orient2d(p[1], p[0], p[2]) == -o);
  const int i = geomcheck::incircle(p[0], p[1], p[2], p[3]);
  RC_ASSERT(geomcheck::incircle(p[1], p[2], p[0], p[3]) == i);
  RC_ASSERT(geomcheck::incircle(p[1], p[0], p[2], p[3]) == -i);
}

// The classroom example (Kettner et al., "Classroom examples of robustness
// problems in geometric computations"): p on a 256 x 256 grid of ulps
// around (0.5, 0.5) against q = (12, 12), r = (24, 24). The plain double
// determinant gets signs wrong there; the predicate must agree with CGAL on
// every point.
TEST(Predicates2d, ClassroomGrid) {
  const Vec2 q{12, 12}, r{24, 24};
  int naive_wrong = 0, checked = 0;
  for (int i = 0; i < 256; ++i) {
    for (int j = 0; j < 256; ++j) {
      const Vec2 p{0.5 + i * 0x1p-53, 0.5 + j * 0x1p-53};
      const int want = cgal_orient(p, q, r);
      // Every rotation: orient2d(q, r, p) takes its differences from p, as
      // the plain determinant below does.
      ASSERT_EQ(geomcheck::orient2d(p, q, r), want) << "p = (" << p.x << ", " << p.y << ")";
      ASSERT_EQ(geomcheck::orient2d(q, r, p), want) << "p = (" << p.x << ", " << p.y << ")";
      ASSERT_EQ(geomcheck::orient2d(r, p, q), want) << "p = (" << p.x << ", " << p.y << ")";
      const double naive = (q.x - p.x) * (r.y - p.y) - (q.y - p.y) * (r.x - p.x);
      naive_wrong += (naive > 0 ? 1 : naive < 0 ? -1 : 0) != want;
      ++checked;
    }
  }
  EXPECT_GT(naive_wrong, 1000) << "the grid no longer defeats the plain determinant: it tests nothing";
  std::printf("classroom grid: %d points, plain doubles wrong on %d, the predicate on none\n", checked, naive_wrong);
}

// Exactly cocircular and collinear points give 0, at any magnitude.
TEST(Predicates2d, ExactZeros) {
  for (int k : {-1070, -600, -1, 0, 1, 600, 1000}) {
    auto s = [k](double x, double y) { return Vec2{std::ldexp(x, k), std::ldexp(y, k)}; };
    EXPECT_EQ(geomcheck::incircle(s(5, 0), s(0, 5), s(-5, 0), s(3, -4)), 0) << k;
    EXPECT_EQ(geomcheck::incircle(s(5, 0), s(0, 5), s(-5, 0), s(3, 4)), 0) << k;
    EXPECT_EQ(geomcheck::incircle(s(5, 0), s(0, 5), s(-5, 0), s(0, 0)), 1) << k;
    EXPECT_EQ(geomcheck::incircle(s(5, 0), s(0, 5), s(-5, 0), s(6, 0)), -1) << k;
    EXPECT_EQ(geomcheck::orient2d(s(1, 1), s(2, 2), s(3, 3)), 0) << k;
    EXPECT_EQ(geomcheck::orient2d(s(0, 0), s(1, 0), s(0, 1)), 1) << k;
  }
  // 1e300 beside 1e-300: only the rational stage can decide.
  const Vec2 a{1e-300, 0}, b{1e300, 1e-300}, c{-1e300, 1e300};
  EXPECT_EQ(geomcheck::orient2d(a, b, c), cgal_orient(a, b, c));
  EXPECT_EQ(geomcheck::detail::orient2d_expansion(a, b, c), 2);
}

// Found by InCircleIsExact (RC_PARAMS="max_success=30000 seed=7"): with the
// fourth point near 2^-932 as the pivot, a product of two differences
// underflowed and was then multiplied by a lift near 2^630, while the
// permanent stayed far above the old floor, so the filter answered -1 where
// the determinant is positive.
TEST(Predicates2d, FilterUnderflowTimesLift) {
  const Vec2 p0{-0x1.5284444444444p-993, -0x1.f90cede62433ap-991};
  const Vec2 p1{-0x1.5284444444447p+315, -0x1.f90cede62433dp+317};
  const Vec2 p2{-0x1.2bcd2e52e52e5p-932, -0x1.00f1c71c71c72p-930};
  const Vec2 p3{-0x1.47e09c09c09c1p-146, -0x1.b4de62433b798p-144};
  const int want = cgal_incircle(p3, p0, p1, p2);
  ASSERT_EQ(want, 1);
  EXPECT_EQ(geomcheck::detail::incircle_rational(p3, p0, p1, p2), want);
  EXPECT_EQ(geomcheck::incircle(p3, p0, p1, p2), want);
  EXPECT_EQ(geomcheck::incircle(p0, p1, p2, p3), cgal_incircle(p0, p1, p2, p3));
}

// The rescaled filter (predicates2d.hpp, stage 2) where the inline filters
// refuse: sets scaled far from 1, huge beside tiny points, every point at
// its own scale; against CGAL on every call. On two clusters (each point
// near 2^+900 or 2^-900, as in bench_delaunay_2d's huge-tiny set) it must
// also decide nearly every call (else the stage is dead weight and the
// exact stages carry the load); with every point at its own scale many
// determinants lie below what doubles hold, and only agreement is asked.
TEST(Predicates2d, RescaledFilterOnHugeAndTiny) {
  std::mt19937_64 rng(20261126);
  std::uniform_real_distribution<double> u(-1, 1);
  std::uniform_int_distribution<int> e(-1000, 1000), pick(0, 2);
  for (const bool clusters : {true, false}) {
    int decided = 0, calls = 0;
    for (int i = 0; i < 20000; ++i) {
      Vec2 p[4];
      const int scale = e(rng);
      for (Vec2& q : p) {
        const int k = clusters ? (pick(rng) == 0 ? 900 : -900) : (pick(rng) == 0 ? e(rng) : scale);
        q = {std::ldexp(u(rng), k), std::ldexp(u(rng), k)};
      }
      const int o = geomcheck::detail::orient2d_rescaled(p[0], p[1], p[2]);
      const int c = geomcheck::detail::incircle_rescaled(p[0], p[1], p[2], p[3]);
      ASSERT_TRUE(o == 2 || o == cgal_orient(p[0], p[1], p[2]))
          << std::hexfloat << p[0].x << " " << p[0].y << " " << p[1].x << " " << p[1].y << " " << p[2].x << " "
          << p[2].y;
      ASSERT_TRUE(c == 2 || c == cgal_incircle(p[0], p[1], p[2], p[3]))
          << std::hexfloat << p[0].x << " " << p[0].y << " " << p[1].x << " " << p[1].y << " " << p[2].x << " "
          << p[2].y << " " << p[3].x << " " << p[3].y;
      decided += (o != 2) + (c != 2);
      calls += 2;
    }
    if (clusters) {
      EXPECT_GT(decided, calls * 9 / 10) << "the rescaled filter decides only " << decided << " of " << calls;
    }
    std::printf("rescaled filter, %s: %d of %d calls decided, every one as CGAL\n",
                clusters ? "two clusters at 2^+-900" : "every point at its own scale", decided, calls);
  }
}

// Differences that become subnormal when scaled (one near 1, the rest near
// 2^-1070 of it) and determinants just above the absolute slack: the
// filter's answers agree with CGAL's.
TEST(Predicates2d, RescaledFilterAtTheUnderflow) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(0.5, 1);
  std::uniform_int_distribution<int> e(-1074, -1000);
  int decided = 0;
  for (int i = 0; i < 20000; ++i) {
    const int k = e(rng);
    const Vec2 a{0, 0}, b{u(rng), std::ldexp(u(rng), k)}, c{std::ldexp(u(rng), e(rng)), std::ldexp(u(rng), k)};
    const Vec2 d{std::ldexp(u(rng), k), -std::ldexp(u(rng), e(rng))};
    const int o = geomcheck::detail::orient2d_rescaled(a, b, c);
    const int ic = geomcheck::detail::incircle_rescaled(a, b, c, d);
    ASSERT_TRUE(o == 2 || o == cgal_orient(a, b, c)) << i;
    ASSERT_TRUE(ic == 2 || ic == cgal_incircle(a, b, c, d)) << i;
    decided += (o != 2) + (ic != 2);
  }
  std::printf("rescaled filter at the underflow: %d of 40000 calls decided, every one as CGAL\n", decided);
}

}  // namespace
