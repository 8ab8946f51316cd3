// The user's own 2D Delaunay triangulator: a sweep over the points sorted by
// (x, y) builds some triangulation of their convex hull, then Lawson flips
// make every edge locally Delaunay. Orientation tests are geomcheck's exact
// orient2d. It has one deliberate flaw: the in-circle test is the plain
// determinant in doubles, whose sign is wrong for nearly cocircular points,
// so some edges stay non-Delaunay (and the flips may cycle, hence a cap):
// built with -DMY_DELAUNAY_FIXED it is geomcheck's exact incircle instead.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <utility>
#include <vector>

#include <geomcheck/predicates2d.hpp>

namespace mine {

struct P { double x, y; };

inline geomcheck::Vec2 vec(P p) { return {p.x, p.y}; }
inline int orient(P a, P b, P c) { return geomcheck::orient2d(vec(a), vec(b), vec(c)); }

// Is d strictly inside the circumcircle of the counter-clockwise a, b, c?
inline bool in_circle(P a, P b, P c, P d) {
#ifdef MY_DELAUNAY_FIXED
  return geomcheck::incircle(vec(a), vec(b), vec(c), vec(d)) > 0;
#else
  // The flaw: the textbook determinant in doubles, rounded, with no error bound.
  const double adx = a.x - d.x, ady = a.y - d.y, bdx = b.x - d.x, bdy = b.y - d.y;
  const double cdx = c.x - d.x, cdy = c.y - d.y;
  const double det = (adx * adx + ady * ady) * (bdx * cdy - cdx * bdy) +
                     (bdx * bdx + bdy * bdy) * (cdx * ady - adx * cdy) +
                     (cdx * cdx + cdy * cdy) * (adx * bdy - bdx * ady);
  return det > 0;
#endif
}

// The Delaunay triangles of pts as counter-clockwise triples of indices into
// pts. Equal points are one vertex, named by their smallest index; points
// with a NaN or infinite coordinate are skipped. No triangles when fewer than
// three distinct points or when they are all collinear.
inline std::vector<std::array<int, 3>> triangulate(const std::vector<P>& pts) {
  // Distinct points sorted by (x, y); ties by index, so each group of equal
  // points starts with its smallest index. Below, vertices are positions in v.
  std::vector<int> order;
  for (int i = 0; i < int(pts.size()); ++i)
    if (std::isfinite(pts[i].x) && std::isfinite(pts[i].y)) order.push_back(i);
  std::sort(order.begin(), order.end(), [&](int i, int j) {
    const P a = pts[i], b = pts[j];
    return a.x != b.x ? a.x < b.x : a.y != b.y ? a.y < b.y : i < j;
  });
  std::vector<P> v;
  std::vector<int> id;  // v[k] is pts[id[k]]
  for (int i : order)
    if (v.empty() || v.back().x != pts[i].x || v.back().y != pts[i].y) v.push_back(pts[i]), id.push_back(i);
  const int n = int(v.size());

  // The first point off the line of v[0], v[1]; all before it are collinear,
  // in order along that line.
  int k = 2;
  while (k < n && orient(v[0], v[1], v[k]) == 0) ++k;
  if (k >= n) return {};

  std::vector<std::array<int, 3>> tri;
  std::unordered_map<std::uint64_t, int> edge;  // directed edge a->b -> the triangle holding it
  auto key = [](int a, int b) { return std::uint64_t(a) << 32 | std::uint32_t(b); };
  auto add = [&](int a, int b, int c) {  // a, b, c counter-clockwise
    edge[key(a, b)] = edge[key(b, c)] = edge[key(c, a)] = int(tri.size());
    tri.push_back({a, b, c});
  };

  // The hull as a counter-clockwise linked list (collinear boundary points included).
  std::vector<int> next(n), prev(n);
  auto link = [&](int a, int b) { next[a] = b, prev[b] = a; };
  const bool left = orient(v[0], v[1], v[k]) > 0;
  for (int i = 0; i + 1 < k; ++i) {  // fan v[k] to the collinear chain
    if (left) add(i, i + 1, k), link(i, i + 1);
    else add(i + 1, i, k), link(i + 1, i);
  }
  if (left) link(k - 1, k), link(k, 0);
  else link(k, k - 1), link(0, k);

  // Sweep: each new point is outside the hull so far (it is greater than
  // every point in it), and sees an edge at the previous point, the
  // rightmost. Connect it to every hull edge it sees strictly.
  for (int p = k + 1; p < n; ++p) {
    int hi = p - 1, lo = p - 1;
    while (orient(v[hi], v[next[hi]], v[p]) < 0) add(next[hi], hi, p), hi = next[hi];
    while (orient(v[prev[lo]], v[lo], v[p]) < 0) add(lo, prev[lo], p), lo = prev[lo];
    link(lo, p), link(p, hi);
  }

  // Lawson flips: an edge a->b of triangle (a, b, c), with (b, a, d) across
  // it, is flipped to c-d when d is inside the circle of a, b, c (and the
  // quad is convex, so the new triangles are counter-clockwise).
  // Safety cap: exact flips never bring an edge back, so they end within
  // n(n-1)/2 flips; the rounded test can flip back and forth forever.
  std::vector<std::pair<int, int>> todo;
  for (const auto& t : tri)
    for (int e = 0; e < 3; ++e)
      if (t[e] < t[(e + 1) % 3]) todo.push_back({t[e], t[(e + 1) % 3]});
  auto third = [&](int t, int a, int b) { return tri[t][0] + tri[t][1] + tri[t][2] - a - b; };
  long long flips = 0;
  const long long cap = 1000 + (long long)n * (n - 1) / 2;
  while (!todo.empty() && flips < cap) {
    const auto [a, b] = todo.back();
    todo.pop_back();
    const auto ab = edge.find(key(a, b)), ba = edge.find(key(b, a));
    if (ab == edge.end() || ba == edge.end()) continue;  // on the hull, or flipped away
    const int t1 = ab->second, t2 = ba->second, c = third(t1, a, b), d = third(t2, a, b);
    if (!in_circle(v[a], v[b], v[c], v[d]) || orient(v[c], v[a], v[d]) <= 0 || orient(v[d], v[b], v[c]) <= 0)
      continue;
    edge.erase(ab), edge.erase(ba);
    tri[t1] = {c, a, d}, tri[t2] = {d, b, c};
    edge[key(c, a)] = edge[key(a, d)] = edge[key(d, c)] = t1;
    edge[key(d, b)] = edge[key(b, c)] = edge[key(c, d)] = t2;
    todo.insert(todo.end(), {{b, c}, {c, a}, {a, d}, {d, b}});
    ++flips;
  }

  for (auto& t : tri) t = {id[t[0]], id[t[1]], id[t[2]]};
  return tri;
}

}  // namespace mine
