#include "geomcheck/collide_cylinder_obb.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "geomcheck/detail/frame.hpp"
#include "geomcheck/detail/obb_stages.hpp"

namespace geomcheck {

namespace {

// The scene in box space: the box is [-e, e]; the cylinder's cap centres P
// and Q are offsets from the box centre along the box axes (so a scene far
// from the origin adds no rounding of its own, and a reflection of the scene
// leaves every box-space value bit-identical).
struct BoxSpace {
  const Obb* box;
  Vec3 e;
  Vec3 P, Q;    // cap centres
  Vec3 u;       // unit axis, from the box-space image of q - p
  double len;   // |q - p|
  double r;
  Vec3 to_box(Vec3 v) const { return {dot(box->axes[0], v), dot(box->axes[1], v), dot(box->axes[2], v)}; }
  Vec3 from_box(Vec3 v) const { return v.x * box->axes[0] + v.y * box->axes[1] + v.z * box->axes[2]; }
  BoxSpace(const Cylinder& cyl, const Obb& b) : box(&b), e(b.e), r(cyl.r) {
    P = to_box(cyl.p - b.c);
    Q = to_box(cyl.q - b.c);
    const Vec3 d = to_box(cyl.q - cyl.p);
    const detail::UnitAndLength ul(max_abs(d) > 0 ? d : Vec3{0, 0, 1});
    u = ul.u;
    len = max_abs(d) > 0 ? ul.len : 0.0;
  }
  // The axis segment S(t), t in [0, 1], from the nearer end (exact at both).
  Vec3 S(double t) const { return t <= 0.5 ? P + t * (Q - P) : Q - (1 - t) * (Q - P); }
  Vec3 clamp_box(Vec3 s) const {
    return {std::clamp(s.x, -e.x, e.x), std::clamp(s.y, -e.y, e.y), std::clamp(s.z, -e.z, e.z)};
  }
  double dist2(double t) const {
    const Vec3 s = S(t);
    const Vec3 o = s - clamp_box(s);
    return dot(o, o);
  }
  Vec3 vertex(int k) const { return {(k & 1) ? e.x : -e.x, (k & 2) ? e.y : -e.y, (k & 4) ? e.z : -e.z}; }
};

// Closest points of the axis segment and the box: f(t) = dist^2(S(t), box)
// is convex and piecewise quadratic in t, its pieces ending where a
// coordinate of S crosses a box plane. Its minimiser over [0, 1] is an end
// or the zero of the (monotone, piecewise linear) slope: found on the one
// piece between the last breakpoint with a negative slope and the first
// with a non-negative one, where the slope is linear.
struct SegBox {
  double t = 0;
  double d2 = 0;
  Vec3 pbox;  // closest box point
};

SegBox segment_box(const BoxSpace& s) {
  const Vec3 d = s.Q - s.P;
  // The segment meeting the box: clipped to every slab (Liang-Barsky), the
  // parameter interval is not empty; then the distance is exactly zero
  // (a flat box, e_i = 0, clips to one parameter exactly, which a minimiser
  // of the squared distance would miss by rounding).
  {
    double t0 = 0, t1 = 1;
    for (int i = 0; i < 3 && t0 <= t1; ++i) {
      if (d[i] == 0) {
        if (s.P[i] < -s.e[i] || s.P[i] > s.e[i]) t0 = 1, t1 = 0;
        continue;
      }
      double a = (-s.e[i] - s.P[i]) / d[i], b = (s.e[i] - s.P[i]) / d[i];
      if (a > b) std::swap(a, b);
      t0 = std::max(t0, a), t1 = std::min(t1, b);
    }
    if (t0 <= t1) {
      SegBox in;
      in.t = 0.5 * (t0 + t1);
      in.d2 = 0;
      in.pbox = s.clamp_box(s.S(in.t));
      return in;
    }
  }
  auto slope = [&](double t, double* d2 = nullptr) {
    const Vec3 x = s.S(t);
    double v = 0, w = 0;
    for (int i = 0; i < 3; ++i) {
      const double ex = x[i] > s.e[i] ? x[i] - s.e[i] : (x[i] < -s.e[i] ? x[i] + s.e[i] : 0.0);
      v += ex * d[i];
      if (d2 && ex != 0) w += d[i] * d[i];
    }
    if (d2) *d2 = w;
    return v;
  };
  SegBox best;
  const double s0 = slope(0);
  if (s0 >= 0) {
    best.t = 0;
  } else if (slope(1) <= 0) {
    best.t = 1;
  } else {
    double lo = 0, hi = 1, slo = s0;
    for (int i = 0; i < 3; ++i) {
      if (d[i] == 0) continue;
      for (double b : {-s.e[i], s.e[i]}) {
        const double t = (b - s.P[i]) / d[i];
        if (!(t > lo && t < hi)) continue;
        const double st = slope(t);
        if (st < 0) lo = t, slo = st;
        else hi = t;
      }
    }
    double den;
    slope(0.5 * (lo + hi), &den);  // the active coordinates of the piece
    best.t = den > 0 ? std::clamp(lo - slo / den, lo, hi) : 0.5 * (lo + hi);
  }
  best.d2 = s.dist2(best.t);
  best.pbox = s.clamp_box(s.S(best.t));
  return best;
}

// The box's section by the plane through cap centre C (box space) normal to
// u, as points (offsets from C) tagged with the box faces they lie on: the
// box vertices on the plane and the crossings of the edges whose ends lie
// strictly on both sides.
struct Section {
  Vec3 x[20];
  unsigned faces[20];
  int edge_axis[20];  // the crossing edge's direction (-1 for a vertex)
  int n = 0;
};

Section section(const BoxSpace& s, Vec3 C) {
  Section out;
  double sv[8];
  Vec3 v[8];
  for (int k = 0; k < 8; ++k) {
    v[k] = s.vertex(k) - C;
    sv[k] = dot(v[k], s.u);
  }
  auto faces_of_vertex = [](int k) {
    return (1u << (0 + (k & 1))) | (1u << (2 + ((k >> 1) & 1))) | (1u << (4 + ((k >> 2) & 1)));
  };
  for (int k = 0; k < 8; ++k) {
    if (sv[k] == 0) {
      out.x[out.n] = v[k];
      out.faces[out.n] = faces_of_vertex(k);
      out.edge_axis[out.n] = -1;
      ++out.n;
    }
  }
  for (int k = 0; k < 8; ++k) {
    for (int j = 0; j < 3; ++j) {
      if (k & (1 << j)) continue;
      const int l = k | (1 << j);
      if (!((sv[k] < 0 && sv[l] > 0) || (sv[k] > 0 && sv[l] < 0))) continue;
      const double lambda = sv[k] / (sv[k] - sv[l]);
      out.x[out.n] = v[k] + lambda * (v[l] - v[k]);
      out.faces[out.n] = faces_of_vertex(k) & ~(1u << (2 * j));  // the two faces containing edge k-l
      out.edge_axis[out.n] = j;
      ++out.n;
    }
  }
  return out;
}

// The point of the box's section nearest the cap centre C (offset from C),
// and its distance: C itself when C is in the box, else on the boundary of
// the section, which is the union of the faces' sections (segments between
// section points sharing a face).
struct NearestInSection {
  bool empty = true;
  Vec3 y;
  double dist = std::numeric_limits<double>::infinity();
};

NearestInSection nearest_in_section(const BoxSpace& s, Vec3 C, const Section& sec) {
  NearestInSection out;
  if (sec.n == 0) return out;
  out.empty = false;
  if (std::fabs(C.x) <= s.e.x && std::fabs(C.y) <= s.e.y && std::fabs(C.z) <= s.e.z) {
    out.y = Vec3{0, 0, 0};
    out.dist = 0;
    return out;
  }
  double best2 = std::numeric_limits<double>::infinity();
  auto consider = [&](Vec3 y) {
    const double l2 = dot(y, y);
    if (l2 < best2) best2 = l2, out.y = y;
  };
  for (int i = 0; i < sec.n; ++i) consider(sec.x[i]);
  for (int i = 0; i < sec.n; ++i) {
    for (int j = i + 1; j < sec.n; ++j) {
      if (!(sec.faces[i] & sec.faces[j])) continue;
      const Vec3 a = sec.x[i], ab = sec.x[j] - sec.x[i];
      const double ab2 = dot(ab, ab);
      if (!(ab2 > 0)) continue;
      const double t = -dot(a, ab) / ab2;
      if (t > 0 && t < 1) consider(a + t * ab);
    }
  }
  out.dist = detail::safe_length(out.y);
  return out;
}

// Where the cylinder and the box meet, decided as the header says.
struct Verdict {
  bool hit = false;
  Vec3 point;  // box space, in both shapes (to rounding)
};

Verdict decide(const BoxSpace& s, detail::ObbCapStage stage) {
  Verdict out;
  const SegBox k = segment_box(s);
  if (!(std::sqrt(k.d2) <= s.r)) return out;  // the bounding capsule misses
  const bool beyond_q = dot(k.pbox - s.Q, s.u) > 0;
  const bool beyond_p = dot(k.pbox - s.P, s.u) < 0;
  if ((!beyond_q && !beyond_p) || stage == detail::ObbCapStage::Capsule) {
    out.hit = true;
    out.point = k.pbox;
    return out;
  }
  const Vec3 C = beyond_q ? s.Q : s.P;
  if (stage == detail::ObbCapStage::TalkRays) {
    // The talk's step 3 (direction corrected to Pbox's radial line): from
    // the cap centre along that line, against the three box planes through
    // Pbox; a hit inside the box and within r is the point.
    const Vec3 w = k.pbox - C;
    const Vec3 dir = w - dot(w, s.u) * s.u;
    for (int i = 0; i < 3; ++i) {
      if (dir[i] == 0) continue;
      const double t = (k.pbox[i] - C[i]) / dir[i];
      if (!(t >= 0)) continue;
      const Vec3 y = C + t * dir;
      if (detail::safe_length(t * dir) <= s.r && std::fabs(y.x) <= s.e.x && std::fabs(y.y) <= s.e.y &&
          std::fabs(y.z) <= s.e.z) {
        out.hit = true;
        out.point = y;
        return out;
      }
    }
    return out;
  }
  const Section sec = section(s, C);
  const NearestInSection ns = nearest_in_section(s, C, sec);
  if (!(ns.dist <= s.r)) return out;
  out.hit = true;
  out.point = C + ns.y;
  return out;
}

// Overlap of the shapes along unit n (box space, from the cylinder towards
// the box): h_cyl(n) + h_box(-n), the box centred at the origin.
double overlap_along(const BoxSpace& s, Vec3 n) {
  const double nu = dot(n, s.u);
  const double h_cyl = std::max(dot(n, s.P), dot(n, s.Q)) + s.r * detail::safe_length(n - nu * s.u);
  return h_cyl + s.e.x * std::fabs(n.x) + s.e.y * std::fabs(n.y) + s.e.z * std::fabs(n.z);
}

struct Best {
  double o = std::numeric_limits<double>::infinity();
  Vec3 n;
  void consider(const BoxSpace& s, Vec3 cand) {
    const double o2 = overlap_along(s, cand);
    if (o2 < o) o = o2, n = cand;
  }
};

// The rim x box-edge patches. For the rim of the cap at C (outward m = su,
// s = +-1) and a box edge along axis j, the patch normal at rim angle theta
// (d = cos f1 + sin f2, radial) is perpendicular to the rim tangent and to
// the edge: n = (|u_j| d + |d_j| m) / sqrt(u_j^2 + d_j^2), in the rim's
// normal cone where s u_j d_j <= 0 (elsewhere the family has no patch). A
// minimal translation on such a patch presses the edge into the rim: the
// edge passes within the penetration depth (<= the best overlap so far) of
// the cap plane, so only such edges are searched, by Newton steps (central
// differences) on the overlap along n(theta) from the angle of the edge's
// point nearest the plane.
constexpr int kAngles = 32;
constexpr double kPi = 3.14159265358979323846;
struct AngleTable {
  double c[kAngles], s[kAngles], c2[kAngles], s2[kAngles];
  AngleTable() {
    for (int i = 0; i < kAngles; ++i) {
      const double th = 2 * kPi * i / kAngles;
      c[i] = std::cos(th), s[i] = std::sin(th), c2[i] = std::cos(2 * th), s2[i] = std::sin(2 * th);
    }
  }
};
const AngleTable& angle_table() {
  static const AngleTable t;
  return t;
}

// cos and sin of |t| < 0.2 by their Taylor series to t^13 (error below
// 1e-17; constant reciprocal factorials, no division).
void rotation(double t, double& c, double& sn) {
  const double t2 = t * t;
  c = 1 + t2 * (-1.0 / 2 + t2 * (1.0 / 24 + t2 * (-1.0 / 720 + t2 * (1.0 / 40320 + t2 * (-1.0 / 3628800 + t2 * (1.0 / 479001600))))));
  sn = t * (1 + t2 * (-1.0 / 6 + t2 * (1.0 / 120 + t2 * (-1.0 / 5040 + t2 * (1.0 / 362880 + t2 * (-1.0 / 39916800 + t2 * (1.0 / 6227020800)))))));
}

// Minima of the overlap along n(theta) on the patch of the rim of cap C
// (outward m = sg u) and the box edge from vertex offset v (from C) along
// box axis j. The slope of that overlap is a positive multiple (in the rim's
// normal cone) of f(theta) = ((R(theta) - vertex) without its edge
// component) . t(theta) = K1 sin 2theta + K2 cos 2theta + A1 sin theta -
// A2 cos theta (A = v without its edge component, in the frame f1, f2), so
// its minima are the roots where f turns from - to +. f has at most four
// roots: bracketed on sample angles (below), refined by Newton kept inside the
// bracket, as rotations of (cos, sin) from its start.
void rim_edge_minima(const BoxSpace& s, Vec3 f1, Vec3 f2, double sg, Vec3 m, Vec3 v, int j, Best& best) {
  const double uj = s.u[j];
  Vec3 vj = v;
  vj[j] = 0;
  const double A1 = dot(vj, f1), A2 = dot(vj, f2), fa = f1[j], fb = f2[j];
  const double K1 = -0.5 * s.r * (fb * fb - fa * fa), K2 = -s.r * fa * fb;
  auto fval = [&](double c, double sn) { return K1 * (2 * sn * c) + K2 * (c * c - sn * sn) + A1 * sn - A2 * c; };
  // Sample angles: 32 uniform ones; when the edge is nearly perpendicular
  // to the axis (|u_j| small) the rim's projection along the edge is a thin
  // ellipse, whose normals from a point meet it twice within about |u_j| of
  // a tip (d_j = 0): there, also a geometric ladder of angles either side.
  constexpr int kMax = kAngles + 4 * 24;
  double th[kMax], cs[kMax], sn[kMax];
  int n = 0;
  const AngleTable& tab = angle_table();
  for (int i = 0; i < kAngles; ++i) th[n] = 2 * kPi * i / kAngles, cs[n] = tab.c[i], sn[n] = tab.s[i], ++n;
  const double tipn = std::sqrt(fa * fa + fb * fb);
  if (std::fabs(uj) < 0.125 && tipn > 0) {
    // The ladder around each tip, in increasing angle, then merged with the
    // uniform angles (both lists sorted; the merge is linear).
    double lt[4 * 24], lc[4 * 24], ls[4 * 24];
    int nl = 0;
    for (double side : {1.0, -1.0}) {
      const double cb = side * fb / tipn, sb = -side * fa / tipn;
      const double tb = std::atan2(sb, cb);
      double dls[24];
      int nd = 0;
      for (double dl = std::max(std::fabs(uj), 0x1p-60) * 0.25; dl < 0.1 && nd < 12; dl *= 4) dls[nd++] = dl;
      for (int q = 2 * nd - 1; q >= 0; --q) {  // -dl (largest first) ... +dl (smallest first)
        const double dl = q >= nd ? -dls[q - nd] : dls[nd - 1 - q];
        double cd, sd;
        rotation(dl, cd, sd);
        double t = tb + dl;
        if (t < 0) t += 2 * kPi;
        if (t >= 2 * kPi) t -= 2 * kPi;
        lt[nl] = t, lc[nl] = cb * cd - sb * sd, ls[nl] = sb * cd + cb * sd, ++nl;
      }
    }
    // Sort the ladder (at most 48 values, already two sorted runs, each
    // possibly wrapped at 2 pi): insertion sort is nearly linear here.
    for (int i = 1; i < nl; ++i)
      for (int q = i; q > 0 && lt[q] < lt[q - 1]; --q) {
        std::swap(lt[q], lt[q - 1]);
        std::swap(lc[q], lc[q - 1]);
        std::swap(ls[q], ls[q - 1]);
      }
    double mt[kMax], mc[kMax], ms[kMax];
    int a = 0, b = 0, m = 0;
    while (a < n || b < nl) {
      if (b >= nl || (a < n && th[a] <= lt[b])) mt[m] = th[a], mc[m] = cs[a], ms[m] = sn[a], ++a;
      else mt[m] = lt[b], mc[m] = lc[b], ms[m] = ls[b], ++b;
      ++m;
    }
    n = m;
    for (int i = 0; i < n; ++i) th[i] = mt[i], cs[i] = mc[i], sn[i] = ms[i];
  }
  double fs[kMax];
  for (int i = 0; i < n; ++i) fs[i] = fval(cs[i], sn[i]);
  for (int i = 0; i < n; ++i) {
    const int i1 = i + 1 < n ? i + 1 : 0;
    const double f0 = fs[i], f1v = fs[i1];
    if (!(f0 < 0 && f1v >= 0)) continue;
    // Roots outside the rim's normal cone carry no patch.
    if (sg * uj * (cs[i] * fa + sn[i] * fb) > 0 && sg * uj * (cs[i1] * fa + sn[i1] * fb) > 0) continue;
    double width = th[i1] - th[i];
    if (width <= 0) width += 2 * kPi;
    // Newton kept inside the bracket (Illinois where it leaves), as
    // rotations of (cos, sin) from the bracket's start.
    double lo = 0, hi = width, flo = f0, fhi = f1v;
    double t = width * (f0 / (f0 - f1v));
    // The overlap is stationary at the root, so an angle error e costs about
    // e^2 / u_j^2 (n turns at a rate up to 1 / |u_j| near the tips): stop
    // below 1e-10 |u_j| (quadratic convergence makes the last step tiny).
    const double tol = 1e-10 * std::min(1.0, std::fabs(uj));
    double c = cs[i], s1 = sn[i];
    int side = 0;
    for (int it = 0; it < 40; ++it) {
      double cd, sd;
      rotation(t, cd, sd);
      c = cs[i] * cd - sn[i] * sd, s1 = sn[i] * cd + cs[i] * sd;
      const double c2 = c * c - s1 * s1, s2 = 2 * s1 * c;
      const double f = K1 * s2 + K2 * c2 + A1 * s1 - A2 * c;
      const double fp = 2 * K1 * c2 - 2 * K2 * s2 + A1 * c + A2 * s1;
      if (f < 0) {
        lo = t, flo = f;
        if (side == -1) fhi *= 0.5;
        side = -1;
      } else {
        hi = t, fhi = f;
        if (side == 1) flo *= 0.5;
        side = 1;
      }
      double next = fp > 0 ? t - f / fp : lo + (hi - lo) * (flo / (flo - fhi));
      if (!(next > lo && next < hi)) next = lo + (hi - lo) * (flo / (flo - fhi));
      if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
      if (std::fabs(next - t) < tol || hi - lo < 0x1p-60) break;
      t = next;
    }
    const Vec3 d = c * f1 + s1 * f2;
    const double dj = d[j];
    if (sg * uj * dj > 0) continue;  // outside the rim's normal cone: no patch
    best.consider(s, (1.0 / std::sqrt(uj * uj + dj * dj)) * (std::fabs(uj) * d + std::fabs(dj) * m));
  }
}

// The rim x box-edge patches. A minimal translation n on the patch of rim
// point R and edge E moves the box by the penetration depth (<= best.o, the
// least overlap so far) to touch R with a point of E, so E passes within
// best.o of the rim circle: the distance from a point y to the circle is
// sqrt(height^2 + (rho - r)^2), at least max(|height|, |rho - r|), which
// bounds the edge from below by (min |height|) and (min |rho - r|) over
// the edge. And for n = a m + b d in the rim's normal cone (a, b >= 0,
// a + b >= 1) and any box point y, the overlap along n is at least
// a (depth of y below the cap plane) + b (r - rho(y)): a box point at least
// best.o below the plane and best.o inside the side rules the patch out
// (the witness, the box centre and the vertices for the whole rim; the
// edge's own points for the edge). Edges are searched in increasing order
// of their bound, which lowers best.o early.
void search_rim_edges(const BoxSpace& s, Vec3 witness, Best& best) {
  const Vec3 f1 = any_perpendicular(s.u);
  const Vec3 f2 = cross(s.u, f1);
  struct Cand {
    double bound;
    int cap, k, j;
  };
  Cand cands[24];
  int nc = 0;
  double hs[2][8];
  Vec3 vs[2][8];
  for (int cap = 0; cap < 2; ++cap) {
    const Vec3 C = cap ? s.Q : s.P;
    const Vec3 m = (cap ? 1.0 : -1.0) * s.u;
    auto deep = [&](Vec3 w, double bo) {  // w from C: at least bo below the plane and inside the side
      const double below = -dot(w, m);
      if (!(below >= bo) || !(s.r >= bo)) return false;
      const Vec3 rad = w - dot(w, s.u) * s.u;
      return dot(rad, rad) <= (s.r - bo) * (s.r - bo);
    };
    bool out = deep(witness - C, best.o) || deep(-C, best.o);
    for (int k = 0; k < 8; ++k) {
      vs[cap][k] = s.vertex(k) - C;
      hs[cap][k] = dot(vs[cap][k], m);
      out = out || deep(vs[cap][k], best.o);
    }
    if (out) continue;
    const double* h = hs[cap];
    const Vec3* v = vs[cap];
    for (int k = 0; k < 8; ++k) {
      for (int j = 0; j < 3; ++j) {
        if ((k & (1 << j)) || s.u[j] == 0) continue;  // u_j == 0: the family is the cap normal
        const int l = k | (1 << j);
        const double hlo = std::min(h[k], h[l]), hhi = std::max(h[k], h[l]);
        const double hgap = hlo > 0 ? hlo : (hhi < 0 ? -hhi : 0.0);
        if (hgap > best.o) continue;
        // rho along the edge is convex: its range is [the closest approach
        // to the axis (clamped), the larger end].
        const Vec3 ed = v[l] - v[k];
        const Vec3 we = ed - dot(ed, s.u) * s.u, wk = v[k] - dot(v[k], s.u) * s.u;
        const double we2 = dot(we, we);
        const double tc = we2 > 0 ? std::clamp(-dot(wk, we) / we2, 0.0, 1.0) : 0.0;
        const Vec3 wc = wk + tc * we, wl = wk + we;
        const double rmin = std::sqrt(dot(wc, wc)), rmax = std::sqrt(std::max(dot(wk, wk), dot(wl, wl)));
        const double rgap = rmin > s.r ? rmin - s.r : (rmax < s.r ? s.r - rmax : 0.0);
        const double bound = std::max(hgap, rgap);
        if (bound > best.o) continue;
        cands[nc++] = {bound, cap, k, j};
      }
    }
  }
  for (int i = 1; i < nc; ++i)
    for (int q = i; q > 0 && cands[q].bound < cands[q - 1].bound; --q) std::swap(cands[q], cands[q - 1]);
  for (int i = 0; i < nc; ++i) {
    const Cand& cd = cands[i];
    const double bo = best.o;
    if (cd.bound > bo) break;
    const double sg = cd.cap ? 1.0 : -1.0;
    const Vec3 m = sg * s.u;
    const Vec3* v = vs[cd.cap];
    const double* h = hs[cd.cap];
    const int k = cd.k, l = k | (1 << cd.j);
    const Vec3 ed = v[l] - v[k];
    const Vec3 we = ed - dot(ed, s.u) * s.u, wk = v[k] - dot(v[k], s.u) * s.u;
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
      if (rmin > s.r + bo || rmax < s.r - bo) continue;
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
    if (ua <= ub && s.r >= bo && rho2_at(closest_to_axis(ua, ub)) <= (s.r - bo) * (s.r - bo)) continue;
    rim_edge_minima(s, f1, f2, sg, m, v[k], cd.j, best);
  }
}

Contact collide_scaled(const Cylinder& cyl, const Obb& box, detail::ObbCapStage stage) {
  Contact out;
  const BoxSpace s(cyl, box);
  const Verdict v = decide(s, stage);
  if (!v.hit) return out;
  out.hit = true;
  out.point = box.c + s.from_box(v.point);
  Best best;
  best.consider(s, s.u);
  best.consider(s, -s.u);
  for (int i = 0; i < 3; ++i) {
    Vec3 a{0, 0, 0};
    a[i] = 1;
    best.consider(s, a);
    best.consider(s, -a);
    const Vec3 x = cross(s.u, a);
    if (max_abs(x) > 0) {
      const Vec3 w = detail::normalized(x);
      best.consider(s, w);
      best.consider(s, -w);
    }
  }
  // The side x vertex patches: a vertex whose radial direction is the
  // minimal translation is within the penetration depth (<= best.o) of the
  // side, and inside the slab.
  for (int k = 0; k < 8; ++k) {
    const Vec3 w = s.vertex(k) - s.P;
    const double z = dot(w, s.u);
    if (z < -best.o || z > s.len + best.o) continue;
    const double rho = detail::safe_length(w - z * s.u);
    if (rho < s.r - best.o || rho > s.r + best.o) continue;
    best.consider(s, detail::unit_perpendicular_part(w, s.u));
  }
  search_rim_edges(s, v.point, best);
  const Vec3 n = s.from_box(best.n);
  out.normal = max_abs(n) > 0 ? detail::normalized(n) : Vec3{0, 0, 1};
  out.depth = std::min(std::max(best.o, 0.0), std::numeric_limits<double>::max());
  return out;
}

// Outside the contract (axes not unit): the answer of an orthonormal frame
// made from them (Gram-Schmidt; the identity where they are degenerate), so
// that every output stays finite. A unit vector has its largest component
// in [3^-1/2, 1]: in-contract frames pass the test untouched.
Obb in_contract(const Obb& b) {
  bool ok = true;
  for (const Vec3& a : b.axes) {
    const double m = max_abs(a);
    ok = ok && m >= 0.5 && m <= 1.5;
  }
  if (ok) return b;
  Obb o = b;
  Vec3 f[3];
  int n = 0;
  for (const Vec3& a0 : b.axes) {
    if (!(max_abs(a0) > 0)) continue;
    Vec3 a = detail::normalized(a0);
    for (int i = 0; i < n; ++i) a = a - dot(a, f[i]) * f[i];
    if (max_abs(a) > 0x1p-20) f[n++] = detail::normalized(a);
  }
  const Vec3 id[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  for (int k = 0; k < 3 && n < 3; ++k) {
    Vec3 a = id[k];
    for (int i = 0; i < n; ++i) a = a - dot(a, f[i]) * f[i];
    if (max_abs(a) > 0.25) f[n++] = detail::normalized(a);
  }
  for (int i = 0; i < 3; ++i) o.axes[i] = f[i];
  return o;
}

}  // namespace

namespace detail {

bool overlap_with_stage(const Cylinder& cyl, const Obb& box, ObbCapStage stage) {
  if (!is_valid(cyl) || !is_valid(box)) return false;
  const SceneScale sc(std::max(largest(cyl), largest(box)));
  return decide(BoxSpace(sc.in(cyl), sc.in(in_contract(box))), stage).hit;
}

Contact collide_with_stage(const Cylinder& cyl, const Obb& box, ObbCapStage stage) {
  if (!is_valid(cyl) || !is_valid(box)) return {};
  const SceneScale sc(std::max(largest(cyl), largest(box)));
  Contact out = collide_scaled(sc.in(cyl), sc.in(in_contract(box)), stage);
  out.point = sc.out(out.point);
  out.depth = std::min(sc.out(out.depth), std::numeric_limits<double>::max());
  return out;
}

}  // namespace detail

bool overlap(const Cylinder& cyl, const Obb& box) {
  return detail::overlap_with_stage(cyl, box, detail::ObbCapStage::Exact);
}

Contact collide(const Cylinder& cyl, const Obb& box) {
  return detail::collide_with_stage(cyl, box, detail::ObbCapStage::Exact);
}

}  // namespace geomcheck
