// geomcheck — delaunay_2d: Delaunay triangulation of points in the plane.
//
// Semantics: the input is a sequence of points (doubles, taken exactly).
// Points with equal coordinates are one vertex (-0.0 equals 0.0); every
// input index maps to a vertex, named by the smallest input index of its
// coordinates (`vertex_of`). When at least three distinct points are not
// collinear, the output is a Delaunay triangulation of the distinct points:
// triangles as counter-clockwise index triples, every triangle
// non-degenerate, no point strictly inside any triangle's circumcircle, the
// union equal to the convex hull, every distinct point a vertex (points on
// the hull's edges included). Collinear, coincident and empty input give no
// triangles and say which (`dimension`). A NaN or infinite coordinate is
// rejected (DelaunayInputError, naming the first bad index); nothing is
// silently dropped.
//
// Cocircular points: a point ON a circumcircle is not in conflict with its
// triangle (only strictly inside is). Four or more cocircular points are
// therefore triangulated by the insertion order, and that order is a
// function of the point set alone (Hilbert key of the bounding-box
// normalised coordinates, then x, then y), so the triangulation does not
// depend on the order of the input, and exact translations and scalings by
// powers of two (no overflow, no underflow) give the same index triples.
//
// Algorithm: spatial sort along a Hilbert curve in rounds of a biased
// randomized insertion order (a counting sort on the key's leading bits);
// Bowyer-Watson insertion (the cavity of triangles in conflict, grown depth
// first so that its boundary comes out in order, re-triangulated as a fan
// around the new point) on a triangulation closed by ghost triangles
// through a vertex at infinity (the hull is updated by the same code);
// point location by a visibility walk from the last new triangle (which
// cannot cycle on a Delaunay triangulation). The triangles live in two arrays shaped like the output
// (vertices, neighbours), compacted in place and moved into the result.
// Predicates: orient2d and incircle of predicates2d.hpp (exact), so every
// decision is exact and the structure cannot become inconsistent.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "geomcheck/predicates2d.hpp"

namespace geomcheck {

/// What the distinct input points span.
enum class DelaunayDimension {
  empty,  ///< no points
  point,  ///< one distinct point (possibly repeated)
  line,   ///< two or more distinct points, all collinear: no triangles
  plane,  ///< three or more distinct points not all collinear
};

/// "empty", "point", "line" or "plane".
const char* to_string(DelaunayDimension d);

/// The result of delaunay_2d.
struct DelaunayTriangulation {
  /// Marks a missing neighbour (an edge on the convex hull).
  static constexpr std::uint32_t kNone = 0xFFFFFFFFu;
  /// Counter-clockwise triangles; entries are input indices of vertices
  /// (each the smallest input index with those coordinates).
  std::vector<std::array<std::uint32_t, 3>> triangles;
  /// neighbors[t][i]: the triangle across the edge opposite triangles[t][i],
  /// or kNone on the hull.
  std::vector<std::array<std::uint32_t, 3>> neighbors;
  /// vertex_of[i]: the vertex (input index) that input point i is.
  std::vector<std::uint32_t> vertex_of;
  /// Number of distinct points.
  std::size_t vertex_count = 0;
  /// Number of hull edges (= vertices on the hull boundary, collinear ones
  /// included); 0 unless dimension == plane.
  std::size_t hull_edges = 0;
  DelaunayDimension dimension = DelaunayDimension::empty;

  /// One line saying what was built, e.g. "plane: 1000 distinct points of
  /// 1003 (3 duplicates merged), 1990 triangles, 8 hull edges" or "line: all
  /// 5 distinct points are collinear, no triangles".
  std::string summary() const;
};

/// Thrown for input that has no triangulation: a NaN or infinite
/// coordinate (index() is the first such point), or more points than the
/// 32-bit indices can name.
class DelaunayInputError : public std::invalid_argument {
 public:
  DelaunayInputError(std::size_t index, const std::string& what)
      : std::invalid_argument(what), index_(index) {}
  /// The offending input index.
  std::size_t index() const noexcept { return index_; }

 private:
  std::size_t index_;
};

/// Thrown when the structure becomes inconsistent (a walk that does not
/// end, a cavity that is not a disc). Exact predicates rule this out; the
/// tests' plain-double variant raises it.
class DelaunayFailure : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// The Delaunay triangulation of points[0..n) (semantics above).
DelaunayTriangulation delaunay_2d(const Vec2* points, std::size_t n);
/// The Delaunay triangulation of `points`.
inline DelaunayTriangulation delaunay_2d(const std::vector<Vec2>& points) {
  return delaunay_2d(points.data(), points.size());
}

}  // namespace geomcheck
