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
#include "geomcheck/oracles/delaunay_2d.hpp"
#include "geomcheck/pointset_file.hpp"
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

// ---- generators ------------------------------------------------------------

double unit(std::uint64_t bits) { return static_cast<double>(bits >> 11) * 0x1p-53; }  // [0, 1), 53 bits

double nudge(double v, int ulps) {
  for (; ulps > 0; --ulps) v = std::nextafter(v, std::numeric_limits<double>::infinity());
  for (; ulps < 0; ++ulps) v = std::nextafter(v, -std::numeric_limits<double>::infinity());
  return v;
}

rc::Gen<Points> uniform_points(double scale) {
  return rc::gen::map(rc::gen::container<std::vector<std::pair<std::uint64_t, std::uint64_t>>>(
                          rc::gen::pair(rc::gen::arbitrary<std::uint64_t>(), rc::gen::arbitrary<std::uint64_t>())),
                      [scale](const std::vector<std::pair<std::uint64_t, std::uint64_t>>& v) {
                        Points p;
                        for (auto [a, b] : v) p.push_back({(2 * unit(a) - 1) * scale, (2 * unit(b) - 1) * scale});
                        return p;
                      });
}

// Clusters: a few centres with points 2^-k around them (k up to 40).
rc::Gen<Points> clustered_points() {
  return rc::gen::exec([] {
    const int clusters = *rc::gen::inRange(1, 5);
    Points p;
    for (int c = 0; c < clusters; ++c) {
      const Vec2 centre{*rc::gen::inRange(-100, 100) * 0.37, *rc::gen::inRange(-100, 100) * 0.53};
      const double r = std::ldexp(1.0, -*rc::gen::inRange(0, 40));
      const int k = *rc::gen::inRange(1, 40);
      for (int i = 0; i < k; ++i)
        p.push_back({centre.x + r * (2 * unit(*rc::gen::arbitrary<std::uint64_t>()) - 1),
                     centre.y + r * (2 * unit(*rc::gen::arbitrary<std::uint64_t>()) - 1)});
    }
    return p;
  });
}

// Integer grid (a random subset, in random order), scaled by 2^e.
rc::Gen<Points> grid_points() {
  return rc::gen::exec([] {
    const int w = *rc::gen::inRange(1, 12), h = *rc::gen::inRange(1, 12);
    const int e = *rc::gen::inRange(-30, 30);
    const int keep = *rc::gen::inRange(50, 101);
    Points p;
    for (int i = 0; i < w; ++i)
      for (int j = 0; j < h; ++j)
        if (*rc::gen::inRange(0, 100) < keep) p.push_back({std::ldexp(i, e), std::ldexp(j, e)});
    return p;
  });
}

// An integer grid rotated by a random angle in doubles: every square is
// within rounding of cocircular.
rc::Gen<Points> rotated_grid_points() {
  return rc::gen::exec([] {
    const int w = *rc::gen::inRange(2, 10), h = *rc::gen::inRange(2, 10);
    const double angle = unit(*rc::gen::arbitrary<std::uint64_t>()) * 6.283185307179586;
    const double c = std::cos(angle), s = std::sin(angle);
    const double ox = *rc::gen::inRange(-1000, 1000), oy = *rc::gen::inRange(-1000, 1000);
    Points p;
    for (int i = 0; i < w; ++i)
      for (int j = 0; j < h; ++j) p.push_back({ox + i * c - j * s, oy + i * s + j * c});
    return p;
  });
}

// All collinear (exactly: small integer multiples of an integer direction),
// optionally with one point moved off the line by a few ulps.
rc::Gen<Points> collinear_points(bool almost) {
  return rc::gen::exec([almost] {
    const int dx = *rc::gen::inRange(-7, 8), dy = *rc::gen::inRange(-7, 8);
    const double ox = *rc::gen::inRange(-50, 50) * 0.25, oy = *rc::gen::inRange(-50, 50) * 0.25;
    const int k = *rc::gen::inRange(2, 40);
    Points p;
    for (int i = 0; i < k; ++i) {
      const int t = *rc::gen::inRange(-1000, 1000);
      p.push_back({ox + t * dx, oy + t * dy});
    }
    if (almost) {
      const std::size_t i = *rc::gen::inRange<std::size_t>(0, p.size());
      const int u = *rc::gen::element(-3, -2, -1, 1, 2, 3);
      if (*rc::gen::arbitrary<bool>()) p[i].x = nudge(p[i].x, u);
      else p[i].y = nudge(p[i].y, u);
    }
    return p;
  });
}

