// geomcheck — internal: the rim x edge patches of a cylinder against a
// polytope (a box, a triangle), for the penetration-depth search of
// collide_cylinder_obb and collide_cylinder_triangle.
//
// The overlap of two convex shapes along a unit direction n is at least
// their penetration depth, and equals it at the normal of the Minkowski
// difference's patch nearest the origin. For the rim of a cap (centre C,
// outward normal m = sg u) and a polytope edge of unit direction e, the patch
// normal at rim angle theta (radial d = cos f1 + sin f2) is perpendicular to
// the rim tangent and to the edge:
//   n = (|u_e| d + |d_e| m) / sqrt(u_e^2 + d_e^2),  u_e = u.e, d_e = d.e,
// in the rim's normal cone where sg u_e d_e <= 0 (elsewhere the family has
// no patch). Everything is computed from dot products with the given
// vectors, so a reflection of the scene (with f1, f2 and the vertices
// reflected with it) gives bit-identical values.
#pragma once

#include <algorithm>
#include <cmath>
#include <utility>

#include "geomcheck/detail/frame.hpp"

namespace geomcheck::detail {

/// The cylinder as the rim search sees it: unit axis u, radius r, and an
/// orthonormal pair f1, f2 across the axis that parametrises the rims.
struct RimFrame {
  Vec3 u;
  double r;
  Vec3 f1, f2;
};

/// The real roots of the polynomial a[0] + a[1] t + ... + a[deg] t^deg in
/// [lo, hi] where it turns from - to + (its minima's slopes), isolated by
/// the roots of its derivative: between consecutive ones the polynomial is
/// monotone, so each such piece holds at most one root, found by Newton's
/// method kept inside the sign-changing bracket (bisection where a step
/// leaves it) until a step no longer moves the root by more than a few
/// ulps. deg <= 4.
inline int poly_rising_roots(const double* a, int deg, double lo, double hi, double* root) {
  // Derivatives' coefficients: der[d] has degree d.
  double der[5][5];
  for (int i = 0; i <= deg; ++i) der[deg][i] = a[i];
  for (int d = deg; d > 1; --d)
    for (int i = 0; i < d; ++i) der[d - 1][i] = (i + 1) * der[d][i + 1];
  auto eval = [](const double* c, int d, double t) {
    double v = c[d];
    for (int i = d - 1; i >= 0; --i) v = v * t + c[i];
    return v;
  };
  // The root of degree d's polynomial in the bracket [l, h] (f(l), f(h) of
  // opposite signs, neither zero); its derivative is der[d - 1].
  auto solve = [&](int d, double l, double h, double fl) {
    const double* c = der[d];
    const double* cp = der[d - 1];
    double x = 0.5 * (l + h);
    for (int it = 0; it < 80; ++it) {
      const double f = eval(c, d, x);
      if (f == 0) return x;
      if ((f < 0) == (fl < 0)) l = x;
      else h = x;
      const double fp = eval(cp, d - 1, x);
      double xn = x - f / fp;
      if (!(xn > l && xn < h)) xn = 0.5 * (l + h);
      if (!(xn > l && xn < h)) return x;  // the bracket is two adjacent doubles
      if (std::fabs(xn - x) <= 0x1p-50 * std::fabs(x) + 0x1p-1000) return xn;
      x = xn;
    }
    return x;
  };
  double crit[4];
  int nc = 0;
  if (deg >= 2 && der[1][1] != 0) crit[nc++] = -der[1][0] / der[1][1];
  for (int d = 2; d <= deg; ++d) {
    const double* c = der[d];
    double r[4];
    int nr = 0;
    double x0 = lo, f0 = eval(c, d, lo);
    for (int j = 0; j <= nc; ++j) {
      const double x1 = j < nc ? std::clamp(crit[j], lo, hi) : hi, f1 = eval(c, d, x1);
      const bool rise = f0 < 0 && f1 >= 0, fall = f0 > 0 && f1 <= 0;
      if (rise || (fall && d < deg)) r[nr++] = f1 == 0 ? x1 : solve(d, x0, x1, f0);
      x0 = x1, f0 = f1;
    }
    for (int i = 0; i < nr; ++i) crit[i] = r[i];
    nc = nr;
  }
  for (int i = 0; i < nc; ++i) root[i] = crit[i];
  return nc;
}

/// Minima of the overlap along n(theta) on the patch of the rim of the cap
/// on side sg (outward m = sg u) and the edge from vertex offset v (from
/// that cap's centre) along unit e; each minimum's n goes to consider(n).
/// The slope of that overlap is a positive multiple (in the rim's normal
/// cone) of f(theta) = ((R(theta) - vertex) without its edge component) .
/// t(theta) = K1 sin 2theta + K2 cos 2theta + A1 sin theta - A2 cos theta (A =
/// v without its edge component, in the frame f1, f2), so its minima are the
/// roots where f turns from - to +. With t = tan(phi / 2), phi the angle
/// from a base angle theta0, (1 + t^2)^2 f is a quartic in t: its roots are
/// isolated exactly (poly_rising_roots), none of them near t = infinity since
/// theta0 + pi is the angle of largest |f| among eight. Roots outside the
/// rim's normal cone are no patch normals, but the overlap along any unit
/// direction bounds the depth from above, so they are considered too.
template <class Consider>
void rim_edge_minima(const RimFrame& fr, double sg, Vec3 v, Vec3 e, Consider&& consider) {
  const Vec3 m = sg * fr.u;
  const double uj = dot(fr.u, e);
  const Vec3 vj = v - dot(v, e) * e;
  // f at theta in the frame (g1, g2).
  auto coeffs = [&](Vec3 g1, Vec3 g2, double& K1, double& K2, double& A1, double& A2) {
    const double fa = dot(g1, e), fb = dot(g2, e);
    A1 = dot(vj, g1), A2 = dot(vj, g2);
    K1 = -0.5 * fr.r * (fb * fb - fa * fa), K2 = -fr.r * fa * fb;
  };
  double K1, K2, A1, A2;
  coeffs(fr.f1, fr.f2, K1, K2, A1, A2);
  // theta0 + pi: the angle of largest |f| among k pi / 4.
  constexpr double h = 0.70710678118654752440;
  const double c8[8] = {1, h, 0, -h, -1, -h, 0, h}, s8[8] = {0, h, 1, h, 0, -h, -1, -h};
  int best = 0;
  double fbest = -1;
  for (int k = 0; k < 8; ++k) {
    const double c = c8[k], sn = s8[k];
    const double f = K1 * (2 * sn * c) + K2 * (c * c - sn * sn) + A1 * sn - A2 * c;
    if (std::fabs(f) > fbest) fbest = std::fabs(f), best = k;
  }
  if (!(fbest > 0)) return;  // f vanishes: the edge lies on the axis line
  // The frame turned so that phi = pi is that angle: g1 = -d(theta_best).
  const Vec3 d0 = c8[best] * fr.f1 + s8[best] * fr.f2, t0 = -s8[best] * fr.f1 + c8[best] * fr.f2;
  const Vec3 g1 = -1.0 * d0, g2 = -1.0 * t0;
  coeffs(g1, g2, K1, K2, A1, A2);
  // (1 + t^2)^2 f = sum a_i t^i.
  const double a[5] = {K2 - A2, 4 * K1 + 2 * A1, -6 * K2, -4 * K1 + 2 * A1, K2 + A2};
  double bound = 0;
  for (int i = 0; i < 4; ++i) bound = std::max(bound, std::fabs(a[i]));
  bound = 1 + bound / std::fabs(a[4]);  // Cauchy: every root within
  // Each candidate is divided by its own length rather than by
  // sqrt(uj^2 + dj^2), which is its length only when d is a unit vector
  // across the axis: the overlap along a short vector is short by as much,
  // and would pass for a depth below the penetration depth.
  auto emit = [&](Vec3 d) {
    const Vec3 n = std::fabs(uj) * d + std::fabs(dot(d, e)) * m;
    const double l2 = dot(n, n);
    if (l2 > 0) consider((1.0 / std::sqrt(l2)) * n);
  };
  double root[4];
  const int nr = poly_rising_roots(a, 4, -bound, bound, root);
  for (int i = 0; i < nr; ++i) {
    const double t = root[i], q = 1 / (1 + t * t);
    const double c = (1 - t * t) * q, sn = 2 * t * q;
    emit(c * g1 + sn * g2);
  }
  // Near the tips of the rim's projection along the edge (d . e = 0), where
  // the edge line pierces the cap plane next to the rim, up to three roots
  // crowd within a tiny angle, and f there is the difference of terms of
  // the coefficients' size: the quartic's rounding (eps * scale) can turn
  // them complex. In the frame g2 = e's direction in the cap plane (length
  // lp), g1 across it, f = sin phi (v1 - r lp^2 cos phi) - B2 cos phi with
  // B2 = uj (uj v2 - lp vu), which at phi = x (tip 0) and pi + x (tip pi)
  // is, to O(x^4), the cubic -B2 + L0 x + B2 x^2 / 2 + (r'/2 - L0/6) x^3,
  // L0 = v1 - r', r' = r lp^2 (tip pi: B2 -> -B2, L0 -> -(v1 + r'), and
  // x^3 -> r'/2 + (v1 + r')/6); its coefficients carry errors of eps
  // times their own size, not the scale's. Its rising roots in |x| <= 1e-3
  // are considered too (the window holds every crowd the quartic cannot
  // resolve; a stray candidate only costs an evaluation).
  // h2: e's direction in the cap plane. For an edge nearly along the axis,
  // e - uj u has cancelled to rounding noise that is not perpendicular to
  // the axis; a second projection makes it so (to rounding), so that h1, h2
  // stay an orthonormal pair there. Both passes are dot products and
  // scalings, so a reflected scene gives the reflected h2 bit for bit.
  Vec3 ep = e - uj * fr.u;
  ep = ep - dot(ep, fr.u) * fr.u;
  const double lp = std::sqrt(dot(ep, ep));
  if (!(lp > 0)) return;
  const Vec3 h2 = (1.0 / lp) * ep, h1 = cross(h2, cross(fr.f1, fr.f2));
  const double v1 = dot(v, h1), v2 = dot(v, h2), vu = dot(v, fr.u);
  const double B2 = uj * (uj * v2 - lp * vu), rp = fr.r * lp * lp;
  constexpr double w = 1e-3;
  for (int tip = 0; tip < 2; ++tip) {
    const double L = tip ? -(v1 + rp) : v1 - rp, c0 = tip ? B2 : -B2;
    const double c[4] = {c0, L, -0.5 * c0, 0.5 * rp - L / 6};
    // A root in the window needs |c0| below the other terms' reach.
    if (std::fabs(c0) * (1 - 0.5 * w * w) > std::fabs(L) * w + std::fabs(c[3]) * (w * w * w)) continue;
    double x[3];
    const int n = poly_rising_roots(c, 3, -w, w, x);
    for (int i = 0; i < n; ++i) {
      const Vec3 d = std::cos(x[i]) * h1 + std::sin(x[i]) * h2;
      emit(tip ? -1.0 * d : d);
    }
  }
}

/// A polytope as the rim search sees it: vertices as offsets from the same
/// origin as the cap centres, edges as vertex pairs with unit directions,
/// and points of the polytope that may rule whole rims out (a witness of the
/// overlap, a centre).
struct RimPolytope {
  const Vec3* vertex;
  int nv;
  const int (*edge)[2];
  const Vec3* dir;  // unit, from edge[i][0] to edge[i][1]
  int ne;
  const Vec3* inner;
  int ni;
};

/// The rim x edge patches of the caps at P and Q (offsets) against the
/// polytope. `best` has `o` (the least overlap so far) and consider(n). A
/// minimal translation n on the patch of rim point R and edge E moves the
/// polytope by the penetration depth (<= best.o) to touch R with a point of
/// E, so E passes within best.o of the rim circle: the distance from a point
/// y to the circle is sqrt(height^2 + (rho - r)^2), at least max(|height|,
/// |rho - r|), which bounds the edge from below by (min |height|) and
/// (min |rho - r|) over the edge. And for n = a m + b d in the rim's normal
/// cone (a, b >= 0, a + b >= 1) and any polytope point y, the overlap along
/// n is at least a (depth of y below the cap plane) + b (r - rho(y)): a
/// polytope point at least best.o below the plane and best.o inside the side
/// rules the patch out (the inner points and the vertices for the whole rim;
/// the edge's own points for the edge). Edges are searched in increasing
/// order of their bound, which lowers best.o early.
template <class Best>
void search_rim_edges(const RimFrame& fr, Vec3 P, Vec3 Q, const RimPolytope& poly, Best& best) {
  constexpr int kMaxV = 8, kMaxE = 12;
  struct Cand {
    double bound;
    int cap, edge;
  };
  Cand cands[2 * kMaxE];
  int nc = 0;
  double hs[2][kMaxV];
  Vec3 vs[2][kMaxV];
  const double r = fr.r;
  const Vec3 u = fr.u;
  for (int cap = 0; cap < 2; ++cap) {
    const Vec3 C = cap ? Q : P;
    const Vec3 m = (cap ? 1.0 : -1.0) * u;
    auto deep = [&](Vec3 w, double bo) {  // w from C: at least bo below the plane and inside the side
      const double below = -dot(w, m);
      if (!(below >= bo) || !(r >= bo)) return false;
      const Vec3 rad = w - dot(w, u) * u;
      return dot(rad, rad) <= (r - bo) * (r - bo);
    };
    bool out = false;
    for (int i = 0; i < poly.ni; ++i) out = out || deep(poly.inner[i] - C, best.o);
    for (int k = 0; k < poly.nv; ++k) {
      vs[cap][k] = poly.vertex[k] - C;
      hs[cap][k] = dot(vs[cap][k], m);
      out = out || deep(vs[cap][k], best.o);
    }
    if (out) continue;
    const double* h = hs[cap];
    const Vec3* v = vs[cap];
    for (int i = 0; i < poly.ne; ++i) {
      if (dot(u, poly.dir[i]) == 0) continue;  // u . e == 0: the family is the cap normal
      const int k = poly.edge[i][0], l = poly.edge[i][1];
      const double hlo = std::min(h[k], h[l]), hhi = std::max(h[k], h[l]);
      const double hgap = hlo > 0 ? hlo : (hhi < 0 ? -hhi : 0.0);
      if (hgap > best.o) continue;
      // rho along the edge is convex: its range is [the closest approach
      // to the axis (clamped), the larger end].
      const Vec3 ed = v[l] - v[k];
      const Vec3 we = ed - dot(ed, u) * u, wk = v[k] - dot(v[k], u) * u;
      const double we2 = dot(we, we);
      const double tc = we2 > 0 ? std::clamp(-dot(wk, we) / we2, 0.0, 1.0) : 0.0;
      const Vec3 wc = wk + tc * we, wl = wk + we;
      const double rmin = std::sqrt(dot(wc, wc)), rmax = std::sqrt(std::max(dot(wk, wk), dot(wl, wl)));
      const double rgap = rmin > r ? rmin - r : (rmax < r ? r - rmax : 0.0);
      const double bound = std::max(hgap, rgap);
      if (bound > best.o) continue;
      cands[nc++] = {bound, cap, i};
    }
  }
  for (int i = 1; i < nc; ++i)
    for (int q = i; q > 0 && cands[q].bound < cands[q - 1].bound; --q) std::swap(cands[q], cands[q - 1]);
  for (int i = 0; i < nc; ++i) {
    const Cand& cd = cands[i];
    const double bo = best.o;
    if (cd.bound > bo) break;
    const double sg = cd.cap ? 1.0 : -1.0;
    const Vec3* v = vs[cd.cap];
    const double* h = hs[cd.cap];
    const int k = poly.edge[cd.edge][0], l = poly.edge[cd.edge][1];
    const Vec3 ed = v[l] - v[k];
    const Vec3 we = ed - dot(ed, u) * u, wk = v[k] - dot(v[k], u) * u;
    const double we2 = dot(we, we);
    auto rho2_at = [&](double t) {
      const Vec3 w = wk + t * we;
      return dot(w, w);
    };
    auto closest_to_axis = [&](double lo, double hi) { return we2 > 0 ? std::clamp(-dot(wk, we) / we2, lo, hi) : lo; };
    const double dh = h[l] - h[k];
    // The edge's part within bo of the cap plane must come within bo of
    // the rim's radius (rho is convex along the edge: on that part its range
    // is [the closest approach to the axis, the larger end]).
    {
      double ta = 0, tb = 1;
      if (dh != 0) {
        ta = std::clamp((-bo - h[k]) / dh, 0.0, 1.0);
        tb = std::clamp((bo - h[k]) / dh, 0.0, 1.0);
        if (ta > tb) std::swap(ta, tb);
      }
      const double rmin = std::sqrt(rho2_at(closest_to_axis(ta, tb)));
      const double rmax = std::sqrt(std::max(rho2_at(ta), rho2_at(tb)));
      if (rmin > r + bo || rmax < r - bo) continue;
    }
    // The edge's part at least bo below the plane: a point of it inside the
    // side by bo rules the edge out.
    double ua = 0, ub = 1;
    if (dh != 0) {
      const double t0 = (-bo - h[k]) / dh;
      if (dh > 0) ub = std::min(ub, t0);
      else ua = std::max(ua, t0);
    } else if (h[k] > -bo) {
      ua = 1, ub = 0;
    }
    if (ua <= ub && r >= bo && rho2_at(closest_to_axis(ua, ub)) <= (r - bo) * (r - bo)) continue;
    rim_edge_minima(fr, sg, v[k], poly.dir[cd.edge], [&](Vec3 n) { best.consider(n); });
  }
}

}  // namespace geomcheck::detail
