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

/// What the two depths are, printed with their differences.
constexpr char kDepthNote[] = "shallow: production's is the minimum, FCL's MPR estimate is not; deep: neither";

/// A random pose: the capsule's first end within reach + 1.5 of the
/// cylinder's middle, its segment up to 3 long, radius in [0.05, 1.5].
const PairBench<Capsule, peers::FclCylinderCapsule> kBench{"cylinder/capsule", random_capsule, kDepthNote};

}  // namespace
}  // namespace geomcheck::bench

int main(int argc, char** argv) { return geomcheck::bench::kBench.run(argc, argv); }