// A few base points repeated and moved by 0 to 2 ulps.
rc::Gen<Points> near_duplicate_points() {
  return rc::gen::exec([] {
    const Points base = *rc::gen::resize(8, uniform_points(1.0));
    Points p;
    if (base.empty()) return p;
    const int k = *rc::gen::inRange(1, 60);
    for (int i = 0; i < k; ++i) {
      Vec2 q = base[*rc::gen::inRange<std::size_t>(0, base.size())];
      q.x = nudge(q.x, *rc::gen::inRange(-2, 3));
      q.y = nudge(q.y, *rc::gen::inRange(-2, 3));
      p.push_back(q);
    }
    return p;
  });
}

// Degenerate positions (grid points, points on a circle of integer points)
// each moved by a few ulps.
rc::Gen<Points> ulp_perturbed_points() {
  return rc::gen::exec([] {
    Points p;
    if (*rc::gen::arbitrary<bool>()) {
      const int w = *rc::gen::inRange(2, 9), h = *rc::gen::inRange(2, 9);
      const double step = *rc::gen::element(0.1, 0.3, 1.0, 1e-3, 7.0);
      for (int i = 0; i < w; ++i)
        for (int j = 0; j < h; ++j) p.push_back({i * step, j * step});
    } else {
      // The 12 integer points at distance 5 and 5*13 = 65 from the centre.
      const int r = *rc::gen::element(5, 25, 65);
      for (int x = -r; x <= r; ++x)
        for (int y = -r; y <= r; ++y)
          if (x * x + y * y == r * r) p.push_back({double(x), double(y)});
    }
    const int spread = *rc::gen::inRange(0, 4);
    for (Vec2& q : p) {
      q.x = nudge(q.x, *rc::gen::inRange(-spread, spread + 1));
      q.y = nudge(q.y, *rc::gen::inRange(-spread, spread + 1));
    }
    return p;
  });
}

// Huge (2^900..2^1000), tiny (2^-1000..2^-900, subnormals included) and
// mixes of both.
rc::Gen<Points> extreme_points() {
  return rc::gen::exec([] {
    const int mode = *rc::gen::inRange(0, 3);
    Points p = *rc::gen::oneOf(uniform_points(1.0), grid_points(), ulp_perturbed_points());
    for (std::size_t i = 0; i < p.size(); ++i) {
      const bool huge = mode == 0 || (mode == 2 && i % 2 == 0);
      const int e = huge ? *rc::gen::inRange(900, 1000) : *rc::gen::inRange(-1070, -900);
      p[i] = {std::ldexp(p[i].x, e), std::ldexp(p[i].y, e)};
    }
    return p;
  });
}

struct Mode {
  const char* name;
  rc::Gen<Points> gen;
};

std::vector<Mode> modes() {
  return {{"uniform", uniform_points(1.0)},
          {"clustered", clustered_points()},
          {"grid", grid_points()},
          {"rotated-grid", rotated_grid_points()},
          {"collinear", collinear_points(false)},
          {"almost-collinear", collinear_points(true)},
          {"near-duplicates", near_duplicate_points()},
          {"ulp-perturbed", ulp_perturbed_points()},
          {"huge-tiny", extreme_points()}};
}

rc::Gen<std::pair<Points, std::string>> any_points() {
  std::vector<rc::Gen<std::pair<Points, std::string>>> gens;
  for (const Mode& m : modes()) {
    const std::string name = m.name;
    gens.push_back(rc::gen::map(m.gen, [name](Points p) { return std::make_pair(std::move(p), name); }));
  }
  return rc::gen::join(rc::gen::elementOf(gens));
}

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

