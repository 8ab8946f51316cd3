// geomcheck — generators of collide_cylinder_capsule: targeted modes and wild doubles.
//
// targeted:
// Cylinder/capsule pairs: random, parallel, anti-parallel and coaxial to
// the axis (exactly and 1e-8 / 1e-16 from parallel), perpendicular to it,
// an end sphere at the rim, cap or side, grazing the rim, crossing a cap
// plane, the segment inside the cylinder (touching +- k ulps, or a small or
// large gap either way), exact Pythagorean touches, zero capsule radius (a
// segment), zero cylinder radius, p == q (a sphere).
#include "common.hpp"

namespace geomcheck::gen {

using namespace detail;

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
        const int k2 = pick_int(-5, 5), j = pick_int(-5, 5), i = pick_int(0, 3);
        q = e + double(i) * out + double(j) * tng + double(k2) * bin;
        tag = "exact-rim-end";
      } else {  // the segment through e, perpendicular to out (a point when v == 0)
        const int j = pick_int(-3, 3), i = pick_int(-3, 3);
        const Vec3 v = double(i) * tng + double(j) * bin;
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
  static const char* const kTags[] = {"exact-segment-side-tangent", "exact-segment-rim-tangent",
                                      "exact-segment-end-on-rim", "exact-segment-on-side"};
  const ExactTripleCylinder x = pick_exact_triple_cylinder();
  Cylinder cyl = x.cyl;
  const int kind = pick_int(0, 4);
  std::pair<Vec3, Vec3> ab;
  std::string tag;
  if (kind < 4) {
    ab = exact_touching_segment(x, kind);
    tag = kTags[kind];
  } else {  // zero cylinder radius too: two segments crossing
    cyl.r = 0;
    const Vec3 a{0, double(-x.len), double(pick_int(0, x.h))};
    ab = {a, {0, double(x.len), a.z}};
    tag = "exact-segment-crosses-zero-radius";
  }
  const int ulps = pick_int(-2, 2);
  const std::string moved = cyl.r == 0 ? "-ulps-off" : (ulps > 0 ? "-ulps-out" : "-ulps-in");
  const Exact& ex = x.ex;
  return {{cyl, Capsule{ex.nudge_x(ex.apply(ab.first), ulps), ex.nudge_x(ex.apply(ab.second), ulps), 0.0}},
          tag + (ulps == 0 ? "-touch" : moved)};
}

}  // namespace

template <>
rc::Gen<Tagged<QueryTraits<QueryId::collide_cylinder_capsule>::Case>> targeted<QueryId::collide_cylinder_capsule>() {
  return rc::gen::resize(100, rc::gen::exec([]() -> std::pair<CylinderCapsuleCase, std::string> {
    const int mode = pick_int(0, 9);
    if (mode == 8) return exact_cylinder_capsule();
    if (mode == 9) return exact_segment_capsule();
    auto [sc, f, s, gap, reach] = pick_approach();
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
        const double across = pick_real(0, 1.5), ball = pick_real(0, 1);
        const Vec3 x = (top ? f.c.q : f.c.p) + (across * f.c.r + ball * s) * rad;
        const double w2 = pick_real(-2, 2), w1 = pick_real(-2, 2);
        const Vec3 dir = capn + w1 * rad + w2 * cross(f.u, rad);
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

template <>
rc::Gen<QueryTraits<QueryId::collide_cylinder_capsule>::Case> wild<QueryId::collide_cylinder_capsule>() {
  return rc::gen::exec([]() -> CylinderCapsuleCase {
    return {{wild_vec(), wild_vec(), *wild_double()}, {wild_vec(), wild_vec(), *wild_double()}};
  });
}

}  // namespace geomcheck::gen
