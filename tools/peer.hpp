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
  double t = NAN;          ///< cast: first-touch parameter
  std::string text;        ///< human readable
};

PeerAnswer peer(const CylinderSphereCase& c);
PeerAnswer peer(const SegmentCylinderCase& c);

}  // namespace geomcheck
