// geomcheck — one spec per registered query: every fact the generic harness
// needs about it, in one place (specs/<query id>.hpp).
//
// A spec says what the query's production claims (Claims), which subject is
// production and which known-wrong variants exist, how cases are generated
// (targeted modes and wild doubles), and how many cases a default campaign
// runs. The checks (checks.hpp; one file per query under properties/src/),
// the tolerances (tolerances.hpp) and the peers (oracles/fcl) are keyed by
// the same id. Everything generic (the RapidCheck suites, the campaign,
// replay, the fuzz targets, the report) takes Spec<Q> and nothing else.
//
// Adding a query: its line in core/include/geomcheck/registry.hpp, then
// specs/<id>.hpp included below (docs/ARCHITECTURE.md has the checklist).
#pragma once

#include <rapidcheck.h>

#include <string>
#include <utility>
#include <vector>

#include "geomcheck/properties/checks.hpp"
#include "geomcheck/properties/generators.hpp"
#include "geomcheck/properties/teeth.hpp"

namespace geomcheck {

/// What a subject claims about its answers. The checks hold it to these
/// claims and the report prints them beside the figures.
struct Claims {
  /// What a collide query's depth is.
  enum class Depth {
    None,         ///< cast and sweep queries: no depth
    Penetration,  ///< the true penetration depth (minimal translation)
    Shallow,      ///< the true penetration depth while the contact is shallow (see the query's header)
    UpperBound,   ///< a consistent contact: the overlap along the normal, an upper bound of the penetration depth
  };
  bool exact_verdict = true;  ///< the verdict is exact outside the verdict band
  Depth depth = Depth::None;
  bool point_in_both = true;  ///< collide: the point lies in both shapes (cast, sweep: on B)
  const char* normal = "";    ///< the normal's convention, in words
  const char* truth = "";     ///< what the truth is computed by
};

/// Words for a depth claim, for reports.
inline const char* to_string(Claims::Depth d) {
  switch (d) {
    case Claims::Depth::None: return "none";
    case Claims::Depth::Penetration: return "penetration depth";
    case Claims::Depth::Shallow: return "penetration depth while shallow";
    case Claims::Depth::UpperBound: return "overlap along the normal (upper bound)";
  }
  return "?";
}

/// A generated case and the generator mode that made it.
template <class Case>
using Tagged = std::pair<Case, std::string>;

/// The spec of query Q, specialised in specs/<id>.hpp. Each specialisation
/// has: `claims`, `default_cases`, `production()`, `variants()` (the
/// known-wrong subjects, each caught by the suites), `targeted()` (a
/// RapidCheck generator of tagged cases that reach the hard places) and
/// `wild()` (raw doubles: NaN, inf, subnormal, huge).
template <QueryId Q>
struct Spec;

/// Facts derived from a spec, for every query alike.
template <QueryId Q>
struct SpecOf {
  using Case = typename QueryTraits<Q>::Case;
  using Impl = ImplOf<Q>;
  /// Whether `impl` answers "hit" on the case (overlap, or a cast's or sweep's hit).
  static bool hit(const Case& c, const Impl& impl = production_of<Q>()) {
    if constexpr (QueryTraits<Q>::kind == QueryKind::Collide) return impl.overlap(c.a, c.b);
    else if constexpr (QueryTraits<Q>::kind == QueryKind::Cast) return impl.cast(c.a, c.b).hit;
    else return impl.sweep(c.a, c.b).hit;
  }
  /// Production or a known-wrong variant, by name (nullptr: no such subject).
  static const Impl* subject(const std::string& name) {
    if (name.empty() || name == production_of<Q>().name) return &production_of<Q>();
    for (const Impl* v : Spec<Q>::variants())
      if (name == v->name) return v;
    return nullptr;
  }
  /// Half wild raw doubles, half targeted cases.
  static rc::Gen<Tagged<Case>> robust() {
    return rc::gen::oneOf(Spec<Q>::targeted(), rc::gen::map(Spec<Q>::wild(), [](const Case& c) {
                            return Tagged<Case>{c, "wild"};
                          }));
  }
};

}  // namespace geomcheck

#include "geomcheck/properties/specs/cast_segment_cylinder.hpp"
#include "geomcheck/properties/specs/collide_cylinder_capsule.hpp"
#include "geomcheck/properties/specs/collide_cylinder_cylinder.hpp"
#include "geomcheck/properties/specs/collide_cylinder_obb.hpp"
#include "geomcheck/properties/specs/collide_cylinder_sphere.hpp"
#include "geomcheck/properties/specs/collide_cylinder_triangle.hpp"
#include "geomcheck/properties/specs/sweep_sphere_cylinder.hpp"
