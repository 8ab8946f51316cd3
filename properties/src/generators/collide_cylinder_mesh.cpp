// geomcheck — the mesh query's generator (collide_cylinder_mesh): gen::meshes.
//
// Meshes are built around the cylinder/triangle generator's cases (every
// near-degenerate contact it reaches) by adding faces that share its edges
// and vertices, duplicate faces, duplicate and 1-ulp-apart vertices,
// zero-area faces (repeated indices, collinear vertices) and faces further
// away, sometimes a heightfield of up to 1152 faces over the scene (deep
// hierarchies), in a random order, so the case's triangle sits anywhere in
// the hierarchy; one in 16 made invalid (an index out of range, a vertex
// not finite). The mode is the triangle generator's, "+grid" with the
// heightfield, "+index-out-of-range" or "+vertex-not-finite" when invalid.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

#include "geomcheck/properties/generators.hpp"
#include "geomcheck/properties/mesh_checks.hpp"

namespace geomcheck::gen {

// A mesh around a cylinder/triangle case; `grid`: sometimes also a
// heightfield of up to 24 x 24 cells (1152 faces) over the scene, for deep
// hierarchies.
rc::Gen<MeshCase> meshes(bool grid) {
  return rc::gen::exec([grid] {
    const auto drawn = *gen::targeted<QueryId::collide_cylinder_triangle>();
    const Cylinder cyl = drawn.first.a;
    const Triangle t = drawn.first.b;
    std::vector<Vec3> v{t.a, t.b, t.c};
    const Vec3 e1 = t.b - t.a, e2 = t.c - t.a;
    double size = std::max({max_abs(e1), max_abs(e2), max_abs(cyl.q - cyl.p), cyl.r});
    if (!(size > 0) || !std::isfinite(size)) size = 1;
    const int extra = *rc::gen::inRange(0, 12);
    for (int i = 0; i < extra; ++i) {
      const std::size_t n = v.size();
      const Vec3 a = v[*rc::gen::inRange<std::size_t>(0, n)], b = v[*rc::gen::inRange<std::size_t>(0, n)],
                 c = v[*rc::gen::inRange<std::size_t>(0, n)];
      Vec3 w;
      switch (*rc::gen::inRange(0, 6)) {
        case 0: w = a; break;                                                     // duplicate vertex
        case 1: w = {std::nextafter(a.x, INFINITY), a.y, std::nextafter(a.z, -INFINITY)}; break;  // 1 ulp apart
        case 2: w = 0.5 * (a + b); break;                                         // (nearly) collinear
        case 3: w = b + c - a; break;                                             // across an edge
        default: {                                                                 // nearby, any way
          const double s = size * std::ldexp(1.0, *rc::gen::inRange(-3, 3));
          w = a + Vec3{s * *rc::gen::inRange(-1000, 1001) / 1000.0, s * *rc::gen::inRange(-1000, 1001) / 1000.0,
                       s * *rc::gen::inRange(-1000, 1001) / 1000.0};
        }
      }
      if (!is_finite(w)) w = a;
      v.push_back(w);
    }
    const auto nv = static_cast<std::uint32_t>(v.size());
    std::vector<MeshFace> f{{0, 1, 2}};
    const int nf = *rc::gen::inRange(0, 24);
    for (int i = 0; i < nf; ++i) {
      auto pick = [&] { return *rc::gen::inRange<std::uint32_t>(0, nv); };
      switch (*rc::gen::inRange(0, 5)) {
        case 0: f.push_back(f[*rc::gen::inRange<std::size_t>(0, f.size())]); break;  // duplicate face
        case 1: {                                                                       // shares an edge
          const MeshFace& g = f[*rc::gen::inRange<std::size_t>(0, f.size())];
          const int k = *rc::gen::inRange(0, 3);
          f.push_back({g[(k + 1) % 3], g[k], pick()});
          break;
        }
        case 2: {  // zero area: a repeated index
          const std::uint32_t a = pick();
          f.push_back({a, a, pick()});
          break;
        }
        default: f.push_back({pick(), pick(), pick()});
      }
    }
    const bool gridded = grid && *rc::gen::inRange(0, 3) == 0;
    if (gridded) {
      const int k = *rc::gen::inRange(2, 25);
      const double cell = size * std::ldexp(1.0, *rc::gen::inRange(-4, 2));
      const Vec3 o = t.a - (0.5 * k * cell) * Vec3{1, 1, 0};
      const auto base = static_cast<std::uint32_t>(v.size());
      for (int i = 0; i <= k; ++i)
        for (int j = 0; j <= k; ++j)
          v.push_back(o + Vec3{i * cell, j * cell, cell * 0.25 * *rc::gen::inRange(-4, 5)});
      auto at = [&](int i, int j) { return base + static_cast<std::uint32_t>(i * (k + 1) + j); };
      for (int i = 0; i < k; ++i)
        for (int j = 0; j < k; ++j) {
          f.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
          f.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
        }
    }
    // A random order: the case's triangle anywhere.
    const auto perm = *rc::gen::container<std::vector<int>>(f.size(), rc::gen::inRange(0, 1 << 30));
    std::vector<std::pair<int, MeshFace>> keyed;
    for (std::size_t i = 0; i < f.size(); ++i) keyed.push_back({perm[i], f[i]});
    std::stable_sort(keyed.begin(), keyed.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
    for (std::size_t i = 0; i < f.size(); ++i) f[i] = keyed[i].second;
    // One mesh in 16 made invalid: a face naming a vertex beyond the last,
    // or a vertex not finite (the query must then answer no overlap).
    std::string invalid;
    if (*rc::gen::inRange(0, 16) == 0) {
      if (*rc::gen::inRange(0, 2) == 0) {
        const std::uint32_t beyond = *rc::gen::inRange<std::uint32_t>(0, 3);
        const std::size_t at = *rc::gen::inRange<std::size_t>(0, f.size() + 1);
        f.insert(f.begin() + at, MeshFace{0, 1, static_cast<std::uint32_t>(v.size()) + beyond});
        invalid = "+index-out-of-range";
      } else {
        v[*rc::gen::inRange<std::size_t>(0, v.size())].y = *rc::gen::element(NAN, INFINITY, -INFINITY);
        invalid = "+vertex-not-finite";
      }
    }
    return MeshCase{cyl, std::move(v), std::move(f), drawn.second + (gridded ? "+grid" : "") + invalid};
  });
}

std::vector<Tagged<MeshCase>> draw_meshes(std::uint64_t seed, int n) {
  const auto gen = meshes(true);
  rc::Random random(seed ^ 0x6d657368c0ffee00ull);
  std::vector<Tagged<MeshCase>> out;
  out.reserve(n > 0 ? n : 0);
  for (int i = 0; i < n; ++i) {
    MeshCase c = gen(random.split(), rc::kNominalSize).value();
    std::string mode = c.mode;
    out.emplace_back(std::move(c), std::move(mode));
  }
  return out;
}

}  // namespace geomcheck::gen
