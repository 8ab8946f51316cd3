// geomcheck — a query's spec, as generic code sees it: everything about
// query Q through one name, Spec<Q>.
//
// The facts live with the query: its line in the registry
// (core/include/geomcheck/registry.hpp: id, entry point, shapes), production's
// entry points (core/include/geomcheck/<id>.hpp), its checks, claims,
// default case count, bounds and known-wrong variants
// (properties/src/checks_<id>.cpp: production_of<Q>, spec_of<Q>), its
// generators (properties/src/generators/<id>.cpp) and FCL's
// adapter (peers/fcl/). The RapidCheck suites, the campaign, replay, the
// fuzz targets and the report take Spec<Q> and nothing else
// (docs/ARCHITECTURE.md has the checklist for a new query).
#pragma once

#include <rapidcheck.h>

#include <string>
#include <utility>
#include <vector>

#include "geomcheck/properties/checks.hpp"
#include "geomcheck/properties/generators.hpp"

namespace geomcheck {

using gen::Tagged;

/// Everything about query Q.
template <QueryId Q>
struct Spec {
  static constexpr QueryId id = Q;
  using Case = typename QueryTraits<Q>::Case;
  using Impl = ImplOf<Q>;

  /// What production claims.
  static const Claims& claims() { return spec_of<Q>().claims; }
  /// Cases of a default campaign.
  static int default_cases() { return spec_of<Q>().default_cases; }
  /// Known-wrong variants; the suites must catch each.
  static const std::vector<const Impl*>& variants() { return spec_of<Q>().variants; }
  /// Production's subject.
  static const Impl& production() { return production_of<Q>(); }

  /// Whether `impl` answers "hit" on the case (overlap, or a cast's or sweep's hit).
  static bool hit(const Case& c, const Impl& impl = production_of<Q>()) {
    if constexpr (QueryTraits<Q>::kind == QueryKind::Collide) return impl.overlap(c.a, c.b);
    else if constexpr (QueryTraits<Q>::kind == QueryKind::Cast) return impl.cast(c.a, c.b).hit;
    else return impl.sweep(c.a, c.b).hit;
  }
  /// Production or a known-wrong variant, by name (nullptr: no such subject).
  static const Impl* subject(const std::string& name) {
    if (name.empty() || name == production().name) return &production();
    for (const Impl* v : variants())
      if (name == v->name) return v;
    return nullptr;
  }

  /// Targeted cases that reach the hard places, tagged by mode.
  static rc::Gen<Tagged<Case>> targeted() { return gen::targeted<Q>(); }
  /// Raw doubles: NaN, inf, subnormal, huge.
  static rc::Gen<Case> wild() { return gen::wild<Q>(); }
  /// Half wild raw doubles, half targeted cases.
  static rc::Gen<Tagged<Case>> robust() {
    return rc::gen::oneOf(targeted(), rc::gen::map(wild(), [](const Case& c) { return Tagged<Case>{c, "wild"}; }));
  }
};

}  // namespace geomcheck
