// geomcheck — no false alarm on correct code: the reference subjects
// (reference_subjects.hpp: user-style code, correct but not exact, in
// double and in float, each declaring only its precision) hold every
// property on GEOMCHECK_REFERENCE_CASES cases of each of three seeds, and
// their known-wrong siblings fail the property that names their flaw.
// Each run is one ctest test (GEOMCHECK_REFERENCE_RUN=<subject>:<seed>, or
// all runs in turn without it); a failing case prints its replay command.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "reference_convex.hpp"

#ifndef GEOMCHECK_REFERENCE_CASES
#define GEOMCHECK_REFERENCE_CASES 2000
#endif
#ifndef GEOMCHECK_REFERENCE_ITERATIVE_CASES
#define GEOMCHECK_REFERENCE_ITERATIVE_CASES 1000
#endif
#ifndef GEOMCHECK_REFERENCE_PROXY_CASES
#define GEOMCHECK_REFERENCE_PROXY_CASES 300
#endif

namespace geomcheck {
namespace {

constexpr std::uint64_t kSeeds[] = {20261121, 7, 1234567};

VerifyOptions options(const std::string& name, std::uint64_t seed, int cases) {
  VerifyOptions opt;
  opt.cases = cases;
  opt.seed = seed;
  opt.out = std::filesystem::path(::testing::TempDir()) / ("geomcheck-reference-" + name + "-" + std::to_string(seed));
  std::filesystem::remove_all(opt.out);
  opt.program = "test_reference_subjects";
  opt.report = false;
  opt.isolate = false;  // correct code: no crash to contain, and the run is faster in process
  return opt;
}

int count(const VerifyResult& r, const std::string& property) {
  const auto it = r.by_property.find(property);
  return it == r.by_property.end() ? 0 : it->second;
}

/// Runs `subject` on every seed (or the one GEOMCHECK_REFERENCE_SEED names)
/// and expects no failing case.
template <class Subject>
void expect_clean(const Subject& s, const char* name, int cases = GEOMCHECK_REFERENCE_CASES) {
  const char* only = std::getenv("GEOMCHECK_REFERENCE_SEED");
  for (std::uint64_t seed : kSeeds) {
    if (only && std::to_string(seed) != only) continue;
    const VerifyResult r = verify(s, options(name, seed, cases));
    EXPECT_EQ(r.failures, 0) << name << " seed " << seed << ": " << r.failures << " failing cases (first: "
                             << (r.by_property.empty() ? "" : r.by_property.begin()->first) << ")";
    EXPECT_GT(r.cases, cases / 2) << "at least half the cases are stated by " << name;
    // The headroom: each error's worst case over its bound (in ulps of the scene).
    report::QueryReport f = r.figures;
    const double u = s.claims->precision.unit_roundoff;
    std::printf("%s seed %llu: %d of %d cases stated; worst error in ulps of the scene (bound): depth %.3g (%.3g), "
                "normal %.3g (%.3g), point %.3g (%.3g), t %.3g (%.3g)\n",
                name, static_cast<unsigned long long>(seed), r.cases, cases, f.depth.pct(1) / u, f.tol.depth / u, f.normal.pct(1) / u,
                f.tol.normal / u, f.point.pct(1) / u, f.tol.point / u, f.t.pct(1) / u, f.tol.t / u);
  }
}

TEST(Reference, SphereInDouble) { expect_clean(ref::sphere_subject<double>("ref-sphere-double"), "sphere-double"); }
TEST(Reference, SphereInFloat) { expect_clean(ref::sphere_subject<float>("ref-sphere-float"), "sphere-float"); }
TEST(Reference, CastInDouble) { expect_clean(ref::cast_subject<double>("ref-cast-double"), "cast-double"); }
TEST(Reference, CastInFloat) { expect_clean(ref::cast_subject<float>("ref-cast-float"), "cast-float"); }

// The engine-backed pairs by a user's general routine (reference_convex.hpp:
// GJK and EPA, conservative advancement), iterative, claiming its margin:
// GEOMCHECK_REFERENCE_ITERATIVE_CASES cases of each seed.
#define GEOMCHECK_ITERATIVE(id)                                                                                \
  TEST(ReferenceIterative, id##_double) {                                                                      \
    expect_clean(ref::convex_subject<QueryId::id, double>("gjk-epa-double"), #id "-double",                  \
                 GEOMCHECK_REFERENCE_ITERATIVE_CASES);                                                         \
  }                                                                                                            \
  TEST(ReferenceIterative, id##_float) {                                                                       \
    expect_clean(ref::convex_subject<QueryId::id, float>("gjk-epa-float"), #id "-float",                     \
                 GEOMCHECK_REFERENCE_ITERATIVE_CASES);                                                         \
  }
GEOMCHECK_ITERATIVE(collide_cylinder_capsule)
GEOMCHECK_ITERATIVE(collide_cylinder_obb)
GEOMCHECK_ITERATIVE(collide_cylinder_triangle)
GEOMCHECK_ITERATIVE(collide_cylinder_cylinder)
GEOMCHECK_ITERATIVE(penetration_cylinder_obb)
GEOMCHECK_ITERATIVE(penetration_cylinder_triangle)
#undef GEOMCHECK_ITERATIVE
TEST(ReferenceIterative, sweep_sphere_cylinder_double) {
  expect_clean(ref::advancing_sweep_subject<double>("advancing-double"), "sweep-double",
               GEOMCHECK_REFERENCE_ITERATIVE_CASES);
}
TEST(ReferenceIterative, sweep_sphere_cylinder_float) {
  expect_clean(ref::advancing_sweep_subject<float>("advancing-float"), "sweep-float",
               GEOMCHECK_REFERENCE_ITERATIVE_CASES);
}
// Spheres and capsules by a user's closest points of their cores (a point,
// a segment) with the radii added (reference_convex.hpp's collide_rounded):
// closed form, so GEOMCHECK_REFERENCE_CASES cases of each seed.
#define GEOMCHECK_ROUNDED(id)                                                                                       \
  TEST(ReferenceRounded, id##_double) {                                                                           \
    expect_clean(ref::convex_subject<QueryId::id, double>("closest-points-double"), #id "-double");              \
  }                                                                                                               \
  TEST(ReferenceRounded, id##_float) {                                                                            \
    expect_clean(ref::convex_subject<QueryId::id, float>("closest-points-float"), #id "-float");                 \
  }
GEOMCHECK_ROUNDED(collide_sphere_sphere)
GEOMCHECK_ROUNDED(collide_sphere_capsule)
GEOMCHECK_ROUNDED(collide_capsule_capsule)
#undef GEOMCHECK_ROUNDED
// Its sibling: the closest points of parallel segments divided by zero.
TEST(ReferenceRounded, SiblingCaught) {
  const VerifyResult r = verify(
      ref::convex_subject<QueryId::collide_capsule_capsule, double>("closest-points-unguarded", ref::Flaw::Unguarded),
      options("closest-points-unguarded", kSeeds[0], GEOMCHECK_REFERENCE_SIBLING_CASES));
  EXPECT_GT(r.failures, 0) << "the closest points of parallel segments unguarded";
}

// Their siblings: the cylinder taken as a capsule, the advancement stopped
// a million times too early.
TEST(ReferenceIterative, SiblingsCaught) {
  const int n = GEOMCHECK_REFERENCE_SIBLING_CASES;
  const VerifyResult capsule = verify(
      ref::convex_subject<QueryId::collide_cylinder_obb, double>("gjk-rounded-caps", ref::Flaw::RoundedCaps),
      options("gjk-rounded-caps", kSeeds[0], n));
  EXPECT_GT(count(capsule, "oracle-verdict"), 0) << "the cylinder taken as a capsule";
  const VerifyResult early = verify(ref::advancing_sweep_subject<double>("advancing-loose", true),
                                    options("advancing-loose", kSeeds[0], n));
  EXPECT_GT(count(early, "oracle-t"), 0) << "the advancement stopped early";
}

// Production as another engine sees the scene, for every registered pair
// query: in float (input and answer rounded to float) and in double (input
// one ulp off), GEOMCHECK_REFERENCE_PROXY_CASES cases of each seed.
template <QueryId Q, class T>
void expect_proxy_clean(const char* name) {
  const char* only = std::getenv("GEOMCHECK_REFERENCE_SEED");
  const auto s = ref::production_seen_in<Q, T>(name);
  for (std::uint64_t seed : kSeeds) {
    if (only && std::to_string(seed) != only) continue;
    const VerifyResult r = verify<Q>(s, options(name, seed, GEOMCHECK_REFERENCE_PROXY_CASES));
    EXPECT_EQ(r.failures, 0) << name << " seed " << seed << ": " << r.failures << " failing cases (first: "
                             << (r.by_property.empty() ? "" : r.by_property.begin()->first) << ")";
    EXPECT_GT(r.cases, GEOMCHECK_REFERENCE_PROXY_CASES * 8 / 10) << "most cases are stated by " << name;
  }
}
/// The float bounds are wide, not blind: production seen in float, its
/// first shape stretched by 2^-10 (about 16 times float's default bound),
/// fails.
template <QueryId Q>
void expect_stretch_caught_in_float() {
  const auto s = ref::production_seen_in<Q, float>("stretched-in-float", 1 + 0x1p-10);
  const VerifyResult r = verify<Q>(s, options(std::string("stretched-") + info(Q).name, kSeeds[0], GEOMCHECK_REFERENCE_SIBLING_CASES));
  EXPECT_GT(r.failures, 0) << "production seen in float with its first shape stretched by 2^-10 passes "
                           << info(Q).name;
}
#define GEOMCHECK_X(id, kind, A, B, summary)                                                          \
  TEST(ReferenceProxyFloat, id) { expect_proxy_clean<QueryId::id, float>("production-in-float-" #id); } \
  TEST(ReferenceProxyDouble, id) { expect_proxy_clean<QueryId::id, double>("production-ulp-off-" #id); } \
  TEST(ReferenceStretchedInFloat, id) { expect_stretch_caught_in_float<QueryId::id>(); }
GEOMCHECK_QUERY_LIST(GEOMCHECK_X)
#undef GEOMCHECK_X

// The siblings: each flaw caught, by the property that names it, in both
// precisions (the float bounds are wide, not blind).
template <class T>
void expect_siblings_caught() {
  const int n = GEOMCHECK_REFERENCE_SIBLING_CASES;
  const VerifyResult deep = verify(ref::sphere_subject<T>("ref-deep-point", ref::Flaw::DeepPointOnFace),
                                   options("deep-point", kSeeds[0], n));
  EXPECT_GT(count(deep, "oracle-point"), 0) << "the point on the nearest face, outside a small ball";
  const VerifyResult capsule = verify(ref::sphere_subject<T>("ref-rounded-caps", ref::Flaw::RoundedCaps),
                                      options("rounded-caps", kSeeds[0], n));
  EXPECT_GT(count(capsule, "oracle-verdict"), 0) << "the cylinder taken as a capsule";
  const VerifyResult nocaps = verify(ref::cast_subject<T>("ref-no-caps", ref::Flaw::NoCaps), options("no-caps", kSeeds[0], n));
  EXPECT_GT(count(nocaps, "oracle-verdict"), 0) << "the cast through an infinite cylinder";
}
TEST(Reference, SiblingsCaughtInDouble) { expect_siblings_caught<double>(); }
TEST(Reference, SiblingsCaughtInFloat) { expect_siblings_caught<float>(); }

// Float bounds derive from float's unit roundoff: production's counts of
// ulps, 2^29 times wider than production's own; a margin widens every
// scaled bound; production's are its table's.
TEST(Reference, BoundsDeriveFromThePrecision) {
  constexpr QueryId Q = QueryId::collide_cylinder_sphere;
  const Tolerances prod = tolerances(Q);
  const Tolerances same = bounds_of(Q, nullptr);
  EXPECT_EQ(same.verdict, prod.verdict);
  Claims f = production_claims<Q>();
  f.precision = Precision::single_precision(0);  // production's counts alone
  const Tolerances single = bounds_of(Q, &f);
  EXPECT_DOUBLE_EQ(single.verdict, prod.verdict * 0x1p29);
  EXPECT_DOUBLE_EQ(single.unit, prod.unit * 0x1p29);
  f.precision = Precision::single_precision(4096);
  EXPECT_DOUBLE_EQ(bounds_of(Q, &f).depth, 4096 * 0x1p-24);
  EXPECT_DOUBLE_EQ(bounds_of(QueryId::collide_cylinder_capsule, &f).normal, 1e-12 * 0x1p29)
      << "a claim below production's count keeps production's";
  Claims m = production_claims<Q>();
  m.margin = 1e-9;
  EXPECT_DOUBLE_EQ(bounds_of(Q, &m).point, prod.point + 1e-9);
  EXPECT_DOUBLE_EQ(bounds_of(Q, &m).unit, prod.unit);
  EXPECT_EQ(bounds_of(QueryId::cast_segment_cylinder, &m).depth, 0) << "no metric of a cast stays none";
}

}  // namespace
}  // namespace geomcheck
