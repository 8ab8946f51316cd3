// geomcheck — the RapidCheck generator of the 3D point-set tests (hull and
// tetrahedralization): sets built to defeat floating point. Integer grids
// (every cube's corners cospherical) and the surfaces of boxes (many
// coplanar points), integer points of one sphere (cospherical), points
// rounded onto a plane (flat input) or a line, random clouds, tight
// clusters beside far points, duplicates, a few ulps of jitter, one
// power-of-two scale from 2^-1000 to 2^1000 or a scale per coordinate axis.
#pragma once

#include <rapidcheck.h>

#include <cmath>
#include <vector>

#include "point_sets_3d.hpp"

namespace geomcheck::test {

/// 1 to 80 points of one of the kinds above (sizes not scaled by
/// RapidCheck's size: every kind is drawn from the first case on).
inline rc::Gen<std::vector<Vec3>> degenerate_point_sets_3d() {
  return rc::gen::resize(rc::kNominalSize, rc::gen::exec([] {
    static const std::vector<Vec3> sphere325 = integer_sphere_points();
    std::vector<Vec3> pts;
    const int n = *rc::gen::inRange(1, 80);
    const int kind = *rc::gen::inRange(0, 9);
    const Vec3 centre{*rc::gen::inRange(-1000, 1001) / 7.0, *rc::gen::inRange(-1000, 1001) / 3.0, 0.1};
    for (int i = 0; i < n; ++i) {
      Vec3 v;
      if (kind == 0) {  // an integer grid
        v = {double(*rc::gen::inRange(0, 4)), double(*rc::gen::inRange(0, 4)), double(*rc::gen::inRange(0, 4))};
      } else if (kind == 1) {  // the surface of a box: a coordinate at its end
        v = {double(*rc::gen::inRange(-5, 6)), double(*rc::gen::inRange(-3, 4)), double(*rc::gen::inRange(-2, 3))};
        const int axis = *rc::gen::inRange(0, 3);
        const double end = *rc::gen::inRange(0, 2) ? 1 : -1;
        (axis == 0 ? v.x : axis == 1 ? v.y : v.z) = end * (axis == 0 ? 5 : axis == 1 ? 3 : 2);
      } else if (kind == 2) {  // integer points of |p|^2 = 50 (cospherical)
        static const Vec3 s[] = {{3, 4, 5}, {-3, 4, 5}, {3, -4, 5}, {3, 4, -5}, {5, 3, 4}, {-5, 3, 4}, {4, 5, -3},
                                 {0, 1, 7}, {0, -1, 7}, {1, 0, -7}, {7, 0, 1}, {-7, 1, 0}, {0, 7, -1}, {5, 5, 0},
                                 {-5, 5, 0}, {0, -5, -5}, {4, -3, -5}, {-4, -5, 3}};
        v = s[*rc::gen::inRange(0, 18)];
      } else if (kind == 3) {  // rounded onto the plane x + 2y + 3z = 1/3
        const double x = *rc::gen::inRange(-1000, 1001) / 997.0, y = *rc::gen::inRange(-1000, 1001) / 991.0;
        v = {x, y, (1.0 / 3 - x - 2 * y) / 3};
      } else if (kind == 4 && i > 0 && *rc::gen::inRange(0, 3) == 0) {  // a duplicate
        v = pts[*rc::gen::inRange<std::size_t>(0, pts.size())];
      } else if (kind == 6) {  // integer points of |p|^2 = 325, translated (cospherical)
        v = sphere325[*rc::gen::inRange<std::size_t>(0, sphere325.size())];
        v = {v.x + 1000, v.y - 7, v.z + 0.5};
      } else if (kind == 7) {  // clusters 1e-9 wide about a centre, and a few far points
        if (*rc::gen::inRange(0, 8) == 0)
          v = {*rc::gen::inRange(-100, 101) * 1e3, *rc::gen::inRange(-100, 101) * 1e3, *rc::gen::inRange(-100, 101) * 1e3};
        else
          v = {centre.x + *rc::gen::inRange(-1000, 1001) * 1e-12, centre.y + *rc::gen::inRange(-1000, 1001) * 1e-12,
               centre.z + *rc::gen::inRange(-1000, 1001) * 1e-12};
      } else if (kind == 8) {  // rounded onto the line t (1, 1/3, 1/7), a few off it
        const double t = *rc::gen::inRange(-1000, 1001) / 31.0;
        v = {t, t / 3, t / 7};
        if (*rc::gen::inRange(0, 10) == 0) v.z += 1;
      } else {
        v = {*rc::gen::inRange(-100000, 100001) / 1e4, *rc::gen::inRange(-100000, 100001) / 1e4,
             *rc::gen::inRange(-100000, 100001) / 1e4};
      }
      if (*rc::gen::inRange(0, 8) == 0)
        v = {ulps(v.x, *rc::gen::inRange(-2, 3)), ulps(v.y, *rc::gen::inRange(-2, 3)), ulps(v.z, *rc::gen::inRange(-2, 3))};
      pts.push_back(v);
    }
    const int mode = *rc::gen::inRange(0, 4);
    const int k = *rc::gen::element(0, -1000, 1000, -500, 500, 37);
    for (Vec3& v : pts) {
      if (mode == 0) v = {std::ldexp(v.x, k), std::ldexp(v.y, k), std::ldexp(v.z, k)};
      if (mode == 1) v = {std::ldexp(v.x, -520), std::ldexp(v.y, 480), v.z};
    }
    return pts;
  }));
}

}  // namespace geomcheck::test
