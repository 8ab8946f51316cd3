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
  Vec3 apply(Vec3 v) const {
    Vec3 w{v[perm % 3], v[(perm + 1) % 3], v[(perm + 2) % 3]};
    if (flips & 1) w.x = -w.x;
    if (flips & 2) w.y = -w.y;
    if (flips & 4) w.z = -w.z;
    return std::ldexp(1.0, e) * (w + off);
  }
  double len(double r) const { return std::ldexp(r, e); }
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

}  // namespace geomcheck::gen
