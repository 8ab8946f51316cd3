#include "generators.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace geomcheck::gen {

namespace {

constexpr int kTriples[][3] = {{3, 4, 5}, {5, 12, 13}, {8, 15, 17}, {7, 24, 25}, {20, 21, 29}, {9, 40, 41}};
constexpr int kNumTriples = 6;

double pick_real(double lo, double hi) { return *real(lo, hi); }
int pick_int(int lo, int hi) { return *rc::gen::inRange(lo, hi + 1); }

Vec3 pick_dir() {
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
Scene pick_scene() {
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
Frame pick_cylinder(const Scene& sc) {
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
double pick_gap(double size) {
  switch (pick_int(0, 4)) {
    case 0: return 0;
    case 1: return std::ldexp(size, -pick_int(20, 50));
    case 2: return -std::ldexp(size, -pick_int(20, 50));
    case 3: return pick_real(0.01, 2) * size;
    default: return -pick_real(0.01, 2) * size;
  }
}

Vec3 radial_dir(const Frame& f, double angle) { return std::cos(angle) * f.e1 + std::sin(angle) * f.e2; }

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
Exact pick_exact() {
  return {pick_int(0, 2), pick_int(0, 7), pick_int(-20, 20),
          {double(pick_int(-1000, 1000)), double(pick_int(-1000, 1000)), double(pick_int(-1000, 1000))}};
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
Spot pick_spot(const Frame& f, int region, int rim_kind = -1) {
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
Vec3 inside_point(const Frame& f) {
  const double l = pick_real(0, 1), rho = f.c.r * std::sqrt(pick_real(0, 1));
  return f.c.p + l * (f.c.q - f.c.p) + rho * radial_dir(f, pick_real(0, 6.283185307179586));
}
// A unit direction perpendicular to `out`.
Vec3 across(const Spot& s) {
  const double beta = pick_real(0, 6.283185307179586);
  return std::cos(beta) * s.tan + std::sin(beta) * s.bi;
}
// A unit direction with a non-negative `out` component.
Vec3 away(const Spot& s) {
  const Vec3 d = pick_dir();
  const double o = dot(d, s.out);
  return o >= 0 ? d : d - (2 * o) * s.out;
}
// A gap that puts a point at distance s + gap from a diagonal rim spot
// inside the corner region of the augmented cylinder (axial and radial
// offsets both <= s) but farther than s from the rim: a miss that a
// segment-vs-augmented-cylinder test reports as a hit.
double pocket_gap(const Spot& sp, const Frame& f, double s) {
  const double ax = std::fabs(dot(sp.out, f.u));
  const double m = std::max(ax, std::sqrt(std::max(0.0, 1 - ax * ax)));
  return pick_real(0.02, 0.98) * s * (1 / m - 1);
}
// Tilt away from parallel: none, 1e-8 or 1e-16.
double pick_tilt() {
  switch (pick_int(0, 2)) {
    case 0: return 0;
    case 1: return 1e-8;
    default: return 1e-16;
  }
}
std::string tilt_tag(double tilt) { return tilt == 0 ? "" : (tilt > 1e-12 ? "-1e-8" : "-1e-16"); }
std::string gap_tag(double gap) { return gap == 0 ? "-touch" : (gap > 0 ? "-gap" : "-deep"); }
std::string ulps_tag(int ulps) { return ulps == 0 ? "-touch" : (ulps > 0 ? "-ulps-in" : "-ulps-out"); }

}  // namespace

rc::Gen<double> real(double lo, double hi) {
  return rc::gen::map(rc::gen::inRange<std::int64_t>(0, std::int64_t(1) << 52), [lo, hi](std::int64_t k) {
    return lo + (hi - lo) * std::ldexp(double(k), -52);
  });
}

double nudge(double v, int k) {
  for (; k > 0; --k) v = std::nextafter(v, INFINITY);
  for (; k < 0; ++k) v = std::nextafter(v, -INFINITY);
  return v;
}

// rc::gen::inRange scales its range with the size; every generator here is
// resized to the nominal size so that every mode, scale and offset is reachable.
rc::Gen<std::pair<CylinderSphereCase, std::string>> cylinder_sphere_case() {
  return rc::gen::resize(100, rc::gen::exec([]() -> std::pair<CylinderSphereCase, std::string> {
    const int mode = pick_int(0, 7);
    if (mode == 7) {  // exact Pythagorean touch, nudged by k ulps
      const auto& t1 = kTriples[pick_int(0, kNumTriples - 1)];
      const auto& t2 = kTriples[pick_int(0, kNumTriples - 1)];
      const int k = pick_int(1, 4), h = pick_int(1, 20), mm = pick_int(1, 3), z0 = pick_int(-10, 10);
      const int where = pick_int(0, 2);
      const Exact ex = pick_exact();
      Cylinder cyl{ex.apply({0, 0, double(z0)}), ex.apply({0, 0, double(z0 + h)}), ex.len(t1[2] * k)};
      Vec3 c;
      double s;
      std::string tag;
      if (where == 0) {  // rim: offset (e a, e b, f c) * M from the rim point, length M c g
        const double a = t1[0], b = t1[1], cc = t1[2];
        c = Vec3{a * k + mm * t2[0] * a, b * k + mm * t2[0] * b, double(z0 + h) + mm * t2[1] * cc};
        s = mm * cc * t2[2];
        tag = "exact-rim";
      } else if (where == 1) {  // side: radial distance c K, K > k
        const int kk = k + mm;
        c = Vec3{double(t1[0] * kk), double(t1[1] * kk), double(z0 + pick_int(0, h))};
        s = t1[2] * mm;
        tag = "exact-side";
      } else {  // cap plane
        s = pick_int(1, 50);
        c = Vec3{double(pick_int(-t1[0] * k, t1[0] * k)), double(pick_int(-t1[1] * k, t1[1] * k)), double(z0) - s};
        tag = "exact-cap";
      }
      const int ulps = pick_int(-2, 2);
      Sphere sph{ex.apply(c), nudge(ex.len(s), ulps)};
      return {{cyl, sph}, tag + (ulps == 0 ? "-touch" : (ulps > 0 ? "-ulps-in" : "-ulps-out"))};
    }
    const Scene sc = pick_scene();
    const Frame f = pick_cylinder(sc);
    const double half = 0.5 * f.len;
    const Vec3 mid = 0.5 * (f.c.p + f.c.q);
    double s = pick_int(0, 10) == 0 ? 0.0 : pick_real(0.01, 3) * sc.size;
    const double gap = pick_gap(sc.size);
    const double angle = pick_real(0, 6.283185307179586);
    const bool top = pick_int(0, 1);
    const Vec3 capn = top ? f.u : -f.u;
    const Vec3 capc = top ? f.c.q : f.c.p;
    Vec3 c;
    std::string tag;
    switch (mode) {
      case 0: {
        c = mid + sc.size * Vec3{pick_real(-6, 6), pick_real(-6, 6), pick_real(-6, 6)};
        tag = "random";
        break;
      }
      case 1: {  // rim, direction anywhere in the normal cone
        const double w = pick_real(0, 1);
        const Vec3 rad = radial_dir(f, angle);
        const Vec3 dir = (1.0 / std::hypot(w, 1 - w)) * (w * capn + (1 - w) * rad);
        c = capc + f.c.r * rad + (s + gap) * dir;
        tag = "rim";
        break;
      }
      case 2: {  // cap plane
        const double rho = f.c.r * std::sqrt(pick_real(0, 1));
        c = capc + rho * radial_dir(f, angle) + (s + gap) * capn;
        tag = "cap";
        break;
      }
      case 3: {  // side
        c = f.c.p + pick_real(0, 1) * (f.c.q - f.c.p) + (f.c.r + s + gap) * radial_dir(f, angle);
        tag = "side";
        break;
      }
      case 4: {  // centre inside
        c = f.c.p + pick_real(0, 1) * (f.c.q - f.c.p) + f.c.r * pick_real(0, 1) * radial_dir(f, angle);
        tag = "inside";
        break;
      }
      case 5: {  // sphere around the whole cylinder, or just not
        c = mid + sc.size * Vec3{pick_real(-1, 1), pick_real(-1, 1), pick_real(-1, 1)};
        s = std::hypot(half, f.c.r) + length(c - mid) + gap;
        if (s < 0) s = 0;
        tag = "containing";
        break;
      }
      default: {  // on the cap-plane extension just outside the rim
        c = capc + (f.c.r + s + std::fabs(gap)) * radial_dir(f, angle) + pick_real(-1, 1) * sc.size * capn;
        tag = "beyond-rim";
        break;
      }
    }
    if (gap != 0 && (mode >= 1 && mode <= 3)) tag += gap > 0 ? "-gap" : "-deep";
    else if (mode >= 1 && mode <= 3) tag += "-touch";
    Sphere sph{c, s};
    if (mode >= 1 && mode <= 3 && gap == 0) sph.r = nudge(s, pick_int(-2, 2));
    return {{f.c, sph}, tag};
  }));
}

rc::Gen<std::pair<SegmentCylinderCase, std::string>> segment_cylinder_case() {
  return rc::gen::resize(100, rc::gen::exec([]() -> std::pair<SegmentCylinderCase, std::string> {
    const int mode = pick_int(0, 8);
    if (mode == 8) {  // exact: tangent lines, rim touches, endpoint on the surface
      const auto& t1 = kTriples[pick_int(0, kNumTriples - 1)];
      const int k = pick_int(1, 4), h = pick_int(1, 20), len = pick_int(1, 40);
      const Exact ex = pick_exact();
      const int r = t1[2] * k;
      Cylinder cyl{ex.apply({0, 0, 0}), ex.apply({0, 0, double(h)}), ex.len(r)};
      Vec3 a, b;
      std::string tag;
      const int ulps = pick_int(-2, 2);
      switch (pick_int(0, 3)) {
        case 0:  // tangent to the side: x = r, along y, at a height within [0, h]
          a = {double(r), double(-len), double(pick_int(0, h))};
          b = {double(r), double(len), a.z};
          tag = "exact-side-tangent";
          break;
        case 1:  // tangent to the rim circle in the cap plane
          a = {double(r), double(-len), double(h)};
          b = {double(r), double(len), double(h)};
          tag = "exact-rim-tangent";
          break;
        case 2:  // ends exactly on the rim point (a k, b k, h), from outside along the triple direction
          b = {double(t1[0] * k), double(t1[1] * k), double(h)};
          a = {b.x + t1[0] * len, b.y + t1[1] * len, b.z + len};
          tag = "exact-end-on-rim";
          break;
        default:  // parallel to the axis, on the side surface line, from below the p cap
          a = {double(t1[0] * k), double(t1[1] * k), double(-len)};
          b = {a.x, a.y, double(h + len)};
          tag = "exact-axis-parallel-on-side";
          break;
      }
      a.x = nudge(a.x, ulps);
      b.x = nudge(b.x, ulps);
      return {{{ex.apply(a), ex.apply(b)}, cyl}, tag + (ulps == 0 ? "" : (ulps > 0 ? "-ulps" : "+ulps"))};
    }
    const Scene sc = pick_scene();
    const Frame f = pick_cylinder(sc);
    const double gap = pick_gap(sc.size);
    const double angle = pick_real(0, 6.283185307179586);
    const bool top = pick_int(0, 1);
    const Vec3 capn = top ? f.u : -f.u;
    const Vec3 capc = top ? f.c.q : f.c.p;
    const Vec3 rad = radial_dir(f, angle);
    const Vec3 tan = cross(f.u, rad);
    const double reach = pick_real(0.1, 6) * sc.size;
    Vec3 a, b;
    std::string tag;
    switch (mode) {
      case 0:
        a = capc + sc.size * Vec3{pick_real(-6, 6), pick_real(-6, 6), pick_real(-6, 6)};
        b = capc + sc.size * Vec3{pick_real(-6, 6), pick_real(-6, 6), pick_real(-6, 6)};
        tag = "random";
        break;
      case 1: {  // parallel to the axis into a cap (or just past the rim)
        const double rho = pick_int(0, 1) ? f.c.r * std::sqrt(pick_real(0, 1)) : f.c.r + gap;
        a = capc + rho * rad + reach * capn;
        b = a - (reach + pick_real(0, 2) * f.len) * capn;
        tag = "axis-parallel-cap";
        break;
      }
      case 2: {  // grazing the side: tangent direction, radial offset r + gap
        const Vec3 x = f.c.p + pick_real(0, 1) * (f.c.q - f.c.p) + (f.c.r + gap) * rad;
        const Vec3 dir = tan + pick_real(-0.3, 0.3) * f.u;
        a = x - reach * dir;
        b = x + pick_real(0, 2) * reach * dir;
        tag = "graze-side";
        break;
      }
      case 3: {  // tangent to the rim circle, in or near the cap plane
        const Vec3 x = capc + (f.c.r + gap) * rad;
        const Vec3 dir = tan + pick_real(-0.1, 0.1) * capn;
        a = x - reach * dir;
        b = x + pick_real(0, 2) * reach * dir;
        tag = "rim-tangent";
        break;
      }
      case 4: {  // starting inside
        a = f.c.p + pick_real(0, 1) * (f.c.q - f.c.p) + f.c.r * pick_real(0, 1) * rad;
        b = a + sc.size * Vec3{pick_real(-6, 6), pick_real(-6, 6), pick_real(-6, 6)};
        tag = "start-inside";
        break;
      }
      case 5: {  // zero length: inside, on the surface, or outside
        a = f.c.p + pick_real(-0.2, 1.2) * (f.c.q - f.c.p) + (f.c.r + (pick_int(0, 1) ? gap : 0.0)) * rad;
        b = a;
        tag = "zero-length";
        break;
      }
      case 6: {  // through both caps, near the axis direction
        const Vec3 off = f.c.r * pick_real(0, 1.5) * rad;
        a = f.c.p - reach * f.u + off;
        b = f.c.q + reach * f.u + off + pick_real(-0.5, 0.5) * f.c.r * tan;
        tag = "through-caps";
        break;
      }
      default: {  // aimed at the rim from outside, ending just past it
        const double w = pick_real(0, 1);
        const Vec3 out = (1.0 / std::hypot(w, 1 - w)) * (w * capn + (1 - w) * rad);
        const Vec3 target = capc + f.c.r * rad + gap * out;
        const Vec3 from = target + reach * (out + pick_real(-0.5, 0.5) * tan);
        a = from;
        b = from + pick_real(1, 2) * (target - from);
        tag = "aim-rim";
        break;
      }
    }
    if (mode >= 1 && mode <= 3) tag += gap == 0 ? "-touch" : (gap > 0 ? "-gap" : "-deep");
    return {{{a, b}, f.c}, tag};
  }));
}

namespace {

// Exact integer constructions for cylinder/capsule, then exact moves. The
// capsule radius is the exact distance, nudged by k ulps.
std::pair<CylinderCapsuleCase, std::string> exact_cylinder_capsule() {
  const auto& t1 = kTriples[pick_int(0, kNumTriples - 1)];
  const auto& t2 = kRimDirs[pick_int(0, kNumRimDirs - 1)];
  const int k = pick_int(1, 4), h = pick_int(1, 20), mm = pick_int(1, 3), z0 = pick_int(-10, 10);
  const Exact ex = pick_exact();
  const double a = t1[0], b = t1[1], c = t1[2];
  Cylinder cyl{ex.apply({0, 0, double(z0)}), ex.apply({0, 0, double(z0 + h)}), ex.len(c * k)};
  const Vec3 tng{-b, a, 0};  // tangent to the rim circle at (a k, b k)
  Vec3 p, q;
  double s;
  std::string tag;
  switch (pick_int(0, 5)) {
    case 0: {  // at the rim point (a k, b k, top): offset (e a, e b, f c) * mm, length mm c g
      const Vec3 rim{a * k, b * k, double(z0 + h)};
      const Vec3 out{t2[0] * a, t2[0] * b, t2[1] * c};
      const Vec3 bin{-t2[1] * a, -t2[1] * b, t2[0] * c};  // perpendicular to out and tng
      const Vec3 e = rim + double(mm) * out;
      s = mm * c * t2[2];
      if (pick_int(0, 1)) {  // an end at e, the segment leaving with a non-negative out component
        p = e;
        q = e + double(pick_int(0, 3)) * out + double(pick_int(-5, 5)) * tng + double(pick_int(-5, 5)) * bin;
        tag = "exact-rim-end";
      } else {  // the segment through e, perpendicular to out (a point when v == 0)
        const Vec3 v = double(pick_int(-3, 3)) * tng + double(pick_int(-3, 3)) * bin;
        p = e - double(pick_int(1, 10)) * v;
        q = e + double(pick_int(1, 10)) * v;
        tag = "exact-rim-through";
      }
      break;
    }
    case 1: {  // parallel to the axis at radial distance c K, K > k
      const int kk = k + mm;
      const int za = pick_int(-10, h), zb = pick_int(std::max(za, 0), h + 10);
      p = {double(t1[0] * kk), double(t1[1] * kk), double(z0 + za)};
      q = {p.x, p.y, double(z0 + zb)};
      s = c * mm;
      tag = "exact-side-parallel";
      break;
    }
    case 2: {  // perpendicular to the axis, along the tangent at radial distance c K
      const int kk = k + mm;
      const Vec3 x{double(t1[0] * kk), double(t1[1] * kk), double(z0 + pick_int(0, h))};
      p = x - double(pick_int(0, 10)) * tng;
      q = x + double(pick_int(0, 10)) * tng;
      s = c * mm;
      tag = "exact-side-perp";
      break;
    }
    case 3: {  // above the cap: one end over the disk at height s, the other anywhere not lower
      s = pick_int(1, 50);
      p = {double(pick_int(-t1[0] * k, t1[0] * k)), double(pick_int(-t1[1] * k, t1[1] * k)), double(z0 + h) + s};
      q = {double(pick_int(-60, 60)), double(pick_int(-60, 60)), p.z + pick_int(0, 5)};
      tag = "exact-cap";
      break;
    }
    case 4: {  // coaxial beyond the top cap, either direction
      s = pick_int(1, 50);
      p = {0, 0, double(z0 + h) + s};
      q = {0, 0, p.z + pick_int(0, 10)};
      tag = "exact-coaxial";
      break;
    }
    default: {  // zero cylinder radius: the capsule crosses over the segment at distance c mm
      cyl.r = 0;
      const Vec3 x{a * mm, b * mm, double(z0 + pick_int(0, h))};
      p = x - double(pick_int(1, 10)) * tng;
      q = x + double(pick_int(1, 10)) * tng;
      s = c * mm;
      tag = "exact-zero-radius-cylinder";
      break;
    }
  }
  if (pick_int(0, 1)) std::swap(p, q);
  const int ulps = pick_int(-2, 2);
  return {{cyl, Capsule{ex.apply(p), ex.apply(q), nudge(ex.len(s), ulps)}}, tag + ulps_tag(ulps)};
}

// Zero capsule radius (the capsule is its segment): exactly on the surface,
// then moved by k ulps outwards (k > 0) or inwards.
std::pair<CylinderCapsuleCase, std::string> exact_segment_capsule() {
  const auto& t1 = kTriples[pick_int(0, kNumTriples - 1)];
  const int k = pick_int(1, 4), h = pick_int(1, 20), len = pick_int(1, 40);
  const Exact ex = pick_exact();
  const int r = t1[2] * k;
  Cylinder cyl{ex.apply({0, 0, 0}), ex.apply({0, 0, double(h)}), ex.len(r)};
  Vec3 a, b;
  std::string tag;
  switch (pick_int(0, 4)) {
    case 0:  // tangent to the side
      a = {double(r), double(-len), double(pick_int(0, h))};
      b = {double(r), double(len), a.z};
      tag = "exact-segment-side-tangent";
      break;
    case 1:  // tangent to the rim circle in the cap plane
      a = {double(r), double(-len), double(h)};
      b = {double(r), double(len), double(h)};
      tag = "exact-segment-rim-tangent";
      break;
    case 2:  // ends on the rim point (a k, b k, h), from outside
      b = {double(t1[0] * k), double(t1[1] * k), double(h)};
      a = {b.x + t1[0] * len, b.y + t1[1] * len, b.z + len};
      tag = "exact-segment-end-on-rim";
      break;
    case 3:  // on the side line, parallel to the axis, past both caps
      a = {double(t1[0] * k), double(t1[1] * k), double(-len)};
      b = {a.x, a.y, double(h + len)};
      tag = "exact-segment-on-side";
      break;
    default:  // zero cylinder radius too: two segments crossing
      cyl.r = 0;
      a = {0, double(-len), double(pick_int(0, h))};
      b = {0, double(len), a.z};
      tag = "exact-segment-crosses-zero-radius";
      break;
  }
  const int ulps = pick_int(-2, 2);
  const std::string moved = cyl.r == 0 ? "-ulps-off" : (ulps > 0 ? "-ulps-out" : "-ulps-in");
  return {{cyl, Capsule{ex.nudge_x(ex.apply(a), ulps), ex.nudge_x(ex.apply(b), ulps), 0.0}},
          tag + (ulps == 0 ? "-touch" : moved)};
}

}  // namespace

rc::Gen<std::pair<CylinderCapsuleCase, std::string>> cylinder_capsule_case() {
  return rc::gen::resize(100, rc::gen::exec([]() -> std::pair<CylinderCapsuleCase, std::string> {
    const int mode = pick_int(0, 9);
    if (mode == 8) return exact_cylinder_capsule();
    if (mode == 9) return exact_segment_capsule();
    const Scene sc = pick_scene();
    const Frame f = pick_cylinder(sc);
    const double s = pick_int(0, 10) == 0 ? 0.0 : pick_real(0.01, 3) * sc.size;
    double gap = pick_gap(sc.size);
    const double reach = pick_real(0.1, 6) * sc.size;
    bool graded = true;  // the closest approach is s + gap: tag the gap, nudge a touch
    Vec3 p, q;
    std::string tag;
    switch (mode) {
      case 0: {
        p = 0.5 * (f.c.p + f.c.q) + sc.size * Vec3{pick_real(-5, 5), pick_real(-5, 5), pick_real(-5, 5)};
        q = pick_int(0, 9) == 0 ? p : p + sc.size * Vec3{pick_real(-5, 5), pick_real(-5, 5), pick_real(-5, 5)};
        tag = "random";
        graded = false;
        break;
      }
      case 1: {  // parallel or anti-parallel to the axis beside the side, exactly or tilted
        const Spot sp = pick_spot(f, 2);
        const double tilt = pick_tilt();
        const double phi = pick_real(0, 6.283185307179586);
        const bool anti = pick_int(0, 1);
        const Vec3 v = (anti ? -f.u : f.u) + tilt * (std::cos(phi) * sp.tan + std::sin(phi) * sp.out);
        const Vec3 e = sp.at + (s + gap) * sp.out;
        p = e - pick_real(0, 1.5) * f.len * v;
        q = e + pick_real(0, 1.5) * f.len * v;
        tag = std::string(anti ? "anti-parallel" : "parallel") + tilt_tag(tilt);
        break;
      }
      case 2: {  // on the axis line beyond a cap, pointing away, either orientation
        const bool top = pick_int(0, 1);
        const Vec3 capn = top ? f.u : -f.u;
        const double tilt = pick_tilt();
        const Vec3 e = (top ? f.c.q : f.c.p) + (s + gap) * capn;
        const Vec3 far = e + reach * (capn + tilt * radial_dir(f, pick_real(0, 6.283185307179586)));
        const bool flip = pick_int(0, 1);
        p = flip ? far : e;
        q = flip ? e : far;
        tag = std::string(dot(q - p, f.u) > 0 ? "coaxial" : "coaxial-anti") + tilt_tag(tilt);
        break;
      }
      case 3: {  // perpendicular to the axis: beside the side along the tangent, or over a cap
        const bool side = pick_int(0, 1);
        const Spot sp = pick_spot(f, side ? 2 : 1);
        const Vec3 v = side ? sp.tan : across(sp);
        const Vec3 e = sp.at + (s + gap) * sp.out;
        p = e - pick_real(0, 1) * reach * v;
        q = e + pick_real(0, 1) * reach * v;
        tag = side ? "perp-side" : "perp-cap";
        break;
      }
      case 4: {  // an end sphere at the rim, a cap or the side; p == q: a sphere
        const Spot sp = pick_spot(f, pick_int(0, 2));
        const Vec3 e = sp.at + (s + gap) * sp.out;
        const bool point = pick_int(0, 4) == 0;
        const Vec3 other = point ? e : e + reach * away(sp);
        const bool flip = pick_int(0, 1);
        p = flip ? other : e;
        q = flip ? e : other;
        tag = (point ? "point-" : "end-") + sp.name;
        break;
      }
      case 5: {  // through the space around the rim, perpendicular to the normal there
        const Spot sp = pick_spot(f, 0);
        bool pocket = false;
        if (s > 0 && sp.name == "rim-diag" && pick_int(0, 2) == 0) {
          gap = pocket_gap(sp, f, s);
          pocket = true;
        }
        const Vec3 v = across(sp);
        const Vec3 e = sp.at + (s + gap) * sp.out;
        p = e - pick_real(0, 1) * reach * v;
        q = e + pick_real(0, 1) * reach * v;
        tag = "graze-" + sp.name;
        if (pocket) {
          tag += "-pocket";
          graded = false;
        }
        break;
      }
      case 6: {  // crossing a cap plane, inside or outside the radius
        const bool top = pick_int(0, 1);
        const Vec3 capn = top ? f.u : -f.u;
        const Vec3 rad = radial_dir(f, pick_real(0, 6.283185307179586));
        const Vec3 x = (top ? f.c.q : f.c.p) + (pick_real(0, 1.5) * f.c.r + pick_real(0, 1) * s) * rad;
        const Vec3 dir = capn + pick_real(-2, 2) * rad + pick_real(-2, 2) * cross(f.u, rad);
        p = x + pick_real(0.05, 1) * reach * dir;
        q = x - pick_real(0.05, 1) * reach * dir;
        if (pick_int(0, 1)) std::swap(p, q);
        tag = "cross-cap";
        graded = false;
        break;
      }
      default: {  // the capsule's segment inside the cylinder
        p = inside_point(f);
        q = inside_point(f);
        tag = "inside";
        graded = false;
        break;
      }
    }
    Capsule cap{p, q, s};
    if (graded) {
      tag += gap_tag(gap);
      if (gap == 0) cap.r = std::max(0.0, nudge(s, pick_int(-2, 2)));
    }
    return {{f.c, cap}, tag};
  }));
}

namespace {

// Exact integer sweeps, then exact moves. The ball radius is the exact
// closest approach, nudged by k ulps (the pocket: a certain miss).
std::pair<SweepCylinderCase, std::string> exact_sweep_cylinder() {
  const int dir = pick_int(0, kNumRimDirs - 1);
  const auto& t1 = kTriples[pick_int(0, kNumTriples - 1)];
  const auto& t2 = kRimDirs[dir];
  const int k = pick_int(1, 4), h = pick_int(1, 20), mm = pick_int(1, 3), z0 = pick_int(-10, 10);
  const Exact ex = pick_exact();
  const double a = t1[0], b = t1[1], c = t1[2];
  Cylinder cyl{ex.apply({0, 0, double(z0)}), ex.apply({0, 0, double(z0 + h)}), ex.len(c * k)};
  // The rim point (a k, b k, top), the offset (e a, e b, f c) * mm of length
  // mm c g out of it, and two integer directions perpendicular to the offset.
  const Vec3 rim{a * k, b * k, double(z0 + h)};
  const Vec3 out{t2[0] * a, t2[0] * b, t2[1] * c};
  const Vec3 tng{-b, a, 0};
  const Vec3 bin{-t2[1] * a, -t2[1] * b, t2[0] * c};
  const Vec3 e = rim + double(mm) * out;
  const std::string side = dir == 6 ? "-above" : (dir == 7 ? "-side" : "-diag");
  double s = mm * c * t2[2];
  Vec3 from, delta;
  std::string tag;
  bool nudged = true;
  const int n = pick_int(1, 10), m = pick_int(0, 10);
  switch (pick_int(0, 6)) {
    case 0: {  // the centre's path passes e perpendicular to the offset (m == 0: stops there)
      const int i = pick_int(-3, 3), j = pick_int(-3, 3);
      const Vec3 v = double(i == 0 && j == 0 ? 1 : i) * tng + double(j) * bin;
      from = e - double(n) * v;
      delta = double(n + m) * v;
      tag = "exact-aim-rim" + side;
      break;
    }
    case 1: {  // the same through the corner pocket of the augmented cylinder: misses
      const auto& t3 = kTriples[pick_int(0, kNumTriples - 1)];
      const Vec3 out3{t3[0] * a, t3[0] * b, t3[1] * c};
      const Vec3 bin3{-t3[1] * a, -t3[1] * b, t3[0] * c};
      const Vec3 e3 = rim + double(mm) * out3;
      s = pick_int(mm * t1[2] * std::max(t3[0], t3[1]), mm * t1[2] * t3[2] - 1);
      const int i = pick_int(-3, 3), j = pick_int(-3, 3);
      const Vec3 v = double(i == 0 && j == 0 ? 1 : i) * tng + double(j) * bin3;
      from = e3 - double(n) * v;
      delta = double(n + m) * v;
      tag = "exact-aim-rim-pocket";
      nudged = false;
      break;
    }
    case 2: {  // grazing the side at radial distance c K, K > k
      const int kk = k + mm;
      const Vec3 x{double(t1[0] * kk), double(t1[1] * kk), double(z0 + pick_int(0, h))};
      const int i = pick_int(-3, 3), j = pick_int(-3, 3);
      const Vec3 v = double(i == 0 && j == 0 ? 1 : i) * tng + Vec3{0, 0, double(j)};
      from = x - double(n) * v;
      delta = double(n + m) * v;
      s = c * mm;
      tag = "exact-graze-side";
      break;
    }
    case 3: {  // along the axis into the top cap over the disk; stops short (j < 0), touches (0) or passes
      s = pick_int(1, 50);
      const int j = pick_int(-2, 2);
      from = {double(pick_int(-t1[0] * k, t1[0] * k)), double(pick_int(-t1[1] * k, t1[1] * k)), double(z0 + h) + s + n};
      delta = {0, 0, -double(n + j)};
      tag = j < 0 ? "exact-axis-cap-short" : (j == 0 ? "exact-axis-cap-end" : "exact-axis-cap");
      break;
    }
    case 4: {  // starting at e (touching), moving away or not at all
      from = e;
      const bool still = pick_int(0, 3) == 0;
      delta = still ? Vec3{0, 0, 0}
                    : double(pick_int(0, 3)) * out + double(pick_int(-5, 5)) * tng + double(pick_int(-5, 5)) * bin;
      tag = std::string(still ? "exact-start-touch-zero-delta" : "exact-start-touch") + side;
      break;
    }
    case 5: {  // ending at e (touching at t = 1), coming from outside
      const Vec3 back = double(n) * out + double(pick_int(-5, 5)) * tng + double(pick_int(-5, 5)) * bin;
      from = e + back;
      delta = -back;
      tag = "exact-end-touch" + side;
      break;
    }
    default: {  // zero cylinder radius: the ball passes the segment at distance c mm
      cyl.r = 0;
      const Vec3 x{a * mm, b * mm, double(z0 + pick_int(0, h))};
      from = x - double(n) * tng;
      delta = double(n + m) * tng;
      s = c * mm;
      tag = "exact-zero-radius-cylinder";
      break;
    }
  }
  const int ulps = nudged ? pick_int(-2, 2) : 0;
  return {{MovingSphere{ex.apply(from), nudge(ex.len(s), ulps), ex.dir(delta)}, cyl},
          tag + (nudged ? ulps_tag(ulps) : "")};
}

}  // namespace

rc::Gen<std::pair<SweepCylinderCase, std::string>> sweep_cylinder_case() {
  return rc::gen::resize(100, rc::gen::exec([]() -> std::pair<SweepCylinderCase, std::string> {
    const int mode = pick_int(0, 9);
    if (mode == 9) return exact_sweep_cylinder();
    const Scene sc = pick_scene();
    const Frame f = pick_cylinder(sc);
    const double s = pick_int(0, 10) == 0 ? 0.0 : pick_real(0.01, 3) * sc.size;
    double gap = pick_gap(sc.size);
    const double reach = pick_real(0.1, 6) * sc.size;
    bool graded = true;  // the closest approach is s + gap: tag the gap, nudge a touch
    Vec3 c, d;
    std::string tag;
    switch (mode) {
      case 0: {
        c = 0.5 * (f.c.p + f.c.q) + sc.size * Vec3{pick_real(-6, 6), pick_real(-6, 6), pick_real(-6, 6)};
        d = sc.size * Vec3{pick_real(-8, 8), pick_real(-8, 8), pick_real(-8, 8)};
        tag = "random";
        graded = false;
        break;
      }
      case 1:
      case 2: {  // aimed past the rim corner: from above the cap, from the side, diagonally
        const Spot sp = pick_spot(f, 0, mode == 2 ? 2 : -1);
        bool pocket = false;
        if (s > 0 && (mode == 2 || (sp.name == "rim-diag" && pick_int(0, 2) == 0))) {  // mode 2: the corner pocket
          gap = pocket_gap(sp, f, s);
          pocket = true;
        }
        const Vec3 v = across(sp);
        const Vec3 e = sp.at + (s + gap) * sp.out;
        c = e - reach * v;
        d = (pick_int(0, 3) == 0 ? 1.0 : pick_real(1, 3)) * reach * v;
        tag = "aim-" + sp.name;
        if (pocket) {
          tag += "-pocket";
          graded = false;
        }
        break;
      }
      case 3: {  // grazing the side (any direction along it) or the rim (tangent to the rim circle)
        const bool side = pick_int(0, 1);
        const Spot sp = pick_spot(f, side ? 2 : 0);
        const Vec3 v = side ? across(sp) : sp.tan;
        const Vec3 e = sp.at + (s + gap) * sp.out;
        c = e - reach * v;
        d = pick_real(1, 3) * reach * v;
        tag = "graze-" + sp.name;
        break;
      }
      case 4: {  // along the axis: into a cap over the disk (stopping at cap distance s + gap), or beside the side
        const bool top = pick_int(0, 1);
        const Vec3 capn = top ? f.u : -f.u;
        const Vec3 capc = top ? f.c.q : f.c.p;
        const Vec3 rad = radial_dir(f, pick_real(0, 6.283185307179586));
        if (pick_int(0, 1)) {
          c = capc + f.c.r * std::sqrt(pick_real(0, 1)) * rad + (s + reach) * capn;
          d = -(reach - gap) * capn;
          tag = "axis-cap";
        } else {
          c = capc + (f.c.r + s + gap) * rad + reach * capn;
          d = -(reach + pick_real(0.1, 1.5) * f.len) * capn;
          tag = "axis-side";
        }
        break;
      }
      case 5: {  // starting inside, or at distance s + gap and moving away
        if (pick_int(0, 2) == 0) {
          c = inside_point(f);
          d = sc.size * Vec3{pick_real(-8, 8), pick_real(-8, 8), pick_real(-8, 8)};
          tag = "start-inside";
          graded = false;
        } else {
          const Spot sp = pick_spot(f, pick_int(0, 2));
          c = sp.at + (s + gap) * sp.out;
          d = reach * away(sp);
          tag = "start-" + sp.name;
        }
        break;
      }
      case 6: {  // zero or tiny displacement (1e-300..1e-12 of the scene) at distance s + gap
        const Spot sp = pick_spot(f, pick_int(0, 2));
        c = sp.at + (s + gap) * sp.out;
        const bool zero = pick_int(0, 1);
        d = zero ? Vec3{0, 0, 0} : std::ldexp(pick_real(1, 2) * sc.size, -pick_int(40, 996)) * pick_dir();
        tag = (zero ? "zero-delta-" : "tiny-delta-") + sp.name;
        break;
      }
      case 7: {  // coming from outside and stopping at distance s + gap (touching at t = 1)
        const Spot sp = pick_spot(f, pick_int(0, 2));
        const Vec3 e = sp.at + (s + gap) * sp.out;
        const Vec3 back = reach * away(sp);
        c = e + back;
        d = -back;
        tag = "end-" + sp.name;
        break;
      }
      default: {  // huge displacement (1e6..1e12 of the scene): towards the cylinder, away, or passing by
        const double huge = std::ldexp(pick_real(1, 2) * sc.size, pick_int(20, 39));
        const Spot sp = pick_spot(f, pick_int(0, 2));
        const Vec3 e = sp.at + (s + gap) * sp.out;
        switch (pick_int(0, 2)) {
          case 0: {
            const Vec3 target = inside_point(f);
            c = e + reach * away(sp);
            d = (huge / length(target - c)) * (target - c);
            tag = "huge-delta-toward";
            graded = false;
            break;
          }
          case 1:
            c = e;
            d = huge * away(sp);
            tag = "huge-delta-away-" + sp.name;
            break;
          default: {
            const Vec3 v = across(sp);
            c = e - huge * v;
            d = (2 * huge) * v;
            tag = "huge-delta-pass-" + sp.name;
            break;
          }
        }
        break;
      }
    }
    MovingSphere ms{c, s, d};
    if (graded) {
      tag += gap_tag(gap);
      if (gap == 0) ms.r = std::max(0.0, nudge(s, pick_int(-2, 2)));
    }
    return {{ms, f.c}, tag};
  }));
}

// ---- cylinder / box -------------------------------------------------------------

namespace {

constexpr double kTwoPi = 6.283185307179586;

using Axes = std::array<Vec3, 3>;
using ObbCase = std::pair<CylinderObbCase, std::string>;

// The six permutations of three coordinates (even ones first).
constexpr int kPerms[6][3] = {{0, 1, 2}, {1, 2, 0}, {2, 0, 1}, {0, 2, 1}, {2, 1, 0}, {1, 0, 2}};

// |a_i . a_j - delta_ij| <= tol * 2^-52 for all i, j, the dot products in
// doubles: production's contract is tol = 16.
bool orthonormal(const Axes& a, double tol) {
  for (int i = 0; i < 3; ++i)
    for (int j = i; j < 3; ++j)
      if (!(std::fabs(dot(a[i], a[j]) - (i == j ? 1.0 : 0.0)) <= tol * 0x1p-52)) return false;
  return true;
}

// Gram-Schmidt in doubles: keeps a[0]'s direction and the handedness.
Axes gram_schmidt(Axes a) {
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
Axes settle(Axes a) {
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
RatRot pyth_rotation(int index) {
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
RatRot product(const RatRot& x, const RatRot& y) {
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
Axes rat_frame(const RatRot& r, int perm, int signs) {
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
Axes quaternion_frame() {
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
Axes pick_box_frame() {
  const int kind = pick_int(0, 3);
  if (kind == 3) return quaternion_frame();
  const int perm = pick_int(0, 5), signs = pick_int(0, 7);
  RatRot r = pyth_rotation(kind >= 1 ? pick_int(1, kNumRotations) : 0);
  if (kind == 2) r = product(r, pyth_rotation(pick_int(1, kNumRotations)));
  return rat_frame(r, perm, signs);
}

// The same box stored another way: (axis, extent) pairs permuted, axes
// negated (exact).
Obb restate(const Obb& b) {
  const int perm = pick_int(0, 5), signs = pick_int(0, 7);
  Obb o = b;
  for (int j = 0; j < 3; ++j) {
    const int i = kPerms[perm][j];
    o.axes[j] = (signs >> j) & 1 ? -b.axes[i] : b.axes[i];
    o.e[j] = b.e[i];
  }
  return o;
}

// The box of frame a and half extents e whose point of box coordinates s
// (|s_i| <= 1) is x.
Obb box_at(Vec3 x, const Axes& a, Vec3 e, Vec3 s) {
  Obb b;
  b.axes = a;
  b.e = e;
  b.c = x - (s.x * e.x) * a[0] - (s.y * e.y) * a[1] - (s.z * e.z) * a[2];
  return b;
}
// Box coordinates of a corner minimising n.x: from it every edge goes in a
// direction with a non-negative n component, so the box lies in n.(y - x) >= 0.
Vec3 lowest(const Axes& a, Vec3 n) {
  return {dot(n, a[0]) > 0 ? -1.0 : 1.0, dot(n, a[1]) > 0 ? -1.0 : 1.0, dot(n, a[2]) > 0 ? -1.0 : 1.0};
}
Vec3 pick_extents(double size) { return size * Vec3{pick_real(0.05, 2), pick_real(0.05, 2), pick_real(0.05, 2)}; }
Vec3 unit(Vec3 v) { return (1 / length(v)) * v; }

// A point of the cylinder minimising n.x (n unit): the lower cap's centre
// plus r times the unit part of -n across the axis (the cap centre when n is
// along the axis). Computed from the stored end points.
Vec3 cylinder_lowest(const Cylinder& c, Vec3 n) {
  const Vec3 u = unit(c.q - c.p);
  const double nu = dot(n, u);
  const Vec3 cap = nu > 0 ? c.p : c.q;
  const Vec3 m = n - nu * u;
  const double lm = length(m);
  return lm > 0 ? cap - (c.r / lm) * m : cap;
}

// The gap's tag; a touch (gap 0) is nudged by k ulps in [-2, 2] first: the
// cylinder radius and the box extents grow (k > 0: towards overlap, both
// shapes only grow) or shrink. (In these constructions rounding is of the
// same order as the nudge, so the tag stays "-touch".)
std::string touch_or_gap(Cylinder& c, Obb& b, double gap) {
  if (gap == 0) {
    const int k = pick_int(-2, 2);
    c.r = std::max(0.0, nudge(c.r, k));
    b.e = {std::max(0.0, nudge(b.e.x, k)), std::max(0.0, nudge(b.e.y, k)), std::max(0.0, nudge(b.e.z, k))};
  }
  return gap_tag(gap);
}

// Rim (twice as likely), cap or side.
int pick_region() {
  const int r = pick_int(0, 3);
  return r <= 1 ? 0 : r - 1;
}
const char* const kFeatureNames[3] = {"corner", "edge", "face"};

// A box corner (feature 0), edge (1) or face (2) at a cylinder spot: the box
// lies in out.(y - at) >= gap and holds at + gap out, so for gap >= 0 its
// distance to the cylinder is gap (to rounding). Corner: any frame, the
// corner lowest along `out`; edge: an axis across `out`, the other two turned
// about it by a random angle; face: an axis along `out`.
Obb box_feature_at(const Spot& sp, double gap, int feature, Vec3 e) {
  Axes a;
  if (feature == 0) {
    a = pick_box_frame();
  } else if (feature == 1) {
    const Vec3 d0 = across(sp), w = cross(d0, sp.out);
    const double g = pick_real(0, kTwoPi);
    a = settle({d0, std::cos(g) * sp.out + std::sin(g) * w, std::cos(g) * w - std::sin(g) * sp.out});
  } else {
    const Vec3 d0 = across(sp);
    a = settle({sp.out, d0, cross(sp.out, d0)});
  }
  Vec3 s = lowest(a, sp.out);
  if (feature == 1) s.x = pick_real(-1, 1);
  if (feature == 2) s.y = pick_real(-1, 1), s.z = pick_real(-1, 1);
  return box_at(sp.at + gap * sp.out, a, e, s);
}

// Random poses: any box frame, the centre within 4 scene sizes of the
// cylinder's middle (true hit rate about 40%).
ObbCase obb_random(const Scene& sc, const Frame& f) {
  Obb b;
  b.axes = pick_box_frame();
  b.e = pick_extents(sc.size);
  b.c = 0.5 * (f.c.p + f.c.q) + sc.size * Vec3{pick_real(-4, 4), pick_real(-4, 4), pick_real(-4, 4)};
  return {{f.c, restate(b)}, "random"};
}

// A box corner, edge or face at the rim (above the cap outside the rim,
// beside the side, diagonal), on a cap or on the side; corners also in the
// capsule pocket: over the cap disc, within r of the cap centre, the box
// wholly beyond the cap plane (in the bounding capsule, not in the
// cylinder: a certain miss).
ObbCase obb_feature(const Scene& sc, const Frame& f, int feature) {
  Cylinder c = f.c;
  if (feature == 0 && c.r > 0 && pick_int(0, 3) == 0) {
    const bool top = pick_int(0, 1);
    const Vec3 capn = top ? f.u : -f.u;
    const double rho = c.r * std::sqrt(pick_real(0, 0.99));
    const double hgt = pick_real(0.02, 0.98) * std::sqrt(std::max(0.0, c.r * c.r - rho * rho));
    const Vec3 x = (top ? c.q : c.p) + rho * radial_dir(f, pick_real(0, kTwoPi)) + hgt * capn;
    const Axes a = pick_box_frame();
    return {{c, restate(box_at(x, a, pick_extents(sc.size), lowest(a, capn)))}, "corner-pocket"};
  }
  const Spot sp = pick_spot(f, pick_region());
  const double gap = pick_gap(sc.size);
  Obb b = box_feature_at(sp, gap, feature, pick_extents(sc.size));
  const std::string t = touch_or_gap(c, b, gap);
  return {{c, restate(b)}, std::string(kFeatureNames[feature]) + "-" + sp.name + t};
}

// A box section off the corner's radial line. In the cap plane, the corner
// W lowest along the cap normal sits over the disc at radius rho; from it the
// long edge rises at a small slope and passes the axis at rho * sin(alpha),
// ending near there, so the box corner nearest the axis (and the box point
// nearest the axis segment) is above the cap, about 60-90 degrees round from
// W. W pokes through the cap plane by delta ("-deep": the section, a small
// polygon around W, overlaps the disc beside that corner's radial line: a
// one-ray-per-plane step 3 misses it), hovers delta above ("-gap": the
// mirrored near miss, distance delta) or touches (+- ulps).
ObbCase obb_offray(const Scene& sc, const Frame& f) {
  Cylinder c = f.c;
  if (c.r == 0) c.r = sc.size;
  const bool top = pick_int(0, 1);
  const Vec3 capn = top ? f.u : -f.u;
  const Vec3 rad = radial_dir(f, pick_real(0, kTwoPi)), tng = cross(f.u, rad);
  const double rho = c.r * pick_real(0.3, 0.95);
  const double sin_a = pick_real(0.05, 0.5), cos_a = std::sqrt(1 - sin_a * sin_a);
  const Vec3 t = -cos_a * rad + (pick_int(0, 1) ? sin_a : -sin_a) * tng;
  const double slope = pick_real(0.02, 0.3);
  const Vec3 d0 = unit(t + slope * capn);
  const Vec3 w = unit(cross(d0, capn)), v = cross(w, d0);  // v: mostly along capn
  const double g = pick_real(0.2, 1.37);                  // the other edges rise at slopes >= 0.2
  const Axes a = settle({d0, std::cos(g) * w + std::sin(g) * v, std::cos(g) * v - std::sin(g) * w});
  const Vec3 e{0.5 * rho * cos_a * pick_real(0.8, 1.2) * std::hypot(1.0, slope), c.r * pick_real(0.05, 1),
               c.r * pick_real(0.05, 1)};
  const int kind = pick_int(0, 2);
  const double delta = pick_int(0, 1) ? std::ldexp(sc.size, -pick_int(20, 50)) : pick_real(0.001, 0.05) * slope * rho;
  const double gap = kind == 0 ? -delta : (kind == 1 ? delta : 0.0);
  Obb b = box_at((top ? c.q : c.p) + rho * rad + gap * capn, a, e, lowest(a, capn));
  const std::string tag = "offray" + touch_or_gap(c, b, gap);
  return {{c, restate(b)}, tag};
}

// A box face on a cap plane, the box beyond the cap ("above": the face and
// the cap are coplanar) or on the cylinder's side of it ("below": the box's
// face flush with the cap). In the plane the rectangle lies in
// rad.y >= r + gap with its edge (across rad) or corner at (r + gap) rad:
// gap > 0 clear of the rim, 0 touching it, < 0 reaching over the disc (by up
// to r a third of the time). "capface-above-over": the face over the disc,
// touching the cap (+- ulps); below, reaching over the disc overlaps
// ("-deep").
ObbCase obb_cap_face(const Scene& sc, const Frame& f) {
  Cylinder c = f.c;
  const bool top = pick_int(0, 1), above = pick_int(0, 1), edge = pick_int(0, 1);
  const Vec3 capn = top ? f.u : -f.u;
  const Vec3 rad = radial_dir(f, pick_real(0, kTwoPi));
  const double gamma = pick_int(0, 2) == 0 ? 0.0 : pick_real(0, kTwoPi);
  const Vec3 d0 = edge ? cross(f.u, rad) : std::cos(gamma) * f.e1 + std::sin(gamma) * f.e2;
  const Axes a = settle({capn, d0, cross(capn, d0)});
  const double gap = pick_int(0, 2) == 0 ? -c.r * pick_real(0, 1) : pick_gap(sc.size);
  Vec3 s = lowest(a, rad);
  s.x = above ? -1 : 1;
  if (edge) s.y = pick_real(-1, 1);
  Obb b = box_at((top ? c.q : c.p) + (c.r + gap) * rad, a, pick_extents(sc.size), s);
  std::string tag = above ? "capface-above" : "capface-below";
  if (above && gap < 0) {
    touch_or_gap(c, b, 0);
    tag += "-over";
  } else {
    tag += touch_or_gap(c, b, gap);
  }
  return {{c, restate(b)}, tag};
}

// The cylinder inside the box (the box's half widths are the cylinder's
// along each axis, plus a margin; "-snug": no margin, touching inside), or
// the box inside the cylinder (the largest scale that keeps every corner in,
// times a factor; "-snug": factor 1). Certain overlaps.
ObbCase obb_contain(const Scene& sc, const Frame& f) {
  Cylinder c = f.c;
  const Vec3 mid = 0.5 * (c.p + c.q);
  const double len = length(c.q - c.p);
  const bool snug = pick_int(0, 2) == 0;
  if (pick_int(0, 1)) {
    const Axes a = pick_int(0, 2) == 0 ? settle({f.u, f.e1, f.e2}) : pick_box_frame();
    Vec3 e;
    for (int i = 0; i < 3; ++i) {
      const double cu = std::fabs(dot(f.u, a[i]));
      e[i] = 0.5 * len * cu + c.r * std::sqrt(std::max(0.0, 1 - cu * cu));
      if (!snug) e[i] += pick_int(0, 1) ? std::ldexp(sc.size, -pick_int(20, 50)) : pick_real(0, 1) * sc.size;
    }
    Obb b;
    b.c = mid;
    b.axes = a;
    b.e = e;
    return {{c, restate(b)}, std::string("cyl-in-box") + (snug ? "-snug" : "")};
  }
  if (c.r == 0) c.r = sc.size;
  const Axes a = pick_box_frame();
  const Vec3 shape{pick_real(0.1, 1), pick_real(0.1, 1), pick_real(0.1, 1)};
  const Vec3 ctr = mid + (pick_real(-0.4, 0.4) * len) * f.u + (pick_real(0, 0.5) * c.r) * radial_dir(f, pick_real(0, kTwoPi));
  const double zc = dot(ctr - mid, f.u);
  const Vec3 pc = (ctr - mid) - zc * f.u;
  double tmax = INFINITY;
  for (int k = 0; k < 8; ++k) {
    const Vec3 v = ((k & 1) ? 1.0 : -1.0) * shape.x * a[0] + ((k & 2) ? 1.0 : -1.0) * shape.y * a[1] +
                   ((k & 4) ? 1.0 : -1.0) * shape.z * a[2];
    const double zv = dot(v, f.u);
    if (zv != 0) tmax = std::min(tmax, (0.5 * len - (zv > 0 ? zc : -zc)) / std::fabs(zv));
    const Vec3 pv = v - zv * f.u;
    const double qa = length2(pv), qb = dot(pc, pv), qc = length2(pc) - c.r * c.r;
    if (qa > 0) tmax = std::min(tmax, (-qb + std::sqrt(std::max(0.0, qb * qb - qa * qc))) / qa);
  }
  const double t = snug ? tmax : tmax * pick_real(0.1, 0.99);
  Obb b;
  b.c = ctr;
  b.axes = a;
  b.e = t * shape;
  return {{c, restate(b)}, std::string("box-in-cyl") + (snug ? "-snug" : "")};
}

// A thin disk-like cylinder (length 1e-6..1e-12 of r, at least 2^-44 of its
// coordinates) resting on a box face: flat (axis along the face normal),
// tilted, or edgewise (axis in the face plane), the contact inside the face
// or on its edge (a fifth of the time), touching (+- ulps) or a tiny gap
// either way.
// The box is placed under the stored cylinder's lowest point.
ObbCase obb_thin(const Scene& sc) {
  const Axes a = pick_box_frame();
  const int i = pick_int(0, 2), j = (i + 1) % 3, k = (i + 2) % 3;
  const double sg = pick_int(0, 1) ? 1.0 : -1.0;
  const Vec3 n = sg * a[i];
  const int orient = pick_int(0, 2);
  const Vec3 w = orient == 0 ? Vec3{} : [&] {
    const double th = pick_int(0, 2) == 0 ? 0.0 : pick_real(0, kTwoPi);
    return std::cos(th) * a[j] + std::sin(th) * a[k];
  }();
  const Vec3 u = orient == 0 ? (pick_int(0, 1) ? n : -n) : (orient == 1 ? unit(n + pick_real(0.01, 2) * w) : w);
  const double r = pick_real(0.05, 2) * sc.size;
  const Vec3 p = sc.offset + sc.size * Vec3{pick_real(-2, 2), pick_real(-2, 2), pick_real(-2, 2)};
  const double len = std::max(r * std::pow(10.0, -pick_real(6, 12)), std::ldexp(max_abs(p), -44));
  Cylinder c{p, p + len * u, r};
  if (pick_int(0, 1)) std::swap(c.p, c.q);
  const bool overhang = pick_int(0, 4) == 0;
  Vec3 s;
  s[i] = sg;
  s[j] = overhang ? (pick_int(0, 1) ? 1.0 : -1.0) : pick_real(-0.95, 0.95);
  s[k] = pick_real(-0.95, 0.95);
  const int gk = pick_int(0, 2);
  const double gap = gk == 0 ? 0.0 : (gk == 1 ? 1.0 : -1.0) * std::ldexp(sc.size, -pick_int(20, 50));
  const Vec3 e{pick_real(0.3, 3) * sc.size, pick_real(0.3, 3) * sc.size, pick_real(0.3, 3) * sc.size};
  Obb b = box_at(cylinder_lowest(c, n) - gap * n, a, e, s);
  const char* names[3] = {"thin-flat", "thin-tilted", "thin-edgewise"};
  const std::string tag = names[orient] + touch_or_gap(c, b, gap);
  return {{c, restate(b)}, tag};
}

// A box edge along the axis (exactly, or 1e-8 / 1e-16 from it) beside the
// side, the box's faces turned away from tangent, touching (+- ulps) or a gap.
ObbCase obb_axis_edge(const Scene& sc, const Frame& f) {
  Cylinder c = f.c;
  const Spot sp = pick_spot(f, 2);
  const double tilt = pick_tilt(), phi = pick_real(0, kTwoPi);
  const Vec3 d0 = tilt == 0 ? f.u : unit(f.u + tilt * (std::cos(phi) * sp.tan + std::sin(phi) * sp.out));
  const double g = pick_real(0.05, 1.52);
  const Axes a = settle({d0, std::cos(g) * sp.out + std::sin(g) * sp.tan, std::cos(g) * sp.tan - std::sin(g) * sp.out});
  const double len = length(c.q - c.p);
  const Vec3 e{pick_real(0.1, 1.5) * len, pick_real(0.05, 2) * sc.size, pick_real(0.05, 2) * sc.size};
  Vec3 s = lowest(a, sp.out);
  s.x = pick_real(-1, 1);
  const double gap = pick_gap(sc.size);
  Obb b = box_at(sp.at + gap * sp.out, a, e, s);
  const std::string tag = "axis-edge" + tilt_tag(tilt) + touch_or_gap(c, b, gap);
  return {{c, restate(b)}, tag};
}

// A box face tangent to the side: face normal radial, the face parallel to
// the axis at distance r + gap, its edges along the axis ("-aligned") or
// turned in the tangent plane.
ObbCase obb_side_face(const Scene& sc, const Frame& f) {
  Cylinder c = f.c;
  const Spot sp = pick_spot(f, 2);
  const bool aligned = pick_int(0, 1);
  const double g = aligned ? 0.0 : pick_real(0, kTwoPi);
  const Vec3 d0 = aligned ? f.u : std::cos(g) * f.u + std::sin(g) * sp.tan;
  const Axes a = settle({sp.out, d0, cross(sp.out, d0)});
  Vec3 s = lowest(a, sp.out);
  s.y = pick_real(-1, 1), s.z = pick_real(-1, 1);
  const double gap = pick_gap(sc.size);
  Obb b = box_at(sp.at + gap * sp.out, a, pick_extents(sc.size), s);
  const std::string tag = std::string("side-face") + (aligned ? "-aligned" : "") + touch_or_gap(c, b, gap);
  return {{c, restate(b)}, tag};
}

// Flat boxes (one extent 0), segment boxes (two), point boxes (three) at a
// cylinder spot, and boxes at a zero-radius cylinder (a segment).
ObbCase obb_degenerate(const Scene& sc, const Frame& f) {
  Frame g = f;
  const int kind = pick_int(0, 3);
  if (kind == 3) g.c.r = 0;
  const Spot sp = pick_spot(g, pick_region());
  const double gap = pick_gap(sc.size);
  Vec3 e = pick_extents(sc.size);
  if (kind < 3) {
    const int z = pick_int(0, 2);
    for (int m = 0; m <= kind; ++m) e[(z + m) % 3] = 0;
  }
  const int feature = pick_int(0, 2);
  Cylinder c = g.c;
  Obb b = box_feature_at(sp, gap, feature, e);
  const char* names[4] = {"flat-box", "segment-box", "point-box", "zero-radius"};
  const std::string tag = names[kind] + touch_or_gap(c, b, gap);
  return {{c, restate(b)}, tag};
}

// Exact integer constructions: the cylinder along +z from z0 to top = z0 + h,
// radius c k for a Pythagorean triple (a, b, c) (k = 0: zero radius); the
// box [lo, hi] with integer bounds, stored with a signed-permutation frame;
// then exact moves. In the cap plane the box section is "rim-corner" (corner
// at (a k, b k) on the rim), "tangent" (face x = c k, across y = 0),
// "inscribed" ([-a k, a k] x [-b k, b k], corners on the rim),
// "circumscribed" ([-c k, c k]^2, faces tangent), "over" (around an integer
// point of the inscribed rectangle) or "outside" (x >= c k + 1..3: a certain
// gap); along the axis "above" (z >= top: a face coplanar with the cap),
// "below" (z <= z0), "across" (the top cap plane), "within" or "through".
// Tags: exact-<section>-<axial> for touches, exact-<section>-overlap for
// certain overlaps, exact-outside, exact-zero-extent (some extents 0: flat,
// segment and point boxes). Exact touches are nudged by k ulps towards
// overlap (k > 0) or away: the radius for rim and side contacts, the cap
// along the axis for face contacts on a cap.
ObbCase exact_cylinder_obb() {
  const auto& t1 = kTriples[pick_int(0, kNumTriples - 1)];
  const int k = pick_int(0, 12) == 0 ? 0 : pick_int(1, 4);
  const int h = pick_int(1, 20), z0 = pick_int(-10, 10), top = z0 + h;
  const int A = t1[0] * k, B = t1[1] * k, C = t1[2] * k;
  const Exact ex = pick_exact();
  Cylinder cyl{ex.apply({0, 0, double(z0)}), ex.apply({0, 0, double(top)}), ex.len(C)};
  int lo[3], hi[3];
  const int xk = pick_int(0, 5);
  int pi = 0, pj = 0;
  switch (xk) {
    case 0:
      lo[0] = A, hi[0] = A + pick_int(1, 20), lo[1] = B, hi[1] = B + pick_int(1, 20);
      break;
    case 1:
    case 5:
      lo[0] = C + (xk == 5 ? pick_int(1, 3) : 0), hi[0] = lo[0] + pick_int(1, 20);
      lo[1] = -pick_int(0, 10), hi[1] = pick_int(0, 10);
      break;
    case 2:
      lo[0] = -A, hi[0] = A, lo[1] = -B, hi[1] = B;
      break;
    case 3:
      lo[0] = -C, hi[0] = C, lo[1] = -C, hi[1] = C;
      break;
    default:
      pi = pick_int(-A, A), pj = pick_int(-B, B);
      lo[0] = pi - pick_int(0, 10), hi[0] = pi + pick_int(0, 10);
      lo[1] = pj - pick_int(0, 10), hi[1] = pj + pick_int(0, 10);
      break;
  }
  const int zk = pick_int(0, 4);
  switch (zk) {
    case 0: lo[2] = top, hi[2] = top + pick_int(1, 20); break;
    case 1: hi[2] = z0, lo[2] = z0 - pick_int(1, 20); break;
    case 2: lo[2] = top - pick_int(1, h), hi[2] = top + pick_int(1, 20); break;
    case 3: lo[2] = z0 + pick_int(0, h), hi[2] = pick_int(lo[2], top); break;
    default: lo[2] = z0 - pick_int(0, 5), hi[2] = top + pick_int(0, 5); break;
  }
  // 0: touching through the radius, 1: through a cap, 2: certain overlap, 3: certain gap.
  int contact = xk <= 1 ? 0 : (xk == 5 ? 3 : (zk <= 1 ? 1 : 2));
  int zeros = 0;
  if (pick_int(0, 4) == 0) {
    for (int i = 0; i < 3; ++i) {
      if (pick_int(0, 2) != 0 || (i == 2 && zk == 2)) continue;
      ++zeros;
      if (i == 2) {
        if (zk == 1) lo[2] = hi[2];
        else if (zk == 4) lo[2] = hi[2] = pick_int(z0, top);
        else hi[2] = lo[2];
      } else if (xk == 1 || xk == 5) {
        if (i == 0) hi[0] = lo[0];
        else lo[1] = hi[1] = 0;
      } else if (xk == 4) {
        lo[i] = hi[i] = i == 0 ? pi : pj;
      } else {
        hi[i] = lo[i];
        if (xk == 3) contact = 0;  // a face of the circumscribed square: tangent to the side
      }
    }
  }
  Obb b;
  Vec3 cc;
  for (int i = 0; i < 3; ++i) {
    cc[i] = 0.5 * (lo[i] + hi[i]);
    b.e[i] = ex.len(0.5 * (hi[i] - lo[i]));
    b.axes[i] = ex.turn({i == 0 ? 1.0 : 0.0, i == 1 ? 1.0 : 0.0, i == 2 ? 1.0 : 0.0});
  }
  b.c = ex.apply(cc);
  const char* xy[6] = {"rim-corner", "tangent", "inscribed", "circumscribed", "over", "outside"};
  const char* zs[5] = {"above", "below", "across", "within", "through"};
  std::string tag = zeros > 0 ? "exact-zero-extent"
                    : contact == 3 ? "exact-outside"
                    : contact == 2 ? std::string("exact-") + xy[xk] + "-overlap"
                                   : std::string("exact-") + xy[xk] + "-" + zs[zk];
  if (contact <= 1) {
    const int ulps = C == 0 && contact == 0 ? pick_int(0, 2) : pick_int(-2, 2);
    if (contact == 0) {
      cyl.r = std::max(0.0, nudge(cyl.r, ulps));
    } else {
      const int s = ex.slot(2);
      Vec3& cap = zk == 0 ? cyl.q : cyl.p;
      const double out = (zk == 0 ? 1.0 : -1.0) * ex.sign(2);  // away from the cylinder, in world
      cap[s] = nudge(cap[s], out > 0 ? ulps : -ulps);
    }
    tag += ulps_tag(ulps);
  }
  return {{cyl, restate(b)}, tag};
}

double to_f32(double v) { return double(float(v)); }
Vec3 to_f32(Vec3 v) { return {to_f32(v.x), to_f32(v.y), to_f32(v.z)}; }

// Patterns seen in public bug reports of collision libraries: boxes kissing
// a cylinder with gaps ~1e-8 of the scene; thin slabs (100 x 100 x 0.1)
// under the cylinder (on the big face or the thin side); a cylinder standing
// or lying on a big box; and float32-valued coordinates (every position,
// radius and extent rounded to float) at offsets 40..100.
ObbCase obb_pattern() {
  const int kind = pick_int(0, 4);
  Scene sc = pick_scene();
  if (kind == 4) {
    sc.size = 1;
    for (int i = 0; i < 3; ++i) sc.offset[i] = (pick_int(0, 1) ? 1 : -1) * pick_real(40, 100);
  }
  const Frame f = pick_cylinder(sc);
  Cylinder c = f.c;
  if (kind == 0) {
    const Spot sp = pick_spot(f, pick_region());
    const double gap = (pick_int(0, 1) ? 1 : -1) * 1e-8 * pick_real(0.5, 2) * sc.size;
    const int feature = pick_int(0, 2);
    Obb b = box_feature_at(sp, gap, feature, pick_extents(sc.size));
    return {{c, restate(b)}, "pattern-kiss" + gap_tag(gap)};
  }
  const int sub = kind == 4 ? pick_int(0, 2) : kind;  // 1 slab, 2 stand or lie, (f32) 0 corner
  Axes a = kind == 4 && pick_int(0, 1) ? rat_frame(pyth_rotation(0), pick_int(0, 5), pick_int(0, 7)) : pick_box_frame();
  const double gap = pick_gap(sc.size);
  Obb b;
  std::string what;
  if (sub == 0) {
    const Spot sp = pick_spot(f, pick_region());
    b = box_feature_at(sp, gap, 0, pick_extents(sc.size));
    what = "corner";
  } else {
    const int i = pick_int(0, 2), j = (i + 1) % 3, k = (i + 2) % 3;
    const double sg = pick_int(0, 1) ? 1.0 : -1.0;
    const Vec3 n = sg * a[i];
    Vec3 e, s;
    s[i] = sg;
    s[j] = pick_real(-0.9, 0.9);
    s[k] = pick_real(-0.9, 0.9);
    if (sub == 1) {  // slab: thin along a[2]; the cylinder on its big face (i == 2) or its thin side
      const double unit_len = pick_real(0.05, 0.3) * sc.size;
      e = {50 * unit_len, 50 * unit_len, 0.05 * unit_len};
      if (i != 2) s[2] = pick_real(-1, 1);
      what = i == 2 ? "slab-face" : "slab-side";
    } else {  // a big box; the cylinder stands (axis along n) or lies (axis across n) on the face
      e[i] = pick_real(1, 5) * sc.size;
      e[j] = pick_real(10, 100) * sc.size;
      e[k] = pick_real(10, 100) * sc.size;
      const bool stand = pick_int(0, 1);
      const double th = pick_int(0, 2) == 0 ? 0.0 : pick_real(0, kTwoPi);
      const Vec3 u = stand ? (pick_int(0, 1) ? n : -n) : std::cos(th) * a[j] + std::sin(th) * a[k];
      c.q = c.p + f.len * u;
      what = stand ? "stand" : "lie";
    }
    b = box_at(cylinder_lowest(c, n) - gap * n, a, e, s);
  }
  if (kind == 4) {
    c = {to_f32(c.p), to_f32(c.q), to_f32(c.r)};
    b.c = to_f32(b.c);
    b.e = to_f32(b.e);
    return {{c, restate(b)}, "pattern-f32" + gap_tag(gap)};
  }
  const std::string t = touch_or_gap(c, b, gap);
  return {{c, restate(b)}, "pattern-" + what + t};
}

}  // namespace

rc::Gen<std::pair<CylinderObbCase, std::string>> cylinder_obb_case() {
  return rc::gen::resize(100, rc::gen::exec([]() -> std::pair<CylinderObbCase, std::string> {
    const int mode = pick_int(0, 13);
    if (mode == 12 || mode == 13) return exact_cylinder_obb();
    if (mode == 11) return obb_pattern();
    const Scene sc = pick_scene();
    if (mode == 7) return obb_thin(sc);
    const Frame f = pick_cylinder(sc);
    switch (mode) {
      case 0: return obb_random(sc, f);
      case 1:
      case 2:
      case 3: return obb_feature(sc, f, mode - 1);
      case 4: return obb_offray(sc, f);
      case 5: return obb_cap_face(sc, f);
      case 6: return obb_contain(sc, f);
      case 8: return obb_axis_edge(sc, f);
      case 9: return obb_side_face(sc, f);
      default: return obb_degenerate(sc, f);
    }
  }));
}

rc::Gen<double> wild_double() {
  return rc::gen::resize(100, rc::gen::exec([]() -> double {
    switch (pick_int(0, 9)) {
      case 0: return std::numeric_limits<double>::quiet_NaN();
      case 1: return pick_int(0, 1) ? INFINITY : -INFINITY;
      case 2: return std::ldexp(double(pick_int(-1000, 1000)), -1074);          // subnormal
      case 3: return pick_int(0, 1) ? 0.0 : -0.0;
      case 4: return std::ldexp(pick_real(-1, 1), pick_int(900, 1023));        // huge
      case 5: return std::ldexp(pick_real(-1, 1), pick_int(-1022, -900));      // tiny
      case 6: return std::numeric_limits<double>::max() * (pick_int(0, 1) ? 1 : -1);
      default: return pick_real(-10, 10);
    }
  }));
}

namespace {
Vec3 wild_vec() { return {*wild_double(), *wild_double(), *wild_double()}; }
}  // namespace

rc::Gen<CylinderSphereCase> wild_cylinder_sphere() {
  return rc::gen::exec([]() -> CylinderSphereCase {
    return {{wild_vec(), wild_vec(), *wild_double()}, {wild_vec(), *wild_double()}};
  });
}
rc::Gen<SegmentCylinderCase> wild_segment_cylinder() {
  return rc::gen::exec([]() -> SegmentCylinderCase {
    return {{wild_vec(), wild_vec()}, {wild_vec(), wild_vec(), *wild_double()}};
  });
}
rc::Gen<CylinderCapsuleCase> wild_cylinder_capsule() {
  return rc::gen::exec([]() -> CylinderCapsuleCase {
    return {{wild_vec(), wild_vec(), *wild_double()}, {wild_vec(), wild_vec(), *wild_double()}};
  });
}
rc::Gen<SweepCylinderCase> wild_sweep_cylinder() {
  return rc::gen::exec([]() -> SweepCylinderCase {
    return {{wild_vec(), *wild_double(), wild_vec()}, {wild_vec(), wild_vec(), *wild_double()}};
  });
}

rc::Gen<CylinderObbCase> wild_cylinder_obb() {
  return rc::gen::resize(100, rc::gen::exec([]() -> CylinderObbCase {
    const Cylinder a{wild_vec(), wild_vec(), *wild_double()};
    Obb b;
    b.c = wild_vec();
    if (pick_int(0, 3) == 0) {  // a valid frame, wild extents
      b.axes = pick_box_frame();
    } else {
      b.axes = {wild_vec(), wild_vec(), wild_vec()};
    }
    b.e = wild_vec();
    return {a, b};
  }));
}

// ---- cylinder / triangle --------------------------------------------------------

namespace {

using TriCase = std::pair<CylinderTriangleCase, std::string>;

// The same triangle stored another way: the vertices shifted cyclically and
// reversed or not (both orientations of its normal).
Triangle restate(const Triangle& t) {
  Triangle o = t;
  for (int i = pick_int(0, 2); i > 0; --i) o = {o.b, o.c, o.a};
  if (pick_int(0, 1)) std::swap(o.b, o.c);
  return o;
}

// The gap's tag; a touch (gap 0) is nudged by k ulps in [-2, 2] first: the
// cylinder radius grows (k > 0) or shrinks by k ulps, and the triangle moves
// by k ulps of the scene's largest coordinate along -out, `out` pointing from
// the cylinder towards the triangle (k > 0: towards overlap).
std::string tri_touch_or_gap(Cylinder& c, Triangle& t, Vec3 out, double gap) {
  if (gap == 0) {
    const int k = pick_int(-2, 2);
    c.r = std::max(0.0, nudge(c.r, k));
    const double m = std::max({max_abs(c.p), max_abs(c.q), c.r, max_abs(t.a), max_abs(t.b), max_abs(t.c)});
    const Vec3 step = (k * std::ldexp(m, -52)) * out;
    t = {t.a - step, t.b - step, t.c - step};
  }
  return gap_tag(gap);
}

// Edge lengths: 0.05..3 scene sizes, a sixth of the time 10..100.
double tri_len(double size) { return (pick_int(0, 5) == 0 ? pick_real(10, 100) : pick_real(0.05, 3)) * size; }

// A unit direction in the plane of the unit vectors e and w (perpendicular),
// with a non-negative e component.
Vec3 half_dir(Vec3 e, Vec3 w) {
  const double phi = pick_real(-1.5707963267948966, 1.5707963267948966);
  return std::cos(phi) * e + std::sin(phi) * w;
}

// A triangle in the plane of the unit vectors e1, e2 (perpendicular) holding
// x strictly inside: vertices at distances 0.3..1 times len, about 120
// degrees apart (every angle between neighbours below 180 degrees).
Triangle face_around(Vec3 x, Vec3 e1, Vec3 e2, double len) {
  const double th = pick_real(0, kTwoPi);
  Vec3 v[3];
  for (int i = 0; i < 3; ++i) {
    const double a = th + i * (kTwoPi / 3) + pick_real(-0.4, 0.4);
    v[i] = x + (len * pick_real(0.3, 1)) * (std::cos(a) * e1 + std::sin(a) * e2);
  }
  return {v[0], v[1], v[2]};
}

// Edge directions at a spot: along `tan` (tangent to the rim or the side's
// circle), along `bi` (across the rim or the side, in the plane of the axis),
// or any direction across `out`.
const char* const kTriEdgeDirs[3] = {"-along", "-across", ""};

// A triangle vertex (feature 0), edge (1) or face (2) at the point x of a
// spot's half-space out.(y - x) >= 0: x is vertex a, lies on edge ab (the
// edge across `out`, direction by edge_dir), or lies inside the face (the
// plane across `out`). With x = at + gap out the triangle's distance to the
// cylinder is gap for gap >= 0 (to rounding).
Triangle tri_feature_at(const Spot& sp, Vec3 x, int feature, int edge_dir, double size) {
  if (feature == 0) {
    const Vec3 b = x + tri_len(size) * (pick_int(0, 3) == 0 ? across(sp) : away(sp));
    return {x, b, x + tri_len(size) * away(sp)};
  }
  if (feature == 1) {
    const Vec3 d = edge_dir == 0 ? sp.tan : (edge_dir == 1 ? sp.bi : across(sp));
    return {x - tri_len(size) * d, x + tri_len(size) * d, x + tri_len(size) * away(sp)};
  }
  return face_around(x, sp.tan, sp.bi, tri_len(size));
}

// Degenerate triangles at the same contact x (vertex a, or a point of edge
// ab), staying in out.(y - x) >= 0: "point" (every vertex at x), "segment"
// (c repeats a or b), "collinear" (c on line ab, from a, or from 0.5 |ab|
// before a when ab lies across `out`, to 0.5 |ab| beyond b: inside the edge
// or extending it either way), "sliver" (collinear, then moved off the line
// by 1e-8, 1e-16 or 2^-30..2^-60 of |ab| to the side of `out`). Returns the
// tag prefix.
std::string collapse(Triangle& t, Vec3 x, Vec3 out, bool two_sided, bool allow_point = true) {
  const int kind = pick_int(allow_point ? 0 : 1, 3);
  if (kind == 0) {
    t = {x, x, x};
    return "point-";
  }
  if (kind == 1) {
    t.c = pick_int(0, 1) ? t.a : t.b;
    return "segment-";
  }
  const Vec3 ab = t.b - t.a;
  t.c = t.a + pick_real(two_sided ? -0.5 : 0.0, 1.5) * ab;
  if (kind == 2) return "collinear-";
  const double l = length(ab);
  if (l > 0) {
    const Vec3 p1 = any_perpendicular(ab), p2 = (1 / l) * cross(ab, p1);
    const double th = pick_real(0, kTwoPi);
    Vec3 w = std::cos(th) * p1 + std::sin(th) * p2;
    if (dot(w, out) < 0) w = -w;
    const int e = pick_int(0, 2);
    t.c = t.c + (l * (e == 0 ? 1e-8 : (e == 1 ? 1e-16 : std::ldexp(1.0, -pick_int(30, 60))))) * w;
  }
  return "sliver-";
}

// Random poses: vertices within 2 scene sizes of a point within 3 of the
// cylinder's middle.
TriCase tri_random(const Scene& sc, const Frame& f) {
  const Vec3 m = 0.5 * (f.c.p + f.c.q) + sc.size * Vec3{pick_real(-3, 3), pick_real(-3, 3), pick_real(-3, 3)};
  auto v = [&] { return m + sc.size * Vec3{pick_real(-2, 2), pick_real(-2, 2), pick_real(-2, 2)}; };
  return {{f.c, Triangle{v(), v(), v()}}, "random"};
}

// A triangle vertex, edge or face at the rim (rim-above, rim-side,
// rim-diag), on a cap or on the side, touching (+- ulps) or a gap either way.
// Edges along the rim's or the side's circle ("-along": tangent to the rim,
// to the side), across it ("-across": crossing the rim, or along the axis on
// the side) or any direction across the normal. With `degenerate`, the
// triangle collapsed at the contact (collapse()).
TriCase tri_feature(const Scene& sc, const Frame& f, int feature, bool degenerate) {
  Cylinder c = f.c;
  const Spot sp = pick_spot(f, pick_region());
  const double gap = pick_gap(sc.size);
  const int edge_dir = pick_int(0, 2);
  const Vec3 x = sp.at + gap * sp.out;
  Triangle t = tri_feature_at(sp, x, feature, edge_dir, sc.size);
  std::string tag = std::string(feature == 0 ? "vertex-" : (feature == 1 ? "edge-" : "face-")) + sp.name +
                    (feature == 1 ? kTriEdgeDirs[edge_dir] : "");
  if (degenerate) tag = collapse(t, x, sp.out, feature == 1) + tag;
  tag += tri_touch_or_gap(c, t, sp.out, gap);
  return {{c, restate(t)}, tag};
}

// A triangle parallel to a cap: above it ("above": a tiny or a large height,
// a certain miss), in the cap plane ("on") or inside the slab ("below": a
// tiny depth or up to the length). In its plane it has a vertex ("-vertex")
// or an edge across the radius ("-edge") at in-plane radius r + gap, the
// triangle beyond (gap > 0 clear of the rim's circle, 0 touching it, < 0
// reaching over the disc), or it covers a point of the disc ("-over": "on"
// touches the cap face, "below" a certain overlap).
TriCase tri_cap_parallel(const Scene& sc, const Frame& f) {
  Cylinder c = f.c;
  const bool top = pick_int(0, 1);
  const Vec3 capn = top ? f.u : -f.u, capc = top ? c.q : c.p;
  const Vec3 rad = radial_dir(f, pick_real(0, kTwoPi)), tng = cross(f.u, rad);
  const int level = pick_int(0, 2), feature = pick_int(0, 2);
  const bool tiny = pick_int(0, 1);
  const double height = level == 1   ? 0.0
                        : level == 0 ? (tiny ? std::ldexp(sc.size, -pick_int(20, 50)) : pick_real(0.01, 2) * sc.size)
                                     : -(tiny ? std::ldexp(sc.size, -pick_int(20, 50)) : pick_real(0, 1) * f.len);
  const Vec3 o = capc + height * capn;
  const double gap = feature == 2 ? 0.0 : pick_gap(sc.size);
  Triangle t;
  if (feature == 2) {
    t = face_around(o + (c.r * std::sqrt(pick_real(0, 1))) * rad, rad, tng, tri_len(sc.size));
  } else {
    const Vec3 x = o + (c.r + gap) * rad;
    if (feature == 0) t = {x, x + tri_len(sc.size) * half_dir(rad, tng), x + tri_len(sc.size) * half_dir(rad, tng)};
    else t = {x - tri_len(sc.size) * tng, x + tri_len(sc.size) * tng, x + tri_len(sc.size) * half_dir(rad, tng)};
  }
  const char* levels[3] = {"capplane-above", "capplane-on", "capplane-below"};
  const char* features[3] = {"-vertex", "-edge", "-over"};
  std::string tag = std::string(levels[level]) + features[feature];
  if (level == 1 && feature == 2) tag += tri_touch_or_gap(c, t, capn, 0);
  else if (level != 0 && feature != 2) tag += tri_touch_or_gap(c, t, rad, gap);
  return {{c, restate(t)}, tag};
}

// A triangle in a plane parallel to the axis: through the axis ("through"),
// cutting a chord ("chord": at 0.05..0.95 r from the axis), or at r + gap
// from it ("beside": tangent to the side, clear of it, or cutting it near
// the side; the triangle covers a point of the plane's line nearest the
// axis, between the caps). Through and chord: the section is the rectangle
// [0, len] x [-w, w] (along the axis, across it); the triangle has a vertex
// or an edge at its long side ("-side"), its short side ("-cap") or a
// corner ("-corner": a rim point) with the triangle beyond the in-plane gap,
// or it covers a point of the section ("-across": a certain overlap).
TriCase tri_axis_plane(const Scene& sc, const Frame& f) {
  Cylinder c = f.c;
  const Vec3 rad = radial_dir(f, pick_real(0, kTwoPi)), tng = cross(f.u, rad);
  const int kind = pick_int(0, 2);
  const double len = length(c.q - c.p);
  if (kind == 2) {
    const double gap = pick_gap(sc.size);
    Triangle t = face_around(c.p + pick_real(0, 1) * (c.q - c.p) + (c.r + gap) * rad, f.u, tng, tri_len(sc.size));
    const std::string tag = "axisplane-beside" + tri_touch_or_gap(c, t, rad, gap);
    return {{c, restate(t)}, tag};
  }
  const double s = kind == 0 ? 0.0 : c.r * pick_real(0.05, 0.95);
  const double w = kind == 0 ? c.r : std::sqrt(std::max(0.0, c.r * c.r - s * s));
  const Vec3 o = c.p + s * rad;
  auto at = [&](double along, double acr) { return o + along * f.u + acr * tng; };
  std::string tag = kind == 0 ? "axisplane-through" : "axisplane-chord";
  const int place = pick_int(0, kind == 0 ? 4 : 3);
  if (place == 4) {
    // An edge along the axis line (its ends computed from p and q, so a few
    // ulps off it), the third vertex in the plane across it: the edge's
    // direction in a cap plane is rounding noise.
    auto on_axis = [&](double t) { return t <= 0.5 ? c.p + t * (c.q - c.p) : c.q - (1 - t) * (c.q - c.p); };
    const double t0 = pick_int(0, 2) == 0 ? 0.0 : pick_real(-0.5, 0.5);
    const double t1 = pick_int(0, 2) == 0 ? 1.0 : pick_real(0.5, 1.5);
    const Triangle t{on_axis(t0), on_axis(t1), at(pick_real(-0.5, 1.5) * len, pick_real(0.1, 3) * w * (pick_int(0, 1) ? 1 : -1))};
    return {{c, restate(t)}, tag + "-axis-edge"};
  }
  if (place == 3) {
    Triangle t = face_around(at(pick_real(0, 1) * len, pick_real(-1, 1) * w), f.u, tng, tri_len(sc.size));
    return {{c, restate(t)}, tag + "-across"};
  }
  const double gap = pick_gap(sc.size);
  const double sa = pick_int(0, 1) ? 1.0 : -1.0, st = pick_int(0, 1) ? 1.0 : -1.0;
  Vec3 x, out;
  if (place == 0) {
    out = sa * tng;
    x = at(pick_real(0, 1) * len, sa * (w + gap));
    tag += "-side";
  } else if (place == 1) {
    out = st * f.u;
    x = at(st > 0 ? len + gap : -gap, pick_real(-1, 1) * w);
    tag += "-cap";
  } else {
    const double psi = pick_real(0, 1.5707963267948966);
    out = std::cos(psi) * (st * f.u) + std::sin(psi) * (sa * tng);
    x = at(st > 0 ? len : 0.0, sa * w) + gap * out;
    tag += "-corner";
  }
  const Vec3 perp = cross(rad, out);  // in the plane, across `out`
  Triangle t;
  if (pick_int(0, 1)) {
    t = {x, x + tri_len(sc.size) * half_dir(out, perp), x + tri_len(sc.size) * half_dir(out, perp)};
    tag += "-vertex";
  } else {
    t = {x - tri_len(sc.size) * perp, x + tri_len(sc.size) * perp, x + tri_len(sc.size) * half_dir(out, perp)};
    tag += "-edge";
  }
  tag += tri_touch_or_gap(c, t, out, gap);
  return {{c, restate(t)}, tag};
}

// A tilted triangle through a cap plane whose point nearest the axis segment
// lies beyond the cap. Vertex W is over the cap disc at radius rho (0.3..0.95
// r); the other two rise from it at slopes 0.02..0.3 towards the axis and past
// it (horizontally 10..50 degrees either side of the inward radius), so the
// triangle passes over the axis at a height of about slope * rho: its point
// nearest the axis segment is beyond the cap, within r of the cap centre,
// while its section by the cap plane is a short segment next to W. W pokes
// through the cap plane by delta ("capcross-deep": the section lies in the
// disc, overlapping; a query without its cap stage misses it), hovers delta
// above it ("-gap": the near miss), touches it ("-touch", +- ulps), or pokes
// through just outside the rim's circle ("-outside": W at radius r + 1.5..3
// delta / slope, the section clear of the disc, a miss). A fifth of the time
// the triangle is collapsed onto its edges from W (segment, collinear,
// sliver).
TriCase tri_cap_cross(const Scene& sc, const Frame& f) {
  Cylinder c = f.c;
  if (c.r == 0) c.r = sc.size;
  const bool top = pick_int(0, 1);
  const Vec3 capn = top ? f.u : -f.u, capc = top ? c.q : c.p;
  const Vec3 rad = radial_dir(f, pick_real(0, kTwoPi)), tng = cross(f.u, rad);
  const int kind = pick_int(0, 4);  // 0, 1 deep, 2 gap, 3 touch, 4 outside
  const double s1 = pick_real(0.02, 0.3), s2 = pick_real(0.02, 0.3), smin = std::min(s1, s2);
  double rho = c.r * pick_real(0.3, 0.95);
  const double delta =
      pick_int(0, 1) ? std::ldexp(sc.size, -pick_int(20, 50)) : pick_real(0.001, 0.05) * smin * rho;
  if (kind == 4) rho = c.r + pick_real(1.5, 3) * delta / smin;
  const double gap = kind <= 1 || kind == 4 ? -delta : (kind == 2 ? delta : 0.0);
  const double a1 = pick_real(0.17, 0.87), a2 = pick_real(0.17, 0.87);
  const Vec3 h1 = -std::cos(a1) * rad + std::sin(a1) * tng, h2 = -std::cos(a2) * rad - std::sin(a2) * tng;
  const double l = rho * pick_real(1.3, 2.5) / std::cos(std::max(a1, a2));
  const Vec3 w = capc + rho * rad + gap * capn;
  Triangle t{w, w + l * (h1 + s1 * capn), w + l * (h2 + s2 * capn)};
  std::string tag = "capcross";
  if (pick_int(0, 4) == 0) tag = collapse(t, w, capn, false, false) + tag;
  if (kind == 4) tag += "-outside";
  else tag += tri_touch_or_gap(c, t, capn, gap);
  return {{c, restate(t)}, tag};
}

// A triangle in the plane n.(y - x) = -gap (x the cylinder's lowest point
// along n: the cylinder lies in n.(y - x) >= 0), holding x - gap n inside
// (four times in five; vertex distances 0.3..1 times len) or on its edge ab
// ("-edge"). Returns the tag suffix.
Triangle tri_under(Vec3 x, Vec3 n, double gap, double len, std::string& tag) {
  const Vec3 e1 = any_perpendicular(n), e2 = cross(n, e1), y = x - gap * n;
  if (pick_int(0, 4) != 0) return face_around(y, e1, e2, len);
  tag += "-edge";
  const double th = pick_real(0, kTwoPi);
  const Vec3 d = std::cos(th) * e1 + std::sin(th) * e2, w = cross(n, d);
  return {y - (len * pick_real(0.1, 1)) * d, y + (len * pick_real(0.1, 1)) * d,
          y + (len * pick_real(0.3, 1)) * (w + pick_real(-1, 1) * d)};
}

// The axis of a cylinder lying on a plane of normal n: along n ("flat",
// "stand"), tilted, or across n ("edgewise", "lie").
Vec3 axis_on(Vec3 n, int orient) {
  if (orient == 0) return pick_int(0, 1) ? n : -n;
  const Vec3 e1 = any_perpendicular(n), e2 = cross(n, e1);
  const double th = pick_int(0, 2) == 0 ? 0.0 : pick_real(0, kTwoPi);
  const Vec3 w = std::cos(th) * e1 + std::sin(th) * e2;
  return orient == 1 ? unit(n + pick_real(0.01, 2) * w) : w;
}

// A small cylinder resting on a huge triangle (10^2..10^4 times the
// cylinder's size): standing on a cap, lying on its side or tilted on its
// rim, touching (+- ulps), a tiny gap or penetration, or 0.001..0.1 of its
// size either way.
TriCase tri_huge(const Scene& sc) {
  const Vec3 n = pick_dir();
  const int orient = pick_int(0, 2);
  const double r = pick_real(0.05, 2) * sc.size, len = pick_real(0.05, 4) * sc.size;
  const Vec3 p = sc.offset + sc.size * Vec3{pick_real(-2, 2), pick_real(-2, 2), pick_real(-2, 2)};
  Cylinder c{p, p + len * axis_on(n, orient), r};
  if (pick_int(0, 1)) std::swap(c.p, c.q);
  const double size = std::max(r, len);
  double gap = 0;
  switch (pick_int(0, 4)) {
    case 0: gap = 0; break;
    case 1: gap = std::ldexp(size, -pick_int(20, 50)); break;
    case 2: gap = -std::ldexp(size, -pick_int(20, 50)); break;
    case 3: gap = pick_real(0.001, 0.1) * size; break;
    default: gap = -pick_real(0.001, 0.1) * size; break;
  }
  const char* names[3] = {"huge-stand", "huge-tilted", "huge-lie"};
  std::string tag = names[orient];
  Triangle t = tri_under(cylinder_lowest(c, n), n, gap, size * std::pow(10.0, pick_real(2, 4)), tag);
  tag += tri_touch_or_gap(c, t, -n, gap);
  return {{c, restate(t)}, tag};
}

// A thin disk-like cylinder (length 1e-6..1e-12 of r, at least 2^-44 of its
// coordinates) on a triangle: flat (axis along the triangle's normal),
// tilted, or edgewise (axis in the triangle's plane), the contact inside the
// triangle or on its edge, touching (+- ulps) or a tiny gap either way.
TriCase tri_thin(const Scene& sc) {
  const Vec3 n = pick_dir();
  const int orient = pick_int(0, 2);
  const double r = pick_real(0.05, 2) * sc.size;
  const Vec3 p = sc.offset + sc.size * Vec3{pick_real(-2, 2), pick_real(-2, 2), pick_real(-2, 2)};
  const double len = std::max(r * std::pow(10.0, -pick_real(6, 12)), std::ldexp(max_abs(p), -44));
  Cylinder c{p, p + len * axis_on(n, orient), r};
  if (pick_int(0, 1)) std::swap(c.p, c.q);
  const int gk = pick_int(0, 2);
  const double gap = gk == 0 ? 0.0 : (gk == 1 ? 1.0 : -1.0) * std::ldexp(sc.size, -pick_int(20, 50));
  const char* names[3] = {"thin-flat", "thin-tilted", "thin-edgewise"};
  std::string tag = names[orient];
  Triangle t = tri_under(cylinder_lowest(c, n), n, gap, pick_real(0.3, 3) * sc.size, tag);
  tag += tri_touch_or_gap(c, t, -n, gap);
  return {{c, restate(t)}, tag};
}

// Triangle-mesh data: a vertex, edge or face at a spot with scene size 1 at
// offsets 40..100, every coordinate and the radius rounded to float.
TriCase tri_f32() {
  Scene sc{1, {}};
  for (int i = 0; i < 3; ++i) sc.offset[i] = (pick_int(0, 1) ? 1 : -1) * pick_real(40, 100);
  const Frame f = pick_cylinder(sc);
  const Spot sp = pick_spot(f, pick_region());
  const double gap = (pick_int(0, 1) ? 1 : -1) * pick_real(0.001, 0.3);
  const Triangle t = tri_feature_at(sp, sp.at + gap * sp.out, pick_int(0, 2), pick_int(0, 2), sc.size);
  const Cylinder c{to_f32(f.c.p), to_f32(f.c.q), to_f32(f.c.r)};
  return {{c, restate(Triangle{to_f32(t.a), to_f32(t.b), to_f32(t.c)})}, "pattern-f32" + gap_tag(gap)};
}

// Exact integer constructions: the cylinder along +z from z0 to top = z0 + h,
// radius C = c k for a Pythagorean triple (a, b, c), the rim point
// R = (a k, b k, top), then exact moves. Triangles by tag:
//   exact-vertex-rim    vertex R, the others strictly beyond the plane across
//                       a rim direction (the triples, straight up, straight
//                       out);
//   exact-vertex-side   vertex (a k, b k, z), z0 <= z <= top, the others
//                       strictly outwards along the radius;
//   exact-vertex-cap    vertex at an integer point of the cap within the
//                       disc, the others above the cap plane;
//   exact-edge-side     an edge through (a k, b k, z) tangent to the side
//                       (along the circle's tangent, the axis or a mix);
//   exact-edge-rim      an edge through R along the rim's tangent (or, for
//                       a diagonal rim direction, any direction across it);
//   exact-inplane-rim   in the cap plane, a vertex or a tangent edge at R,
//                       the triangle outside the disc;
//   exact-face-cap      in the cap plane, a vertex within the disc;
//   exact-zero-radius   k = 0 (the cylinder is its segment): an edge across
//                       the axis at height z0..top, the triangle on one side.
// A quarter of the triangles are degenerate at the contact ("point-",
// "segment-", "collinear-" after "exact-"). Touches are nudged by k ulps
// towards overlap (k > 0: "-ulps-in") or away ("-ulps-out"): the radius for
// rim and side contacts, the top cap along the axis for cap contacts, the
// triangle across the axis for the zero radius ("-ulps-off": a degenerate
// triangle moved off the axis either way). A fifth of the non-zero-radius
// triangles are moved instead, exactly: out of the cylinder along the
// contact's normal ("-gap", at most half of r and h), or from the contact
// 2^-1..2^-25 of the way towards the cylinder's centre ("-deep").
TriCase exact_cylinder_triangle() {
  const auto& t1 = kTriples[pick_int(0, kNumTriples - 1)];
  const double a = t1[0], b = t1[1], cc = t1[2];
  const int k = pick_int(0, 12) == 0 ? 0 : pick_int(1, 4);
  const int h = pick_int(1, 20), z0 = pick_int(-10, 10), top = z0 + h;
  const double A = a * k, B = b * k, C = cc * k;
  const Exact ex = pick_exact();
  Cylinder cyl{ex.apply({0, 0, double(z0)}), ex.apply({0, 0, double(top)}), ex.len(C)};
  const Vec3 R{A, B, double(top)}, rad{a, b, 0}, tng{-b, a, 0}, up{0, 0, 1};
  auto n = [](int lo, int hi) { return double(pick_int(lo, hi)); };
  Vec3 va, vb, vc, x, out;  // the vertices; the contact x (vertex a or on edge ab); its normal
  int nudged = 0;           // 0: the radius, 1: the top cap, 2: the triangle along +x
  std::string what;
  switch (k == 0 ? 7 : pick_int(0, 6)) {
    case 0:
    case 4: {
      const auto& t2 = kRimDirs[pick_int(0, kNumRimDirs - 1)];
      out = {t2[0] * a, t2[0] * b, t2[1] * cc};
      const Vec3 bin{-t2[1] * a, -t2[1] * b, t2[0] * cc};  // across out and tng
      x = R;
      vc = R + n(1, 4) * out + n(-5, 5) * tng + n(-5, 5) * bin;
      if (pick_int(0, 1) == 0) {  // vertex at R
        va = R;
        vb = R + n(1, 4) * out + n(-5, 5) * tng + n(-5, 5) * bin;
        what = "vertex-rim";
      } else {  // an edge through R across out
        const bool diag = t2[0] > 0 && t2[1] > 0;
        Vec3 e = diag && pick_int(0, 1) ? n(-3, 3) * tng + n(-3, 3) * bin : tng;
        if (e == Vec3{}) e = tng;
        va = R - n(0, 5) * e;
        vb = R + n(1, 5) * e;
        what = "edge-rim";
      }
      break;
    }
    case 1:
    case 3: {
      const Vec3 v{A, B, n(z0, top)};
      out = rad;
      x = v;
      vc = v + n(1, 4) * rad + n(-5, 5) * tng + n(-5, 5) * up;
      if (pick_int(0, 1) == 0) {
        va = v;
        vb = v + n(1, 4) * rad + n(-5, 5) * tng + n(-5, 5) * up;
        what = "vertex-side";
      } else {
        Vec3 e = n(-3, 3) * tng + n(-3, 3) * up;
        if (e == Vec3{}) e = tng;
        va = v - n(0, 5) * e;
        vb = v + n(1, 5) * e;
        what = "edge-side";
      }
      break;
    }
    case 2: {
      va = x = {n(-int(A), int(A)), n(-int(B), int(B)), double(top)};
      out = up;
      vb = va + Vec3{n(-5, 5), n(-5, 5), n(1, 5)};
      vc = va + Vec3{n(-5, 5), n(-5, 5), n(1, 5)};
      nudged = 1;
      what = "vertex-cap";
      break;
    }
    case 5: {
      x = R;
      out = rad;
      vc = R + n(1, 5) * rad + n(-5, 5) * tng;
      if (pick_int(0, 1)) {
        va = R;
        vb = R + n(1, 5) * rad + n(-5, 5) * tng;
      } else {
        va = R - n(0, 5) * tng;
        vb = R + n(1, 5) * tng;
      }
      what = "inplane-rim";
      break;
    }
    case 6: {
      const int m = int(C) + 10;
      va = x = {n(-int(A), int(A)), n(-int(B), int(B)), double(top)};
      out = up;
      vb = {n(-m, m), n(-m, m), double(top)};
      vc = {n(-m, m), n(-m, m), double(top)};
      nudged = 1;
      what = "face-cap";
      break;
    }
    default: {
      const double zc = n(z0, top);
      x = {0, 0, zc};
      out = {1, 0, 0};
      va = {0, -n(1, 5), zc};  // the axis strictly inside the edge
      vb = {0, n(1, 5), zc};
      vc = {n(1, 5), n(-5, 5), zc > z0 && zc < top ? zc + n(-5, 5) : zc};  // crossing the axis between the caps
      nudged = 2;
      what = "zero-radius";
      break;
    }
  }
  bool collapsed = false;
  if (pick_int(0, 3) == 0) {
    collapsed = true;
    switch (pick_int(0, 2)) {
      case 0: va = vb = vc = x; what = "point-" + what; break;
      case 1: vc = pick_int(0, 1) ? va : vb; what = "segment-" + what; break;
      default: vc = pick_int(0, 1) ? 0.5 * (va + vb) : va + 2.0 * (vb - va); what = "collinear-" + what; break;
    }
  }
  std::string tag = "exact-" + what;
  if (nudged != 2 && pick_int(0, 4) == 0) {
    // Out along the contact normal by 2^-s |out| (at most half of min(C, h)),
    // or into the cylinder towards its centre m by 2^-s |x - m|, s >= 1 (x
    // goes strictly inside: along the normal it could slide on the surface).
    Vec3 step;
    const bool into = pick_int(0, 1);
    if (into) {
      step = std::ldexp(1.0, -pick_int(2, 26)) * (2.0 * x - Vec3{0, 0, double(z0 + top)});
    } else {
      const double lo = std::ceil(std::log2(2 * length(out) / std::min(C, double(h))));
      step = -std::ldexp(1.0, -int(lo) - pick_int(0, 24)) * out;
    }
    for (Vec3* v : {&va, &vb, &vc}) *v = *v - step;
    tag += into ? "-deep" : "-gap";
    nudged = -1;
  }
  Triangle t{ex.apply(va), ex.apply(vb), ex.apply(vc)};
  const int ulps = pick_int(-2, 2);
  if (nudged == 0) {
    cyl.r = nudge(cyl.r, ulps);
    tag += ulps_tag(ulps);
  } else if (nudged == 1) {
    const int s = ex.slot(2);
    cyl.q[s] = nudge(cyl.q[s], ex.sign(2) > 0 ? ulps : -ulps);
    tag += ulps_tag(ulps);
  } else if (nudged == 2) {
    const int s = ex.slot(0);
    for (Vec3* v : {&t.a, &t.b, &t.c}) (*v)[s] = nudge((*v)[s], ex.sign(0) > 0 ? ulps : -ulps);
    tag += ulps == 0 ? "-touch" : (collapsed ? "-ulps-off" : ulps_tag(-ulps));
  }
  if (pick_int(0, 1)) std::swap(cyl.p, cyl.q);
  return {{cyl, restate(t)}, tag};
}

}  // namespace

rc::Gen<std::pair<CylinderTriangleCase, std::string>> cylinder_triangle_case() {
  return rc::gen::resize(100, rc::gen::exec([]() -> std::pair<CylinderTriangleCase, std::string> {
    const int mode = pick_int(0, 14);
    if (mode == 12 || mode == 13) return exact_cylinder_triangle();
    if (mode == 14) return tri_f32();
    const Scene sc = pick_scene();
    if (mode == 10) return tri_huge(sc);
    if (mode == 11) return tri_thin(sc);
    const Frame f = pick_cylinder(sc);
    switch (mode) {
      case 0: return tri_random(sc, f);
      case 1:
      case 2:
      case 3: return tri_feature(sc, f, mode - 1, false);
      case 4: return tri_feature(sc, f, pick_int(0, 1), true);
      case 5: return tri_cap_parallel(sc, f);
      case 6: return tri_axis_plane(sc, f);
      default: return tri_cap_cross(sc, f);  // 7, 8, 9
    }
  }));
}

rc::Gen<CylinderTriangleCase> wild_cylinder_triangle() {
  return rc::gen::resize(100, rc::gen::exec([]() -> CylinderTriangleCase {
    const Cylinder a{wild_vec(), wild_vec(), *wild_double()};
    Triangle b{wild_vec(), wild_vec(), wild_vec()};
    if (pick_int(0, 3) == 0) {  // repeated vertices: segment and point triangles
      b.c = pick_int(0, 1) ? b.a : b.b;
      if (pick_int(0, 1)) b.b = b.a;
    }
    return {a, b};
  }));
}


// ---- cylinder / cylinder --------------------------------------------------------

namespace {

using CylCase = std::pair<CylinderCylinderCase, std::string>;

// A scene as pick_scene, or a third of the time one of size 2^-60..2^60,
// optionally 2^10..2^40 sizes from the origin.
Scene pick_wide_scene() {
  if (pick_int(0, 2) != 0) return pick_scene();
  Scene s;
  s.size = std::ldexp(1.0, pick_int(-60, 60));
  s.offset = {0, 0, 0};
  if (pick_int(0, 2) == 0) {
    const double far = std::ldexp(s.size, pick_int(10, 40));
    s.offset = {pick_real(-far, far), pick_real(-far, far), pick_real(-far, far)};
  }
  return s;
}

// The same cylinder with its caps stored the other way round, half the time.
Cylinder restate(const Cylinder& c) { return pick_int(0, 1) ? Cylinder{c.q, c.p, c.r} : c; }

// An angle from parallel: exactly none, or 1e-4, 1e-8, 1e-12, 1e-16 radians.
double pick_angle() {
  switch (pick_int(0, 4)) {
    case 0: return 0;
    case 1: return 1e-4;
    case 2: return 1e-8;
    case 3: return 1e-12;
    default: return 1e-16;
  }
}
std::string angle_tag(double a) {
  if (a == 0) return "";
  if (a > 1e-6) return "-1e-4";
  if (a > 1e-10) return "-1e-8";
  if (a > 1e-14) return "-1e-12";
  return "-1e-16";
}

// A dyadic value in [lo, hi] with three fractional bits: sums of a few of
// them are exact.
double pick_dyadic(int lo8, int hi8) { return pick_int(lo8, hi8) / 8.0; }

// Where an axis-aligned construction lands: exact moves (coordinate
// permutation, sign flips, a power-of-two scale 2^-60..2^60, no offset, so
// that ulp-sized features and tiny angles survive bit for bit), or a
// rounded rigid motion into a random frame of a scene.
struct Place {
  bool exact = true;
  Exact ex{};
  Vec3 o, e1, e2, u;
  double s = 1;
  Vec3 pt(Vec3 v) const { return exact ? ex.apply(v) : o + s * (v.x * e1 + v.y * e2 + v.z * u); }
  double len(double r) const { return exact ? ex.len(r) : s * r; }
  Cylinder cyl(Vec3 p, Vec3 q, double r) const { return {pt(p), pt(q), len(r)}; }
};
Place pick_place(bool exact) {
  Place pl;
  pl.exact = exact;
  pl.ex = pick_exact();
  pl.ex.off = {0, 0, 0};
  if (pick_int(0, 3) == 0) pl.ex.e = pick_int(-60, 60);
  if (!exact) {
    const Scene sc = pick_wide_scene();
    pl.o = sc.offset;
    pl.s = sc.size;
    pl.u = pick_dir();
    pl.e1 = any_perpendicular(pl.u);
    pl.e2 = cross(pl.u, pl.e1);
  }
  return pl;
}
// Exact moves for the constructions whose point is an ulp or a tiny angle;
// a rounded rigid motion for a third of the others.
Place place_for(bool fine) { return pick_place(fine || pick_int(0, 2) != 0); }

// A gap along a construction coordinate: exactly zero, k ulps either way of
// a touching coordinate v (returned as the moved coordinate), or a small or
// large gap either way.
struct Gap {
  double v;
  std::string tag;
};
Gap pick_coordinate_gap(double v, double size) {
  switch (pick_int(0, 4)) {
    case 0: return {v, "-touch"};
    case 1: {
      const int k = pick_int(1, 4) * (pick_int(0, 1) ? 1 : -1);
      return {nudge(v, k), k > 0 ? "-ulps-out" : "-ulps-in"};
    }
    case 2: {
      const double g = std::ldexp(size, -pick_int(20, 50)) * (pick_int(0, 1) ? 1 : -1);
      return {v + g, g > 0 ? "-gap" : "-deep"};
    }
    default: {
      const double g = pick_real(0.01, 2) * size * (pick_int(0, 1) ? 1 : -1);
      return {v + g, g > 0 ? "-gap" : "-deep"};
    }
  }
}

// Parallel, anti-parallel and nearly parallel cylinders side by side: A on
// the z axis, B's axis at x = d = rA + rB (+ gap, or k ulps), an axial
// offset either way. The angle is made exactly: a tangential tilt moves B's
// top cap centre to y = lB * angle (B's bottom at y = 0, so nothing rounds
// it away), a radial one A's top cap centre to x = -lA * angle (A leaning
// away from B, both axes in the plane y = 0). Exact moves only when tilted
// below 1e-8 (a rotation in doubles would round those angles).
CylCase cyl_parallel() {
  const double rA = pick_int(0, 10) == 0 ? 0.0 : pick_dyadic(1, 24), rB = pick_dyadic(1, 24);
  const double lA = pick_dyadic(2, 40), lB = pick_dyadic(2, 40);
  const double angle = pick_angle();
  const bool radial = pick_int(0, 1), anti = pick_int(0, 1);
  const Gap g = pick_coordinate_gap(rA + rB, 1.0);
  const double z0 = pick_dyadic(-8 * int(lB) - 4, 8 * int(lA) + 4);
  const Place pl = place_for(angle != 0 && angle < 1e-6);
  Vec3 aq{0, 0, lA}, bp{g.v, 0, z0}, bq{g.v, 0, z0 + lB};
  if (angle != 0 && radial) aq.x = -lA * angle;
  if (angle != 0 && !radial) bq.y = lB * angle;
  if (anti) std::swap(bp, bq);
  const std::string tilt = angle == 0 ? "" : angle_tag(angle) + (radial ? "-radial" : "-tangential");
  return {{pl.cyl({0, 0, 0}, aq, rA), pl.cyl(bp, bq, rB)},
          std::string(anti ? "anti-parallel-side" : "parallel-side") + tilt + g.tag};
}

// Coaxial and stacked cylinders: B's bottom cap on A's top cap plane (z =
// lA, exactly; k ulps above or below; a small or large gap; overlapping),
// B's axis on A's (coaxial) or beside it within rA + rB (stacked; at exactly
// rA + rB the rims meet at a point), B the same way up or upside down
// (anti), optionally tilted about its bottom cap centre (tangentially: the
// rim dips by rB sin(angle)).
CylCase cyl_coaxial() {
  const double rA = pick_dyadic(0, 24), rB = pick_dyadic(1, 24);
  const double lA = pick_dyadic(1, 40), lB = pick_dyadic(1, 40);
  const double angle = pick_angle();
  const bool anti = pick_int(0, 1);
  const int lat = pick_int(0, 3);  // coaxial, inside, at the rim sum, beyond
  double x = 0;
  if (lat == 1) x = pick_dyadic(0, int(8 * (rA + rB)));
  if (lat == 2) x = rA + rB;
  if (lat == 3) x = rA + rB + pick_dyadic(1, 16);
  Gap g = pick_coordinate_gap(lA, 1.0);
  if (pick_int(0, 5) == 0) g = {pick_dyadic(0, int(8 * lA)), "-overlap"};  // B's cap inside A's length
  const Place pl = place_for(true);
  Vec3 bp{x, 0, g.v}, bq{x, 0, g.v + lB};
  if (angle != 0) bq.y = lB * angle;
  if (anti) std::swap(bp, bq);
  const std::string where = lat == 0 ? "coaxial" : (lat == 2 ? "stacked-rim" : "stacked");
  return {{pl.cyl({0, 0, 0}, {0, 0, lA}, rA), pl.cyl(bp, bq, rB)},
          where + (anti ? "-anti" : "") + angle_tag(angle) + g.tag};
}

// Perpendicular crossings, A on the z axis: B along x with its side against
// A's side (the axes rA + rB apart: a point contact) or lying on A's top
// cap; B along y with its bottom cap against A's side (the cap plane
// tangent to the side along a line), or crossing A's axis (through).
CylCase cyl_perpendicular() {
  const double rA = pick_dyadic(0, 24), rB = pick_dyadic(0, 24);
  const double lA = pick_dyadic(2, 40), lB = pick_dyadic(2, 40);
  const double s = pick_dyadic(0, int(8 * lB));
  const Place pl = place_for(pick_int(0, 1));
  Vec3 bp, bq;
  std::string tag;
  switch (pick_int(0, 3)) {
    case 0: {
      const Gap g = pick_coordinate_gap(rA + rB, 1.0);
      const double z = pick_dyadic(-8, int(8 * lA) + 8);
      bp = {-s, g.v, z}, bq = {lB - s, g.v, z};
      tag = "perp-side-side" + g.tag;
      break;
    }
    case 1: {
      const Gap g = pick_coordinate_gap(lA + rB, 1.0);
      const double y = pick_dyadic(-int(8 * rA) - 8, int(8 * rA) + 8);
      bp = {-s, y, g.v}, bq = {lB - s, y, g.v};
      tag = "perp-side-on-cap" + g.tag;
      break;
    }
    case 2: {
      const Gap g = pick_coordinate_gap(rA, 1.0);
      const double x = pick_dyadic(-int(8 * rB) - 4, int(8 * rB) + 4), z = pick_dyadic(-8, int(8 * lA) + 8);
      bp = {x, g.v, z}, bq = {x, g.v + lB, z};
      tag = "perp-cap-on-side" + g.tag;
      break;
    }
    default: {
      const double z = pick_dyadic(0, int(8 * lA));
      bp = {-s, pick_dyadic(-int(8 * rA), int(8 * rA)), z}, bq = {lB - s, bp.y, z};
      tag = "perp-through";
      break;
    }
  }
  if (pick_int(0, 1)) std::swap(bp, bq);
  return {{pl.cyl({0, 0, 0}, {0, 0, lA}, rA), pl.cyl(bp, bq, rB)}, tag};
}

// B's cap (feature 0), side (1) or rim (2) at a spot of A: B lies in
// out.(y - at) >= gap and holds at + gap out, so for gap >= 0 their
// distance is gap (to rounding). Cap: B's axis along `out`, the spot inside
// its cap disc; side: B's axis across `out`, rB above the plane; rim: B's
// axis leaning away from A (w.out in [0.1, 0.95]), the point of its rim
// lowest along `out` at the spot.
Cylinder cylinder_feature_at(const Spot& sp, double gap, int feature, double rB, double lB) {
  const Vec3 x = sp.at + gap * sp.out;
  if (feature == 0) {
    const Vec3 p = x + (rB * std::sqrt(pick_real(0, 1))) * across(sp);
    return {p, p + lB * sp.out, rB};
  }
  if (feature == 1) {
    const Vec3 v = across(sp), c = x + rB * sp.out;
    const double t = pick_real(0, 1) * lB;
    return {c - t * v, c + (lB - t) * v, rB};
  }
  const double co = pick_real(0.1, 0.95), si = std::sqrt(1 - co * co);
  const Vec3 w = co * sp.out + si * across(sp);
  const Vec3 p = x + (rB / si) * (sp.out - co * w);
  return {p, p + lB * w, rB};
}
const char* const kCylFeatureNames[3] = {"cap", "side", "rim"};

// Radius and length of a cylinder whose length over radius is 10^-6..10^6
// (a disk to a needle), the larger of the two size * 0.5..4.
std::pair<double, double> pick_proportions(double size, bool extreme) {
  if (!extreme) return {pick_int(0, 15) == 0 ? 0.0 : pick_real(0.05, 4) * size, pick_real(0.05, 8) * size};
  const double ratio = std::pow(10.0, pick_real(-6, 6));
  const double big = pick_real(0.5, 4) * size;
  return ratio >= 1 ? std::pair<double, double>{big / ratio, big} : std::pair<double, double>{big, big * ratio};
}

// Features against features (see cylinder_feature_at) at a spot of A (its
// rim, a cap or its side); `extreme`: both cylinders disks or needles.
CylCase cyl_feature(int feature, bool extreme) {
  const Scene sc = pick_wide_scene();
  Frame f = pick_cylinder(sc);
  if (extreme) {
    const auto [r, len] = pick_proportions(sc.size, true);
    f.c = {f.c.p, f.c.p + len * f.u, r};
    f.u = (1.0 / length(f.c.q - f.c.p)) * (f.c.q - f.c.p);
    f.e1 = any_perpendicular(f.u);
    f.e2 = cross(f.u, f.e1);
  }
  const Spot sp = pick_spot(f, pick_region());
  const double gap = pick_gap(extreme ? std::min(f.c.r + length(f.c.q - f.c.p), sc.size) : sc.size);
  const auto [rB, lB] = pick_proportions(sc.size, extreme);
  Cylinder a = f.c, b = cylinder_feature_at(sp, gap, feature, rB, lB);
  if (gap == 0) {  // touching, then both radii grown or shrunk by k ulps
    const int k = pick_int(-2, 2);
    a.r = std::max(0.0, nudge(a.r, k));
    b.r = std::max(0.0, nudge(b.r, k));
  }
  return {{restate(a), restate(b)},
          std::string(extreme ? "ratio-" : "") + kCylFeatureNames[feature] + "-on-" + sp.name + gap_tag(gap)};
}

// Random pairs in a scene (2^-60..2^60, possibly far from the origin): B's
// middle within 3 sizes of A's; a quarter of the time through A (B's
// middle inside A: overlapping).
CylCase cyl_random() {
  const Scene sc = pick_wide_scene();
  const Frame f = pick_cylinder(sc);
  const bool through = pick_int(0, 3) == 0;
  const Vec3 mid = through ? inside_point(f)
                           : 0.5 * (f.c.p + f.c.q) + sc.size * Vec3{pick_real(-3, 3), pick_real(-3, 3), pick_real(-3, 3)};
  const Vec3 v = pick_dir();
  const auto [r, len] = pick_proportions(sc.size, pick_int(0, 4) == 0);
  const Cylinder b{mid - (0.5 * len) * v, mid + (0.5 * len) * v, r};
  return {{restate(f.c), b}, through ? "random-through" : "random"};
}

// Exact integer constructions (a Pythagorean triple a, b, c; rA + rB = c m),
// then exact moves (no offset where a coordinate is nudged). Touching
// exactly; the radius of B (or B's cap coordinate) moved by k ulps.
CylCase exact_cylinder_cylinder() {
  const auto& t = kTriples[pick_int(0, kNumTriples - 1)];
  const int m = pick_int(1, 3), a = t[0] * m, b = t[1] * m, c = t[2] * m;
  const int rA = pick_int(0, 8) == 0 ? 0 : pick_int(1, c - 1), rB = c - rA;
  const int h = pick_int(1, 20), hB = pick_int(1, 20);
  Exact ex = pick_exact();
  const int ulps = pick_int(-2, 2);
  double rb = rB;
  Vec3 bp, bq;
  std::string tag;
  bool radius_nudge = true;
  switch (pick_int(0, 5)) {
    case 0: {  // parallel, the axes (a m, b m) apart: sides touching along a segment (or a point at the ends)
      const int zb = pick_int(-hB, h);
      bp = {double(a), double(b), double(zb)}, bq = {double(a), double(b), double(zb + hB)};
      tag = "exact-parallel-side";
      break;
    }
    case 1: {  // stacked caps at z = h, lateral offset j (a, b), j <= m (j == m: the rims meet at a point)
      const int j = pick_int(0, m);
      ex.off = {0, 0, 0};
      const double z = nudge(double(h), ulps);  // k > 0: a gap of k ulps
      bp = {double(t[0] * j), double(t[1] * j), z}, bq = {bp.x, bp.y, z + hB};
      tag = j == m ? "exact-rim-rim" : "exact-stacked-caps";
      radius_nudge = false;
      break;
    }
    case 2: {  // perpendicular, the axes rA + rB apart: sides touching at a point
      const int z = pick_int(0, h), s = pick_int(0, hB);
      bp = {double(-s), double(c), double(z)}, bq = {double(hB - s), double(c), double(z)};
      tag = "exact-perp-side";
      break;
    }
    case 3: {  // B lying on A's top cap, along (a, b, 0) over the cap's centre
      const int s = pick_int(0, 3);
      bp = {double(-t[0] * s), double(-t[1] * s), double(h + rB)};
      bq = bp + double(s + pick_int(1, 3)) * Vec3{double(t[0]), double(t[1]), 0};
      tag = "exact-side-on-cap";
      break;
    }
    case 4: {  // B's cap tangent to A's side at (a k, b k) (rA = c k), B reaching out along (a, b, 0)
      const int k = pick_int(1, 3);
      const Vec3 at{double(t[0] * k), double(t[1] * k), double(pick_int(0, h))};
      const Cylinder A{ex.apply({0, 0, 0}), ex.apply({0, 0, double(h)}), nudge(ex.len(double(t[2] * k)), ulps)};
      const Cylinder B{ex.apply(at), ex.apply(at + double(pick_int(1, 3)) * Vec3{double(t[0]), double(t[1]), 0}),
                       ex.len(double(pick_int(1, 10)))};
      return {{restate(A), B}, "exact-cap-on-side" + ulps_tag(ulps)};
    }
    default: {  // zero radii: two segments crossing at a point, or B's side touching A's segment
      const int z = pick_int(0, h);
      const bool seg = pick_int(0, 1);
      const double x = seg ? 0.0 : double(c);
      const Vec3 p0{x, double(-pick_int(1, 5)), double(z)}, q0{x, double(pick_int(1, 5)), double(z)};
      const Cylinder A{ex.apply({0, 0, 0}), ex.apply({0, 0, double(h)}), 0.0};
      if (seg)  // B's segment moved off A's by k ulps (along construction x)
        return {{A, Cylinder{ex.nudge_x(ex.apply(p0), ulps), ex.nudge_x(ex.apply(q0), ulps), 0.0}},
                std::string("exact-zero-radius-cross") + (ulps == 0 ? "-touch" : "-ulps-off")};
      return {{A, Cylinder{ex.apply(p0), ex.apply(q0), nudge(ex.len(double(c)), ulps)}},
              "exact-zero-radius-side" + ulps_tag(ulps)};
    }
  }
  const Cylinder A{ex.apply({0, 0, 0}), ex.apply({0, 0, double(h)}), ex.len(rA)};
  const Cylinder B{ex.apply(bp), ex.apply(bq), radius_nudge ? nudge(ex.len(rb), ulps) : ex.len(rb)};
  const std::string ut = radius_nudge ? ulps_tag(ulps) : (ulps == 0 ? "-touch" : (ulps > 0 ? "-ulps-out" : "-ulps-in"));
  const bool anti = pick_int(0, 1);  // B stored the other way round: the same set
  return {{A, anti ? Cylinder{B.q, B.p, B.r} : B}, tag + ut};
}

}  // namespace

rc::Gen<std::pair<CylinderCylinderCase, std::string>> cylinder_cylinder_case() {
  return rc::gen::resize(100, rc::gen::exec([]() -> std::pair<CylinderCylinderCase, std::string> {
    CylCase c;
    switch (pick_int(0, 12)) {
      case 0:
      case 1: c = cyl_random(); break;
      case 2:
      case 3: c = cyl_parallel(); break;
      case 4: c = cyl_coaxial(); break;
      case 5: c = cyl_perpendicular(); break;
      case 6: c = cyl_feature(0, false); break;
      case 7: c = cyl_feature(1, false); break;
      case 8: c = cyl_feature(2, false); break;
      case 9: c = cyl_feature(pick_int(0, 2), true); break;
      default: c = exact_cylinder_cylinder(); break;
    }
    // Either cylinder first: the query is symmetric, production's roles need not be.
    if (pick_int(0, 1)) std::swap(c.first.a, c.first.b);
    return c;
  }));
}

rc::Gen<CylinderCylinderCase> wild_cylinder_cylinder() {
  return rc::gen::resize(100, rc::gen::exec([]() -> CylinderCylinderCase {
    Cylinder a{wild_vec(), wild_vec(), *wild_double()}, b{wild_vec(), wild_vec(), *wild_double()};
    if (pick_int(0, 3) == 0) {  // one of them an ordinary cylinder
      a = {{0, 0, 0}, {0, 0, 1}, 0.5};
      if (pick_int(0, 1)) std::swap(a, b);
    }
    return {a, b};
  }));
}

}  // namespace geomcheck::gen
