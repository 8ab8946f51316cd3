// Sphere swept against a cylinder: production, and FCL as far as it can
// express the query (see fcl_adapter.hpp), on the same inputs in one run.
//
//   bench_sweep_sphere_cylinder [--benchmark_* flags]
//   GEOMCHECK_BENCH_SEED=<n> bench_sweep_sphere_cylinder
//
// Two batches of kBatch sweeps from a fixed seed (printed), each shuffled:
//   random  random ball (radius 0.05 to 1.5) and motion around a random
//           cylinder, exactly half of them hitting according to production;
//   rim     sweeps aimed at a rim: the ball starts in the corner region of a
//           random rim point (beyond the cap, outside the radius) and moves
//           towards that point (missed by less than the ball's radius) and
//           up to as far again beyond it, so that production's stage 2 (the
//           rim) decides.
// FCL has no sweep query returning a contact; the adapter asks
// fcl::continuousCollide (conservative advancement of the moving ball):
// BM_fcl_sweep_* is the adapter's default (after a miss it asks again in up
// to three equivalent frames, see fcl_adapter.hpp), BM_fcl_sweep_once_* a
// single FCL call. Both include the adapter's validation and conversion, as
// in bench_cast_segment_cylinder. After the run the program prints ns/query
// and the FCL/production ratios per batch.
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "bench_common.hpp"
#include "bench_random.hpp"
#include "geomcheck/oracles/fcl_adapter.hpp"
#include "geomcheck/sweep_sphere_cylinder.hpp"

