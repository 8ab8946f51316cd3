// Cylinder/sphere: production against FCL on the same inputs, in one run.
//
//   bench_collide_cylinder_sphere [--benchmark_* flags]
//   GEOMCHECK_BENCH_SEED=<n> bench_collide_cylinder_sphere   (other inputs)
//
// The batch: kBatch random cylinder/sphere pairs from a fixed seed (printed),
// exactly half of them overlapping according to production, shuffled so that
// branches are not predictable. The FCL benchmarks time fcl::collide on
// shapes converted once beforehand (fcl_convert.hpp); BM_fcl_collide_adapter
// adds the adapter's validation and conversion for reference. After the run
// the program prints ns/query and the FCL/production ratios; the target is
// production at least 10x faster than FCL's collide.
#include <benchmark/benchmark.h>

#include <cstdio>
#include <utility>
#include <vector>

#include "bench_common.hpp"
#include "bench_random.hpp"
#include "geomcheck/collide_cylinder_sphere.hpp"
#include "geomcheck/oracles/cylinder_sphere.hpp"
#include "geomcheck/oracles/fcl_adapter.hpp"
#include "geomcheck/oracles/fcl_convert.hpp"

namespace geomcheck::bench {
namespace {

constexpr std::size_t kBatch = 4096;

struct Pair {
  Cylinder a;
  Sphere b;
};

struct Inputs {
  std::uint64_t seed = 0;
  std::vector<Pair> pairs;
  std::vector<oracles::FclCylinderSphere> fcl;  // the same pairs, converted for FCL
};

Inputs make_inputs(std::uint64_t seed) {
  Inputs in;
  in.seed = seed;
  Rng rng(seed);
  std::size_t n_hit = 0, n_miss = 0;
  while (in.pairs.size() < kBatch) {
    Pair pr;
    pr.a = rng.cylinder();
    const Vec3 mid = 0.5 * pr.a.p + 0.5 * pr.a.q;
    const double reach = 0.5 * length(pr.a.q - pr.a.p) + pr.a.r;
    pr.b.c = mid + rng.in_box(reach + 1.5);
    pr.b.r = rng.uniform(0.05, 1.5);
    const bool hit = overlap(pr.a, pr.b);
    if (hit ? n_hit >= kBatch / 2 : n_miss >= kBatch / 2) continue;
    (hit ? n_hit : n_miss)++;
    in.pairs.push_back(pr);
  }
  for (std::size_t i = in.pairs.size(); i > 1; --i) std::swap(in.pairs[i - 1], in.pairs[rng.next() % i]);
  in.fcl.reserve(in.pairs.size());
  for (const Pair& pr : in.pairs) in.fcl.emplace_back(pr.a, pr.b);
  return in;
}

const Inputs& inputs() {
  static const Inputs in = make_inputs(seed_from_env());
  return in;
}

void BM_prod_overlap(benchmark::State& state) {
  const auto& pairs = inputs().pairs;
  for (auto _ : state) {
    for (const Pair& pr : pairs) benchmark::DoNotOptimize(overlap(pr.a, pr.b));
  }
  set_per_query(state, pairs.size());
}
BENCHMARK(BM_prod_overlap);

void BM_prod_collide(benchmark::State& state) {
  const auto& pairs = inputs().pairs;
  for (auto _ : state) {
    for (const Pair& pr : pairs) benchmark::DoNotOptimize(collide(pr.a, pr.b));
  }
  set_per_query(state, pairs.size());
}
BENCHMARK(BM_prod_collide);

void BM_fcl_overlap(benchmark::State& state) {
  const auto& fcl = inputs().fcl;
  for (auto _ : state) {
    for (const auto& pr : fcl) benchmark::DoNotOptimize(oracles::fcl_overlap_prepared(pr));
  }
  set_per_query(state, fcl.size());
}
BENCHMARK(BM_fcl_overlap);

void BM_fcl_collide(benchmark::State& state) {
  const auto& fcl = inputs().fcl;
  for (auto _ : state) {
    for (const auto& pr : fcl) benchmark::DoNotOptimize(oracles::fcl_collide_prepared(pr));
  }
  set_per_query(state, fcl.size());
}
BENCHMARK(BM_fcl_collide);

// Reference only: validation + conversion + fcl::collide, per query.
void BM_fcl_collide_adapter(benchmark::State& state) {
  const auto& pairs = inputs().pairs;
  for (auto _ : state) {
    for (const Pair& pr : pairs) benchmark::DoNotOptimize(oracles::fcl_collide(pr.a, pr.b));
  }
  set_per_query(state, pairs.size());
}
BENCHMARK(BM_fcl_collide_adapter);

// The exact oracle on the same pairs: the verdict decided in rationals and
// a certified enclosure of the signed distance.
void BM_oracle_collide(benchmark::State& state) {
  const auto& pairs = inputs().pairs;
  for (auto _ : state) {
    for (const Pair& pr : pairs) benchmark::DoNotOptimize(oracle::solve_cylinder_sphere(pr.a, pr.b).verdict);
  }
  set_per_query(state, pairs.size());
}
BENCHMARK(BM_oracle_collide);


void print_inputs(const Inputs& in) {
  std::size_t prod_hits = 0, fcl_hits = 0, agree = 0;
  for (std::size_t i = 0; i < in.pairs.size(); ++i) {
    const bool p = overlap(in.pairs[i].a, in.pairs[i].b);
    const bool f = oracles::fcl_overlap_prepared(in.fcl[i]);
    prod_hits += p;
    fcl_hits += f;
    agree += (p == f);
  }
  std::printf("cylinder/sphere batch: %zu pairs, seed = %llu (0x%llx; GEOMCHECK_BENCH_SEED overrides)\n",
              in.pairs.size(), static_cast<unsigned long long>(in.seed), static_cast<unsigned long long>(in.seed));
  std::printf("overlapping: production %zu, FCL %zu; verdicts agree on %zu/%zu\n\n", prod_hits, fcl_hits, agree,
              in.pairs.size());
  std::fflush(stdout);
}

}  // namespace
}  // namespace geomcheck::bench

int main(int argc, char** argv) {
  using namespace geomcheck::bench;
  print_inputs(inputs());
  CaptureReporter reporter(kBatch);
  if (int rc = run_benchmarks(argc, argv, reporter)) return rc;
  const auto ratios = print_summary(reporter, {
                                                  {"overlap fcl/prod", {"BM_fcl_overlap", "BM_prod_overlap"}},
                                                  {"collide fcl/prod", {"BM_fcl_collide", "BM_prod_collide"}},
                                                  {"collide exact-oracle/prod", {"BM_oracle_collide", "BM_prod_collide"}},
                                              });
  if (auto it = ratios.find("collide fcl/prod"); it != ratios.end())
    std::printf("target: production collide >= 10x faster than FCL collide: %s\n", it->second >= 10 ? "met" : "NOT met");
  return 0;
}
