// geomcheck — helpers shared by the generators of every query (internal to
// properties/src/generators/). Each draw goes through rc::gen::inRange, so a
// shrunk case goes to the simplest mode, scale and offset.
#pragma once

#include <rapidcheck.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <utility>

#include "geomcheck/properties/generators.hpp"

namespace geomcheck::gen::detail {

constexpr int kTriples[][3] = {{3, 4, 5}, {5, 12, 13}, {8, 15, 17}, {7, 24, 25}, {20, 21, 29}, {9, 40, 41}};
constexpr int kNumTriples = 6;

inline double pick_real(double lo, double hi) { return *real(lo, hi); }
inline int pick_int(int lo, int hi) { return *rc::gen::inRange(lo, hi + 1); }

inline Vec3 pick_dir() {
  if (pick_int(0, 2) == 0) {  // axis-aligned, exactly
    Vec3 v{0, 0, 0};
    v[pick_int(0, 2)] = pick_int(0, 1) ? 1.0 : -1.0;
    return v;
  }
  for (;;) {
    const Vec3 v{pick_real(-1, 1), pick_real(-1, 1), pick_real(-1, 1)};
    const double l = length(v);
    if (l > 0.1) return (1.0 / l) * v;
  }
}

// Scene size (power of two, 2^-20..2^20) and an optional far-away offset.
struct Scene {
  double size;
  Vec3 offset;
};
inline Scene pick_scene() {
  Scene s;
  s.size = std::ldexp(1.0, pick_int(0, 3) == 0 ? pick_int(-20, 20) : 0);
  s.offset = {0, 0, 0};
  if (pick_int(0, 4) == 0) {
    const double far = std::ldexp(s.size, pick_int(10, 20));
    s.offset = {pick_real(-far, far), pick_real(-far, far), pick_real(-far, far)};
  }
  return s;
}

// Random cylinder in a scene, with its unit axis and a unit perpendicular.
struct Frame {
  Cylinder c;
  Vec3 u, e1, e2;
  double len;
};
inline Frame pick_cylinder(const Scene& sc) {
  Frame f;
  f.u = pick_dir();
  f.len = pick_real(0.05, 8) * sc.size;
  const double r = pick_int(0, 15) == 0 ? 0.0 : pick_real(0.05, 4) * sc.size;
  const Vec3 p = sc.offset + sc.size * Vec3{pick_real(-2, 2), pick_real(-2, 2), pick_real(-2, 2)};
  f.c = {p, p + f.len * f.u, r};
  f.u = (1.0 / length(f.c.q - f.c.p)) * (f.c.q - f.c.p);
  f.e1 = any_perpendicular(f.u);
  f.e2 = cross(f.u, f.e1);
  return f;
}

// A gap: touching (0), tiny either way, or large either way.
inline double pick_gap(double size) {
  switch (pick_int(0, 4)) {
    case 0: return 0;
    case 1: return std::ldexp(size, -pick_int(20, 50));
    case 2: return -std::ldexp(size, -pick_int(20, 50));
    case 3: return pick_real(0.01, 2) * size;
    default: return -pick_real(0.01, 2) * size;
  }
}

inline Vec3 radial_dir(const Frame& f, double angle) { return std::cos(angle) * f.e1 + std::sin(angle) * f.e2; }

// Exact integer construction along +z, then exact moves (axis permutation,
// sign flips, power-of-two scale, integer offset).
struct Exact {
  int perm, flips, e;
  Vec3 off;
  Vec3 apply(Vec3 v) const { return std::ldexp(1.0, e) * (turn(v) + off); }
  // A direction: the permutation and the flips only (exact, no scale).
  Vec3 turn(Vec3 v) const {
    Vec3 w{v[perm % 3], v[(perm + 1) % 3], v[(perm + 2) % 3]};
    if (flips & 1) w.x = -w.x;
    if (flips & 2) w.y = -w.y;
    if (flips & 4) w.z = -w.z;
    return w;
  }
  double len(double r) const { return std::ldexp(r, e); }
  // The world coordinate that construction coordinate i lands on, and the
  // sign it gets there.
  int slot(int i) const { return (i - perm + 3) % 3; }
  double sign(int i) const { return (flips >> slot(i)) & 1 ? -1.0 : 1.0; }
  // A displacement: the same moves without the offset.
  Vec3 dir(Vec3 v) const { return apply(v) - apply({0, 0, 0}); }
  // Moves the image of construction coordinate x by k ulps away from the
  // image of the plane x = 0 (k < 0: towards it).
  Vec3 nudge_x(Vec3 w, int k) const {
    const int i = (3 - perm) % 3;
    const double ref = apply({0, 0, 0})[i];
    double* v = i == 0 ? &w.x : (i == 1 ? &w.y : &w.z);
    *v = nudge(*v, *v >= ref ? k : -k);
    return w;
  }
};
inline Exact pick_exact() {
  return {pick_int(0, 2), pick_int(0, 7), pick_int(-20, 20),
          {double(pick_int(-1000, 1000)), double(pick_int(-1000, 1000)), double(pick_int(-1000, 1000))}};
}

// The draws of a targeted mode in which a ball of radius s (zero one time
// in 11) approaches a random cylinder to within a gap: the scene, the
// cylinder, s, the gap and the reach (how far from the cylinder a path
// starts), in that order.
struct Approach {
  Scene sc;
  Frame f;
  double s, gap, reach;
};
inline Approach pick_approach() {
  Approach a;
  a.sc = pick_scene();
  a.f = pick_cylinder(a.sc);
  a.s = pick_int(0, 10) == 0 ? 0.0 : pick_real(0.01, 3) * a.sc.size;
  a.gap = pick_gap(a.sc.size);
  a.reach = pick_real(0.1, 6) * a.sc.size;
  return a;
}

// An exact cylinder from a Pythagorean triple t1 scaled by k: axis from the
// origin to (0, 0, h), radius r = t1[2] k, in the exact frame `ex`; `len`
// an integer length for segments built against it. Draws t1, k, h, len and
// ex in that order.
struct ExactTripleCylinder {
  const int* t1;
  int k, h, len, r;
  Exact ex;
  Cylinder cyl;
};
inline ExactTripleCylinder pick_exact_triple_cylinder() {
  ExactTripleCylinder x;
  x.t1 = kTriples[pick_int(0, kNumTriples - 1)];
  x.k = pick_int(1, 4);
  x.h = pick_int(1, 20);
  x.len = pick_int(1, 40);
  x.ex = pick_exact();
  x.r = x.t1[2] * x.k;
  x.cyl = {x.ex.apply({0, 0, 0}), x.ex.apply({0, 0, double(x.h)}), x.ex.len(x.r)};
  return x;
}

// A segment touching that cylinder exactly, in construction coordinates:
// kind 0 tangent to the side (x = r, along y, at a drawn height within
// [0, h]), 1 tangent to the rim circle in the cap plane, 2 ending on the rim
// point (t1[0] k, t1[1] k, h) from outside along the triple's direction, 3
// on the side line, parallel to the axis, past both caps.
inline std::pair<Vec3, Vec3> exact_touching_segment(const ExactTripleCylinder& x, int kind) {
  const int* t1 = x.t1;
  const double k = x.k, h = x.h, len = x.len, r = x.r;
  switch (kind) {
    case 0: {
      const Vec3 a{r, -len, double(pick_int(0, x.h))};
      return {a, {r, len, a.z}};
    }
    case 1: return {{r, -len, h}, {r, len, h}};
    case 2: {
      const Vec3 b{t1[0] * k, t1[1] * k, h};
      return {{b.x + t1[0] * len, b.y + t1[1] * len, b.z + len}, b};
    }
    default: {
      const Vec3 a{t1[0] * k, t1[1] * k, -len};
      return {a, {a.x, a.y, h + len}};
    }
  }
}

// Directions (radial, axial, length) out of a rim point: the triples, and
// straight up from the cap and straight out from the side.
constexpr int kRimDirs[][3] = {{3, 4, 5}, {5, 12, 13}, {8, 15, 17}, {7, 24, 25}, {20, 21, 29}, {9, 40, 41},
                               {0, 1, 1}, {1, 0, 1}};
constexpr int kNumRimDirs = 8;

// A point of the cylinder's surface, a unit direction `out` in its normal
// cone (the distance to the cylinder grows along it at rate 1), and two unit
// directions perpendicular to `out`. For g >= 0, a line through at + g out
// along any combination of `tan` and `bi` stays at distance >= g from the
// cylinder, and a path leaving at + g out with a non-negative `out`
// component never gets closer (the distance is convex, its gradient there
// is `out`).
struct Spot {
  Vec3 at, out, tan, bi;
  std::string name;
};
// region 0: the rim (rim_kind 0: normal along the cap normal, 1: radial,
// 2: in between; -1: any of these), 1: the cap, 2: the side.
inline Spot pick_spot(const Frame& f, int region, int rim_kind = -1) {
  const double angle = pick_real(0, 6.283185307179586);
  const bool top = pick_int(0, 1);
  const Vec3 capn = top ? f.u : -f.u;
  const Vec3 capc = top ? f.c.q : f.c.p;
  const Vec3 rad = radial_dir(f, angle);
  Spot s;
  s.tan = cross(f.u, rad);
  if (region == 0) {
    const int kind = rim_kind >= 0 ? rim_kind : pick_int(0, 2);
    const double w = kind == 0 ? 1.0 : (kind == 1 ? 0.0 : pick_real(0.05, 0.95));
    s.at = capc + f.c.r * rad;
    s.out = (1.0 / std::hypot(w, 1 - w)) * (w * capn + (1 - w) * rad);
    s.name = kind == 0 ? "rim-above" : (kind == 1 ? "rim-side" : "rim-diag");
  } else if (region == 1) {
    s.at = capc + f.c.r * std::sqrt(pick_real(0, 1)) * rad;
    s.out = capn;
    s.name = "cap";
  } else {
    s.at = f.c.p + pick_real(0, 1) * (f.c.q - f.c.p) + f.c.r * rad;
    s.out = rad;
    s.name = "side";
  }
  s.bi = cross(s.tan, s.out);
  return s;
}
// A point of the solid cylinder.
inline Vec3 inside_point(const Frame& f) {
  const double l = pick_real(0, 1), rho = f.c.r * std::sqrt(pick_real(0, 1));
  return f.c.p + l * (f.c.q - f.c.p) + rho * radial_dir(f, pick_real(0, 6.283185307179586));
}
// A unit direction perpendicular to `out`.
inline Vec3 across(const Spot& s) {
  const double beta = pick_real(0, 6.283185307179586);
  return std::cos(beta) * s.tan + std::sin(beta) * s.bi;
}
// A unit direction with a non-negative `out` component.
inline Vec3 away(const Spot& s) {
  const Vec3 d = pick_dir();
  const double o = dot(d, s.out);
  return o >= 0 ? d : d - (2 * o) * s.out;
}
// A gap that puts a point at distance s + gap from a diagonal rim spot
// inside the corner region of the augmented cylinder (axial and radial
// offsets both <= s) but farther than s from the rim: a miss that a
// segment-vs-augmented-cylinder test reports as a hit.
inline double pocket_gap(const Spot& sp, const Frame& f, double s) {
  const double ax = std::fabs(dot(sp.out, f.u));
  const double m = std::max(ax, std::sqrt(std::max(0.0, 1 - ax * ax)));
  return pick_real(0.02, 0.98) * s * (1 / m - 1);
}
// Tilt away from parallel: none, 1e-8 or 1e-16.
inline double pick_tilt() {
  switch (pick_int(0, 2)) {
    case 0: return 0;
    case 1: return 1e-8;
    default: return 1e-16;
  }
}
inline std::string tilt_tag(double tilt) { return tilt == 0 ? "" : (tilt > 1e-12 ? "-1e-8" : "-1e-16"); }
inline std::string gap_tag(double gap) { return gap == 0 ? "-touch" : (gap > 0 ? "-gap" : "-deep"); }
inline std::string ulps_tag(int ulps) { return ulps == 0 ? "-touch" : (ulps > 0 ? "-ulps-in" : "-ulps-out"); }


constexpr double kTwoPi = 6.283185307179586;

using Axes = std::array<Vec3, 3>;
using ObbCase = std::pair<CylinderObbCase, std::string>;

// The six permutations of three coordinates (even ones first).
constexpr int kPerms[6][3] = {{0, 1, 2}, {1, 2, 0}, {2, 0, 1}, {0, 2, 1}, {2, 1, 0}, {1, 0, 2}};

// |a_i . a_j - delta_ij| <= tol * 2^-52 for all i, j, the dot products in
// doubles: production's contract is tol = 16.
inline bool orthonormal(const Axes& a, double tol) {
  for (int i = 0; i < 3; ++i)
    for (int j = i; j < 3; ++j)
      if (!(std::fabs(dot(a[i], a[j]) - (i == j ? 1.0 : 0.0)) <= tol * 0x1p-52)) return false;
  return true;
}

// Gram-Schmidt in doubles: keeps a[0]'s direction and the handedness.
inline Axes gram_schmidt(Axes a) {
  a[0] = (1 / length(a[0])) * a[0];
  a[1] = a[1] - dot(a[0], a[1]) * a[0];
  a[1] = (1 / length(a[1])) * a[1];
  a[2] = a[2] - dot(a[0], a[2]) * a[0];
  a[2] = a[2] - dot(a[1], a[2]) * a[1];
  a[2] = (1 / length(a[2])) * a[2];
  return a;
}

// A frame computed in doubles (orthonormal up to rounding), brought to
// within 4 eps of orthonormal (the contract allows 16) by Gram-Schmidt
// passes where it is not already.
inline Axes settle(Axes a) {
  for (int i = 0; i < 4 && !orthonormal(a, 4); ++i) a = gram_schmidt(a);
  return a;
}

// An integer matrix over a positive denominator: a rotation by a
// Pythagorean angle about a coordinate axis, or a product of such.
struct RatRot {
  long m[3][3];
  long den;
};
constexpr int kRotTriples[2][3] = {{3, 4, 5}, {5, 12, 13}};
constexpr int kNumRotations = 24;
// index 0: the identity; 1..24: about axis (i-1)/8, by the triple
// ((i-1)/4)%2, with (cos, sin) = (a, b), (b, a), (a, -b), (b, -a) over c.
inline RatRot pyth_rotation(int index) {
  RatRot r{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, 1};
  if (index <= 0) return r;
  const int axis = (index - 1) / 8, tr = ((index - 1) / 4) % 2, var = (index - 1) % 4;
  const long a = kRotTriples[tr][0], b = kRotTriples[tr][1], c = kRotTriples[tr][2];
  const long co = var % 2 == 0 ? a : b;
  const long si = (var % 2 == 0 ? b : a) * (var >= 2 ? -1 : 1);
  const int j = (axis + 1) % 3, k = (axis + 2) % 3;
  for (auto& row : r.m)
    for (long& x : row) x = 0;
  r.m[axis][axis] = c;
  r.m[j][j] = co;
  r.m[j][k] = -si;
  r.m[k][j] = si;
  r.m[k][k] = co;
  r.den = c;
  return r;
}
inline RatRot product(const RatRot& x, const RatRot& y) {
  RatRot r{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      r.m[i][j] = 0;
      for (int k = 0; k < 3; ++k) r.m[i][j] += x.m[i][k] * y.m[k][j];
    }
  r.den = x.den * y.den;
  return r;
}
// The columns of P R as box axes, P the signed permutation (perm, signs):
// each entry an integer over the denominator, rounded once. Signed
// permutations alone are exact; one rotation is exactly orthogonal with unit
// lengths to rounding; products are orthonormal to a few eps (checked; a
// Gram-Schmidt pass otherwise).
inline Axes rat_frame(const RatRot& r, int perm, int signs) {
  Axes a;
  for (int i = 0; i < 3; ++i) {
    double col[3];
    for (int j = 0; j < 3; ++j) col[j] = double(r.m[j][i]) / double(r.den);
    for (int j = 0; j < 3; ++j) {
      const double v = col[kPerms[perm][j]];
      (j == 0 ? a[i].x : (j == 1 ? a[i].y : a[i].z)) = (signs >> j) & 1 ? -v : v;
    }
  }
  return orthonormal(a, 4) ? a : settle(a);
}
// A uniform random rotation: a unit quaternion (rejection in the 4-ball)
// turned into a matrix in doubles.
inline Axes quaternion_frame() {
  double w, x, y, z, n2;
  do {
    w = pick_real(-1, 1), x = pick_real(-1, 1), y = pick_real(-1, 1), z = pick_real(-1, 1);
    n2 = w * w + x * x + y * y + z * z;
  } while (!(n2 > 1e-4 && n2 <= 1));
  const double s = 1 / std::sqrt(n2);
  w *= s, x *= s, y *= s, z *= s;
  return settle({Vec3{1 - 2 * (y * y + z * z), 2 * (x * y + w * z), 2 * (x * z - w * y)},
                 Vec3{2 * (x * y - w * z), 1 - 2 * (x * x + z * z), 2 * (y * z + w * x)},
                 Vec3{2 * (x * z + w * y), 2 * (y * z - w * x), 1 - 2 * (x * x + y * y)}});
}
// Box frames, either handedness: a signed permutation (exact), times one
// Pythagorean rotation (3-4-5 or 5-12-13 about a coordinate axis) or a
// product of two, or a rounded random rotation.
inline Axes pick_box_frame() {
  const int kind = pick_int(0, 3);
  if (kind == 3) return quaternion_frame();
  const int perm = pick_int(0, 5), signs = pick_int(0, 7);
  RatRot r = pyth_rotation(kind >= 1 ? pick_int(1, kNumRotations) : 0);
  if (kind == 2) r = product(r, pyth_rotation(pick_int(1, kNumRotations)));
  return rat_frame(r, perm, signs);
}

inline Vec3 unit(Vec3 v) { return (1 / length(v)) * v; }

// Rim (twice as likely), cap or side.
inline int pick_region() {
  const int r = pick_int(0, 3);
  return r <= 1 ? 0 : r - 1;
}

// Through a volatile float: g++ 12.2 at -O2 vectorizes the conversions of
// a Vec3's y and z and drops the rounding to float (double(float(v)) came
// back as v; fixed here since 2026-11-28, when g++'s and clang's cases were
// first compared draw for draw).
inline double to_f32(double v) {
  volatile float f = static_cast<float>(v);
  return f;
}
inline Vec3 to_f32(Vec3 v) { return {to_f32(v.x), to_f32(v.y), to_f32(v.z)}; }

// A point of the cylinder minimising n.x (n unit): the lower cap's centre
// plus r times the unit part of -n across the axis (the cap centre when n is
// along the axis). Computed from the stored end points.
inline Vec3 cylinder_lowest(const Cylinder& c, Vec3 n) {
  const Vec3 u = unit(c.q - c.p);
  const double nu = dot(n, u);
  const Vec3 cap = nu > 0 ? c.p : c.q;
  const Vec3 m = n - nu * u;
  const double lm = length(m);
  return lm > 0 ? cap - (c.r / lm) * m : cap;
}

/// Three wild doubles.
inline Vec3 wild_vec() { return {*wild_double(), *wild_double(), *wild_double()}; }

}  // namespace geomcheck::gen::detail
