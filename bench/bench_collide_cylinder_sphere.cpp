// Cylinder/sphere: production against FCL on the same inputs, in one run.
//
//   bench_collide_cylinder_sphere [--benchmark_* flags]
//   GEOMCHECK_BENCH_SEED=<n> bench_collide_cylinder_sphere   (other inputs)
//
// The batch: kPairBatch random cylinder/sphere pairs from a fixed seed
// (printed), exactly half of them overlapping according to production,
// shuffled so that branches are not predictable. The FCL benchmarks time
// fcl::collide on shapes converted once beforehand (fcl_convert.hpp);
// BM_fcl_collide_adapter adds the adapter's validation and conversion for
// reference (bench_pair.hpp: the batch and these benchmarks). After the run
// the program prints ns/query and the FCL/production ratios; the target is
// production at least 10x faster than FCL's collide.
#include <benchmark/benchmark.h>

#include <cstdio>
#include <map>
#include <string>

#include "bench_common.hpp"
#include "bench_pair.hpp"
#include "bench_random.hpp"
#include "geomcheck/collide_cylinder_sphere.hpp"
#include "geomcheck/oracles/cylinder_sphere.hpp"
#include "geomcheck/peers/fcl_adapter.hpp"
#include "geomcheck/peers/fcl_convert.hpp"

namespace geomcheck::bench {
namespace {

using Bench = PairBench<Sphere, peers::FclCylinderSphere>;

/// The batch: half overlapping according to production, shuffled.
Bench::Batch make_batch(std::uint64_t seed) {
  const Bench draws{"cylinder/sphere", random_sphere, nullptr};  // its poses and verdicts only
  Rng rng(seed);
  std::size_t undecided = 0;  // production always decides
  Bench::Batch b;
  b.pairs = draws.half_overlapping(rng, undecided);
  Bench::shuffle_and_convert(b, rng);
  return b;
}

/// bench_pair.hpp's benchmarks (BM_prod_overlap, ..., BM_fcl_collide_adapter)
/// and the exact oracle on the same pairs: the verdict decided in rationals
/// and a certified enclosure of the signed distance.
void register_benchmarks(const Bench::Batch& b) {
  const Bench plain{"cylinder/sphere", random_sphere, nullptr};
  plain.register_batch("", b);
  register_each("BM_oracle_collide", b.pairs,
                [](const Bench::Pair& pr) { return oracle::solve_cylinder_sphere(pr.a, pr.b).verdict; });
}

/// The seed and production's and FCL's verdicts on the batch.
void print_batch(std::uint64_t seed, const Bench::Batch& b) {
  std::size_t prod_hits = 0, fcl_hits = 0, agree = 0;
  for (std::size_t i = 0; i < b.pairs.size(); ++i) {
    const bool p = overlap(b.pairs[i].a, b.pairs[i].b);
    const bool f = peers::fcl_overlap_prepared(b.fcl[i]);
    prod_hits += p;
    fcl_hits += f;
    agree += (p == f);
  }
  std::printf("cylinder/sphere batch: %zu pairs, %s\n", b.pairs.size(), seed_text(seed).c_str());
  std::printf("overlapping: production %zu, FCL %zu; verdicts agree on %zu/%zu\n\n", prod_hits, fcl_hits, agree,
              b.pairs.size());
  std::fflush(stdout);
}

}  // namespace
}  // namespace geomcheck::bench

int main(int argc, char** argv) {
  using namespace geomcheck::bench;
  const std::uint64_t seed = seed_from_env();
  const Bench::Batch batch = make_batch(seed);
  print_batch(seed, batch);
  register_benchmarks(batch);
  CaptureReporter reporter(kPairBatch);
  std::map<std::string, double> ratios;
  if (int rc = run_and_summarise(argc, argv, reporter,
                                 {fcl_over_prod("overlap"), fcl_over_prod("collide"), oracle_over_prod("collide")},
                                 &ratios))
    return rc;
  if (auto it = ratios.find("collide fcl/prod"); it != ratios.end())
    std::printf("target: production collide >= 10x faster than FCL collide: %s\n", it->second >= 10 ? "met" : "NOT met");
  return 0;
}
