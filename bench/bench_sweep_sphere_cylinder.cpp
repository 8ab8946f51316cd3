// Sphere swept against a cylinder: production, and FCL as far as it can
// express the query (see fcl_adapter.hpp), on the same inputs in one run.
//
//   bench_sweep_sphere_cylinder [--benchmark_* flags]
//   GEOMCHECK_BENCH_SEED=<n> bench_sweep_sphere_cylinder
//
// Two batches of kBatch sweeps from a fixed seed (printed), each shuffled:
//   random  random ball (radius 0.05 to 1.5) and motion around a random
//           cylinder, exactly half of them hitting according to production;
//   rim     sweeps aimed at a rim: the ball starts in the corner region of a
//           random rim point (beyond the cap, outside the radius) and moves
//           towards that point (missed by less than the ball's radius) and
//           up to as far again beyond it, so that production's stage 2 (the
//           rim) decides.
// FCL has no sweep query returning a contact; the adapter asks
// fcl::continuousCollide (conservative advancement of the moving ball):
// BM_fcl_sweep_* is the adapter's default (after a miss it asks again in up
// to three equivalent frames, see fcl_adapter.hpp), BM_fcl_sweep_once_* a
// single FCL call (bench_cast.hpp). Both include the adapter's validation and conversion, as
// in bench_cast_segment_cylinder. After the run the program prints ns/query
// and the FCL/production ratios per batch.
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "bench_cast.hpp"
#include "bench_common.hpp"
#include "bench_random.hpp"
#include "geomcheck/peers/fcl_adapter.hpp"
#include "geomcheck/sweep_sphere_cylinder.hpp"

namespace geomcheck::bench {
namespace {

constexpr std::size_t kBatch = 4096;
constexpr double kPi = 3.14159265358979323846;

struct Case {
  MovingSphere m;
  Cylinder c;
};

struct Inputs {
  std::vector<Case> random, rim;
};

/// Production's sweep and FCL's through the adapter (bench_cast.hpp).
const CastBench kSweep{"sweep", [](const Case& k) { return sweep(k.m, k.c); },
                       [](const Case& k, peers::FclCastMethod m) { return peers::fcl_sweep(k.m, k.c, m); }};

/// A random cylinder, then a ball (radius 0.05 to 1.5) moving between two
/// points within reach + 3 of its middle.
Case random_case(Rng& rng) {
  Case k;
  k.c = rng.cylinder();
  k.m.c = rng.around(k.c, 3.0);
  k.m.delta = rng.around(k.c, 3.0) - k.m.c;
  k.m.r = rng.uniform(0.05, 1.5);
  return k;
}

Case rim_case(Rng& rng) {
  Case k;
  k.c = rng.cylinder();
  const Vec3 axis = k.c.q - k.c.p;
  const Vec3 u = (1.0 / length(axis)) * axis;
  const Vec3 e1 = any_perpendicular(u);
  const Vec3 e2 = cross(u, e1);
  const bool top = rng.next() & 1;
  const double theta = rng.uniform(0.0, 2 * kPi);
  const Vec3 radial = std::cos(theta) * e1 + std::sin(theta) * e2;
  const Vec3 rim = (top ? k.c.q : k.c.p) + k.c.r * radial;
  // A direction inside the rim's normal cone (between the radial and the
  // cap's outward normal, ends excluded): the corner region.
  const double phi = rng.uniform(0.05, 0.5 * kPi - 0.05);
  const Vec3 n = std::cos(phi) * radial + std::sin(phi) * (top ? u : -u);
  k.m.r = rng.uniform(0.05, 1.5);
  k.m.c = rim + (k.m.r + rng.uniform(0.5, 3.0)) * n;
  const Vec3 aim = rim + rng.in_box(0.5 * k.m.r);  // within 0.87 r of the rim point
  k.m.delta = rng.uniform(1.0, 2.0) * (aim - k.m.c);
  return k;
}

/// The random batch (half hitting according to production) and the rim
/// batch, each shuffled.
Inputs make_inputs(std::uint64_t seed) {
  Inputs in;
  Rng rng(seed);
  in.random = kSweep.half_hitting(kBatch, [&] { return random_case(rng); });
  while (in.rim.size() < kBatch) in.rim.push_back(rim_case(rng));
  shuffle(in.random, rng);
  shuffle(in.rim, rng);
  return in;
}

}  // namespace
}  // namespace geomcheck::bench

int main(int argc, char** argv) {
  using namespace geomcheck::bench;
  const std::uint64_t seed = seed_from_env();
  const Inputs in = make_inputs(seed);
  std::printf("sphere/cylinder sweep batches: %zu cases each, %s\n", in.random.size(), seed_text(seed).c_str());
  kSweep.print_agreement("random", in.random);
  kSweep.print_agreement("rim", in.rim);
  std::printf("\n");
  std::fflush(stdout);
  kSweep.register_batch("random", in.random);
  kSweep.register_batch("rim", in.rim);
  CaptureReporter reporter(kBatch);
  std::vector<Ratio> ratios = kSweep.ratios("random");
  for (Ratio& r : kSweep.ratios("rim")) ratios.push_back(r);
  return run_and_summarise(argc, argv, reporter, ratios);
}
