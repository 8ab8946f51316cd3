// geomcheck benchmarks — convex_hull_3d against CGAL's convex_hull_3
// (Epick, into a Surface_mesh) on the same inputs in the same run: uniform
// points in a cube (few on the hull), points rounded onto a sphere (every
// point on the hull), the integer grid (coplanar faces), and the uniform set
// scaled by 2^500 and 2^-500. After the run the time ratios geomcheck / CGAL
// are printed.
//
//   build/release/bench/bench_convex_hull_3d [--benchmark_filter=...]
#include <benchmark/benchmark.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/convex_hull_3.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

#include "geomcheck/convex_hull_3d.hpp"
#include "point_sets_3d.hpp"

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using geomcheck::Vec3;

constexpr std::uint64_t kSeed = 20261203;

// Set k: 0 uniform 10^5, 1 uniform 10^6, 2 sphere 10^5, 3 grid 100^3,
// 4 uniform 10^6 times 2^500, 5 uniform 10^6 times 2^-500.
const std::vector<Vec3>& point_set(int k) {
  static std::map<int, std::vector<Vec3>> cache;
  auto& p = cache[k];
  if (!p.empty()) return p;
  namespace b = geomcheck::bench3d;
  if (k == 2) p = b::sphere(100000, kSeed);
  else if (k == 3) p = b::grid(100);
  else p = b::uniform(k == 0 ? 100000 : 1000000, -1, 1, k == 4 ? 500 : (k == 5 ? -500 : 0), kSeed);
  return p;
}
constexpr const char* kNames[] = {"uniform-1e5", "uniform-1e6", "sphere-1e5", "grid-100^3", "uniform-1e6-x2^500",
                                  "uniform-1e6-x2^-500"};

std::map<std::string, double> g_ns;

void BM_geomcheck(benchmark::State& s) {
  const std::vector<Vec3>& p = point_set(static_cast<int>(s.range(0)));
  std::size_t facets = 0;
  for (auto _ : s) {
    facets = geomcheck::convex_hull_3d(p).facets.size();
    benchmark::DoNotOptimize(facets);
  }
  s.counters["facets"] = static_cast<double>(facets);
  s.SetLabel(kNames[s.range(0)]);
}

void BM_cgal(benchmark::State& s) {
  const std::vector<Vec3>& p = point_set(static_cast<int>(s.range(0)));
  const std::vector<K::Point_3> pts = geomcheck::bench3d::cgal_points<K>(p);
  std::size_t facets = 0;
  for (auto _ : s) {
    CGAL::Surface_mesh<K::Point_3> m;
    CGAL::convex_hull_3(pts.begin(), pts.end(), m);
    facets = m.number_of_faces();
    benchmark::DoNotOptimize(facets);
  }
  s.counters["facets"] = static_cast<double>(facets);
  s.SetLabel(kNames[s.range(0)]);
}

BENCHMARK(BM_geomcheck)->DenseRange(0, 5)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_cgal)->DenseRange(0, 5)->Unit(benchmark::kMillisecond);

class Ratios : public benchmark::ConsoleReporter {
 public:
  void ReportRuns(const std::vector<Run>& runs) override {
    for (const Run& r : runs) g_ns[r.benchmark_name()] = r.GetAdjustedRealTime();
    ConsoleReporter::ReportRuns(runs);
  }
};

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  std::printf("seed %llu\n", static_cast<unsigned long long>(kSeed));
  Ratios reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  for (int k = 0; k <= 5; ++k) {
    const std::string a = "BM_geomcheck/" + std::to_string(k), b = "BM_cgal/" + std::to_string(k);
    if (g_ns.count(a) && g_ns.count(b))
      std::printf("ratio geomcheck/cgal %-20s = %.2f  (%.1f ms / %.1f ms)\n", kNames[k], g_ns[a] / g_ns[b], g_ns[a], g_ns[b]);
  }
  benchmark::Shutdown();
  return 0;
}
