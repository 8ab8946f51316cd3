// geomcheck — generators of collide_sphere_sphere: targeted modes and wild doubles.
//
// targeted (a scene of size 2^-20..2^20, sometimes far from the origin; the
// gap to touching is zero, tiny either way or large either way):
//   random      two balls anywhere in the scene
//   touching    centres ra + rb + gap apart along any direction
//   concentric  the same centre (D = 0)
//   inside      one ball inside the other, or internally touching
//   degenerate  zero radii (points)
//   exact       centres an integer quadruple apart ((1,2,2,3), (2,3,6,7),
//               (1,4,8,9), (4,4,7,9), (2,6,9,11) times k) with ra + rb its
//               length, nudged by -2..2 ulps, under an exact move
//
// wild:
// Any balls, valid or not, from wild doubles (robustness).
#include "common.hpp"

namespace geomcheck::gen {

using namespace detail;

namespace {
using SpheresCase = QueryTraits<QueryId::collide_sphere_sphere>::Case;
constexpr int kQuadruples[][4] = {{1, 2, 2, 3}, {2, 3, 6, 7}, {1, 4, 8, 9}, {4, 4, 7, 9}, {2, 6, 9, 11}};
}  // namespace

template <>
rc::Gen<Tagged<SpheresCase>> targeted<QueryId::collide_sphere_sphere>() {
  return rc::gen::resize(100, rc::gen::exec([]() -> std::pair<SpheresCase, std::string> {
    const int mode = pick_int(0, 5);
    if (mode == 5) {
      const auto& t = kQuadruples[pick_int(0, 4)];
      const int k = pick_int(1, 8);
      const Exact ex = pick_exact();
      const int c = t[3] * k, ra = pick_int(0, c), ulps = pick_int(-2, 2);
      const Sphere a{ex.apply({0, 0, 0}), ex.len(ra)};
      const Sphere b{ex.apply({double(t[0] * k), double(t[1] * k), double(t[2] * k)}), nudge(ex.len(c - ra), ulps)};
      return {{a, b}, std::string("exact") + (ulps == 0 ? "-touch" : (ulps > 0 ? "-ulps-in" : "-ulps-out"))};
    }
    const Scene sc = pick_scene();
    double ra = pick_int(0, 12) == 0 ? 0.0 : pick_real(0.01, 3) * sc.size;
    double rb = pick_int(0, 12) == 0 ? 0.0 : pick_real(0.01, 3) * sc.size;
    const double gap = pick_gap(sc.size);
    const Vec3 c = sc.offset + sc.size * Vec3{pick_real(-2, 2), pick_real(-2, 2), pick_real(-2, 2)};
    switch (mode) {
      case 0: return {{{c, ra}, {c + sc.size * Vec3{pick_real(-6, 6), pick_real(-6, 6), pick_real(-6, 6)}, rb}}, "random"};
      case 1:
        return {{{c, ra}, {c + (ra + rb + gap) * pick_dir(), rb}},
                std::string("touching") + (gap == 0 ? "-touch" : (gap > 0 ? "-gap" : "-deep"))};
      case 2: return {{{c, ra}, {c, rb}}, "concentric"};
      case 3: {
        // B inside A: |cb - ca| + rb <= ra, or internally touching (gap 0).
        if (rb > ra) std::swap(ra, rb);
        const double d = gap == 0 ? ra - rb : (ra - rb) * pick_real(0, 1);
        return {{{c, ra}, {c + d * pick_dir(), rb}}, gap == 0 ? "inside-touch" : "inside"};
      }
      default: {
        // One draw per statement: the order of draws within an expression is the compiler's.
        const double off = pick_int(0, 1) ? gap : 0.0;
        const Vec3 dir = pick_dir();
        const double r = pick_int(0, 1) ? 0.0 : rb;
        return {{{c, 0.0}, {c + off * dir, r}}, "degenerate"};
      }
    }
  }));
}

template <>
rc::Gen<SpheresCase> wild<QueryId::collide_sphere_sphere>() {
  return rc::gen::exec([]() -> SpheresCase { return {{wild_vec(), *wild_double()}, {wild_vec(), *wild_double()}}; });
}

}  // namespace geomcheck::gen
