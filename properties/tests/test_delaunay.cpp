// delaunay_2d: properties against the exact validity checker and CGAL's
// Delaunay_triangulation_2, metamorphic properties (permutation, exact
// translation, power-of-two scaling), input errors, fixed hard cases, and
// the teeth (the same construction on plain double predicates).
//
// Seeds: RC_PARAMS from ctest (fixed, printed by RapidCheck). A failing
// property saves its shrunk point set as a case file under
// <build>/failures/ and prints the command that replays it.
#include <gtest/gtest.h>
#include <rapidcheck.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <map>
#include <optional>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "geomcheck/delaunay_2d.hpp"
#include "geomcheck/detail/delaunay_build.hpp"
#include "geomcheck/detail/delaunay_links.hpp"
#include "geomcheck/oracles/delaunay_2d.hpp"
#include "geomcheck/pointset_file.hpp"
#include "geomcheck/properties/generators.hpp"
#include "support.hpp"

namespace geomcheck {
void showValue(const Vec2& p, std::ostream& os) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "(%a, %a)", p.x, p.y);
  os << buf;
}
}  // namespace geomcheck

namespace {

using geomcheck::DelaunayTriangulation;
using geomcheck::Vec2;
using Points = std::vector<Vec2>;

// ---- generators: properties/src/generators/delaunay_2d.cpp ----------------

double unit(std::uint64_t bits) { return static_cast<double>(bits >> 11) * 0x1p-53; }  // [0, 1), 53 bits
using geomcheck::gen::collinear_points;
using geomcheck::gen::grid_points;
using geomcheck::gen::uniform_points;
using Mode = geomcheck::gen::PointSetMode;
std::vector<Mode> modes() { return geomcheck::gen::point_set_modes(); }
rc::Gen<std::pair<Points, std::string>> any_points() { return geomcheck::gen::point_sets(); }

// ---- running ---------------------------------------------------------------

std::string save_points(const Points& p, const std::string& name, const std::string& why) {
  geomcheck::PointSetFile f;
  f.points = p;
  f.found_by = "rapidcheck property=" + name;
  f.note = why;
  std::filesystem::path dir = std::filesystem::path(GEOMCHECK_BINARY_DIR) / "failures";
  std::filesystem::create_directories(dir);
  const std::filesystem::path path = dir / ("delaunay_2d-" + name + ".case");
  std::string error;
  if (!geomcheck::save_point_set(path, f, error)) return "(not saved: " + error + ")";
  return path.string();
}

// One property run: every case drawn from `gen` (resized to the nominal
// size: rc::gen::inRange scales its range with the size, and every
// exponent, grid size and ulp offset should be reachable whatever max_size
// says), `check` returning "" or what is wrong.
struct Outcome {
  bool failed = false;
  int cases = 0;          ///< cases run up to and including the first failure
  std::string why;        ///< the shrunk counterexample's problem
  std::string text;       ///< RapidCheck's report
  Points input;           ///< the shrunk counterexample
  std::map<std::string, int> mix;  ///< cases by generator
};

Outcome check_points(const std::string& name, const rc::Gen<std::pair<Points, std::string>>& gen,
                     const std::function<std::string(const Points&)>& check) {
  Outcome out;
  rc::detail::TestMetadata meta;
  meta.id = name;
  meta.description = name;
  const auto& config = rc::detail::configuration();
  const auto sized = rc::gen::resize(rc::kNominalSize, gen);
  const auto result = rc::detail::checkTestable(
      [&] {
        const auto drawn = *sized;
        RC_TAG(drawn.second);
        ++out.mix[drawn.second];
        const std::string w = check(drawn.first);
        if (!w.empty()) {
          out.input = drawn.first;  // the last failure seen is the shrunk one
          out.why = w;
          RC_FAIL(w);
        }
      },
      meta, config.testParams, geomcheck::listener(), config.reproduce);
  rc::detail::SuccessResult ok;
  rc::detail::FailureResult failure;
  if (result.match(ok)) {
    out.cases = ok.numSuccess;
    return out;
  }
  out.failed = true;
  if (result.match(failure)) out.cases = failure.numSuccess + 1;
  std::ostringstream os;
  rc::detail::printResultMessage(result, os);
  out.text = os.str();
  return out;
}

// Runs the property on production; on failure saves the shrunk input and
// names the replay.
void run(const std::string& name, const std::function<std::string(const Points&)>& check,
         rc::Gen<std::pair<Points, std::string>> gen = any_points()) {
  const Outcome o = check_points(name, gen, check);
  std::string line;
  for (auto& [k, v] : o.mix) line += " " + k + "=" + std::to_string(v);
  std::printf("%s: cases by generator:%s\n", name.c_str(), line.c_str());
  const unsigned long long seed = rc::detail::configuration().testParams.seed;
  if (!o.failed) {
    std::printf("%s: %d cases passed (seed %llu)\n", name.c_str(), o.cases, seed);
    return;
  }
  const std::string path = save_points(o.input, name, o.why);
  ADD_FAILURE() << name << ": " << o.why << "\n" << o.text << "\n  saved: " << path
                << "\n  replay: " GEOMCHECK_TOOL_PATH " replay " << path
                << "\n  rerun:  RC_PARAMS=\"seed=" << seed << "\" ctest -R test_delaunay";
}

std::string valid(const Points& p) {
  DelaunayTriangulation t;
  try {
    t = geomcheck::delaunay_2d(p);
  } catch (const std::exception& e) {
    return std::string("threw: ") + e.what();
  }
  return geomcheck::oracle::check_delaunay(p, t);
}

// Triangles as sets of coordinates (input order free).
using CoordTri = std::array<std::pair<double, double>, 3>;
std::set<CoordTri> by_coordinates(const Points& p, const DelaunayTriangulation& t) {
  std::set<CoordTri> out;
  for (const auto& x : t.triangles) {
    CoordTri c{{{p[x[0]].x, p[x[0]].y}, {p[x[1]].x, p[x[1]].y}, {p[x[2]].x, p[x[2]].y}}};
    std::rotate(c.begin(), std::min_element(c.begin(), c.end()), c.end());
    out.insert(c);
  }
  return out;
}

// ---- properties ------------------------------------------------------------

TEST(Delaunay2d, ValidAndAgreesWithCgal) {
  run("valid-and-cgal", [](const Points& p) -> std::string {
    const std::string v = valid(p);
    if (!v.empty()) return "invalid: " + v;
    return geomcheck::oracle::compare_with_cgal(p, geomcheck::delaunay_2d(p));
  });
}

TEST(Delaunay2d, PermutationsGiveTheSameTriangulation) {
  run("permutation", [](const Points& p) -> std::string {
    Points q = p;
    std::mt19937_64 rng(p.size() * 7919 + 1);
    std::shuffle(q.begin(), q.end(), rng);
    const auto a = by_coordinates(p, geomcheck::delaunay_2d(p));
    const auto b = by_coordinates(q, geomcheck::delaunay_2d(q));
    return a == b ? "" : "a permutation of the input changed " + std::to_string(a.size()) + " triangles";
  });
}

TEST(Delaunay2d, ExactTranslationsAndPowerOfTwoScalesGiveTheSameTriangles) {
  // Integer coordinates below 2^20 times 2^s; translations by integers below
  // 2^30 times 2^s, and scalings by 2^e, are exact.
  const auto gen = rc::gen::exec([] {
    Points p = *rc::gen::oneOf(grid_points(), collinear_points(false),
                               rc::gen::map(uniform_points(1.0), [](Points q) {
                                 for (Vec2& v : q) v = {std::round(v.x * 1048575), std::round(v.y * 1048575)};
                                 return q;
                               }));
    for (Vec2& v : p) v = {std::round(v.x), std::round(v.y)};  // grid_points may have scaled
    return std::make_pair(p, std::string("integer"));
  });
  run("translate-scale",
      [](const Points& p) -> std::string {
        const int s = static_cast<int>(p.size() % 7) - 3;
        Points base = p, moved = p;
        const double tx = std::ldexp(static_cast<double>(p.size() * 104729 % 1000003) - 500000, 10 + s);
        const double ty = std::ldexp(-static_cast<double>(p.size() * 7919 % 999983), 10 + s);
        const int e = static_cast<int>(p.size() % 400) - 200;
        for (std::size_t i = 0; i < p.size(); ++i) {
          base[i] = {std::ldexp(p[i].x, s), std::ldexp(p[i].y, s)};
          moved[i] = {std::ldexp(base[i].x + tx, e), std::ldexp(base[i].y + ty, e)};
        }
        const auto a = geomcheck::oracle::canonical_triangles(geomcheck::delaunay_2d(base));
        const auto b = geomcheck::oracle::canonical_triangles(geomcheck::delaunay_2d(moved));
        return a == b ? "" : "translating by (" + std::to_string(tx) + ", " + std::to_string(ty) + ") and scaling by 2^" +
                                 std::to_string(e) + " changed the triangles";
      },
      gen);
}

TEST(Delaunay2d, NonFiniteInputIsRejectedWithTheFirstBadIndex) {
  const auto gen = rc::gen::map(uniform_points(1.0), [](Points p) { return std::make_pair(p, std::string("uniform")); });
  run("non-finite",
      [](const Points& p) -> std::string {
        if (p.empty()) return "";
        Points q = p;
        const std::size_t first = p.size() / 3, second = p.size() - 1;
        const double bad[] = {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity(),
                              -std::numeric_limits<double>::infinity()};
        (p.size() % 2 ? q[first].x : q[first].y) = bad[p.size() % 3];
        q[second].x = bad[(p.size() + 1) % 3];
        try {
          geomcheck::delaunay_2d(q);
        } catch (const geomcheck::DelaunayInputError& e) {
          if (e.index() != first) return "named index " + std::to_string(e.index()) + ", first bad is " + std::to_string(first);
          if (std::string(e.what()).find("point " + std::to_string(first)) == std::string::npos)
            return std::string("message does not name the point: ") + e.what();
          return "";
        }
        return "non-finite input was accepted";
      },
      gen);
}

// ---- fixed hard cases ------------------------------------------------------

void expect_valid(const Points& p, const char* what) {
  const DelaunayTriangulation t = geomcheck::delaunay_2d(p);
  EXPECT_EQ(geomcheck::oracle::check_delaunay(p, t), "") << what;
  EXPECT_EQ(geomcheck::oracle::compare_with_cgal(p, t), "") << what;
  std::printf("%s: %s\n", what, t.summary().c_str());
}

TEST(Delaunay2d, HardCases) {
  // Kettner et al., "Classroom examples of robustness problems": a 64x64
  // ulp grid around (0.5, 0.5) next to the line through (12, 12), (24, 24).
  Points classroom{{12, 12}, {24, 24}};
  for (int i = 0; i < 64; ++i)
    for (int j = 0; j < 64; ++j) classroom.push_back({0.5 + i * 0x1p-53, 0.5 + j * 0x1p-53});
  expect_valid(classroom, "classroom ulp grid");
  // A 100x100 integer grid (every square cocircular).
  Points grid;
  for (int i = 0; i < 100; ++i)
    for (int j = 0; j < 100; ++j) grid.push_back({double(i), double(j)});
  const DelaunayTriangulation tg = geomcheck::delaunay_2d(grid);
  EXPECT_EQ(geomcheck::oracle::check_delaunay(grid, tg), "");
  EXPECT_EQ(tg.triangles.size(), 2u * 99 * 99);
  // 1000 points on a parabola (every four points near cocircular), and the
  // same on a circle of radius 2^30 in doubles.
  Points parabola, circle;
  for (int i = 0; i < 1000; ++i) {
    const double x = (i - 500) * 0.001;
    parabola.push_back({x, x * x});
    circle.push_back({0x1p30 * std::cos(i * 0.0062831853), 0x1p30 * std::sin(i * 0.0062831853)});
  }
  expect_valid(parabola, "parabola");
  expect_valid(circle, "circle");
  // All collinear, with duplicates: no triangles, said so.
  Points line;
  for (int i = 0; i < 50; ++i) line.push_back({3.0 * (i % 17), 5.0 * (i % 17)});
  const DelaunayTriangulation tl = geomcheck::delaunay_2d(line);
  EXPECT_EQ(tl.dimension, geomcheck::DelaunayDimension::line);
  EXPECT_TRUE(tl.triangles.empty());
  EXPECT_EQ(tl.vertex_count, 17u);
  EXPECT_NE(tl.summary().find("collinear"), std::string::npos) << tl.summary();
  EXPECT_EQ(geomcheck::oracle::check_delaunay(line, tl), "");
  // One point repeated; nothing.
  EXPECT_EQ(geomcheck::delaunay_2d(Points(5, Vec2{1, 2})).dimension, geomcheck::DelaunayDimension::point);
  EXPECT_EQ(geomcheck::delaunay_2d(Points{}).dimension, geomcheck::DelaunayDimension::empty);
}

TEST(Delaunay2d, GridsAtEveryScaleAndBesideHugePoints) {
  // Integer grids scaled by powers of two across the range (the exact
  // in-circle stage for small grids scales differences by a power of two),
  // alone and beside points 2^+-900 away in scale, where a tiny difference
  // scaled down underflows; and the lattice points of a circle with its
  // centre (one conflict region of every triangle).
  for (const int e : {-1074, -1060, -1000, -953, -700, -300, -60, 0, 40, 300, 700, 960}) {
    Points p;
    for (int i = 0; i < 12; ++i)
      for (int j = 0; j < 12; ++j) p.push_back({std::ldexp(i, e), std::ldexp(j, e)});
    expect_valid(p, ("grid 12x12 x2^" + std::to_string(e)).c_str());
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) p.push_back({std::ldexp(i + 1, e > 0 ? -900 : 898), std::ldexp(j, e > 0 ? -900 : 898)});
    expect_valid(p, ("grid 12x12 x2^" + std::to_string(e) + " beside 4x4 at the other end").c_str());
  }
  // The set that caught a small-grid stage taking an underflowed difference for 0.
  const Points mixed{{0, 0},
                     {0, 0x0.0000000000002p-1022},
                     {0, 0x1p+898},
                     {0x1p-953, 0},
                     {0x1p+897, 0x1p+897},
                     {0x0.0000000000002p-1022, 0x0.0000000000004p-1022},
                     {0x1p+898, 0},
                     {0x0.0000000000004p-1022, 0x0.0000000000002p-1022},
                     {0x1p+898, 0x1p+898},
                     {0x0.0000000000006p-1022, 0},
                     {0x1.8p+898, 0x1p+897},
                     {0x1.8p-955, 0x1p-955},
                     {0x1p+899, 0},
                     {0x1p-954, 0x1p-956},
                     {0x1p+927, 0x1p+926}};
  expect_valid(mixed, "huge, tiny and subnormal grid points");
  Points circle{{0, 0}};
  for (int x = -5525; x <= 5525; ++x) {
    const double y = std::sqrt(5525.0 * 5525.0 - double(x) * x);
    if (y == std::floor(y)) {
      circle.push_back({double(x), y});
      if (y != 0) circle.push_back({double(x), -y});
    }
  }
  ASSERT_GT(circle.size(), 40u);
  expect_valid(circle, "lattice points of a circle and its centre");
}

