// geomcheck — properties of collide(Cylinder, TriangleMesh).
//
// The mesh query is the triangle query over the faces the hierarchy
// reaches, so its properties are: the hierarchy's answers equal the brute
// force over every face in index order, bit for bit (overlap, hit, depth,
// normal, point, face index); the contact is the deepest face's triangle
// answer (smallest index on ties) and the verdict is "some face overlaps";
// and, against the certified engine face by face, the verdict is exact
// outside the band and the reported face's contact meets the triangle
// query's claims (check_oracle of collide_cylinder_triangle).
//
// Meshes are built around the cylinder/triangle generator's cases (every
// near-degenerate contact it reaches) by adding faces that share its edges
// and vertices, duplicate faces, duplicate and 1-ulp-apart vertices,
// zero-area faces (repeated indices, collinear vertices) and faces further
// away, sometimes a heightfield of up to 1152 faces over the scene (deep
// hierarchies), in a random order, so the case's triangle sits anywhere in
// the hierarchy. A failure prints the mesh and cylinder in hexadecimal and the
// command that reruns the property.
#include <gtest/gtest.h>
#include <rapidcheck.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <cstdint>
#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

#include "geomcheck/properties/generators.hpp"
#include "geomcheck/collide_cylinder_mesh.hpp"
#include "geomcheck/collide_cylinder_triangle.hpp"
#include "geomcheck/properties/checks.hpp"
#include "geomcheck/properties/tolerances.hpp"
#include "support.hpp"

