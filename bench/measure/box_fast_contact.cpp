// geomcheck — the cylinder/box consistent contact (production's collide since 2026-11-28,
// detail::collide_consistent) against the exact penetration depth (penetration(Cylinder, Obb),
// production's collide before), and an earlier prototype beside them: production's verdict and
// the best of the closed-form patch normals (+-u, +-box axes, +-u x box axis, the side x vertex
// radial directions) with three Newton steps on each circle of normals perpendicular to a box
// axis, from the best normal and from the axis. Times on the same contact pairs and depth /
// penetration depth for each.
//
// Built with -DGEOMCHECK_MEASURE=ON (the release preset): build/release/bench/measure/box_fast_contact.
//   ./box_fast_contact 4096 [seed]
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <vector>

#include "geomcheck/collide_cylinder_obb.hpp"
#include "geomcheck/detail/obb_stages.hpp"
#include "geomcheck/penetration_cylinder_obb.hpp"

using namespace geomcheck;

namespace {

struct Space {
  Vec3 P, Q, u, e;
  double r;
};

Space box_space(const Cylinder& c, const Obb& b) {
  auto to = [&](Vec3 v) { return Vec3{dot(b.axes[0], v), dot(b.axes[1], v), dot(b.axes[2], v)}; };
  Space s;
  s.P = to(c.p - b.c);
  s.Q = to(c.q - b.c);
  const Vec3 d = s.Q - s.P;
  s.u = (1.0 / length(d)) * d;
  s.e = b.e;
  s.r = c.r;
  return s;
}

struct Best {
  const Space* s;
  double o = 1e300;
  Vec3 n{0, 0, 1};
  double along(Vec3 n2) const {
    const double nu = dot(n2, s->u);
    return std::max(dot(n2, s->P), dot(n2, s->Q)) + s->r * length(n2 - nu * s->u) +
           s->e.x * std::fabs(n2.x) + s->e.y * std::fabs(n2.y) + s->e.z * std::fabs(n2.z);
  }
  void consider(Vec3 n2) {
    const double v = along(n2);
    if (v < o) o = v, n = n2;
  }
};

// Three Newton steps on the circle of normals perpendicular to box axis j, from the
// projection of `from` onto it; each step turns (c, s) by the rational half-angle rotation.
void circle(Best& b, int j, Vec3 from) {
  const Space& s = *b.s;
  const int k = (j + 1) % 3, l = (j + 2) % 3;
  const double m2 = from[k] * from[k] + from[l] * from[l];
  if (!(m2 > 1e-12)) return;
  const double im = 1 / std::sqrt(m2);
  double c = from[k] * im, sn = from[l] * im;
  for (int it = 0; it < 3; ++it) {
    const double nP = c * s.P[k] + sn * s.P[l], nQ = c * s.Q[k] + sn * s.Q[l];
    const Vec3& X = nP >= nQ ? s.P : s.Q;
    const double a1 = X[l] * c - X[k] * sn, a2 = -(X[k] * c + X[l] * sn);
    const double t = s.u[k] * c + s.u[l] * sn, t1 = s.u[l] * c - s.u[k] * sn;
    const double w2 = 1 - t * t;
    if (!(w2 > 1e-12)) return;
    const double iw = 1 / std::sqrt(w2);
    const double g1 = -s.r * t * t1 * iw, g2 = -s.r * iw * ((t1 * t1 - t * t) + t * t * t1 * t1 / w2);
    const double b0 = s.e[k] * std::fabs(c) + s.e[l] * std::fabs(sn);
    const double b1 = s.e[l] * std::copysign(1.0, sn) * c - s.e[k] * std::copysign(1.0, c) * sn;
    const double f1 = a1 + g1 + b1, f2 = a2 + g2 - b0;
    const double d = std::clamp(f2 > 0 ? -f1 / f2 : (f1 > 0 ? -0.25 : 0.25), -0.5, 0.5);
    const double h = 0.5 * d, q = 1 / (1 + h * h), cd = (1 - h * h) * q, sd = 2 * h * q;
    const double c2 = c * cd - sn * sd;
    sn = sn * cd + c * sd, c = c2;
    Vec3 m{0, 0, 0};
    m[k] = c, m[l] = sn;
    b.consider(m);
  }
}

double fast_depth(const Cylinder& c, const Obb& box, bool newton = true) {
  const Space s = box_space(c, box);
  Best b{&s};
  b.consider(s.u);
  b.consider(-s.u);
  for (int i = 0; i < 3; ++i) {
    Vec3 a{0, 0, 0};
    a[i] = 1;
    b.consider(a);
    b.consider(-a);
    const Vec3 x = cross(s.u, a);
    const double lx = length(x);
    if (lx > 0) b.consider((1 / lx) * x), b.consider((-1 / lx) * x);
  }
  for (int v = 0; v < 8; ++v) {
    const Vec3 w = Vec3{(v & 1) ? s.e.x : -s.e.x, (v & 2) ? s.e.y : -s.e.y, (v & 4) ? s.e.z : -s.e.z} - s.P;
    const Vec3 rad = w - dot(w, s.u) * s.u;
    const double lr = length(rad);
    if (lr > 0) b.consider((1 / lr) * rad);
  }
  if (!newton) return b.o;
  const Vec3 first = b.n;
  for (int j = 0; j < 3; ++j) circle(b, j, first);
  for (int j = 0; j < 3; ++j) circle(b, j, dot(first, s.u) >= 0 ? s.u : -s.u);
  return b.o;
}

}  // namespace

