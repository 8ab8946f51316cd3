// The CGAL translation unit of the Delaunay oracles (see the header).
#include "geomcheck/oracles/delaunay_2d.hpp"

// Under clang (the fuzz builds), the oracle and the CGAL code it
// instantiates carry no coverage instrumentation: libFuzzer is steered by
// the code under test, and every run of the checker would otherwise hand it
// thousands of CGAL features to account for (most of a run's time). The
// address and undefined-behaviour sanitizers stay on. (Standard-library
// templates declared before this point keep theirs.)
#if defined(__clang__)
#pragma clang diagnostic push
#pragma clang diagnostic ignored "-Wignored-attributes"
#pragma clang attribute push(__attribute__((no_sanitize("coverage"))), apply_to = function)
#endif

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Mpzf.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#include <CGAL/convex_hull_2.h>

#include <algorithm>
#include <cstdio>
#include <numeric>
#include <utility>

namespace geomcheck::oracle {

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using P2 = K::Point_2;
using Tri = std::array<std::uint32_t, 3>;
constexpr std::uint32_t kNone = DelaunayTriangulation::kNone;

P2 cg(Vec2 p) { return P2(p.x, p.y); }

std::string pt(const std::vector<Vec2>& pts, std::uint32_t i) {
  char buf[128];
  std::snprintf(buf, sizeof buf, "%u (%a, %a)", i, pts[i].x, pts[i].y);
  return buf;
}

Tri canonical(Tri t) {
  const int k = t[0] < t[1] ? (t[0] < t[2] ? 0 : 2) : (t[1] < t[2] ? 1 : 2);
  return {t[k], t[(k + 1) % 3], t[(k + 2) % 3]};
}

// Smallest index of each distinct point, computed by sorting (independent
// of production's hashing and Hilbert keys).
std::vector<std::uint32_t> representatives(const std::vector<Vec2>& pts) {
  std::vector<std::uint32_t> idx(pts.size());
  std::iota(idx.begin(), idx.end(), 0u);
  std::sort(idx.begin(), idx.end(), [&](std::uint32_t a, std::uint32_t b) {
    if (pts[a].x != pts[b].x) return pts[a].x < pts[b].x;
    if (pts[a].y != pts[b].y) return pts[a].y < pts[b].y;
    return a < b;
  });
  std::vector<std::uint32_t> rep(pts.size());
  for (std::size_t k = 0; k < idx.size(); ++k)
    rep[idx[k]] = (k > 0 && pts[idx[k]] == pts[idx[k - 1]]) ? rep[idx[k - 1]] : idx[k];
  return rep;
}

// Exact (Mpzf: a big-integer mantissa and a binary exponent, so sums and
// products of doubles are exact without rationals).
CGAL::Mpzf twice_area(Vec2 a, Vec2 b, Vec2 c) {
  const CGAL::Mpzf ax(a.x), ay(a.y), bx(b.x), by(b.y), cx(c.x), cy(c.y);
  return (bx - ax) * (cy - ay) - (by - ay) * (cx - ax);
}

// A directed edge a->b of triangle t, opposite its corner k.
struct Edge {
  std::uint32_t a, b, t;
  int k;
};
bool edge_less(const Edge& x, const Edge& y) { return x.a != y.a ? x.a < y.a : x.b < y.b; }
const Edge* find_edge(const std::vector<Edge>& edges, std::uint32_t a, std::uint32_t b) {
  const Edge key{a, b, 0, 0};
  const auto it = std::lower_bound(edges.begin(), edges.end(), key, edge_less);
  return it != edges.end() && it->a == a && it->b == b ? &*it : nullptr;
}

}  // namespace

std::vector<Tri> canonical_triangles(const DelaunayTriangulation& t) {
  std::vector<Tri> out;
  out.reserve(t.triangles.size());
  for (const Tri& x : t.triangles) out.push_back(canonical(x));
  std::sort(out.begin(), out.end());
  return out;
}