namespace geomcheck {
namespace {

struct MeshCase {
  Cylinder cyl;
  std::vector<Vec3> vertices;
  std::vector<MeshFace> faces;
  std::string tag;
};

/// A point's coordinates as hexadecimal floats (the case files' form).
std::string hex(Vec3 v) {
  return "(" + format_double(v.x) + ", " + format_double(v.y) + ", " + format_double(v.z) + ")";
}

std::string describe(const MeshCase& c) {
  std::ostringstream os;
  os << "[" << c.tag << "] cylinder p=" << hex(c.cyl.p) << " q=" << hex(c.cyl.q) << " r=" << format_double(c.cyl.r)
     << "\n  " << c.vertices.size() << " vertices:";
  for (std::size_t i = 0; i < c.vertices.size(); ++i) os << "\n    v" << i << " " << hex(c.vertices[i]);
  os << "\n  " << c.faces.size() << " faces:";
  for (std::size_t i = 0; i < c.faces.size(); ++i)
    os << "\n    f" << i << " " << c.faces[i][0] << " " << c.faces[i][1] << " " << c.faces[i][2];
  return os.str();
}

std::string describe(const Contact& k) {
  if (!k.hit) return "no hit";
  return "depth=" + format_double(k.depth) + " normal=" + hex(k.normal) + " point=" + hex(k.point);
}

bool same(const Contact& a, const Contact& b) {
  if (a.hit != b.hit) return false;
  if (!a.hit) return true;
  auto eq = [](double x, double y) { return x == y || (std::isnan(x) && std::isnan(y)); };
  auto eqv = [&](Vec3 x, Vec3 y) { return eq(x.x, y.x) && eq(x.y, y.y) && eq(x.z, y.z); };
  return eq(a.depth, b.depth) && eqv(a.normal, b.normal) && eqv(a.point, b.point);
}

// A mesh around a cylinder/triangle case; `grid`: sometimes also a
// heightfield of up to 24 x 24 cells (1152 faces) over the scene, for deep
// hierarchies.
rc::Gen<MeshCase> mesh_case(bool grid) {
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
    if (grid && *rc::gen::inRange(0, 3) == 0) {
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
    return MeshCase{cyl, std::move(v), std::move(f), drawn.second};
  });
}

struct Outcome {
  int cases = 0, hits = 0;
};

// Runs `check` (empty string: pass) over the generator; `cap` bounds the
// number of cases (0: RC_PARAMS as given).
Outcome run(const char* name, int cap, bool grid,
            const std::function<std::string(const MeshCase&, const TriangleMesh&)>& check) {
  Outcome out;
  auto prop = [&] {
    const MeshCase c = *mesh_case(grid);
    const TriangleMesh mesh(c.vertices, c.faces);
    ++out.cases;
    const bool hit = overlap(c.cyl, mesh);
    out.hits += hit;
    RC_TAG(hit ? "hit" : "miss");
    const std::string f = check(c, mesh);
    if (!f.empty()) RC_FAIL(f + "\n" + describe(c));
  };
  rc::detail::TestMetadata meta;
  meta.id = name;
  meta.description = name;
  const auto& config = rc::detail::configuration();
  auto params = config.testParams;
  if (cap > 0 && params.maxSuccess > cap) params.maxSuccess = cap;
  const auto result = rc::detail::checkTestable(prop, meta, params, listener(), config.reproduce);
  rc::detail::SuccessResult success;
  std::printf("[property] collide_cylinder_mesh.%s: %d cases, %d hits (seed %llu)\n", name, out.cases, out.hits,
              static_cast<unsigned long long>(params.seed));
  if (!result.match(success)) {
    std::ostringstream os;
    rc::detail::printResultMessage(result, os);
    ADD_FAILURE() << "collide_cylinder_mesh." << name << " failed:\n"
                  << os.str() << "\nrerun it:   RC_PARAMS=\"seed=" << params.seed
                  << "\" ./properties/tests/test_mesh --gtest_filter=collide_cylinder_mesh." << name;
  } else {
    EXPECT_GT(out.hits, out.cases / 10) << "too few overlapping cases";
    EXPECT_LT(out.hits, out.cases - out.cases / 10) << "too few separated cases";
  }
  return out;
}

TEST(collide_cylinder_mesh, bvh_equals_brute_force) {
  run("bvh_equals_brute_force", 0, true, [](const MeshCase& c, const TriangleMesh& m) -> std::string {
    const bool o = overlap(c.cyl, m), ob = detail::overlap_brute_force(c.cyl, m);
    if (o != ob) return std::string("overlap: hierarchy ") + (o ? "yes" : "no") + ", brute force " + (ob ? "yes" : "no");
    std::uint32_t i = 0xffffffffu, ib = 0xffffffffu;
    const Contact k = collide(c.cyl, m, &i), kb = detail::collide_brute_force(c.cyl, m, &ib);
    if (!same(k, kb) || i != ib)
      return "collide: hierarchy face " + std::to_string(i) + " " + describe(k) + "; brute force face " +
             std::to_string(ib) + " " + describe(kb);
    if (k.hit != o) return "collide.hit differs from overlap";
    // Argument order: the same contact, normal negated.
    std::uint32_t j = 0xffffffffu;
    const Contact s = collide(m, c.cyl, &j);
    if (s.hit != k.hit || j != i || (k.hit && !(s.normal == -k.normal && s.depth == k.depth && s.point == k.point)))
      return "collide(mesh, cylinder) is not the flipped collide(cylinder, mesh)";
    return {};
  });
}

// The face filter (mesh_face_gap) skips a face only when it is apart by
// more than its margin, far above its rounding: it must never skip a face
// the triangle query finds overlapping. Driven by the cylinder/triangle
// generator's near-degenerate cases (exact touches at caps, rims and sides,
// nudged by ulps), where the computed gap of an overlapping face comes
// within rounding of 0. The test prints how close the overlapping faces
// came to the margin, and holds that they came within 2^-40 of 0: a filter
// off by more than that (a margin of -2^-40, or a support term left out)
// would skip some of them and fail here.
TEST(collide_cylinder_mesh, face_filter_sound) {
  const double margin = detail::mesh_face_margin();
  double closest = -INFINITY;
  int cases = 0, overlapping = 0, above_zero = 0;
  const auto result = rc::check("face filter", [&] {
    const auto drawn = *gen::targeted<QueryId::collide_cylinder_triangle>();
    const Cylinder& cyl = drawn.first.a;
    const Triangle& t = drawn.first.b;
    ++cases;
    if (!overlap(cyl, t)) return;
    ++overlapping;
    const double g = detail::mesh_face_gap(cyl, t);
    closest = std::max(closest, g);
    above_zero += g > 0;
    RC_ASSERT(!(g > margin));
  });
  std::printf("[property] collide_cylinder_mesh.face_filter_sound: %d cases, %d overlapping; largest gap of an "
              "overlapping face %.3g (margin %.3g); %d above 0\n",
              cases, overlapping, closest, margin, above_zero);
  EXPECT_TRUE(result);
  EXPECT_GT(overlapping, cases / 10);
  EXPECT_GT(closest, -0x1p-40) << "no overlapping face came near the filter's threshold";
}

TEST(collide_cylinder_mesh, deepest_face) {
  run("deepest_face", 5000, true, [](const MeshCase& c, const TriangleMesh& m) -> std::string {
    std::uint32_t idx = 0xffffffffu;
    const Contact k = collide(c.cyl, m, &idx);
    bool any = false;
    double deepest = -INFINITY;
    std::uint32_t first = 0xffffffffu;
    for (std::uint32_t f = 0; f < m.size(); ++f) {
      const Triangle t = m.triangle(f);
      if (!overlap(c.cyl, t)) continue;
      any = true;
      const Contact kf = collide(c.cyl, t);
      if (kf.depth > deepest) deepest = kf.depth, first = f;
    }
    if (k.hit != any) return std::string("mesh hit ") + (k.hit ? "yes" : "no") + " but some face overlaps: " + (any ? "yes" : "no");
    if (!k.hit) return {};
    if (idx != first)
      return "reported face " + std::to_string(idx) + ", the deepest (smallest index) is " + std::to_string(first);
    const Contact kf = collide(c.cyl, m.triangle(idx));
    if (!same(k, kf)) return "contact differs from the face's own: " + describe(k) + " vs " + describe(kf);
    return {};
  });
}

TEST(collide_cylinder_mesh, oracle_agreement) {
  // The engine face by face: about 50 faces' worth of certified verdicts a
  // case, so fewer cases than the other properties.
  run("oracle_agreement", 1500, false, [](const MeshCase& c, const TriangleMesh& m) -> std::string {
    bool robust_hit = false, all_robust_miss = true;
    std::string hit_text;
    for (std::uint32_t f = 0; f < m.size(); ++f) {
      const CylinderTriangleCase tc{c.cyl, m.triangle(f)};
      const Evaluation e = evaluate(tc);
      if (!e.valid) return "invalid face " + std::to_string(f);
      if (e.truth_hit && !e.near_boundary) robust_hit = true, hit_text = "face " + std::to_string(f) + ": " + e.truth_text;
      if (e.truth_hit || e.near_boundary) all_robust_miss = false;
    }
    std::uint32_t idx = 0xffffffffu;
    const Contact k = collide(c.cyl, m, &idx);
    if (robust_hit && !k.hit) return "missed: " + hit_text;
    if (all_robust_miss && k.hit) return "false hit on face " + std::to_string(idx) + ": every face is separated beyond the band";
    if (k.hit) {
      if (idx >= m.size()) return "face index out of range";
      if (auto f = check_oracle(CylinderTriangleCase{c.cyl, m.triangle(idx)}))
        return "face " + std::to_string(idx) + ": " + f->property + ": " + f->detail;
    }
    return {};
  });
}

TEST(collide_cylinder_mesh, invalid_input) {
  const Cylinder cyl{{0, 0, 0}, {0, 0, 1}, 1};
  const std::vector<Vec3> v{{0, 0, 0.5}, {1, 0, 0.5}, {0, 1, 0.5}};
  const TriangleMesh ok(v, {{0, 1, 2}});
  EXPECT_TRUE(overlap(cyl, ok));
  const TriangleMesh out_of_range(v, {{0, 1, 3}});
  EXPECT_FALSE(out_of_range.valid());
  EXPECT_FALSE(overlap(cyl, out_of_range));
  EXPECT_FALSE(collide(cyl, out_of_range).hit);
  const TriangleMesh nan_vertex({{0, 0, 0.5}, {NAN, 0, 0.5}, {0, 1, 0.5}}, {{0, 1, 2}});
  EXPECT_FALSE(nan_vertex.valid());
  EXPECT_FALSE(overlap(cyl, nan_vertex));
  const TriangleMesh empty;
  EXPECT_FALSE(overlap(cyl, empty));
  std::uint32_t idx = 7;
  EXPECT_FALSE(collide(cyl, empty, &idx).hit);
  EXPECT_EQ(idx, 7u);  // left alone on no hit
  EXPECT_FALSE(overlap(Cylinder{{0, 0, 0}, {0, 0, 1}, -1}, ok));
}

}  // namespace
}  // namespace geomcheck
