// geomcheck — the checks of penetration_cylinder_triangle (declared for every query in checks.hpp).
//
// What each check means for a cylinder and a triangle is written once, for this
// query and collide_cylinder_triangle, in triangle_checks.hpp.
#include "triangle_checks.hpp"
#include "geomcheck/penetration_cylinder_triangle.hpp"
#include "geomcheck/properties/checks.hpp"
#include "geomcheck/properties/teeth.hpp"

namespace geomcheck {

// The spec of penetration_cylinder_triangle: cylinder/triangle: exact verdict; the penetration depth over the Minkowski patches.
GEOMCHECK_SPEC(penetration_cylinder_triangle, 100000,
               (Claims{true, Claims::Depth::Penetration, true, "unit, from the cylinder towards the triangle: the minimal translation", "certified engine: exact verdict, certified signed distance, EPA penetration depth enclosure"}),
               (Tolerances{/*verdict*/ 1e-14, /*depth*/ 1e-14, /*normal*/ 1e-14, /*point*/ 1e-14, /*t*/ 0, /*unit*/ 1e-14}),
               &teeth::kTriangleNoCapStage)

static_assert(answers_penetration(kId), "production answers this query with penetration()");
GEOMCHECK_PAIR_CHECKS(triangle_checks)

}  // namespace geomcheck
