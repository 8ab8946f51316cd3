// geomcheck — the spec of sweep_sphere_cylinder (see spec.hpp).
// A moving sphere swept against a cylinder: the first time of contact.
#pragma once

#include "geomcheck/properties/spec.hpp"

namespace geomcheck {

template <>
struct Spec<QueryId::sweep_sphere_cylinder> {
  static constexpr QueryId id = QueryId::sweep_sphere_cylinder;
  using Case = SweepCylinderCase;
  using Impl = ImplOf<id>;
  /// What production claims.
  static constexpr Claims claims{true, Claims::Depth::None, true,
                                 "the cylinder's outward surface normal at the contact (zero when the ball starts inside)",
                                 "certified engine: the swept ball (a capsule) against the cylinder; t bracketed"};
  /// Cases of a default campaign.
  static constexpr int default_cases = 10000;
  static const Impl& production() { return production_of<id>(); }
  /// Known-wrong variants (properties/src/teeth.cpp); the suites must catch each.
  static std::vector<const Impl*> variants() { return {&teeth::kSweepNoCornerStage, &teeth::kSweepTalkRimPoint}; }
  /// Targeted modes (generators/sweep_sphere_cylinder.cpp), tagged by mode.
  static rc::Gen<Tagged<Case>> targeted() { return gen::sweep_cylinder_case(); }
  /// Wild raw doubles: NaN, inf, subnormal, huge.
  static rc::Gen<Case> wild() { return gen::wild_sweep_cylinder(); }
};

}  // namespace geomcheck
