#include "geomcheck/collide_cylinder_triangle.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "geomcheck/detail/frame.hpp"
#include "geomcheck/detail/planar_epa.hpp"
#include "geomcheck/detail/sign_filters.hpp"
#include "geomcheck/detail/rim_edge.hpp"
#include "geomcheck/detail/triangle_stages.hpp"

namespace geomcheck {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// The scene as offsets from the cap centre p: the triangle's vertices V[k],
// the other cap centre Q, the unit axis u (from Q) and the length. Values
// computed from dot and cross products of these offsets are bit-identical
// (or exactly negated) when the scene is reflected.
struct TriSpace {
  Vec3 V[3];
  Vec3 Q;
  Vec3 P0, Q0, T[3];  // the points themselves: their differences, exactly, orient directions
  Vec3 u;
  double len, r;
  Vec3 nt;  // (V1 - V0) x (V2 - V0), each component accurately: zero for a degenerate triangle
  TriSpace(const Cylinder& cyl, const Triangle& t) : P0(cyl.p), Q0(cyl.q), T{t.a, t.b, t.c}, r(cyl.r) {
    V[0] = t.a - cyl.p, V[1] = t.b - cyl.p, V[2] = t.c - cyl.p;
    Q = cyl.q - cyl.p;
    const detail::UnitAndLength ul(max_abs(Q) > 0 ? Q : Vec3{0, 0, 1});
    u = ul.u;
    len = max_abs(Q) > 0 ? ul.len : 0.0;
    nt = accurate_cross(V[1] - V[0], V[2] - V[0]);
  }
  // a x b with each component a 2x2 determinant by Kahan's fma algorithm,
  // within 2 ulps of the exact one. The plain cross product of the edges of
  // a sliver loses the digits of its small value: its direction was off by
  // eps / sin(angle), and the sliver's extent along that normal (length *
  // angle) showed as a spurious overlap.
  static Vec3 accurate_cross(Vec3 a, Vec3 b) {
    auto det = [](double p, double q, double r, double t) {  // p q - r t
      const double w = r * t, e = std::fma(-r, t, w), f = std::fma(p, q, -w);
      return f + e;
    };
    return {det(a[1], b[2], a[2], b[1]), det(a[2], b[0], a[0], b[2]), det(a[0], b[1], a[1], b[0])};
  }
  bool flat() const { return max_abs(nt) > 0; }
  // The longest edge, V[lk] -> V[lk + 1]: a point of the triangle projects
  // onto it between its ends.
  int longest() const {
    int k = 0;
    double l2 = -1;
    for (int i = 0; i < 3; ++i) {
      const Vec3 e = V[i == 2 ? 0 : i + 1] - V[i];
      if (dot(e, e) > l2) l2 = dot(e, e), k = i;
    }
    return k;
  }
};

// Exact signs of sums of products: each product splits exactly into a sum
// of two doubles (fma), and the parts are summed as a non-overlapping
// expansion (Shewchuk's grow-expansion, zeros dropped), whose largest
// component has the sign of the sum. Exact while no product underflows.
template <int N>
struct ExactSum {
  double e[N];
  int m = 0;
  void grow(double x) {
    int k = 0;
    double q = x;
    for (int i = 0; i < m; ++i) {
      const double sum = q + e[i], bv = sum - q, err = (q - (sum - bv)) + (e[i] - bv);
      if (err != 0) e[k++] = err;
      q = sum;
    }
    if (q != 0) e[k++] = q;
    m = k;
  }
  void add_product(double x, double y) {
    const double hi = x * y, lo = std::fma(x, y, -hi);
    grow(lo);
    grow(hi);
  }
  int sign() const { return m == 0 ? 0 : (e[m - 1] > 0 ? 1 : -1); }
};

// The offset x - y between two points of the scene, exactly (not the
// rounded difference: offsets that differ in the true scene can round to
// the same double, and a scene lying in one plane only after that rounding
// is no true mirror tie; regressions 0010, 0011).
struct Key {
  Vec3 x, y;
};

// The sign of w . (x - y), exactly. A reflection of the scene negates the
// exact value, so an orientation chosen by this sign is reflected with the
// scene even where the rounded product is zero or noise.
// The rounded value decides where it exceeds its error bound (each
// difference within 2^-53 of itself, the dot product within 3 * 2^-53 of
// the sum of its terms' magnitudes, and an underflow margin); a reflection
// leaves that test's outcome as it is.
int exact_dot_sign(Vec3 w, const Key& k) {
  const detail::FilterValue f = detail::dot_difference_filter(w, k.x, k.y);
  if (std::fabs(f.value) > f.bound) return f.value > 0 ? 1 : -1;
  ExactSum<12> s;
  for (int i = 0; i < 3; ++i) s.add_product(w[i], k.x[i]), s.add_product(-w[i], k.y[i]);
  return s.sign();
}

// w turned to the side of the first key off its plane (exact signs); left
// as it is when every key lies in that plane.
void orient_by(Vec3& w, const Key* keys, int nk) {
  for (int i = 0; i < nk; ++i) {
    const int k = exact_dot_sign(w, keys[i]);
    if (k != 0) {
      if (k < 0) w = -w;
      return;
    }
  }
}


// sg * q . (a x b) added to an exact sum: each 2x2 minor of a x b is four
// exact parts (two products, each split by fma), each part times q_i split
// again.
template <int N>
void add_triple(ExactSum<N>& s, double sg, Vec3 q, Vec3 a, Vec3 b) {
  for (int i = 0; i < 3; ++i) {
    const int j = i == 2 ? 0 : i + 1, k = j == 2 ? 0 : j + 1;
    const double p1 = a[j] * b[k], p1l = std::fma(a[j], b[k], -p1);
    const double p2 = a[k] * b[j], p2l = std::fma(a[k], b[j], -p2);
    s.add_product(sg * q[i], p1);
    s.add_product(sg * q[i], p1l);
    s.add_product(-sg * q[i], p2);
    s.add_product(-sg * q[i], p2l);
  }
}

// The sign of q . (a x b), exactly.
int exact_triple_sign(Vec3 q, Vec3 a, Vec3 b) {
  ExactSum<48> s;
  add_triple(s, 1.0, q, a, b);
  return s.sign();
}

struct Closest {
  double d2 = kInf;
  Vec3 tri;  // the triangle's point
  Vec3 seg;  // the other point
  void keep(Vec3 a, Vec3 b) {
    const Vec3 d = a - b;
    const double l2 = dot(d, d);
    if (l2 < d2) d2 = l2, tri = a, seg = b;
  }
};

// Closest point of segment [a, b] to x.
Vec3 on_segment(Vec3 a, Vec3 b, Vec3 x) {
  const Vec3 e = b - a;
  const double e2 = dot(e, e);
  if (!(e2 > 0)) return a;
  const double t = std::clamp(dot(x - a, e) / e2, 0.0, 1.0);
  return t <= 0.5 ? a + t * e : b - (1 - t) * e;
}

// Is x (in the triangle's plane, up to rounding) inside the closed
// triangle? The signs of the triple products with the normal, and x
// between the ends of the longest edge along it. The second test follows
// from the first in exact arithmetic, but on a sliver the triple products
// of a point near the sliver's line are rounding noise however far beyond
// the sliver's ends it lies (the edges are all nearly along that line);
// the projection onto the longest edge is accurate there.
bool inside(const TriSpace& s, Vec3 x) {
  const int lk = s.longest();
  const Vec3 a0 = s.V[lk], e0 = s.V[lk == 2 ? 0 : lk + 1] - a0;
  const double along = dot(x - a0, e0);
  if (along < 0 || along > dot(e0, e0)) return false;
  for (int k = 0; k < 3; ++k) {
    const Vec3 a = s.V[k], b = s.V[k == 2 ? 0 : k + 1];
    if (dot(s.nt, cross(b - a, x - a)) < 0) return false;
  }
  return true;
}

// Closest point of the triangle to x: the projection onto the plane when it
// falls inside, else the nearest of the edges' closest points (a degenerate
// triangle is the union of its edges).
Vec3 on_triangle(const TriSpace& s, Vec3 x) {
  if (s.flat()) {
    const Vec3 w = x - s.V[0];
    const Vec3 y = x - (dot(s.nt, w) / dot(s.nt, s.nt)) * s.nt;
    if (inside(s, y)) return y;
  }
  Closest c;
  for (int k = 0; k < 3; ++k) {
    const Vec3 y = on_segment(s.V[k], s.V[k == 2 ? 0 : k + 1], x);
    c.keep(y, x);
  }
  return c.tri;
}

// Closest points of segments [p1, q1] (the triangle's edge) and [p2, q2]
// (the axis): Ericson, Real-Time Collision Detection 5.1.9, every degenerate
// branch explicit. On nearly parallel segments the parameters are ill
// conditioned, but the distance is not (the squared distance is flat along
// the valley), which is all the verdict needs.
void segment_segment(Vec3 p1, Vec3 q1, Vec3 p2, Vec3 q2, Closest& out) {
  const Vec3 d1 = q1 - p1, d2 = q2 - p2, rr = p1 - p2;
  const double a = dot(d1, d1), e = dot(d2, d2), f = dot(d2, rr);
  double s = 0, t = 0;
  if (!(a > 0) && !(e > 0)) {
    s = t = 0;
  } else if (!(a > 0)) {
    t = std::clamp(f / e, 0.0, 1.0);
  } else {
    const double c = dot(d1, rr);
    if (!(e > 0)) {
      s = std::clamp(-c / a, 0.0, 1.0);
    } else {
      const double b = dot(d1, d2);
      const double den = std::max(a * e - b * b, 0.0);
      s = den > 0 ? std::clamp((b * f - c * e) / den, 0.0, 1.0) : 0.0;
      t = (b * s + f) / e;
      if (t < 0) t = 0, s = std::clamp(-c / a, 0.0, 1.0);
      else if (t > 1) t = 1, s = std::clamp((b - c) / a, 0.0, 1.0);
    }
  }
  const Vec3 x1 = s <= 0.5 ? p1 + s * d1 : q1 - (1 - s) * d1;
  const Vec3 x2 = t <= 0.5 ? p2 + t * d2 : q2 - (1 - t) * d2;
  out.keep(x1, x2);
}

// The point where the segment [0, Q] crosses the plane through the
// triangle's longest edge AB whose normal is made exactly perpendicular to
// AB, so that only its turn about AB (whose error is bounded by the width
// of a sliver) is rounding; at parameter t_parallel when the segment is
// parallel to that plane.
Vec3 crossing_by_longest_edge(const TriSpace& s, double t_parallel) {
  const int k = s.longest();
  const Vec3 A = s.V[k], e = detail::normalized(s.V[k == 2 ? 0 : k + 1] - A);
  const Vec3 n0 = cross(e, s.V[k == 0 ? 2 : k - 1] - A);
  const Vec3 n = n0 - dot(n0, e) * e;
  const double den = dot(n, s.Q);
  const double t = den != 0 ? std::clamp(dot(n, A) / den, 0.0, 1.0) : t_parallel;
  return t <= 0.5 ? t * s.Q : s.Q - (1 - t) * s.Q;
}

// Does the segment [0, Q] meet the triangle, decided exactly (for the
// offsets)? Its line meets the closed triangle iff the three orientations
// w[k] = Q . (V_k x V_k+1) agree in sign (not all zero), and the segment
// meets the plane iff its ends orient oppositely against the triangle (or
// one lies on it): with T0 = V0 . (V1 x V2) the orientations are T0 (P, the
// origin) and T0 - (w0 + w1 + w2) (Q). A rounded sign within its error
// bound of zero is recomputed exactly. Where they meet, the pair of c is
// replaced by a meeting point: an end on the plane exactly, else the
// nearest of c's triangle point and the crossing of the plane through the
// longest edge (segment_triangle's), whichever lies nearer the other shape.
void meet_exactly(const TriSpace& s, const double* w, Closest& c) {
  int sg[3];
  double wb = 0;
  for (int k = 0; k < 3; ++k) {
    const Vec3 a = s.V[k], b = s.V[k == 2 ? 0 : k + 1];
    const double bound = detail::triple_filter(s.Q, a, b).bound;
    wb += bound;
    sg[k] = std::fabs(w[k]) > bound ? (w[k] > 0 ? 1 : -1) : exact_triple_sign(s.Q, a, b);
  }
  const bool pos = sg[0] >= 0 && sg[1] >= 0 && sg[2] >= 0, neg = sg[0] <= 0 && sg[1] <= 0 && sg[2] <= 0;
  if (!(pos || neg) || (sg[0] == 0 && sg[1] == 0 && sg[2] == 0)) return;
  const detail::FilterValue f0 = detail::triple_filter(s.V[0], s.V[1], s.V[2]);
  const double vv = f0.bound;
  const double t0 = f0.value, tq = t0 - (w[0] + w[1] + w[2]);
  int sp = t0 > 0 ? 1 : (t0 < 0 ? -1 : 0), sq = tq > 0 ? 1 : (tq < 0 ? -1 : 0);
  if (!(std::fabs(t0) > vv)) sp = exact_triple_sign(s.V[0], s.V[1], s.V[2]);
  if (!(std::fabs(tq) > vv + wb)) {
    ExactSum<96> e;
    add_triple(e, 1.0, s.V[0], s.V[1], s.V[2]);
    for (int k = 0; k < 3; ++k) add_triple(e, -1.0, s.Q, s.V[k], s.V[k == 2 ? 0 : k + 1]);
    sq = e.sign();
  }
  if (sp != 0 && sp == sq) return;
  if (sp == 0 || sq == 0) {
    const Vec3 y = sp == 0 ? Vec3{0, 0, 0} : s.Q;
    c.d2 = 0, c.tri = y, c.seg = y;
    return;
  }
  const Vec3 y = crossing_by_longest_edge(s, 0.5);
  c.keep(on_triangle(s, y), y);
  c.seg = c.tri, c.d2 = 0;
}

// Closest points of the axis segment [0, Q] and the triangle: attained at
// an end of the segment (against the triangle), on an edge (against the
// segment), or where the segment crosses the triangle. The crossing is
// found without the triangle's plane, whose normal is noise on a sliver:
// the line through the segment meets the triangle iff the orientations of
// the line against the three edges agree in sign, and they are then the
// barycentric weights of the meeting point X (accurate even on a sliver).
// X and its nearest segment point are kept like the other candidates, so a
// rounding error can only overstate the distance. The distance is zero
// outright when the three orientations are of one sign beyond their
// rounding and X lies inside the segment beyond the rounding of that test,
// and when the candidates are apart by more than r but the segment meets
// the triangle exactly (meet_exactly: so that a zero-radius cylinder
// through a triangle overlaps it).
Closest segment_triangle(const TriSpace& s) {
  Closest c;
  const Vec3 P{0, 0, 0};
  double w[3];
  bool sure = true;
  double wb = 0;  // the sum of the three orientations' error bounds
  const double mq = max_abs(s.Q);
  for (int k = 0; k < 3; ++k) {
    const Vec3 a = s.V[k], b = s.V[k == 2 ? 0 : k + 1];
    const detail::FilterValue f = detail::triple_filter(s.Q, a, b);
    w[k] = f.value;
    wb += f.bound;
    sure = sure && std::fabs(w[k]) > f.bound;
  }
  const bool pos = w[0] >= 0 && w[1] >= 0 && w[2] >= 0, neg = w[0] <= 0 && w[1] <= 0 && w[2] <= 0;
  const double sum = w[0] + w[1] + w[2];
  if ((pos || neg) && sum != 0) {
    const double b1 = w[2] / sum, b2 = w[0] / sum;  // V0's weight is w[1] / sum
    const Vec3 x = s.V[0] + b1 * (s.V[1] - s.V[0]) + b2 * (s.V[2] - s.V[0]);
    const double xq = dot(x, s.Q), qq = dot(s.Q, s.Q), tol = 0x1p-46 * (max_abs(x) + mq) * mq;
    // The ends on opposite sides of the triangle's plane, beyond the
    // rounding of their orientations T0 (the origin) and T0 - sum (Q), as
    // in meet_exactly: X's place along a line nearly parallel to the plane
    // is ill-conditioned, and xq alone put a segment ending 1e-11 * scale
    // short of a sliver across it (regression collide_cylinder_triangle/0013).
    const auto across = [&] {
      const detail::FilterValue f0 = detail::triple_filter(s.V[0], s.V[1], s.V[2]);
      const double tq = f0.value - sum;
      return std::fabs(f0.value) > f0.bound && std::fabs(tq) > f0.bound + wb && (f0.value > 0) != (tq > 0);
    };
    if (sure && xq > tol && xq < qq - tol && across()) {
      // The meeting point itself, accurately even on a sliver (where the
      // barycentric weights lose digits to their small sum).
      const Vec3 y = crossing_by_longest_edge(s, xq / qq);
      c.d2 = 0, c.tri = y, c.seg = y;
      return c;
    }
    c.keep(x, on_segment(P, s.Q, x));
  }
  c.keep(on_triangle(s, P), P);
  c.keep(on_triangle(s, s.Q), s.Q);
  for (int k = 0; k < 3; ++k) segment_segment(s.V[k], s.V[k == 2 ? 0 : k + 1], P, s.Q, c);
  // The candidates are apart by more than r, but they are rounded: does
  // the segment meet the triangle exactly? (A zero-radius cylinder through
  // a triangle overlaps it however the rounding falls.)
  if (!(detail::safe_length(c.tri - c.seg) <= s.r)) meet_exactly(s, w, c);
  return c;
}

// The point of the triangle's section by the plane through C normal to u
// nearest C (as an offset from C), and its distance; infinite when the
// plane misses the triangle. The section is the triangle itself when it
// lies in the plane, else the segment spanned by the vertices on the plane
// and the crossings of the edges whose ends lie strictly on both sides.
struct SectionNearest {
  Vec3 y{0, 0, 0};
  double dist = kInf;
  bool inner = false;  // the whole triangle on the cylinder's side of the plane (or in it)
};

SectionNearest section_nearest(const TriSpace& s, Vec3 C, double sg) {
  SectionNearest out;
  Vec3 v[3];
  double h[3];
  for (int k = 0; k < 3; ++k) v[k] = s.V[k] - C, h[k] = dot(v[k], s.u);
  out.inner = sg * h[0] <= 0 && sg * h[1] <= 0 && sg * h[2] <= 0;
  if (h[0] == 0 && h[1] == 0 && h[2] == 0) {
    TriSpace local = s;
    for (int k = 0; k < 3; ++k) local.V[k] = v[k];
    out.y = on_triangle(local, Vec3{0, 0, 0});
    out.dist = detail::safe_length(out.y);
    return out;
  }
  Vec3 x[6];
  int n = 0;
  for (int k = 0; k < 3; ++k) {
    if (h[k] == 0) x[n++] = v[k];
    const int l = k == 2 ? 0 : k + 1;
    if ((h[k] < 0 && h[l] > 0) || (h[k] > 0 && h[l] < 0)) {
      const double lambda = h[k] / (h[k] - h[l]);
      x[n++] = lambda <= 0.5 ? v[k] + lambda * (v[l] - v[k]) : v[l] - (1 - lambda) * (v[l] - v[k]);
    }
  }
  if (n == 0) return out;
  Closest c;
  const Vec3 O{0, 0, 0};
  for (int i = 0; i < n; ++i) c.keep(x[i], O);
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j) c.keep(on_segment(x[i], x[j], O), O);
  out.y = c.tri;
  out.dist = detail::safe_length(c.tri);
  return out;
}

