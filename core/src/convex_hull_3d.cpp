#include "geomcheck/convex_hull_3d.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <tuple>
#include <utility>

#include "geomcheck/predicates3d.hpp"

namespace geomcheck {

namespace {

constexpr std::uint32_t kNone = 0xffffffffu;

struct Facet {
  std::array<std::uint32_t, 3> v;  // outward
  std::array<std::uint32_t, 3> n;  // the neighbour across edge (v[k], v[k+1])
  std::vector<std::uint32_t> conflicts;  // points strictly beyond its plane, assigned here
  std::uint32_t far = kNone;             // the conflict farthest from the plane (by the filter's value)
  double far_value = 0;
  bool alive = true;
};

class Hull {
 public:
  /// `unit`: the points scaled by one power of two, the largest coordinate
  /// into [1, 2) (for the farthest-point heuristic only: the same numbers
  /// for every power-of-two scaling of the input, so the same order).
  Hull(const std::vector<Vec3>& p, const std::vector<Vec3>& unit)
      : p_(p), unit_(unit), by_start_(p.size(), kNone) {}

  /// q strictly beyond the plane of f (on its outer side), exactly.
  bool sees(std::uint32_t f, std::uint32_t q) const {
    const auto& v = facets_[f].v;
    return orient3d(p_[v[0]], p_[v[1]], p_[v[2]], p_[q]) < 0;
  }
  /// How far beyond f's plane q lies, roughly (a heuristic).
  double how_far(std::uint32_t f, std::uint32_t q) const {
    const auto& v = facets_[f].v;
    const double x = -detail::orient3d_filter(unit_[v[0]], unit_[v[1]], unit_[v[2]], unit_[q]).value;
    return x == x ? x : 0;
  }

  /// The tetrahedron a, b, c, d (not coplanar) as four outward facets.
  void start(std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d) {
    if (orient3d(p_[a], p_[b], p_[c], p_[d]) > 0) std::swap(b, c);  // d now beyond the normal of (a, b, c)
    // Outward facets of (a, b, c, d) with d on the positive side of (a, b, c).
    add({b, c, d});
    add({a, d, c});
    add({a, b, d});
    add({a, c, b});
    // Each edge's neighbour: the facet holding it reversed.
    for (std::uint32_t f = 0; f < 4; ++f)
      for (int k = 0; k < 3; ++k) {
        const std::uint32_t x = facets_[f].v[k], y = facets_[f].v[(k + 1) % 3];
        for (std::uint32_t g = 0; g < 4; ++g)
          for (int j = 0; j < 3; ++j)
            if (facets_[g].v[j] == y && facets_[g].v[(j + 1) % 3] == x) facets_[f].n[k] = g;
      }
  }

  /// Assigns q to a facet it sees among `candidates` (none: q is inside).
  void assign(std::uint32_t q, const std::vector<std::uint32_t>& candidates) {
    for (std::uint32_t f : candidates)
      if (sees(f, q)) {
        Facet& g = facets_[f];
        g.conflicts.push_back(q);
        const double far = how_far(f, q);
        if (g.far == kNone || far > g.far_value) g.far = q, g.far_value = far;
        return;
      }
  }

  /// Inserts q, which sees facet f0.
  void insert(std::uint32_t q, std::uint32_t f0) {
    // The facets q sees: connected, from f0.
    visible_.clear();
    visible_.push_back(f0);
    facets_[f0].alive = false;
    for (std::size_t i = 0; i < visible_.size(); ++i)
      for (std::uint32_t g : facets_[visible_[i]].n)
        if (facets_[g].alive && sees(g, q)) {
          facets_[g].alive = false;
          visible_.push_back(g);
        }
    // The horizon: edges of visible facets whose neighbour stays; a new
    // facet (x, y, q) on each, linked to the one that stays.
    created_.clear();
    for (std::uint32_t f : visible_)
      for (int k = 0; k < 3; ++k) {
        const std::uint32_t g = facets_[f].n[k];
        if (!facets_[g].alive) continue;
        const std::uint32_t x = facets_[f].v[k], y = facets_[f].v[(k + 1) % 3];
        const std::uint32_t h = add({x, y, q});
        facets_[h].n[0] = g;
        for (int j = 0; j < 3; ++j)
          if (facets_[g].v[j] == y && facets_[g].v[(j + 1) % 3] == x) facets_[g].n[j] = h;
        created_.push_back(h);
        by_start_[x] = h;
      }
    // The horizon is one loop: (x, y, q)'s edge (y, q) meets the new facet
    // starting at y, its edge (q, x) the one ending at x.
    for (std::uint32_t h : created_) {
      const std::uint32_t y = facets_[h].v[1];
      const std::uint32_t next = by_start_[y];
      facets_[h].n[1] = next;
      facets_[next].n[2] = h;
    }
    // The conflicts of the removed facets go to the new ones (or are inside).
    for (std::uint32_t f : visible_) {
      std::vector<std::uint32_t> moved;
      moved.swap(facets_[f].conflicts);
      for (std::uint32_t r : moved)
        if (r != q) assign(r, created_);
    }
  }

