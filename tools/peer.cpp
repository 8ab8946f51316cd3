#include "peer.hpp"

#include <cstdio>

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

}  // namespace

PeerAnswer peer(const CylinderSphereCase& c) {
  return with_distance(contact_answer(oracles::fcl_collide(c.a, c.b)), oracles::fcl_distance(c.a, c.b));
}

PeerAnswer peer(const SegmentCylinderCase& c) {
  return cast_answer(oracles::fcl_cast(c.a, c.b), "FCL continuous collision of a radius-0 sphere");
}

PeerAnswer peer(const CylinderCapsuleCase& c) {
  return with_distance(contact_answer(oracles::fcl_collide(c.a, c.b), " (libccd MPR estimate, not the minimum)"), oracles::fcl_distance(c.a, c.b));
}

PeerAnswer peer(const CylinderObbCase& c) {
  return with_distance(contact_answer(oracles::fcl_collide(c.a, c.b), " (libccd MPR estimate, not the minimum)"), oracles::fcl_distance(c.a, c.b));
}

PeerAnswer peer(const CylinderTriangleCase& c) {
  return with_distance(
      contact_answer(oracles::fcl_collide(c.a, c.b),
                     " (FCL's mesh narrow phase shapeTriangleIntersect; libccd MPR estimate, not the minimum)"),
      oracles::fcl_distance(c.a, c.b));
}

PeerAnswer peer(const CylinderCylinderCase& c) {
  return with_distance(contact_answer(oracles::fcl_collide(c.a, c.b), " (libccd MPR estimate, not the minimum)"), oracles::fcl_distance(c.a, c.b));
}

PeerAnswer peer(const SweepCylinderCase& c) {
  return cast_answer(oracles::fcl_sweep(c.a, c.b), "FCL continuous collision of the ball; no point or normal");
}

}  // namespace geomcheck