struct Verdict {
  bool hit = false;
  Vec3 point;  // offset from p, in both shapes (to rounding)
};

Verdict decide(const TriSpace& s, detail::TriCapStage stage) {
  Verdict out;
  // The boxes around the bounding capsule and the triangle are apart: no
  // overlap (a cheap reject for the common far-apart pair).
  for (int i = 0; i < 3; ++i) {
    const double lo = std::min(std::min(s.V[0][i], s.V[1][i]), s.V[2][i]);
    const double hi = std::max(std::max(s.V[0][i], s.V[1][i]), s.V[2][i]);
    if (lo > std::max(0.0, s.Q[i]) + s.r || hi < std::min(0.0, s.Q[i]) - s.r) return out;
  }
  const Closest k = segment_triangle(s);
  if (!(detail::safe_length(k.tri - k.seg) <= s.r)) return out;  // the bounding capsule misses
  // The closed slab, to the rounding of z (Ptri's axial coordinate, from
  // an offset of size |Ptri|) and of len: beyond it by less, Ptri is on the
  // cap plane within r of the cap centre, so in the cylinder to rounding.
  const double z = dot(k.tri, s.u), zr = 0x1p-49 * (max_abs(k.tri) + s.len);
  if (z >= -zr && z <= s.len + zr) {
    out.hit = true;
    out.point = k.tri;
    return out;
  }
  if (stage == detail::TriCapStage::None) return out;
  const Vec3 C = z > s.len ? s.Q : Vec3{0, 0, 0};
  const SectionNearest sn = section_nearest(s, C, z > s.len ? 1.0 : -1.0);
  if (sn.inner) {
    // The heights from C put the whole triangle on the cylinder's side of
    // the cap plane (or in it), so Ptri was beyond it only by the rounding
    // of its axial coordinate: it is in the slab (to rounding), and in the
    // cylinder.
    out.hit = true;
    out.point = k.tri;
    return out;
  }
  if (!(sn.dist <= s.r)) return out;
  out.hit = true;
  out.point = C + sn.y;
  return out;
}

