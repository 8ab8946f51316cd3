// Segment cast against a cylinder: production, and FCL as far as it can
// express the query (see fcl_adapter.hpp), on the same inputs in one run.
//
//   bench_cast_segment_cylinder [--benchmark_* flags]
//   GEOMCHECK_BENCH_SEED=<n> bench_cast_segment_cylinder
//
// The batch: kBatch random segment/cylinder pairs from a fixed seed
// (printed), exactly half of them hitting according to production. FCL has
// no segment cast; the adapter asks fcl::continuousCollide (conservative
// advancement of a moving point): BM_fcl_cast is the adapter's default (after
// a miss it asks again in up to three equivalent frames, see
// fcl_adapter.hpp), BM_fcl_cast_once a single FCL call.
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdio>
#include <utility>
#include <vector>

#include "bench_common.hpp"
#include "bench_random.hpp"
#include "geomcheck/cast_segment_cylinder.hpp"
#include "geomcheck/oracles/cast_segment_cylinder.hpp"
#include "geomcheck/oracles/fcl_adapter.hpp"

namespace geomcheck::bench {
namespace {

constexpr std::size_t kBatch = 4096;

struct Case {
  Segment s;
  Cylinder c;
};

struct Inputs {
  std::uint64_t seed = 0;
  std::vector<Case> cases;
};

Inputs make_inputs(std::uint64_t seed) {
  Inputs in;
  in.seed = seed;
  Rng rng(seed);
  std::size_t n_hit = 0, n_miss = 0;
  while (in.cases.size() < kBatch) {
    Case k;
    k.c = rng.cylinder();
    const Vec3 mid = 0.5 * k.c.p + 0.5 * k.c.q;
    const double reach = 0.5 * length(k.c.q - k.c.p) + k.c.r;
    k.s.a = mid + rng.in_box(reach + 3.0);
    k.s.b = mid + rng.in_box(reach + 3.0);
    const bool hit = cast(k.s, k.c).hit;
    if (hit ? n_hit >= kBatch / 2 : n_miss >= kBatch / 2) continue;
    (hit ? n_hit : n_miss)++;
    in.cases.push_back(k);
  }
  for (std::size_t i = in.cases.size(); i > 1; --i) std::swap(in.cases[i - 1], in.cases[rng.next() % i]);
  return in;
}

const Inputs& inputs() {
  static const Inputs in = make_inputs(seed_from_env());
  return in;
}

void BM_prod_cast(benchmark::State& state) {
  const auto& cases = inputs().cases;
  for (auto _ : state) {
    for (const Case& k : cases) benchmark::DoNotOptimize(cast(k.s, k.c));
  }
  set_per_query(state, cases.size());
}
BENCHMARK(BM_prod_cast);

void BM_fcl_cast(benchmark::State& state) {
  const auto& cases = inputs().cases;
  for (auto _ : state) {
    for (const Case& k : cases) benchmark::DoNotOptimize(oracles::fcl_cast(k.s, k.c));
  }
  set_per_query(state, cases.size());
}
BENCHMARK(BM_fcl_cast);

void BM_fcl_cast_once(benchmark::State& state) {
  const auto& cases = inputs().cases;
  for (auto _ : state) {
    for (const Case& k : cases)
      benchmark::DoNotOptimize(oracles::fcl_cast(k.s, k.c, oracles::FclCastMethod::kConservativeAdvancementOnce));
  }
  set_per_query(state, cases.size());
}
BENCHMARK(BM_fcl_cast_once);

// The exact oracle on the same cases: hit/miss decided in rationals and a
// certified enclosure of t (what every property check pays per case).
void BM_oracle_cast(benchmark::State& state) {
  const auto& cases = inputs().cases;
  for (auto _ : state) {
    for (const Case& k : cases) benchmark::DoNotOptimize(oracle::solve_cast(k.s, k.c).hit);
  }
  set_per_query(state, cases.size());
}
BENCHMARK(BM_oracle_cast);


void print_inputs(const Inputs& in) {
  std::size_t prod_hits = 0;
  std::size_t hits[2] = {0, 0}, agree[2] = {0, 0};
  double max_dt[2] = {0, 0};
  const oracles::FclCastMethod methods[2] = {oracles::FclCastMethod::kConservativeAdvancement,
                                             oracles::FclCastMethod::kConservativeAdvancementOnce};
  for (const Case& k : in.cases) {
    const CastHit p = cast(k.s, k.c);
    prod_hits += p.hit;
    for (int m = 0; m < 2; ++m) {
      const oracles::PeerCast f = oracles::fcl_cast(k.s, k.c, methods[m]);
      hits[m] += f.hit;
      agree[m] += (f.ok && f.hit == p.hit);
      if (p.hit && f.ok && f.hit) max_dt[m] = std::fmax(max_dt[m], std::fabs(f.t - p.t));
    }
  }
  std::printf("segment/cylinder batch: %zu cases, seed = %llu (0x%llx; GEOMCHECK_BENCH_SEED overrides)\n",
              in.cases.size(), static_cast<unsigned long long>(in.seed), static_cast<unsigned long long>(in.seed));
  std::printf("hits: production %zu; FCL %zu (verdicts agree %zu/%zu, max |dt| %.3g); FCL once %zu (agree %zu/%zu, "
              "max |dt| %.3g)\n\n",
              prod_hits, hits[0], agree[0], in.cases.size(), max_dt[0], hits[1], agree[1], in.cases.size(), max_dt[1]);
  std::fflush(stdout);
}

}  // namespace
}  // namespace geomcheck::bench

int main(int argc, char** argv) {
  using namespace geomcheck::bench;
  print_inputs(inputs());
  CaptureReporter reporter(kBatch);
  if (int rc = run_benchmarks(argc, argv, reporter)) return rc;
  print_summary(reporter, {
                              {"cast fcl/prod", {"BM_fcl_cast", "BM_prod_cast"}},
                              {"cast fcl-once/prod", {"BM_fcl_cast_once", "BM_prod_cast"}},
                              {"cast exact-oracle/prod", {"BM_oracle_cast", "BM_prod_cast"}},
                          });
  return 0;
}
