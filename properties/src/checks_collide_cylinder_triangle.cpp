// geomcheck — the checks of collide_cylinder_triangle (declared for every query in checks.hpp).
//
// What each check means for a cylinder and a triangle is written once, for this
// query and penetration_cylinder_triangle, in triangle_checks.hpp.
#include <cmath>

#include "triangle_checks.hpp"
#include "geomcheck/collide_cylinder_triangle.hpp"
#include "geomcheck/properties/checks.hpp"
#include "geomcheck/properties/teeth.hpp"

namespace geomcheck {

// The spec of collide_cylinder_triangle: cylinder/triangle: exact verdict; a consistent contact (depth = overlap along the normal, at most 1.5 times the penetration depth).
GEOMCHECK_SPEC(collide_cylinder_triangle, 100000,
               (Claims{true, Claims::Depth::UpperBound, true, "unit, from the cylinder towards the triangle: a consistent contact, not the minimal translation", "certified engine: exact verdict, certified signed distance, EPA penetration depth as a lower bound of the depth"}),
               // A consistent contact, as collide_cylinder_obb's.
               (Tolerances{/*verdict*/ 1e-14, /*depth*/ 1e-14, /*normal*/ 0, /*point*/ 1e-14, /*t*/ 0, /*unit*/ 1e-14, /*depth_ratio*/ 1.5}),
               &teeth::kTriangleNoCapStage, &teeth::kTriangleNoCircleSearch)

GEOMCHECK_PAIR_CHECKS(triangle_checks)

}  // namespace geomcheck