TEST(Delaunay2d, SeedsAndRegressionsReplay) {
  int files = 0;
  for (const char* folder : {"seeds", "regressions"}) {
    const std::filesystem::path dir = std::filesystem::path(GEOMCHECK_SOURCE_DIR) / "corpora" / folder / "delaunay_2d";
    if (!std::filesystem::exists(dir)) continue;
    for (const auto& entry : std::filesystem::directory_iterator(dir)) {
      const auto r = geomcheck::load_point_set(entry.path());
      ASSERT_TRUE(r.ok()) << r.error;
      ++files;
      const Points& p = r.value.points;
      if (r.value.oracle_verdict == "rejected") {
        EXPECT_THROW(geomcheck::delaunay_2d(p), geomcheck::DelaunayInputError) << entry.path();
        continue;
      }
      const DelaunayTriangulation t = geomcheck::delaunay_2d(p);
      EXPECT_EQ(geomcheck::oracle::check_delaunay(p, t), "") << entry.path();
      EXPECT_EQ(geomcheck::oracle::compare_with_cgal(p, t), "") << entry.path();
    }
  }
  std::printf("%d point-set files replayed\n", files);
  EXPECT_GT(files, 0);
}

// ---- the checker can fail ---------------------------------------------------

// Neighbours recomputed from the triangles (after a test has edited them).
void relink(DelaunayTriangulation& t) { geomcheck::detail::link_neighbors(t); }

