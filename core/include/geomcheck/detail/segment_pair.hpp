// geomcheck — internal: the distance of two segments (either may be a single
// point) and the direction between their closest points, the core of the
// sphere and capsule pairs. A capsule is its segment swept by a ball (a
// sphere: a segment of zero length), so two of them meet iff the distance D
// of their segments is at most r1 + r2, and their penetration depth is
// exactly r1 + r2 - D: the Minkowski difference is the parallelogram of the
// segments swept by a ball of radius r1 + r2, and the distance to its
// boundary is 1-Lipschitz (D = 0, segments that cross or overlap, included:
// the parallelogram is flat, so leaving it across its plane costs r1 + r2).
//
// Precision: the direction between the closest points is what the contact's
// normal is, and for a capsule its error turns into excess overlap along
// the normal in proportion to the segment's length. Rounded differences
// q - p would give it an angle error of eps * scene / D; here every
// difference of input points is carried exactly (hi + lo), products that
// cancel are formed with fma, and the residual is projected off the
// segment's direction a second time, so the angle error is a few eps (plus
// eps^2 * scene / D), whatever D.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

#include "geomcheck/detail/frame.hpp"
#include "geomcheck/results.hpp"
#include "geomcheck/shapes.hpp"
#include "geomcheck/vec3.hpp"

// The solvers form exact products with fma, a libm call unless the compiler
// may use the processor's FMA instructions. Where it can dispatch at run
// time (GCC, x86-64 Linux), a solver marked GEOMCHECK_FMA_CLONES is compiled
// twice, once with them, and the processor picks; fma is correctly rounded
// either way, so both give the same bits.
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && defined(__linux__)
#define GEOMCHECK_FMA_CLONES __attribute__((target_clones("fma", "default")))
#else
#define GEOMCHECK_FMA_CLONES
#endif
// The helpers below are inlined into every solver (so into each of its
// clones, where fma is an instruction), whatever the optimiser's size limits.
#if defined(__GNUC__)
#define GEOMCHECK_SOLVER_INLINE inline __attribute__((always_inline))
#else
#define GEOMCHECK_SOLVER_INLINE inline
#endif