// Overlap of the shapes along unit n (from the cylinder towards the
// triangle): h_cyl(n) + h_tri(-n).
double overlap_along(const TriSpace& s, Vec3 n) {
  const double nu = dot(n, s.u);
  const double h_cyl = std::max(0.0, dot(n, s.Q)) + s.r * detail::safe_length(n - nu * s.u);
  const double lo = std::min(std::min(dot(n, s.V[0]), dot(n, s.V[1])), dot(n, s.V[2]));
  return h_cyl - lo;
}

struct Best {
  const TriSpace* s;
  double o = kInf;
  Vec3 n{0, 0, 1};
  void consider(Vec3 cand) {
    const double o2 = overlap_along(*s, cand);
    if (o2 < o) o = o2, n = cand;
  }
  // w and -w, w first, after orienting w by the first non-zero of the keys
  // (exact signs of dot products with offsets of the scene, so that a
  // reflection reflects the choice; a cross product alone would flip it).
  void both(Vec3 w, const Key* keys, int nk) {
    orient_by(w, keys, nk);
    consider(w);
    consider(-w);
  }
};

Contact collide_scaled(const Cylinder& cyl, const Triangle& tri, detail::TriCapStage stage) {
  Contact out;
  const TriSpace s(cyl, tri);
  const Verdict v = decide(s, stage);
  if (!v.hit) return out;
  out.hit = true;
  out.point = cyl.p + v.point;
  Best best{&s};
  // Keys orienting a direction: towards the cap centres from the triangle,
  // then along the triangle's edges (a direction normal to all four offsets
  // is normal to a plane holding the whole scene, whose mirror pair is a
  // true tie).
  const Key keys[4] = {{s.P0, s.T[0]}, {s.Q0, s.T[0]}, {s.T[1], s.T[0]}, {s.T[2], s.T[0]}};
  best.consider(s.u);
  best.consider(-s.u);
  if (s.flat()) best.both(detail::normalized(s.nt), keys, 4);
  // Side x edge: axis x edge (the radial direction of the edge's line when
  // the edge is parallel to the axis).
  Vec3 dir[3];
  int edge[3][2];
  int ne = 0;
  for (int k = 0; k < 3; ++k) {
    const int l = k == 2 ? 0 : k + 1;
    const Vec3 e = s.V[l] - s.V[k];
    if (!(max_abs(e) > 0)) continue;
    const Vec3 eu = detail::normalized(e);
    const Vec3 x = cross(s.u, eu);
    // Towards the edge, else the third vertex, from the axis; where both
    // lie in the plane through the axis normal to the direction, the
    // edge's other end and the other cap centre (a direction normal to all
    // four offsets is normal to a plane holding the whole scene, whose
    // mirror pair is a true tie; a cross product's own sign would not
    // reflect with the scene, regression 0009).
    const Key side_keys[4] = {{s.T[k], s.P0}, {s.T[k == 0 ? 2 : k - 1], s.P0}, {s.T[l], s.P0}, {s.Q0, s.P0}};
    if (max_abs(x) > 0) best.both(detail::normalized(x), side_keys, 4);
    else best.both(detail::unit_perpendicular_part(s.V[k], s.u), side_keys, 4);
    dir[ne] = eu, edge[ne][0] = k, edge[ne][1] = l, ++ne;
  }
  // Side x vertex: the radial direction through each vertex within the best
  // overlap so far of the side, and inside the slab by as much.
  for (int k = 0; k < 3; ++k) detail::consider_side_vertex(s.V[k], s.u, s.len, s.r, best);
  // A point triangle on the axis line has no edge and no radial direction:
  // every direction across the axis is alike (the overlap is the radius,
  // often far below the overlap along the axis), so take one, oriented by
  // the vertex's offset so that a reflection of the scene reflects it
  // (open case 0001 of the fuzz smoke; a pick by any_perpendicular alone
  // is negated by some reflections: regressions 0004, 0005).
  if (ne == 0) {
    Vec3 n;
    if (!detail::radial_direction(s.V[0], s.u, n)) {
      const Key point_keys[2] = {{s.T[0], s.P0}, {s.Q0, s.P0}};
      best.both(any_perpendicular(s.u), point_keys, 2);
    }
  }
  // Rim x edge. The frame across the axis: f1 towards the vertex farthest
  // from the axis, f2 oriented by the vertices (both reflect with the scene).
  if (ne > 0) {
    detail::RimFrame fr;
    fr.u = s.u;
    fr.r = s.r;
    int far = 0;
    double far2 = -1;
    for (int k = 0; k < 3; ++k) {
      const Vec3 w = s.V[k] - dot(s.V[k], s.u) * s.u;
      const double w2 = dot(w, w);
      if (w2 > far2) far2 = w2, far = k;
    }
    // With every vertex on the axis line to rounding (no radial direction),
    // f1 is any_perpendicular's, which a reflection may negate rather than
    // reflect; oriented by the vertices it reflects (regression 0008). The
    // last key, the other cap centre, orients f2 when the whole triangle
    // lies exactly in the plane through p normal to it but the axis does
    // not (regression 0014); normal to all four offsets, the scene lies in
    // one plane and its mirror pair is a true tie.
    const Key vertex_keys[4] = {{s.T[0], s.P0}, {s.T[1], s.P0}, {s.T[2], s.P0}, {s.Q0, s.P0}};
    if (!(far2 > 0) || !detail::radial_direction(s.V[far], s.u, fr.f1)) {
      fr.f1 = any_perpendicular(s.u);
      orient_by(fr.f1, vertex_keys, 4);
    }
    fr.f2 = cross(s.u, fr.f1);
    orient_by(fr.f2, vertex_keys, 4);
    const Vec3 inner[1] = {v.point};
    const detail::RimPolytope poly{s.V, 3, edge, dir, ne, inner, 1};
    detail::search_rim_edges(fr, Vec3{0, 0, 0}, s.Q, poly, best);
  }
  out.normal = max_abs(best.n) > 0 ? detail::normalized(best.n) : Vec3{0, 0, 1};
  out.depth = std::min(std::max(best.o, 0.0), std::numeric_limits<double>::max());
  return out;
}

