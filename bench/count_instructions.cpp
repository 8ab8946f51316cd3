// geomcheck — instructions per query, production vs FCL, on the same inputs.
//
// Wall-clock time on a shared two-core machine varies by 2x between runs;
// instruction counts under `valgrind --tool=callgrind` do not. Each run_*
// function below makes exactly kCalls queries over the benchmark batch;
// bench/instructions.sh runs this under callgrind and prints instructions
// per query and the ratio. (Instructions are not time: a square root or a
// division costs more than an add. Read them beside the Google Benchmark
// figures, not instead of them.)
#include <cstdio>
#include <vector>

#include "bench_random.hpp"
#include "geomcheck/cast_segment_cylinder.hpp"
#include "geomcheck/collide_cylinder_sphere.hpp"
#include "geomcheck/peers/fcl_convert.hpp"

using namespace geomcheck;

namespace {

constexpr int kCalls = 100000;

struct Pair {
  Cylinder a;
  Sphere b;
};

std::vector<Pair> make(std::uint64_t seed) {
  bench::Rng rng(seed);
  std::vector<Pair> out;
  while (out.size() < 4096) {  // a power of two: the loops index with a mask
    Pair pr;
    pr.a = rng.cylinder();
    const Vec3 mid = 0.5 * pr.a.p + 0.5 * pr.a.q;
    pr.b.c = mid + rng.in_box(0.5 * length(pr.a.q - pr.a.p) + pr.a.r + 1.5);
    pr.b.r = rng.uniform(0.05, 1.5);
    out.push_back(pr);
  }
  return out;
}

}  // namespace

// Not inlined, so that callgrind attributes each loop to its own function.
__attribute__((noinline)) int run_prod_overlap(const std::vector<Pair>& v) {
  int hits = 0;
  for (int i = 0; i < kCalls; ++i) hits += overlap(v[i & 4095].a, v[i & 4095].b);
  return hits;
}
__attribute__((noinline)) double run_prod_collide(const std::vector<Pair>& v) {
  double s = 0;
  for (int i = 0; i < kCalls; ++i) s += collide(v[i & 4095].a, v[i & 4095].b).depth;
  return s;
}
__attribute__((noinline)) int run_fcl_overlap(const std::vector<peers::FclCylinderSphere>& v) {
  int hits = 0;
  for (int i = 0; i < kCalls; ++i) hits += peers::fcl_overlap_prepared(v[i & 4095]);
  return hits;
}
__attribute__((noinline)) double run_fcl_collide(const std::vector<peers::FclCylinderSphere>& v) {
  double s = 0;
  for (int i = 0; i < kCalls; ++i) s += peers::fcl_collide_prepared(v[i & 4095]).depth;
  return s;
}

int main() {
  const auto pairs = make(0x67656f6d63686b31ULL);
  std::vector<peers::FclCylinderSphere> fcl;
  for (const auto& p : pairs) fcl.emplace_back(p.a, p.b);
  const int a = run_prod_overlap(pairs), c = run_fcl_overlap(fcl);
  const double b = run_prod_collide(pairs), d = run_fcl_collide(fcl);
  std::printf("calls %d: overlap hits %d (FCL %d), depth sums %.6g (FCL %.6g)\n", kCalls, a, c, b, d);
  return 0;
}
