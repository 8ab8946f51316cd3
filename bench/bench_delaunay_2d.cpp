// geomcheck benchmarks — delaunay_2d against CGAL's Delaunay_triangulation_2
// (Epick, range insert, which spatially sorts first) on the same inputs in
// the same run: 10^5 and 10^6 uniform points in the unit square, and the
// 1000 x 1000 integer grid. Every benchmark reports the peak heap of one
// construction (this program counts its own allocations), and after the
// run the time ratios geomcheck / CGAL are printed.
//
//   build/release/bench/bench_delaunay_2d [--benchmark_filter=...]
#include <benchmark/benchmark.h>
#include <malloc.h>

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <atomic>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <new>
#include <random>
#include <string>
#include <vector>

#include "geomcheck/delaunay_2d.hpp"

// ---- heap accounting: current and peak bytes of this process ---------------

namespace {
std::atomic<std::int64_t> g_current{0}, g_peak{0};
void note_alloc(void* p) {
  if (!p) return;
  const std::int64_t now = g_current += static_cast<std::int64_t>(malloc_usable_size(p));
  std::int64_t peak = g_peak.load();
  while (now > peak && !g_peak.compare_exchange_weak(peak, now)) {
  }
}
void note_free(void* p) {
  if (p) g_current -= static_cast<std::int64_t>(malloc_usable_size(p));
}
void* counted_new(std::size_t n) {
  void* p = std::malloc(n ? n : 1);
  if (!p) throw std::bad_alloc();
  note_alloc(p);
  return p;
}
}  // namespace

