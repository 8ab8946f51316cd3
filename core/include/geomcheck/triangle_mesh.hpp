// geomcheck — TriangleMesh: an indexed set of closed triangles with a
// bounding volume hierarchy over them.
//
// Semantics: the union of its triangles (each face {i, j, k} is
// Triangle{v[i], v[j], v[k]}, degenerate ones included: repeated indices or
// collinear vertices give its segment or point). Duplicate faces, shared
// edges and vertices, unreferenced vertices and an empty mesh are all
// allowed. The mesh is valid when every vertex is finite and every index
// is in range; an invalid mesh has no hierarchy and overlaps nothing.
//
// The hierarchy is built once, in the constructor: axis-aligned boxes (the
// exact minimum and maximum of the vertex doubles), split top-down at the
// median of the face centroids along the longest axis of their box (ties
// broken by face index, so the build is deterministic), leaves of at most
// four faces, nodes in depth-first order.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "geomcheck/shapes.hpp"

namespace geomcheck {

namespace detail {

/// A node of the hierarchy: its box, and either its faces (a leaf:
/// order[first, first + count)) or its children (count == 0: the left child
/// follows the node, the right one is at `right`).
struct BvhNode {
  Vec3 lo, hi;
  std::uint32_t first = 0, count = 0, right = 0;
};

struct Bvh {
  std::vector<BvhNode> nodes;        ///< nodes[0] is the root (none for an empty or invalid mesh)
  std::vector<std::uint32_t> order;  ///< face indices, leaf by leaf
};

}  // namespace detail

using MeshFace = std::array<std::uint32_t, 3>;

class TriangleMesh {
 public:
  TriangleMesh() = default;
  /// Stores the mesh and, when it is valid, builds its hierarchy.
  TriangleMesh(std::vector<Vec3> vertices, std::vector<MeshFace> faces);

  const std::vector<Vec3>& vertices() const { return vertices_; }
  const std::vector<MeshFace>& faces() const { return faces_; }
  std::size_t size() const { return faces_.size(); }
  /// Face i as a triangle (the mesh must be valid).
  Triangle triangle(std::size_t i) const {
    const MeshFace& f = faces_[i];
    return {vertices_[f[0]], vertices_[f[1]], vertices_[f[2]]};
  }
  bool valid() const { return valid_; }
  const detail::Bvh& bvh() const { return bvh_; }
  /// The largest magnitude of a vertex coordinate (0 for no vertices).
  double magnitude() const { return magnitude_; }

 private:
  std::vector<Vec3> vertices_;
  std::vector<MeshFace> faces_;
  bool valid_ = true;
  double magnitude_ = 0;
  detail::Bvh bvh_;
};

inline bool is_valid(const TriangleMesh& m) { return m.valid(); }

}  // namespace geomcheck
