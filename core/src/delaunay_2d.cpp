#include "geomcheck/delaunay_2d.hpp"

#include "geomcheck/detail/delaunay_build.hpp"

namespace geomcheck {

namespace {
struct ExactPredicates {
  static int orient(Vec2 a, Vec2 b, Vec2 c) { return orient2d(a, b, c); }
  static int incircle(Vec2 a, Vec2 b, Vec2 c, Vec2 d) { return geomcheck::incircle(a, b, c, d); }
};
}  // namespace

const char* to_string(DelaunayDimension d) {
  switch (d) {
    case DelaunayDimension::empty: return "empty";
    case DelaunayDimension::point: return "point";
    case DelaunayDimension::line: return "line";
    case DelaunayDimension::plane: return "plane";
  }
  return "?";
}

std::string DelaunayTriangulation::summary() const {
  const std::size_t n = vertex_of.size();
  const std::size_t merged = n - vertex_count;
  const std::string dups =
      merged == 0 ? std::string() : " (" + std::to_string(merged) + (merged == 1 ? " duplicate" : " duplicates") + " merged)";
  switch (dimension) {
    case DelaunayDimension::empty: return "empty: no points, no triangles";
    case DelaunayDimension::point:
      return "point: " + std::to_string(n) + (n == 1 ? " point" : " coincident points") + ", no triangles";
    case DelaunayDimension::line:
      return "line: all " + std::to_string(vertex_count) + " distinct points of " + std::to_string(n) + dups +
             " are collinear, no triangles";
    case DelaunayDimension::plane:
      return "plane: " + std::to_string(vertex_count) + " distinct points of " + std::to_string(n) + dups + ", " +
             std::to_string(triangles.size()) + " triangles, " + std::to_string(hull_edges) + " hull edges";
  }
  return "?";
}

DelaunayTriangulation delaunay_2d(const Vec2* points, std::size_t n) {
  return detail::DelaunayBuilder<ExactPredicates>().run(points, n);
}

}  // namespace geomcheck
