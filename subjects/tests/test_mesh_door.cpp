// geomcheck — the mesh door (verify.hpp, "The mesh family") tried as a user
// would: a user's brute force over the faces (production's triangle query
// on each face, the deepest kept: not production's hierarchy) passes under
// its own claims, and so does one that answers a contact one ulp off; a
// subject that keeps the first overlapping face instead of the deepest is
// caught as deepest-face, its meshes shrunk, saved, drawn and replayed; one
// that misses every contact is caught as oracle-verdict; one that crashes
// fails its mesh and the run goes on; invalid meshes are not asked of a
// subject that claims valid input only; files of another query are refused.
// Fixed seed (VerifyOptions' default).
#include <gtest/gtest.h>

#include <cmath>
#include <csignal>
#include <filesystem>
#include <string>
#include <vector>

#include "geomcheck/collide_cylinder_triangle.hpp"
#include "geomcheck/mesh_file.hpp"
#include "door_options.hpp"
#include "geomcheck/verify.hpp"

namespace geomcheck {
namespace {

constexpr MeshQueryId kMesh = MeshQueryId::collide_cylinder_mesh;

VerifyOptions quiet_options(const std::string& out, int cases = 150) { return testing::quiet_options(out, cases); }

/// A user's mesh query: every face asked in index order, the deepest
/// overlapping face kept (the first of equal depths), or with `first` the
/// first overlapping face.
Contact faces_one_by_one(const Cylinder& c, const TriangleMesh& m, std::uint32_t* face, bool first) {
  Contact best;
  for (std::uint32_t f = 0; f < m.size(); ++f) {
    const Triangle t = m.triangle(f);
    if (!overlap(c, t)) continue;
    const Contact k = collide(c, t);
    if (!best.hit || k.depth > best.depth) {
      best = k;
      if (face) *face = f;
      if (first) break;
    }
  }
  return best;
}

TEST(MeshDoor, UsersBruteForcePasses) {
  const auto mine = subject<kMesh>("faces-one-by-one", [](const Cylinder& c, const TriangleMesh& m, std::uint32_t* f) {
    return faces_one_by_one(c, m, f, false);
  });
  const VerifyResult r = verify(mine, quiet_options("mesh-brute"));
  EXPECT_EQ(r.failures, 0) << (r.by_property.empty() ? "" : r.by_property.begin()->first);
  EXPECT_GT(r.cases, 100);
  EXPECT_GT(r.not_expressed, 0) << "the generators draw invalid meshes, not asked of a valid-input subject";
  EXPECT_EQ(r.cases + r.not_expressed, 150);
  EXPECT_EQ(r.mesh_figures.under_test, "faces-one-by-one");
  EXPECT_EQ(r.mesh_figures.meshes, r.cases);
  EXPECT_GT(r.mesh_figures.faces_by_engine, 0u);
  EXPECT_GT(r.mesh_figures.verdicts.at("overlapping"), 10);
}

TEST(MeshDoor, OneUlpOffPassesInProcess) {
  const auto mine = subject<kMesh>("one-ulp-off", [](const Cylinder& c, const TriangleMesh& m, std::uint32_t* f) {
    Contact k = faces_one_by_one(c, m, f, false);
    if (k.hit) k.depth = std::nextafter(k.depth, INFINITY), k.point.z = std::nextafter(k.point.z, -INFINITY);
    return k;
  });
  VerifyOptions opt = quiet_options("mesh-ulp");
  opt.isolate = false;
  const VerifyResult r = verify(mine, opt);
  EXPECT_EQ(r.failures, 0) << (r.by_property.empty() ? "" : r.by_property.begin()->first);
}

TEST(MeshDoor, FirstFaceCaughtShrunkAndReplayed) {
  const auto first = subject<kMesh>("first-face", [](const Cylinder& c, const TriangleMesh& m, std::uint32_t* f) {
    return faces_one_by_one(c, m, f, true);
  });
  VerifyOptions opt = quiet_options("mesh-first", 300);
  const VerifyResult r = verify(first, opt);
  testing::expect_caught_only_as(r, "deepest-face");
  for (const auto& path : r.saved) {
    const MeshParseResult pr = load_mesh_file(path);
    ASSERT_TRUE(pr.ok()) << pr.error;
    EXPECT_GE(pr.value.faces.size(), 2u) << "a deeper face than the first stays";
    EXPECT_TRUE(std::filesystem::exists(std::filesystem::path(path).replace_extension(".html")));
  }
  EXPECT_EQ(replay(first, r.saved), static_cast<int>(r.saved.size())) << "each saved mesh fails again";
  const auto right = subject<kMesh>("faces-one-by-one", [](const Cylinder& c, const TriangleMesh& m, std::uint32_t* f) {
    return faces_one_by_one(c, m, f, false);
  });
  EXPECT_EQ(replay(right, r.saved), 0) << "the deepest face's answer passes them";
  EXPECT_FALSE(r.mesh_figures.counterexamples.empty());
}

TEST(MeshDoor, MissesCaughtAsVerdict) {
  const auto blind = subject<kMesh>("never-hits", [](const Cylinder&, const TriangleMesh&, std::uint32_t*) {
    return Contact{};
  });
  const VerifyResult r = verify(blind, quiet_options("mesh-blind"));
  ASSERT_GT(r.failures, 0);
  EXPECT_EQ(r.by_property.count("oracle-verdict"), 1u);
}

TEST(MeshDoor, CrashFailsItsMeshAndTheRunGoesOn) {
  const auto crashy = subject<kMesh>("crashes-on-big-meshes", [](const Cylinder& c, const TriangleMesh& m, std::uint32_t* f) {
    if (m.size() > 200) std::raise(SIGSEGV);
    return faces_one_by_one(c, m, f, false);
  });
  const VerifyResult r = verify(crashy, quiet_options("mesh-crash"));
  ASSERT_GT(r.failures, 0);
  EXPECT_EQ(r.by_property.size(), 1u);
  EXPECT_GT(r.by_property.count("subject-crashed"), 0u);
  EXPECT_GT(r.cases, 100) << "the run went on after each crash";
}

TEST(MeshDoor, ProductionWithoutClaimsIsHeldToItsBits) {
  // Production and its known-wrong variant keep production's yardsticks.
  const VerifyResult ok = verify(production_mesh(), quiet_options("mesh-production", 60));
  EXPECT_EQ(ok.failures, 0);
  EXPECT_EQ(ok.not_expressed, 0) << "production answers invalid input too";
  const VerifyResult bad = verify(*mesh_subject("mesh_first_face"), quiet_options("mesh-variant", 300));
  EXPECT_GT(bad.by_property.count("deepest-face"), 0u);
}

TEST(MeshDoor, FileOfAnotherQueryIsAUsageError) {
  const auto mine = subject<kMesh>("faces-one-by-one", [](const Cylinder& c, const TriangleMesh& m, std::uint32_t* f) {
    return faces_one_by_one(c, m, f, false);
  });
  const std::string point_set = std::string(GEOMCHECK_SOURCE_DIR) + "/corpora/seeds/delaunay_2d/almost-collinear-one-ulp.case";
  std::vector<std::string> args{"verify-my-mesh", "--replay", point_set};
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  EXPECT_EQ(verify(mine, static_cast<int>(argv.size()), argv.data()), 2);
  const std::string mesh = std::string(GEOMCHECK_SOURCE_DIR) + "/corpora/seeds/collide_cylinder_mesh/cap-resting-on-square.case";
  args = {"verify-my-mesh", "--replay", mesh};
  argv.clear();
  for (auto& a : args) argv.push_back(a.data());
  EXPECT_EQ(verify(mine, static_cast<int>(argv.size()), argv.data()), 0);
}

}  // namespace
}  // namespace geomcheck
