// geomcheck — properties of collide(Cylinder, TriangleMesh).
//
// The checks are mesh_checks.hpp's (what they hold is at its head), on the
// meshes of gen::meshes (generators.hpp); the face filter's soundness is
// driven here towards its margin, and every known-wrong variant of the
// query must be caught. A failure prints the mesh and cylinder in
// hexadecimal and the command that reruns the property.
#include <gtest/gtest.h>
#include <rapidcheck.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <cstdint>
#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

#include "geomcheck/properties/generators.hpp"
#include "geomcheck/collide_cylinder_mesh.hpp"
#include "geomcheck/collide_cylinder_triangle.hpp"
#include "geomcheck/properties/checks.hpp"
#include "geomcheck/properties/tolerances.hpp"
#include "support.hpp"

namespace geomcheck {
namespace {

std::string describe(const MeshCase& c) { return "[" + c.mode + "] " + describe_mesh(c.cyl, c.vertices, c.faces); }

struct Outcome {
  int cases = 0, hits = 0;
};

// Runs `check` (empty string: pass) over the generator; `per_mille` of the
// configured number of cases (RC_PARAMS' max_success, 20000 in the default
// preset, 2000 under the sanitizers and in --quick), at least 1 (0: all).
Outcome run(const char* name, int per_mille, bool grid,
            const std::function<std::string(const MeshCase&, const TriangleMesh&)>& check) {
  Outcome out;
  auto prop = [&] {
    const MeshCase c = *gen::meshes(grid);
    const TriangleMesh mesh(c.vertices, c.faces);
    ++out.cases;
    const bool hit = overlap(c.cyl, mesh);
    out.hits += hit;
    RC_TAG(hit ? "hit" : "miss");
    const std::string f = check(c, mesh);
    if (!f.empty()) RC_FAIL(f + "\n" + describe(c));
  };
  rc::detail::TestMetadata meta;
  meta.id = name;
  meta.description = name;
  const auto& config = rc::detail::configuration();
  auto params = config.testParams;
  if (per_mille > 0) params.maxSuccess = std::max(1, static_cast<int>(static_cast<long long>(params.maxSuccess) * per_mille / 1000));
  const auto result = rc::detail::checkTestable(prop, meta, params, listener(), config.reproduce);
  rc::detail::SuccessResult success;
  std::printf("[property] collide_cylinder_mesh.%s: %d cases, %d hits (seed %llu)\n", name, out.cases, out.hits,
              static_cast<unsigned long long>(params.seed));
  if (!result.match(success)) {
    std::ostringstream os;
    rc::detail::printResultMessage(result, os);
    ADD_FAILURE() << "collide_cylinder_mesh." << name << " failed:\n"
                  << os.str() << "\nrerun it:   RC_PARAMS=\"seed=" << params.seed
                  << "\" ./properties/tests/test_mesh --gtest_filter=collide_cylinder_mesh." << name;
  } else {
    EXPECT_GT(out.hits, out.cases / 10) << "too few overlapping cases";
    EXPECT_LT(out.hits, out.cases - out.cases / 10) << "too few separated cases";
  }
  return out;
}

// The consistency checks (mesh_checks.hpp): robustness, the brute force
// bit for bit, argument order, the deepest face's own contact.
TEST(collide_cylinder_mesh, consistency) {
  run("consistency", 0, true, [](const MeshCase& c, const TriangleMesh& m) -> std::string {
    if (auto f = check_mesh_consistency(c.cyl, m)) return f->property + ": " + f->detail;
    return {};
  });
}

// The face filter (mesh_face_gap) skips a face only when it is apart by
// more than its margin, far above its rounding: it must never skip a face
// the triangle query finds overlapping. Driven by the cylinder/triangle
// generator's near-degenerate cases (exact touches at caps, rims and sides,
// nudged by ulps), where the computed gap of an overlapping face comes
// within rounding of 0. The test prints how close the overlapping faces
// came to the margin, and holds that they came within 2^-40 of 0: a filter
// off by more than that (a margin of -2^-40, or a support term left out)
// would skip some of them and fail here.
TEST(collide_cylinder_mesh, face_filter_sound) {
  const double margin = detail::mesh_face_margin();
  double closest = -INFINITY;
  int cases = 0, overlapping = 0, above_zero = 0;
  const auto result = rc::check("face filter", [&] {
    const auto drawn = *gen::targeted<QueryId::collide_cylinder_triangle>();
    const Cylinder& cyl = drawn.first.a;
    const Triangle& t = drawn.first.b;
    ++cases;
    if (!overlap(cyl, t)) return;
    ++overlapping;
    const double g = detail::mesh_face_gap(cyl, t);
    closest = std::max(closest, g);
    above_zero += g > 0;
    RC_ASSERT(!(g > margin));
  });
  std::printf("[property] collide_cylinder_mesh.face_filter_sound: %d cases, %d overlapping; largest gap of an "
              "overlapping face %.3g (margin %.3g); %d above 0\n",
              cases, overlapping, closest, margin, above_zero);
  EXPECT_TRUE(result);
  EXPECT_GT(overlapping, cases / 10);
  EXPECT_GT(closest, -0x1p-40) << "no overlapping face came near the filter's threshold";
}

TEST(collide_cylinder_mesh, oracle_agreement) {
  // The engine face by face (those whose boxes meet the cylinder's): fewer
  // cases than the consistency property (1500 of the default preset's 20000).
  int by_box = 0, by_engine = 0;
  run("oracle_agreement", 75, true, [&](const MeshCase& c, const TriangleMesh& m) -> std::string {
    MeshTruth truth;
    if (auto f = check_mesh_all(c.cyl, m, production_mesh(), &truth)) return f->property + ": " + f->detail;
    by_box += truth.faces_by_box, by_engine += truth.faces_by_engine;
    return {};
  });
  std::printf("[property] collide_cylinder_mesh.oracle_agreement: faces separated by their boxes %d, by the engine %d\n",
              by_box, by_engine);
  EXPECT_GT(by_engine, 0);
}

/// What rc::check (under `label`) found holding generated meshes to
/// `check(case, mesh)`: whether every case passed, and the property of the
/// first failure and its case's number (from 1).
struct Caught {
  bool passed = true;
  std::string property;
  int at = 0;
};
template <class Check>
Caught first_caught(const std::string& label, Check&& check) {
  Caught out;
  int cases = 0;
  out.passed = rc::check(label, [&] {
    const MeshCase c = *gen::meshes(true);
    const TriangleMesh m(c.vertices, c.faces);
    ++cases;
    const CheckResult f = check(c, m);
    if (f && out.property.empty()) out.property = f->property, out.at = cases;
    RC_ASSERT(!f);
  });
  return out;
}

// Teeth: every known-wrong variant of the mesh query fails the checks on
// some generated case.
TEST(collide_cylinder_mesh, teeth) {
  for (const MeshImpl* v : mesh_variants()) {
    const Caught caught =
        first_caught(std::string("variant ") + v->name,
                     [&](const MeshCase& c, const TriangleMesh& m) { return check_mesh_consistency(c.cyl, m, *v); });
    std::printf("[teeth] %s: caught as '%s' at case %d\n", v->name, caught.property.c_str(), caught.at);
    EXPECT_FALSE(caught.passed) << v->name << " passed every check";
    // Caught by what it gets wrong, the deepest face (not by a comparison
    // with production's own answers).
    EXPECT_EQ(caught.property, "deepest-face");
  }
}

// A subject with claims of its own (the door's yardsticks, MeshClaims) is
// never held to production's bits: production held to production's claims
// as if it were a user's passes (no false alarm), and so does a correct
// subject that is not production bit for bit (production's answer moved by
// one ulp, its flipped order not given); the first-face variant, also held
// to its own claims, is caught by what it gets wrong, the deepest face, read
// against the faces' certified penetration depths.
MeshImpl with_claims(MeshImpl impl, const MeshClaims* claims) {
  impl.claims = claims;
  return impl;
}

TEST(collide_cylinder_mesh, own_claims_no_false_alarm) {
  static const MeshClaims claims{};
  const MeshImpl as_user = with_claims(production_mesh(), &claims);
  const MeshImpl ulp_off{"production-one-ulp-off", nullptr,
                         [](const Cylinder& a, const TriangleMesh& m, std::uint32_t* f) {
                           Contact k = collide(a, m, f);
                           if (k.hit) k.depth = std::nextafter(k.depth, INFINITY), k.point.x = std::nextafter(k.point.x, -INFINITY);
                           return k;
                         },
                         nullptr, &claims};
  run("own_claims_no_false_alarm", 50, true, [&](const MeshCase& c, const TriangleMesh& m) -> std::string {
    for (const MeshImpl* s : {&as_user, &ulp_off})
      if (auto f = check_mesh_all(c.cyl, m, *s)) return std::string(s->name) + ": " + f->property + ": " + f->detail;
    return {};
  });
}

TEST(collide_cylinder_mesh, own_claims_teeth) {
  static const MeshClaims claims{};
  for (const MeshImpl* v : mesh_variants()) {
    const MeshImpl as_user = with_claims(*v, &claims);
    const Caught caught = first_caught(std::string("variant with its own claims ") + v->name,
                                       [&](const MeshCase& c, const TriangleMesh& m) {
                                         return check_mesh_all(c.cyl, m, as_user);
                                       });
    std::printf("[teeth] %s with its own claims: caught as '%s' at case %d\n", v->name, caught.property.c_str(),
                caught.at);
    EXPECT_FALSE(caught.passed) << v->name << " passed every check of its own claims";
    EXPECT_EQ(caught.property, "deepest-face");
  }
}

TEST(collide_cylinder_mesh, invalid_input) {
  const Cylinder cyl{{0, 0, 0}, {0, 0, 1}, 1};
  const std::vector<Vec3> v{{0, 0, 0.5}, {1, 0, 0.5}, {0, 1, 0.5}};
  const TriangleMesh ok(v, {{0, 1, 2}});
  EXPECT_TRUE(overlap(cyl, ok));
  const TriangleMesh out_of_range(v, {{0, 1, 3}});
  EXPECT_FALSE(out_of_range.valid());
  EXPECT_FALSE(overlap(cyl, out_of_range));
  EXPECT_FALSE(collide(cyl, out_of_range).hit);
  const TriangleMesh nan_vertex({{0, 0, 0.5}, {NAN, 0, 0.5}, {0, 1, 0.5}}, {{0, 1, 2}});
  EXPECT_FALSE(nan_vertex.valid());
  EXPECT_FALSE(overlap(cyl, nan_vertex));
  const TriangleMesh empty;
  EXPECT_FALSE(overlap(cyl, empty));
  std::uint32_t idx = 7;
  EXPECT_FALSE(collide(cyl, empty, &idx).hit);
  EXPECT_EQ(idx, 7u);  // left alone on no hit
  EXPECT_FALSE(overlap(Cylinder{{0, 0, 0}, {0, 0, 1}, -1}, ok));
}

}  // namespace
}  // namespace geomcheck
