// The CGAL translation unit of the 3D Delaunay oracles (see the header).
#include "geomcheck/oracles/delaunay_3d.hpp"

// In fuzz builds the library goes without coverage instrumentation as a
// whole (oracles/CMakeLists.txt); the sanitizers stay on.
#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Mpzf.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <utility>

namespace geomcheck::oracle {

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using P3 = K::Point_3;
using Facet = std::array<std::uint32_t, 3>;

P3 cg(Vec3 p) { return P3(p.x, p.y, p.z); }

std::string pt(const std::vector<Vec3>& pts, std::uint32_t i) {
  char buf[160];
  std::snprintf(buf, sizeof buf, "%u (%a, %a, %a)", i, pts[i].x, pts[i].y, pts[i].z);
  return buf;
}
std::string tet_text(const std::vector<Vec3>& pts, std::uint32_t i, const Tetrahedron& t) {
  return "tetrahedron " + std::to_string(i) + " (" + pt(pts, t[0]) + ", " + pt(pts, t[1]) + ", " + pt(pts, t[2]) +
         ", " + pt(pts, t[3]) + ")";
}

}  // namespace

IntegerSigns3::IntegerSigns3(const std::vector<Vec3>& pts) {
  // Each coordinate is m 2^e with m an odd integer: the span from the
  // lowest set bit of any coordinate to the highest of any.
  int lowest = 1 << 20, highest = -(1 << 20);
  for (const Vec3& p : pts)
    for (double v : {p.x, p.y, p.z}) {
      if (v == 0) continue;
      if (!std::isfinite(v)) return;
      int e = 0;
      const double f = std::frexp(v, &e);  // |f| in [0.5, 1), v = f 2^e
      const auto m = static_cast<std::int64_t>(std::ldexp(std::fabs(f), 53));
      lowest = std::min(lowest, e - 53 + __builtin_ctzll(static_cast<unsigned long long>(m)));
      highest = std::max(highest, e);
    }
  if (highest - lowest > kMaxBits) return;
  if (highest < lowest) lowest = 0;  // every coordinate zero
  coords_.reserve(pts.size());
  for (const Vec3& p : pts)
    coords_.push_back({std::llround(std::ldexp(p.x, -lowest)), std::llround(std::ldexp(p.y, -lowest)),
                       std::llround(std::ldexp(p.z, -lowest))});
  ok_ = true;
}

int IntegerSigns3::orientation(std::uint32_t p, std::uint32_t q, std::uint32_t r, std::uint32_t s) const {
  // CGAL's orientationC3: the sign of det(q - p, r - p, s - p).
  const auto& a = coords_[p];
  const __int128 qx = coords_[q][0] - a[0], qy = coords_[q][1] - a[1], qz = coords_[q][2] - a[2];
  const __int128 rx = coords_[r][0] - a[0], ry = coords_[r][1] - a[1], rz = coords_[r][2] - a[2];
  const __int128 sx = coords_[s][0] - a[0], sy = coords_[s][1] - a[1], sz = coords_[s][2] - a[2];
  const __int128 det = qx * (ry * sz - rz * sy) - qy * (rx * sz - rz * sx) + qz * (rx * sy - ry * sx);
  return (det > 0) - (det < 0);
}

int IntegerSigns3::side_of_oriented_sphere(std::uint32_t p, std::uint32_t q, std::uint32_t r, std::uint32_t s,
                                           std::uint32_t t) const {
  // CGAL's side_of_oriented_sphereC3: the sign of the 4x4 determinant of
  // the rows p - t, r - t, q - t, s - t, each with its squared length.
  const auto& o = coords_[t];
  __int128 m[4][4];
  const std::uint32_t rows[4] = {p, r, q, s};
  for (int i = 0; i < 4; ++i) {
    const auto& v = coords_[rows[i]];
    const __int128 x = v[0] - o[0], y = v[1] - o[1], z = v[2] - o[2];
    m[i][0] = x, m[i][1] = y, m[i][2] = z, m[i][3] = x * x + y * y + z * z;
  }
  // Expansion along the last column by 2x2 minors of the first two rows and
  // of the last two.
  auto minor2 = [&](int r0, int r1, int c0, int c1) { return m[r0][c0] * m[r1][c1] - m[r0][c1] * m[r1][c0]; };
  __int128 det = 0;
  // Laplace expansion over the column pairs of rows (0, 1) and (2, 3).
  static constexpr int kPairs[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};
  static constexpr int kSigns[6] = {1, -1, 1, 1, -1, 1};
  for (int k = 0; k < 6; ++k) {
    const int c0 = kPairs[k][0], c1 = kPairs[k][1];
    const int d0 = kPairs[5 - k][0], d1 = kPairs[5 - k][1];  // the complementary columns
    det += kSigns[k] * minor2(0, 1, c0, c1) * minor2(2, 3, d0, d1);
  }
  return (det > 0) - (det < 0);
}

