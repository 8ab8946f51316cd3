// geomcheck — FCL's answer to any registered query, in one shape.
#pragma once

#include <string>

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
  std::string text;        ///< human readable
};

PeerAnswer peer(const CylinderSphereCase& c);
PeerAnswer peer(const SegmentCylinderCase& c);
/// fcl_collide(Cylinder, Capsule): libccd's MPR, depth not the minimum (see fcl_adapter.hpp).
PeerAnswer peer(const CylinderCapsuleCase& c);
/// fcl_sweep: continuous collision of the ball, hit and t only (see fcl_adapter.hpp).
PeerAnswer peer(const SweepCylinderCase& c);
/// fcl_collide(Cylinder, Obb): libccd's MPR on FCL's box, depth not the minimum (see fcl_adapter.hpp).
PeerAnswer peer(const CylinderObbCase& c);
/// fcl_collide(Cylinder, Triangle): FCL's per-triangle mesh narrow phase (shapeTriangleIntersect;
/// fcl::collide has no cylinder/triangle pair), libccd's MPR, depth not the minimum (see fcl_adapter.hpp).
PeerAnswer peer(const CylinderTriangleCase& c);

}  // namespace geomcheck
