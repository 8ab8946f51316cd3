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
// fcl_adapter.hpp), BM_fcl_cast_once a single FCL call (bench_cast.hpp).
#include <benchmark/benchmark.h>

#include <cstdio>
#include <vector>

#include "bench_cast.hpp"
#include "bench_common.hpp"
#include "bench_random.hpp"
#include "geomcheck/cast_segment_cylinder.hpp"
#include "geomcheck/oracles/cast_segment_cylinder.hpp"
#include "geomcheck/peers/fcl_adapter.hpp"

namespace geomcheck::bench {
namespace {

constexpr std::size_t kBatch = 4096;

struct Case {
  Segment s;
  Cylinder c;
};

/// A random cylinder, then the segment's ends within reach + 3 of its middle.
Case random_case(Rng& rng) {
  Case k;
  k.c = rng.cylinder();
  k.s.a = rng.around(k.c, 3.0);
  k.s.b = rng.around(k.c, 3.0);
  return k;
}

/// Production's cast and FCL's through the adapter (bench_cast.hpp).
const CastBench kCast{"cast", [](const Case& k) { return cast(k.s, k.c); },
                      [](const Case& k, peers::FclCastMethod m) { return peers::fcl_cast(k.s, k.c, m); }};

/// The batch: half hitting according to production, shuffled.
std::vector<Case> make_batch(std::uint64_t seed) {
  Rng rng(seed);
  std::vector<Case> cases = kCast.half_hitting(kBatch, [&] { return random_case(rng); });
  shuffle(cases, rng);
  return cases;
}

/// The benchmarks of kCast, and the exact oracle on the same cases: hit/miss
/// decided in rationals and a certified enclosure of t (what every property
/// check pays per case).
void register_benchmarks(const std::vector<Case>& cases) {
  kCast.register_batch("", cases);
  register_each("BM_oracle_cast", cases, [](const Case& k) { return oracle::solve_cast(k.s, k.c).hit; });
}

}  // namespace
}  // namespace geomcheck::bench

int main(int argc, char** argv) {
  using namespace geomcheck::bench;
  const std::uint64_t seed = seed_from_env();
  const std::vector<Case> cases = make_batch(seed);
  std::printf("segment/cylinder batch: %zu cases, %s\n", cases.size(), seed_text(seed).c_str());
  kCast.print_agreement("", cases);
  std::printf("\n");
  std::fflush(stdout);
  register_benchmarks(cases);
  CaptureReporter reporter(kBatch);
  std::vector<Ratio> ratios = kCast.ratios();
  ratios.push_back(oracle_over_prod("cast"));
  return run_and_summarise(argc, argv, reporter, ratios);
}
