// geomcheck — convex_hull_3d (core/convex_hull_3d.hpp) held to the exact
// checker (oracles/delaunay_3d.hpp: closed and outward, every facet on the
// hull, the hull's volume) on point sets built to defeat floating point
// (oracles/tests/point_set_generator_3d.hpp); metamorphic: scaling every
// point by a power of two keeps the facets.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cmath>
#include <cstdio>
#include <ostream>
#include <vector>

#include "geomcheck/convex_hull_3d.hpp"
#include "geomcheck/oracles/delaunay_3d.hpp"
#include "point_set_generator_3d.hpp"

namespace {

using geomcheck::Vec3;

rc::Gen<std::vector<Vec3>> hull_points() { return geomcheck::test::degenerate_point_sets_3d(); }

}  // namespace

namespace geomcheck {

RC_GTEST_PROP(ConvexHull3d, ExactHull, ()) {
  const std::vector<Vec3> p = *hull_points();
  const ConvexHull3 h = convex_hull_3d(p);
  const std::string why = oracle::check_convex_hull_3d(p, h);
  RC_CLASSIFY(h.dimension == ConvexHull3::Dimension::solid, "solid");
  RC_ASSERT(why == "");
}

RC_GTEST_PROP(ConvexHull3d, PowerOfTwoScaleKeepsFacets, ()) {
  const std::vector<Vec3> p = *hull_points();
  const int k = *rc::gen::element(-7, 3, 64);
  std::vector<Vec3> q = p;
  for (Vec3& v : q) {
    v = {std::ldexp(v.x, k), std::ldexp(v.y, k), std::ldexp(v.z, k)};
    for (double c : {v.x, v.y, v.z}) RC_PRE(std::isfinite(c) && (c == 0 || std::fabs(c) >= 0x1p-1000));
  }
  for (const Vec3& v : p)
    for (double c : {v.x, v.y, v.z}) RC_PRE(c == 0 || std::fabs(c) >= 0x1p-1000);
  const ConvexHull3 a = convex_hull_3d(p), b = convex_hull_3d(q);
  RC_ASSERT(a.dimension == b.dimension);
  RC_ASSERT(a.facets == b.facets);
}

TEST(ConvexHull3d, KnownAnswers) {
  EXPECT_EQ(convex_hull_3d({}).dimension, ConvexHull3::Dimension::empty);
  EXPECT_EQ(convex_hull_3d({{1, 2, 3}, {1, 2, 3}}).dimension, ConvexHull3::Dimension::point);
  EXPECT_EQ(convex_hull_3d({{0, 0, 0}, {1, 1, 1}, {2, 2, 2}}).dimension, ConvexHull3::Dimension::line);
  EXPECT_EQ(convex_hull_3d({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}}).dimension, ConvexHull3::Dimension::plane);
  EXPECT_EQ(convex_hull_3d({{0, 0, 0}, {1, 0, NAN}, {0, 1, 0}, {0, 0, 1}}).dimension, ConvexHull3::Dimension::invalid);
  // A cube with its centre and face centres: 8 corners, 12 triangles at
  // least (face centres may split faces), the centre never a vertex.
  std::vector<Vec3> cube;
  for (int i = 0; i < 8; ++i) cube.push_back({double(i & 1), double((i >> 1) & 1), double((i >> 2) & 1)});
  cube.push_back({0.5, 0.5, 0.5});
  cube.push_back({0.5, 0.5, 0});
  cube.push_back({0.5, 0.5, 1});
  const ConvexHull3 h = convex_hull_3d(cube);
  EXPECT_EQ(oracle::check_convex_hull_3d(cube, h), "");
  EXPECT_GE(h.facets.size(), 12u);
  for (const auto& f : h.facets)
    for (std::uint32_t v : f) EXPECT_NE(v, 8u) << "the centre is inside";
  // A facet turned inside out, or dropped, is caught by the checker.
  ConvexHull3 bad = h;
  std::swap(bad.facets[0][1], bad.facets[0][2]);
  EXPECT_NE(oracle::check_convex_hull_3d(cube, bad), "");
  bad = h;
  bad.facets.pop_back();
  EXPECT_NE(oracle::check_convex_hull_3d(cube, bad), "");
}

}  // namespace geomcheck
