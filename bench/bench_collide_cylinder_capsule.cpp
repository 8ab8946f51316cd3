// Cylinder/capsule: production against FCL on the same inputs, in one run
// (bench_pair.hpp: the batches, the benchmarks and the ratios).
//
//   bench_collide_cylinder_capsule [--benchmark_* flags]
//   GEOMCHECK_BENCH_SEED=<n> bench_collide_cylinder_capsule   (other inputs)
#include <cmath>

#include "bench_pair.hpp"
#include "geomcheck/collide_cylinder_capsule.hpp"

namespace geomcheck::bench {
namespace {

using Bench = PairBench<Capsule, oracles::FclCylinderCapsule>;

/// A random pose: the capsule's first end within reach + 1.5 of the
/// cylinder's middle, its segment up to 3 long, radius in [0.05, 1.5].
Bench::Pair random_pair(Rng& rng) {
  Bench::Pair pr;
  pr.a = rng.cylinder();
  const Vec3 mid = 0.5 * pr.a.p + 0.5 * pr.a.q;
  const double reach = 0.5 * length(pr.a.q - pr.a.p) + pr.a.r;
  pr.b.p = mid + rng.in_box(reach + 1.5);
  pr.b.q = pr.b.p + rng.uniform(0.0, 3.0) * rng.direction();
  pr.b.r = rng.uniform(0.05, 1.5);
  return pr;
}

}  // namespace
}  // namespace geomcheck::bench

int main(int argc, char** argv) {
  using namespace geomcheck::bench;
  const Bench bench{"cylinder/capsule", random_pair,
                    "shallow: production's is the minimum, FCL's MPR estimate is not; deep: neither"};
  return bench.run(argc, argv);
}
