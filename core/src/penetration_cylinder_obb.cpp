// geomcheck — penetration_cylinder_obb: the exact penetration depth (see the
// header). The search over the Minkowski patches is collide_cylinder_obb.cpp's
// exact contact, with the production cap stage.
#include "geomcheck/penetration_cylinder_obb.hpp"

#include "geomcheck/detail/obb_stages.hpp"

namespace geomcheck {

Contact penetration(const Cylinder& cyl, const Obb& box) {
  return detail::collide_with_stage(cyl, box, detail::ObbCapStage::Exact);
}

}  // namespace geomcheck
