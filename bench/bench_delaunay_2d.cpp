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
#include <cmath>
#include <cstdlib>
#include <map>
#include <new>
#include <random>
#include <string>
#include <vector>

#include "geomcheck/delaunay_2d.hpp"
#include "pointset_bench.hpp"

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

// ---- the same sets moved: speed as a function of the set's shape ------------
//
// Each set below is run as given and under exact transforms (every
// transformed coordinate representable, so the transformed set is the same
// configuration): scalings by 2^+-500 and 2^+-1000, a translation, a
// rotation by 90 degrees. The triangles are the same under each (a property
// of properties/ holds it); the time should be too.
//   ulp-grid   256 x 256 points at ulp offsets around (2.5, 2.5): every
//              in-circle test nearly degenerate (the robustness
//              literature's classroom example);
//   fixed-uniform  10^6 uniform points on the 2^-32 grid in [0, 1);
//   int-grid   the 1000 x 1000 integer grid;
//   huge-tiny  10^5 uniform points, half scaled by 2^+900 and half by 2^-900.
const std::vector<Vec2>& base_set(int set) {
  static std::map<int, std::vector<Vec2>> cache;
  auto& p = cache[set];
  if (!p.empty()) return p;
  std::mt19937_64 rng(kSeed + set);
  switch (set) {
    case 0:  // ulp-grid
      for (int i = -128; i < 128; ++i)
        for (int j = -128; j < 128; ++j) p.push_back({2.5 + i * 0x1p-51, 2.5 + j * 0x1p-51});
      break;
    case 1:  // fixed-uniform
      p.resize(1000000);
      for (Vec2& q : p) q = {std::ldexp(double(rng() >> 32), -32), std::ldexp(double(rng() >> 32), -32)};
      break;
    case 2:  // int-grid
      p = grid(1000);
      break;
    default: {  // huge-tiny
      p.resize(100000);
      std::uniform_real_distribution<double> u(0, 1);
      for (std::size_t k = 0; k < p.size(); ++k) {
        const int e = k % 2 ? 900 : -900;
        p[k] = {std::ldexp(u(rng), e), std::ldexp(u(rng), e)};
      }
    }
  }
  return p;
}
constexpr const char* kSetNames[] = {"ulp-grid", "fixed-uniform", "int-grid", "huge-tiny"};
constexpr const char* kMoveNames[] = {"as-given", "x2^500", "x2^-500", "x2^1000", "x2^-1000", "translated", "rotated90"};

// Set `set` under move `move` (all exact for the sets above; huge-tiny is
// run as given only).
std::vector<Vec2> moved(int set, int move) {
  std::vector<Vec2> p = base_set(set);
  const int scale[] = {0, 500, -500, 1000, -1000};
  for (Vec2& q : p) {
    if (move >= 1 && move <= 4) {
      q = {std::ldexp(q.x, scale[move]), std::ldexp(q.y, scale[move])};
    } else if (move == 5) {
      const double t = set == 0 ? -2.0 : (set == 1 ? 3.0 : 1048576.0);  // exact: 0.5 +- 2^-44, [3, 4), integers
      q = {q.x + t, q.y + t};
    } else if (move == 6) {
      q = {-q.y, q.x};
    }
  }
  return p;
}

void BM_moved(benchmark::State& s, bool cgal) {
  const std::vector<Vec2> p = moved(static_cast<int>(s.range(0)), static_cast<int>(s.range(1)));
  s.SetLabel(std::string(kSetNames[s.range(0)]) + " " + kMoveNames[s.range(1)]);
  if (cgal) run_cgal(s, p);
  else run_geomcheck(s, p);
}
void BM_geomcheck_moved(benchmark::State& s) { BM_moved(s, false); }
void BM_cgal_moved(benchmark::State& s) { BM_moved(s, true); }
void moved_args(benchmark::internal::Benchmark* b) {
  for (int set = 0; set < 3; ++set)
    for (int move = 0; move < 7; ++move) b->Args({set, move});
  b->Args({3, 0});
}
BENCHMARK(BM_geomcheck_moved)->Apply(moved_args)->Unit(benchmark::kMillisecond)->Iterations(3);
BENCHMARK(BM_cgal_moved)->Apply(moved_args)->Unit(benchmark::kMillisecond)->Iterations(3);

BENCHMARK(BM_geomcheck_uniform)->Arg(100000)->Arg(1000000)->Unit(benchmark::kMillisecond)->MinTime(2.0);
BENCHMARK(BM_cgal_uniform)->Arg(100000)->Arg(1000000)->Unit(benchmark::kMillisecond)->MinTime(2.0);
BENCHMARK(BM_geomcheck_grid)->Arg(1000)->Unit(benchmark::kMillisecond)->MinTime(2.0);
BENCHMARK(BM_cgal_grid)->Arg(1000)->Unit(benchmark::kMillisecond)->MinTime(2.0);

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  std::printf("delaunay_2d vs CGAL Delaunay_triangulation_2 (Epick, range insert); points seed %llu\n",
              static_cast<unsigned long long>(kSeed));
  Capture reporter("/min_time");
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
  // The moved sets: time against the set as given (target: within 1.2x),
  // and against CGAL on the same moved set.
  bool header = false;
  for (int set = 0; set < 4; ++set)
    for (int move = 0; move < 7; ++move) {
      const std::string args = "/" + std::to_string(set) + "/" + std::to_string(move) + "/iterations:3";
      const auto g = reporter.runs.find("BM_geomcheck_moved" + args);
      const auto c = reporter.runs.find("BM_cgal_moved" + args);
      const auto g0 = reporter.runs.find("BM_geomcheck_moved/" + std::to_string(set) + "/0/iterations:3");
      if (g == reporter.runs.end() || c == reporter.runs.end() || g0 == reporter.runs.end()) continue;
      if (!header)
        std::printf("\n%-26s %12s %14s %12s %10s\n", "set, moved", "geomcheck ms", "vs as given", "CGAL ms", "vs CGAL");
      header = true;
      std::printf("%-26s %12.1f %14.2f %12.1f %10.2f\n",
                  (std::string(kSetNames[set]) + " " + kMoveNames[move]).c_str(), g->second.first,
                  g->second.first / g0->second.first, c->second.first, g->second.first / c->second.first);
    }
  if (header)
    std::printf("(vs as given: this move's time / the set as given, target <= 1.2; huge-tiny: vs CGAL, target <= 10)\n");
  benchmark::Shutdown();
  return 0;
}
