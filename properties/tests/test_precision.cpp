// geomcheck — the precision table, measured: on a fixed seed, the worst
// observed error of every bound in tolerances.hpp must lie in
// [bound / 100, bound]. Above: production is less precise than claimed.
// Below: the bound is stale (far too loose) and must be tightened.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>

#include "geomcheck/properties/tolerances.hpp"
#include "suites.hpp"

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

struct Worst {
  double verdict = 0, depth = 0, normal = 0, point = 0, t = 0, unit = 0;
};

void take(double& w, double v) {
  if (v > w) w = v;  // NaN (not applicable) is ignored
}

template <QueryId Q>
Worst measure() {
  Worst w;
  const auto gen = Suite<Q>::targeted();
  rc::Random random(kSeed);
  for (int i = 0, n = cases(); i < n; ++i) {
    random.split();
    const auto c = gen(random.split(), 50).value().first;
    const Evaluation e = evaluate(c);
    if (!e.valid) continue;
    if (e.disagree) take(w.verdict, e.margin);
    take(w.depth, e.depth_err);
    take(w.normal, e.normal_err);
    take(w.point, e.point_err);
    take(w.t, e.t_err);
    take(w.unit, e.unit_err);
  }
  return w;
}

void expect_in_range(const char* query, const char* what, double worst, double bound) {
  std::printf("[precision] %-24s %-8s worst %.3e  bound %.1e\n", query, what, worst, bound);
  if (bound == 0) return;  // not a metric of this query
  EXPECT_LE(worst, bound) << query << " " << what << ": production is less precise than the table says";
  if (cases() < kCases) return;  // a partial sample: upper bounds only
  EXPECT_GE(worst, bound / 100) << query << " " << what << ": the bound is stale (worst " << worst
                                << " is below bound/100); tighten it in tolerances.hpp and the README";
}

template <QueryId Q>
void check_table() {
  const Worst w = measure<Q>();
  const Tolerances t = tolerances(Q);
  const char* n = info(Q).name;
  std::printf("[precision] seed %llu, %d cases%s\n", static_cast<unsigned long long>(kSeed), cases(),
              cases() < kCases ? " (partial sample: upper bounds only)" : "");
  expect_in_range(n, "verdict", w.verdict, t.verdict);
  expect_in_range(n, "depth", w.depth, t.depth);
  expect_in_range(n, "normal", w.normal, t.normal);
  expect_in_range(n, "point", w.point, t.point);
  expect_in_range(n, "t", w.t, t.t);
  expect_in_range(n, "unit", w.unit, t.unit);
}

TEST(precision, collide_cylinder_sphere) { check_table<QueryId::collide_cylinder_sphere>(); }
TEST(precision, cast_segment_cylinder) { check_table<QueryId::cast_segment_cylinder>(); }
TEST(precision, collide_cylinder_capsule) { check_table<QueryId::collide_cylinder_capsule>(); }
TEST(precision, sweep_sphere_cylinder) { check_table<QueryId::sweep_sphere_cylinder>(); }
TEST(precision, collide_cylinder_obb) { check_table<QueryId::collide_cylinder_obb>(); }

}  // namespace
}  // namespace geomcheck
