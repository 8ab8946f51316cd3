#include "geomcheck/triangle_mesh.hpp"

#include <algorithm>
#include <utility>

namespace geomcheck {

namespace {

struct Builder {
  const std::vector<Vec3>& v;
  const std::vector<MeshFace>& f;
  std::vector<Vec3> lo, hi, mid;  // per face: box and box centre
  detail::Bvh& out;

  Builder(const std::vector<Vec3>& vertices, const std::vector<MeshFace>& faces, detail::Bvh& bvh)
      : v(vertices), f(faces), out(bvh) {
    const std::size_t n = f.size();
    lo.resize(n), hi.resize(n), mid.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      const Vec3 a = v[f[i][0]], b = v[f[i][1]], c = v[f[i][2]];
      for (int k = 0; k < 3; ++k) {
        lo[i][k] = std::min(std::min(a[k], b[k]), c[k]);
        hi[i][k] = std::max(std::max(a[k], b[k]), c[k]);
        mid[i][k] = 0.5 * lo[i][k] + 0.5 * hi[i][k];  // no overflow near the largest doubles
      }
    }
    out.order.resize(n);
    for (std::size_t i = 0; i < n; ++i) out.order[i] = static_cast<std::uint32_t>(i);
    out.nodes.reserve(2 * (n / 4 + 1));
  }

  std::uint32_t build(std::uint32_t first, std::uint32_t last) {
    const std::uint32_t id = static_cast<std::uint32_t>(out.nodes.size());
    out.nodes.emplace_back();
    detail::BvhNode node;
    node.lo = lo[out.order[first]], node.hi = hi[out.order[first]];
    Vec3 clo = mid[out.order[first]], chi = clo;
    for (std::uint32_t i = first; i < last; ++i) {
      const std::uint32_t t = out.order[i];
      for (int k = 0; k < 3; ++k) {
        node.lo[k] = std::min(node.lo[k], lo[t][k]), node.hi[k] = std::max(node.hi[k], hi[t][k]);
        clo[k] = std::min(clo[k], mid[t][k]), chi[k] = std::max(chi[k], mid[t][k]);
      }
    }
    if (last - first <= 4) {
      node.first = first, node.count = last - first;
      out.nodes[id] = node;
      return id;
    }
    int axis = 0;
    for (int k = 1; k < 3; ++k)
      if (chi[k] - clo[k] > chi[axis] - clo[axis]) axis = k;
    const std::uint32_t half = first + (last - first) / 2;
    std::nth_element(out.order.begin() + first, out.order.begin() + half, out.order.begin() + last,
                     [&](std::uint32_t a, std::uint32_t b) {
                       return mid[a][axis] < mid[b][axis] || (mid[a][axis] == mid[b][axis] && a < b);
                     });
    build(first, half);
    node.right = build(half, last);
    out.nodes[id] = node;
    return id;
  }
};

}  // namespace

TriangleMesh::TriangleMesh(std::vector<Vec3> vertices, std::vector<MeshFace> faces)
    : vertices_(std::move(vertices)), faces_(std::move(faces)) {
  for (const Vec3& x : vertices_) {
    if (!is_finite(x)) valid_ = false;
    else magnitude_ = std::max(magnitude_, max_abs(x));
  }
  for (const MeshFace& fc : faces_)
    for (std::uint32_t i : fc)
      if (i >= vertices_.size()) valid_ = false;
  if (faces_.size() >= 0xffffffffu) valid_ = false;
  if (!valid_ || faces_.empty()) return;
  Builder b(vertices_, faces_, bvh_);
  b.build(0, static_cast<std::uint32_t>(faces_.size()));
}

}  // namespace geomcheck
