#include "geomcheck/collide_cylinder_obb.hpp"
#include "geomcheck/collide_many.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <utility>

#include "geomcheck/detail/frame.hpp"
#include "geomcheck/detail/obb_stages.hpp"
#include "geomcheck/detail/planar_epa.hpp"
#include "geomcheck/detail/rim_edge.hpp"

namespace geomcheck {

namespace {

// a + b + c, summed in the order of their values (magnitude, then sign):
// the same bits for any order of the arguments. Sorted on integer keys by
// masks (random signs would mispredict branches).
inline double sum3(double a, double b, double c) {
  auto bits = [](double x) {
    std::uint64_t v;
    std::memcpy(&v, &x, sizeof v);
    return v;
  };
  auto key = [](std::uint64_t v) { return ((v & 0x7fffffffffffffffULL) << 1) | (~v >> 63); };
  std::uint64_t va = bits(a), vb = bits(b), vc = bits(c);
  std::uint64_t ka = key(va), kb = key(vb), kc = key(vc);
  auto order = [](std::uint64_t& k1, std::uint64_t& v1, std::uint64_t& k2, std::uint64_t& v2) {
    const std::uint64_t m = 0 - std::uint64_t(k2 < k1);  // all ones where they swap
    const std::uint64_t dk = (k1 ^ k2) & m, dv = (v1 ^ v2) & m;
    k1 ^= dk, k2 ^= dk, v1 ^= dv, v2 ^= dv;
  };
  order(ka, va, kb, vb);
  order(kb, vb, kc, vc);
  order(ka, va, kb, vb);
  double x, y, z;
  std::memcpy(&x, &va, sizeof x);
  std::memcpy(&y, &vb, sizeof y);
  std::memcpy(&z, &vc, sizeof z);
  return (x + y) + z;
}
inline double dot3(Vec3 a, Vec3 b) { return sum3(a.x * b.x, a.y * b.y, a.z * b.z); }

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
    // |d| from the squares summed in a fixed order of their values, so that
    // a permutation or a reflection of the box's axes gives the same bits
    // (as every other box-space value; collide's symmetry checks hold it).
    const double l2 = sum3(d.x * d.x, d.y * d.y, d.z * d.z);
    const detail::UnitAndLength ul(max_abs(d) > 0 ? d : Vec3{0, 0, 1});
    const bool plain = l2 > detail::kSafeLo * detail::kSafeLo && l2 < detail::kSafeHi * detail::kSafeHi;
    const double dl = plain ? std::sqrt(l2) : ul.len;
    u = plain ? (1.0 / dl) * d : ul.u;
    len = max_abs(d) > 0 ? (ex == 1 ? dl : std::ldexp(dl, ex - 1)) : 0.0;
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

// The least overlap found and its direction: consider() measures a
// direction, offer() takes one whose overlap is already known.
struct Best {
  const BoxSpace* s;
  double o = std::numeric_limits<double>::infinity();
  Vec3 n{0, 0, 1};
  void offer(double v, Vec3 cand) {
    if (v < o) o = v, n = cand;
  }
  void consider(Vec3 cand) { offer(overlap_along(*s, cand), cand); }
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

// --- The consistent contact -----------------------------------------------
//
// collide's normal and depth (see the header). The overlap along unit n,
//   g(n) = max(n.P, n.Q) + r |n - (n.u) u| + e . |n|
// (box space, the box centred at the origin), is at least the penetration
// depth for every n, and the penetration depth is its least value, taken at
// a boundary point of the Minkowski difference with a single normal: +-u
// (cap x vertex), a side x vertex radial direction, or a normal with n_j = 0
// for some box axis j (face, side x edge, rim x edge). On the circle
// n_j = 0, g is the support function of the shapes' projection along a_j:
// a convex body K_j (a rectangle plus the hull of the caps' two ellipses)
// that contains the origin, and the least g on the circle is the distance
// from the origin to K_j's boundary. That distance is found as EPA finds it,
// in the plane: support points in the order of their normals span a polygon
// inside K_j, whose nearest edge's distance is a lower bound; the support
// along that edge's normal gives g there (an upper bound) and a new vertex.
// A circle is refined until (1 + kEps) times its lower bound reaches the
// least g known before the circles' steps, or its own least g: then it
// holds no direction kEps lower than the answer, the cap and side x vertex
// normals were offered exactly, and the depth is at most (1 + kEps) times
// the penetration depth (to rounding). A circle also stops after kMaxIter
// steps (met only by very shallow contacts, whose polygon must close in on
// a sharply curved boundary) and once its least g is below 2^-40 times the
// scene's size (touching, to rounding: its lower bound would never leave
// zero). kEps = 1/64 and kMaxIter = 64 are detail::PlanarEpa's. The
// penetration depth itself is penetration(Cylinder, Obb).

// Circle j's body K_j and its polygon (detail/planar_epa.hpp); coordinates
// (k, l) = (j + 1, j + 2).
class Circle {
 public:
  // The support points, counter-clockwise: along each axis direction both
  // ends of its support set (the rectangle edge, with the rim point of the
  // cap its side picks), and along the two directions across u both ends of
  // theirs (the side's projection, from either cap); the least overlap
  // along these directions is offered. Choices are selections rather than
  // branches where they depend on the data (a branch on random data is
  // mispredicted about half the time).
  // `is[i]` = 1 / |u x a_i| (0 where u is along a_i to rounding).
  void init(const BoxSpace& s, int j, const double is[3], double size, Best& best) {
    s_ = &s;
    epa_.start(0x1p-44 * size * (0x1p-44 * size));
    k_ = (j + 1) % 3, l_ = (j + 2) % 3;
    ru_ = {s.u[k_], s.u[l_], s.u[j]};
    ek_ = s.e[k_], el_ = s.e[l_];
    midk_ = 0.5 * (s.P[k_] + s.Q[k_]), midl_ = 0.5 * (s.P[l_] + s.Q[l_]);
    // Axis direction q (counter-clockwise from (1, 0)): its normal, the
    // rectangle corners behind and ahead of it along the boundary.
    static constexpr double kN[4][2] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};
    static constexpr double kBehind[4][2] = {{1, -1}, {1, 1}, {-1, 1}, {-1, -1}};
    static constexpr double kAhead[4][2] = {{1, 1}, {-1, 1}, {-1, -1}, {1, -1}};
    const double fq[2] = {s.r * is[k_], s.r * is[l_]};
    double low = std::numeric_limits<double>::infinity();
    int low_q = 0;  // 0..3 an axis, 4 or 5 the direction across u (+ or -)
    auto axis = [&](int q) {
      const double c = kN[q][0], sn = kN[q][1];
      const double t = c * ru_.uk + sn * ru_.ul;
      // The cap: the one n . u picks; where n . u = 0 the side's segment
      // lies along the rectangle edge, and its ends go with the corners
      // (the cap behind along the tangent (-sn, c) with the corner behind).
      const bool q_behind = -sn * s.Q[k_] + c * s.Q[l_] < -sn * s.P[k_] + c * s.P[l_];
      const Vec3& Xb = t > 0 ? s.Q : (t < 0 ? s.P : (q_behind ? s.Q : s.P));
      const Vec3& Xa = t > 0 ? s.Q : (t < 0 ? s.P : (q_behind ? s.P : s.Q));
      const double f = fq[q & 1];
      const detail::PlanarPt w = ru_.scaled(c, sn, f);
      epa_.add(support(Xb, kBehind[q][0], kBehind[q][1], w));
      epa_.add(support(Xa, kAhead[q][0], kAhead[q][1], w));
      const detail::PlanarPt pa = epa_.last();
      const double g = c * pa.x + sn * pa.y;
      const bool lt = g < low;
      low = lt ? g : low;
      low_q = lt ? q : low_q;
    };
    // Across u: m = (u x a_j) / |u x a_j| = (-ul, uk) / |.|, in the
    // quadrant qm (strictly, when uk and ul are not zero); -m in qm + 2.
    const bool split = is[j] > 0 && ru_.uk != 0 && ru_.ul != 0;
    const double mk = -ru_.ul * is[j], ml = ru_.uk * is[j];
    auto across = [&](double sg) {
      const double vk = sg * mk, vl = sg * ml;
      const double sk = vk > 0 ? 1.0 : -1.0, sl = vl > 0 ? 1.0 : -1.0;
      const detail::PlanarPt w = ru_.scaled(vk, vl, s.r);  // |n x u| = 1
      const detail::PlanarPt p = support(s.P, sk, sl, w), pq = support(s.Q, sk, sl, w);
      const bool p_first = -vl * p.x + vk * p.y <= -vl * pq.x + vk * pq.y;
      epa_.add(p_first ? p : pq);
      epa_.add(p_first ? pq : p);
      const double g = std::max(vk * p.x + vl * p.y, vk * pq.x + vl * pq.y);
      const bool lt = g < low;
      low = lt ? g : low;
      low_q = lt ? (sg > 0 ? 4 : 5) : low_q;
    };
    detail::starting_directions(split, mk, ml, axis, across);
    if (low < best.o) {
      const double sg = low_q == 4 ? 1.0 : -1.0;
      offer(best, low_q < 4 ? kN[low_q][0] : sg * mk, low_q < 4 ? kN[low_q][1] : sg * ml, low);
    }
    epa_.close();
  }

