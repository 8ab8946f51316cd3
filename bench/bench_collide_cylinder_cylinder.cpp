// Cylinder/cylinder: production against FCL on the same inputs, in one run
// (bench_pair.hpp: the batches, the benchmarks and the ratios).
//
//   bench_collide_cylinder_cylinder [--benchmark_* flags]
//   GEOMCHECK_BENCH_SEED=<n> bench_collide_cylinder_cylinder   (other inputs)
//
// FCL has no closed form for two cylinders: its collide runs libccd's MPR.
#include <cmath>

#include "bench_pair.hpp"
#include "geomcheck/collide_cylinder_cylinder.hpp"

namespace geomcheck::bench {
namespace {

/// What the two depths are, printed with their differences.
constexpr char kDepthNote[] =
    "production's is the overlap along its normal, an upper bound of the penetration depth; FCL's is MPR's estimate";

/// A random pose: B's middle within reach + 1.5 of A's middle, B's length
/// 0.5..4 and radius 0.1..1.5 (as Rng::cylinder), any direction.
Cylinder random_b(Rng& rng, const Cylinder& a) {
  const Vec3 c = rng.around(a, 1.5);
  const Vec3 half = (0.5 * rng.uniform(0.5, 4.0)) * rng.direction();
  return {c - half, c + half, rng.uniform(0.1, 1.5)};
}

const PairBench<Cylinder, oracles::FclCylinderCylinder> kBench{"cylinder/cylinder", random_b, kDepthNote};

}  // namespace
}  // namespace geomcheck::bench

int main(int argc, char** argv) { return geomcheck::bench::kBench.run(argc, argv); }
