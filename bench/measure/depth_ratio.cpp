// geomcheck — depth / certified penetration depth of collide(Cylinder, Cylinder) on random pairs.
// Built with -DGEOMCHECK_MEASURE=ON (the release preset): build/release/bench/measure/depth_ratio.
//   ./depth_ratio 3000 0   (mode 1: near-parallel, 2: parallel)
#include <cstdio>
#include <random>
#include <cmath>
#include "geomcheck/collide_cylinder_cylinder.hpp"
#include "geomcheck/detail/cylinder_pair.hpp"
#include "geomcheck/oracles/engine.hpp"
using namespace geomcheck;
using namespace geomcheck::oracle;
int main(int argc, char** argv) {
  int n = argc > 1 ? atoi(argv[1]) : 2000;
  int mode = argc > 2 ? atoi(argv[2]) : 0;
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> U(-1, 1), P(0.05, 1);
  int bad = 0, hits = 0, near = 0;
  std::vector<double> ratios;
  for (int i = 0; i < n; ++i) {
    Cylinder a{{U(rng), U(rng), U(rng)}, {U(rng), U(rng), U(rng)}, P(rng) * 0.5};
    Cylinder b{{U(rng), U(rng), U(rng)}, {U(rng), U(rng), U(rng)}, P(rng) * 0.5};
    if (mode == 1) { // near parallel
      double th = std::pow(10.0, -4 - 12 * (i % 100) / 100.0);
      Vec3 d = b.q - b.p; Vec3 pp = any_perpendicular(d);
      a.q = a.p + d + th * length(d) * pp;
    }
    if (mode == 2) { a.q = a.p + (b.q - b.p); }
    auto A = make_shape(a), B = make_shape(b);
    auto r = classify(A, B);
    double sd = to_double(r.distance.mid());
    bool truth = r.verdict != Verdict::Separated;
    bool ov = overlap(a, b);
    Contact c = collide(a, b);
    if (ov != c.hit) { printf("case %d overlap/collide mismatch\n", i); }
    if (std::fabs(sd) < 1e-10 * 2) { ++near; continue; }
    if (ov != truth) { ++bad; if (bad < 10) printf("case %d: prod %d truth %d sd %.3g\n", i, ov, truth, sd); }
    if (truth && c.hit) {
      ++hits;
      auto pd = penetration(A, B, 1e-9);
      double pdv = to_double(pd.depth.mid());
      if (pdv > 1e-6) ratios.push_back(c.depth / pdv);
    }
  }
  std::sort(ratios.begin(), ratios.end());
  printf("n %d hits %d near %d bad %d\n", n, hits, near, bad);
  if (!ratios.empty()) printf("ratio min %.4f med %.4f p90 %.4f p99 %.4f max %.4f\n", ratios[0], ratios[ratios.size()/2], ratios[ratios.size()*9/10], ratios[ratios.size()*99/100], ratios.back());
}
