// geomcheck benchmarks — the heap accounting of the point-set benchmarks:
// current and peak bytes of this process, counted by replacing the global
// operator new and delete. Defines them: include it in one translation unit
// of a program.
#pragma once

#include <malloc.h>

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

}  // namespace
