// geomcheck — the checks of penetration_cylinder_obb (declared for every query in checks.hpp).
//
// What each check means for a cylinder and a box is written once, for this
// query and collide_cylinder_obb, in box_checks.hpp.
#include "box_checks.hpp"
#include "geomcheck/penetration_cylinder_obb.hpp"
#include "geomcheck/properties/checks.hpp"
#include "geomcheck/properties/teeth.hpp"

namespace geomcheck {

// The spec of penetration_cylinder_obb: cylinder/oriented box: exact verdict; the penetration depth over the Minkowski patches.
GEOMCHECK_SPEC(penetration_cylinder_obb, 100000,
               (Claims{true, Claims::Depth::Penetration, true, "unit, from the cylinder towards the box: the minimal translation", "certified engine: exact verdict, certified signed distance, EPA penetration depth enclosure"}),
               (Tolerances{/*verdict*/ 1e-14, /*depth*/ 1e-14, /*normal*/ 1e-14, /*point*/ 1e-14, /*t*/ 0, /*unit*/ 1e-14}),
               &teeth::kBoxAsCapsule, &teeth::kBoxTalkRays)

static_assert(answers_penetration(kId), "production answers this query with penetration()");
GEOMCHECK_PAIR_CHECKS(box_checks)

}  // namespace geomcheck
