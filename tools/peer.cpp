#include "peer.hpp"

#include <cstdio>

namespace geomcheck {

namespace {
std::string v3(Vec3 v) {
  char b[128];
  std::snprintf(b, sizeof b, "(%.17g, %.17g, %.17g)", v.x, v.y, v.z);
  return b;
}
}  // namespace

PeerAnswer peer(const CylinderSphereCase& c) {
  PeerAnswer p;
  p.supported = true;
  const oracles::PeerContact r = oracles::fcl_collide(c.a, c.b);
  p.ok = r.ok;
  if (!r.ok) {
    p.text = "FCL failed: " + r.error;
    return p;
  }
  p.hit = r.hit;
  if (r.hit) {
    p.depth = r.depth;
    char b[64];
    std::snprintf(b, sizeof b, "%.17g", r.depth);
    p.text = std::string("hit depth=") + b + " normal=" + v3(r.normal) + " point=" + v3(r.point);
  } else {
    p.text = "no hit";
  }
  return p;
}

PeerAnswer peer(const SegmentCylinderCase& c) {
  PeerAnswer p;
  const oracles::PeerCast r = oracles::fcl_cast(c.a, c.b);
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
    p.text = std::string("hit t=") + b + " (FCL continuous collision of a radius-0 sphere)";
  } else {
    p.text = "no hit";
  }
  return p;
}

}  // namespace geomcheck
