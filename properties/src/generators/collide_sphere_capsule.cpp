// geomcheck — generators of collide_sphere_capsule: targeted modes and wild doubles.
//
// targeted (a scene of size 2^-20..2^20, sometimes far from the origin; the
// gap to touching is zero, tiny either way or large either way):
//   random      a sphere and a capsule anywhere in the scene
//   side        the centre across the segment's interior at ra + rb + gap
//   end         the centre out of an end cap, at ra + rb + gap from the end
//   on-line     the centre on the segment's line, beyond an end or on it
//   on-segment  the centre on the segment (D = 0)
//   inside      the sphere inside the capsule, or the capsule inside the sphere
//   degenerate  a zero-length capsule (two balls), zero radii
//   exact       integer constructions: the centre at (a k, b k) across a
//               segment along z, or at (a k, b k, -c') beyond its end, with
//               ra + rb the triple's c, nudged by -2..2 ulps, under an exact
//               move
//
// wild:
// Any shapes, valid or not, from wild doubles (robustness).
#include "common.hpp"

namespace geomcheck::gen {

using namespace detail;

namespace {
using SphereCapsuleCase = QueryTraits<QueryId::collide_sphere_capsule>::Case;
}

template <>
rc::Gen<Tagged<SphereCapsuleCase>> targeted<QueryId::collide_sphere_capsule>() {
  return rc::gen::resize(100, rc::gen::exec([]() -> std::pair<SphereCapsuleCase, std::string> {
    const int mode = pick_int(0, 7);
    if (mode == 7) {
      const auto& t = kTriples[pick_int(0, kNumTriples - 1)];
      const int k = pick_int(1, 4), len = pick_int(0, 30), beyond = pick_int(0, 1);
      const Exact ex = pick_exact();
      const int c = t[2] * k;
      const int rs = pick_int(0, c), rc_ = c - rs;
      Vec3 x;
      if (!beyond) x = {double(t[0] * k), double(t[1] * k), double(pick_int(0, len))};
      else x = {0, double(t[0] * k), -double(t[1] * k)};  // (0, a k, -b k) from the end p
      const int ulps = pick_int(-2, 2);
      const Sphere s{ex.apply(x), ex.len(rs)};
      const Capsule cap{ex.apply({0, 0, 0}), ex.apply({0, 0, double(len)}), nudge(ex.len(rc_), ulps)};
      return {{s, cap}, std::string(beyond ? "exact-end" : "exact-side") +
                            (ulps == 0 ? "-touch" : (ulps > 0 ? "-ulps-in" : "-ulps-out"))};
    }
    const Scene sc = pick_scene();
    const Vec3 u = pick_dir();
    const double len = pick_int(0, 12) == 0 ? 0.0 : pick_real(0.05, 8) * sc.size;
    double rs = pick_int(0, 12) == 0 ? 0.0 : pick_real(0.01, 3) * sc.size;
    double rc_ = pick_int(0, 12) == 0 ? 0.0 : pick_real(0.01, 3) * sc.size;
    const double gap = pick_gap(sc.size);
    const Vec3 p = sc.offset + sc.size * Vec3{pick_real(-2, 2), pick_real(-2, 2), pick_real(-2, 2)};
    const Vec3 q = p + len * u;
    const Vec3 e1 = (1.0 / length(any_perpendicular(u))) * any_perpendicular(u), e2 = cross(u, e1);
    const double ang = pick_real(0, 6.283185307179586);
    const Vec3 n = std::cos(ang) * e1 + std::sin(ang) * e2;
    const double R = rs + rc_;
    Vec3 x;
    std::string tag;
    switch (mode) {
      case 0:
        x = p + sc.size * Vec3{pick_real(-6, 6), pick_real(-6, 6), pick_real(-6, 6)};
        tag = "random";
        break;
      case 1:
        x = p + pick_real(0, 1) * len * u + (R + gap) * n;
        tag = "side";
        break;
      case 2: {
        Vec3 out = pick_dir();
        if (dot(out, u) > 0) out = out - 2 * dot(out, u) * u;
        x = p + (R + gap) * out;
        tag = "end";
        break;
      }
      case 3:
        x = pick_int(0, 1) ? q + (R + gap) * u : p - (R + gap) * u;
        tag = "on-line";
        break;
      case 4:
        x = p + pick_real(0, 1) * len * u;
        tag = "on-segment";
        break;
      case 5:
        if (pick_int(0, 1)) {
          const double along = pick_real(0, 1), out = pick_real(0, 1);  // one draw per statement
          x = p + along * len * u + out * rc_ * n;
          rs = rc_ * pick_real(0, 1);
          tag = "inside-capsule";
        } else {
          x = p + 0.5 * len * u;
          rs = 0.5 * len + rc_ + std::fabs(gap);
          tag = "capsule-inside";
        }
        break;
      default:
        return {{Sphere{p + (R + gap) * pick_dir(), rs}, Capsule{p, p, pick_int(0, 1) ? 0.0 : rc_}}, "degenerate"};
    }
    if (mode >= 1 && mode <= 3) tag += gap == 0 ? "-touch" : (gap > 0 ? "-gap" : "-deep");
    return {{Sphere{x, rs}, pick_int(0, 1) ? Capsule{p, q, rc_} : Capsule{q, p, rc_}}, tag};
  }));
}

template <>
rc::Gen<SphereCapsuleCase> wild<QueryId::collide_sphere_capsule>() {
  return rc::gen::exec([]() -> SphereCapsuleCase { return {{wild_vec(), *wild_double()}, {wild_vec(), wild_vec(), *wild_double()}}; });
}

}  // namespace geomcheck::gen
