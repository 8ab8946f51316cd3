// geomcheck — the checks of collide_sphere_sphere (declared for every query
// in checks.hpp): written once for the ball pairs in ball_checks.hpp, which
// says what each means.
//
// Known-wrong variant: the distance of the centres formed from their rounded
// squared distance in floats (what a float engine does), held to double
// bounds.
#include <cmath>

#include "ball_checks.hpp"
#include "geomcheck/collide_sphere_sphere.hpp"

namespace geomcheck {

namespace {
Contact in_floats(const Sphere& a, const Sphere& b) {
  if (!is_valid(a) || !is_valid(b)) return {};
  const float dx = float(b.c.x) - float(a.c.x), dy = float(b.c.y) - float(a.c.y), dz = float(b.c.z) - float(a.c.z);
  const float l = std::sqrt(dx * dx + dy * dy + dz * dz), R = float(a.r) + float(b.r);
  if (!(l <= R)) return {};
  Contact out;
  out.hit = true;
  out.normal = l > 0 ? Vec3{dx / l, dy / l, dz / l} : Vec3{0, 0, 1};
  out.depth = double(R - l);
  out.point = a.c + a.r * out.normal;
  return out;
}
const ImplOf<QueryId::collide_sphere_sphere> kFloats = {
    "sphere-sphere-in-floats", [](const Sphere& a, const Sphere& b) { return in_floats(a, b).hit; }, in_floats};
}  // namespace

// The spec of collide_sphere_sphere: sphere/sphere: exact verdict; the true penetration depth.
GEOMCHECK_SPEC(collide_sphere_sphere, 20000,
               (Claims{true, Claims::Depth::Penetration, true, "unit, from A towards B: the minimal translation", "closed form (oracles/src/ball_pairs.cpp): exact squared distance, exact verdict, certified depth"}),
               (Tolerances{/*verdict*/ 1e-14, /*depth*/ 1e-14, /*normal*/ 1e-14, /*point*/ 1e-14, /*t*/ 0, /*unit*/ 1e-14}),
               &kFloats)

GEOMCHECK_PAIR_CHECKS(ball_checks)

}  // namespace geomcheck
