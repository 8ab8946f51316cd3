// geomcheck — oracles for a 3D Delaunay tetrahedralization and a convex
// hull: exact validity checkers and CGAL's Delaunay_triangulation_3, both on CGAL's
// exact predicates (Epick: interval filter, exact fallback), independent of
// production's (predicates3d.hpp); the checkers take their signs from 128-bit
// integers instead where every coordinate is a short integer times one power
// of two (IntegerSigns3).
//
// A tetrahedralization of points p[0..n) is a list of index quadruples. Its
// conventions, which check_delaunay_3d holds:
//   - a tetrahedron names representative indices only (the smallest index of
//     equal coordinates), four distinct ones;
//   - every tetrahedron (a, b, c, d) is positively oriented, CGAL's and the
//     right-handed convention: d lies on the side of the plane abc that
//     (b - a) x (c - a) points to (CGAL::orientation POSITIVE; Shewchuk's
//     orient3d(a, b, c, d) is then -1);
//   - fewer than four distinct points, or all distinct points coplanar: no
//     tetrahedron.
// check_delaunay_3d accepts a list exactly when it is a Delaunay
// tetrahedralization of the points under these conventions:
//   - indices in range, representative, distinct; every tetrahedron
//     positively oriented (exact), so none is flat;
//   - every facet (a triangle, up to rotation) lies in at most two
//     tetrahedra, and then with opposite orientations (one on each side);
//   - every facet in two is locally Delaunay: the other tetrahedron's
//     opposite vertex is not strictly inside this one's circumsphere (exact
//     side_of_oriented_sphere; on it is allowed: cospherical ties);
//   - no distinct point lies strictly outside a facet in one tetrahedron
//     (its plane, oriented outwards): every boundary facet is on the hull;
//   - every distinct point is a vertex; without tetrahedra, the distinct
//     points are fewer than four or coplanar, and with them they are not.
// Positive orientations and paired facets make the union a manifold covered
// once near every facet; boundary facets on the hull's planes make it the
// hull; locally Delaunay facets make it Delaunay (the 3D analogue of
// Lawson's lemma).
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "geomcheck/convex_hull_3d.hpp"
#include "geomcheck/vec3.hpp"

namespace geomcheck::oracle {

using Tetrahedron = std::array<std::uint32_t, 4>;

/// Exact orientation and in-sphere signs in 128-bit integers, for point
/// sets whose coordinates are all integers times one power of two, spanning
/// at most kMaxBits bits (grids, integer spheres and planes, small integers,
/// at any exact power-of-two scale): the checkers ask these first and CGAL's
/// predicates for any other set. Signs follow CGAL's orientation and
/// side_of_oriented_sphere on the points of the given indices.
class IntegerSigns3 {
 public:
  static constexpr int kMaxBits = 20;  // |x| < 2^20: an in-sphere determinant stays below 2^112
  explicit IntegerSigns3(const std::vector<Vec3>& points);
  /// Whether the set qualifies (else neither sign may be asked).
  bool ok() const { return ok_; }
  /// CGAL::orientation(p, q, r, s): +1 when s is on the positive side of pqr.
  int orientation(std::uint32_t p, std::uint32_t q, std::uint32_t r, std::uint32_t s) const;
  /// CGAL::side_of_oriented_sphere(p, q, r, s, t): +1 when t is inside the
  /// sphere of the positively oriented pqrs.
  int side_of_oriented_sphere(std::uint32_t p, std::uint32_t q, std::uint32_t r, std::uint32_t s,
                              std::uint32_t t) const;

 private:
  bool ok_ = false;
  std::vector<std::array<std::int64_t, 3>> coords_;
};

/// "" when `tets` is a Delaunay tetrahedralization of `points` (above), else
/// the first violation found, in words, naming the tetrahedron, facet or
/// point. Cost: facets sorted, plus every boundary facet against every
/// distinct point (O(h n) orientation tests).
std::string check_delaunay_3d(const std::vector<Vec3>& points, const std::vector<Tetrahedron>& tets);

/// CGAL's Delaunay tetrahedra of the points (Epick, range insert), as
/// quadruples of representative indices, positively oriented, each in
/// canonical form (canonical_tetrahedron), sorted. Empty for fewer than four
/// distinct points or coplanar ones.
std::vector<Tetrahedron> cgal_delaunay_3d(const std::vector<Vec3>& points);

/// t with its smallest index first, by an even permutation (the orientation
/// kept), and the other three rotated so that the second is the smallest of
/// them.
Tetrahedron canonical_tetrahedron(Tetrahedron t);

/// "" when `hull` is the convex hull of `points` by the semantics of
/// convex_hull_3d.hpp, else the first violation found: the dimension is the
/// distinct points' (exact orientation tests); for a solid, every facet
/// names representative, distinct, non-collinear points; every directed edge
/// is in one facet and its reverse in one other (a closed, consistently
/// oriented surface); no distinct point lies strictly outside a facet's
/// plane (each facet is on the hull); and the volume the facets enclose
/// equals the sum of the volumes of CGAL's Delaunay tetrahedra (exact
/// sums), so the surface wraps the hull once. Cost: O(facets * points)
/// orientation tests.
std::string check_convex_hull_3d(const std::vector<Vec3>& points, const ConvexHull3& hull);

}  // namespace geomcheck::oracle
