// geomcheck — delaunay_3d (core/delaunay_3d.hpp) held to the exact checker
// (oracles/delaunay_3d.hpp: positively oriented, facets paired and locally
// Delaunay, the boundary on the hull, every point a vertex) on point sets
// built to defeat floating point (oracles/tests/point_set_generator_3d.hpp),
// to CGAL's Delaunay_triangulation_3 in general position (the same
// tetrahedra), and metamorphic: the tetrahedra do not depend on the input's
// order, and scaling every point by a power of two keeps them bit for bit.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <vector>

#include "geomcheck/convex_hull_3d.hpp"
#include "geomcheck/delaunay_3d.hpp"
#include "geomcheck/oracles/delaunay_3d.hpp"
#include "geomcheck/predicates3d.hpp"
#include "point_set_generator_3d.hpp"

namespace geomcheck {

namespace {

using Dim = DelaunayTetrahedralization::Dimension;

std::vector<oracle::Tetrahedron> canonical(const std::vector<std::array<std::uint32_t, 4>>& tets) {
  std::vector<oracle::Tetrahedron> out;
  for (const auto& t : tets) out.push_back(oracle::canonical_tetrahedron(t));
  std::sort(out.begin(), out.end());
  return out;
}

/// "" when neighbors[] and vertex_of are what the header says.
std::string check_links(const std::vector<Vec3>& p, const DelaunayTetrahedralization& d) {
  if (d.vertex_of.size() != p.size()) return "vertex_of has the wrong size";
  for (std::size_t i = 0; i < p.size(); ++i) {
    const std::uint32_t v = d.vertex_of[i];
    const Vec3 a = p[i], b = p[v];
    if (v > i || !(a.x == b.x && a.y == b.y && a.z == b.z)) return "vertex_of[" + std::to_string(i) + "] is wrong";
    if (v < i && d.vertex_of[v] != v) return "vertex_of[" + std::to_string(i) + "] is not a representative";
  }
  if (d.neighbors.size() != d.tetrahedra.size()) return "neighbors has the wrong size";
  std::size_t hull = 0;
  for (std::size_t t = 0; t < d.tetrahedra.size(); ++t)
    for (int i = 0; i < 4; ++i) {
      const std::uint32_t u = d.neighbors[t][i];
      if (u == DelaunayTetrahedralization::kNone) {
        ++hull;
        continue;
      }
      if (u >= d.tetrahedra.size()) return "a neighbour out of range";
      int shared = 0;
      for (int j = 0; j < 4; ++j)
        if (j != i && std::count(d.tetrahedra[u].begin(), d.tetrahedra[u].end(), d.tetrahedra[t][j])) ++shared;
      if (shared != 3) return "tetrahedron " + std::to_string(t) + "'s neighbour " + std::to_string(i) + " shares no facet";
      if (std::count(d.neighbors[u].begin(), d.neighbors[u].end(), static_cast<std::uint32_t>(t)) != 1)
        return "neighbours not mutual";
    }
  if (hull != d.hull_facets) return "hull_facets is not the number of kNone links";
  return "";
}

}  // namespace

RC_GTEST_PROP(Delaunay3d, ExactTetrahedralization, ()) {
  const std::vector<Vec3> p = *test::degenerate_point_sets_3d();
  const DelaunayTetrahedralization d = delaunay_3d(p);
  RC_CLASSIFY(d.dimension == Dim::solid, "solid");
  RC_ASSERT(oracle::check_delaunay_3d(p, d.tetrahedra) == "");
  RC_ASSERT(check_links(p, d) == "");
  // The dimension is the hull's (an independent exact computation).
  const ConvexHull3 h = convex_hull_3d(p);
  RC_ASSERT(std::string(to_string(d.dimension)) == to_string(h.dimension));
  if (d.dimension == Dim::solid) {
    // The boundary facets triangulate a sphere: F = 2 V - 4 over the vertices they use.
    std::vector<std::uint32_t> on_hull;
    for (std::size_t t = 0; t < d.tetrahedra.size(); ++t)
      for (int i = 0; i < 4; ++i)
        if (d.neighbors[t][i] == DelaunayTetrahedralization::kNone)
          for (int j = 0; j < 4; ++j)
            if (j != i) on_hull.push_back(d.tetrahedra[t][j]);
    std::sort(on_hull.begin(), on_hull.end());
    on_hull.erase(std::unique(on_hull.begin(), on_hull.end()), on_hull.end());
    RC_ASSERT(d.hull_facets == 2 * on_hull.size() - 4);
  }
}

RC_GTEST_PROP(Delaunay3d, SameAsCgalInGeneralPosition, ()) {
  // Random doubles: no five cospherical, no four coplanar, in practice.
  const int n = *rc::gen::inRange(4, 200);
  std::vector<Vec3> p;
  for (int i = 0; i < n; ++i)
    p.push_back({*rc::gen::inRange(-(1 << 30), 1 << 30) * 0x1p-30, *rc::gen::inRange(-(1 << 30), 1 << 30) * 0x1p-30,
                 *rc::gen::inRange(-(1 << 30), 1 << 30) * 0x1p-30});
  const DelaunayTetrahedralization d = delaunay_3d(p);
  RC_ASSERT(canonical(d.tetrahedra) == oracle::cgal_delaunay_3d(p));
}

RC_GTEST_PROP(Delaunay3d, InputOrderDoesNotMatter, ()) {
  const std::vector<Vec3> p = *test::degenerate_point_sets_3d();
  std::vector<std::size_t> order(p.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  for (std::size_t i = order.size(); i > 1; --i)
    std::swap(order[i - 1], order[*rc::gen::inRange<std::size_t>(0, i)]);
  std::vector<Vec3> q(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) q[i] = p[order[i]];
  const DelaunayTetrahedralization a = delaunay_3d(p), b = delaunay_3d(q);
  RC_ASSERT(a.dimension == b.dimension);
  // b's index j is p's order[j]; both name representatives of their own input.
  std::vector<std::array<std::uint32_t, 4>> mapped;
  for (const auto& t : b.tetrahedra) {
    std::array<std::uint32_t, 4> m{};
    for (int i = 0; i < 4; ++i) m[i] = a.vertex_of[order[t[i]]];
    mapped.push_back(m);
  }
  RC_ASSERT(canonical(mapped) == canonical(a.tetrahedra));
}

RC_GTEST_PROP(Delaunay3d, PowerOfTwoScaleKeepsTetrahedra, ()) {
  const std::vector<Vec3> p = *test::degenerate_point_sets_3d();
  const int k = *rc::gen::element(-7, 3, 64, -300);
  std::vector<Vec3> q = p;
  for (Vec3& v : q) {  // an exact scaling: nothing overflows, underflows or lands among the subnormals
    for (double c : {v.x, v.y, v.z}) {
      const double s = std::ldexp(c, k);
      RC_PRE(std::isfinite(s) && std::ldexp(s, -k) == c && (c == 0 || std::fabs(s) >= 0x1p-1000));
      RC_PRE(c == 0 || std::fabs(c) >= 0x1p-1000);
    }
    v = {std::ldexp(v.x, k), std::ldexp(v.y, k), std::ldexp(v.z, k)};
  }
  const DelaunayTetrahedralization a = delaunay_3d(p), b = delaunay_3d(q);
  RC_ASSERT(a.dimension == b.dimension);
  RC_ASSERT(a.tetrahedra == b.tetrahedra);
  RC_ASSERT(a.neighbors == b.neighbors);
}

TEST(Delaunay3d, KnownAnswers) {
  EXPECT_EQ(delaunay_3d(std::vector<Vec3>{}).dimension, Dim::empty);
  EXPECT_EQ(delaunay_3d({{1, 2, 3}, {1, 2, 3}}).dimension, Dim::point);
  EXPECT_EQ(delaunay_3d({{0, 0, 0}, {1, 1, 1}, {2, 2, 2}, {-0.0, 0, 0}}).dimension, Dim::line);
  EXPECT_EQ(delaunay_3d({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}}).summary(),
            "plane: all 4 distinct points of 4 are coplanar, no tetrahedra");
  try {
    delaunay_3d({{0, 0, 0}, {1, 0, NAN}, {0, 1, 0}, {0, 0, 1}});
    ADD_FAILURE() << "a NaN was accepted";
  } catch (const DelaunayInputError& e) {
    EXPECT_EQ(e.index(), 1u);
  }
  // One tetrahedron, positively oriented whatever the input's order.
  const std::vector<Vec3> four = {{0, 0, 0}, {0, 1, 0}, {1, 0, 0}, {0, 0, 1}};
  const DelaunayTetrahedralization one = delaunay_3d(four);
  ASSERT_EQ(one.tetrahedra.size(), 1u);
  EXPECT_EQ(one.hull_facets, 4u);
  const auto& t1 = one.tetrahedra[0];
  EXPECT_EQ(orient3d(four[t1[0]], four[t1[1]], four[t1[2]], four[t1[3]]), -1);  // right-handed
  // An integer grid: every unit cube's eight corners are cospherical, the
  // tetrahedra fill the box (volume 4^3 = 64, in sixths: 384).
  std::vector<Vec3> grid;
  for (int x = 0; x <= 4; ++x)
    for (int y = 0; y <= 4; ++y)
      for (int z = 0; z <= 4; ++z) grid.push_back({double(x), double(y), double(z)});
  grid.push_back({2, 2, 2});  // a duplicate
  const DelaunayTetrahedralization g = delaunay_3d(grid);
  EXPECT_EQ(oracle::check_delaunay_3d(grid, g.tetrahedra), "");
  EXPECT_EQ(g.vertex_count, 125u);
  EXPECT_EQ(g.vertex_of.back(), 62u);
  double sixths = 0;
  for (const auto& t : g.tetrahedra) {
    const Vec3 a = grid[t[0]], b = grid[t[1]], c = grid[t[2]], e = grid[t[3]];
    const Vec3 u = b - a, v = c - a, w = e - a;
    sixths += u.x * (v.y * w.z - v.z * w.y) - u.y * (v.x * w.z - v.z * w.x) + u.z * (v.x * w.y - v.y * w.x);
  }
  EXPECT_EQ(sixths, 384);
  EXPECT_EQ(g.hull_facets, 6u * 16u * 2u);
  // The 168 integer points of one sphere: all on the hull.
  const std::vector<Vec3> s = test::integer_sphere_points();
  const DelaunayTetrahedralization ds = delaunay_3d(s);
  EXPECT_EQ(oracle::check_delaunay_3d(s, ds.tetrahedra), "");
  EXPECT_EQ(check_links(s, ds), "");
  // A tetrahedron turned inside out is caught by the checker.
  DelaunayTetrahedralization bad = g;
  std::swap(bad.tetrahedra[0][0], bad.tetrahedra[0][1]);
  EXPECT_NE(oracle::check_delaunay_3d(grid, bad.tetrahedra), "");
}

}  // namespace geomcheck