namespace {

// Smallest index of each distinct point, by sorting.
std::vector<std::uint32_t> representatives(const std::vector<Vec3>& pts) {
  std::vector<std::uint32_t> idx(pts.size());
  std::iota(idx.begin(), idx.end(), 0u);
  auto key = [&](std::uint32_t a) { return std::make_tuple(pts[a].x, pts[a].y, pts[a].z); };
  std::sort(idx.begin(), idx.end(), [&](std::uint32_t a, std::uint32_t b) {
    return key(a) != key(b) ? key(a) < key(b) : a < b;
  });
  std::vector<std::uint32_t> rep(pts.size());
  for (std::size_t k = 0; k < idx.size(); ++k)
    rep[idx[k]] = (k > 0 && key(idx[k]) == key(idx[k - 1])) ? rep[idx[k - 1]] : idx[k];
  return rep;
}

// The facets of a positively oriented (a, b, c, d), each oriented outwards
// (the opposite vertex on its negative side): opposite a, b, c, d in turn.
constexpr int kOutward[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};

// A facet occurrence: its vertices rotated to start at the smallest (the
// orientation kept), the tetrahedron and the corner opposite.
struct Occurrence {
  Facet f;
  std::uint32_t t;
  int k;
};
Facet rotated(Facet f) {
  const int m = f[0] < f[1] ? (f[0] < f[2] ? 0 : 2) : (f[1] < f[2] ? 1 : 2);
  return {f[m], f[(m + 1) % 3], f[(m + 2) % 3]};
}
// The same triangle whatever the orientation: smallest first, then the
// smaller of the other two.
Facet unoriented(Facet f) {
  f = rotated(f);
  if (f[1] > f[2]) std::swap(f[1], f[2]);
  return f;
}

}  // namespace

Tetrahedron canonical_tetrahedron(Tetrahedron t) {
  // Even permutations only: a cyclic shift of four is odd, so move the
  // smallest to the front by a double swap.
  const int m = static_cast<int>(std::min_element(t.begin(), t.end()) - t.begin());
  if (m != 0) {
    std::swap(t[0], t[m]);
    // one more transposition among the other three keeps the parity even
    const int a = m == 1 ? 2 : 1, b = m == 3 ? 2 : 3;
    std::swap(t[a], t[b]);
  }
  // Rotate the last three (an even permutation) to put their smallest second.
  for (int r = 0; r < 2 && !(t[1] <= t[2] && t[1] <= t[3]); ++r) {
    const std::uint32_t x = t[1];
    t[1] = t[2], t[2] = t[3], t[3] = x;
  }
  return t;
}

