// Sphere/capsule: production against FCL on the same inputs, in one run
// (bench_pair.hpp: the batches, the benchmarks and the ratios), and ODE,
// Bullet and MuJoCo where built (bench_engines.hpp). FCL answers this pair
// with a closed form of its own. The target: production at least 5x faster
// than FCL's collide and overlap, and faster than every other engine.
//
//   bench_collide_sphere_capsule [--benchmark_* flags]
//   GEOMCHECK_BENCH_SEED=<n> bench_collide_sphere_capsule   (other inputs)
#include "bench_pair.hpp"
#include "geomcheck/collide_sphere_capsule.hpp"

namespace geomcheck::bench {
namespace {

/// What the two depths are, printed with their differences.
constexpr char kDepthNote[] = "both the true penetration depth ra + rb - D, up to rounding";

/// A random pose: A from Rng::first, B's first end within reach + 1.5 of
/// A's middle, its segment up to 3 long, radius in [0.05, 1.5].
const PairBench<Capsule, peers::FclPair<Sphere, Capsule>, Sphere> kBench{"sphere/capsule", random_capsule, kDepthNote};

}  // namespace
}  // namespace geomcheck::bench

int main(int argc, char** argv) {
  return geomcheck::bench::run_with_other_engines<geomcheck::QueryId::collide_sphere_capsule>(geomcheck::bench::kBench, argc,
                                                                                      argv);
}
