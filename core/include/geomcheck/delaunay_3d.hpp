// geomcheck — delaunay_3d: Delaunay tetrahedralization of points in space.
//
// Semantics: the input is a sequence of points (doubles, taken exactly).
// Points with equal coordinates are one vertex (-0.0 equals 0.0); every
// input index maps to a vertex, named by the smallest input index of its
// coordinates (`vertex_of`). When four distinct points are not coplanar,
// the output is a Delaunay tetrahedralization of the distinct points:
// tetrahedra as index quadruples, each positively oriented (the right-handed
// convention: d lies on the side of the plane abc that (b - a) x (c - a)
// points to; geomcheck::orient3d(a, b, c, d) is then -1), no distinct point
// strictly inside any tetrahedron's circumsphere, the union equal to the
// convex hull, every distinct point a vertex (points on the hull's faces and
// edges included). Fewer than four distinct points, or coplanar ones, give
// no tetrahedra and say which (`dimension`). A NaN or infinite coordinate is
// rejected (DelaunayInputError, naming the first bad index); nothing is
// silently dropped.
//
// Cospherical points: a point ON a circumsphere is not in conflict with its
// tetrahedron (only strictly inside is; on a hull facet's plane, only
// strictly inside its circumcircle). Five or more cospherical points (every
// cube of an integer grid) are therefore tetrahedralized by the insertion
// order, and that order is a function of the point set alone (a key from
// the Hilbert index of the bounding-box-normalised coordinates, then x, y,
// z), so the tetrahedra do not depend on the order of the input, and exact
// translations and scalings by powers of two (no overflow, no underflow)
// give the same index quadruples. In general position the tetrahedralization
// is unique, and equal to every other Delaunay code's.
//
// Algorithm: the distinct points scaled by one power of two (largest
// magnitude into [1, 2), so that the filters answer at any scale), ordered
// along a 3D Hilbert curve in rounds of a biased randomized insertion order
// (as delaunay_2d); Bowyer-Watson insertion (the cavity of tetrahedra in
// conflict, grown from the located one across facets, re-tetrahedralized as
// a star around the new point, its internal facets paired through a small
// hash of directed edges) on a tetrahedralization closed by infinite
// tetrahedra through a vertex at infinity (so the hull is updated by the
// same code); point location by a visibility walk from the last new
// tetrahedron. Predicates: orient3d and insphere of predicates3d.hpp
// (exact), so every decision is exact and the structure cannot become
// inconsistent.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "geomcheck/delaunay_2d.hpp"  // DelaunayInputError, DelaunayFailure
#include "geomcheck/vec3.hpp"

namespace geomcheck {

/// The result of delaunay_3d.
struct DelaunayTetrahedralization {
  /// What the distinct input points span.
  enum class Dimension : unsigned char {
    empty,  ///< no points
    point,  ///< one distinct point (possibly repeated)
    line,   ///< two or more distinct points, all collinear
    plane,  ///< three or more distinct points, all coplanar, not collinear
    solid,  ///< four distinct points not coplanar: tetrahedra
  };
  /// Marks a missing neighbour (a facet on the convex hull).
  static constexpr std::uint32_t kNone = 0xFFFFFFFFu;
  /// Positively oriented tetrahedra; entries are input indices of vertices
  /// (each the smallest input index with those coordinates).
  std::vector<std::array<std::uint32_t, 4>> tetrahedra;
  /// neighbors[t][i]: the tetrahedron across the facet opposite
  /// tetrahedra[t][i], or kNone on the hull.
  std::vector<std::array<std::uint32_t, 4>> neighbors;
  /// vertex_of[i]: the vertex (input index) that input point i is.
  std::vector<std::uint32_t> vertex_of;
  /// Number of distinct points.
  std::size_t vertex_count = 0;
  /// Number of hull facets (triangles on the boundary); 0 unless solid.
  std::size_t hull_facets = 0;
  Dimension dimension = Dimension::empty;

  /// One line saying what was built, e.g. "solid: 1000 distinct points of
  /// 1003 (3 duplicates merged), 6312 tetrahedra, 120 hull facets".
  std::string summary() const;
};

/// "empty", "point", "line", "plane" or "solid".
const char* to_string(DelaunayTetrahedralization::Dimension d);

/// The Delaunay tetrahedralization of points[0..n) (semantics above).
DelaunayTetrahedralization delaunay_3d(const Vec3* points, std::size_t n);
/// The Delaunay tetrahedralization of `points`.
inline DelaunayTetrahedralization delaunay_3d(const std::vector<Vec3>& points) {
  return delaunay_3d(points.data(), points.size());
}

}  // namespace geomcheck
