// geomcheck — the checks of penetration_cylinder_triangle (declared for every query in checks.hpp).
//
// What each check means for a cylinder and a triangle is written once, for this
// query and collide_cylinder_triangle, in triangle_checks.hpp.
#include <cmath>

#include "triangle_checks.hpp"
#include "geomcheck/penetration_cylinder_triangle.hpp"
#include "geomcheck/properties/checks.hpp"
#include "geomcheck/properties/teeth.hpp"

namespace geomcheck {

// The spec of penetration_cylinder_triangle: cylinder/triangle: exact verdict; the penetration depth over the Minkowski patches.
GEOMCHECK_SPEC(penetration_cylinder_triangle, 100000,
               (Claims{true, Claims::Depth::Penetration, true, "unit, from the cylinder towards the triangle: the minimal translation", "certified engine: exact verdict, certified signed distance, EPA penetration depth enclosure"}),
               &teeth::kTriangleNoCapStage)

namespace {
using Case = QueryTraits<kId>::Case;
using Impl = ImplOf<kId>;
}  // namespace

void hold_to_truth(Evaluation& e, const Case& c, const Contact& ct, const Contact* peer) {
  triangle_checks::hold_to_truth(e, c, ct, peer);
}
CheckResult check_consistency(const Case& c, const Impl& impl) { return triangle_checks::consistency(c, impl); }
CheckResult check_symmetry(const Case& c, const Impl& impl) { return triangle_checks::symmetry(c, impl); }
CheckResult check_metamorphic(const Case& c, int move, const Impl& impl) {
  return triangle_checks::metamorphic(c, move, impl);
}
CheckResult check_monotone(const Case& c, const Impl& impl) { return triangle_checks::monotone(c, impl); }

}  // namespace geomcheck
