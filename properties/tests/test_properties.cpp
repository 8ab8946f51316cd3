// geomcheck — the generic properties of every registered query, run by
// RapidCheck over the targeted generators of each query's spec.
#include <gtest/gtest.h>

#include "geomcheck/properties/spec.hpp"
#include "support.hpp"

namespace geomcheck {
namespace {

template <QueryId Q>
void run(const std::string& what, const std::function<CheckResult(const typename Spec<Q>::Case&)>& check,
         const rc::Gen<std::pair<typename Spec<Q>::Case, std::string>>& gen = Spec<Q>::targeted()) {
  const std::string name = std::string(info(Q).name) + "." + what;
  const PropertyRun r = run_property<Q>(name, gen, check, [](const auto& c) { return Spec<Q>::hit(c); });
  expect_passed(r, name);
}

template <QueryId Q>
void all_moves(const std::string& what) {
  run<Q>(what, [](const auto& c) -> CheckResult {
    for (int m = 0; m < kNumMoves; ++m)
      if (auto f = check_metamorphic(c, m)) return f;
    return std::nullopt;
  });
}

#define GEOMCHECK_PROPERTY_TESTS(Q)                                                                              \
  TEST(Q, oracle_agreement) { run<QueryId::Q>("oracle_agreement", [](const auto& c) { return check_oracle(c); }); } \
  TEST(Q, consistency) { run<QueryId::Q>("consistency", [](const auto& c) { return check_consistency(c); }); }      \
  TEST(Q, symmetry) { run<QueryId::Q>("symmetry", [](const auto& c) { return check_symmetry(c); }); }               \
  TEST(Q, metamorphic) { all_moves<QueryId::Q>("metamorphic"); }                                                    \
  TEST(Q, monotone) { run<QueryId::Q>("monotone", [](const auto& c) { return check_monotone(c); }); }               \
  TEST(Q, robust) {                                                                                                \
    run<QueryId::Q>("robust", [](const auto& c) { return check_robust(c); }, Spec<QueryId::Q>::robust());            \
  }

// evaluate() keeps the thread's last evaluations (set_evaluation_memo),
// keyed by all an evaluation depends on. One case, asked on one thread of
// production and then of subjects that differ from it in one thing each (a
// deeper contact, the overlap denied, a claimed margin): each gets the
// evaluation of its own answers, never the one kept for production's.
TEST(EvaluationMemo, KeyedByTheSubjectsAnswersAndClaims) {
  constexpr QueryId Q = QueryId::collide_cylinder_sphere;
  using Impl = ImplOf<Q>;
  set_evaluation_memo(true);
  // Overlapping by 0.5 along +x: the sphere's centre 1.5 from the axis.
  const CylinderSphereCase c{Cylinder{{0, 0, 0}, {0, 0, 2}, 1}, Sphere{{1.5, 0, 1}, 1}};
  const Evaluation prod = evaluate(c);
  ASSERT_TRUE(prod.valid && prod.prod_hit && prod.truth_hit);
  ASSERT_FALSE(prod.disagree);
  ASSERT_LE(prod.depth_err, 1e-15);

  static auto deeper = [](const Cylinder& a, const Sphere& b) {
    Contact k = collide(a, b);
    k.depth += 0.25;
    return k;
  };
  const Impl deep{"deeper", [](const Cylinder& a, const Sphere& b) { return overlap(a, b); }, deeper};
  const Evaluation e_deep = evaluate(c, deep);
  EXPECT_GE(e_deep.depth_err, 0.2 / e_deep.scale) << "the deeper contact's own depth error";

  const Impl denies{"denies", [](const Cylinder&, const Sphere&) { return false; },
                    [](const Cylinder& a, const Sphere& b) { return collide(a, b); }};
  const Evaluation e_denies = evaluate(c, denies);
  EXPECT_FALSE(e_denies.prod_hit);
  EXPECT_TRUE(e_denies.disagree);
  EXPECT_FALSE(e_denies.excused) << "0.5 deep: far outside the verdict band";

  // The same answers as denies, with a claimed margin wider than the depth.
  static const Claims wide = [] {
    Claims k = Spec<Q>::claims();
    k.margin = 1;
    return k;
  }();
  Impl denies_wide = denies;
  denies_wide.claims = &wide;
  const Evaluation e_wide = evaluate(c, denies_wide);
  EXPECT_TRUE(e_wide.disagree);
  EXPECT_TRUE(e_wide.excused) << "a disagreement within the claimed margin";

  // And production again: its own evaluation, as before.
  const Evaluation again = evaluate(c);
  EXPECT_FALSE(again.disagree);
  EXPECT_EQ(again.depth_err, prod.depth_err);
}

#define GEOMCHECK_X(id, kind, A, B, summary) GEOMCHECK_PROPERTY_TESTS(id)
GEOMCHECK_QUERY_LIST(GEOMCHECK_X)
#undef GEOMCHECK_X

}  // namespace
}  // namespace geomcheck