  // EPA steps until (1 + kEps) times the nearest edge's distance reaches
  // the least of `bound` and this circle's own least overlap (offered to
  // `best`). The circles do not see each other's results, so that their
  // order (the box's axes' order) changes no answer.
  void refine(double bound, double floor, Best& best) {
    const detail::PlanarEpa::Least r = epa_.refine(bound, floor, [&](double c, double sn) { return support(c, sn); });
    if (r.found) offer(best, r.c, r.sn, r.o);
  }

 private:
  // K_j's support point with the cap X, the rectangle corner (sk ek, sl el)
  // and the rim's share w (times r / |n x u|) given.
  detail::PlanarPt support(const Vec3& X, double sk, double sl, detail::PlanarPt w) const {
    return {X[k_] + sk * ek_ + w.x, X[l_] + sl * el_ + w.y};
  }
  // K_j's support point along any unit (c, sn). Where the support set is a
  // segment (n . u = 0: the side; c or sn = 0: a rectangle edge) its
  // midpoint, which a reflection or a swap of the caps maps to itself.
  detail::PlanarPt support(double c, double sn) const {
    const double t = c * ru_.uk + sn * ru_.ul, t1 = c * ru_.ul - sn * ru_.uk;
    const double w = ru_.uj * ru_.uj + t1 * t1;
    const double f = w > 0x1p-100 ? s_->r / std::sqrt(w) : 0.0;
    const detail::PlanarPt rw = ru_.rim(c, sn, t1);
    const double sk = c > 0 ? 1.0 : (c < 0 ? -1.0 : 0.0), sl = sn > 0 ? 1.0 : (sn < 0 ? -1.0 : 0.0);
    const double xk = t > 0 ? s_->Q[k_] : (t < 0 ? s_->P[k_] : midk_);
    const double xl = t > 0 ? s_->Q[l_] : (t < 0 ? s_->P[l_] : midl_);
    return {xk + sk * ek_ + f * rw.x, xl + sl * el_ + f * rw.y};
  }
  void offer(Best& best, double c, double sn, double g) const {
    Vec3 n{0, 0, 0};
    n[k_] = c, n[l_] = sn;
    best.offer(g, n);
  }

