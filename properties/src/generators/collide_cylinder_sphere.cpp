// geomcheck — generators of collide_cylinder_sphere: targeted modes and wild doubles.
//
// targeted:
// Cylinder/sphere pairs: random, at the rim, on a cap plane, on the side
// (touching +- k ulps, or a small or large gap either way), exactly touching
// Pythagorean constructions, centre inside, sphere containing the
// cylinder, zero radii; scales 2^-20..2^20, optionally far from the origin.
//
// wild:
// Any shapes, valid or not, from wild doubles (robustness).
#include "common.hpp"

namespace geomcheck::gen {

using namespace detail;

template <>
rc::Gen<Tagged<QueryTraits<QueryId::collide_cylinder_sphere>::Case>> targeted<QueryId::collide_cylinder_sphere>() {
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
        const double across = pick_real(0, 1), along = pick_real(0, 1);
        c = f.c.p + along * (f.c.q - f.c.p) + f.c.r * across * radial_dir(f, angle);
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

template <>
rc::Gen<QueryTraits<QueryId::collide_cylinder_sphere>::Case> wild<QueryId::collide_cylinder_sphere>() {
  return rc::gen::exec([]() -> CylinderSphereCase {
    return {{wild_vec(), wild_vec(), *wild_double()}, {wild_vec(), *wild_double()}};
  });
}

}  // namespace geomcheck::gen