// --- The consistent contact -----------------------------------------------
//
// collide's normal and depth (see the header). The overlap along unit n,
//   g(n) = max(n.P, n.Q) + r |n - (n.u) u| - min_i n.V_i,
// is at least the penetration depth for every n, and the penetration depth
// is its least value, taken at a boundary point of the Minkowski difference
// with a single normal: +-u (cap x vertex), a side x vertex radial
// direction, or a normal perpendicular to an edge e (the face, side x edge,
// rim x edge). On the circle n . e = 0, g is the support function of the
// shapes' projection along e: a convex body K (the hull of the caps'
// ellipses plus the triangle's projection, a segment) that contains the
// origin, and the least g on the circle is the distance from the origin to
// K's boundary. That distance is found as EPA finds it, in the plane, as
// collide_cylinder_obb.cpp does on the box's circles: support points in the
// order of their normals span a polygon inside K, whose nearest edge's
// distance is a lower bound; the support along that edge's normal gives g
// there (an upper bound) and a new vertex. A circle is refined until
// (1 + kEps) times its lower bound reaches the least g known before the
// circles' steps, or its own least g: then it holds no direction kEps lower
// than the answer, the cap and side x vertex normals were offered exactly,
// and the depth is at most (1 + kEps) times the penetration depth (to
// rounding). A circle also stops after kMaxIter steps and once its least g
// is below 2^-40 times the scene's size (touching, to rounding). kEps =
// 1/64 and kMaxIter = 64 are detail::PlanarEpa's (detail/planar_epa.hpp).
//
// Representation: the scene is taken from the axis's midpoint (a swap of
// the caps changes no offset), each circle's frame is made from its edge's
// two ends symmetrically (the edge's direction enters only through
// products that do not see its sign; the frame's one free sign is set by
// exact signs over the edge's two ends together), and the circles do not
// see each other's results: rotating or reversing the triangle's vertices,
// or swapping the caps, gives the same circles, and a reflection of the
// scene the reflected ones, bit for bit.

