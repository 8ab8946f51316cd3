// Cylinder/box: production against FCL on the same inputs, in one run
// (bench_pair.hpp: the batches, the benchmarks and the ratios).
//
//   bench_collide_cylinder_obb [--benchmark_* flags]
//   GEOMCHECK_BENCH_SEED=<n> bench_collide_cylinder_obb   (other inputs)
#include <array>
#include <cmath>

#include "bench_pair.hpp"
#include "geomcheck/collide_cylinder_obb.hpp"

namespace geomcheck::bench {
namespace {

/// What the two depths are, printed with their differences.
constexpr char kDepthNote[] = "production's is the minimum, FCL's MPR estimate is not";

/// A random rotation (unit quaternion to matrix, then Gram-Schmidt: the
/// axes are orthonormal to a few ulps, inside the contract).
std::array<Vec3, 3> random_frame(Rng& rng) {
  const std::array<Vec3, 3> m = rotation_columns(rng.unit_quaternion(0.01));
  Vec3 a0 = m[0], a1 = m[1];
  a0 = (1 / length(a0)) * a0;
  a1 = a1 - dot(a1, a0) * a0;
  a1 = (1 / length(a1)) * a1;
  return {a0, a1, cross(a0, a1)};
}

/// A random pose: the box's centre within reach + 1.5 of the cylinder's
/// middle, half extents in [0.05, 1.5], a random rotation.
Obb random_box(Rng& rng, const Cylinder& a) {
  Obb b;
  b.c = rng.around(a, 1.5);
  b.axes = random_frame(rng);
  b.e = {rng.uniform(0.05, 1.5), rng.uniform(0.05, 1.5), rng.uniform(0.05, 1.5)};
  return b;
}

const PairBench<Obb, oracles::FclCylinderBox> kBench{"cylinder/box", random_box, kDepthNote};

}  // namespace
}  // namespace geomcheck::bench

int main(int argc, char** argv) { return geomcheck::bench::kBench.run(argc, argv); }
