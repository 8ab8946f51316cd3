// geomcheck — bench_checks: the full check of one case (the truth, production
// held to it, every property: what a campaign does per case), per registered
// query, on one core, over the campaign's generator mix (the first N cases of
// `geomcheck campaign --seed 20261121`), two ways in the same run:
//   before  the engine without its double-double round, the cast's closed
//           form without its interval filter (oracle::set_cast_filter), and the truth asked
//           twice per case (evaluate, then check_all: as campaigns did), and
//           again by every check that compares the case with a moved copy;
//   after   the engine's cascade as built (interval filter, doubles,
//           double-double, then 128 and 384 digits), the cast's filter on, and the truth asked once
//           (check_all(c, e), and evaluate()'s memo: set_evaluation_memo).
// Both decide with certainty: only the speed differs. Printed after the
// benchmarks: cases per second of CPU time each way, their ratio, and the
// share of cases whose truth was decided at each stage of the cascade
// (after); then certified penetration depths per second at the width the
// checks ask (1e-20 * scale), with and without the double-double round, on
// the overlapping pairs among the first 1000 campaign cases of box, triangle
// and cylinder.
//   build/release/bench/bench_checks [--benchmark_filter=obb]
//   GEOMCHECK_BENCH_SLOWEST=10 build/release/bench/bench_checks ...  (also
//   lists the slowest cases of each "after" run)
#include <benchmark/benchmark.h>

#include <time.h>

#include <cstdio>
#include <cstdlib>
#include <tuple>
#include <algorithm>
#include <map>
#include <string>
#include <vector>

#include "geomcheck/oracles/cast_segment_cylinder.hpp"
#include "geomcheck/oracles/engine.hpp"
#include "geomcheck/properties/checks.hpp"
#include "geomcheck/properties/spec.hpp"

namespace {

using namespace geomcheck;
constexpr std::uint64_t kSeed = 20261121;

struct Figures {
  double before = 0, after = 0;  // cases per second
  int cases = 0;
  std::map<std::string, int> stages;
  std::map<std::string, int> stage_cases;       // cases decided at each stage, invalid inputs too (after)
  std::map<std::string, double> stage_seconds;  // their CPU time, whole check
};
std::map<std::string, Figures>& figures() {
  static std::map<std::string, Figures> f;
  return f;
}

/// The first n cases of the campaign's sequence for Q (tools/campaign.cpp).
template <QueryId Q>
std::vector<typename Spec<Q>::Case> campaign_cases(int n) {
  const auto gen = Spec<Q>::targeted();
  rc::Random random = geomcheck::gen::sequence<Q>(kSeed);
  std::vector<typename Spec<Q>::Case> out;
  for (int i = 0; i < n; ++i) out.push_back(gen(random.split(), 50).value().first);
  return out;
}

/// This thread's CPU time, in seconds (the machine may be busy).
double cpu_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return ts.tv_sec + ts.tv_nsec * 1e-9;
}

