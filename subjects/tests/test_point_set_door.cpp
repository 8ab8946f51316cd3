// geomcheck — the point-set door (verify.hpp, "The point-set family") tried
// as a user would: production's triangles through the door pass; a
// triangulator that loses a triangle, that names indices it was not given,
// that crashes, or that answers a different but valid-looking triangulation
// is caught, counted and saved; files of another query are refused. Fixed
// seed (VerifyOptions' default).
#include <gtest/gtest.h>

#include <cmath>
#include <chrono>
#include <csignal>
#include <filesystem>
#include <string>
#include <thread>
#include <vector>

#include "geomcheck/pointset_file.hpp"
#include "door_options.hpp"
#include "geomcheck/verify.hpp"

namespace geomcheck {
namespace {

using Points = std::vector<Vec2>;
constexpr PointSetQueryId kDelaunay = PointSetQueryId::delaunay_2d;

VerifyOptions quiet_options(const std::string& out, int cases = 120) { return testing::quiet_options(out, cases); }

std::vector<std::array<int, 3>> production_triangles(const Points& p) {
  std::vector<std::array<int, 3>> out;
  for (const auto& t : delaunay_2d(p).triangles) out.push_back({int(t[0]), int(t[1]), int(t[2])});
  return out;
}

TEST(PointSetDoor, ProductionTrianglesPass) {
  const auto mine = subject<kDelaunay>("production-triangles", production_triangles);
  const VerifyResult r = verify(mine, quiet_options("ps-production"));
  EXPECT_EQ(r.failures, 0) << (r.by_property.empty() ? "" : r.by_property.begin()->first);
  EXPECT_EQ(r.cases, 120);
  EXPECT_EQ(r.not_expressed, 0) << "the generators draw finite sets only";
  EXPECT_EQ(r.point_set_figures.subject, "production-triangles");
  EXPECT_EQ(r.point_set_figures.sets, r.cases);
  EXPECT_GT(r.point_set_figures.cgal_us, 0);
}

TEST(PointSetDoor, LostTriangleCaughtShrunkAndReplayed) {
  // Drops the last triangle of any triangulation with more than two.
  const auto lossy = subject<kDelaunay>("drops-a-triangle", [](const Points& p) {
    auto t = production_triangles(p);
    if (t.size() > 2) t.pop_back();
    return t;
  });
  VerifyOptions opt = quiet_options("ps-lossy");
  const VerifyResult r = verify(lossy, opt);
  testing::expect_caught_only_as(r, "valid");
  for (const auto& f : r.saved) {
    const PointSetParseResult pr = load_point_set(f);
    ASSERT_TRUE(pr.ok()) << pr.error;
    EXPECT_TRUE(std::filesystem::exists(std::filesystem::path(f).replace_extension(".html")));
  }
  // Shrunk: the saved sets are small (a lost triangle needs a handful of
  // points), one at least had points dropped; each still fails, and
  // production passes it.
  bool dropped = false;
  for (const auto& f : r.saved) {
    const PointSetParseResult pr = load_point_set(f);
    EXPECT_LE(pr.value.points.size(), 32u) << f;
    dropped = dropped || pr.value.note.find("points dropped") != std::string::npos;
  }
  EXPECT_TRUE(dropped);
  EXPECT_EQ(replay(lossy, {r.saved.front()}), 1);
  EXPECT_EQ(replay(production_point_set(), {r.saved.front()}), 0);
  EXPECT_TRUE(std::filesystem::exists(opt.out / "report.json"));
}

TEST(PointSetDoor, IndexOutOfRangeIsInvalidNotACrash) {
  const auto wild = subject<kDelaunay>("wild-index", [](const Points& p) {
    auto t = production_triangles(p);
    if (!t.empty()) t[0][1] = static_cast<int>(p.size()) + 7;
    return t;
  });
  const VerifyResult r = verify(wild, quiet_options("ps-wild", 60));
  ASSERT_GT(r.failures, 0);
  EXPECT_EQ(r.by_property.count("valid"), 1u);
  EXPECT_EQ(r.by_property.size(), 1u);
}

TEST(PointSetDoor, CrashContainedInTheChild) {
  const auto crashes = subject<kDelaunay>("crashes-on-big-sets", [](const Points& p) {
    if (p.size() > 40) std::raise(SIGSEGV);
    return production_triangles(p);
  });
  const VerifyResult r = verify(crashes, quiet_options("ps-crash", 60));
  ASSERT_GT(r.failures, 0);
  EXPECT_EQ(r.by_property.count("subject-crashed"), 1u);
  EXPECT_EQ(r.by_property.size(), 1u);
  EXPECT_EQ(r.cases, r.point_set_figures.sets);
}

TEST(PointSetDoor, AnyInputClaimHeldOnNonFiniteSets) {
  // A set with a NaN, from a file: a subject that claims any input must
  // reject it; one that claims finite input only is not asked it.
  const std::filesystem::path dir = std::filesystem::path(::testing::TempDir()) / "ps-nan-files";
  std::filesystem::create_directories(dir);
  PointSetFile f;
  f.points = {{0, 0}, {1, 0}, {0, 1}, {std::nan(""), 2}, {1, 1}};
  f.found_by = "hand";
  std::string err;
  ASSERT_TRUE(save_point_set(dir / "nan.case", f, err)) << err;
  const auto answer = [](const Points& p) {
    return all_finite(p) ? production_triangles(p) : std::vector<std::array<int, 3>>{};
  };
  const auto careless = subject<kDelaunay>("accepts-nan", answer, PointSetClaims{true});
  const VerifyResult r = verify(careless, {dir / "nan.case"}, quiet_options("ps-nan"));
  EXPECT_EQ(r.not_expressed, 0);
  EXPECT_EQ(r.failures, 1);
  EXPECT_EQ(r.by_property.count("non-finite-input-accepted"), 1u);
  const auto finite_only = subject<kDelaunay>("finite-only", answer);
  const VerifyResult s = verify(finite_only, {dir / "nan.case"}, quiet_options("ps-nan-finite"));
  EXPECT_EQ(s.not_expressed, 1);
  EXPECT_EQ(s.failures, 0);
  // Production claims any input, and rejects it naming index 3.
  const VerifyResult prod = verify(production_point_set(), {dir / "nan.case"}, quiet_options("ps-nan-production"));
  EXPECT_EQ(prod.failures, 0);
  EXPECT_EQ(prod.cases, 1);
}

TEST(PointSetDoor, SecondsStopTheRun) {
  const auto mine = subject<kDelaunay>("production-triangles", production_triangles);
  VerifyOptions opt = quiet_options("ps-seconds", 500);
  opt.seconds = 1e-9;  // past before the first case
  const VerifyResult r = verify(mine, opt);
  EXPECT_LT(r.cases, 500);
  EXPECT_TRUE(r.point_set_figures.stopped_by_time);
  EXPECT_EQ(r.point_set_figures.sets, r.cases);
}

TEST(PointSetDoor, SecondsStopTheChildToo) {
  const auto slow = subject<kDelaunay>("slow", [](const Points& p) {
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    return production_triangles(p);
  });
  VerifyOptions opt = quiet_options("ps-seconds-child", 200);
  opt.seconds = 0.3;
  const VerifyResult r = verify(slow, opt);
  EXPECT_GT(r.cases, 0);
  EXPECT_LT(r.cases, 200);
  EXPECT_EQ(r.failures, 0) << "stopping by the clock is no failure";
  EXPECT_TRUE(r.point_set_figures.stopped_by_time);
}

// A subject that fails on a set and crashes on the smaller sets its shrink
// asks: the set's failure is counted and saved as found, not lost to the
// crash.
TEST(PointSetDoor, CrashWhileShrinkingLosesNothing) {
  const std::filesystem::path dir = std::filesystem::path(::testing::TempDir()) / "ps-crash-shrink-files";
  std::filesystem::create_directories(dir);
  PointSetFile f;
  for (int x = 0; x < 5; ++x)
    for (int y = 0; y < 4; ++y) f.points.push_back({x + 0.25 * y, y + 0.125 * x * x});
  f.found_by = "hand";
  std::string err;
  ASSERT_TRUE(save_point_set(dir / "grid.case", f, err)) << err;
  const auto fragile = subject<kDelaunay>("crashes-on-small-sets", [](const Points& p) {
    if (p.size() < 20) std::raise(SIGSEGV);
    auto t = production_triangles(p);
    t.pop_back();
    return t;
  });
  const VerifyResult r = verify(fragile, {dir / "grid.case"}, quiet_options("ps-crash-shrink"));
  EXPECT_EQ(r.cases, 1);
  EXPECT_EQ(r.failures, 1);
  EXPECT_EQ(r.by_property.count("valid"), 1u);
  EXPECT_EQ(r.by_property.count("subject-crashed"), 0u);
  ASSERT_EQ(r.saved.size(), 1u);
  EXPECT_EQ(load_point_set(r.saved.front()).value.points.size(), 20u) << "saved as found";
}

TEST(PointSetDoor, FileOfAnotherQueryRefused) {
  const auto mine = subject<kDelaunay>("production-triangles", production_triangles);
  const std::filesystem::path pair =
      std::filesystem::path(GEOMCHECK_SOURCE_DIR) / "corpora/seeds/collide_cylinder_sphere";
  std::filesystem::path file;
  for (const auto& e : std::filesystem::directory_iterator(pair))
    if (e.path().extension() == ".case") file = e.path();
  ASSERT_FALSE(file.empty());
  const std::string program = "verify_point_set";
  std::vector<std::string> args{program, "--replay", file.string()};
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  EXPECT_EQ(verify(mine, static_cast<int>(argv.size()), argv.data()), 2);
}

}  // namespace
}  // namespace geomcheck
