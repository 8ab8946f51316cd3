// geomcheck — the spec of collide_cylinder_obb (see spec.hpp).
// Cylinder/oriented box: exact verdict; the penetration depth over the Minkowski patches.
#pragma once

#include "geomcheck/properties/spec.hpp"

namespace geomcheck {

template <>
struct Spec<QueryId::collide_cylinder_obb> {
  static constexpr QueryId id = QueryId::collide_cylinder_obb;
  using Case = CylinderObbCase;
  using Impl = ImplOf<id>;
  /// What production claims.
  static constexpr Claims claims{true, Claims::Depth::Penetration, true,
                                 "unit, from the cylinder towards the box: the minimal translation",
                                 "certified engine: exact verdict, certified signed distance, EPA penetration depth enclosure"};
  /// Cases of a default campaign.
  static constexpr int default_cases = 10000;
  static const Impl& production() { return production_of<id>(); }
  /// Known-wrong variants (properties/src/teeth.cpp); the suites must catch each.
  static std::vector<const Impl*> variants() { return {&teeth::kBoxAsCapsule, &teeth::kBoxTalkRays}; }
  /// Targeted modes (generators/collide_cylinder_obb.cpp), tagged by mode.
  static rc::Gen<Tagged<Case>> targeted() { return gen::cylinder_obb_case(); }
  /// Wild raw doubles: NaN, inf, subnormal, huge.
  static rc::Gen<Case> wild() { return gen::wild_cylinder_obb(); }
};

}  // namespace geomcheck