/// Every case once per iteration batch: the benchmark runs exactly the set.
template <QueryId Q>
void bm_check(benchmark::State& state, bool after, int n) {
  static const auto cases = campaign_cases<Q>(n);
  oracle::set_double_double_default(after);
  oracle::set_cast_filter(after);
  set_evaluation_memo(after);
  Figures& fig = figures()[info(Q).name];
  fig.cases = n;
  int failures = 0;
  std::map<std::string, int> stages;
  std::map<std::string, int> stage_cases;  // these two count the invalid inputs too
  std::map<std::string, double> stage_seconds;
  // GEOMCHECK_BENCH_SLOWEST=<n>: the n slowest cases of the "after" run
  // (index in the set, CPU time, stage, the truth's text), for profiling.
  const char* slow_env = std::getenv("GEOMCHECK_BENCH_SLOWEST");
  const int slowest = after && slow_env ? std::atoi(slow_env) : 0;
  std::vector<std::tuple<double, std::size_t, std::string, std::string>> slow;
  const double t0 = cpu_seconds();
  std::size_t done = 0;
  for (auto _ : state) {
    const std::size_t index = done % cases.size();
    const auto& c = cases[index];
    ++done;
    const double c0 = cpu_seconds();
    oracle::reset_deepest_stage();
    const Evaluation e = evaluate(c);
    const oracle::Stage st = oracle::deepest_stage();
    const CheckResult f = after ? check_all(c, e) : check_all(c);
    failures += f.has_value();
    const std::string stage = e.valid ? oracle::to_string(st) : std::string("invalid input");
    if (e.valid) ++stages[stage];
    ++stage_cases[stage];
    stage_seconds[stage] += cpu_seconds() - c0;
    if (slowest > 0) slow.emplace_back(cpu_seconds() - c0, index, stage, e.truth_text);
    benchmark::DoNotOptimize(e.truth_hit);
  }
  std::sort(slow.begin(), slow.end(), [](const auto& x, const auto& y) { return std::get<0>(x) > std::get<0>(y); });
  for (int i = 0; i < slowest && i < static_cast<int>(slow.size()); ++i)
    std::printf("slowest %s #%zu: %.2f ms, %s: %s\n", info(Q).name, std::get<1>(slow[i]), 1e3 * std::get<0>(slow[i]),
                std::get<2>(slow[i]).c_str(), std::get<3>(slow[i]).substr(0, 400).c_str());
  const double s = cpu_seconds() - t0;
  state.SetItemsProcessed(static_cast<std::int64_t>(done));
  state.counters["failures"] = failures;
  (after ? fig.after : fig.before) = done / s;
  if (after) fig.stages = stages, fig.stage_cases = stage_cases, fig.stage_seconds = stage_seconds;
  oracle::set_double_double_default(true);
  oracle::set_cast_filter(true);
  set_evaluation_memo(true);
}

/// Certified penetration depths at the width the checks ask (1e-20 *
/// scale), on the overlapping cases among the first `n` of Q's campaign
/// cases (a cylinder against a polytope-like shape), before and after.
struct DepthFigures {
  double before = 0, after = 0;
  int cases = 0;
};
std::map<std::string, DepthFigures>& depth_figures() {
  static std::map<std::string, DepthFigures> f;
  return f;
}

template <QueryId Q>
void bm_depth(benchmark::State& state, bool after, int n) {
  static const auto pairs = [n] {
    std::vector<std::pair<oracle::ConvexShape, oracle::ConvexShape>> out;
    for (const auto& c : campaign_cases<Q>(n)) {
      if (!is_valid(c.a) || !is_valid(c.b)) continue;
      auto a = oracle::make_shape(c.a), b = oracle::make_shape(c.b);
      if (oracle::classify(a, b).verdict == oracle::Verdict::Overlapping) out.emplace_back(std::move(a), std::move(b));
    }
    return out;
  }();
  DepthFigures& fig = depth_figures()[info(Q).name];
  fig.cases = static_cast<int>(pairs.size());
  if (pairs.empty()) {
    state.SkipWithError("no overlapping case");
    return;
  }
  const double t0 = cpu_seconds();
  std::size_t done = 0;
  int certified = 0;
  for (auto _ : state) {
    const auto& pr = pairs[done++ % pairs.size()];
    certified += oracle::penetration(pr.first, pr.second, 1e-20, after).overlapping;
  }
  (after ? fig.after : fig.before) = done / (cpu_seconds() - t0);
  state.SetItemsProcessed(static_cast<std::int64_t>(done));
  state.counters["certified"] = certified;
}

template <QueryId Q>
void register_depth(int n) {
  const std::string name = std::string("depth/") + info(Q).name;
  for (bool after : {false, true})
    benchmark::RegisterBenchmark((name + (after ? "/after" : "/before")).c_str(),
                                 [n, after](benchmark::State& s) { bm_depth<Q>(s, after, n); })
        ->Iterations(200)
        ->Unit(benchmark::kMicrosecond);
}