std::string check_delaunay_3d(const std::vector<Vec3>& pts, const std::vector<Tetrahedron>& tets) {
  const std::size_t n = pts.size();
  const std::vector<std::uint32_t> rep = representatives(pts);
  std::vector<std::uint32_t> distinct;
  for (std::uint32_t i = 0; i < n; ++i)
    if (rep[i] == i) distinct.push_back(i);
  // The dimension: four non-coplanar distinct points or not.
  bool solid = false;
  if (distinct.size() >= 4) {
    std::size_t b = 1, c = 0;
    while (b < distinct.size() && pts[distinct[b]] == pts[distinct[0]]) ++b;
    for (std::size_t k = b + 1; k < distinct.size() && !c; ++k)
      if (!CGAL::collinear(cg(pts[distinct[0]]), cg(pts[distinct[b]]), cg(pts[distinct[k]]))) c = k;
    for (std::size_t k = c + 1; c && k < distinct.size() && !solid; ++k)
      solid = CGAL::orientation(cg(pts[distinct[0]]), cg(pts[distinct[b]]), cg(pts[distinct[c]]),
                                cg(pts[distinct[k]])) != CGAL::COPLANAR;
  }
  if (!solid) {
    if (!tets.empty())
      return std::to_string(tets.size()) + " tetrahedra for " + std::to_string(distinct.size()) +
             " distinct points that span no volume";
    return "";
  }
  if (tets.empty()) return "no tetrahedron for points that span a volume";

  // Exact signs: in integers where the coordinates allow, else CGAL's.
  const IntegerSigns3 ints(pts);
  auto orientation = [&](std::uint32_t p, std::uint32_t q, std::uint32_t r, std::uint32_t s) {
    if (ints.ok()) return ints.orientation(p, q, r, s);
    return static_cast<int>(CGAL::orientation(cg(pts[p]), cg(pts[q]), cg(pts[r]), cg(pts[s])));
  };
  auto inside_sphere = [&](const Tetrahedron& t, std::uint32_t v) {
    if (ints.ok()) return ints.side_of_oriented_sphere(t[0], t[1], t[2], t[3], v) > 0;
    return CGAL::side_of_oriented_sphere(cg(pts[t[0]]), cg(pts[t[1]]), cg(pts[t[2]]), cg(pts[t[3]]), cg(pts[v])) ==
           CGAL::ON_POSITIVE_SIDE;
  };
  std::vector<Occurrence> occ;
  occ.reserve(4 * tets.size());
  std::vector<char> used(n, 0);
  for (std::uint32_t i = 0; i < tets.size(); ++i) {
    const Tetrahedron& t = tets[i];
    for (int k = 0; k < 4; ++k) {
      if (t[k] >= n || rep[t[k]] != t[k])
        return "tetrahedron " + std::to_string(i) + " names " + std::to_string(t[k]) + ", not a vertex";
      used[t[k]] = 1;
    }
    if (orientation(t[0], t[1], t[2], t[3]) <= 0) return tet_text(pts, i, t) + " is not positively oriented (or is flat)";
    for (int k = 0; k < 4; ++k)
      occ.push_back({rotated({t[kOutward[k][0]], t[kOutward[k][1]], t[kOutward[k][2]]}), i, k});
  }
  std::sort(occ.begin(), occ.end(), [](const Occurrence& x, const Occurrence& y) {
    const Facet a = unoriented(x.f), b = unoriented(y.f);
    return a != b ? a < b : x.t < y.t;
  });
  for (std::size_t j = 0; j < occ.size();) {
    std::size_t e = j + 1;
    while (e < occ.size() && unoriented(occ[e].f) == unoriented(occ[j].f)) ++e;
    const Occurrence& x = occ[j];
    const Tetrahedron& tx = tets[x.t];
    if (e - j > 2)
      return "facet (" + std::to_string(x.f[0]) + ", " + std::to_string(x.f[1]) + ", " + std::to_string(x.f[2]) +
             ") lies in " + std::to_string(e - j) + " tetrahedra";
    if (e - j == 2) {
      const Occurrence& y = occ[j + 1];
      if (x.f == y.f)
        return "tetrahedra " + std::to_string(x.t) + " and " + std::to_string(y.t) +
               " lie on the same side of their common facet (they overlap)";
      // Locally Delaunay, both ways round (exact; on the sphere allowed).
      const Tetrahedron& ty = tets[y.t];
      const std::uint32_t vy = ty[y.k], vx = tx[x.k];
      if (inside_sphere(tx, vy))
        return "not locally Delaunay: " + pt(pts, vy) + " lies strictly inside the circumsphere of " +
               tet_text(pts, x.t, tx);
      if (inside_sphere(ty, vx))
        return "not locally Delaunay: " + pt(pts, vx) + " lies strictly inside the circumsphere of " +
               tet_text(pts, y.t, ty);
    } else {
      // A boundary facet: no distinct point strictly outside its plane.
      for (std::uint32_t p : distinct)
        if (orientation(x.f[0], x.f[1], x.f[2], p) > 0)
          return "boundary facet (" + std::to_string(x.f[0]) + ", " + std::to_string(x.f[1]) + ", " +
                 std::to_string(x.f[2]) + ") of tetrahedron " + std::to_string(x.t) + " is not on the hull: " +
                 pt(pts, p) + " lies outside it";
    }
    j = e;
  }
  for (std::uint32_t p : distinct)
    if (!used[p]) return "point " + pt(pts, p) + " is no vertex";
  return "";
}

