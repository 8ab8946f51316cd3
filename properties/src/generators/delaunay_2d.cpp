// geomcheck — generators of delaunay_2d: point sets that reach the hard places
// of a triangulation (uniform, clustered at 2^-40, grids scaled by 2^+-30,
// rotated grids within rounding of cocircular, exactly and almost collinear
// sets, near duplicates, degenerate positions moved by ulps, huge and tiny
// coordinates and their mixes).
#include <algorithm>
#include <cmath>
#include <cstdint>

#include "common.hpp"

namespace geomcheck::gen {

using namespace detail;
using Points = std::vector<Vec2>;

namespace {
double unit(std::uint64_t bits) { return static_cast<double>(bits >> 11) * 0x1p-53; }  // [0, 1), 53 bits
}  // namespace

rc::Gen<Points> uniform_points(double scale) {
  return rc::gen::map(rc::gen::container<std::vector<std::pair<std::uint64_t, std::uint64_t>>>(
                          rc::gen::pair(rc::gen::arbitrary<std::uint64_t>(), rc::gen::arbitrary<std::uint64_t>())),
                      [scale](const std::vector<std::pair<std::uint64_t, std::uint64_t>>& v) {
                        Points p;
                        for (auto [a, b] : v) p.push_back({(2 * unit(a) - 1) * scale, (2 * unit(b) - 1) * scale});
                        return p;
                      });
}

// Integer grid (a random subset, in random order), scaled by 2^e.
rc::Gen<Points> grid_points() {
  return rc::gen::exec([] {
    const int w = *rc::gen::inRange(1, 12), h = *rc::gen::inRange(1, 12);
    const int e = *rc::gen::inRange(-30, 30);
    const int keep = *rc::gen::inRange(50, 101);
    Points p;
    for (int i = 0; i < w; ++i)
      for (int j = 0; j < h; ++j)
        if (*rc::gen::inRange(0, 100) < keep) p.push_back({std::ldexp(i, e), std::ldexp(j, e)});
    return p;
  });
}

// All collinear (exactly: small integer multiples of an integer direction),
// optionally with one point moved off the line by a few ulps.
rc::Gen<Points> collinear_points(bool almost) {
  return rc::gen::exec([almost] {
    const int dx = *rc::gen::inRange(-7, 8), dy = *rc::gen::inRange(-7, 8);
    const double ox = *rc::gen::inRange(-50, 50) * 0.25, oy = *rc::gen::inRange(-50, 50) * 0.25;
    const int k = *rc::gen::inRange(2, 40);
    Points p;
    for (int i = 0; i < k; ++i) {
      const int t = *rc::gen::inRange(-1000, 1000);
      p.push_back({ox + t * dx, oy + t * dy});
    }
    if (almost) {
      const std::size_t i = *rc::gen::inRange<std::size_t>(0, p.size());
      const int u = *rc::gen::element(-3, -2, -1, 1, 2, 3);
      if (*rc::gen::arbitrary<bool>()) p[i].x = nudge(p[i].x, u);
      else p[i].y = nudge(p[i].y, u);
    }
    return p;
  });
}

namespace {

// Clusters: a few centres with points 2^-k around them (k up to 40).
rc::Gen<Points> clustered_points() {
  return rc::gen::exec([] {
    const int clusters = *rc::gen::inRange(1, 5);
    Points p;
    for (int c = 0; c < clusters; ++c) {
      const Vec2 centre{*rc::gen::inRange(-100, 100) * 0.37, *rc::gen::inRange(-100, 100) * 0.53};
      const double r = std::ldexp(1.0, -*rc::gen::inRange(0, 40));
      const int k = *rc::gen::inRange(1, 40);
      for (int i = 0; i < k; ++i)
        p.push_back({centre.x + r * (2 * unit(*rc::gen::arbitrary<std::uint64_t>()) - 1),
                     centre.y + r * (2 * unit(*rc::gen::arbitrary<std::uint64_t>()) - 1)});
    }
    return p;
  });
}


// An integer grid rotated by a random angle in doubles: every square is
// within rounding of cocircular.
rc::Gen<Points> rotated_grid_points() {
  return rc::gen::exec([] {
    const int w = *rc::gen::inRange(2, 10), h = *rc::gen::inRange(2, 10);
    const double angle = unit(*rc::gen::arbitrary<std::uint64_t>()) * 6.283185307179586;
    const double c = std::cos(angle), s = std::sin(angle);
    const double ox = *rc::gen::inRange(-1000, 1000), oy = *rc::gen::inRange(-1000, 1000);
    Points p;
    for (int i = 0; i < w; ++i)
      for (int j = 0; j < h; ++j) p.push_back({ox + i * c - j * s, oy + i * s + j * c});
    return p;
  });
}


// A few base points repeated and moved by 0 to 2 ulps.
rc::Gen<Points> near_duplicate_points() {
  return rc::gen::exec([] {
    const Points base = *rc::gen::resize(8, uniform_points(1.0));
    Points p;
    if (base.empty()) return p;
    const int k = *rc::gen::inRange(1, 60);
    for (int i = 0; i < k; ++i) {
      Vec2 q = base[*rc::gen::inRange<std::size_t>(0, base.size())];
      q.x = nudge(q.x, *rc::gen::inRange(-2, 3));
      q.y = nudge(q.y, *rc::gen::inRange(-2, 3));
      p.push_back(q);
    }
    return p;
  });
}

// Degenerate positions (grid points, points on a circle of integer points)
// each moved by a few ulps.
rc::Gen<Points> ulp_perturbed_points() {
  return rc::gen::exec([] {
    Points p;
    if (*rc::gen::arbitrary<bool>()) {
      const int w = *rc::gen::inRange(2, 9), h = *rc::gen::inRange(2, 9);
      const double step = *rc::gen::element(0.1, 0.3, 1.0, 1e-3, 7.0);
      for (int i = 0; i < w; ++i)
        for (int j = 0; j < h; ++j) p.push_back({i * step, j * step});
    } else {
      // The 12 integer points at distance 5 and 5*13 = 65 from the centre.
      const int r = *rc::gen::element(5, 25, 65);
      for (int x = -r; x <= r; ++x)
        for (int y = -r; y <= r; ++y)
          if (x * x + y * y == r * r) p.push_back({double(x), double(y)});
    }
    const int spread = *rc::gen::inRange(0, 4);
    for (Vec2& q : p) {
      q.x = nudge(q.x, *rc::gen::inRange(-spread, spread + 1));
      q.y = nudge(q.y, *rc::gen::inRange(-spread, spread + 1));
    }
    return p;
  });
}

// Huge (2^900..2^1000), tiny (2^-1070..2^-900, subnormals included) and
// mixes of both.
rc::Gen<Points> extreme_points() {
  return rc::gen::exec([] {
    const int mode = *rc::gen::inRange(0, 3);
    Points p = *rc::gen::oneOf(uniform_points(1.0), grid_points(), ulp_perturbed_points());
    // The base set brought below 1 in magnitude first, so that 2^1000 cannot overflow.
    double top = 0;
    for (const Vec2& q : p) top = std::max({top, std::fabs(q.x), std::fabs(q.y)});
    const int base = top > 0 ? std::ilogb(top) + 1 : 0;
    for (std::size_t i = 0; i < p.size(); ++i) {
      const bool huge = mode == 0 || (mode == 2 && i % 2 == 0);
      const int e = (huge ? *rc::gen::inRange(900, 1000) : *rc::gen::inRange(-1070, -900)) - base;
      p[i] = {std::ldexp(p[i].x, e), std::ldexp(p[i].y, e)};
    }
    return p;
  });
}

}  // namespace

std::vector<PointSetMode> point_set_modes() {
  return {{"uniform", uniform_points(1.0)},
          {"clustered", clustered_points()},
          {"grid", grid_points()},
          {"rotated-grid", rotated_grid_points()},
          {"collinear", collinear_points(false)},
          {"almost-collinear", collinear_points(true)},
          {"near-duplicates", near_duplicate_points()},
          {"ulp-perturbed", ulp_perturbed_points()},
          {"huge-tiny", extreme_points()}};
}

rc::Gen<Tagged<Points>> point_sets() {
  std::vector<rc::Gen<Tagged<Points>>> gens;
  for (const PointSetMode& m : point_set_modes()) {
    const std::string name = m.name;
    gens.push_back(rc::gen::map(m.gen, [name](Points p) { return std::make_pair(std::move(p), name); }));
  }
  return rc::gen::join(rc::gen::elementOf(gens));
}

std::vector<Tagged<Points>> draw_point_sets(std::uint64_t seed, int n) {
  const auto gen = point_sets();
  rc::Random random(seed ^ 0xd1b54a32d192ed03ull);
  std::vector<Tagged<Points>> sets;
  for (int i = 0; i < n; ++i) sets.push_back(gen(random.split(), rc::kNominalSize).value());
  return sets;
}

}  // namespace geomcheck::gen