// The scene as offsets from the axis's midpoint.
struct MidSpace {
  Vec3 P, Q, V[3];
  Vec3 P0, Q0, T[3];  // the points themselves (exact orientation keys)
  Vec3 u;
  double r, size;
  MidSpace(const Cylinder& cyl, const Triangle& t) : P0(cyl.p), Q0(cyl.q), T{t.a, t.b, t.c}, r(cyl.r) {
    const Vec3 mid = 0.5 * (cyl.p + cyl.q);
    P = cyl.p - mid, Q = cyl.q - mid;
    for (int k = 0; k < 3; ++k) V[k] = T[k] - mid;
    const Vec3 d = cyl.q - cyl.p;
    u = detail::UnitAndLength(max_abs(d) > 0 ? d : Vec3{0, 0, 1}).u;
    size = std::max({max_abs(P), max_abs(Q), r, max_abs(V[0]), max_abs(V[1]), max_abs(V[2])});
  }
  // The overlap along n (from the cylinder towards the triangle).
  double overlap(Vec3 n) const {
    const double h_cyl = std::max(dot(n, P), dot(n, Q)) + r * detail::safe_length(n - dot(n, u) * u);
    return h_cyl - std::min(std::min(dot(n, V[0]), dot(n, V[1])), dot(n, V[2]));
  }
};

// The sign of w . (A + B - C - D), exactly (A, B, C, D points of the
// scene): symmetric in A and B and in C and D, negated with w by a
// reflection of the scene.
int exact_sign_4(Vec3 w, Vec3 A, Vec3 B, Vec3 C, Vec3 D) {
  const detail::FilterValue f = detail::sum_difference_filter(w, A, B, C, D);
  if (std::fabs(f.value) > f.bound) return f.value > 0 ? 1 : -1;
  ExactSum<32> e;
  for (int i = 0; i < 3; ++i) {
    e.add_product(w[i], A[i]), e.add_product(w[i], B[i]);
    e.add_product(-w[i], C[i]), e.add_product(-w[i], D[i]);
  }
  return e.sign();
}

// Circle k's frame: e along edge k (either way), b2 across it towards the
// third vertex, b1 = e x b2 turned towards the axis's midpoint, else
// towards the third vertex, from the edge's midpoint (exact signs). False
// for a degenerate triangle (an edge of length 0, or the third vertex
// within 2^-30 of its offset of the edge's line): collide then takes the
// exact search. `x` is u x e up to sign (zero where u is along e), made
// from the frame.
struct EdgeFrame {
  Vec3 e, b1, b2, x;
};

// The sign of a . b, exactly.
int exact_sign_of_dot(Vec3 a, Vec3 b) {
  ExactSum<6> e;
  for (int i = 0; i < 3; ++i) e.add_product(a[i], b[i]);
  return e.sign();
}