std::vector<Tetrahedron> cgal_delaunay_3d(const std::vector<Vec3>& pts) {
  using Vb = CGAL::Triangulation_vertex_base_with_info_3<std::uint32_t, K>;
  using Tds = CGAL::Triangulation_data_structure_3<Vb, CGAL::Delaunay_triangulation_cell_base_3<K>>;
  using DT = CGAL::Delaunay_triangulation_3<K, Tds>;
  const std::vector<std::uint32_t> rep = representatives(pts);
  std::vector<std::pair<P3, std::uint32_t>> in;
  in.reserve(pts.size());
  for (std::uint32_t i = 0; i < pts.size(); ++i)
    if (rep[i] == i) in.emplace_back(cg(pts[i]), i);
  DT dt(in.begin(), in.end());
  std::vector<Tetrahedron> out;
  if (dt.dimension() < 3) return out;
  for (auto c = dt.finite_cells_begin(); c != dt.finite_cells_end(); ++c)
    out.push_back(canonical_tetrahedron(
        {c->vertex(0)->info(), c->vertex(1)->info(), c->vertex(2)->info(), c->vertex(3)->info()}));
  std::sort(out.begin(), out.end());
  return out;
}

namespace {
// Six times the signed volume of (a, b, c, d), exactly.
CGAL::Mpzf six_volume(Vec3 a, Vec3 b, Vec3 c, Vec3 d) {
  const CGAL::Mpzf ax(a.x), ay(a.y), az(a.z);
  const CGAL::Mpzf ux = CGAL::Mpzf(b.x) - ax, uy = CGAL::Mpzf(b.y) - ay, uz = CGAL::Mpzf(b.z) - az;
  const CGAL::Mpzf vx = CGAL::Mpzf(c.x) - ax, vy = CGAL::Mpzf(c.y) - ay, vz = CGAL::Mpzf(c.z) - az;
  const CGAL::Mpzf wx = CGAL::Mpzf(d.x) - ax, wy = CGAL::Mpzf(d.y) - ay, wz = CGAL::Mpzf(d.z) - az;
  return ux * (vy * wz - vz * wy) - uy * (vx * wz - vz * wx) + uz * (vx * wy - vy * wx);
}

// The dimension of the distinct points' affine hull, exactly.
ConvexHull3::Dimension dimension_of(const std::vector<Vec3>& pts, const std::vector<std::uint32_t>& distinct) {
  using D = ConvexHull3::Dimension;
  if (distinct.empty()) return D::empty;
  if (distinct.size() == 1) return D::point;
  const P3 a = cg(pts[distinct[0]]), b = cg(pts[distinct[1]]);
  std::size_t c = 0;
  for (std::size_t k = 2; k < distinct.size() && !c; ++k)
    if (!CGAL::collinear(a, b, cg(pts[distinct[k]]))) c = k;
  if (!c) return D::line;
  for (std::size_t k = c + 1; k < distinct.size(); ++k)
    if (CGAL::orientation(a, b, cg(pts[distinct[c]]), cg(pts[distinct[k]])) != CGAL::COPLANAR) return D::solid;
  return D::plane;
}
}  // namespace

