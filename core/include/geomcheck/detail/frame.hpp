// geomcheck — internal helpers shared by the production cylinder queries.
//
// Every helper has a fast path (plain arithmetic) for magnitudes where no
// square can overflow or underflow, and an exact power-of-two rescaling
// outside it; the two agree bit for bit wherever both apply.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

#include "geomcheck/results.hpp"
#include "geomcheck/shapes.hpp"

namespace geomcheck::detail {

/// Squares of magnitudes in [kSafeLo, kSafeHi] are normal doubles.
inline constexpr double kSafeLo = 0x1p-450;
inline constexpr double kSafeHi = 0x1p+450;

/// v scaled by 2^-ilogb(m) (exact), for the slow paths.
inline Vec3 scaled_down(Vec3 v, double m) {
  const int e = std::ilogb(m);
  return {std::ldexp(v.x, -e), std::ldexp(v.y, -e), std::ldexp(v.z, -e)};
}

/// Unit vector along v (non-zero, finite), without overflow or underflow.
inline Vec3 normalized(Vec3 v) {
  const double l2 = dot(v, v);
  if (l2 > kSafeLo * kSafeLo && l2 < kSafeHi * kSafeHi) return (1.0 / std::sqrt(l2)) * v;
  const Vec3 s = scaled_down(v, max_abs(v));
  return (1.0 / length(s)) * s;
}

/// Length of v without overflow or underflow of its square.
inline double safe_length(Vec3 v) {
  const double l2 = dot(v, v);
  if (l2 > kSafeLo * kSafeLo && l2 < kSafeHi * kSafeHi) return std::sqrt(l2);
  const double m = max_abs(v);
  if (m == 0 || !std::isfinite(m)) return m;
  return std::ldexp(length(scaled_down(v, m)), std::ilogb(m));
}

/// The unit vector perpendicular to unit u along the part of v
/// perpendicular to u, into `out`; false (out untouched) when that part
/// vanishes, i.e. v has no direction across u. The result is perpendicular
/// to u to rounding whatever v is: when v is nearly parallel to u,
/// subtracting its axial component cancels to noise, so the direction is
/// then built from v's components in an orthonormal frame around u. A
/// reflection of v and u reflects the result bit for bit (the frame is
/// any_perpendicular's, which a reflection reflects or negates, and the
/// components change sign with it).
inline bool radial_direction(Vec3 v, Vec3 u, Vec3& out) {
  const Vec3 w = v - dot(v, u) * u;
  const double wl2 = dot(w, w), vl2 = dot(v, v);
  // Fast path: w well above the cancellation level of v.
  if (wl2 > 0x1p-40 * vl2 && wl2 > kSafeLo * kSafeLo && vl2 < kSafeHi * kSafeHi) {
    const Vec3 r = (1.0 / std::sqrt(wl2)) * w;
    out = normalized(r - dot(r, u) * u);
    return true;
  }
  const Vec3 e1 = any_perpendicular(u);
  const Vec3 e2 = cross(u, e1);
  const double a = dot(v, e1), b = dot(v, e2);
  const double m = std::max(std::fabs(a), std::fabs(b));
  if (!(m > 0) || !std::isfinite(m)) return false;
  const int e = std::ilogb(m);
  const double as = std::ldexp(a, -e), bs = std::ldexp(b, -e);
  const double l = std::sqrt(as * as + bs * bs);
  out = (as / l) * e1 + (bs / l) * e2;
  return true;
}

/// radial_direction, or any unit perpendicular to u (any_perpendicular's,
/// which a reflection need not reflect) when v has no direction across u.
inline Vec3 unit_perpendicular_part(Vec3 v, Vec3 u) {
  Vec3 out;
  return radial_direction(v, u, out) ? out : any_perpendicular(u);
}

/// Unit vector along d (non-zero, finite) and |d|, with one square root.
struct UnitAndLength {
  Vec3 u;
  double len;
  explicit UnitAndLength(Vec3 d) : len(safe_length(d)) { u = len > kSafeLo ? (1.0 / len) * d : normalized(d); }
};

/// The cylinder's mid point, unit axis and half height.
struct AxisFrame {
  Vec3 mid;
  Vec3 u;
  double half;
  explicit AxisFrame(const Cylinder& c) {
    const UnitAndLength a(c.q - c.p);
    u = a.u;
    half = 0.5 * a.len;
    mid = 0.5 * (c.p + c.q);
  }
};

/// An exact power-of-two rescaling of a whole scene: the queries run on the
/// scene scaled so that its largest magnitude is in [1, 2) whenever it lies
/// outside [2^-100, 2^100], which keeps squares and fourth powers far from
/// overflow and underflow. Inside that range nothing is scaled; the scaled
/// computation is in any case bit-identical to the unscaled one wherever
/// that one does not overflow or underflow (2^k commutes with rounding).
struct SceneScale {
  int e = 0;
  explicit SceneScale(double largest) {
    if (!(largest >= 0x1p-100 && largest <= 0x1p+100) && largest > 0 && std::isfinite(largest)) e = std::ilogb(largest);
  }
  double in(double v) const { return e == 0 ? v : std::ldexp(v, -e); }
  Vec3 in(Vec3 v) const { return e == 0 ? v : Vec3{in(v.x), in(v.y), in(v.z)}; }
  double out(double v) const { return e == 0 ? v : std::ldexp(v, e); }
  Vec3 out(Vec3 v) const { return e == 0 ? v : Vec3{out(v.x), out(v.y), out(v.z)}; }
  Cylinder in(const Cylinder& c) const { return {in(c.p), in(c.q), in(c.r)}; }
  Sphere in(const Sphere& s) const { return {in(s.c), in(s.r)}; }
  Segment in(const Segment& s) const { return {in(s.a), in(s.b)}; }
  Capsule in(const Capsule& s) const { return {in(s.p), in(s.q), in(s.r)}; }
  /// A box: centre and extents scale, the axes (directions) do not.
  Obb in(const Obb& b) const { return {in(b.c), b.axes, in(b.e)}; }
  Triangle in(const Triangle& t) const { return {in(t.a), in(t.b), in(t.c)}; }
};

inline double largest(const Cylinder& c) { return std::max(std::max(max_abs(c.p), max_abs(c.q)), c.r); }
inline double largest(const Sphere& s) { return std::max(max_abs(s.c), s.r); }
inline double largest(const Segment& s) { return std::max(max_abs(s.a), max_abs(s.b)); }
/// A box's centre and extents (its axes are directions, unit in the contract).
inline double largest(const Obb& b) { return std::max(max_abs(b.c), max_abs(b.e)); }
inline double largest(const Triangle& t) { return std::max(std::max(max_abs(t.a), max_abs(t.b)), max_abs(t.c)); }
inline double largest(const Capsule& s) { return std::max(std::max(max_abs(s.p), max_abs(s.q)), s.r); }

/// The entry root of q(t) = qa t^2 + 2 qb t + qc for a path that starts
/// outside (qc > 0), into t: qc / (-qb + sqrt(qb^2 - qa qc)), the smaller
/// root without cancellation; false when the path does not enter within
/// [0, 1]: it moves away or along (qb >= 0), never reaches (a negative
/// discriminant), or reaches after t = 1.
inline bool entry_root(double qa, double qb, double qc, double& t) {
  if (qb >= 0) return false;
  const double disc = qb * qb - qa * qc;
  if (disc < 0) return false;
  t = qc / (-qb + std::sqrt(disc));
  return !(t > 1);
}

/// A pair query's verdict in its rescaled scene (SceneScale of both shapes'
/// largest magnitude): `scaled(a', b')` decides the scaled shapes. Invalid
/// input gives "no overlap".
template <class A, class B, class Scaled>
bool overlap_rescaled(const A& a, const B& b, Scaled&& scaled) {
  if (!is_valid(a) || !is_valid(b)) return false;
  const SceneScale sc(std::max(largest(a), largest(b)));
  return scaled(sc.in(a), sc.in(b));
}

/// A pair query's contact in its rescaled scene: `scaled(a', b')` answers
/// the scaled shapes; its point and depth are scaled back, the depth
/// saturating to the largest double. Invalid input gives no contact.
template <class A, class B, class Scaled>
Contact collide_rescaled(const A& a, const B& b, Scaled&& scaled) {
  if (!is_valid(a) || !is_valid(b)) return {};
  const SceneScale sc(std::max(largest(a), largest(b)));
  Contact out = scaled(sc.in(a), sc.in(b));
  out.point = sc.out(out.point);
  out.depth = std::min(sc.out(out.depth), std::numeric_limits<double>::max());
  return out;
}

/// The side x vertex patch of a cylinder (axis from its start along unit u,
/// length len, radius r) against a polytope's vertex at w (relative to the
/// axis start): a vertex within best.o of the side and inside the slab by as
/// much offers its radial direction to `best`. A vertex on the axis line (to
/// rounding) has no radial direction: every one is alike, and a pick would
/// not reflect with the scene.
template <class Best>
inline void consider_side_vertex(Vec3 w, Vec3 u, double len, double r, Best& best) {
  const double z = dot(w, u);
  if (z < -best.o || z > len + best.o) return;
  const double rho = safe_length(w - z * u);
  if (rho < r - best.o || rho > r + best.o) return;
  Vec3 n;
  if (radial_direction(w, u, n)) best.consider(n);
}

/// A point relative to a cylinder: the closest point of the solid cylinder,
/// the distance to it, and (when outside) the unit normal from the cylinder
/// towards the point.
struct ClosestOnCylinder {
  Vec3 point;       ///< closest point of the solid cylinder (the point itself inside)
  Vec3 normal;      ///< outward unit normal towards the point (zero inside)
  double dist = 0;  ///< distance from the point to the solid cylinder
  bool inside = false;
};

/// The point p + v, given by its offset v from the cap centre p (computed by
/// the caller from nearby values, so that a scene far from the origin adds
/// no rounding of its own), against the cylinder of unit axis u and length
/// len. Offsets at or below `noise` carry no direction (they are rounding):
/// a radial offset below it gives any perpendicular, and of two offsets the
/// one below it is dropped, so that a tiny gap does not lose the normal to
/// cancellation (collide_cylinder_sphere regression 0002).
inline ClosestOnCylinder closest_on_cylinder(const Cylinder& cyl, Vec3 u, double len, Vec3 v, double noise) {
  ClosestOnCylinder out;
  const double ax = dot(v, u);
  const Vec3 w = v - ax * u;
  const double rho = safe_length(w);
  const double ea = ax < 0 ? -ax : (ax > len ? ax - len : 0.0);
  const double er = std::max(rho - cyl.r, 0.0);
  if (ea == 0 && er == 0) {
    out.point = cyl.p + v;
    out.inside = true;
    return out;
  }
  out.point = cyl.p + (std::clamp(ax, 0.0, len) * u + (rho > cyl.r ? (cyl.r / rho) * w : w));
  out.dist = safe_length(Vec3{ea, er, 0});
  auto radial_dir = [&] { return rho > noise ? unit_perpendicular_part(w, u) : any_perpendicular(u); };
  const double ean = ea > noise ? ea : 0.0, ern = er > noise ? er : 0.0;
  const Vec3 cap = 2 * ax >= len ? u : -u;
  if (ern == 0) out.normal = ean > 0 || ea >= er ? cap : radial_dir();
  else if (ean == 0) out.normal = radial_dir();
  else {
    const double big = std::max(ean, ern);  // scaled so that huge offsets do not overflow
    out.normal = normalized((ean / big) * cap + (ern / big) * radial_dir());
  }
  return out;
}

}  // namespace geomcheck::detail
