// geomcheck — penetration_cylinder_triangle: the exact penetration depth (see the
// header). The search over the Minkowski patches is collide_cylinder_triangle.cpp's
// exact contact, with the production cap stage.
#include "geomcheck/penetration_cylinder_triangle.hpp"

#include "geomcheck/detail/triangle_stages.hpp"

namespace geomcheck {

Contact penetration(const Cylinder& cyl, const Triangle& tri) {
  return detail::collide_with_stage(cyl, tri, detail::TriCapStage::Exact);
}

}  // namespace geomcheck
