// geomcheck — generators of penetration_cylinder_obb: collide_cylinder_obb's
// (properties/src/generators/collide_cylinder_obb.cpp lists the modes), the
// same shapes asked for their penetration depth.
#include "geomcheck/properties/generators.hpp"

namespace geomcheck::gen {

GEOMCHECK_GENERATORS_AS(penetration_cylinder_obb, collide_cylinder_obb)

}  // namespace geomcheck::gen
