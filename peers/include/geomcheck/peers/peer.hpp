// geomcheck — another engine (ODE, Bullet, MuJoCo) as a subject: its answers
// to a registered query held to the same truth and the same properties as
// production's (subjects/verify.hpp), under claims that say what the engine
// promises (an inexact verdict, its margins, its depth's meaning).
//
// Each engine lives in peers/<engine>/ and defines, for every registered
// query Q, peer_<engine><Q>() (see GEOMCHECK_DECLARE_PEER below): a
// PeerSubject<Q> whose subject is null where the engine cannot express Q.
// The conversion of geomcheck's shapes into the engine's (a cylinder by its
// cap centres becomes a centred, axis-aligned cylinder with a rotation) and
// the engine's conventions (normal direction, depth sign, contact point,
// margins) are the adapter's, written in its header and tested on hand
// cases with known answers.
#pragma once

#include "geomcheck/properties/checks.hpp"
#include "geomcheck/registry.hpp"

namespace geomcheck::peers {

/// An engine's subject of query Q.
template <QueryId Q>
struct PeerSubject {
  using Case = typename QueryTraits<Q>::Case;
  /// The engine's answers (with its claims); null: the engine cannot express Q.
  const ImplOf<Q>* subject = nullptr;
  /// Whether the engine can express this case at all (a box whose stored
  /// axes are not orthonormal, a degenerate shape the engine refuses); a
  /// case it cannot express is not asked and not counted as its failure.
  bool (*expresses)(const Case&) = nullptr;
  /// What the engine is, as the report names it ("ODE 0.16", ...).
  const char* engine = "";
};

/// A cast or sweep that starts in the cylinder: a hit at t = 0 at `point`
/// (what every engine's adapter answers after its own start test).
inline CastHit starts_inside_at(Vec3 point) {
  CastHit h;
  h.hit = true;
  h.t = 0;
  h.point = point;
  h.starts_inside = true;
  return h;
}

}  // namespace geomcheck::peers

/// Declares peer_<engine><Q>() for every registered query Q (put in the
/// engine's header: `GEOMCHECK_DECLARE_PEER(ode)`), defined in its sources
/// (a template chosen by the query's entry point and shapes, instantiated
/// for every registered query).
#define GEOMCHECK_DECLARE_PEER(engine)                  \
  namespace geomcheck::peers {                          \
  template <QueryId Q>                                  \
  PeerSubject<Q> peer_##engine();                       \
  }
