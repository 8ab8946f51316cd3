// geomcheck — the checks of collide_cylinder_obb (declared for every query in checks.hpp).
//
// What each check means for a cylinder and a box is written once, for this
// query and penetration_cylinder_obb, in box_checks.hpp.
#include <cmath>

#include "box_checks.hpp"
#include "geomcheck/collide_cylinder_obb.hpp"
#include "geomcheck/properties/checks.hpp"
#include "geomcheck/properties/teeth.hpp"

namespace geomcheck {

// The spec of collide_cylinder_obb: cylinder/oriented box: exact verdict; a consistent contact (depth = overlap along the normal, at most 1.5 times the penetration depth).
GEOMCHECK_SPEC(collide_cylinder_obb, 100000,
               (Claims{true, Claims::Depth::UpperBound, true, "unit, from the cylinder towards the box: a consistent contact, not the minimal translation", "certified engine: exact verdict, certified signed distance, EPA penetration depth as a lower bound of the depth"}),
               // A consistent contact, as collide_cylinder_cylinder's; by
               // construction its depth is at most (1 + 1/64) times the penetration
               // depth (see the query's header), held here to the common 1.5.
               (Tolerances{/*verdict*/ 1e-14, /*depth*/ 1e-14, /*normal*/ 0, /*point*/ 1e-14, /*t*/ 0, /*unit*/ 1e-14, /*depth_ratio*/ 1.5}),
               &teeth::kBoxAsCapsule, &teeth::kBoxTalkRays, &teeth::kBoxNoCircleSearch)

bool obb_in_contract(const Obb& b) {
  for (int i = 0; i < 3; ++i)
    for (int j = i; j < 3; ++j)
      if (!(std::fabs(dot(b.axes[i], b.axes[j]) - (i == j ? 1.0 : 0.0)) <= 16 * 0x1p-52)) return false;
  return true;
}

GEOMCHECK_PAIR_CHECKS(box_checks)

}  // namespace geomcheck
