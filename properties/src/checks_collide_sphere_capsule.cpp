// geomcheck — the checks of collide_sphere_capsule (declared for every query
// in checks.hpp): written once for the ball pairs in ball_checks.hpp, which
// says what each means.
//
// Known-wrong variant: the centre projected on the capsule's infinite line,
// not clamped to its segment (right only beside the segment).
#include <cmath>

#include "ball_checks.hpp"
#include "geomcheck/collide_sphere_capsule.hpp"

namespace geomcheck {

namespace {
Contact line_not_segment(const Sphere& s, const Capsule& k) {
  if (!is_valid(s) || !is_valid(k)) return {};
  const Vec3 d = k.q - k.p;
  const double dd = dot(d, d);
  const Vec3 c = dd > 0 ? k.p + (dot(s.c - k.p, d) / dd) * d : k.p;
  const Vec3 v = c - s.c;
  const double l = length(v);
  if (!(l <= s.r + k.r)) return {};
  Contact out;
  out.hit = true;
  out.normal = l > 0 ? (1.0 / l) * v : Vec3{0, 0, 1};
  out.depth = s.r + k.r - l;
  out.point = s.c + s.r * out.normal;
  return out;
}
const ImplOf<QueryId::collide_sphere_capsule> kInfiniteLine = {
    "capsule-as-infinite-line", [](const Sphere& s, const Capsule& k) { return line_not_segment(s, k).hit; },
    line_not_segment};
}  // namespace

// The spec of collide_sphere_capsule: sphere/capsule: exact verdict; the true penetration depth.
GEOMCHECK_SPEC(collide_sphere_capsule, 20000,
               (Claims{true, Claims::Depth::Penetration, true, "unit, from the sphere towards the capsule: the minimal translation", "closed form (oracles/src/ball_pairs.cpp): exact squared distance, exact verdict, certified depth"}),
               (Tolerances{/*verdict*/ 1e-14, /*depth*/ 1e-14, /*normal*/ 1e-14, /*point*/ 1e-14, /*t*/ 0, /*unit*/ 1e-14}),
               &kInfiniteLine)

GEOMCHECK_PAIR_CHECKS(ball_checks)

}  // namespace geomcheck
