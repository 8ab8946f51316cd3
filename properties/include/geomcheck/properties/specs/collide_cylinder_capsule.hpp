// geomcheck — the spec of collide_cylinder_capsule (see spec.hpp).
// Cylinder/capsule: exact verdict; the true depth while the capsule's segment stays outside the cylinder.
#pragma once

#include "geomcheck/properties/spec.hpp"

namespace geomcheck {

template <>
struct Spec<QueryId::collide_cylinder_capsule> {
  static constexpr QueryId id = QueryId::collide_cylinder_capsule;
  using Case = CylinderCapsuleCase;
  using Impl = ImplOf<id>;
  /// What production claims.
  static constexpr Claims claims{true, Claims::Depth::Shallow, true,
                                 "unit, from the cylinder towards the capsule",
                                 "certified engine (capsule = segment + ball): exact verdict, certified signed distance and penetration depth"};
  /// Cases of a default campaign.
  static constexpr int default_cases = 10000;
  static const Impl& production() { return production_of<id>(); }
  /// Known-wrong variants (properties/src/teeth.cpp); the suites must catch each.
  static std::vector<const Impl*> variants() { return {&teeth::kCapsuleCapsule}; }
  /// Targeted modes (generators/collide_cylinder_capsule.cpp), tagged by mode.
  static rc::Gen<Tagged<Case>> targeted() { return gen::cylinder_capsule_case(); }
  /// Wild raw doubles: NaN, inf, subnormal, huge.
  static rc::Gen<Case> wild() { return gen::wild_cylinder_capsule(); }
};

}  // namespace geomcheck