namespace geomcheck::detail {

/// x - y exactly, as hi + lo per component (Knuth's two-sum).
struct ExactDiff {
  Vec3 hi, lo;
};
GEOMCHECK_SOLVER_INLINE ExactDiff exact_diff(Vec3 x, Vec3 y) {
  ExactDiff d;
  for (int i = 0; i < 3; ++i) {
    const double a = x[i], b = -y[i];
    const double s = a + b;
    const double bb = s - a;
    d.hi[i] = s;
    d.lo[i] = (a - (s - bb)) + (b - bb);
  }
  return d;
}

/// a * b - c * d to within about 1.5 ulp (Kahan's fma form: no cancellation
/// of rounded products).
GEOMCHECK_SOLVER_INLINE double product_difference(double a, double b, double c, double d) {
  const double w = c * d;
  const double e = std::fma(-c, d, w);
  const double f = std::fma(a, b, -w);
  return f + e;
}

/// u x v with every minor formed by product_difference, u and v given
/// exactly as hi + lo: the first-order terms of the lo parts are added.
GEOMCHECK_SOLVER_INLINE Vec3 accurate_cross(const ExactDiff& u, const ExactDiff& v) {
  const Vec3 &a = u.hi, &b = v.hi;
  Vec3 c{product_difference(a.y, b.z, a.z, b.y), product_difference(a.z, b.x, a.x, b.z),
         product_difference(a.x, b.y, a.y, b.x)};
  return c + (cross(a, v.lo) + cross(u.lo, b));
}

/// The closest points of two segments and their distance, as a solver
/// leaves them for a contact (collide); the unit normal is formed once, by
/// ball_contact.
/// A Vec3 slot a solver always writes before it is read: left uninitialised
/// (Vec3 zero-initialises, and zeroing the report on every call costs as
/// much as the sphere pair's arithmetic).
struct Slot3 {
  double x, y, z;
  Slot3& operator=(Vec3 v) {
    x = v.x, y = v.y, z = v.z;
    return *this;
  }
  operator Vec3() const { return {x, y, z}; }
};

struct SegmentPair {
  static constexpr bool kWantsDirection = true;
  double dist2 = 0;  ///< D^2: the verdict compares it with (ra + rb)^2, no square root
  Slot3 a;           ///< the closest point of the first segment
  /// The direction from a towards the second segment's closest point where
  /// D > 0, not normalised (unit already when `dir_is_unit`).
  Slot3 dir;
  /// What the normal is where the segments touch (D = 0): `across` itself
  /// (Across::Unit: the common perpendicular, computed on the way), its
  /// direction (Across::Normalise: their cross product, nonzero), or a
  /// perpendicular of it (Across::PerpendicularOf: the longer segment;
  /// (0, 0, 1) when it is zero), formed only if needed.
  enum class Across : unsigned char { Unit, Normalise, PerpendicularOf };
  Slot3 across;
  Across across_is = Across::Unit;
  bool dir_is_unit = false;
  /// Where the normal is another candidate's direction than the closest
  /// points' (closest_segments near a tie): the closest points' own unit
  /// direction, along which the contact's point is placed (in both solids).
  Slot3 pair_dir;
  bool normal_elsewhere = false;
  void points(Vec3 x, Vec3) { a = x; }
  void direction(Vec3 d, bool unit) { dir = d, dir_is_unit = unit; }
  void touching(Vec3 x, Across how) { across = x, across_is = how; }
};

/// The same solver's report for a verdict (overlap): the squared distance
/// alone, the rest dropped (the same arithmetic, so the same bits as
/// collide's).
struct SegmentDistance {
  static constexpr bool kWantsDirection = false;
  double dist2 = 0;
  void points(Vec3, Vec3) {}
  void direction(Vec3, bool) {}
  void touching(Vec3, SegmentPair::Across) {}
};

/// The residual x - c from the closest point c of segment [p, q] to x (x +
/// x_lo, when x is a computed point carried to twice the precision), and
/// c: carried exactly where it cancels (see the file's head). An end is
/// the closest point only where the rounded projection says so beyond its
/// rounding; within it (x beside an end, to a few ulps) the residual is the
/// projection's, across the segment: the true one may be x minus the end,
/// tilted along the segment by up to that rounding, and a normal tilted
/// along a capsule costs overlap in proportion to its length, while the
/// projection's distance is short of the true one by at most the same few
/// ulps of the scene (fuzz_collide_sphere_capsule found the tilt: an end
/// taken for a centre 2e-23 beside the segment, the normal 0.18 * scale off).
GEOMCHECK_SOLVER_INLINE Vec3 point_segment_residual(Vec3 x, Vec3 p, Vec3 q, Vec3& c, Vec3 x_lo = Vec3{}) {
  const ExactDiff d = exact_diff(q, p);
  const double dd = dot(d.hi, d.hi);
  ExactDiff w = exact_diff(x, p);
  w.lo = w.lo + x_lo;
  const double wd = dot(w.hi, d.hi);
  // wd's rounding (and w.lo's share) within 2^-50 of the sum of its terms'
  // magnitudes; dd's within 2^-51 of itself.
  const double band = 0x1p-50 * (std::fabs(w.hi.x * d.hi.x) + std::fabs(w.hi.y * d.hi.y) + std::fabs(w.hi.z * d.hi.z)) +
                      0x1p-51 * dd + 0x1p-1022;
  if (!(dd > 0) || !(wd > -band)) {
    c = p;
    return w.hi + w.lo;
  }
  if (wd - dd >= band) {
    c = q;
    const ExactDiff e = exact_diff(x, q);
    return e.hi + (e.lo + x_lo);
  }
  const double t = std::min(std::max(wd / dd, 0.0), 1.0);
  Vec3 n;
  for (int i = 0; i < 3; ++i) {
    const double prod = t * d.hi[i];
    const double err = std::fma(t, d.hi[i], -prod);
    n[i] = (w.hi[i] - prod) + ((w.lo[i] - err) - t * d.lo[i]);
  }
  // What is left along the segment (t's rounding, or the clamp): projected off.
  n = n - (dot(n, d.hi) / dd) * d.hi;
  c = p + t * d.hi;
  return n;
}

/// v / max |v_i| (v != 0): components in [-1, 1], the largest +-1 (a
/// division, not a multiplication by 1 / max, which overflows for a
/// subnormal max).
GEOMCHECK_SOLVER_INLINE Vec3 max_scaled(Vec3 v) {
  const double m = max_abs(v);
  return {v.x / m, v.y / m, v.z / m};
}

/// v / |v| for v != 0, scaled first so that its square neither overflows
/// nor underflows.
GEOMCHECK_SOLVER_INLINE Vec3 unit_of(Vec3 v) {
  const Vec3 s = max_scaled(v);
  return (1.0 / length(s)) * s;
}

/// |v|, safe from overflow and underflow of the squares.
GEOMCHECK_SOLVER_INLINE double norm_of(Vec3 v) {
  const double m = max_abs(v);
  if (!(m > 0)) return 0;
  if (m > 0x1p-450 && m < 0x1p+450) return length(v);
  return m * length(max_scaled(v));
}

/// A unit perpendicular of u (nonzero), or (0, 0, 1) for u == 0.
GEOMCHECK_SOLVER_INLINE Vec3 some_perpendicular(Vec3 u) {
  if (!(max_abs(u) > 0)) return {0, 0, 1};
  return unit_of(any_perpendicular(max_scaled(u)));
}

/// x with its component along d (d . d = dd > 0) removed, twice ("twice is
/// enough": what the first pass leaves is rounding of the result's size).
GEOMCHECK_SOLVER_INLINE Vec3 perpendicular_part(Vec3 x, Vec3 d, double dd) {
  x = x - (dot(x, d) / dd) * d;
  return x - (dot(x, d) / dd) * d;
}

/// The point x of one segment against the other segment [p, q]: taken
/// into `out` when its squared distance is below `best` (`second` keeps the
/// runner-up's; x on the first
/// segment: the direction points from x away; else towards x). The squares
/// of a scene in [1, 2) are in range but for distances below 2^-500, which
/// ball_pair treats as touching anyway.
template <class Out>
GEOMCHECK_SOLVER_INLINE void consider_end(Vec3 x, Vec3 p, Vec3 q, bool x_on_first, double& best, double& second,
                                          Out& out, Vec3 x_lo = Vec3{}) {
  Vec3 c;
  const Vec3 r = point_segment_residual(x, p, q, c, x_lo);
  const double d2 = dot(r, r);
  if (!(d2 < best)) {
    second = std::min(second, d2);
    return;
  }
  second = best;
  best = d2;
  if (x_on_first) {
    out.points(x, c);
    out.direction(-r, false);
  } else {
    out.points(c, x);
    out.direction(r, false);
  }
}

/// The closest points of segments [p1, q1] and [p2, q2] (a scene of
/// magnitude in [1, 2): ball_pair scales it so).
///
/// Where the segments are far from parallel (their cross product m large
/// against eps times the lengths and the offset w = p2 - p1: then the
/// parameters s, t of the lines' crossing are good to 2^-20), a crossing
/// inside both is the answer: its distance along m, m's direction the
/// normal. Elsewhere the answer is the nearest of the four ends against the
/// other segment (exact for parallel segments) and, for nearly parallel
/// ones, of B's point nearest A's line (the offset of B(t) across A's
/// direction is linear in t: a one-dimensional minimum) against A. Any
/// parameter error there slides along the valley of the distance, which
/// rises by |v| sin(angle) per unit of t: the distance found is within
/// about eps * scene of the true one.
template <class Out>
GEOMCHECK_SOLVER_INLINE void closest_segments(Vec3 p1, Vec3 q1, Vec3 p2, Vec3 q2, Out& out) {
  const ExactDiff u = exact_diff(q1, p1), v = exact_diff(q2, p2), w = exact_diff(p2, p1);
  const Vec3 m = accurate_cross(u, v);
  const double mm = dot(m, m);
  const double uu = dot(u.hi, u.hi), vv = dot(v.hi, v.hi), ww = dot(w.hi, w.hi);
  const bool crossing_well_posed = mm > 0 && mm >= 0x1p-62 * std::max(uu, vv) * ww;
  if (crossing_well_posed) {
    // w = s u - t v + N with N along m: s = (w x v) . m / |m|^2, t = (w x u) . m / |m|^2.
    const double s = dot(cross(w.hi, v.hi), m) / mm;
    const double t = dot(cross(w.hi, u.hi), m) / mm;
    if (s >= 0 && s <= 1 && t >= 0 && t <= 1) {
      const Vec3 nm = unit_of(m);
      const double along = dot(w.hi, nm) + dot(w.lo, nm);
      out.dist2 = along * along;
      out.direction(along < 0 ? -nm : nm, true);
      out.touching(nm, SegmentPair::Across::Unit);
      out.points(p1 + s * u.hi, p2 + t * v.hi);
      return;
    }
  }
  if (mm > 0) out.touching(m, SegmentPair::Across::Normalise);
  else out.touching(uu >= vv ? u.hi : v.hi, SegmentPair::Across::PerpendicularOf);
  // The ends (and B's point nearest A's line) against the other segment;
  // the smallest residual wins.
  double best = INFINITY, second = INFINITY;
  consider_end(p1, p2, q2, true, best, second, out);
  consider_end(q1, p2, q2, true, best, second, out);
  consider_end(p2, p1, q1, false, best, second, out);
  consider_end(q2, p1, q1, false, best, second, out);
  if (!crossing_well_posed && mm > 0 && uu > 0) {
    const Vec3 yw = perpendicular_part(w.hi + w.lo, u.hi, uu), yv = perpendicular_part(v.hi + v.lo, u.hi, uu);
    const double yy = dot(yv, yv);
    if (yy > 0) {
      const double t = std::clamp(-dot(yw, yv) / yy, 0.0, 1.0);
      if (t > 0 && t < 1) {
        // B(t) = p2 + t v to twice the precision: rounded to a double, it
        // leaves B's line by eps * scene, which tilts the direction to A
        // by eps * scene / D (fuzz_collide_capsule_capsule: 0.028 rad at
        // D = 1e-15 * scene).
        Vec3 x, x_lo;
        for (int i = 0; i < 3; ++i) {
          const double prod = t * v.hi[i], err = std::fma(t, v.hi[i], -prod);
          const double sum = p2[i] + prod, bb = sum - p2[i];
          x[i] = sum;
          x_lo[i] = ((p2[i] - (sum - bb)) + (prod - bb)) + (err + t * v.lo[i]);
        }
        consider_end(x, p1, q1, false, best, second, out, x_lo);
      }
    }
  }
  out.dist2 = best;
  // Two candidates within 2^-20 of each other in squared distance (an end
  // beside the other segment's end, inside or outside it by less than D /
  // 2^10), or near touching (D <= 2^-30 of the scene, where rounding decides
  // which end faces which): the winner's direction may lie outside the
  // normal cone of the truly closest feature, tilted along a segment, which
  // costs overlap in proportion to the segment's length
  // (fuzz_collide_capsule_capsule: an end 2e-23 inside the other segment
  // at D = 4.7e-10, a vertex-to-vertex direction 4.3e-14 rad off, 4.3e-14 *
  // scale; and 0.025 * scale at D = 1e-15 * scene). The overlap along any
  // direction is at least the depth, and equal to it (to D) in that cone:
  // of the candidates (the winner's, the common perpendicular, the four
  // ends' residuals) the one along which the segments overlap least serves.
  if constexpr (Out::kWantsDirection) {
    if (!(best > 0 && (best <= 0x1p-60 || second <= best * (1 + 0x1p-20)))) return;
    auto overlap_along = [&](Vec3 n) {
      return std::max(dot(p1, n), dot(q1, n)) - std::min(dot(p2, n), dot(q2, n));
    };
    const Vec3 own = Vec3(out.dir) * (1.0 / std::sqrt(best));
    Vec3 chosen = own;
    double least = overlap_along(chosen);
    auto offer = [&](Vec3 n) {
      const double o = overlap_along(n);
      if (o < least) least = o, chosen = n;
    };
    if (mm > 0) {
      const Vec3 nm = unit_of(m);
      offer(dot(nm, chosen) < 0 ? -nm : nm);
    }
    const Vec3 ends[4][3] = {{p1, p2, q2}, {q1, p2, q2}, {p2, p1, q1}, {q2, p1, q1}};
    for (int k = 0; k < 4; ++k) {
      Vec3 c;
      const Vec3 r = point_segment_residual(ends[k][0], ends[k][1], ends[k][2], c);
      if (max_abs(r) > 0) offer(k < 2 ? -unit_of(r) : unit_of(r));
    }
    out.direction(chosen, true);
    out.pair_dir = own;
    out.normal_elsewhere = true;
  }
}

/// Where along the unit normal n, from the first closest point a, the two
/// solids overlap: [max(-r1, D - r2), min(r1, D + r2)]; its middle, a point
/// in both (a + mid * n).
inline double overlap_middle(double dist, double r1, double r2) {
  const double lo = std::max(-r1, dist - r2), hi = std::min(r1, dist + r2);
  return 0.5 * lo + 0.5 * hi;
}

/// 2^e for e in [-1022, 1023], from its bits (no libm call).
inline double pow2(int e) {
  const std::uint64_t bits = static_cast<std::uint64_t>(e + 1023) << 52;
  double x;
  std::memcpy(&x, &bits, sizeof x);
  return x;
}

/// ilogb(m) for finite m > 0, from the bits of a normal m (libm's for a
/// subnormal one).
inline int exponent_of(double m) {
  std::uint64_t bits;
  std::memcpy(&bits, &m, sizeof bits);
  const int biased = static_cast<int>((bits >> 52) & 0x7ff);
  return biased > 0 ? biased - 1023 : std::ilogb(m);
}

/// Scaling by 2^e (|e| <= 2100), a map of space for shapes.hpp's mapped:
/// two multiplications by powers of two (each a normal double), exact but
/// for values pushed into the subnormals.
struct PowerOfTwo {
  double f1, f2;
  explicit PowerOfTwo(int e) : f1(pow2(e / 2)), f2(pow2(e - e / 2)) {}
  Vec3 pt(Vec3 v) const { return (v * f1) * f2; }
  Vec3 vec(Vec3 v) const { return v; }
  double len(double r) const { return (r * f1) * f2; }
};

inline double radius_of(const Sphere& s) { return s.r; }
inline double radius_of(const Capsule& c) { return c.r; }

/// The closest points and normal of two balls or capsules (`solve(a, b,
/// pair)` fills `pair`),
/// in the scene scaled by an exact power of two so that its largest
/// magnitude lies in [1, 2): every square and product of the solution is
/// then in range, and a scene scaled or reflected exactly is answered bit
/// for bit the same (scaled or reflected). `back` is the exponent that
/// returns to the caller's scale. A distance at the rounding level (D <=
/// 2^-50 of the scene) is touching segments: D = 0 and the normal the
/// solver's `across`. The direction between closest points that close is
/// noise, and for a capsule a normal tilted along a segment costs overlap
/// in proportion to its length; along `across` the overlap exceeds the true
/// depth by at most 2 D, and so does the depth ra + rb.
/// Invalid input: `valid` false.
template <class Out>
struct BallPair {
  bool valid = false;
  Out sp;
  double ra = 0, rb = 0;
  int back = 0;
  /// D^2 <= (ra + rb)^2, the scene in [1, 2): no overflow; a distance
  /// below 2^-50 is zero (touching segments).
  bool hit() const { return valid && sp.dist2 <= (ra + rb) * (ra + rb); }
};
template <class Out, class A, class B, class Solve>
BallPair<Out> ball_pair(const A& a, const B& b, Solve solve) {
  BallPair<Out> out;
  if (!is_valid(a) || !is_valid(b)) return out;
  out.valid = true;
  const double m = std::max(largest(a), largest(b));
  out.back = m > 0 ? exponent_of(m) : 0;
  const PowerOfTwo to(-out.back);
  const A sa = mapped(a, to);
  const B sb = mapped(b, to);
  solve(sa, sb, out.sp);
  out.ra = radius_of(sa), out.rb = radius_of(sb);
  if (out.sp.dist2 <= 0x1p-100) out.sp.dist2 = 0;
  return out;
}

/// The contact of a hitting pair: depth r1 + r2 - D (saturating to the
/// largest double), the normal from the first shape towards the second, the
/// point in the middle of the solids' overlap along it from the first
/// segment's closest point.
inline Contact ball_contact(const BallPair<SegmentPair>& p) {
  Contact c;
  if (!p.hit()) return c;
  c.hit = true;
  const SegmentPair& sp = p.sp;
  const double dist = std::sqrt(sp.dist2);
  if (dist > 0) {
    // |dir| is D (in (2^-50, 8) in the scaled scene: dist2 is its square)
    // or 1.
    c.normal = sp.dir_is_unit ? Vec3(sp.dir) : (1.0 / dist) * Vec3(sp.dir);
  } else if (sp.across_is == SegmentPair::Across::Unit) {
    c.normal = sp.across;
  } else if (sp.across_is == SegmentPair::Across::Normalise) {
    c.normal = unit_of(sp.across);
  } else {
    c.normal = some_perpendicular(sp.across);
  }
  const double depth = std::max((p.ra + p.rb) - dist, 0.0);
  c.depth = PowerOfTwo(p.back).len(depth);
  if (std::isinf(c.depth)) c.depth = std::numeric_limits<double>::max();
  const Vec3 along = dist > 0 && sp.normal_elsewhere ? Vec3(sp.pair_dir) : c.normal;
  const Vec3 x = Vec3(sp.a) + overlap_middle(dist, p.ra, p.rb) * along;
  c.point = PowerOfTwo(p.back).pt(x);
  return c;
}

}  // namespace geomcheck::detail
