// geomcheck benchmarks — shared pieces: the seed, the benchmarks of a
// query over a batch, the per-query time capture and the ratio table
// printed after the run.
//
// Every benchmark runs over the SAME pre-generated batch of inputs (one
// iteration = one pass over the batch) and reports items processed, so
// Google Benchmark's items_per_second and the `per_query` counter are per
// query. After the run, `print_summary` prints CPU ns/query per benchmark
// and the requested ratios (slower / faster).
#pragma once

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include <unistd.h>

namespace geomcheck::bench {

/// The default seed; GEOMCHECK_BENCH_SEED overrides it.
constexpr std::uint64_t kDefaultSeed = 0x6765'6f6d'6368'6b31ULL;  // "geomchk1"

inline std::uint64_t seed_from_env() {
  if (const char* s = std::getenv("GEOMCHECK_BENCH_SEED")) return std::strtoull(s, nullptr, 0);
  return kDefaultSeed;
}

/// "seed = <n> (0x<n>; GEOMCHECK_BENCH_SEED overrides)", as the programs print it.
inline std::string seed_text(std::uint64_t seed) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "seed = %llu (0x%llx; GEOMCHECK_BENCH_SEED overrides)",
                static_cast<unsigned long long>(seed), static_cast<unsigned long long>(seed));
  return buf;
}

/// Marks a benchmark's work: `batch` queries per iteration.
inline void set_per_query(benchmark::State& state, std::size_t batch) {
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()) * static_cast<std::int64_t>(batch));
  state.counters["per_query"] = benchmark::Counter(static_cast<double>(batch),
                                                   benchmark::Counter::kIsIterationInvariantRate |
                                                       benchmark::Counter::kInvert);
}

/// Times `query` on every item of `items`, one pass over them an iteration.
template <class T, class Query>
void time_each(benchmark::State& state, const std::vector<T>& items, const Query& query) {
  for (auto _ : state) {
    for (const T& x : items) benchmark::DoNotOptimize(query(x));
  }
  set_per_query(state, items.size());
}

/// Registers the benchmark `name`: time_each of `query` over `items`, which
/// must outlive the run.
template <class T, class Query>
benchmark::internal::Benchmark* register_each(const std::string& name, const std::vector<T>& items, Query query) {
  return benchmark::RegisterBenchmark(name.c_str(),
                                      [&items, query](benchmark::State& state) { time_each(state, items, query); });
}

/// "_<set>" appended to a benchmark's name, nothing for the unnamed set.
inline std::string set_suffix(const std::string& set) { return set.empty() ? "" : "_" + set; }

/// A ratio of the summary: its label and the benchmarks (slow, fast).
using Ratio = std::pair<std::string, std::pair<std::string, std::string>>;

/// "<query> fcl[-<variant>]/prod[ (<set>)]": BM_fcl_<query>[_<variant>][_<set>]
/// over BM_prod_<query>[_<set>].
inline Ratio fcl_over_prod(const std::string& query, const std::string& set = "", const std::string& variant = "") {
  return {query + " fcl" + (variant.empty() ? "" : "-" + variant) + "/prod" + (set.empty() ? "" : " (" + set + ")"),
          {"BM_fcl_" + query + set_suffix(variant) + set_suffix(set), "BM_prod_" + query + set_suffix(set)}};
}

/// "<query> exact-oracle/prod": BM_oracle_<query> over BM_prod_<query>.
inline Ratio oracle_over_prod(const std::string& query) {
  return {query + " exact-oracle/prod", {"BM_oracle_" + query, "BM_prod_" + query}};
}

/// Console output as usual, plus the CPU time per query of every run (CPU
/// rather than wall time: the ratios then hold on a shared machine too; the
/// `per_query` counter and items_per_second are CPU-time based as well).
class CaptureReporter : public benchmark::ConsoleReporter {
 public:
  explicit CaptureReporter(std::size_t batch)
      : ConsoleReporter(isatty(STDOUT_FILENO) ? OO_ColorTabular : OO_Tabular), batch_(batch) {}

