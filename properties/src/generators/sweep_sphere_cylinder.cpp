// geomcheck — generators of sweep_sphere_cylinder: targeted modes and wild doubles.
//
// targeted:
// Sphere sweeps against a cylinder: random, aimed past the rim corner from
// above the cap, from the side and diagonally (touching +- k ulps, a gap
// either way, or inside the corner pocket of the augmented cylinder),
// along the axis into a cap, grazing the side and the rim, starting inside
// or touching, ending touching, zero, tiny and huge displacements, exact
// Pythagorean constructions; scales 2^-20..2^20, optionally far from the
// origin.
#include "common.hpp"

namespace geomcheck::gen {

using namespace detail;

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
      if (still) {
        delta = {0, 0, 0};
      } else {
        const int k2 = pick_int(-5, 5), j = pick_int(-5, 5), i = pick_int(0, 3);
        delta = double(i) * out + double(j) * tng + double(k2) * bin;
      }
      tag = std::string(still ? "exact-start-touch-zero-delta" : "exact-start-touch") + side;
      break;
    }
    case 5: {  // ending at e (touching at t = 1), coming from outside
      const int k2 = pick_int(-5, 5), j = pick_int(-5, 5);
      const Vec3 back = double(n) * out + double(j) * tng + double(k2) * bin;
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

template <>
rc::Gen<Tagged<QueryTraits<QueryId::sweep_sphere_cylinder>::Case>> targeted<QueryId::sweep_sphere_cylinder>() {
  return rc::gen::resize(100, rc::gen::exec([]() -> std::pair<SweepCylinderCase, std::string> {
    const int mode = pick_int(0, 9);
    if (mode == 9) return exact_sweep_cylinder();
    auto [sc, f, s, gap, reach] = pick_approach();
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
        if (zero) {
          d = {0, 0, 0};
        } else {
          const Vec3 dir = pick_dir();
          const int e = pick_int(40, 996);
          const double m = pick_real(1, 2) * sc.size;
          d = std::ldexp(m, -e) * dir;
        }
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
        const int ex = pick_int(20, 39);
        const double huge = std::ldexp(pick_real(1, 2) * sc.size, ex);
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

template <>
rc::Gen<QueryTraits<QueryId::sweep_sphere_cylinder>::Case> wild<QueryId::sweep_sphere_cylinder>() {
  return rc::gen::exec([]() -> SweepCylinderCase {
    return {{wild_vec(), *wild_double(), wild_vec()}, {wild_vec(), wild_vec(), *wild_double()}};
  });
}

}  // namespace geomcheck::gen
