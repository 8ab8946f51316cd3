#include "geomcheck/collide_cylinder_triangle.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "geomcheck/detail/frame.hpp"
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

}  // namespace

namespace detail {

bool overlap_with_stage(const Cylinder& cyl, const Triangle& tri, TriCapStage stage) {
  return overlap_rescaled(cyl, tri, [&](const Cylinder& c, const Triangle& t) { return decide(TriSpace(c, t), stage).hit; });
}

bool depth_bound(const Cylinder& cyl, const Triangle& tri, double* bound) {
  if (!is_valid(cyl) || !is_valid(tri)) return false;
  const SceneScale sc(std::max(largest(cyl), largest(tri)));
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

}  // namespace detail

bool overlap(const Cylinder& cyl, const Triangle& tri) {
  return detail::overlap_with_stage(cyl, tri, detail::TriCapStage::Exact);
}

Contact collide(const Cylinder& cyl, const Triangle& tri) {
  return detail::collide_with_stage(cyl, tri, detail::TriCapStage::Exact);
}

}  // namespace geomcheck
