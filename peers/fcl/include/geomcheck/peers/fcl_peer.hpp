// geomcheck — FCL's answer to any registered query, in one shape: FCL as a
// peer of the campaign (it answers every case of a query it can express).
#pragma once

#include <string>
#include <type_traits>
#include <utility>

#include "geomcheck/peers/fcl_adapter.hpp"
#include "geomcheck/properties/checks.hpp"

namespace geomcheck::peers {

/// FCL's answer, reduced to what reports compare.
struct FclAnswer {
  bool supported = false;  ///< FCL can express this query (kFclAsks, kFclCasts)
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

/// FCL's answer to a case of any registered query (fcl_adapter.hpp says how
/// FCL is asked for each pair: libccd's MPR and GJK, guarded, or a closed
/// form; continuous collision for casts and sweeps); not supported where the
/// adapter does not ask FCL about the query's shapes, with no code for it.
template <class Case>
FclAnswer fcl_answer(const Case& c);

/// `impl` (default: production) evaluated with FCL's answer scored against
/// the same truth.
template <class Case>
Evaluation evaluate_with_fcl(const Case& c, const FclAnswer& p,
                              const ImplOfCase<Case>& impl = production_of<query_of_case<Case>>()) {
  const bool answered = p.supported && p.ok;
  constexpr QueryKind kind = QueryTraits<query_of_case<Case>>::kind;
  if constexpr (kind == QueryKind::Cast || kind == QueryKind::Sweep) {
    return evaluate(c, impl, answered && p.hit ? &p.t : nullptr);
  } else {
    return evaluate(c, impl, answered ? &p.contact : nullptr);
  }
}

}  // namespace geomcheck::peers
