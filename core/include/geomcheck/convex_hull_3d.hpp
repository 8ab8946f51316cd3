// geomcheck — convex_hull_3d: the convex hull of a 3D point set, exactly.
//
// Semantics: the input is any list of finite points (duplicates allowed).
// The answer's dimension is that of the distinct points' affine hull:
// empty, point, line, plane or solid. Only a solid hull has facets: a
// closed surface of triangles, each (a, b, c) oriented outwards (its
// normal (b - a) x (c - a) points away from the hull: no input point lies
// strictly on that side of its plane), every edge in exactly two facets in
// opposite directions. Every extreme point is a vertex. A facet names the
// smallest index of its coordinates among equal points.
//
// Coplanar facets: a flat face of the hull with more than three points on
// it is triangulated, and points on it that are not its corners (on an edge
// or inside) may be vertices of that triangulation or not, as the insertion
// order met them; its triangles are coplanar neighbours.
//
// Algorithm: incremental with conflict lists (Clarkson and Shor): a first
// tetrahedron from the first four independent points (index order), every
// other distinct point assigned to a facet it sees; then, facet by facet, the conflict farthest from its plane (by
// the filter's value, as Quickhull chooses) removes the facets it sees,
// strictly, and is joined to their horizon; the removed facets' conflicts
// go to the new facets or, seeing none, are inside. Every decision is
// orient3d's exact sign (predicates3d.hpp), so the result is exact for
// every finite input and unchanged by scaling every point by one power of
// two.
//
// Non-finite coordinates: dimension `invalid`, no facets.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "geomcheck/vec3.hpp"

namespace geomcheck {

/// The convex hull of a point set (see above).
struct ConvexHull3 {
  enum class Dimension : unsigned char { invalid, empty, point, line, plane, solid };
  Dimension dimension = Dimension::empty;
  /// Outward triangles (solid only).
  std::vector<std::array<std::uint32_t, 3>> facets;
};

/// The convex hull of `points`, exactly.
ConvexHull3 convex_hull_3d(const std::vector<Vec3>& points);

/// The dimension's name ("solid", "plane", ...).
const char* to_string(ConvexHull3::Dimension d);

}  // namespace geomcheck