// Flips the first interior edge whose quadrilateral is strictly convex (the
// flipped pair stays counter-clockwise), then relinks; false when none is.
bool flip_some_edge(const Points& p, DelaunayTriangulation& t) {
  for (std::uint32_t i = 0; i < t.triangles.size(); ++i)
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t j = t.neighbors[i][k];
      if (j == DelaunayTriangulation::kNone) continue;
      const std::uint32_t c = t.triangles[i][k], a = t.triangles[i][(k + 1) % 3], b = t.triangles[i][(k + 2) % 3];
      std::uint32_t d = 0;
      for (std::uint32_t v : t.triangles[j])
        if (v != a && v != b) d = v;
      if (geomcheck::orient2d(p[c], p[a], p[d]) > 0 && geomcheck::orient2d(p[d], p[b], p[c]) > 0) {
        t.triangles[i] = {c, a, d};
        t.triangles[j] = {d, b, c};
        relink(t);
        return true;
      }
    }
  return false;
}

TEST(Delaunay2dOracle, CheckerCatchesCorruptedTriangulations) {
  // A valid triangulation of 40 points with no four cocircular (uniform
  // doubles), then one corruption at a time; each must be reported.
  std::mt19937_64 rng(20261124);
  Points p;
  for (int i = 0; i < 40; ++i) p.push_back({unit(rng()), unit(rng())});
  p.push_back(p[7]);  // one duplicate
  const DelaunayTriangulation good = geomcheck::delaunay_2d(p);
  ASSERT_EQ(geomcheck::oracle::check_delaunay(p, good), "");
  ASSERT_EQ(geomcheck::oracle::compare_with_cgal(p, good), "");
  const auto expect_caught = [&](const DelaunayTriangulation& bad, const char* what, const char* words) {
    const std::string v = geomcheck::oracle::check_delaunay(p, bad);
    EXPECT_NE(v.find(words), std::string::npos) << what << ": checker said \"" << v << "\"";
  };
  {  // a clockwise triangle
    DelaunayTriangulation t = good;
    std::swap(t.triangles[3][1], t.triangles[3][2]);
    relink(t);
    expect_caught(t, "clockwise triangle", "not counter-clockwise");
  }
  {  // an interior edge flipped: still a triangulation, no longer Delaunay
    DelaunayTriangulation t = good;
    ASSERT_TRUE(flip_some_edge(p, t));
    expect_caught(t, "flipped edge", "not locally Delaunay");
  }
  {  // a triangle missing
    DelaunayTriangulation t = good;
    t.triangles.erase(t.triangles.begin() + 5);
    relink(t);
    EXPECT_NE(geomcheck::oracle::check_delaunay(p, t), "") << "missing triangle";
  }
  {  // a triangle twice
    DelaunayTriangulation t = good;
    t.triangles.push_back(t.triangles[0]);
    t.neighbors.push_back(t.neighbors[0]);
    expect_caught(t, "duplicated triangle", "in two triangles");
  }
  {  // neighbours not mutual
    DelaunayTriangulation t = good;
    for (auto& n : t.neighbors[0])
      if (n != DelaunayTriangulation::kNone) {
        n = (n + 1) % static_cast<std::uint32_t>(t.triangles.size());
        break;
      }
    EXPECT_NE(geomcheck::oracle::check_delaunay(p, t), "") << "wrong neighbour";
  }
  {  // the duplicate not merged into the smallest index
    DelaunayTriangulation t = good;
    t.vertex_of[40] = 40;
    expect_caught(t, "vertex_of", "vertex_of[40]");
  }
  {  // a wrong dimension, a wrong hull count
    DelaunayTriangulation t = good;
    t.dimension = geomcheck::DelaunayDimension::line;
    expect_caught(t, "dimension", "dimension");
    t = good;
    t.hull_edges += 1;
    expect_caught(t, "hull_edges", "hull_edges");
  }
  {  // a point left out of the triangulation (its triangles merged away)
    Points q = p;
    q.push_back({0.5, 0.5});
    EXPECT_NE(geomcheck::oracle::check_delaunay(q, good), "") << "extra input point";
  }
  {  // CGAL's comparison: a flipped triangulation differs from CGAL's
    DelaunayTriangulation t = good;
    ASSERT_TRUE(flip_some_edge(p, t));
    EXPECT_NE(geomcheck::oracle::compare_with_cgal(p, t).find("not CGAL's"), std::string::npos);
  }
}