// w (normal to the edge and to b2) turned towards the axis's midpoint, else
// towards the third vertex T_m, from the midpoint of T_k and T_l, else so
// that w . u and b2 . u have one sign (exact signs; each key symmetric in
// the caps, whose swap negates u, and in k and l): a reflection of the
// scene reflects the choice, where the cross product that made w would be
// negated instead, and a swap of the caps or of the edge's ends leaves it.
// Left as it is where all three are zero (the axis in the plane of w's
// normal, to within its rounding).
void orient_across_edge(const MidSpace& s, int k, int l, int m, Vec3 b2, Vec3& w) {
  int sg = exact_sign_4(w, s.P0, s.Q0, s.T[k], s.T[l]);
  if (sg == 0) sg = exact_sign_4(w, s.T[m], s.T[m], s.T[k], s.T[l]);
  if (sg == 0) sg = exact_sign_of_dot(w, s.u) * exact_sign_of_dot(b2, s.u);
  if (sg < 0) w = -1.0 * w;
}

bool edge_frame(const MidSpace& s, int k, EdgeFrame& f) {
  const int l = k == 2 ? 0 : k + 1, m = 3 - k - l;
  const Vec3 E = s.V[l] - s.V[k];
  if (!(max_abs(E) > 0)) return false;
  f.e = detail::normalized(E);
  const Vec3 w0 = s.V[m] - 0.5 * (s.V[k] + s.V[l]);
  if (!(max_abs(w0) > 0)) return false;
  // Below 2^-300, scaled by a power of two to magnitude about 1 (exactly),
  // so that the projections below do not underflow for a triangle far
  // smaller than the scene (its offsets subnormal).
  const Vec3 w = max_abs(w0) < 0x1p-300 ? detail::scaled_down(w0, max_abs(w0)) : w0;
  Vec3 w1 = w - dot(w, f.e) * f.e;
  // Within 2^-30 of w of the edge's line, the third vertex's offset across
  // it is mostly the rounding of the projection (a collinear triangle).
  if (!(max_abs(w1) > 0x1p-30 * max_abs(w))) return false;
  w1 = w1 - dot(w1, f.e) * f.e;
  if (!(max_abs(w1) > 0)) return false;
  f.b2 = detail::normalized(w1);
  f.b1 = cross(f.e, f.b2);
  orient_across_edge(s, k, l, m, f.b2, f.b1);
  // u x e up to sign, from the oriented frame: (-(u.b2) b1 + (u.b1) b2) /
  // its length (a reflection of the scene reflects it, as it does b1 and
  // b2; the cross product would be negated).
  const double u1 = dot(s.u, f.b1), u2 = dot(s.u, f.b2), w2 = u1 * u1 + u2 * u2;
  f.x = w2 > 0x1p-100 ? (1 / std::sqrt(w2)) * (-u2 * f.b1 + u1 * f.b2) : Vec3{0, 0, 0};
  return true;
}

// The least overlap found and its direction: consider() measures a
// direction, offer() takes one whose overlap is already known.
struct MidBest {
  const MidSpace* s;
  double o = kInf;
  Vec3 n{0, 0, 1};
  void offer(double v, Vec3 cand) {
    if (v < o) o = v, n = cand;
  }
  void consider(Vec3 cand) { offer(s->overlap(cand), cand); }
};

// The closed-form directions whose overlaps bound collide's depth from
// above bit for bit (depth_bound): +-u, and per edge +-b1 (the face's
// normal) and +-u x e. Each pair +-n from one set of dot products (the
// same bits as overlap(n) and overlap(-n): negation is exact).
void closed_forms(const MidSpace& s, const EdgeFrame* fr, MidBest& best) {
  auto both = [&](Vec3 n) {
    const double nP = dot(n, s.P), nQ = dot(n, s.Q), rim = s.r * detail::safe_length(n - dot(n, s.u) * s.u);
    const double v0 = dot(n, s.V[0]), v1 = dot(n, s.V[1]), v2 = dot(n, s.V[2]);
    best.offer(std::max(nP, nQ) + rim - std::min(std::min(v0, v1), v2), n);
    best.offer(std::max(-nP, -nQ) + rim - std::min(std::min(-v0, -v1), -v2), -1.0 * n);
  };
  both(s.u);
  for (int k = 0; k < 3; ++k) {
    both(fr[k].b1);
    if (max_abs(fr[k].x) > 0) both(fr[k].x);
  }
}

