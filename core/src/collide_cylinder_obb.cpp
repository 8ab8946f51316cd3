#include "geomcheck/collide_cylinder_obb.hpp"
#include "geomcheck/collide_many.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "geomcheck/detail/frame.hpp"
#include "geomcheck/detail/obb_stages.hpp"
#include "geomcheck/detail/rim_edge.hpp"

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
    // q - p is exact or nearly so; its box-space image is not when its
    // products with the axes underflow (a rotation of a subnormal 10-bit
    // number keeps 10 bits): such a tiny axis is rotated after an exact
    // power-of-two scaling to [1, 2), and its length scaled back (elsewhere
    // the scaling would change no bit, and is skipped).
    const Vec3 dw = cyl.q - cyl.p;
    const double m = max_abs(dw);
    int ex = 1;
    if (m > 0 && m < 0x1p-500) std::frexp(m, &ex);
    const Vec3 d =
        to_box(ex == 1 ? dw : Vec3{std::ldexp(dw.x, 1 - ex), std::ldexp(dw.y, 1 - ex), std::ldexp(dw.z, 1 - ex)});
    const detail::UnitAndLength ul(max_abs(d) > 0 ? d : Vec3{0, 0, 1});
    u = ul.u;
    len = max_abs(d) > 0 ? (ex == 1 ? ul.len : std::ldexp(ul.len, ex - 1)) : 0.0;
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
  const BoxSpace* s;
  double o = std::numeric_limits<double>::infinity();
  Vec3 n{0, 0, 1};
  void consider(Vec3 cand) {
    const double o2 = overlap_along(*s, cand);
    if (o2 < o) o = o2, n = cand;
  }
};

// The rim x box-edge patches (detail/rim_edge.hpp): the box's 8 vertices
// and 12 edges (along the box axes), the witness and the centre as inner
// points.
struct BoxEdges {
  int edge[12][2];
  Vec3 dir[12];
  BoxEdges() {
    int n = 0;
    for (int k = 0; k < 8; ++k)
      for (int j = 0; j < 3; ++j) {
        if (k & (1 << j)) continue;
        edge[n][0] = k, edge[n][1] = k | (1 << j);
        dir[n] = Vec3{0, 0, 0};
        dir[n][j] = 1;
        ++n;
      }
  }
};

void search_rim_edges(const BoxSpace& s, Vec3 witness, Best& best) {
  static const BoxEdges edges;
  detail::RimFrame fr;
  fr.u = s.u;
  fr.r = s.r;
  fr.f1 = any_perpendicular(s.u);
  fr.f2 = cross(s.u, fr.f1);
  Vec3 vertex[8];
  for (int k = 0; k < 8; ++k) vertex[k] = s.vertex(k);
  const Vec3 inner[2] = {witness, Vec3{0, 0, 0}};
  const detail::RimPolytope poly{vertex, 8, edges.edge, edges.dir, 12, inner, 2};
  detail::search_rim_edges(fr, s.P, s.Q, poly, best);
}

Contact collide_scaled(const Cylinder& cyl, const Obb& box, detail::ObbCapStage stage) {
  Contact out;
  const BoxSpace s(cyl, box);
  const Verdict v = decide(s, stage);
  if (!v.hit) return out;
  out.hit = true;
  out.point = box.c + s.from_box(v.point);
  Best best{&s};
  best.consider(s.u);
  best.consider(-s.u);
  for (int i = 0; i < 3; ++i) {
    Vec3 a{0, 0, 0};
    a[i] = 1;
    best.consider(a);
    best.consider(-a);
    const Vec3 x = cross(s.u, a);
    if (max_abs(x) > 0) {
      const Vec3 w = detail::normalized(x);
      best.consider(w);
      best.consider(-w);
    }
  }
  // The side x vertex patches: a vertex whose radial direction is the
  // minimal translation is within the penetration depth (<= best.o) of the
  // side, and inside the slab.
  for (int k = 0; k < 8; ++k) detail::consider_side_vertex(s.vertex(k) - s.P, s.u, s.len, s.r, best);
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
  return overlap_rescaled(cyl, box, [&](const Cylinder& c, const Obb& b) {
    return decide(BoxSpace(c, in_contract(b)), stage).hit;
  });
}

Contact collide_with_stage(const Cylinder& cyl, const Obb& box, ObbCapStage stage) {
  return collide_rescaled(cyl, box, [&](const Cylinder& c, const Obb& b) { return collide_scaled(c, in_contract(b), stage); });
}

}  // namespace detail

bool overlap(const Cylinder& cyl, const Obb& box) {
  return detail::overlap_with_stage(cyl, box, detail::ObbCapStage::Exact);
}

Contact collide(const Cylinder& cyl, const Obb& box) {
  return detail::collide_with_stage(cyl, box, detail::ObbCapStage::Exact);
}

void overlap_many(const Cylinder& cyl, const Obb* b, std::size_t n, bool* out) {
  detail::each_scalar(cyl, b, n, out, [](const Cylinder& c, const Obb& x) { return overlap(c, x); });
}

void collide_many(const Cylinder& cyl, const Obb* b, std::size_t n, Contact* out) {
  detail::each_scalar(cyl, b, n, out, [](const Cylinder& c, const Obb& x) { return collide(c, x); });
}

}  // namespace geomcheck
