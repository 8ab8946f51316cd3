// geomcheck — the spec of collide_cylinder_sphere (see spec.hpp).
// Cylinder/sphere: overlap and collide with the true penetration depth.
#pragma once

#include "geomcheck/properties/spec.hpp"

namespace geomcheck {

template <>
struct Spec<QueryId::collide_cylinder_sphere> {
  static constexpr QueryId id = QueryId::collide_cylinder_sphere;
  using Case = CylinderSphereCase;
  using Impl = ImplOf<id>;
  /// What production claims.
  static constexpr Claims claims{true, Claims::Depth::Penetration, true,
                                 "unit, from the cylinder towards the sphere: the minimal translation",
                                 "closed form (oracles/src/cylinder_sphere.cpp): exact verdict, certified signed distance"};
  /// Cases of a default campaign.
  static constexpr int default_cases = 100000;
  static const Impl& production() { return production_of<id>(); }
  /// Known-wrong variants (properties/src/teeth.cpp); the suites must catch each.
  static std::vector<const Impl*> variants() { return {&teeth::kCapsuleForCylinder}; }
  /// Targeted modes (generators/collide_cylinder_sphere.cpp), tagged by mode.
  static rc::Gen<Tagged<Case>> targeted() { return gen::cylinder_sphere_case(); }
  /// Wild raw doubles: NaN, inf, subnormal, huge.
  static rc::Gen<Case> wild() { return gen::wild_cylinder_sphere(); }
};

}  // namespace geomcheck
