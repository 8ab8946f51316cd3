#include "geomcheck/collide_cylinder_capsule.hpp"
#include "geomcheck/collide_many.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "geomcheck/detail/frame.hpp"
#include "geomcheck/detail/segment_tube.hpp"

namespace geomcheck {

namespace {

// The capsule's segment S(l) = a + l e, l in [0, 1], measured from the
// cylinder's cap centre p (so that a scene far from the origin adds no
// rounding of its own): axial coordinate z(l) = za + l ze along the unit
// axis u (the cylinder is 0 <= z <= len), radial vector w(l) = wa + l we.
struct SegmentInFrame {
  Vec3 u;
  double len, r;
  Vec3 a, e;        // S's start (from p) and direction
  double za, ze;
  Vec3 wa, we;
  SegmentInFrame(const Cylinder& cyl, const Capsule& cap) : r(cyl.r), a(cap.p - cyl.p), e(cap.q - cap.p) {
    const detail::UnitAndLength ul(cyl.q - cyl.p);
    u = ul.u;
    len = ul.len;
    za = dot(a, u);
    ze = dot(e, u);
    wa = a - za * u;
    we = e - ze * u;
  }
  Vec3 point(double l) const { return a + l * e; }  // from p
  // How far S(l) lies beyond a cap plane (0 between them). Beyond q's plane
  // the excess is (za - len) + l ze, not (za + l ze) - len: where S starts on
  // that plane (za == len) and leaves it at a slope below an ulp of len, the
  // sum would absorb l ze, and the rim piece would pass for a side piece
  // (regression collide_cylinder_capsule/0005).
  double beyond(double l) const {
    const double z = za + l * ze;
    if (z < 0) return -z;
    const double zq = (za - len) + l * ze;
    return zq > 0 ? zq : 0.0;
  }
  // Distance from S(l) to the solid cylinder, from the offsets beyond the
  // cap plane and beyond the side.
  double dist(double l) const {
    const double ea = beyond(l);
    const double er = std::max(detail::safe_length(wa + l * we) - r, 0.0);
    if (ea == 0) return er;
    if (er == 0) return ea;
    return detail::safe_length(Vec3{ea, er, 0});
  }
  // Beyond a cap plane and outside the radius at l: the rim piece.
  bool at_rim(double l) const { return beyond(l) > 0 && detail::safe_length(wa + l * we) > r; }
};

// On a rim piece the squared distance F(l) = (z - cap)^2 + (rho - r)^2 is
// smooth and convex: its minimum on [lo, hi] by Newton on F' = 0, kept
// inside a shrinking bracket (bisection when a step leaves it).
double minimize_rim(const SegmentInFrame& s, double lo, double hi) {
  const bool at_q = (s.za - s.len) + 0.5 * (lo + hi) * s.ze > 0;
  const double sz = at_q ? 1.0 : -1.0, cap = at_q ? s.len : 0.0;
  const double we2 = dot(s.we, s.we);
  auto deriv = [&](double l, double& d1, double& d2) {
    const double ea = sz * ((s.za - cap) + l * s.ze);
    const Vec3 w = s.wa + l * s.we;
    const double rho = detail::safe_length(w);
    const double er = rho - s.r;
    const double rp = rho > 0 ? dot(w, s.we) / rho : 0.0;
    d1 = ea * sz * s.ze + er * rp;
    d2 = s.ze * s.ze + rp * rp + (rho > 0 ? er * (we2 - rp * rp) / rho : 0.0);
  };
  double d1, d2;
  deriv(lo, d1, d2);
  if (d1 >= 0) return lo;
  deriv(hi, d1, d2);
  if (d1 <= 0) return hi;
  double l = 0.5 * (lo + hi);
  for (int it = 0; it < 80 && hi - lo > 0x1p-60; ++it) {
    deriv(l, d1, d2);
    if (d1 == 0) return l;
    (d1 < 0 ? lo : hi) = l;
    double next = d2 > 0 ? l - d1 / d2 : 0.5 * (lo + hi);
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    else if (std::fabs(next - l) <= 0x1p-46) return next;  // quadratic convergence: the next step is below rounding
    if (next == l) break;
    l = next;
  }
  return l;
}

// Where S comes closest to the cylinder: l* and D = dist(S(l*), C). D == 0
// when S meets the cylinder (then l* is inside it).
struct Closest {
  double l = 0, d = 0;
};

Closest closest(const SegmentInFrame& s, const Cylinder& cyl) {
  // S inside the cylinder somewhere: the robust segment/cylinder interval,
  // taken where its midpoint is within the radius. A line that only grazes
  // the side (tangent to it: a double root, the quadratic's coefficients qb
  // and qc both at the rounding level) gets roots that are quotients of
  // rounding, and an interval that can span the whole segment: its midpoint
  // then lies outside the radius (0.3% of the scene in regression
  // collide_cylinder_capsule/0006), and the search below finds where S comes
  // closest. (The slab's part of the interval is linear and reliable: a
  // crossing of a disk of subnormal thickness is kept, regression 0009.)
  const detail::TubeInterval iv = detail::tube_interval(s.a, s.e, s.u, s.len, 0.0, cyl.r);
  if (!iv.empty && iv.entry <= 1 && iv.exit >= 0) {
    const double l = 0.5 * (std::max(iv.entry, 0.0) + std::min(iv.exit, 1.0));
    if (detail::safe_length(s.wa + l * s.we) <= cyl.r) return {l, 0.0};
  }
  // dist(S(l), C) is convex in l: its minimum over [0, 1] is at an end, at
  // a kink (a cap plane or the radius crossed) or at a stationary point of
  // a smooth piece (closest approach to the axis line; on a rim piece, to
  // the rim circle).
  double cand[10];
  int n = 0;
  cand[n++] = 0;
  cand[n++] = 1;
  auto add = [&](double l) {
    if (l > 0 && l < 1) cand[n++] = l;
  };
  if (s.ze != 0) {
    add(-s.za / s.ze);
    add((s.len - s.za) / s.ze);
  }
  const double we2 = dot(s.we, s.we);
  // The closest approach to the axis line: a stationary point of the side
  // piece, and on a cap face (where the distance is flat when S is parallel
  // to the cap) the point whose normal is the axis. On a rim piece it is no
  // stationary point, and a nearly axis-parallel S puts it anywhere (its
  // quotient is ill-conditioned) at a distance that ties with the true
  // minimiser's to rounding: taken there, it tilted the normal of a contact
  // whose optimum sits on a cap plane (regression collide_cylinder_capsule/0003).
  if (we2 > 0) {
    const double l = -dot(s.wa, s.we) / we2;
    if (!s.at_rim(l)) add(l);
  }
  // The radius crossings (roots of rho(l) = r) where the line meets the
  // infinite cylinder: that interval's ends (NaN or infinite otherwise).
  add(iv.cyl_lo);
  add(iv.cyl_hi);
  for (int i = 1; i < n; ++i)  // insertion sort of at most 7 values
    for (int j = i; j > 0 && cand[j] < cand[j - 1]; --j) std::swap(cand[j], cand[j - 1]);
  int best = 0;
  double bd = s.dist(cand[0]);
  for (int i = 1; i < n; ++i) {
    const double d = s.dist(cand[i]);
    if (d < bd) bd = d, best = i;
  }
  Closest out{cand[best], bd};
  // A rim piece between two neighbouring candidates has its stationary point
  // inside; by convexity an interior stationary point is the minimiser.
  // Every rim piece is searched, not only those next to the best candidate:
  // candidates tie (a radius crossing at 1e-16 and the end 0 gave the same
  // distance, and the piece beyond the tie held the minimum, 8 % of the
  // scene lower: regression sweep_sphere_cylinder/0003).
  const Closest cand_best = out;
  bool interior = false;
  for (int j = 0; j + 1 < n; ++j) {
    const double lo = cand[j], hi = cand[j + 1];
    if (!(hi > lo) || !s.at_rim(0.5 * (lo + hi))) continue;
    const double l = minimize_rim(s, lo, hi);
    if (!(l > lo && l < hi)) continue;
    // An interior stationary point is the minimiser, even where rounding
    // puts its distance an ulp above the best candidate's: its normal is the
    // minimal-translation direction, the candidate's is off by up to the
    // twist of the segment.
    const double d = s.dist(l);
    if (interior ? d < out.d : d <= cand_best.d * (1 + 0x1p-44)) out = {l, d}, interior = true;
  }
  return out;
}

// Overlap of the shapes along unit n (from the cylinder towards the
// capsule): h_cyl(n) + h_cap(-n) by the support functions, measured from p.
double overlap_along(const SegmentInFrame& s, const Capsule& cap, Vec3 n) {
  const double nu = dot(n, s.u);
  const double h_cyl = std::max(0.0, s.len * nu) + s.r * detail::safe_length(n - nu * s.u);
  const double low_cap = std::min(dot(n, s.a), dot(n, s.a + s.e)) - cap.r;
  return h_cyl - low_cap;
}

bool overlap_scaled(const Cylinder& cyl, const Capsule& cap) {
  if (!is_valid(cyl)) return false;
  const SegmentInFrame s(cyl, cap);
  return closest(s, cyl).d <= cap.r;
}

Contact collide_scaled(const Cylinder& cyl, const Capsule& cap) {
  Contact out;
  if (!is_valid(cyl)) return out;
  const SegmentInFrame s(cyl, cap);
  const Closest k = closest(s, cyl);
  if (!(k.d <= cap.r)) return out;
  const double scene = std::max(detail::largest(cyl), detail::largest(cap));
  const double noise = 16 * 0x1p-52 * std::max(scene, s.len);
  out.hit = true;
  const Vec3 x = s.point(k.l);
  // Shallow: the sphere contact at S's closest point (true depth, the
  // direction between the closest points). That direction is computed from
  // offsets of size D with rounding eps * scene, so below D = 2^-20 * scene
  // it is no longer trusted: such a core touches the cylinder to the
  // precision that matters, and goes to the deep branch, whose depth is the
  // overlap along its normal whatever the normal.
  const detail::ClosestOnCylinder c = detail::closest_on_cylinder(cyl, s.u, s.len, x, noise);
  if (k.d > 0x1p-20 * scene && !c.inside) {
    // Measured from p and the capsule's p, the closest points carry
    // rounding of eps * scene; the direction between them, over a distance
    // D, then errs by eps * scene / D, and a long segment lying across it
    // turns that angle into overlap (a rim contact at the far end of a long
    // cylinder). So they are found again from the cylinder's cap centre and
    // the capsule's end nearer to them: offsets of the contact's size.
    // Only a rim's normal depends on the offsets' rounding over D (a cap's
    // is the axis, a side's the radial direction, of the radius' size), and
    // only where the terms x is formed from are large against D.
    const double ax = dot(x, s.u);
    const bool rim = (ax < 0 || ax > s.len) && detail::safe_length(x - ax * s.u) > cyl.r;
    const bool from_q = 2 * ax > s.len, end_q = k.l > 0.5;
    // Where S's closest point is a stationary point inside the core (the
    // direction n0 found is perpendicular to S, to its rounding), the
    // direction between the closest points is also perpendicular to the
    // rim's tangent at the rim point: n = e x tau / |e x tau|, good to eps /
    // sin(e, tau) whatever l's rounding. The direction between the points
    // themselves errs by about |e| dl / D: at D = 1.7e-5 * scene in the
    // middle of the core no double l is close enough (normal error 2.3e-12 *
    // scale; regression collide_cylinder_capsule/0008).
    auto rim_normal = [&](Vec3 n0) {
      if (!rim || !(k.l > 0 && k.l < 1)) return n0;
      const Vec3 eu = detail::normalized(s.e);
      if (!(std::fabs(dot(n0, eu)) < 0x1p-20)) return n0;
      const Vec3 tau = cross(s.u, detail::unit_perpendicular_part(x, s.u));
      const Vec3 cp = cross(eu, tau);
      const double sn = detail::safe_length(cp);
      if (!(sn > 0x1p-10)) return n0;
      const Vec3 n = (dot(cp, n0) < 0 ? -1 / sn : 1 / sn) * cp;
      return dot(n, n0) > 1 - 0x1p-30 ? n : n0;
    };
    if (rim && (from_q || end_q) && std::max(max_abs(s.a), max_abs(s.e)) > 64 * k.d) {
      const Cylinder base = from_q ? Cylinder{cyl.q, cyl.p, cyl.r} : cyl;
      const SegmentInFrame sl(base, end_q ? Capsule{cap.q, cap.p, cap.r} : cap);
      const Closest kl = closest(sl, base);
      const detail::ClosestOnCylinder near = detail::closest_on_cylinder(base, sl.u, sl.len, sl.point(kl.l), noise);
      if (!near.inside && kl.d > 0) {
        out.point = near.point;
        out.normal = rim_normal(near.normal);
        out.depth = std::max(cap.r - kl.d, 0.0);
        return out;
      }
    }
    out.point = c.point;
    out.normal = rim_normal(c.normal);
    out.depth = std::max(cap.r - k.d, 0.0);
    // Within rounding of a cap plane the rim and the side meet, and the
    // rounding of ax picks the branch. Where S's closest approach to the
    // axis line lies there, the normal of either is the common perpendicular
    // of the axis and S, u x e / |u x e|; it is offered too, and the one of
    // the two with the smaller overlap along it kept. A zero-radius cylinder
    // passing beneath a core 4.5e-16 of its length from its end p got the
    // rim's normal at p, tilted by l's rounding over the small angle between
    // the rim tangent and S (normal error 2.82e-12 * scale; regression
    // collide_cylinder_capsule/0010).
    if (rim && k.l > 0 && k.l < 1 && (std::fabs(ax) <= noise || std::fabs(ax - s.len) <= noise)) {
      const Vec3 cp = cross(s.u, detail::normalized(s.e));
      const double sn = detail::safe_length(cp);
      if (sn > 0x1p-10) {
        const Vec3 nc = (dot(cp, out.normal) < 0 ? -1 / sn : 1 / sn) * cp;
        if (dot(nc, out.normal) > 1 - 0x1p-30 && overlap_along(s, cap, nc) < overlap_along(s, cap, out.normal))
          out.normal = nc;
      }
    }
    // A side contact at S's closest approach to the axis line: the direction
    // between the closest points is the common perpendicular of the axis and
    // S, u x e / |u x e|, good to about eps / sin(angle between them), where
    // the radial vector w(l) is good to eps * scene / (r + D) only. A thin
    // cylinder crossing a long capsule's core at a distance D small against
    // the scene is where that differs (regression collide_cylinder_capsule/0004).
    const double we2 = dot(s.we, s.we);
    if (!rim && ax >= 0 && ax <= s.len && we2 > 0 && k.l == -dot(s.wa, s.we) / we2) {
      const Vec3 cp = cross(s.u, detail::normalized(s.e));
      const double sn = detail::safe_length(cp);
      if (sn * scene > cyl.r + k.d) out.normal = (dot(cp, c.normal) < 0 ? -1 / sn : 1 / sn) * cp;
    }
    return out;
  }
  // Deep: S meets the cylinder (or nearly). The least overlap over the
  // candidate directions: the direction between the closest points (when S
  // is outside), the axis both ways, the radial direction of S's closest
  // approach to the axis line (both ways), the common perpendicular of S and
  // the axis (both ways).
  out.point = c.inside ? cyl.p + x : c.point;
  Vec3 cands[9];
  int n = 0;
  cands[n++] = s.u;
  cands[n++] = -s.u;
  const double we2 = dot(s.we, s.we);
  const double lc = we2 > 0 ? std::clamp(-dot(s.wa, s.we) / we2, 0.0, 1.0) : 0.5;
  const Vec3 wc = s.wa + lc * s.we;
  if (detail::safe_length(wc) > noise) {
    const Vec3 rd = detail::unit_perpendicular_part(wc, s.u);
    cands[n++] = rd;
    cands[n++] = -rd;
  }
  if (detail::safe_length(s.we) > noise) {
    // Oriented towards the segment's side of the axis (a reflection of the
    // scene reflects the choice; cross products alone would flip it).
    Vec3 cp = detail::normalized(cross(s.u, detail::normalized(s.we)));
    if (dot(cp, s.wa + 0.5 * s.we) < 0) cp = -cp;
    cands[n++] = cp;
    cands[n++] = -cp;
  }
  if (!c.inside && k.d > noise) cands[n++] = c.normal;
  if (n == 2) {
    // S along the axis line: any perpendicular.
    const Vec3 pp = any_perpendicular(s.u);
    cands[n++] = pp;
    cands[n++] = -pp;
  }
  double best = std::numeric_limits<double>::infinity();
  for (int i = 0; i < n; ++i) {
    const double o = overlap_along(s, cap, cands[i]);
    if (o < best) best = o, out.normal = cands[i];
  }
  out.depth = std::min(std::max(best, 0.0), std::numeric_limits<double>::max());
  return out;
}

}  // namespace

bool overlap(const Cylinder& cyl, const Capsule& cap) {
  return detail::overlap_rescaled(cyl, cap, [](const Cylinder& c, const Capsule& k) { return overlap_scaled(c, k); });
}

Contact collide(const Cylinder& cyl, const Capsule& cap) {
  return detail::collide_rescaled(cyl, cap, [](const Cylinder& c, const Capsule& k) { return collide_scaled(c, k); });
}

namespace {

// overlap_many's filter: a capsule clearly apart from the cylinder or
// clearly meeting it is decided in doubles, with a margin far above the
// rounding; every other one (and any outside the filter's range) goes to the
// scalar query. The scalar verdict is exact outside its band of touching,
// far inside the margin, so every answer is the scalar one (test_many.cpp
// holds it, bit for bit, on the targeted generator's touching poses).
//
// Meets: a point X = (p_k - p) + t (q_k - p_k) of the capsule's segment,
// t in [0, 1] (the segment's closest approach to the axis line, and its
// ends), whose axial excess beyond the caps plus radial excess beyond r is
// below the capsule's radius less the margin: X is then within that radius
// of the cylinder (the distance is at most the sum of the two excesses).
// Apart: a direction m (the axis, across the axis towards X, the common
// perpendicular of the axis and the segment) along which the capsule's
// values, m.(ends - p) -+ r_k |m|, all lie above the cylinder's largest,
// m.d / 2 + |m.d| / 2 + r |m x d| / |d|, or all below its smallest. Every
// value is a few dozen operations on rounded differences and on the rounded
// unit axis u = d / |d| (|m x d| / |d| is taken as |m x u|), off by at most
// about 50 * 2^-53 * M * reach (M = |m|inf or 1, reach = the largest
// offset from p plus |d|inf, r and r_k); the margin is 2^-32 * M * reach.
// Used where reach and M lie within [2^-200, 2^200] (no square leaves the
// normal range but negligible ones) and d.d is at least 2^-500.
class CapsuleListFilter {
 public:
  explicit CapsuleListFilter(const Cylinder& c) : p_(c.p), d_(c.q - c.p), r_(c.r) {
    const double dd = dot(d_, d_);
    dmax_ = max_abs(d_);
    usable_ = dd >= 0x1p-500 && dmax_ <= 0x1p200;
    dlen_ = std::sqrt(dd);
    u_ = (1 / dlen_) * d_;
  }
  /// 1: the capsule meets the cylinder; 0: it does not; -1: not decided.
  int decide(const Capsule& k) const {
    if (!usable_) return -1;
    if (!is_valid(k)) return 0;  // the scalar query's "no overlap"
    const Vec3 a = k.p - p_, b = k.q - p_, e = k.q - k.p;
    const double reach = std::max(max_abs(a), max_abs(b)) + dmax_ + r_ + k.r;
    if (!(reach >= 0x1p-200 && reach <= 0x1p200)) return -1;
    const double margin = 0x1p-32 * reach;
    // A point of the segment (t in [0, 1]): its axial coordinate and radial
    // offset; within the capsule's radius of the cylinder (1), or the
    // direction from the cylinder's nearest point to it, for the tests of
    // separation.
    struct Point {
      double ax, rho;  // axial coordinate, radial distance (|radial|)
      Vec3 radial;
    };
    auto at = [&](double t) {
      const Vec3 x = a + t * e;
      const double ax = dot(x, u_);
      const Vec3 radial = x - ax * u_;
      return Point{ax, std::sqrt(dot(radial, radial)), radial};
    };
    auto meets = [&](const Point& x) {
      const double over = std::max(std::max(-x.ax, x.ax - dlen_), 0.0);
      const double out = std::max(x.rho - r_, 0.0), reach_k = k.r - margin;
      return reach_k > 0 && over * over + out * out < reach_k * reach_k;
    };
    // Along m, given upper bounds of |m| and of |m x u| (the cylinder's
    // reach across its axis is r |m x u|; both enlarge an interval, so a
    // bound from above keeps the test sound).
    auto apart_with = [&](Vec3 m, double m_len, double mxu_len) {
      const double M = max_abs(m);
      if (!(M >= 0x1p-200 && M <= 0x1p200)) return false;
      const double mm = 0x1p-32 * M * reach;
      const double ma = dot(m, a), mb = dot(m, b), md = dot(m, d_);
      const double rk = k.r * m_len;
      const double h = 0.5 * std::fabs(md) + r_ * mxu_len;
      return std::min(ma, mb) - rk > 0.5 * md + h + mm || std::max(ma, mb) + rk < 0.5 * md - h - mm;
    };
    constexpr double kUp = 1 + 0x1p-48;  // a computed length (or a product with u's) enlarged past its rounding
    auto apart = [&](Vec3 m) {
      const Vec3 mu = cross(m, u_);
      return apart_with(m, kUp * std::sqrt(dot(m, m)), kUp * std::sqrt(dot(mu, mu)));
    };
    // The segment's closest approach to the axis line (its middle when
    // parallel), clamped to the segment.
    const double de = dot(u_, e), da = dot(u_, a), ee = dot(e, e);
    const double den = ee - de * de;
    double t = den > 0x1p-40 * ee ? (de * da - dot(e, a)) / den : 0.5;
    t = std::clamp(t, 0.0, 1.0);
    const Point c = at(t);
    if (meets(c)) return 1;
    // Across the axis towards that point (|m x u| <= |m| |u|, |u| within
    // 2^-51 of 1), and along the axis (|d x u| = |d| |u - d / |d|| is below
    // 2^-50 |d|).
    if (apart_with(c.radial, kUp * c.rho, kUp * kUp * c.rho) || apart_with(d_, kUp * dlen_, 0x1p-48 * dlen_)) return 0;
    // The ends, and the crossings of the cap planes (clamped to the segment).
    Point more[4] = {at(0), at(1), c, c};
    if (meets(more[0]) || meets(more[1])) return 1;
    if (de != 0) {
      more[2] = at(std::clamp(-da / de, 0.0, 1.0));
      more[3] = at(std::clamp((dlen_ - da) / de, 0.0, 1.0));
      if (meets(more[2]) || meets(more[3])) return 1;
    }
    // From the cylinder's point nearest to each of them (beyond a rim).
    const Point* pts[5] = {&c, &more[0], &more[1], &more[2], &more[3]};
    for (const Point* x : pts) {
      if (!(x->rho > 0)) continue;
      const Vec3 radial_part = (std::max(x->rho - r_, 0.0) / x->rho) * x->radial;
      const double axial_part = x->ax < 0 ? x->ax : (x->ax > dlen_ ? x->ax - dlen_ : 0.0);
      if (apart(radial_part + axial_part * u_)) return 0;
    }
    if (apart(cross(d_, e))) return 0;
    return -1;
  }

 private:
  Vec3 p_, d_, u_;
  double r_, dlen_ = 0, dmax_ = 0;
  bool usable_ = false;
};

}  // namespace

void overlap_many(const Cylinder& cyl, const Capsule* b, std::size_t n, bool* out) {
  if (!is_valid(cyl)) {
    for (std::size_t i = 0; i < n; ++i) out[i] = false;
    return;
  }
  const CapsuleListFilter filter(cyl);
  for (std::size_t i = 0; i < n; ++i) {
    const int v = filter.decide(b[i]);
    out[i] = v < 0 ? overlap(cyl, b[i]) : v == 1;
  }
}

void collide_many(const Cylinder& cyl, const Capsule* b, std::size_t n, Contact* out) {
  if (!is_valid(cyl)) {
    for (std::size_t i = 0; i < n; ++i) out[i] = Contact{};
    return;
  }
  // A capsule the filter finds clearly apart gets collide's own answer for a
  // miss, Contact{} (overlap == collide.hit, a property of the query); every
  // other one the scalar collide.
  const CapsuleListFilter filter(cyl);
  for (std::size_t i = 0; i < n; ++i) out[i] = filter.decide(b[i]) == 0 ? Contact{} : collide(cyl, b[i]);
}

}  // namespace geomcheck
