#include "generators.hpp"

#include <cmath>
#include <limits>

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
};
Exact pick_exact() {
  return {pick_int(0, 2), pick_int(0, 7), pick_int(-20, 20),
          {double(pick_int(-1000, 1000)), double(pick_int(-1000, 1000)), double(pick_int(-1000, 1000))}};
}

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

}  // namespace geomcheck::gen
