// geomcheck — the spec of collide_cylinder_triangle (see spec.hpp).
// Cylinder/triangle: exact verdict; the penetration depth over the Minkowski patches.
#pragma once

#include "geomcheck/properties/spec.hpp"

namespace geomcheck {

template <>
struct Spec<QueryId::collide_cylinder_triangle> {
  static constexpr QueryId id = QueryId::collide_cylinder_triangle;
  using Case = CylinderTriangleCase;
  using Impl = ImplOf<id>;
  /// What production claims.
  static constexpr Claims claims{true, Claims::Depth::Penetration, true,
                                 "unit, from the cylinder towards the triangle: the minimal translation",
                                 "certified engine: exact verdict, certified signed distance, EPA penetration depth enclosure"};
  /// Cases of a default campaign.
  static constexpr int default_cases = 10000;
  static const Impl& production() { return production_of<id>(); }
  /// Known-wrong variants (properties/src/teeth.cpp); the suites must catch each.
  static std::vector<const Impl*> variants() { return {&teeth::kTriangleNoCapStage}; }
  /// Targeted modes (generators/collide_cylinder_triangle.cpp), tagged by mode.
  static rc::Gen<Tagged<Case>> targeted() { return gen::cylinder_triangle_case(); }
  /// Wild raw doubles: NaN, inf, subnormal, huge.
  static rc::Gen<Case> wild() { return gen::wild_cylinder_triangle(); }
};

}  // namespace geomcheck
