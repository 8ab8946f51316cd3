// geomcheck — generators of penetration_cylinder_triangle: collide_cylinder_triangle's
// (properties/src/generators/collide_cylinder_triangle.cpp lists the modes), the
// same shapes asked for their penetration depth.
#include "geomcheck/properties/generators.hpp"

namespace geomcheck::gen {

template <>
rc::Gen<Tagged<QueryTraits<QueryId::penetration_cylinder_triangle>::Case>> targeted<QueryId::penetration_cylinder_triangle>() {
  return targeted_as<QueryId::penetration_cylinder_triangle, QueryId::collide_cylinder_triangle>();
}

template <>
rc::Gen<QueryTraits<QueryId::penetration_cylinder_triangle>::Case> wild<QueryId::penetration_cylinder_triangle>() {
  return wild_as<QueryId::penetration_cylinder_triangle, QueryId::collide_cylinder_triangle>();
}

}  // namespace geomcheck::gen
