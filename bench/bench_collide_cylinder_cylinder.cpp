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
#include "geomcheck/detail/cylinder_pair.hpp"

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

/// Production before 2026-11-27 (one Newton step on each circle, stopped
/// at a half-angle of 2^-10, no search of the sphere), for the before/after
/// figures of the same run.
Contact collide_before(const Cylinder& a, const Cylinder& b) {
  detail::CylinderPairOptions o;
  o.newton_steps = 1;
  o.relative_stop = false;
  o.rim_steps = 0;
  return detail::cylinder_pair(a, b, true, o);
}

PairBench<Cylinder, peers::FclCylinderCylinder> make_bench() {
  PairBench<Cylinder, peers::FclCylinderCylinder> b{"cylinder/cylinder", random_b, kDepthNote};
  b.collide_before = collide_before;
  return b;
}
const PairBench<Cylinder, peers::FclCylinderCylinder> kBench = make_bench();

}  // namespace
}  // namespace geomcheck::bench

int main(int argc, char** argv) { return geomcheck::bench::kBench.run(argc, argv); }
