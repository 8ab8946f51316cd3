// geomcheck — oracles for delaunay_2d: an exact validity checker and CGAL's
// Delaunay_triangulation_2, both independent of production's predicates
// (CGAL's exact Epick predicates, and exact Mpzf sums for the areas).
//
// check_delaunay accepts a result exactly when it is a Delaunay
// triangulation of the input by the semantics of delaunay_2d.hpp:
//   - vertex_of maps every index to the smallest index of equal coordinates;
//     vertex_count is the number of distinct points; the dimension is right;
//   - every triangle is counter-clockwise and non-degenerate (exact
//     orientation) on representative vertices; every distinct point is a
//     vertex;
//   - neighbours are mutual and share the edge, each directed edge is used
//     once, and an edge without neighbour has no triangle on its other side;
//   - every interior edge is locally Delaunay (exact in-circle: the opposite
//     vertex is not strictly inside);
//   - the boundary edges form one cycle whose corners are CGAL's
//     convex_hull_2, with the collinear boundary points in order between;
//   - triangles = 2n - h - 2 (n distinct points, h on the hull boundary),
//     and the exact areas add up to the hull's (so nothing overlaps).
// These imply the triangulation covers the hull once and is Delaunay.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "geomcheck/delaunay_2d.hpp"

namespace geomcheck::oracle {

/// "" when `t` is a valid Delaunay triangulation of `points` (above), else
/// the first violation found, in words, naming the triangle or index.
std::string check_delaunay(const std::vector<Vec2>& points, const DelaunayTriangulation& t);

/// CGAL's Delaunay triangles of the points (Epick, range insert), as triples
/// of smallest input indices, each rotated to start at its smallest entry,
/// sorted. Empty for fewer than three non-collinear distinct points.
std::vector<std::array<std::uint32_t, 3>> cgal_delaunay(const std::vector<Vec2>& points);

/// "" when `t` has the same triangles as CGAL's triangulation except where
/// both choices are legitimate: every triangle in one and not in the other
/// must have a neighbour in its own triangulation whose opposite vertex is
/// exactly on its circumcircle (four or more cocircular points); else the
/// first unexplained difference. When no four points are cocircular this
/// demands the identical triangle set.
std::string compare_with_cgal(const std::vector<Vec2>& points, const DelaunayTriangulation& t);

/// The triangles of `t` in cgal_delaunay's canonical form.
std::vector<std::array<std::uint32_t, 3>> canonical_triangles(const DelaunayTriangulation& t);

}  // namespace geomcheck::oracle
