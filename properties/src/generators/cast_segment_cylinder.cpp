// geomcheck — generators of cast_segment_cylinder: targeted modes and wild doubles.
//
// targeted:
// Segment/cylinder casts: random, parallel to the axis into a cap, grazing
// the side, tangent to the rim, aimed at the rim +- a gap, starting
// inside, zero length, through both caps, exact Pythagorean touches.
#include "common.hpp"

namespace geomcheck::gen {

using namespace detail;

template <>
rc::Gen<Tagged<QueryTraits<QueryId::cast_segment_cylinder>::Case>> targeted<QueryId::cast_segment_cylinder>() {
  return rc::gen::resize(100, rc::gen::exec([]() -> std::pair<SegmentCylinderCase, std::string> {
    const int mode = pick_int(0, 8);
    if (mode == 8) {  // exact: tangent lines, rim touches, endpoint on the surface
      static const char* const kTags[] = {"exact-side-tangent", "exact-rim-tangent", "exact-end-on-rim",
                                          "exact-axis-parallel-on-side"};
      const ExactTripleCylinder x = pick_exact_triple_cylinder();
      const int ulps = pick_int(-2, 2);
      const int kind = pick_int(0, 3);
      auto [a, b] = exact_touching_segment(x, kind);
      a.x = nudge(a.x, ulps);
      b.x = nudge(b.x, ulps);
      return {{{x.ex.apply(a), x.ex.apply(b)}, x.cyl},
              kTags[kind] + std::string(ulps == 0 ? "" : (ulps > 0 ? "-ulps" : "+ulps"))};
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
        const double across = pick_real(0, 1), along = pick_real(0, 1);
        a = f.c.p + along * (f.c.q - f.c.p) + f.c.r * across * rad;
        b = a + sc.size * Vec3{pick_real(-6, 6), pick_real(-6, 6), pick_real(-6, 6)};
        tag = "start-inside";
        break;
      }
      case 5: {  // zero length: inside, on the surface, or outside
        const double out = pick_int(0, 1) ? gap : 0.0, along = pick_real(-0.2, 1.2);
        a = f.c.p + along * (f.c.q - f.c.p) + (f.c.r + out) * rad;
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

template <>
rc::Gen<QueryTraits<QueryId::cast_segment_cylinder>::Case> wild<QueryId::cast_segment_cylinder>() {
  return rc::gen::exec([]() -> SegmentCylinderCase {
    return {{wild_vec(), wild_vec()}, {wild_vec(), wild_vec(), *wild_double()}};
  });
}

}  // namespace geomcheck::gen
