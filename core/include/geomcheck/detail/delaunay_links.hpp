// geomcheck — internal: the neighbours of a triangulation given by its
// triangles alone (the point-set door's triangulation_of, and the tests
// that edit a triangulation).
#pragma once

#include <cstddef>
#include <cstdint>
#include <map>
#include <utility>

#include "geomcheck/delaunay_2d.hpp"

namespace geomcheck::detail {

/// Sets t.neighbors from t.triangles: neighbors[i][k], the triangle that
/// holds the edge opposite triangles[i][k] in the other direction (the first
/// such triangle), or kNone. Returns the count of edges without a neighbour
/// (t.hull_edges is left as it is).
inline std::size_t link_neighbors(DelaunayTriangulation& t) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> owner;
  for (std::uint32_t i = 0; i < t.triangles.size(); ++i)
    for (int k = 0; k < 3; ++k) owner.emplace(std::make_pair(t.triangles[i][(k + 1) % 3], t.triangles[i][(k + 2) % 3]), i);
  t.neighbors.assign(t.triangles.size(), {DelaunayTriangulation::kNone, DelaunayTriangulation::kNone,
                                          DelaunayTriangulation::kNone});
  std::size_t unlinked = 0;
  for (std::uint32_t i = 0; i < t.triangles.size(); ++i)
    for (int k = 0; k < 3; ++k) {
      const auto it = owner.find({t.triangles[i][(k + 2) % 3], t.triangles[i][(k + 1) % 3]});
      if (it != owner.end()) t.neighbors[i][k] = it->second;
      else ++unlinked;
    }
  return unlinked;
}

}  // namespace geomcheck::detail