// ---- teeth -----------------------------------------------------------------

// The same construction on the plain double evaluation of the determinants.
struct PlainPredicates {
  static int orient(Vec2 a, Vec2 b, Vec2 c) {
    const double d = (a.x - c.x) * (b.y - c.y) - (a.y - c.y) * (b.x - c.x);
    return d > 0 ? 1 : (d < 0 ? -1 : 0);
  }
  static int incircle(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
    const double adx = a.x - d.x, bdx = b.x - d.x, cdx = c.x - d.x;
    const double ady = a.y - d.y, bdy = b.y - d.y, cdy = c.y - d.y;
    const double det = (adx * adx + ady * ady) * (bdx * cdy - cdx * bdy) +
                       (bdx * bdx + bdy * bdy) * (cdx * ady - adx * cdy) +
                       (cdx * cdx + cdy * cdy) * (adx * bdy - bdx * ady);
    return det > 0 ? 1 : (det < 0 ? -1 : 0);
  }
};

// The plain variant through the checker: "" or what is wrong (an invalid
// triangulation, or the structure breaking).
std::string plain_variant_problem(const Points& p) {
  try {
    const DelaunayTriangulation t = geomcheck::detail::DelaunayBuilder<PlainPredicates>().run(p.data(), p.size());
    return geomcheck::oracle::check_delaunay(p, t);
  } catch (const geomcheck::DelaunayFailure& e) {
    return std::string("threw: ") + e.what();
  }
}

TEST(Delaunay2dTeeth, PlainDoublePredicatesAreCaught) {
  // The properties production passes, run on the plain variant: the
  // ulp-perturbed, almost-collinear and huge-tiny generators must each catch
  // it within the configured number
  // of cases (an invalid triangulation, or the structure breaking), not
  // only the overflowing huge-tiny one.
  int caught = 0;
  for (const Mode& m : modes()) {
    const std::string name = m.name;
    const Outcome o = check_points("teeth-plain-predicates-" + name,
                                   rc::gen::map(m.gen, [name](Points p) { return std::make_pair(std::move(p), name); }),
                                   plain_variant_problem);
    if (o.failed) {
      ++caught;
      std::printf("plain double predicates, %s: caught at case %d: %s\n", m.name, o.cases, o.why.c_str());
    } else {
      std::printf("plain double predicates, %s: not caught in %d cases\n", m.name, o.cases);
    }
    if (name == "ulp-perturbed" || name == "almost-collinear" || name == "huge-tiny") {
      EXPECT_TRUE(o.failed) << "the plain-double variant passed every " << m.name << " case";
    }
  }
  EXPECT_GE(caught, 3);
}

}  // namespace