std::string check_convex_hull_3d(const std::vector<Vec3>& pts, const ConvexHull3& hull) {
  using D = ConvexHull3::Dimension;
  for (const Vec3& v : pts)
    if (!(std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z)))
      return hull.dimension == D::invalid && hull.facets.empty() ? "" : "non-finite input not answered as invalid";
  const std::size_t n = pts.size();
  const std::vector<std::uint32_t> rep = representatives(pts);
  std::vector<std::uint32_t> distinct;
  for (std::uint32_t i = 0; i < n; ++i)
    if (rep[i] == i) distinct.push_back(i);
  const D dim = dimension_of(pts, distinct);
  if (hull.dimension != dim) return std::string("dimension ") + to_string(hull.dimension) + ", the input is " + to_string(dim);
  if (dim != D::solid) return hull.facets.empty() ? "" : std::to_string(hull.facets.size()) + " facets for a flat hull";
  if (hull.facets.size() < 4) return std::to_string(hull.facets.size()) + " facets cannot close a solid";
  // Facets: representative, distinct, not collinear; directed edges.
  std::vector<std::array<std::uint32_t, 3>> edges;  // (from, to, facet)
  for (std::uint32_t i = 0; i < hull.facets.size(); ++i) {
    const Facet& f = hull.facets[i];
    for (int k = 0; k < 3; ++k)
      if (f[k] >= n || rep[f[k]] != f[k])
        return "facet " + std::to_string(i) + " names " + std::to_string(f[k]) + ", not a distinct point's index";
    if (CGAL::collinear(cg(pts[f[0]]), cg(pts[f[1]]), cg(pts[f[2]])))
      return "facet " + std::to_string(i) + " (" + pt(pts, f[0]) + ", " + pt(pts, f[1]) + ", " + pt(pts, f[2]) +
             ") is degenerate";
    for (int k = 0; k < 3; ++k) edges.push_back({f[k], f[(k + 1) % 3], i});
  }
  std::sort(edges.begin(), edges.end());
  for (std::size_t j = 0; j < edges.size(); ++j) {
    if (j + 1 < edges.size() && edges[j][0] == edges[j + 1][0] && edges[j][1] == edges[j + 1][1])
      return "edge (" + std::to_string(edges[j][0]) + ", " + std::to_string(edges[j][1]) + ") is in facets " +
             std::to_string(edges[j][2]) + " and " + std::to_string(edges[j + 1][2]) + " in the same direction";
    const std::array<std::uint32_t, 3> rev{edges[j][1], edges[j][0], 0};
    const auto it = std::lower_bound(edges.begin(), edges.end(), rev);
    if (it == edges.end() || (*it)[0] != rev[0] || (*it)[1] != rev[1])
      return "edge (" + std::to_string(edges[j][0]) + ", " + std::to_string(edges[j][1]) + ") of facet " +
             std::to_string(edges[j][2]) + " has no facet on its other side";
  }
  // Every facet on the hull.
  const IntegerSigns3 ints(pts);
  for (std::uint32_t i = 0; i < hull.facets.size(); ++i) {
    const Facet& f = hull.facets[i];
    const P3 a = cg(pts[f[0]]), b = cg(pts[f[1]]), c = cg(pts[f[2]]);
    for (std::uint32_t q : distinct)
      if (ints.ok() ? ints.orientation(f[0], f[1], f[2], q) > 0 : CGAL::orientation(a, b, c, cg(pts[q])) == CGAL::POSITIVE)
        return "facet " + std::to_string(i) + " is not on the hull: " + pt(pts, q) + " lies outside its plane";
  }
  // Enclosed volume (from the first point) against the hull's.
  CGAL::Mpzf enclosed = 0, volume = 0;
  const Vec3 o = pts[distinct[0]];
  for (const Facet& f : hull.facets) enclosed += six_volume(o, pts[f[0]], pts[f[1]], pts[f[2]]);
  for (const Tetrahedron& t : cgal_delaunay_3d(pts)) volume += six_volume(pts[t[0]], pts[t[1]], pts[t[2]], pts[t[3]]);
  if (enclosed != volume) return "the facets enclose another volume than the hull's (a part missing or wrapped twice)";
  return "";
}

}  // namespace geomcheck::oracle
