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

using Bench = PairBench<Obb, oracles::FclCylinderBox>;

/// A random rotation (unit quaternion to matrix, then Gram-Schmidt: the
/// axes are orthonormal to a few ulps, inside the contract).
std::array<Vec3, 3> random_frame(Rng& rng) {
  double w, x, y, z, n;
  do {
    w = rng.uniform(-1, 1), x = rng.uniform(-1, 1), y = rng.uniform(-1, 1), z = rng.uniform(-1, 1);
    n = w * w + x * x + y * y + z * z;
  } while (n > 1 || n < 0.01);
  n = 1 / std::sqrt(n);
  w *= n, x *= n, y *= n, z *= n;
  Vec3 a0{1 - 2 * (y * y + z * z), 2 * (x * y + w * z), 2 * (x * z - w * y)};
  Vec3 a1{2 * (x * y - w * z), 1 - 2 * (x * x + z * z), 2 * (y * z + w * x)};
  a0 = (1 / length(a0)) * a0;
  a1 = a1 - dot(a1, a0) * a0;
  a1 = (1 / length(a1)) * a1;
  return {a0, a1, cross(a0, a1)};
}

/// A random pose: the box's centre within reach + 1.5 of the cylinder's
/// middle, half extents in [0.05, 1.5], a random rotation.
Bench::Pair random_pair(Rng& rng) {
  Bench::Pair pr;
  pr.a = rng.cylinder();
  const Vec3 mid = 0.5 * pr.a.p + 0.5 * pr.a.q;
  const double reach = 0.5 * length(pr.a.q - pr.a.p) + pr.a.r;
  pr.b.c = mid + rng.in_box(reach + 1.5);
  pr.b.axes = random_frame(rng);
  pr.b.e = {rng.uniform(0.05, 1.5), rng.uniform(0.05, 1.5), rng.uniform(0.05, 1.5)};
  return pr;
}

}  // namespace
}  // namespace geomcheck::bench

int main(int argc, char** argv) {
  using namespace geomcheck::bench;
  const Bench bench{"cylinder/box", random_pair,
                    "production's is the minimum, FCL's MPR estimate is not"};
  return bench.run(argc, argv);
}
