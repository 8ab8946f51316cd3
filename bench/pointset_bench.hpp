// geomcheck benchmarks — what the point-set benchmarks (bench_delaunay_2d,
// bench_delaunay_3d) share: the heap accounting (current and peak bytes of
// this process, counted by replacing the global operator new and delete;
// this header defines them: include it in one translation unit of a
// program) and the reporter that keeps each run's time and peak heap for
// the ratio table.
#pragma once

#include <benchmark/benchmark.h>
#include <malloc.h>

#include <map>
#include <string>
#include <utility>
#include <vector>

#include <atomic>
#include <cstdint>
#include <cstdlib>
#include <new>

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

// Peak heap of one construction above what was live before it, in MB.
template <class F>
double peak_mb(F&& build) {
  const std::int64_t base = g_current.load();
  g_peak = base;
  build();
  return static_cast<double>(g_peak.load() - base) / (1024.0 * 1024.0);
}

// Keeps the per-run real time and peak memory (counter peak_MB) for the
// ratio table, by benchmark name cut before `cut` ("/min_time",
// "/iterations").
class Capture : public benchmark::ConsoleReporter {
 public:
  explicit Capture(std::string cut) : cut_(std::move(cut)) {}
  std::map<std::string, std::pair<double, double>> runs;  // name -> (ms, peak MB)
  void ReportRuns(const std::vector<Run>& rs) override {
    for (const Run& r : rs) {
      if (r.error_occurred || r.run_type != Run::RT_Iteration) continue;
      const auto peak = r.counters.find("peak_MB");
      std::string name = r.benchmark_name();
      name = name.substr(0, name.find(cut_));
      runs[name] = {r.GetAdjustedRealTime(), peak == r.counters.end() ? 0.0 : double(peak->second)};
    }
    ConsoleReporter::ReportRuns(rs);
  }

 private:
  std::string cut_;
};

}  // namespace