void* operator new(std::size_t n) { return counted_new(n); }
void* operator new[](std::size_t n) { return counted_new(n); }
void operator delete(void* p) noexcept { note_free(p), std::free(p); }
void operator delete[](void* p) noexcept { note_free(p), std::free(p); }
void operator delete(void* p, std::size_t) noexcept { note_free(p), std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { note_free(p), std::free(p); }

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using DT = CGAL::Delaunay_triangulation_2<K>;
using geomcheck::Vec2;

constexpr std::uint64_t kSeed = 20261124;

const std::vector<Vec2>& uniform(std::size_t n) {
  static std::map<std::size_t, std::vector<Vec2>> cache;
  auto& p = cache[n];
  if (p.empty()) {
    std::mt19937_64 rng(kSeed);
    std::uniform_real_distribution<double> u(0, 1);
    p.resize(n);
    for (Vec2& q : p) q = {u(rng), u(rng)};
  }
  return p;
}

const std::vector<Vec2>& grid(int side) {
  static std::map<int, std::vector<Vec2>> cache;
  auto& p = cache[side];
  if (p.empty())
    for (int i = 0; i < side; ++i)
      for (int j = 0; j < side; ++j) p.push_back({double(i), double(j)});
  return p;
}

std::vector<K::Point_2> to_cgal(const std::vector<Vec2>& p) {
  std::vector<K::Point_2> out;
  out.reserve(p.size());
  for (const Vec2& q : p) out.emplace_back(q.x, q.y);
  return out;
}

// Peak heap of one construction above what was live before it, in MB.
template <class F>
double peak_mb(F&& build) {
  const std::int64_t base = g_current.load();
  g_peak = base;
  build();
  return static_cast<double>(g_peak.load() - base) / (1024.0 * 1024.0);
}

void run_geomcheck(benchmark::State& state, const std::vector<Vec2>& p) {
  std::size_t triangles = 0;
  for (auto _ : state) {
    const geomcheck::DelaunayTriangulation t = geomcheck::delaunay_2d(p);
    triangles = t.triangles.size();
    benchmark::DoNotOptimize(triangles);
  }
  state.counters["points"] = static_cast<double>(p.size());
  state.counters["triangles"] = static_cast<double>(triangles);
  state.counters["peak_MB"] = peak_mb([&] { benchmark::DoNotOptimize(geomcheck::delaunay_2d(p).triangles.size()); });
}

void run_cgal(benchmark::State& state, const std::vector<Vec2>& p) {
  const std::vector<K::Point_2> pts = to_cgal(p);
  std::size_t faces = 0;
  for (auto _ : state) {
    DT dt;
    dt.insert(pts.begin(), pts.end());
    faces = dt.number_of_faces();
    benchmark::DoNotOptimize(faces);
  }
  state.counters["points"] = static_cast<double>(p.size());
  state.counters["triangles"] = static_cast<double>(faces);
  state.counters["peak_MB"] = peak_mb([&] {
    DT dt;
    dt.insert(pts.begin(), pts.end());
    benchmark::DoNotOptimize(dt.number_of_faces());
  });
}

void BM_geomcheck_uniform(benchmark::State& s) { run_geomcheck(s, uniform(static_cast<std::size_t>(s.range(0)))); }
void BM_cgal_uniform(benchmark::State& s) { run_cgal(s, uniform(static_cast<std::size_t>(s.range(0)))); }
void BM_geomcheck_grid(benchmark::State& s) { run_geomcheck(s, grid(static_cast<int>(s.range(0)))); }
void BM_cgal_grid(benchmark::State& s) { run_cgal(s, grid(static_cast<int>(s.range(0)))); }

BENCHMARK(BM_geomcheck_uniform)->Arg(100000)->Arg(1000000)->Unit(benchmark::kMillisecond)->MinTime(2.0);
BENCHMARK(BM_cgal_uniform)->Arg(100000)->Arg(1000000)->Unit(benchmark::kMillisecond)->MinTime(2.0);
BENCHMARK(BM_geomcheck_grid)->Arg(1000)->Unit(benchmark::kMillisecond)->MinTime(2.0);
BENCHMARK(BM_cgal_grid)->Arg(1000)->Unit(benchmark::kMillisecond)->MinTime(2.0);

// Keeps the per-run real time and peak memory for the ratio table.
class Capture : public benchmark::ConsoleReporter {
 public:
  std::map<std::string, std::pair<double, double>> runs;  // name -> (ms, peak MB)
  void ReportRuns(const std::vector<Run>& rs) override {
    for (const Run& r : rs) {
      if (r.error_occurred || r.run_type != Run::RT_Iteration) continue;
      const auto peak = r.counters.find("peak_MB");
      std::string name = r.benchmark_name();
      name = name.substr(0, name.find("/min_time"));
      runs[name] = {r.GetAdjustedRealTime(), peak == r.counters.end() ? 0.0 : double(peak->second)};
    }
    ConsoleReporter::ReportRuns(rs);
  }
};

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  std::printf("delaunay_2d vs CGAL Delaunay_triangulation_2 (Epick, range insert); points seed %llu\n",
              static_cast<unsigned long long>(kSeed));
  Capture reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  std::printf("\n%-22s %12s %12s %8s %14s %14s\n", "input", "geomcheck ms", "CGAL ms", "ratio", "geomcheck MB", "CGAL MB");
  const std::pair<const char*, const char*> rows[] = {{"uniform/100000", "uniform 10^5"},
                                                      {"uniform/1000000", "uniform 10^6"},
                                                      {"grid/1000", "grid 1000x1000"}};
  for (const auto& [suffix, label] : rows) {
    const auto g = reporter.runs.find(std::string("BM_geomcheck_") + suffix);
    const auto c = reporter.runs.find(std::string("BM_cgal_") + suffix);
    if (g == reporter.runs.end() || c == reporter.runs.end()) continue;
    std::printf("%-22s %12.1f %12.1f %8.2f %14.1f %14.1f\n", label, g->second.first, c->second.first,
                g->second.first / c->second.first, g->second.second, c->second.second);
  }
  std::printf("(ratio = geomcheck time / CGAL time; targets: <= 1 at uniform 10^6, <= 1.5 on the grid)\n");
  benchmark::Shutdown();
  return 0;
}