  const BoxSpace* s_ = nullptr;
  int k_ = 1, l_ = 2;
  detail::RimShare ru_;
  double ek_ = 0, el_ = 0, midk_ = 0, midl_ = 0;
  detail::PlanarEpa epa_;
};

Contact collide_consistent_scaled(const Cylinder& cyl, const Obb& box, bool refine) {
  Contact out;
  const BoxSpace s(cyl, box);
  const Verdict v = decide(s, detail::ObbCapStage::Exact);
  if (!v.hit) return out;
  out.hit = true;
  out.point = box.c + s.from_box(v.point);
  Best best{&s};
  const Vec3& u = s.u;
  // +-u (cap x vertex).
  // (Sums over the box axes are sum3's, the same bits in any axis order.)
  const double E = sum3(s.e.x * std::fabs(u.x), s.e.y * std::fabs(u.y), s.e.z * std::fabs(u.z));
  const double uP = dot3(u, s.P), uQ = dot3(u, s.Q);
  best.offer(std::max(uP, uQ) + E, u);
  best.offer(E - std::min(uP, uQ), -1.0 * u);
  // 1 / |u x a_i|, from the other two components (1 - u_i^2 would cancel
  // to rounding noise where u is near a_i).
  double is[3];
  for (int i = 0; i < 3; ++i) {
    const double a = u[(i + 1) % 3], b = u[(i + 2) % 3];
    const double w = a * a + b * b;
    is[i] = w > 0x1p-100 ? 1 / std::sqrt(w) : 0.0;
  }
  // The scene's size in box space (a maximum: the same in any axis order).
  const double size = std::max({max_abs(s.P), max_abs(s.Q), s.r, max_abs(s.e)});
  Circle circle[3];
  for (int j = 0; j < 3; ++j) circle[j].init(s, j, is, size, best);
  // Side x vertex: the radial direction n of a vertex within best.o of the
  // side and inside the slab by as much (a minimal translation along it
  // moves the vertex onto the side); the overlap along it (n . u = 0) is
  // n . P + r + e . |n|.
  // Side x vertex: the radial direction n of each vertex within best.o of
  // the side and inside the slab by as much (a minimal translation along n
  // moves that vertex onto the side), and the overlap along it, with n as
  // it is (n . u is 0 but for rounding, which is not small for a vertex near
  // the axis line). Measured from the axis's midpoint, so that a swap of
  // the caps changes no bit; a vertex within 2^-44 times the scene's size of
  // the axis line has no radial direction but rounding noise (the bound is
  // the scene's, so that a scaled scene decides alike).
  {
    const double tiny2 = 0x1p-44 * size * (0x1p-44 * size);
    const Vec3 mid = 0.5 * (s.P + s.Q);
    const double o = best.o, half = 0.5 * s.len, hi = s.r + o, lo = std::max(s.r - o, 0.0);
    Vec3 wr[8];
    double rho2[8];
    unsigned near = 0;
    for (int q = 0; q < 8; ++q) {
      const Vec3 w = s.vertex(q) - mid;
      const double z = dot3(w, u);
      wr[q] = w - z * u;
      rho2[q] = dot3(wr[q], wr[q]);
      const bool in = (std::fabs(z) <= half + o) & (rho2[q] <= hi * hi) & (rho2[q] >= lo * lo) & (rho2[q] > tiny2);
      near |= unsigned(in) << q;
    }
    for (; near; near &= near - 1) {
      const int q = __builtin_ctz(near);
      const Vec3 n = (1 / std::sqrt(rho2[q])) * wr[q];
      const double nu = dot3(n, u);
      best.offer(dot3(n, mid) + half * std::fabs(nu) + s.r * std::sqrt(std::max(1 - nu * nu, 0.0)) +
                     sum3(s.e.x * std::fabs(n.x), s.e.y * std::fabs(n.y), s.e.z * std::fabs(n.z)),
                 n);
    }
  }
  const double bound = best.o;
  // Touching, to rounding: a lower bound that never leaves zero would take
  // every step; an overlap of 2^-40 times the scene's size is answer enough.
  const double floor = 0x1p-40 * size;
  if (refine)
    for (int j = 0; j < 3; ++j) circle[j].refine(bound, floor, best);
  const Vec3 nb = max_abs(best.n) > 0 ? detail::normalized(best.n) : Vec3{0, 0, 1};
  const Vec3 n = s.from_box(nb);
  out.normal = max_abs(n) > 0 ? detail::normalized(n) : Vec3{0, 0, 1};
  out.depth = std::min(std::max(overlap_along(s, nb), 0.0), std::numeric_limits<double>::max());
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

Contact collide_consistent(const Cylinder& cyl, const Obb& box, bool refine) {
  return collide_rescaled(
      cyl, box, [&](const Cylinder& c, const Obb& b) { return collide_consistent_scaled(c, in_contract(b), refine); });
}

}  // namespace detail

bool overlap(const Cylinder& cyl, const Obb& box) {
  return detail::overlap_with_stage(cyl, box, detail::ObbCapStage::Exact);
}

Contact collide(const Cylinder& cyl, const Obb& box) { return detail::collide_consistent(cyl, box); }

void overlap_many(const Cylinder& cyl, const Obb* b, std::size_t n, bool* out) {
  detail::each_scalar(cyl, b, n, out, [](const Cylinder& c, const Obb& x) { return overlap(c, x); });
}

void collide_many(const Cylinder& cyl, const Obb* b, std::size_t n, Contact* out) {
  detail::each_scalar(cyl, b, n, out, [](const Cylinder& c, const Obb& x) { return collide(c, x); });
}

}  // namespace geomcheck