int main(int argc, char** argv) {
  const int n = argc > 1 ? std::atoi(argv[1]) : 4096;
  const unsigned long seed = argc > 2 ? std::strtoul(argv[2], nullptr, 0) : 20261125;
  std::printf("seed %lu, %d contact pairs\n", seed, n);
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> U(-1, 1), L(0.5, 4), R(0.1, 1.5), E(0.05, 1.5);
  auto unit = [&]() {
    for (;;) {
      const Vec3 v{U(rng), U(rng), U(rng)};
      const double l = length(v);
      if (l > 0.1 && l <= 1) return (1 / l) * v;
    }
  };
  std::vector<Cylinder> cs;
  std::vector<Obb> bs;
  while (static_cast<int>(cs.size()) < n) {
    const Vec3 p{U(rng), U(rng), U(rng)};
    const Cylinder c{p, p + L(rng) * unit(), R(rng)};
    const Vec3 a0 = unit();
    Vec3 a1 = unit();
    a1 = a1 - dot(a1, a0) * a0;
    if (length(a1) < 0.1) continue;
    a1 = (1 / length(a1)) * a1;
    Obb b{0.5 * (c.p + c.q) + (0.5 * length(c.q - c.p) + c.r + 1.5) * Vec3{U(rng), U(rng), U(rng)},
          {{a0, a1, cross(a0, a1)}},
          {E(rng), E(rng), E(rng)}};
    if (!overlap(c, b)) continue;
    cs.push_back(c), bs.push_back(b);
  }
  std::vector<double> exact(n), fast(n), fixed(n);
  for (int i = 0; i < n; ++i) {
    exact[i] = penetration(cs[i], bs[i]).depth;
    fast[i] = fast_depth(cs[i], bs[i]);
    fixed[i] = detail::collide_consistent(cs[i], bs[i]).depth;
  }
  // Times: production collide; production overlap + the prototype's normal search.
  using clk = std::chrono::steady_clock;
  double sink = 0;
  auto time = [&](auto&& f) {
    double bestns = 1e300;
    for (int rep = 0; rep < 5; ++rep) {
      const auto t0 = clk::now();
      for (int i = 0; i < n; ++i) sink += f(i);
      const double ns = std::chrono::duration<double, std::nano>(clk::now() - t0).count() / n;
      bestns = std::min(bestns, ns);
    }
    return bestns;
  };
  const double t_exact = time([&](int i) { return penetration(cs[i], bs[i]).depth; });
  const double t_over = time([&](int i) { return overlap(cs[i], bs[i]) ? 1.0 : 0.0; });
  const double t_fast = time([&](int i) { return overlap(cs[i], bs[i]) ? fast_depth(cs[i], bs[i]) : 0.0; });
  const double t_fixed = time([&](int i) { return detail::collide_consistent(cs[i], bs[i]).depth; });
  auto scale = [&](int i) {
    return std::max({max_abs(cs[i].p), max_abs(cs[i].q), cs[i].r, max_abs(bs[i].c), max_abs(bs[i].e)});
  };
  std::printf("ns per contact (best of 5 passes): penetration (exact) %.0f, overlap %.0f, collide (consistent) %.0f, "
              "prototype (overlap + closed-form normals and Newton) %.0f\n",
              t_exact, t_over, t_fixed, t_fast);
  auto report = [&](const char* what, const std::vector<double>& d) {
    std::vector<double> ratio;
    int below = 0, equal = 0;
    for (int i = 0; i < n; ++i) {
      if (d[i] < exact[i] - 1e-14 * scale(i)) ++below;  // production's bound on its depth
      if (exact[i] <= 1e-9) continue;
      ratio.push_back(d[i] / exact[i]);
      equal += d[i] <= exact[i] * (1 + 1e-12);
    }
    std::sort(ratio.begin(), ratio.end());
    auto pct = [&](double p) { return ratio[std::min(ratio.size() - 1, static_cast<size_t>(p * ratio.size()))]; };
    std::printf("%s: depth / penetration depth over %zu contacts: p50 %.4f p90 %.4f p99 %.4f max %.3f; equal (1e-12) %d; "
                "below the penetration depth by more than 1e-14 * scale: %d\n",
                what, ratio.size(), pct(0.5), pct(0.9), pct(0.99), ratio.back(), equal, below);
  };
  report("collide (consistent)", fixed);
  report("prototype: closed-form normals and Newton", fast);
  std::printf("(sink %g)\n", sink);
}