std::string check_delaunay(const std::vector<Vec2>& pts, const DelaunayTriangulation& t) {
  const std::size_t n = pts.size();
  // Vertices: the de-duplicated input.
  if (t.vertex_of.size() != n)
    return "vertex_of has " + std::to_string(t.vertex_of.size()) + " entries for " + std::to_string(n) + " points";
  const std::vector<std::uint32_t> rep = representatives(pts);
  std::vector<std::uint32_t> distinct;
  for (std::uint32_t i = 0; i < n; ++i) {
    if (t.vertex_of[i] != rep[i])
      return "vertex_of[" + std::to_string(i) + "] = " + std::to_string(t.vertex_of[i]) +
             ", the smallest index of its coordinates is " + std::to_string(rep[i]);
    if (rep[i] == i) distinct.push_back(i);
  }
  const std::size_t m = distinct.size();
  if (t.vertex_count != m)
    return "vertex_count " + std::to_string(t.vertex_count) + ", distinct points " + std::to_string(m);
  DelaunayDimension dim = m == 0 ? DelaunayDimension::empty : (m == 1 ? DelaunayDimension::point : DelaunayDimension::line);
  for (std::size_t k = 2; k < m && dim == DelaunayDimension::line; ++k)
    if (CGAL::orientation(cg(pts[distinct[0]]), cg(pts[distinct[1]]), cg(pts[distinct[k]])) != CGAL::COLLINEAR)
      dim = DelaunayDimension::plane;
  if (t.dimension != dim)
    return std::string("dimension ") + to_string(t.dimension) + ", the input is " + to_string(dim);
  const std::size_t nt = t.triangles.size();
  if (dim != DelaunayDimension::plane) {
    if (nt != 0) return std::to_string(nt) + " triangles for " + to_string(dim) + " input";
    return "";
  }
  if (t.neighbors.size() != nt) return "neighbors has " + std::to_string(t.neighbors.size()) + " entries";

  // Triangles: representative vertices, counter-clockwise, non-degenerate.
  std::vector<Edge> edge;  // directed edges, sorted
  edge.reserve(3 * nt);
  std::vector<char> used(n, 0);
  for (std::uint32_t i = 0; i < nt; ++i) {
    const Tri& x = t.triangles[i];
    for (int k = 0; k < 3; ++k) {
      if (x[k] >= n || rep[x[k]] != x[k])
        return "triangle " + std::to_string(i) + " names " + std::to_string(x[k]) + ", not a vertex";
      used[x[k]] = 1;
    }
    if (CGAL::orientation(cg(pts[x[0]]), cg(pts[x[1]]), cg(pts[x[2]])) != CGAL::LEFT_TURN)
      return "triangle " + std::to_string(i) + " (" + pt(pts, x[0]) + ", " + pt(pts, x[1]) + ", " + pt(pts, x[2]) +
             ") is not counter-clockwise and non-degenerate";
    for (int k = 0; k < 3; ++k) edge.push_back({x[(k + 1) % 3], x[(k + 2) % 3], i, k});
  }
  std::sort(edge.begin(), edge.end(), [](const Edge& x, const Edge& y) {
    return edge_less(x, y) || (!edge_less(y, x) && x.t < y.t);
  });
  for (std::size_t j = 1; j < edge.size(); ++j)
    if (edge[j].a == edge[j - 1].a && edge[j].b == edge[j - 1].b)
      return "directed edge " + std::to_string(edge[j].a) + "->" + std::to_string(edge[j].b) + " is in two triangles";
  for (std::uint32_t v : distinct)
    if (!used[v]) return "point " + pt(pts, v) + " is not a vertex of any triangle";

  // Adjacency and local Delaunayhood; boundary edges.
  std::vector<std::uint32_t> next_on_boundary(n, kNone);  // per vertex: the boundary edge leaving it
  std::size_t boundary_edges = 0;
  for (std::uint32_t i = 0; i < nt; ++i) {
    const Tri& x = t.triangles[i];
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t a = x[(k + 1) % 3], b = x[(k + 2) % 3], nb = t.neighbors[i][k];
      const Edge* twin = find_edge(edge, b, a);
      if (nb == kNone) {
        if (twin)
          return "triangle " + std::to_string(i) + " has no neighbour across " + std::to_string(a) + "-" +
                 std::to_string(b) + " but triangle " + std::to_string(twin->t) + " is there";
        if (next_on_boundary[a] != kNone) return "vertex " + std::to_string(a) + " starts two boundary edges";
        next_on_boundary[a] = b;
        ++boundary_edges;
        continue;
      }
      if (!twin || twin->t != nb)
        return "triangle " + std::to_string(i) + "'s neighbour " + std::to_string(nb) + " across " + std::to_string(a) +
               "-" + std::to_string(b) + " does not share that edge";
      const int j = twin->k;
      if (t.neighbors[nb][j] != i)
        return "triangles " + std::to_string(i) + " and " + std::to_string(nb) + " are not mutual neighbours";
      // Once per edge: for the triangles (a, b, c) and (b, a, d) on its two
      // sides, incircle(a, b, c, d) = incircle(b, a, d, c) exactly (the same
      // determinant, its rows permuted evenly), so the test from the other
      // side would give the same answer.
      if (nb < i) continue;
      const std::uint32_t d = t.triangles[nb][j];
      if (CGAL::side_of_oriented_circle(cg(pts[x[0]]), cg(pts[x[1]]), cg(pts[x[2]]), cg(pts[d])) ==
          CGAL::ON_POSITIVE_SIDE)
        return "edge " + std::to_string(a) + "-" + std::to_string(b) + " is not locally Delaunay: " + pt(pts, d) +
               " is strictly inside the circumcircle of triangle " + std::to_string(i);
    }
  }

  // The boundary is one cycle, convex, with the hull's corners.
  if (boundary_edges == 0) return "no boundary edges";
  const std::uint32_t start = static_cast<std::uint32_t>(
      std::find_if(next_on_boundary.begin(), next_on_boundary.end(), [](std::uint32_t b) { return b != kNone; }) -
      next_on_boundary.begin());
  std::vector<std::uint32_t> cycle;
  for (std::uint32_t v = start;;) {
    cycle.push_back(v);
    if (next_on_boundary[v] == kNone) return "the boundary is not closed at vertex " + std::to_string(v);
    v = next_on_boundary[v];
    if (v == start) break;
    if (cycle.size() > boundary_edges) return "the boundary is not a simple cycle";
  }
  if (cycle.size() != boundary_edges)
    return "the boundary is " + std::to_string(boundary_edges - cycle.size() + 1) + " cycles or more";
  const std::size_t h = cycle.size();
  std::vector<std::uint32_t> corners;
  for (std::size_t k = 0; k < h; ++k) {
    const P2 p = cg(pts[cycle[(k + h - 1) % h]]), v = cg(pts[cycle[k]]), q = cg(pts[cycle[(k + 1) % h]]);
    const CGAL::Orientation o = CGAL::orientation(p, v, q);
    if (o == CGAL::RIGHT_TURN) return "the boundary turns clockwise at " + pt(pts, cycle[k]);
    if (o == CGAL::LEFT_TURN) corners.push_back(cycle[k]);
    else if (!CGAL::collinear_are_strictly_ordered_along_line(p, v, q))
      return "the boundary folds back at " + pt(pts, cycle[k]);
  }
  std::vector<P2> in, hull;
  for (std::uint32_t v : distinct) in.push_back(cg(pts[v]));
  CGAL::convex_hull_2(in.begin(), in.end(), std::back_inserter(hull));
  if (hull.size() != corners.size())
    return "the boundary has " + std::to_string(corners.size()) + " corners, the convex hull " +
           std::to_string(hull.size());
  const auto first = std::find(hull.begin(), hull.end(), cg(pts[corners[0]]));
  if (first == hull.end()) return "boundary corner " + pt(pts, corners[0]) + " is not a hull vertex";
  std::rotate(hull.begin(), first, hull.end());
  for (std::size_t k = 0; k < hull.size(); ++k)
    if (hull[k] != cg(pts[corners[k]])) return "boundary corner " + pt(pts, corners[k]) + " is not the hull's";

  // Euler count and area.
  if (nt != 2 * m - h - 2)
    return std::to_string(nt) + " triangles, 2n - h - 2 = " + std::to_string(2 * m - h - 2) + " (n = " +
           std::to_string(m) + ", h = " + std::to_string(h) + ")";
  if (t.hull_edges != h) return "hull_edges " + std::to_string(t.hull_edges) + ", the boundary has " + std::to_string(h);
  CGAL::Mpzf area = 0, hull_area = 0;
  for (const Tri& x : t.triangles) area += twice_area(pts[x[0]], pts[x[1]], pts[x[2]]);
  for (std::size_t k = 1; k + 1 < corners.size(); ++k)
    hull_area += twice_area(pts[corners[0]], pts[corners[k]], pts[corners[k + 1]]);
  if (area != hull_area) return "the triangles' areas do not add up to the hull's (overlap or gap)";
  return "";
}

