// geomcheck — FCL's answer to any registered query, in one shape.
#pragma once

#include <string>
#include <type_traits>
#include <utility>

#include "geomcheck/oracles/fcl_adapter.hpp"
#include "geomcheck/properties/checks.hpp"

namespace geomcheck {

/// FCL's answer, reduced to what reports compare.
struct PeerAnswer {
  bool supported = false;  ///< FCL can express this query
  bool ok = false;         ///< FCL answered (no exception, no garbage)
  bool hit = false;
  double depth = NAN;      ///< collide: penetration depth
  double t = NAN;          ///< cast, sweep: first-touch parameter
  Contact contact;         ///< collide: FCL's contact (hit, depth, point, normal) as geomcheck's Contact
  /// collide: fcl::distance (GJK or closed form) on the same pair: > 0
  /// separated, -1 when FCL sees them meet; NaN when not asked or it failed.
  double distance = NAN;
  std::string text;        ///< human readable
};

/// FCL's answer to a case of any registered query (oracles/fcl/fcl_adapter.hpp
/// says how FCL is asked for each pair: libccd's MPR and GJK, guarded, or a
/// closed form; continuous collision for casts and sweeps).
template <class Case>
PeerAnswer peer(const Case& c);

/// `impl` (default: production) evaluated with FCL's answer scored against
/// the same truth.
template <class Case>
Evaluation evaluate_with_peer(const Case& c, const PeerAnswer& p,
                              const ImplOfCase<Case>& impl = production_of<query_of_case<Case>>()) {
  const bool answered = p.supported && p.ok;
  if constexpr (std::is_same_v<Case, SegmentCylinderCase> || std::is_same_v<Case, SweepCylinderCase>) {
    return evaluate(c, impl, answered && p.hit ? &p.t : nullptr);
  } else {
    return evaluate(c, impl, answered ? &p.contact : nullptr);
  }
}

}  // namespace geomcheck
