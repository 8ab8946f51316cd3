// geomcheck — generators of penetration_cylinder_obb: collide_cylinder_obb's
// (properties/src/generators/collide_cylinder_obb.cpp lists the modes), the
// same shapes asked for their penetration depth.
#include "geomcheck/properties/generators.hpp"

namespace geomcheck::gen {

template <>
rc::Gen<Tagged<QueryTraits<QueryId::penetration_cylinder_obb>::Case>> targeted<QueryId::penetration_cylinder_obb>() {
  return targeted_as<QueryId::penetration_cylinder_obb, QueryId::collide_cylinder_obb>();
}

template <>
rc::Gen<QueryTraits<QueryId::penetration_cylinder_obb>::Case> wild<QueryId::penetration_cylinder_obb>() {
  return wild_as<QueryId::penetration_cylinder_obb, QueryId::collide_cylinder_obb>();
}

}  // namespace geomcheck::gen
