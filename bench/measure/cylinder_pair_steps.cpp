// geomcheck — collide(Cylinder, Cylinder): depth / certified penetration depth
// and time per contact, without and with the rim x rim candidate, by the
// number of Newton steps on the circles of side normals, on the contact pairs
// of bench_collide_cylinder_cylinder's layout.
//
// Built with -DGEOMCHECK_MEASURE=ON (the release preset): build/release/bench/measure/cylinder_pair_steps.
//   ./cylinder_pair_steps [pairs=2000] [seed=1]
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "bench_random.hpp"
#include "geomcheck/collide_cylinder_cylinder.hpp"
#include "geomcheck/detail/cylinder_pair.hpp"
#include "geomcheck/oracles/engine.hpp"

using namespace geomcheck;

int main(int argc, char** argv) {
  const int n = argc > 1 ? std::atoi(argv[1]) : 2000;
  const unsigned long long seed = argc > 2 ? std::strtoull(argv[2], nullptr, 0) : 1;
  bench::Rng rng(seed);
  std::vector<Cylinder> as, bs;
  std::vector<double> pd;
  while (static_cast<int>(as.size()) < n) {
    // bench_collide_cylinder_cylinder's random pair
    const Cylinder a = rng.cylinder();
    const Vec3 mid = 0.5 * a.p + 0.5 * a.q;
    const double reach = 0.5 * length(a.q - a.p) + a.r;
    const Vec3 c = mid + rng.in_box(reach + 1.5);
    const Vec3 half = (0.5 * rng.uniform(0.5, 4.0)) * rng.direction();
    const Cylinder b{c - half, c + half, rng.uniform(0.1, 1.5)};
    if (!overlap(a, b)) continue;
    const auto A = oracle::make_shape(a), B = oracle::make_shape(b);
    const auto p = oracle::penetration(A, B, 1e-12);
    if (!p.overlapping) continue;
    const double lo = oracle::to_double(p.depth.lo), hi = oracle::to_double(p.depth.hi);
    if (!(lo >= 1e-9) || hi - lo > 1e-3 * lo) continue;
    as.push_back(a), bs.push_back(b), pd.push_back(0.5 * (lo + hi));
  }
  std::printf("seed %llu, %d contact pairs (penetration depth >= 1e-9, enclosed within 0.1%%)\n", seed, n);
  for (int variant = 0; variant < 10; ++variant) {
    const int steps = variant % 5;
    detail::CylinderPairOptions opt;
    opt.newton_steps = steps;
    opt.rim_rim = variant >= 5;
    std::vector<double> ratio(n);
    int below = 0;
    for (int i = 0; i < n; ++i) {
      const Contact k = detail::cylinder_pair(as[i], bs[i], true, opt);
      ratio[i] = k.depth / pd[i];
      below += k.depth < pd[i] * (1 - 1e-9);
    }
    std::sort(ratio.begin(), ratio.end());
    auto pct = [&](double q) { return ratio[std::min<std::size_t>(n - 1, static_cast<std::size_t>(q * n))]; };
    double best = 1e300, sink = 0;
    for (int rep = 0; rep < 20; ++rep) {
      const auto t0 = std::chrono::steady_clock::now();
      for (int i = 0; i < n; ++i) sink += detail::cylinder_pair(as[i], bs[i], true, opt).depth;
      best = std::min(best, std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - t0).count() / n);
    }
    std::printf("rim-rim %d, steps %d: depth / PD p50 %.5f p90 %.5f p99 %.5f p99.9 %.4f max %.4f, below %d; %.1f ns (sink %g)\n", int(opt.rim_rim), steps,
                pct(0.5), pct(0.9), pct(0.99), pct(0.999), ratio.back(), below, best, sink);
  }
}
