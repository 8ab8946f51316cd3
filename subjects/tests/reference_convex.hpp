// Reference subjects for the engine-backed pairs, written the way a user
// writes a general collision routine (reference_subjects.hpp's vectors, not
// production's algorithms), once for any floating-point type T:
//
//   collide(A, B)   any two convex shapes given by support functions:
//                   GJK for the distance (the closest point of a simplex by
//                   brute force over its faces), EPA for the penetration
//                   (the polytope grown towards its face nearest the
//                   origin); a contact's depth is the overlap along the
//                   normal, its point the mid point of the witnesses.
//                   Spheres and capsules against each other: the closest
//                   points of their cores (point, segment), the radii
//                   added.
//   sweep(ball, C)  a moving ball against a cylinder by conservative
//                   advancement: step by the gap over the speed until the
//                   gap is within the tolerance.
//
// Both are iterative, so they claim an error: `margin` (a fraction of the
// scene's scale, Claims::margin) beside their arithmetic's precision. They
// state solid shapes only (a radius, extents and a triangle's height not
// thinner than kThin of the shape's own size): EPA's polytope is flat
// otherwise, as a user's engine documents.
#pragma once

#include <array>
#include <vector>

#include "reference_subjects.hpp"

namespace ref {

template <class T> V<T> cross(V<T> a, V<T> b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

/// The tolerances of the iterations, relative to the scene's scale.
template <class T> struct Tol;
template <> struct Tol<double> {
  static constexpr double gjk = 1e-12, epa = 1e-9, advance = 1e-10, margin = 1e-6;
};
template <> struct Tol<float> {
  static constexpr float gjk = 1e-5f, epa = 1e-4f, advance = 2e-7f;
  static constexpr double margin = 1e-3;
};
/// The thinnest shape stated, relative to the scale.
constexpr double kThin = 1e-3;

// --- support functions: the farthest point of a shape along d ---------------

template <class T> struct Box { V<T> c; std::array<V<T>, 3> axes; V<T> e; };
template <class T> struct Tri { V<T> a, b, c; };
template <class T> struct Cap { V<T> p, q; T r; };

template <class T> V<T> support(const Cyl<T>& s, V<T> d) {
  const V<T> u = s.q - s.p;
  V<T> x = dot(d, u) >= 0 ? s.q : s.p;
  const V<T> radial = across(d, u);
  if (max_abs(radial) > 0) x = x + s.r * unit(radial);
  return x;
}
template <class T> V<T> support(const Ball<T>& s, V<T> d) { return max_abs(d) > 0 ? s.c + s.r * unit(d) : s.c; }
template <class T> V<T> support(const Cap<T>& s, V<T> d) {
  const V<T> x = dot(d, s.q - s.p) >= 0 ? s.q : s.p;
  return max_abs(d) > 0 ? x + s.r * unit(d) : x;
}
template <class T> V<T> support(const Box<T>& s, V<T> d) {
  V<T> x = s.c;
  const T e[3] = {s.e.x, s.e.y, s.e.z};
  for (int i = 0; i < 3; ++i) x = x + (dot(d, s.axes[i]) >= 0 ? e[i] : -e[i]) * s.axes[i];
  return x;
}
template <class T> V<T> support(const Tri<T>& s, V<T> d) {
  const T a = dot(d, s.a), b = dot(d, s.b), c = dot(d, s.c);
  return a >= b && a >= c ? s.a : (b >= c ? s.b : s.c);
}

/// A point of the difference A - B with the points of A and B it came from.
template <class T> struct Vert { V<T> w, a, b; };

template <class A, class B, class T>
Vert<T> support_diff(const A& a, const B& b, V<T> d) {
  const V<T> pa = support(a, d), pb = support(b, T(-1) * d);
  return {pa - pb, pa, pb};
}

/// The closest point to the origin of the hull of the simplex s (1 to 4
/// points), by brute force over its faces: each subset's affine closest
/// point, kept when its weights are positive; the nearest of those. The
/// simplex is reduced to the subset used.
template <class T>
V<T> closest_on_simplex(std::vector<Vert<T>>& s) {
  const int n = static_cast<int>(s.size());
  T best = std::numeric_limits<T>::infinity();
  int best_mask = 1;
  V<T> best_v = s[0].w;
  for (int mask = 1; mask < (1 << n); ++mask) {
    int idx[4], k = 0;
    for (int i = 0; i < n; ++i)
      if (mask & (1 << i)) idx[k++] = i;
    // x = w0 + sum mu_j (w_j - w0): the normal equations (G mu = r).
    T mu[3] = {0, 0, 0};
    if (k > 1) {
      V<T> e[3];
      for (int j = 1; j < k; ++j) e[j - 1] = s[idx[j]].w - s[idx[0]].w;
      const int m = k - 1;
      T g[3][3], r[3];
      for (int i = 0; i < m; ++i) {
        r[i] = -dot(e[i], s[idx[0]].w);
        for (int j = 0; j < m; ++j) g[i][j] = dot(e[i], e[j]);
      }
      if (m == 1) {
        if (!(g[0][0] > 0)) continue;
        mu[0] = r[0] / g[0][0];
      } else if (m == 2) {
        const T det = g[0][0] * g[1][1] - g[0][1] * g[1][0];
        if (!(std::fabs(det) > 64 * std::numeric_limits<T>::epsilon() * g[0][0] * g[1][1])) continue;
        mu[0] = (r[0] * g[1][1] - g[0][1] * r[1]) / det;
        mu[1] = (g[0][0] * r[1] - r[0] * g[1][0]) / det;
      } else {
        const T det = g[0][0] * (g[1][1] * g[2][2] - g[1][2] * g[2][1]) -
                      g[0][1] * (g[1][0] * g[2][2] - g[1][2] * g[2][0]) +
                      g[0][2] * (g[1][0] * g[2][1] - g[1][1] * g[2][0]);
        if (!(std::fabs(det) > 64 * std::numeric_limits<T>::epsilon() * g[0][0] * g[1][1] * g[2][2])) continue;
        for (int c = 0; c < 3; ++c) {
          T h[3][3];
          for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) h[i][j] = j == c ? r[i] : g[i][j];
          mu[c] = (h[0][0] * (h[1][1] * h[2][2] - h[1][2] * h[2][1]) - h[0][1] * (h[1][0] * h[2][2] - h[1][2] * h[2][0]) +
                   h[0][2] * (h[1][0] * h[2][1] - h[1][1] * h[2][0])) /
                  det;
        }
      }
    }
    std::vector<T> w(k);
    T sum = 0;
    bool positive = true;
    for (int j = 1; j < k; ++j) w[j] = mu[j - 1], sum += mu[j - 1], positive &= mu[j - 1] > 0;
    w[0] = 1 - sum;
    positive &= w[0] > 0;
    if (!positive) continue;
    V<T> v{0, 0, 0};
    for (int j = 0; j < k; ++j) v = v + w[j] * s[idx[j]].w;
    const T d = dot(v, v);
    if (d < best) best = d, best_mask = mask, best_v = v;
  }
  std::vector<Vert<T>> kept;
  for (int i = 0; i < n; ++i)
    if (best_mask & (1 << i)) kept.push_back(s[i]);
  s = kept;
  return best_v;
}

/// EPA: the penetration of A and B whose difference contains the origin,
/// from a tetrahedron `seed` around it. Returns false where the polytope is
/// flat (no tetrahedron of volume) or not closed; `converged` says whether
/// the nearest face reached the tolerance (a sliver face or the iteration
/// cap stop it short).
template <class A, class B, class T>
bool epa(const A& a, const B& b, std::vector<Vert<T>> seed, T scale, V<T>& normal, Vert<T>& witness_a_b,
         bool& converged) {
  struct Face { int i, j, k; V<T> n; T d; };
  std::vector<Vert<T>> pts = seed;
  std::vector<Face> faces;
  auto make = [&](int i, int j, int k, Face& f) {
    const V<T> n = cross(pts[j].w - pts[i].w, pts[k].w - pts[i].w);
    if (!(max_abs(n) > 0)) return false;
    f = {i, j, k, unit(n), 0};
    f.d = dot(f.n, pts[i].w);
    return true;
  };
  // The tetrahedron, every face turned outwards.
  const V<T> centre = T(0.25) * (pts[0].w + pts[1].w + pts[2].w + pts[3].w);
  const int tet[4][3] = {{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 3, 2}};
  for (auto& t : tet) {
    Face f;
    if (!make(t[0], t[1], t[2], f)) return false;
    if (dot(f.n, pts[t[0]].w - centre) < 0) {
      if (!make(t[0], t[2], t[1], f)) return false;
    }
    faces.push_back(f);
  }
  const T tol = Tol<T>::epa * scale;
  Face best = faces[0];
  for (int iter = 0; iter < 1024 && !faces.empty(); ++iter) {
    const auto nearest = std::min_element(faces.begin(), faces.end(), [](const Face& x, const Face& y) { return x.d < y.d; });
    best = *nearest;
    const Vert<T> w = support_diff(a, b, best.n);
    if (dot(w.w, best.n) - best.d <= tol) break;
    // The faces w sees, connected to the nearest one (a flood over shared
    // edges keeps the horizon one loop); the horizon's edges, each with w,
    // close the hull.
    const std::size_t nf = faces.size();
    std::vector<char> gone(nf, 0);
    auto owner = [&](int i, int j) {  // the face holding the directed edge i -> j
      for (std::size_t g = 0; g < nf; ++g) {
        const Face& f = faces[g];
        if ((f.i == i && f.j == j) || (f.j == i && f.k == j) || (f.k == i && f.i == j)) return static_cast<int>(g);
      }
      return -1;
    };
    std::vector<int> todo{static_cast<int>(nearest - faces.begin())};
    gone[todo[0]] = 1;
    std::vector<std::array<int, 2>> edges;
    while (!todo.empty()) {
      const Face f = faces[todo.back()];
      todo.pop_back();
      for (auto e : {std::array<int, 2>{f.i, f.j}, std::array<int, 2>{f.j, f.k}, std::array<int, 2>{f.k, f.i}}) {
        const int g = owner(e[1], e[0]);
        if (g < 0) return false;  // not a closed hull
        if (gone[g]) continue;
        if (dot(faces[g].n, w.w - pts[faces[g].i].w) > 0) {
          gone[g] = 1;
          todo.push_back(g);
        }
      }
    }
    for (std::size_t g = 0; g < nf; ++g) {
      if (!gone[g]) continue;
      const Face& f = faces[g];
      for (auto e : {std::array<int, 2>{f.i, f.j}, std::array<int, 2>{f.j, f.k}, std::array<int, 2>{f.k, f.i}})
        if (!gone[owner(e[1], e[0])]) edges.push_back(e);
    }
    std::vector<Face> kept;
    for (std::size_t g = 0; g < nf; ++g)
      if (!gone[g]) kept.push_back(faces[g]);
    pts.push_back(w);
    const int nw = static_cast<int>(pts.size()) - 1;
    bool closed = true;
    for (auto e : edges) {
      Face f{};
      closed &= make(e[0], e[1], nw, f);
      kept.push_back(f);
    }
    if (!closed) break;  // a sliver face: keep the polytope before it
    faces = kept;
  }
  converged = dot(support_diff(a, b, best.n).w, best.n) - best.d <= tol;
  // The origin's projection on the nearest face, in barycentrics.
  const V<T> p = best.d * best.n;
  const V<T> wi = pts[best.i].w, wj = pts[best.j].w, wk = pts[best.k].w;
  const T area = dot(cross(wj - wi, wk - wi), best.n);
  T l1 = dot(cross(wk - wj, p - wj), best.n) / area, l2 = dot(cross(wi - wk, p - wk), best.n) / area;
  l1 = std::min(std::max(l1, T(0)), T(1));
  l2 = std::min(std::max(l2, T(0)), T(1) - l1);
  const T l3 = 1 - l1 - l2;
  normal = best.n;
  witness_a_b.a = l1 * pts[best.i].a + l2 * pts[best.j].a + l3 * pts[best.k].a;
  witness_a_b.b = l1 * pts[best.i].b + l2 * pts[best.j].b + l3 * pts[best.k].b;
  return true;
}

/// The contact of two convex shapes: GJK, then EPA where they overlap.
/// The normal points from A towards B.
template <class A, class B, class T>
Touch<T> collide_convex(const A& a, const B& b, T scale) {
  Touch<T> out;
  std::vector<Vert<T>> s{support_diff(a, b, V<T>{1, 0, 0})};
  V<T> v = s[0].w;
  const T touch = Tol<T>::gjk * scale;
  for (int iter = 0; iter < 128; ++iter) {
    if (len(v) <= touch) break;
    const Vert<T> w = support_diff(a, b, T(-1) * v);
    const T lower = dot(v, w.w) / len(v);  // every point of A - B is this far along v / |v|
    if (lower > touch) return out;         // separated
    if (len(v) - lower <= touch) break;    // converged: touching, to the tolerance
    s.push_back(w);
    v = closest_on_simplex(s);
    if (s.size() == 4) break;  // the origin inside the simplex
  }
  out.hit = true;
  // Touching to the tolerance or overlapping: EPA from a tetrahedron about
  // the origin (the origin on its boundary, or just outside, when they
  // touch): the simplex, grown by supports across what it spans.
  while (s.size() < 4) {
    std::vector<V<T>> dirs;
    if (s.size() == 1) {
      dirs = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    } else if (s.size() == 2) {
      const V<T> e = unit(s[1].w - s[0].w), p1 = any_perp(e), p2 = cross(e, p1);
      dirs = {p1, T(-1) * p1, p2, T(-1) * p2, p1 + p2, T(-1) * (p1 + p2), p1 - p2, p2 - p1};
    } else {
      const V<T> n = unit(cross(s[1].w - s[0].w, s[2].w - s[0].w));
      dirs = {n, T(-1) * n};
    }
    bool grown = false;
    for (const V<T>& d : dirs) {
      const Vert<T> w = support_diff(a, b, d);
      bool fresh = true;
      for (const auto& x : s) fresh &= max_abs(x.w - w.w) > touch;
      if (!fresh) continue;
      if (s.size() == 2 && len(cross(s[1].w - s[0].w, w.w - s[0].w)) <= touch * len(s[1].w - s[0].w)) continue;
      if (s.size() == 3) {
        const V<T> n = cross(s[1].w - s[0].w, s[2].w - s[0].w);
        if (std::fabs(dot(n, w.w - s[0].w)) <= touch * len(n)) continue;
      }
      s.push_back(w);
      grown = true;
      break;
    }
    if (!grown) break;  // A - B is flat
  }
  V<T> n;
  Vert<T> wab{};
  bool converged = false;
  bool found = s.size() == 4 && epa(a, b, s, scale, n, wab, converged);
  if (!converged) {
    // Stopped short: again from the tetrahedron of the supports along the
    // four diagonals, keeping the normal with the smaller overlap (every
    // overlap bounds the penetration depth from above).
    std::vector<Vert<T>> t;
    for (const V<T>& d : {V<T>{1, 1, 1}, V<T>{1, -1, -1}, V<T>{-1, 1, -1}, V<T>{-1, -1, 1}}) t.push_back(support_diff(a, b, d));
    V<T> n2;
    Vert<T> wab2{};
    bool converged2 = false;
    if (epa(a, b, t, scale, n2, wab2, converged2) &&
        (!found || dot(support_diff(a, b, n2).w, n2) < dot(support_diff(a, b, n).w, n))) {
      n = n2, wab = wab2, found = true, converged = converged2;
    }
  }
  if (found && !converged) {
    // Still short (ruled faces, where EPA's polytope refines slowly): the
    // overlap along a direction bounds the penetration depth from above,
    // so walk the direction downhill over the sphere (eight neighbours,
    // the step halved where none is lower) from EPA's.
    T best = dot(support_diff(a, b, n).w, n);
    for (T step = T(1e-2); step > std::numeric_limits<T>::epsilon();) {
      const V<T> p1 = any_perp(n), p2 = cross(n, p1);
      bool moved = false;
      for (const V<T>& d : {p1, T(-1) * p1, p2, T(-1) * p2, p1 + p2, T(-1) * (p1 + p2), p1 - p2, p2 - p1}) {
        const V<T> m = unit(n + step * d);
        const T h = dot(support_diff(a, b, m).w, m);
        if (h < best) {
          best = h, n = m, moved = true;
          break;
        }
      }
      if (!moved) step /= 2;
    }
    const Vert<T> w = support_diff(a, b, n);
    wab.a = w.a, wab.b = w.b;
  }
  if (!found) {
    // Flat (not stated, see kThin), or touching where no tetrahedron
    // grows: depth 0 along the gap's direction.
    out.normal = max_abs(v) > 0 ? unit(T(-1) * v) : V<T>{0, 0, 1};
    return out;
  }
  const Vert<T> far = support_diff(a, b, n);
  const T overlap = dot(far.w, n);  // the overlap along n: negative, a separating plane
  if (overlap < -touch) return Touch<T>{};
  out.normal = n;
  out.depth = std::max(overlap, T(0));
  out.point = T(0.5) * (wab.a + wab.b);
  return out;
}

/// The contact of two rounded shapes (a core swept by a ball: a point or a
/// segment, Cap<T>), as engines treat their spheres and capsules: the
/// closest points of the cores (the textbook parametric solution, guarded
/// for parallel and degenerate segments), the radii added to their
/// distance d: the depth is ra + rb - d. Where the cores nearly meet, the
/// direction between the closest points is rounding; their difference is
/// flat (a point, a segment or a parallelogram), so the normal of its span
/// is a minimal translation, overlapping by at most 2 d more (within the
/// margin for d below a quarter of it).
/// Flaw::Unguarded: a known-wrong sibling, the parametric solution divided
/// by the determinant of parallel segments (zero) too.
template <class T>
Touch<T> collide_rounded(const Cap<T>& a, const Cap<T>& b, T scale, Flaw flaw = Flaw::None) {
  const V<T> d1 = a.q - a.p, d2 = b.q - b.p, r = a.p - b.p;
  const T aa = dot(d1, d1), e = dot(d2, d2), f = dot(d2, r);
  const auto clamp01 = [](T x) { return std::min(std::max(x, T(0)), T(1)); };
  T s = 0, t = 0;
  if (aa == 0 && e == 0) {
  } else if (aa == 0) {
    t = clamp01(f / e);
  } else {
    const T c = dot(d1, r);
    if (e == 0) {
      s = clamp01(-c / aa);
    } else {
      const T bb = dot(d1, d2), denom = aa * e - bb * bb;
      s = denom > 0 || flaw == Flaw::Unguarded ? clamp01((bb * f - c * e) / denom) : T(0);
      t = (bb * s + f) / e;
      if (t < 0) {
        t = 0, s = clamp01(-c / aa);
      } else if (t > 1) {
        t = 1, s = clamp01((bb - c) / aa);
      }
    }
  }
  const V<T> c1 = a.p + s * d1, c2 = b.p + t * d2;
  const T d = len(c2 - c1);
  if (d > a.r + b.r) return Touch<T>{};
  Touch<T> out;
  out.hit = true;
  if (d > T(Tol<T>::margin / 4) * scale) {
    out.normal = T(1 / d) * (c2 - c1);
  } else {
    const V<T> n = cross(d1, d2);
    const T la = std::sqrt(aa), lb = std::sqrt(e);
    // The cross product's direction is good to eps / sin(angle): taken
    // where that tilts the parallelogram by less than a quarter margin;
    // segments more nearly parallel span a strip thinner than that, and a
    // perpendicular to the longer one does.
    if (len(n) > T(8 / Tol<T>::margin) * std::numeric_limits<T>::epsilon() * la * lb)
      out.normal = unit(n);
    else if (std::max(la, lb) > 0)
      out.normal = any_perp(la >= lb ? unit(d1) : unit(d2));
    else
      out.normal = {0, 0, 1};
  }
  out.depth = a.r + b.r - d;
  out.point = c1 + (a.r - out.depth / 2) * out.normal;
  return out;
}
template <class T> Cap<T> rounded(const Ball<T>& b) { return {b.c, b.c, b.r}; }
template <class T> Cap<T> rounded(const Cap<T>& c) { return c; }

/// The gap between a ball and a cylinder (negative: they overlap) and the
/// cylinder's closest point to the centre.
template <class T>
T gap(const Cyl<T>& cy, V<T> c, T r, V<T>& closest) {
  const Touch<T> k = collide<T>(cy, Ball<T>{c, T(0)});
  if (k.hit) {
    closest = c;
    return -r;
  }
  const V<T> d = cy.q - cy.p, u = unit(d), w = c - cy.p;
  const T length = len(d), t = dot(w, u);
  const V<T> radial = across(w, d);
  const T rho = len(radial);
  const V<T> e = rho > 0 ? unit(radial) : any_perp(u);
  closest = cy.p + std::min(std::max(t, T(0)), length) * u + std::min(rho, cy.r) * e;
  return len(c - closest) - r;
}

/// A ball moving by delta against a cylinder: conservative advancement.
/// `loose`: a known-wrong sibling, stopping a million times too early.
template <class T>
Ray<T> sweep(const Ball<T>& b, V<T> delta, const Cyl<T>& cy, T scale, bool loose = false) {
  Ray<T> out;
  V<T> x;
  if (gap(cy, b.c, b.r, x) <= 0) {
    out.hit = out.inside = true;
    out.point = x;
    return out;
  }
  const T speed = len(delta), tol = Tol<T>::advance * scale * (loose ? 1e6 : 1);
  if (!(speed > 0)) return out;
  // A grazing path approaches its closest point in ever smaller steps:
  // after the last step, a gap within the claimed margin is a contact.
  const int steps = 100000;
  T t = 0;
  for (int iter = 0; iter <= steps; ++iter) {
    const V<T> c = b.c + t * delta;
    const T g = gap(cy, c, b.r, x);
    if (g <= tol || (iter == steps && g <= T(Tol<T>::margin / 2) * scale)) {
      out.hit = true;
      out.t = t;
      out.point = x;
      // B's outward normal at x: the ball's direction, or (its centre on
      // the surface to rounding) the reference collide's normal.
      const Touch<T> k = collide<T>(cy, Ball<T>{c, b.r + 2 * tol});
      out.normal = max_abs(c - x) > 0 ? unit(c - x) : k.normal;
      return out;
    }
    t += g / speed;
    if (t > 1) return out;
  }
  return out;
}

// --- adapters --------------------------------------------------------------

template <class T> Cyl<T> mine(const geomcheck::Cylinder& c) { return {mine<T>(c.p), mine<T>(c.q), T(c.r)}; }
template <class T> Ball<T> mine(const geomcheck::Sphere& s) { return {mine<T>(s.c), T(s.r)}; }
template <class T> Cap<T> mine(const geomcheck::Capsule& c) { return {mine<T>(c.p), mine<T>(c.q), T(c.r)}; }
template <class T> Box<T> mine(const geomcheck::Obb& b) {
  return {mine<T>(b.c), {mine<T>(b.axes[0]), mine<T>(b.axes[1]), mine<T>(b.axes[2])}, mine<T>(b.e)};
}
template <class T> Tri<T> mine(const geomcheck::Triangle& t) { return {mine<T>(t.a), mine<T>(t.b), mine<T>(t.c)}; }

/// A shape scaled by k about the origin.
inline geomcheck::Cylinder scaled(geomcheck::Cylinder c, double k) { return {k * c.p, k * c.q, k * c.r}; }
inline geomcheck::Sphere scaled(geomcheck::Sphere s, double k) { return {k * s.c, k * s.r}; }
inline geomcheck::Capsule scaled(geomcheck::Capsule c, double k) { return {k * c.p, k * c.q, k * c.r}; }
inline geomcheck::Obb scaled(geomcheck::Obb b, double k) {
  b.c = k * b.c;
  b.e = k * b.e;
  return b;
}
inline geomcheck::Triangle scaled(geomcheck::Triangle t, double k) { return {k * t.a, k * t.b, k * t.c}; }

/// The scale a user takes: the largest coordinate, radius or extent.
inline double user_scale(const geomcheck::Cylinder& c) { return std::max({max_abs(mine<double>(c.p)), max_abs(mine<double>(c.q)), c.r}); }
inline double user_scale(const geomcheck::Sphere& s) { return std::max(max_abs(mine<double>(s.c)), s.r); }
inline double user_scale(const geomcheck::Capsule& c) { return std::max({max_abs(mine<double>(c.p)), max_abs(mine<double>(c.q)), c.r}); }
inline double user_scale(const geomcheck::Obb& b) { return max_abs(mine<double>(b.c)) + max_abs(mine<double>(b.e)); }
inline double user_scale(const geomcheck::Triangle& t) {
  return std::max({max_abs(mine<double>(t.a)), max_abs(mine<double>(t.b)), max_abs(mine<double>(t.c))});
}
inline double user_scale(const geomcheck::MovingSphere& s) {
  return std::max(max_abs(mine<double>(s.c)) + max_abs(mine<double>(s.delta)), s.r);
}

/// Solid: not thinner than kThin of its own size (what the subject states).
inline bool solid(const geomcheck::Cylinder& c) {
  const double l = len(mine<double>(c.q - c.p));
  return c.r >= kThin * l && l >= kThin * c.r;
}
/// A ball: not a point (the difference of two points has no interior).
inline bool solid(const geomcheck::Sphere& s) { return s.r > 0; }
inline bool solid(const geomcheck::Capsule& c) { return c.r >= kThin * len(mine<double>(c.q - c.p)); }
inline bool solid(const geomcheck::Obb& b) {
  return std::min({b.e.x, b.e.y, b.e.z}) >= kThin * std::max({b.e.x, b.e.y, b.e.z});
}
inline bool solid(const geomcheck::Triangle& t) {
  const V<double> a = mine<double>(t.a), b = mine<double>(t.b), c = mine<double>(t.c);
  const double edge = std::max({len(b - a), len(c - b), len(a - c)});
  return len(cross(b - a, c - a)) >= kThin * edge * edge;
}
/// A ball not smaller than kThin of the scene: the normal at a stop within
/// the advancement's tolerance of contact turns by up to tolerance / r.
inline bool solid(const geomcheck::MovingSphere& m, double scale) { return m.r >= kThin * scale; }

/// The claims of an iterative subject in T: production's, at T's
/// precision, and within Tol<T>::margin of the scale.
template <geomcheck::QueryId Q, class T>
geomcheck::Claims iterative_claims() {
  geomcheck::Claims c = claims_in<Q, T>();
  c.margin = Tol<T>::margin;
  c.point_in_both = false;  // the witnesses' mid point: near both, not in both
  return c;
}

/// Spheres and capsules: a core swept by a ball (collide_rounded).
template <class S>
constexpr bool rounded_shape = std::is_same_v<S, geomcheck::Sphere> || std::is_same_v<S, geomcheck::Capsule>;

/// The collide (or penetration) query Q of a convex A against a convex B,
/// by GJK and EPA in T.
/// Flaw::RoundedCaps: a known-wrong sibling, a cylinder A taken as a
/// capsule; Flaw::Unguarded, two capsules' closest points unguarded.
template <geomcheck::QueryId Q, class T>
auto convex_subject(const char* name, Flaw flaw = Flaw::None) {
  using namespace geomcheck;
  using A = typename QueryTraits<Q>::ShapeA;
  using B = typename QueryTraits<Q>::ShapeB;
  auto collide_fn = [flaw](const A& a0, const B& b0) {
    // The scene scaled by a power of two (exactly) to a scale in [1, 2):
    // squared lengths and determinants stay in T's range.
    const double k = std::ldexp(1.0, -std::ilogb(std::max(user_scale(a0), user_scale(b0))));
    const A a = scaled(a0, k);
    const B b = scaled(b0, k);
    const double s = std::max(user_scale(a), user_scale(b));
    Touch<T> t;
    if constexpr (std::is_same_v<A, Cylinder>) {
      t = flaw == Flaw::RoundedCaps ? collide_convex(Cap<T>{mine<T>(a.p), mine<T>(a.q), T(a.r)}, mine<T>(b), T(s))
                                    : collide_convex(mine<T>(a), mine<T>(b), T(s));
    } else if constexpr (rounded_shape<A> && rounded_shape<B>) {
      t = collide_rounded(rounded(mine<T>(a)), rounded(mine<T>(b)), T(s), flaw);
    } else {
      (void)flaw;
      t = collide_convex(mine<T>(a), mine<T>(b), T(s));
    }
    return Contact{t.hit, (1 / k) * theirs(t.point), theirs(t.normal), double(t.depth) / k};
  };
  auto overlap_fn = [collide_fn](const A& a, const B& b) { return collide_fn(a, b).hit; };
  auto expresses = [](const A& a, const B& b) {
    const double s = std::max(user_scale(a), user_scale(b));
    return s > 0 && std::isfinite(s) && solid(a) && solid(b);
  };
  return subject<Q>(name, overlap_fn, collide_fn, iterative_claims<Q, T>(), expresses);
}

/// sweep_sphere_cylinder by conservative advancement in T (`loose`: the
/// known-wrong sibling).
template <class T>
auto advancing_sweep_subject(const char* name, bool loose = false) {
  using namespace geomcheck;
  constexpr QueryId Q = QueryId::sweep_sphere_cylinder;
  auto sweep_fn = [loose](const MovingSphere& m, const Cylinder& c) {
    const double s = std::max(user_scale(m), user_scale(c));
    return theirs(ref::sweep<T>({mine<T>(m.c), T(m.r)}, mine<T>(m.delta), mine<T>(c), T(s), loose));
  };
  auto expresses = [](const MovingSphere& m, const Cylinder& c) {
    const double s = std::max(user_scale(m), user_scale(c));
    return s > 0 && std::isfinite(s) && solid(m, s) && solid(c);
  };
  return subject<Q>(name, sweep_fn, iterative_claims<Q, T>(), expresses);
}

}  // namespace ref
