// geomcheck — the spec of collide_cylinder_cylinder (see spec.hpp).
// Cylinder/cylinder: exact verdict; a consistent contact (depth = overlap along the normal).
#pragma once

#include "geomcheck/properties/spec.hpp"

namespace geomcheck {

template <>
struct Spec<QueryId::collide_cylinder_cylinder> {
  static constexpr QueryId id = QueryId::collide_cylinder_cylinder;
  using Case = CylinderCylinderCase;
  using Impl = ImplOf<id>;
  /// What production claims.
  static constexpr Claims claims{true, Claims::Depth::UpperBound, true,
                                 "unit, from the first cylinder towards the second: a consistent contact, not the minimal translation",
                                 "certified engine: exact verdict, certified signed distance, EPA penetration depth as a lower bound of the depth"};
  /// Cases of a default campaign.
  static constexpr int default_cases = 10000;
  static const Impl& production() { return production_of<id>(); }
  /// Known-wrong variants (properties/src/teeth.cpp); the suites must catch each.
  static std::vector<const Impl*> variants() { return {&teeth::kCylinderNoPlanes, &teeth::kCylinderNoParallelBranch, &teeth::kCylinderPlainFrame}; }
  /// Targeted modes (generators/collide_cylinder_cylinder.cpp), tagged by mode.
  static rc::Gen<Tagged<Case>> targeted() { return gen::cylinder_cylinder_case(); }
  /// Wild raw doubles: NaN, inf, subnormal, huge.
  static rc::Gen<Case> wild() { return gen::wild_cylinder_cylinder(); }
};

}  // namespace geomcheck
