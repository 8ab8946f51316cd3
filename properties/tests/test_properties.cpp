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

#define GEOMCHECK_X(id, kind, A, B, summary) GEOMCHECK_PROPERTY_TESTS(id)
GEOMCHECK_QUERY_LIST(GEOMCHECK_X)
#undef GEOMCHECK_X

}  // namespace
}  // namespace geomcheck