// Runs the property; on failure saves the shrunk input and names the replay.
void run(const std::string& name, const std::function<std::string(const Points&)>& check,
         rc::Gen<std::pair<Points, std::string>> gen = any_points()) {
  std::optional<Points> failing;
  std::string why;
  std::map<std::string, int> mix;
  rc::detail::TestMetadata meta;
  meta.id = name;
  meta.description = name;
  const auto& config = rc::detail::configuration();
  const auto result = rc::detail::checkTestable(
      [&] {
        const auto drawn = *gen;
        RC_TAG(drawn.second);
        ++mix[drawn.second];
        const std::string w = check(drawn.first);
        if (!w.empty()) {
          failing = drawn.first;
          why = w;
          RC_FAIL(w);
        }
      },
      meta, config.testParams, geomcheck::listener(), config.reproduce);
  std::string line;
  for (auto& [k, v] : mix) line += " " + k + "=" + std::to_string(v);
  std::printf("%s: cases by generator:%s\n", name.c_str(), line.c_str());
  rc::detail::SuccessResult ok;
  if (result.match(ok)) {
    std::printf("%s: %d cases passed (seed %llu)\n", name.c_str(), ok.numSuccess,
                static_cast<unsigned long long>(config.testParams.seed));
    return;
  }
  std::ostringstream os;
  rc::detail::printResultMessage(result, os);
  const std::string text = os.str();
  const std::string path = failing ? save_points(*failing, name, why) : "(no input)";
  ADD_FAILURE() << name << ": " << why << "\n" << text << "\n  saved: " << path
                << "\n  replay: " GEOMCHECK_TOOL_PATH " replay " << path
                << "\n  rerun:  RC_PARAMS=\"" << (std::getenv("RC_PARAMS") ? std::getenv("RC_PARAMS") : "")
                << "\" ctest -R test_delaunay";
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

// Runs the plain variant on one generator until the checker or the
// structure catches it; returns the case count and the first finding, or
// nullopt when all cases passed.
std::optional<std::pair<int, std::string>> teeth_run(const std::string& mode, const rc::Gen<Points>& gen) {
  int cases = 0;
  std::string first;
  rc::detail::TestMetadata meta;
  meta.id = meta.description = "teeth-plain-predicates-" + mode;
  const auto& config = rc::detail::configuration();
  const auto result = rc::detail::checkTestable(
      [&] {
        const Points p = *gen;
        ++cases;
        std::string why;
        try {
          const DelaunayTriangulation t = geomcheck::detail::DelaunayBuilder<PlainPredicates>().run(p.data(), p.size());
          why = geomcheck::oracle::check_delaunay(p, t);
        } catch (const geomcheck::DelaunayFailure& e) {
          why = std::string("threw: ") + e.what();
        }
        if (!why.empty()) {
          if (first.empty()) first = why;
          RC_FAIL(why);
        }
      },
      meta, config.testParams, geomcheck::listener(), config.reproduce);
  rc::detail::FailureResult failure;
  if (!result.match(failure)) return std::nullopt;
  return std::make_pair(failure.numSuccess + 1, first);
}

TEST(Delaunay2dTeeth, PlainDoublePredicatesAreCaught) {
  // The properties production passes, run on the plain variant: the
  // ulp-perturbed, almost-collinear and huge-tiny generators must each catch
  // it within the configured number
  // of cases (an invalid triangulation, or the structure breaking), not
  // only the overflowing huge-tiny one.
  int caught = 0;
  for (const Mode& m : modes()) {
    const auto r = teeth_run(m.name, m.gen);
    if (r) {
      ++caught;
      std::printf("plain double predicates, %s: caught at case %d: %s\n", m.name, r->first, r->second.c_str());
    } else {
      std::printf("plain double predicates, %s: not caught\n", m.name);
    }
    const std::string name = m.name;
    if (name == "ulp-perturbed" || name == "almost-collinear" || name == "huge-tiny") {
      EXPECT_TRUE(r.has_value()) << "the plain-double variant passed every " << m.name << " case";
    }
  }
  EXPECT_GE(caught, 3);
}

}  // namespace
