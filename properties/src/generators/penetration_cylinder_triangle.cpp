// geomcheck — generators of penetration_cylinder_triangle: collide_cylinder_triangle's
// (properties/src/generators/collide_cylinder_triangle.cpp lists the modes), the
// same shapes asked for their penetration depth.
#include "geomcheck/properties/generators.hpp"

namespace geomcheck::gen {

GEOMCHECK_GENERATORS_AS(penetration_cylinder_triangle, collide_cylinder_triangle)

}  // namespace geomcheck::gen
