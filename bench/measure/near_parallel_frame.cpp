// geomcheck — verdicts of the compensated and the plain frame on near-parallel side-by-side pairs.
// Built with -DGEOMCHECK_MEASURE=ON (the release preset): build/release/bench/measure/near_parallel_frame.
#include <cstdio>
#include <random>
#include <cmath>
#include "geomcheck/detail/cylinder_pair.hpp"

#ifndef GAP
#define GAP 3e-10  // the gap, as a multiple of the scale; -DGAP=... for another
#endif
#include "geomcheck/oracles/engine.hpp"
using namespace geomcheck; using namespace geomcheck::oracle;
int main() {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> U(-1, 1);
  for (double th : {1e-4, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10, 1e-12, 1e-16}) {
    int bad[2] = {0, 0}, n = 0;
    for (int i = 0; i < 300; ++i) {
      Vec3 u{U(rng), U(rng), U(rng)}; u = (1 / length(u)) * u;
      Vec3 p1 = any_perpendicular(u); Vec3 p2 = cross(u, p1);
      double ang = U(rng) * 3.14159;
      Vec3 off = std::cos(ang) * p1 + std::sin(ang) * p2;
      double ra = 0.1 + 0.2 * std::fabs(U(rng)), rb = 0.1 + 0.2 * std::fabs(U(rng));
      double gap = (i % 2 ? 1 : -1) * GAP;   // separated or overlapping by GAP * scale
      Vec3 c{U(rng), U(rng), U(rng)};
      Cylinder b{c - u, c + u, rb};
      // A tilted by th about the offset direction's perpendicular, centred at distance ra+rb+gap
      Vec3 tilt = cross(u, off);
      Vec3 ua = u + th * tilt;
      Vec3 ca = c + (ra + rb + gap) * off + 0.3 * U(rng) * u;
      Cylinder a{ca - 0.7 * ua, ca + 0.7 * ua, ra};
      auto r = classify(make_shape(a), make_shape(b));
      double sd = to_double(r.distance.mid());
      if (std::fabs(sd) < 2e-10 * 2) continue;
      ++n;
      bool truth = r.verdict != Verdict::Separated;
      for (int k = 0; k < 2; ++k) {
        detail::CylinderPairOptions o; o.accurate_frame = k == 0;
        bool ov = detail::cylinder_pair(a, b, false, o).hit;
        if (ov != truth) ++bad[k];
      }
    }
    printf("theta %.0e: cases %d  accurate frame wrong %d  plain frame wrong %d\n", th, n, bad[0], bad[1]);
  }
}
