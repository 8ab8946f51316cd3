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

using Bench = PairBench<Cylinder, oracles::FclCylinderCylinder>;

/// A random pose: B's middle within reach + 1.5 of A's middle, B's length
/// 0.5..4 and radius 0.1..1.5 (as Rng::cylinder), any direction.
Bench::Pair random_pair(Rng& rng) {
  Bench::Pair pr;
  pr.a = rng.cylinder();
  const Vec3 mid = 0.5 * pr.a.p + 0.5 * pr.a.q;
  const double reach = 0.5 * length(pr.a.q - pr.a.p) + pr.a.r;
  const Vec3 c = mid + rng.in_box(reach + 1.5);
  const Vec3 half = (0.5 * rng.uniform(0.5, 4.0)) * rng.direction();
  pr.b = {c - half, c + half, rng.uniform(0.1, 1.5)};
  return pr;
}

}  // namespace
}  // namespace geomcheck::bench

int main(int argc, char** argv) {
  using namespace geomcheck::bench;
  const Bench bench{"cylinder/cylinder", random_pair,
                    "production's is the overlap along its normal, an upper bound of the penetration depth; FCL's is MPR's estimate"};
  return bench.run(argc, argv);
}