namespace geomcheck::bench {
namespace {

constexpr std::size_t kBatch = 4096;
constexpr double kPi = 3.14159265358979323846;

struct Case {
  MovingSphere m;
  Cylinder c;
};

struct Inputs {
  std::uint64_t seed = 0;
  std::vector<Case> random, rim;
};

Case random_case(Rng& rng) {
  Case k;
  k.c = rng.cylinder();
  const Vec3 mid = 0.5 * k.c.p + 0.5 * k.c.q;
  const double reach = 0.5 * length(k.c.q - k.c.p) + k.c.r;
  k.m.c = mid + rng.in_box(reach + 3.0);
  k.m.delta = (mid + rng.in_box(reach + 3.0)) - k.m.c;
  k.m.r = rng.uniform(0.05, 1.5);
  return k;
}

Case rim_case(Rng& rng) {
  Case k;
  k.c = rng.cylinder();
  const Vec3 axis = k.c.q - k.c.p;
  const Vec3 u = (1.0 / length(axis)) * axis;
  const Vec3 e1 = any_perpendicular(u);
  const Vec3 e2 = cross(u, e1);
  const bool top = rng.next() & 1;
  const double theta = rng.uniform(0.0, 2 * kPi);
  const Vec3 radial = std::cos(theta) * e1 + std::sin(theta) * e2;
  const Vec3 rim = (top ? k.c.q : k.c.p) + k.c.r * radial;
  // A direction inside the rim's normal cone (between the radial and the
  // cap's outward normal, ends excluded): the corner region.
  const double phi = rng.uniform(0.05, 0.5 * kPi - 0.05);
  const Vec3 n = std::cos(phi) * radial + std::sin(phi) * (top ? u : -u);
  k.m.r = rng.uniform(0.05, 1.5);
  k.m.c = rim + (k.m.r + rng.uniform(0.5, 3.0)) * n;
  const Vec3 aim = rim + rng.in_box(0.5 * k.m.r);  // within 0.87 r of the rim point
  k.m.delta = rng.uniform(1.0, 2.0) * (aim - k.m.c);
  return k;
}

void shuffle(std::vector<Case>& v, Rng& rng) {
  for (std::size_t i = v.size(); i > 1; --i) std::swap(v[i - 1], v[rng.next() % i]);
}

Inputs make_inputs(std::uint64_t seed) {
  Inputs in;
  in.seed = seed;
  Rng rng(seed);
  std::size_t n_hit = 0, n_miss = 0;
  while (in.random.size() < kBatch) {
    const Case k = random_case(rng);
    const bool hit = sweep(k.m, k.c).hit;
    if (hit ? n_hit >= kBatch / 2 : n_miss >= kBatch / 2) continue;
    (hit ? n_hit : n_miss)++;
    in.random.push_back(k);
  }
  while (in.rim.size() < kBatch) in.rim.push_back(rim_case(rng));
  shuffle(in.random, rng);
  shuffle(in.rim, rng);
  return in;
}

const Inputs& inputs() {
  static const Inputs in = make_inputs(seed_from_env());
  return in;
}

void bm_prod_sweep(benchmark::State& state, const std::vector<Case>* cases) {
  for (auto _ : state) {
    for (const Case& k : *cases) benchmark::DoNotOptimize(sweep(k.m, k.c));
  }
  set_per_query(state, cases->size());
}

void bm_fcl_sweep(benchmark::State& state, const std::vector<Case>* cases, oracles::FclCastMethod method) {
  for (auto _ : state) {
    for (const Case& k : *cases) benchmark::DoNotOptimize(oracles::fcl_sweep(k.m, k.c, method));
  }
  set_per_query(state, cases->size());
}

void register_batch(const char* set, const std::vector<Case>& cases) {
  const std::string s = set;
  benchmark::RegisterBenchmark(("BM_prod_sweep_" + s).c_str(), bm_prod_sweep, &cases);
  benchmark::RegisterBenchmark(("BM_fcl_sweep_" + s).c_str(), bm_fcl_sweep, &cases,
                               oracles::FclCastMethod::kConservativeAdvancement);
  benchmark::RegisterBenchmark(("BM_fcl_sweep_once_" + s).c_str(), bm_fcl_sweep, &cases,
                               oracles::FclCastMethod::kConservativeAdvancementOnce);
}

void print_batch(const char* set, const std::vector<Case>& cases) {
  std::size_t prod_hits = 0;
  std::size_t hits[2] = {0, 0}, agree[2] = {0, 0};
  double max_dt[2] = {0, 0};
  const oracles::FclCastMethod methods[2] = {oracles::FclCastMethod::kConservativeAdvancement,
                                             oracles::FclCastMethod::kConservativeAdvancementOnce};
  for (const Case& k : cases) {
    const CastHit p = sweep(k.m, k.c);
    prod_hits += p.hit;
    for (int m = 0; m < 2; ++m) {
      const oracles::PeerCast f = oracles::fcl_sweep(k.m, k.c, methods[m]);
      hits[m] += f.hit;
      agree[m] += (f.ok && f.hit == p.hit);
      if (p.hit && f.ok && f.hit) max_dt[m] = std::fmax(max_dt[m], std::fabs(f.t - p.t));
    }
  }
  std::printf("%-6s hits: production %zu; FCL %zu (verdicts agree %zu/%zu, max |dt| %.3g); FCL once %zu (agree "
              "%zu/%zu, max |dt| %.3g)\n",
              set, prod_hits, hits[0], agree[0], cases.size(), max_dt[0], hits[1], agree[1], cases.size(), max_dt[1]);
}

void print_inputs(const Inputs& in) {
  std::printf("sphere/cylinder sweep batches: %zu cases each, seed = %llu (0x%llx; GEOMCHECK_BENCH_SEED overrides)\n",
              in.random.size(), static_cast<unsigned long long>(in.seed), static_cast<unsigned long long>(in.seed));
  print_batch("random", in.random);
  print_batch("rim", in.rim);
  std::printf("\n");
  std::fflush(stdout);
}

}  // namespace
}  // namespace geomcheck::bench

int main(int argc, char** argv) {
  using namespace geomcheck::bench;
  print_inputs(inputs());
  register_batch("random", inputs().random);
  register_batch("rim", inputs().rim);
  CaptureReporter reporter(kBatch);
  if (int rc = run_benchmarks(argc, argv, reporter)) return rc;
  print_summary(reporter, {
                              {"sweep fcl/prod (random)", {"BM_fcl_sweep_random", "BM_prod_sweep_random"}},
                              {"sweep fcl-once/prod (random)", {"BM_fcl_sweep_once_random", "BM_prod_sweep_random"}},
                              {"sweep fcl/prod (rim)", {"BM_fcl_sweep_rim", "BM_prod_sweep_rim"}},
                              {"sweep fcl-once/prod (rim)", {"BM_fcl_sweep_once_rim", "BM_prod_sweep_rim"}},
                          });
  return 0;
}
