// Cylinder/triangle: production against FCL on the same inputs, in one run.
//
//   bench_collide_cylinder_triangle [--benchmark_* flags]
//   GEOMCHECK_BENCH_SEED=<n> bench_collide_cylinder_triangle   (other inputs)
//
// The batches, benchmarks and ratios are bench_pair.hpp's; the pair's
// second query, penetration_cylinder_triangle, is timed on the same batches
// (BM_prod_penetration_<set>). The verdicts
// that select the pairs are the certified engine's
// (oracles/engine.hpp: classify), not production's, so that the inputs are
// the same whatever the implementation under measurement answers.
// Triangles: three vertices 0.7 from a centre in random directions (random
// orientation and shape), the centre uniform in the cylinder grown by 0.7
// (printed: the fraction of these poses in contact).
// The FCL benchmarks time FCL's per-triangle narrow phase on shapes
// converted once beforehand (fcl_convert.hpp: FCL as shipped,
// GJKSolver_libccd::shapeTriangleIntersect, libccd's MPR, GST_LIBCCD; what
// FCL's mesh traversal runs for each triangle, fcl::collide having no
// cylinder/triangle pair); BM_fcl_collide_adapter_* adds the adapter's
// validation, conversion and guarded support functions (fcl_adapter.hpp)
// for reference.
#include <cmath>

#include "bench_pair.hpp"
#include "geomcheck/collide_cylinder_triangle.hpp"
#include "geomcheck/penetration_cylinder_triangle.hpp"
#include "geomcheck/oracles/engine.hpp"

namespace geomcheck::bench {
namespace {

using Bench = PairBench<Triangle, peers::FclCylinderTriangle>;

constexpr double kVertexDistance = 0.7;  // from the triangle's centre

/// What the two depths are, printed with their differences.
constexpr char kDepthNote[] =
    "production's is the overlap along its normal, within 1 + 1/64 of the minimum (penetration's is the minimum); "
    "FCL's MPR estimate is neither";

/// A random pose: the triangle's centre uniform in the cylinder grown by
/// 0.7 (half length + 0.7 along the axis from the middle, radius + 0.7 from
/// the axis), its vertices 0.7 from the centre in uniform random directions.
Triangle random_triangle(Rng& rng, const Cylinder& a) {
  const Vec3 mid = 0.5 * a.p + 0.5 * a.q;
  const Vec3 axis = a.q - a.p;
  const double half = 0.5 * length(axis);
  const Vec3 u = (1 / length(axis)) * axis;
  Vec3 w;
  do {
    w = rng.direction();
    w = w - dot(w, u) * u;
  } while (length(w) < 0.1);
  w = (1 / length(w)) * w;
  const double along = rng.uniform(-1, 1) * (half + kVertexDistance);
  const double off = std::sqrt(rng.unit()) * (a.r + kVertexDistance);
  const Vec3 c = mid + along * u + off * w;
  Triangle b;
  b.a = c + kVertexDistance * rng.direction();
  b.b = c + kVertexDistance * rng.direction();
  b.c = c + kVertexDistance * rng.direction();
  return b;
}

/// The certified verdict: 1 overlapping or touching, 0 separated, -1 undecided.
int certified_hit(const Bench::Pair& pr) {
  oracle::EngineOptions opt;
  opt.certificates = false;
  const oracle::Verdict v = oracle::classify(oracle::make_shape(pr.a), oracle::make_shape(pr.b), opt).verdict;
  if (v == oracle::Verdict::Undecided) return -1;
  return v == oracle::Verdict::Separated ? 0 : 1;
}

Bench make_bench() {
  Bench b{"cylinder/triangle", random_triangle, kDepthNote, certified_hit, "the certified engine"};
  b.penetration = [](const Cylinder& a, const Triangle& x) { return penetration(a, x); };
  return b;
}
const Bench kBench = make_bench();

}  // namespace
}  // namespace geomcheck::bench

int main(int argc, char** argv) { return geomcheck::bench::kBench.run(argc, argv); }