// The circle of normals perpendicular to an edge: K in the frame (b1, b2),
// and its polygon (detail/planar_epa.hpp).
class EdgeCircle {
 public:
  void init(const MidSpace& s, const EdgeFrame& f, MidBest& best) {
    f_ = &f;
    r_ = s.r;
    epa_.start(0x1p-44 * s.size * (0x1p-44 * s.size));
    near_ = 0x1p-40 * s.size;
    ru_ = {dot(s.u, f.b1), dot(s.u, f.b2), dot(s.u, f.e)};
    P_ = {dot(s.P, f.b1), dot(s.P, f.b2)}, Q_ = {dot(s.Q, f.b1), dot(s.Q, f.b2)};
    mid_ = {0.5 * (P_.x + Q_.x), 0.5 * (P_.y + Q_.y)};
    for (int i = 0; i < 3; ++i) X_[i] = {dot(s.V[i], f.b1), dot(s.V[i], f.b2)};
    // 1 / |u x b1|, 1 / |u x b2|, 1 / |u x e|, each from the other two
    // components of u (1 - u_i^2 would cancel where u is near the axis).
    auto inv = [](double a, double b) {
      const double w = a * a + b * b;
      return w > 0x1p-100 ? 1 / std::sqrt(w) : 0.0;
    };
    const double is1 = inv(ru_.ul, ru_.uj), is2 = inv(ru_.uk, ru_.uj), ise = inv(ru_.uk, ru_.ul);
    static constexpr double kN[4][2] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};
    const double fq[2] = {r_ * is1, r_ * is2};
    double low = kInf;
    Pt low_n{1, 0};
    auto axis = [&](int q) {
      const double c = kN[q][0], sn = kN[q][1];
      const double t = c * ru_.uk + sn * ru_.ul;
      // The cap n . u picks; where n . u = 0 the side's segment lies along
      // the tangent, and its ends go behind and ahead (as the box's).
      const bool q_behind = -sn * Q_.x + c * Q_.y < -sn * P_.x + c * P_.y;
      const Pt& Xb = t > 0 ? Q_ : (t < 0 ? P_ : (q_behind ? Q_ : P_));
      const Pt& Xa = t > 0 ? Q_ : (t < 0 ? P_ : (q_behind ? P_ : Q_));
      const Pt w = ru_.scaled(c, sn, fq[q & 1]);
      // The triangle's support set along n: its vertices within `near_` of
      // the least n . X (the whole triangle along its face normal, where
      // rounding alone separates them), the ends along the tangent.
      int ib, ia;
      tri_ends(c, sn, ib, ia);
      epa_.add({Xb.x + w.x - X_[ib].x, Xb.y + w.y - X_[ib].y});
      epa_.add({Xa.x + w.x - X_[ia].x, Xa.y + w.y - X_[ia].y});
      const Pt pa = epa_.last();
      const double g = c * pa.x + sn * pa.y;
      if (g < low) low = g, low_n = {c, sn};
    };
    // Across u: m = (-u2, u1) / |.| and -m.
    const bool split = ise > 0 && ru_.uk != 0 && ru_.ul != 0;
    const double mk = -ru_.ul * ise, ml = ru_.uk * ise;
    auto across = [&](double sg) {
      const double vk = sg * mk, vl = sg * ml;
      const Pt w = ru_.scaled(vk, vl, r_);  // |n x u| = 1
      int ib, ia;
      tri_ends(vk, vl, ib, ia);
      // Both caps' points, with the triangle's ends behind and ahead.
      const Pt p = {P_.x + w.x, P_.y + w.y}, pq = {Q_.x + w.x, Q_.y + w.y};
      const bool p_first = -vl * p.x + vk * p.y <= -vl * pq.x + vk * pq.y;
      const Pt& first = p_first ? p : pq;
      const Pt& second = p_first ? pq : p;
      epa_.add({first.x - X_[ib].x, first.y - X_[ib].y});
      epa_.add({second.x - X_[ia].x, second.y - X_[ia].y});
      const double g = std::max(vk * p.x + vl * p.y, vk * pq.x + vl * pq.y) -
                       std::min(std::min(vk * X_[0].x + vl * X_[0].y, vk * X_[1].x + vl * X_[1].y),
                                vk * X_[2].x + vl * X_[2].y);
      if (g < low) low = g, low_n = {vk, vl};
    };
    detail::starting_directions(split, mk, ml, axis, across);
    if (low < best.o) offer(best, low_n.x, low_n.y, low);
    epa_.close();
  }

  // EPA steps until (1 + kEps) times the nearest edge's distance reaches
  // the least of `bound` and this circle's own least overlap (offered to
  // `best`).
  void refine(double bound, double floor, MidBest& best) {
    const detail::PlanarEpa::Least r = epa_.refine(bound, floor, [&](double c, double sn) { return support(c, sn); });
    if (r.found) offer(best, r.c, r.sn, r.o);
  }

 private:
  using Pt = detail::PlanarPt;

  // The triangle's vertices at the ends (behind, ahead along the tangent
  // (-sn, c)) of its support set along (c, sn) in K, -X: the vertices
  // within `near_` of the least (c, sn) . X.
  void tri_ends(double c, double sn, int& ib, int& ia) const {
    double v[3];
    for (int i = 0; i < 3; ++i) v[i] = c * X_[i].x + sn * X_[i].y;
    const double lo = std::min(std::min(v[0], v[1]), v[2]) + near_;
    ends(c, sn, [&](int i) { return v[i] <= lo; }, ib, ia);
  }
  // Among the vertices `in` selects, the ends along the tangent (-sn, c)
  // of K's points -X_i: the least and the greatest tangent coordinate, a
  // tie decided by the vertices' coordinates (their values, not their
  // order: the vertices' order is the triangle's representation).
  template <class In>
  void ends(double c, double sn, In&& in, int& ib, int& ia) const {
    auto before = [&](int i, double ti, int j, double tj) {
      return ti < tj || (ti == tj && (X_[i].x < X_[j].x || (X_[i].x == X_[j].x && X_[i].y < X_[j].y)));
    };
    double tb = 0, ta = 0;
    ib = ia = -1;
    for (int i = 0; i < 3; ++i) {
      if (!in(i)) continue;
      const double t = sn * X_[i].x - c * X_[i].y;  // the tangent coordinate of -X_i
      if (ib < 0 || before(i, t, ib, tb)) tb = t, ib = i;
      if (ia < 0 || before(ia, ta, i, t)) ta = t, ia = i;
    }
  }
  // K's support point along any unit (c, sn). Where a support set is a
  // segment (n . u = 0: the side; vertices of the triangle at one least
  // value) its midpoint, which a reflection or a swap of the caps or of the
  // vertices maps to itself.
  Pt support(double c, double sn) const {
    const double t = c * ru_.uk + sn * ru_.ul, t1 = c * ru_.ul - sn * ru_.uk;
    const double w = ru_.uj * ru_.uj + t1 * t1;
    const double f = w > 0x1p-100 ? r_ / std::sqrt(w) : 0.0;
    const Pt rw = ru_.rim(c, sn, t1);
    const Pt& X = t > 0 ? Q_ : (t < 0 ? P_ : mid_);
    double v[3];
    for (int i = 0; i < 3; ++i) v[i] = c * X_[i].x + sn * X_[i].y;
    const double lo = std::min(std::min(v[0], v[1]), v[2]);
    int ib, ia;
    ends(c, sn, [&](int i) { return v[i] == lo; }, ib, ia);
    const double tx = 0.5 * (X_[ib].x + X_[ia].x), ty = 0.5 * (X_[ib].y + X_[ia].y);
    return {X.x + f * rw.x - tx, X.y + f * rw.y - ty};
  }
  void offer(MidBest& best, double c, double sn, double g) const { best.offer(g, c * f_->b1 + sn * f_->b2); }

  const EdgeFrame* f_ = nullptr;
  double r_ = 0, near_ = 0;
  detail::RimShare ru_;  // u in the frame (b1, b2, e)
  Pt P_{0, 0}, Q_{0, 0}, mid_{0, 0}, X_[3];
  detail::PlanarEpa epa_;
};