  std::vector<Facet>& facets() { return facets_; }

 private:
  std::uint32_t add(std::array<std::uint32_t, 3> v) {
    Facet f;
    f.v = v;
    f.n = {kNone, kNone, kNone};
    facets_.push_back(std::move(f));
    return static_cast<std::uint32_t>(facets_.size() - 1);
  }

  const std::vector<Vec3>& p_;
  const std::vector<Vec3>& unit_;
  std::vector<Facet> facets_;
  std::vector<std::uint32_t> visible_, created_;
  std::vector<std::uint32_t> by_start_;  // the new facet starting at each horizon vertex (by point index)
};

}  // namespace

const char* to_string(ConvexHull3::Dimension d) {
  switch (d) {
    case ConvexHull3::Dimension::invalid: return "invalid";
    case ConvexHull3::Dimension::empty: return "empty";
    case ConvexHull3::Dimension::point: return "point";
    case ConvexHull3::Dimension::line: return "line";
    case ConvexHull3::Dimension::plane: return "plane";
    case ConvexHull3::Dimension::solid: return "solid";
  }
  return "?";
}

ConvexHull3 convex_hull_3d(const std::vector<Vec3>& p) {
  using D = ConvexHull3::Dimension;
  ConvexHull3 out;
  const auto n = static_cast<std::uint32_t>(p.size());
  for (const Vec3& v : p)
    if (!(std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z))) {
      out.dimension = D::invalid;
      return out;
    }
  if (n == 0) return out;
  // The distinct points, each at the smallest index of its coordinates.
  std::vector<std::uint32_t> idx(n);
  std::iota(idx.begin(), idx.end(), 0u);
  auto key = [&](std::uint32_t a) { return std::make_tuple(p[a].x, p[a].y, p[a].z); };
  std::sort(idx.begin(), idx.end(), [&](std::uint32_t a, std::uint32_t b) { return key(a) != key(b) ? key(a) < key(b) : a < b; });
  std::vector<std::uint32_t> distinct;
  for (std::size_t k = 0; k < idx.size(); ++k)
    if (k == 0 || key(idx[k]) != key(idx[k - 1])) distinct.push_back(idx[k]);
  std::sort(distinct.begin(), distinct.end());
  // The first tetrahedron: the first independent points in index order.
  const std::uint32_t a = distinct[0];
  out.dimension = D::point;
  if (distinct.size() < 2) return out;
  const std::uint32_t b = distinct[1];
  out.dimension = D::line;
  std::size_t ic = 2;
  auto collinear = [&](std::uint32_t c) {
    // a, b, c collinear iff every coordinate projection is (exact orient2d).
    return orient2d({p[a].x, p[a].y}, {p[b].x, p[b].y}, {p[c].x, p[c].y}) == 0 &&
           orient2d({p[a].y, p[a].z}, {p[b].y, p[b].z}, {p[c].y, p[c].z}) == 0 &&
           orient2d({p[a].z, p[a].x}, {p[b].z, p[b].x}, {p[c].z, p[c].x}) == 0;
  };
  while (ic < distinct.size() && collinear(distinct[ic])) ++ic;
  if (ic == distinct.size()) return out;
  const std::uint32_t c = distinct[ic];
  out.dimension = D::plane;
  std::size_t id = ic + 1;
  while (id < distinct.size() && orient3d(p[a], p[b], p[c], p[distinct[id]]) == 0) ++id;
  if (id == distinct.size()) return out;
  const std::uint32_t d = distinct[id];
  out.dimension = D::solid;

  double m = 0;
  for (const Vec3& v : p) m = std::max(m, max_abs(v));
  std::vector<Vec3> unit(p);
  const int e = std::ilogb(m);  // m > 0: four independent points
  bool exact = true;  // no coordinate scaled into the subnormals: every sign is the input's
  for (Vec3& v : unit) {
    for (double c : {v.x, v.y, v.z}) exact = exact && (c == 0 || std::ilogb(c) - e >= -1022);
    v = {std::ldexp(v.x, -e), std::ldexp(v.y, -e), std::ldexp(v.z, -e)};
  }
  // Where the scaling is exact the decisions use the scaled points too: a
  // set far from 1 in scale then never leaves orient3d's inline filter.
  Hull h(exact ? unit : p, unit);
  h.start(a, b, c, d);
  // The rest, each assigned to a first facet it sees.
  std::vector<std::uint32_t> rest;
  for (std::uint32_t q : distinct)
    if (q != a && q != b && q != c && q != d) rest.push_back(q);
  const std::vector<std::uint32_t> first{0, 1, 2, 3};
  for (std::uint32_t q : rest) h.assign(q, first);
  // Each facet with conflicts, in creation order: its farthest point goes
  // in (as Quickhull chooses: the points it swallows leave early).
  for (std::uint32_t f = 0; f < h.facets().size(); ++f) {
    if (h.facets()[f].alive && !h.facets()[f].conflicts.empty()) h.insert(h.facets()[f].far, f);
  }
  for (const auto& f : h.facets())
    if (f.alive) out.facets.push_back(f.v);
  return out;
}

}  // namespace geomcheck
