// geomcheck benchmarks — delaunay_3d against CGAL's Delaunay_triangulation_3
// (Epick, range insert, which spatially sorts first) on the same inputs in
// the same run: 10^5 and 10^6 uniform points in a cube, the 100^3 integer
// grid (every cube's corners cospherical), 10^5 points rounded onto a
// sphere, and the uniform 10^6 scaled by 2^500 and 2^-500. Every benchmark
// reports the peak heap of one construction (this program counts its own
// allocations); after the run the ratios geomcheck / CGAL are printed.
//
//   build/release/bench/bench_delaunay_3d [--benchmark_filter=...]
#include <benchmark/benchmark.h>

#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

#include "geomcheck/delaunay_3d.hpp"
#include "point_sets_3d.hpp"
#include "pointset_bench.hpp"

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using DT = CGAL::Delaunay_triangulation_3<K>;
using geomcheck::Vec3;

constexpr std::uint64_t kSeed = 20261203;

// Set k: 0 uniform 10^5, 1 uniform 10^6, 2 grid 100^3, 3 sphere 10^5,
// 4 uniform 10^6 times 2^500, 5 uniform 10^6 times 2^-500.
constexpr int kSets = 6;
constexpr const char* kNames[kSets] = {"uniform 10^5", "uniform 10^6", "grid 100^3", "sphere 10^5",
                                       "uniform 10^6 x2^500", "uniform 10^6 x2^-500"};
const std::vector<Vec3>& point_set(int k) {
  static std::map<int, std::vector<Vec3>> cache;
  auto& p = cache[k];
  if (!p.empty()) return p;
  namespace b = geomcheck::bench3d;
  if (k == 2) p = b::grid(100);
  else if (k == 3) p = b::sphere(100000, kSeed);
  else p = b::uniform(k == 0 ? 100000 : 1000000, 0, 1, k == 4 ? 500 : (k == 5 ? -500 : 0), kSeed);
  return p;
}

void BM_geomcheck(benchmark::State& s) {
  const std::vector<Vec3>& p = point_set(static_cast<int>(s.range(0)));
  std::size_t tets = 0;
  for (auto _ : s) {
    tets = geomcheck::delaunay_3d(p).tetrahedra.size();
    benchmark::DoNotOptimize(tets);
  }
  s.counters["tetrahedra"] = static_cast<double>(tets);
  s.counters["peak_MB"] = peak_mb([&] { benchmark::DoNotOptimize(geomcheck::delaunay_3d(p).tetrahedra.size()); });
  s.SetLabel(kNames[s.range(0)]);
}

void BM_cgal(benchmark::State& s) {
  const std::vector<Vec3>& p = point_set(static_cast<int>(s.range(0)));
  const std::vector<K::Point_3> pts = geomcheck::bench3d::cgal_points<K>(p);
  std::size_t tets = 0;
  for (auto _ : s) {
    DT dt(pts.begin(), pts.end());
    tets = dt.number_of_finite_cells();
    benchmark::DoNotOptimize(tets);
  }
  s.counters["tetrahedra"] = static_cast<double>(tets);
  s.counters["peak_MB"] = peak_mb([&] {
    DT dt(pts.begin(), pts.end());
    benchmark::DoNotOptimize(dt.number_of_finite_cells());
  });
  s.SetLabel(kNames[s.range(0)]);
}

BENCHMARK(BM_geomcheck)->DenseRange(0, kSets - 1)->Unit(benchmark::kMillisecond)->Iterations(2);
BENCHMARK(BM_cgal)->DenseRange(0, kSets - 1)->Unit(benchmark::kMillisecond)->Iterations(2);

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  std::printf("delaunay_3d vs CGAL Delaunay_triangulation_3 (Epick, range insert); points seed %llu\n",
              static_cast<unsigned long long>(kSeed));
  Capture reporter("/iterations");
  benchmark::RunSpecifiedBenchmarks(&reporter);
  std::printf("\n%-22s %12s %10s %8s %13s %9s %8s\n", "input", "geomcheck ms", "CGAL ms", "ratio", "geomcheck MB",
              "CGAL MB", "ratio");
  for (int k = 0; k < kSets; ++k) {
    const auto g = reporter.runs.find("BM_geomcheck/" + std::to_string(k));
    const auto c = reporter.runs.find("BM_cgal/" + std::to_string(k));
    if (g == reporter.runs.end() || c == reporter.runs.end()) continue;
    std::printf("%-22s %12.1f %10.1f %8.2f %13.1f %9.1f %8.2f\n", kNames[k], g->second.first, c->second.first,
                g->second.first / c->second.first, g->second.second, c->second.second,
                g->second.second / c->second.second);
  }
  std::printf("(ratio = geomcheck / CGAL, time and peak heap; target <= 1, stretch 0.8)\n");
  benchmark::Shutdown();
  return 0;
}