namespace {
using Vb = CGAL::Triangulation_vertex_base_with_info_2<std::uint32_t, K>;
using Tds = CGAL::Triangulation_data_structure_2<Vb>;
using DT = CGAL::Delaunay_triangulation_2<K, Tds>;

// CGAL's triangulation of the distinct points, each vertex carrying its
// smallest input index.
void build_cgal(const std::vector<Vec2>& pts, DT& dt) {
  const std::vector<std::uint32_t> rep = representatives(pts);
  std::vector<std::pair<P2, std::uint32_t>> in;
  for (std::uint32_t i = 0; i < pts.size(); ++i)
    if (rep[i] == i) in.emplace_back(cg(pts[i]), i);
  dt.insert(in.begin(), in.end());
}
}  // namespace

std::vector<Tri> cgal_delaunay(const std::vector<Vec2>& pts) {
  DT dt;
  build_cgal(pts, dt);
  std::vector<Tri> out;
  if (dt.dimension() < 2) return out;
  for (auto f = dt.finite_faces_begin(); f != dt.finite_faces_end(); ++f)
    out.push_back(canonical({f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info()}));
  std::sort(out.begin(), out.end());
  return out;
}

std::string compare_with_cgal(const std::vector<Vec2>& pts, const DelaunayTriangulation& t) {
  DT dt;
  build_cgal(pts, dt);
  std::vector<Tri> theirs;  // canonical, sorted, distinct
  if (dt.dimension() == 2)
    for (auto f = dt.finite_faces_begin(); f != dt.finite_faces_end(); ++f)
      theirs.push_back(canonical({f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info()}));
  std::vector<Tri> ours;
  for (const Tri& x : t.triangles) ours.push_back(canonical(x));
  for (std::vector<Tri>* v : {&theirs, &ours}) {
    std::sort(v->begin(), v->end());
    v->erase(std::unique(v->begin(), v->end()), v->end());
  }
  const auto contains = [](const std::vector<Tri>& v, const Tri& x) { return std::binary_search(v.begin(), v.end(), x); };
  const auto cocircular = [&](Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
    return CGAL::side_of_oriented_circle(cg(a), cg(b), cg(c), cg(d)) == CGAL::ON_ORIENTED_BOUNDARY;
  };
  for (std::uint32_t i = 0; i < t.triangles.size(); ++i) {
    const Tri& x = t.triangles[i];
    if (contains(theirs, canonical(x))) continue;
    bool explained = false;
    for (int k = 0; k < 3 && !explained; ++k) {
      const std::uint32_t nb = t.neighbors[i][k];
      if (nb == kNone || nb >= t.triangles.size()) continue;
      for (std::uint32_t d : t.triangles[nb])
        if (d != x[0] && d != x[1] && d != x[2] && cocircular(pts[x[0]], pts[x[1]], pts[x[2]], pts[d])) explained = true;
    }
    if (!explained)
      return "triangle (" + pt(pts, x[0]) + ", " + pt(pts, x[1]) + ", " + pt(pts, x[2]) +
             ") is not CGAL's and no neighbouring point is on its circumcircle";
  }
  if (dt.dimension() == 2)
    for (auto f = dt.finite_faces_begin(); f != dt.finite_faces_end(); ++f) {
      const Tri x{f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info()};
      if (contains(ours, canonical(x))) continue;
      bool explained = false;
      for (int k = 0; k < 3 && !explained; ++k) {
        const auto g = f->neighbor(k);
        if (dt.is_infinite(g)) continue;
        const auto d = g->vertex(g->index(f));
        explained = CGAL::side_of_oriented_circle(f->vertex(0)->point(), f->vertex(1)->point(), f->vertex(2)->point(),
                                                  d->point()) == CGAL::ON_ORIENTED_BOUNDARY;
      }
      if (!explained)
        return "CGAL's triangle (" + pt(pts, x[0]) + ", " + pt(pts, x[1]) + ", " + pt(pts, x[2]) +
               ") is missing and no neighbouring point is on its circumcircle";
    }
  if (ours.size() != theirs.size())
    return std::to_string(ours.size()) + " triangles, CGAL " + std::to_string(theirs.size());
  return "";
}

}  // namespace geomcheck::oracle

#if defined(__clang__)
#pragma clang attribute pop
#pragma clang diagnostic pop
#endif
