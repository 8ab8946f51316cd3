#include "peer.hpp"

#include <cstdio>
#include <type_traits>

namespace geomcheck {

namespace {
std::string v3(Vec3 v) {
  char b[128];
  std::snprintf(b, sizeof b, "(%.17g, %.17g, %.17g)", v.x, v.y, v.z);
  return b;
}

/// A collide answer (cylinder against a sphere, capsule, box, triangle or cylinder); `note` follows the depth.
PeerAnswer contact_answer(const oracles::PeerContact& r, const char* note = "") {
  PeerAnswer p;
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
PeerAnswer cast_answer(const oracles::PeerCast& r, const char* how) {
  PeerAnswer p;
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
PeerAnswer with_distance(PeerAnswer p, const oracles::PeerDistance& d) {
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

// How FCL answers a collide pair, after its depth: libccd's MPR everywhere
// but the sphere (FCL's closed form) and the triangle (its mesh narrow phase).
template <class B>
const char* collide_note() {
  if constexpr (std::is_same_v<B, Sphere>) return "";
  else if constexpr (std::is_same_v<B, Triangle>)
    return " (FCL's mesh narrow phase shapeTriangleIntersect; libccd MPR estimate, not the minimum)";
  else return " (libccd MPR estimate, not the minimum)";
}

}  // namespace

template <class Case>
PeerAnswer peer(const Case& c) {
  constexpr QueryKind kind = QueryTraits<query_of_case<Case>>::kind;
  if constexpr (kind == QueryKind::Collide)
    return with_distance(contact_answer(oracles::fcl_collide(c.a, c.b), collide_note<typename Case::ShapeB>()),
                         oracles::fcl_distance(c.a, c.b));
  else if constexpr (kind == QueryKind::Cast)
    return cast_answer(oracles::fcl_cast(c.a, c.b), "FCL continuous collision of a radius-0 sphere");
  else return cast_answer(oracles::fcl_sweep(c.a, c.b), "FCL continuous collision of the ball; no point or normal");
}

#define GEOMCHECK_X(id, kind, A, B, summary) template PeerAnswer peer(const PairCase<A, B, QueryId::id>&);
GEOMCHECK_QUERY_LIST(GEOMCHECK_X)
#undef GEOMCHECK_X

}  // namespace geomcheck
