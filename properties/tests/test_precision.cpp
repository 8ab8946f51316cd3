// geomcheck — the precision table, measured: on a fixed seed, the worst
// observed error of every bound of production (each query's spec) must lie in
// [bound / 100, bound]. Above: production is less precise than claimed.
// Below: the bound is stale (far too loose) and must be tightened.
#include <gtest/gtest.h>

#include <cstdio>
#include <cmath>
#include <cstdlib>
#include <string>

#include "geomcheck/properties/tolerances.hpp"
#include "geomcheck/properties/spec.hpp"
#include "support.hpp"

namespace geomcheck {
namespace {

constexpr std::uint64_t kSeed = 20261121;
constexpr int kCases = 20000;

// The table is calibrated on kCases cases. Fewer cases (the environment
// variable GEOMCHECK_PRECISION_CASES, or the build's cache variable of that
// name: the sanitizer build, same code, same numbers, 10x slower) check only
// the upper bounds: a sample too small to reach the worst cases cannot call
// a bound stale.
#ifndef GEOMCHECK_PRECISION_CASES_BUILD
#define GEOMCHECK_PRECISION_CASES_BUILD kCases
#endif
int cases() {
  const char* v = std::getenv("GEOMCHECK_PRECISION_CASES");
  const int n = v ? std::atoi(v) : GEOMCHECK_PRECISION_CASES_BUILD;
  return n > 0 && n < kCases ? n : kCases;
}

/// The worst error of each metric; where one exceeds its bound, the case
/// that reached it is saved as a case file (the path is printed).
struct Worst {
  double v[6] = {0, 0, 0, 0, 0, 0};
  std::string where[6];
};
constexpr const char* kMetric[6] = {"verdict", "depth", "normal", "point", "t", "unit"};

double bound_of(const Tolerances& t, int k) {
  const double b[6] = {t.verdict, t.depth, t.normal, t.point, t.t, t.unit};
  return b[k];
}

template <QueryId Q>
Worst measure() {
  Worst w;
  const auto gen = Spec<Q>::targeted();
  const Tolerances tol = tolerances(Q);
  rc::Random random(kSeed);
  for (int i = 0, n = cases(); i < n; ++i) {
    random.split();
    const auto c = gen(random.split(), 50).value().first;
    const Evaluation e = evaluate(c);
    if (!e.valid) continue;
    const double err[6] = {e.disagree ? e.margin : NAN, e.depth_err, e.normal_err, e.point_err, e.t_err, e.unit_err};
    for (int k = 0; k < 6; ++k) {
      if (!(err[k] > w.v[k])) continue;  // NaN (not applicable) is ignored
      w.v[k] = err[k];
      if (err[k] > bound_of(tol, k) && bound_of(tol, k) > 0)
        w.where[k] = save_counterexample(
            from_case<Q>(c, "precision table seed " + std::to_string(kSeed) + " case " + std::to_string(i), "",
                         std::string(kMetric[k]) + " error " + std::to_string(err[k]) + " * scale"),
            std::string(info(Q).name) + "_precision_" + kMetric[k]);
    }
  }
  return w;
}

void expect_in_range(const char* query, const char* what, double worst, double bound, const std::string& where = "") {
  std::printf("[precision] %-24s %-8s worst %.3e  bound %.1e\n", query, what, worst, bound);
  if (bound == 0) return;  // not a metric of this query
  EXPECT_LE(worst, bound) << query << " " << what << ": production is less precise than the table says"
                          << (where.empty() ? "" : "; the worst case is saved as " + where);
  if (cases() < kCases) return;  // a partial sample: upper bounds only
  EXPECT_GE(worst, bound / 100) << query << " " << what << ": the bound is stale (worst " << worst
                                << " is below bound/100); tighten it in the query's spec (checks_<id>.cpp) and docs/tolerances.md";
}

template <QueryId Q>
void check_table() {
  const Worst w = measure<Q>();
  const Tolerances t = tolerances(Q);
  const char* n = info(Q).name;
  std::printf("[precision] seed %llu, %d cases%s\n", static_cast<unsigned long long>(kSeed), cases(),
              cases() < kCases ? " (partial sample: upper bounds only)" : "");
  for (int k = 0; k < 6; ++k) expect_in_range(n, kMetric[k], w.v[k], bound_of(t, k), w.where[k]);
}

// One test per registered query (its row of bounds, in its spec).
#define GEOMCHECK_X(id, kind, A, B, summary) \
  TEST(precision, id) { check_table<QueryId::id>(); }
GEOMCHECK_QUERY_LIST(GEOMCHECK_X)
#undef GEOMCHECK_X

}  // namespace
}  // namespace geomcheck