template <QueryId Q>
void register_query(int n) {
  const std::string name = std::string("check/") + info(Q).name;
  benchmark::RegisterBenchmark((name + "/before").c_str(), [n](benchmark::State& s) { bm_check<Q>(s, false, n); })
      ->Iterations(n)
      ->Unit(benchmark::kMicrosecond);
  benchmark::RegisterBenchmark((name + "/after").c_str(), [n](benchmark::State& s) { bm_check<Q>(s, true, n); })
      ->Iterations(n)
      ->Unit(benchmark::kMicrosecond);
}

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  std::printf("bench_checks: seed %llu; the first N cases of the campaign's generator mix per query, one core\n",
              static_cast<unsigned long long>(kSeed));
  for_each_query([](auto q) {
    constexpr QueryId Q = decltype(q)::value;
    // The engine-backed queries are 10-100 times slower per case than the
    // closed-form ones: 400 cases for a query whose truth reaches the
    // engine on a probe of 40, 20,000 for the others (decided by the truth's
    // stages, not by a timing, so every run times the same sets).
    const auto probe = campaign_cases<Q>(40);
    oracle::reset_deepest_stage();
    for (const auto& c : probe) benchmark::DoNotOptimize(evaluate(c).truth_hit);
    register_query<Q>(oracle::deepest_stage() == oracle::Stage::None ? 20000 : 400);
  });
  register_depth<QueryId::collide_cylinder_obb>(1000);
  register_depth<QueryId::collide_cylinder_triangle>(1000);
  register_depth<QueryId::collide_cylinder_cylinder>(1000);
  benchmark::RunSpecifiedBenchmarks();
  std::printf("\n%-26s %7s %12s %12s %7s  %s\n", "query", "cases", "before /s", "after /s", "ratio",
              "truth decided by (after)");
  for (const auto& [name, f] : figures()) {
    if (!(f.before > 0) || !(f.after > 0)) continue;
    std::string st;
    int n = 0;
    for (const auto& kv : f.stages) n += kv.second;
    for (const auto& [k, v] : f.stages) {
      char b[64];
      std::snprintf(b, sizeof b, "%s%s %.1f%%", st.empty() ? "" : ", ", k.c_str(), 100.0 * v / std::max(1, n));
      st += b;
    }
    std::printf("%-26s %7d %12.0f %12.0f %6.2fx  %s\n", name.c_str(), f.cases, f.before, f.after, f.after / f.before,
                st.c_str());
  }
  // Where the time goes (after): per stage of the cascade that decided the
  // case's truth, its share of the cases, its share of the CPU time, and
  // the cases per second among the cases it decided (the whole check).
  std::printf("\n%-26s %-16s %8s %8s %12s   (after: time per stage of the cascade)\n", "query", "decided by",
              "cases", "time", "cases/s");
  for (const auto& [name, f] : figures()) {
    if (!(f.after > 0) || f.stages.size() < 2) continue;
    int n = 0;
    double total = 0;
    for (const auto& kv : f.stage_cases) n += kv.second;
    for (const auto& kv : f.stage_seconds) total += kv.second;
    for (const auto& [k, v] : f.stage_cases) {
      const double sec = f.stage_seconds.at(k);
      std::printf("%-26s %-16s %7.1f%% %7.1f%% %12.0f\n", name.c_str(), k.c_str(), 100.0 * v / std::max(1, n),
                  100.0 * sec / total, sec > 0 ? v / sec : 0.0);
    }
  }
  std::printf("\n%-26s %7s %12s %12s %7s   (certified penetration depths at 1e-20 * scale)\n", "query",
              "pairs", "before /s", "after /s", "ratio");
  for (const auto& [name, f] : depth_figures())
    if (f.before > 0 && f.after > 0)
      std::printf("%-26s %7d %12.0f %12.0f %6.2fx\n", name.c_str(), f.cases, f.before, f.after, f.after / f.before);
  benchmark::Shutdown();
  return 0;
}
