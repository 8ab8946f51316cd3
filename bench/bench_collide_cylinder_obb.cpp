// Cylinder/box: production against FCL on the same inputs, in one run
// (bench_pair.hpp: the batches, the benchmarks and the ratios); the pair's
// second query, penetration_cylinder_obb, on the same batches
// (BM_prod_penetration_<set>).
//
//   bench_collide_cylinder_obb [--benchmark_* flags]
//   GEOMCHECK_BENCH_SEED=<n> bench_collide_cylinder_obb   (other inputs)
#include <array>
#include <cmath>

#include "bench_pair.hpp"
#include "geomcheck/collide_cylinder_obb.hpp"
#include "geomcheck/penetration_cylinder_obb.hpp"

namespace geomcheck::bench {
namespace {

/// What the two depths are, printed with their differences.
constexpr char kDepthNote[] =
    "production's is the overlap along its normal, within 1 + 1/64 of the minimum (penetration's is the minimum); "
    "FCL's MPR estimate is neither";

PairBench<Obb, peers::FclCylinderBox> make_bench() {
  PairBench<Obb, peers::FclCylinderBox> b{"cylinder/box", random_box, kDepthNote};
  b.penetration = [](const Cylinder& a, const Obb& x) { return penetration(a, x); };
  return b;
}
const PairBench<Obb, peers::FclCylinderBox> kBench = make_bench();

}  // namespace
}  // namespace geomcheck::bench

int main(int argc, char** argv) { return geomcheck::bench::kBench.run(argc, argv); }