  void ReportRuns(const std::vector<Run>& runs) override {
    for (const Run& r : runs) {
      if (r.error_occurred) continue;
      const bool median = r.run_type == Run::RT_Aggregate && r.aggregate_name == "median";
      if (r.run_type != Run::RT_Iteration && !median) continue;
      const auto b = batches_.find(r.run_name.function_name);
      const double ns = r.GetAdjustedCPUTime() / benchmark::GetTimeUnitMultiplier(r.time_unit) * 1e9 /
                        (b == batches_.end() ? static_cast<double>(batch_) : b->second);
      (median ? median_ : ns_)[r.run_name.function_name].push_back(ns);
    }
    ConsoleReporter::ReportRuns(runs);
  }

  /// A benchmark whose iteration is a pass over `batch` queries (on average)
  /// rather than the default batch; set before the benchmark's runs are
  /// reported (e.g. at the end of the benchmark function).
  void set_batch(const std::string& name, double batch) { batches_[name] = batch; }

  /// CPU time per query: the median aggregate when reported, else the median
  /// over repetitions; negative when the benchmark did not run (filtered
  /// out, or failed).
  double ns_per_query(const std::string& name) const {
    if (auto m = median_.find(name); m != median_.end() && !m->second.empty()) return m->second.back();
    auto it = ns_.find(name);
    if (it == ns_.end() || it->second.empty()) return -1;
    std::vector<double> v = it->second;
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
  }

  /// Names of the benchmarks that ran.
  std::vector<std::string> names() const {
    std::vector<std::string> out;
    for (const auto& [name, v] : ns_) out.push_back(name);
    for (const auto& [name, v] : median_)
      if (!ns_.count(name)) out.push_back(name);
    return out;
  }

 private:
  std::size_t batch_;
  std::map<std::string, double> batches_;              // per-benchmark batch, where not batch_
  std::map<std::string, std::vector<double>> ns_;      // per repetition
  std::map<std::string, std::vector<double>> median_;  // the median aggregate, when reported
};

/// Runs the registered benchmarks with a CaptureReporter.
inline int run_benchmarks(int argc, char** argv, CaptureReporter& reporter) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  benchmark::Shutdown();
  return 0;
}

/// Prints the ns/query table and "ratio <label> = <slow/fast>x" for each
/// (label, slow, fast) triple whose both benchmarks ran. Returns the ratios
/// by label (missing ones are absent).
inline std::map<std::string, double> print_summary(const CaptureReporter& rep, const std::vector<Ratio>& ratios) {
  std::printf("\n%-28s %12s\n", "benchmark", "CPU ns/query");
  for (const std::string& name : rep.names()) std::printf("%-28s %12.2f\n", name.c_str(), rep.ns_per_query(name));
  std::map<std::string, double> out;
  for (const auto& [label, pair] : ratios) {
    const double slow = rep.ns_per_query(pair.first), fast = rep.ns_per_query(pair.second);
    if (slow <= 0 || fast <= 0) {
      std::printf("ratio %s = n/a (%s or %s did not run)\n", label.c_str(), pair.first.c_str(), pair.second.c_str());
      continue;
    }
    out[label] = slow / fast;
    std::printf("ratio %s = %.1fx  (%.2f ns / %.2f ns)\n", label.c_str(), slow / fast, slow, fast);
  }
  return out;
}

/// The end of a program: runs the registered benchmarks, then prints the
/// ns/query table and `ratios` (print_summary), the measured ratios in
/// `*measured` when given. Returns main's exit code.
inline int run_and_summarise(int argc, char** argv, CaptureReporter& reporter, const std::vector<Ratio>& ratios,
                             std::map<std::string, double>* measured = nullptr) {
  if (int rc = run_benchmarks(argc, argv, reporter)) return rc;
  const std::map<std::string, double> out = print_summary(reporter, ratios);
  if (measured) *measured = out;
  return 0;
}

}  // namespace geomcheck::bench