// The consistent contact of a cylinder and a proper triangle (all three
// edge frames made), the verdict's point given.
Contact consistent_contact(const MidSpace& s, const EdgeFrame* fr, bool refine) {
  Contact out;
  MidBest best{&s};
  closed_forms(s, fr, best);
  const double cf = best.o;
  const Vec3 cf_n = best.n;
  // The circles whose edge can hold the penetration depth's normal on its
  // rim x edge patch: a minimal translation along such a normal moves the
  // triangle by the penetration depth (<= best.o) to touch a rim point
  // with a point of the edge, so the edge passes within best.o of that
  // rim's circle; an edge farther from both has its circle skipped (the
  // face and side x edge normals on it were offered in closed form).
  // Bounds of that distance from below: the edge's gap to the cap plane
  // and the gap of its distance from the axis to r (convex along the
  // edge: its range is [the closest approach, the larger end]), computed
  // from the edge's midpoint and half, so that the edge's two ends enter
  // alike.
  EdgeCircle circle[3];
  bool live[3];
  {
    const double o = best.o;
    for (int k = 0; k < 3; ++k) {
      const int l = k == 2 ? 0 : k + 1;
      const Vec3 mid = 0.5 * (s.V[k] + s.V[l]), half = 0.5 * (s.V[l] - s.V[k]);
      const Vec3 wm = mid - dot(mid, s.u) * s.u, wh = half - dot(half, s.u) * s.u;
      const double wh2 = dot(wh, wh);
      const double tc = wh2 > 0 ? std::clamp(-dot(wm, wh) / wh2, -1.0, 1.0) : 0.0;
      const Vec3 wc = wm + tc * wh;
      const double rmin = std::sqrt(dot(wc, wc)), rmax = std::sqrt(std::max(dot(wm - wh, wm - wh), dot(wm + wh, wm + wh)));
      const double rgap = rmin > s.r ? rmin - s.r : (rmax < s.r ? s.r - rmax : 0.0);
      bool near = false;
      for (int cap = 0; cap < 2; ++cap) {
        const Vec3& C = cap ? s.Q : s.P;
        const double sg = cap ? 1.0 : -1.0;
        const double hk = sg * dot(s.V[k] - C, s.u), hl = sg * dot(s.V[l] - C, s.u);
        const double hlo = std::min(hk, hl), hhi = std::max(hk, hl);
        const double hgap = hlo > 0 ? hlo : (hhi < 0 ? -hhi : 0.0);
        near = near || std::max(hgap, rgap) <= o;
      }
      live[k] = near;
      if (near) circle[k].init(s, fr[k], best);
    }
  }
  // Side x vertex: the radial direction of each vertex within best.o of the
  // side and inside the slab by as much (a minimal translation along it
  // moves the vertex onto the side), measured from the axis's midpoint; a
  // vertex within 2^-44 times the scene's size of the axis line has no
  // radial direction but rounding noise.
  {
    const double tiny2 = 0x1p-44 * s.size * (0x1p-44 * s.size);
    const double o = best.o, half = 0.5 * detail::safe_length(s.Q - s.P), hi = s.r + o, lo = std::max(s.r - o, 0.0);
    for (int k = 0; k < 3; ++k) {
      const double z = dot(s.V[k], s.u);
      const Vec3 wr = s.V[k] - z * s.u;
      const double rho2 = dot(wr, wr);
      if (std::fabs(z) <= half + o && rho2 <= hi * hi && rho2 >= lo * lo && rho2 > tiny2)
        best.consider((1 / std::sqrt(rho2)) * wr);
    }
  }
  const double bound = best.o;
  const double floor = 0x1p-40 * s.size;
  if (refine)
    for (int k = 0; k < 3; ++k)
      if (live[k]) circle[k].refine(bound, floor, best);
  const Vec3 nb = max_abs(best.n) > 0 ? detail::normalized(best.n) : Vec3{0, 0, 1};
  const double d = s.overlap(nb);
  // Never above the closed forms' least overlap (depth_bound), measured
  // the same way.
  const bool keep = d <= cf;
  out.normal = keep ? nb : cf_n;
  out.depth = std::min(std::max(keep ? d : cf, 0.0), std::numeric_limits<double>::max());
  return out;
}

Contact collide_consistent_scaled(const Cylinder& cyl, const Triangle& tri, bool refine) {
  const TriSpace ts(cyl, tri);
  const Verdict v = decide(ts, detail::TriCapStage::Exact);
  if (!v.hit) return Contact{};
  const MidSpace s(cyl, tri);
  EdgeFrame fr[3];
  for (int k = 0; k < 3; ++k)
    if (!edge_frame(s, k, fr[k])) return collide_scaled(cyl, tri, detail::TriCapStage::Exact);
  Contact out = consistent_contact(s, fr, refine);
  out.hit = true;
  out.point = cyl.p + v.point;
  return out;
}

}  // namespace

namespace detail {

bool overlap_with_stage(const Cylinder& cyl, const Triangle& tri, TriCapStage stage) {
  return overlap_rescaled(cyl, tri, [&](const Cylinder& c, const Triangle& t) { return decide(TriSpace(c, t), stage).hit; });
}

bool depth_bound(const Cylinder& cyl, const Triangle& tri, double* bound) {
  if (!is_valid(cyl) || !is_valid(tri)) return false;
  const SceneScale sc(std::max(largest(cyl), largest(tri)));
  {
    // A proper triangle: the consistent contact's closed forms, which its
    // depth never exceeds (consistent_contact).
    const MidSpace ms(sc.in(cyl), sc.in(tri));
    EdgeFrame fr[3];
    if (edge_frame(ms, 0, fr[0]) && edge_frame(ms, 1, fr[1]) && edge_frame(ms, 2, fr[2])) {
      MidBest best{&ms};
      closed_forms(ms, fr, best);
      const double o = std::min(std::max(best.o, 0.0), std::numeric_limits<double>::max());
      *bound = std::min(sc.out(o), std::numeric_limits<double>::max());
      return true;
    }
  }
  // A degenerate triangle: the exact search's candidates (collide_scaled).
  const TriSpace s(sc.in(cyl), sc.in(tri));
  double o = std::min(overlap_along(s, s.u), overlap_along(s, -s.u));
  auto both = [&](Vec3 w) { o = std::min(o, std::min(overlap_along(s, w), overlap_along(s, -w))); };
  if (s.flat()) both(detail::normalized(s.nt));
  for (int k = 0; k < 3; ++k) {  // side x edge, as collide_scaled
    const Vec3 e = s.V[k == 2 ? 0 : k + 1] - s.V[k];
    if (!(max_abs(e) > 0)) continue;
    const Vec3 x = cross(s.u, detail::normalized(e));
    both(max_abs(x) > 0 ? detail::normalized(x) : detail::unit_perpendicular_part(s.V[k], s.u));
  }
  o = std::min(std::max(o, 0.0), std::numeric_limits<double>::max());
  *bound = std::min(sc.out(o), std::numeric_limits<double>::max());
  return true;
}

Contact collide_with_stage(const Cylinder& cyl, const Triangle& tri, TriCapStage stage) {
  return collide_rescaled(cyl, tri, [&](const Cylinder& c, const Triangle& t) { return collide_scaled(c, t, stage); });
}

Contact collide_consistent(const Cylinder& cyl, const Triangle& tri, bool refine) {
  return collide_rescaled(cyl, tri,
                          [&](const Cylinder& c, const Triangle& t) { return collide_consistent_scaled(c, t, refine); });
}

}  // namespace detail

bool overlap(const Cylinder& cyl, const Triangle& tri) {
  return detail::overlap_with_stage(cyl, tri, detail::TriCapStage::Exact);
}

Contact collide(const Cylinder& cyl, const Triangle& tri) { return detail::collide_consistent(cyl, tri); }

}  // namespace geomcheck
