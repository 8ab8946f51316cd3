#include "geomcheck/peers/fcl_peer.hpp"

#include <cstdio>
#include <type_traits>

namespace geomcheck::peers {

namespace {
std::string v3(Vec3 v) {
  char b[128];
  std::snprintf(b, sizeof b, "(%.17g, %.17g, %.17g)", v.x, v.y, v.z);
  return b;
}

/// A collide answer; `note` follows the depth.
FclAnswer contact_answer(const PeerContact& r, const char* note = "") {
  FclAnswer p;
  p.supported = true;
  p.ok = r.ok;
  if (!r.ok) {
    p.text = "FCL failed: " + r.error;
    return p;
  }
  p.hit = r.hit;
  p.contact.hit = r.hit;
  if (r.hit) {
    p.depth = r.depth;
    p.contact.depth = r.depth;
    p.contact.point = r.point;
    p.contact.normal = r.normal;
    char b[64];
    std::snprintf(b, sizeof b, "%.17g", r.depth);
    p.text = std::string("hit depth=") + b + note + " normal=" + v3(r.normal) + " point=" + v3(r.point);
  } else {
    p.text = "no hit";
  }
  return p;
}

/// A cast or sweep answer; `how` says what FCL was asked.
FclAnswer cast_answer(const PeerCast& r, const char* how) {
  FclAnswer p;
  p.supported = r.supported;
  p.ok = r.ok;
  if (!r.ok) {
    p.text = "FCL failed: " + r.error;
    return p;
  }
  p.hit = r.hit;
  if (r.hit) {
    p.t = r.t;
    char b[64];
    std::snprintf(b, sizeof b, "%.17g", r.t);
    p.text = std::string("hit t=") + b + " (" + how + ")";
  } else {
    p.text = "no hit";
  }
  return p;
}

/// Adds FCL's distance on the same pair.
FclAnswer with_distance(FclAnswer p, const PeerDistance& d) {
  if (d.ok) {
    p.distance = d.distance;
    char b[64];
    std::snprintf(b, sizeof b, "%.17g", d.distance);
    p.text += std::string("; distance=") + b;
  } else {
    p.text += "; distance failed: " + d.error;
  }
  return p;
}

// How FCL answers a collide pair, after its depth: its closed form, or
// libccd's MPR (for a triangle, in its mesh narrow phase).
template <class A, class B>
const char* collide_note() {
  if constexpr (kFclClosedFormCollide<A, B>) return "";
  else if constexpr (std::is_same_v<B, Triangle>)
    return " (FCL's mesh narrow phase shapeTriangleIntersect; libccd MPR estimate, not the minimum)";
  else return " (libccd MPR estimate, not the minimum)";
}

}  // namespace

template <class Case>
FclAnswer fcl_answer(const Case& c) {
  using A = typename QueryTraits<query_of_case<Case>>::ShapeA;
  using B = typename QueryTraits<query_of_case<Case>>::ShapeB;
  constexpr QueryKind kind = QueryTraits<query_of_case<Case>>::kind;
  if constexpr (kind == QueryKind::Collide) {
    if constexpr (kFclAsks<A, B>)
      return with_distance(contact_answer(fcl_collide(c.a, c.b), collide_note<A, B>()), fcl_distance(c.a, c.b));
    else return FclAnswer{};  // not supported
  } else if constexpr (kind == QueryKind::Cast && std::is_same_v<A, Segment> && kFclCasts<B>) {
    return cast_answer(fcl_cast(c.a, c.b), "FCL continuous collision of a radius-0 sphere");
  } else if constexpr (kind == QueryKind::Sweep && std::is_same_v<A, MovingSphere> && kFclCasts<B>) {
    return cast_answer(fcl_sweep(c.a, c.b), "FCL continuous collision of the ball; no point or normal");
  } else {
    return FclAnswer{};  // not supported
  }
}

#define GEOMCHECK_X(id, kind, A, B, summary) template FclAnswer fcl_answer(const PairCase<A, B, QueryId::id>&);
GEOMCHECK_QUERY_LIST(GEOMCHECK_X)
#undef GEOMCHECK_X

}  // namespace geomcheck::peers
