// geomcheck — the 3D Delaunay checker (oracles/delaunay_3d.hpp) accepts
// CGAL's tetrahedralizations and rejects what is not one: on random points,
// integer grids (every cube's corners cospherical: ties), cospherical and
// coplanar sets, duplicates, and sets scaled by 2^+-500; and each known
// violation (a tetrahedron dropped, duplicated or turned inside out, a
// duplicate's index, a non-Delaunay pair of tetrahedra) is named.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include "geomcheck/oracles/delaunay_3d.hpp"
#include "exact_signs_3d.hpp"
#include "point_sets_3d.hpp"

namespace geomcheck::oracle {
namespace {

constexpr std::uint64_t kSeed = 20261203;

std::vector<Vec3> scaled(std::vector<Vec3> p, int k) {
  for (Vec3& v : p) v = {std::ldexp(v.x, k), std::ldexp(v.y, k), std::ldexp(v.z, k)};
  return p;
}

std::vector<Vec3> random_points(int n, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> U(-1, 1);
  std::vector<Vec3> p;
  for (int i = 0; i < n; ++i) p.push_back({U(rng), U(rng), U(rng)});
  return p;
}

std::vector<Vec3> grid(int m) {
  std::vector<Vec3> p;
  for (int x = 0; x < m; ++x)
    for (int y = 0; y < m; ++y)
      for (int z = 0; z < m; ++z) p.push_back({double(x), double(y), double(z)});
  return p;
}

/// The integer points of one sphere and its centre.
std::vector<Vec3> sphere() {
  std::vector<Vec3> p = test::integer_sphere_points();
  p.push_back({0, 0, 0});
  return p;
}

void expect_accepted(const std::vector<Vec3>& p, const char* what) {
  const std::vector<Tetrahedron> t = cgal_delaunay_3d(p);
  EXPECT_EQ(check_delaunay_3d(p, t), "") << what << ": CGAL's " << t.size() << " tetrahedra rejected";
  std::printf("%s: %zu points, %zu tetrahedra accepted\n", what, p.size(), t.size());
}

TEST(Delaunay3dChecker, AcceptsCgal) {
  std::mt19937_64 rng(kSeed);
  std::printf("seed %llu\n", static_cast<unsigned long long>(kSeed));
  expect_accepted(random_points(500, rng), "random");
  expect_accepted(grid(6), "6^3 grid");
  expect_accepted(sphere(), "cospherical integer points and the centre");
  std::vector<Vec3> dup = random_points(100, rng);
  for (int i = 0; i < 40; ++i) dup.push_back(dup[static_cast<std::size_t>(i * 2)]);
  expect_accepted(dup, "with duplicates");
  expect_accepted(scaled(grid(4), 500), "4^3 grid times 2^500");
  expect_accepted(scaled(grid(4), -500), "4^3 grid times 2^-500");
  std::vector<Vec3> mixed = grid(3);
  for (Vec3& v : mixed) v = {std::ldexp(v.x, -520), std::ldexp(v.y, 480), v.z};
  expect_accepted(mixed, "grid stretched by 2^-520 and 2^480");
}

TEST(Delaunay3dChecker, FlatInput) {
  std::vector<Vec3> plane;
  for (int i = 0; i < 20; ++i) plane.push_back({double(i % 5), double(i / 5), double(i % 5 + i / 5)});
  EXPECT_TRUE(cgal_delaunay_3d(plane).empty());
  EXPECT_EQ(check_delaunay_3d(plane, {}), "");
  EXPECT_NE(check_delaunay_3d(grid(2), {}), "") << "a cube's corners without tetrahedra";
  EXPECT_NE(check_delaunay_3d(plane, {{0, 1, 5, 6}}), "") << "a flat tetrahedron for coplanar points";
}

TEST(Delaunay3dChecker, RejectsViolations) {
  std::mt19937_64 rng(kSeed + 1);
  const std::vector<Vec3> p = random_points(60, rng);
  const std::vector<Tetrahedron> t = cgal_delaunay_3d(p);
  ASSERT_EQ(check_delaunay_3d(p, t), "");
  int dropped_caught = 0;
  for (std::size_t i = 0; i < t.size(); ++i) {
    std::vector<Tetrahedron> d = t;
    d.erase(d.begin() + static_cast<std::ptrdiff_t>(i));
    dropped_caught += check_delaunay_3d(p, d) != "";
  }
  EXPECT_EQ(dropped_caught, static_cast<int>(t.size())) << "every dropped tetrahedron is noticed";
  std::vector<Tetrahedron> twice = t;
  twice.push_back(t[3]);
  EXPECT_NE(check_delaunay_3d(p, twice), "");
  std::vector<Tetrahedron> inside_out = t;
  std::swap(inside_out[5][0], inside_out[5][1]);
  EXPECT_NE(check_delaunay_3d(p, inside_out).find("not positively oriented"), std::string::npos);
  // A duplicate of a vertex named instead of the vertex.
  std::vector<Vec3> q = p;
  const std::uint32_t v = t[0][0];
  q.push_back(p[v]);
  std::vector<Tetrahedron> by_dup = cgal_delaunay_3d(q);
  ASSERT_EQ(check_delaunay_3d(q, by_dup), "");
  for (Tetrahedron& x : by_dup)
    for (std::uint32_t& i : x)
      if (i == v) i = static_cast<std::uint32_t>(q.size() - 1);
  EXPECT_NE(check_delaunay_3d(q, by_dup).find("not a vertex"), std::string::npos);
}

// A flat bipyramid: the triangle (1,0,0), (-1/2, +-sqrt(3)/2, 0) and apexes
// at z = +-1/10. Its Delaunay tetrahedralization is the three tetrahedra
// around the apexes' edge; the two tetrahedra on the base triangle fill the
// same hull, but each apex lies inside the other's circumsphere.
TEST(Delaunay3dChecker, RejectsNonDelaunayPair) {
  const std::vector<Vec3> p = {{1, 0, 0}, {-0.5, 0.8660254037844386, 0}, {-0.5, -0.8660254037844386, 0},
                               {0, 0, 0.1}, {0, 0, -0.1}};
  const std::vector<Tetrahedron> delaunay = cgal_delaunay_3d(p);
  EXPECT_EQ(delaunay.size(), 3u);
  EXPECT_EQ(check_delaunay_3d(p, delaunay), "");
  // Base (0, 1, 2) is counter-clockwise from above: the top apex is on its
  // positive side, the bottom one on its negative side.
  const std::vector<Tetrahedron> two = {{0, 1, 2, 3}, {0, 2, 1, 4}};
  const std::string why = check_delaunay_3d(p, two);
  EXPECT_NE(why.find("not locally Delaunay"), std::string::npos) << why;
}

TEST(Delaunay3dChecker, CanonicalKeepsOrientation) {
  // Every even permutation of (0, 1, 2, 3) maps to (0, 1, 2, 3), every odd
  // one to (0, 1, 3, 2).
  Tetrahedron t{0, 1, 2, 3};
  int seen_even = 0, seen_odd = 0;
  std::sort(t.begin(), t.end());
  do {
    int inversions = 0;
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j) inversions += t[i] > t[j];
    const Tetrahedron c = canonical_tetrahedron(t);
    if (inversions % 2 == 0) {
      EXPECT_EQ(c, (Tetrahedron{0, 1, 2, 3}));
      ++seen_even;
    } else {
      EXPECT_EQ(c, (Tetrahedron{0, 1, 3, 2}));
      ++seen_odd;
    }
  } while (std::next_permutation(t.begin(), t.end()));
  EXPECT_EQ(seen_even, 12);
  EXPECT_EQ(seen_odd, 12);
}

// The checkers' integer signs (IntegerSigns3) against rational
// determinants: small coordinates (ties everywhere), coordinates at the
// edge of the span, at any power-of-two scale; and the sets they must
// leave to CGAL.
TEST(Delaunay3dOracle, IntegerSignsAgreeWithRationals) {
  std::mt19937_64 rng(kSeed);
  const std::int64_t edge = (std::int64_t(1) << IntegerSigns3::kMaxBits) - 1;
  int ties = 0;
  for (int round = 0; round < 4000; ++round) {
    std::uniform_int_distribution<std::int64_t> small(-2, 2), wide(-edge, edge), pick(0, 1);
    const bool at_edge = round % 2 == 1;
    std::vector<Vec3> p;
    for (int i = 0; i < 5; ++i) {
      auto c = [&] { return static_cast<double>(at_edge && pick(rng) ? (pick(rng) ? edge : -edge) : at_edge ? wide(rng) : small(rng)); };
      p.push_back({c(), c(), c()});
    }
    const int k = std::uniform_int_distribution<int>(-1000, 1000)(rng);
    p = scaled(p, k);
    const IntegerSigns3 ints(p);
    ASSERT_TRUE(ints.ok()) << "round " << round;
    const int o = ints.orientation(0, 1, 2, 3);
    ASSERT_EQ(o, -test::orient3d_q(p[0], p[1], p[2], p[3])) << "round " << round;
    const int s = ints.side_of_oriented_sphere(0, 1, 2, 3, 4);
    ASSERT_EQ(s, -test::insphere_q(p[0], p[1], p[2], p[3], p[4])) << "round " << round;
    ties += (o == 0) + (s == 0);
  }
  EXPECT_GT(ties, 400) << "the small coordinates make ties";
  // Not for these: a span of 21 bits, a coordinate that is no short
  // binary fraction, a NaN.
  EXPECT_FALSE(IntegerSigns3({{0, 0, 0}, {double(std::int64_t(1) << 21), 1, 0}}).ok());
  EXPECT_FALSE(IntegerSigns3({{0.1, 0, 0}, {1, 1, 1}}).ok());
  EXPECT_FALSE(IntegerSigns3({{NAN, 0, 0}}).ok());
  EXPECT_TRUE(IntegerSigns3({{0, 0, 0}}).ok());
}

}  // namespace
}  // namespace geomcheck::oracle
