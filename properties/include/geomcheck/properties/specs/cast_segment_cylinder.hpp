// geomcheck — the spec of cast_segment_cylinder (see spec.hpp).
// Segment cast against a cylinder: the first hit from the segment start.
#pragma once

#include "geomcheck/properties/spec.hpp"

namespace geomcheck {

template <>
struct Spec<QueryId::cast_segment_cylinder> {
  static constexpr QueryId id = QueryId::cast_segment_cylinder;
  using Case = SegmentCylinderCase;
  using Impl = ImplOf<id>;
  /// What production claims.
  static constexpr Claims claims{true, Claims::Depth::None, true,
                                 "the cylinder's outward surface normal at the hit (zero when the segment starts inside)",
                                 "closed form (oracles/src/cast_segment_cylinder.cpp): exact hit or miss, certified t"};
  /// Cases of a default campaign.
  static constexpr int default_cases = 100000;
  static const Impl& production() { return production_of<id>(); }
  /// Known-wrong variants (properties/src/teeth.cpp); the suites must catch each.
  static std::vector<const Impl*> variants() { return {&teeth::kInfiniteCylinder, &teeth::kEricsonPrinted}; }
  /// Targeted modes (generators/cast_segment_cylinder.cpp), tagged by mode.
  static rc::Gen<Tagged<Case>> targeted() { return gen::segment_cylinder_case(); }
  /// Wild raw doubles: NaN, inf, subnormal, huge.
  static rc::Gen<Case> wild() { return gen::wild_segment_cylinder(); }
};

}  // namespace geomcheck
