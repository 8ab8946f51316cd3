// geomcheck — geomcheck's shapes as FCL sees them (fcl_convert.hpp), and
// FCL's mesh query as shipped.
#include "geomcheck/peers/fcl_convert.hpp"

#include <algorithm>
#include <vector>

#include <fcl/narrowphase/collision.h>

#include "fcl_guards.hpp"

namespace geomcheck::peers {

using fcl_detail::contact_from;
using fcl_detail::guarded;
using fcl_detail::no_contact;
using fcl_detail::norm;
using fcl_detail::to_fcl;
using fcl_detail::unit;

fcl::Matrix3d fcl_rotation_z_to(const Vec3& u) {
  const Vec3 e1 = any_perpendicular(u);
  const Vec3 e2 = cross(u, e1);
  fcl::Matrix3d r;
  r.col(0) = to_fcl(e1);
  r.col(1) = to_fcl(e2);
  r.col(2) = to_fcl(u);
  return r;
}

FclCylinder::FclCylinder(const Cylinder& c)
    : FclPosed{fcl::Cylinderd(c.r, norm(c.q - c.p)), fcl::Transform3d::Identity()} {
  pose.linear() = fcl_rotation_z_to(unit(c.q - c.p));
  pose.translation() = to_fcl(0.5 * c.p + 0.5 * c.q);
}

FclSphere::FclSphere(const Sphere& s) : FclPosed{fcl::Sphered(s.r), fcl::Transform3d::Identity()} {
  pose.translation() = to_fcl(s.c);
}

FclCapsule::FclCapsule(const Capsule& c)
    : FclPosed{fcl::Capsuled(c.r, norm(c.q - c.p)), fcl::Transform3d::Identity()} {
  if (c.p != c.q) pose.linear() = fcl_rotation_z_to(unit(c.q - c.p));
  pose.translation() = to_fcl(0.5 * c.p + 0.5 * c.q);
}

FclBox::FclBox(const Obb& b)
    : FclPosed{fcl::Boxd(2 * b.e.x, 2 * b.e.y, 2 * b.e.z), fcl::Transform3d::Identity()} {
  // FCL takes the frame for a rotation: a left-handed one gets its third
  // axis negated, which leaves the (symmetric) box the same set.
  const bool left_handed = dot(cross(b.axes[0], b.axes[1]), b.axes[2]) < 0;
  fcl::Matrix3d r;
  r.col(0) = to_fcl(b.axes[0]);
  r.col(1) = to_fcl(b.axes[1]);
  r.col(2) = to_fcl(left_handed ? -b.axes[2] : b.axes[2]);
  pose.linear() = r;
  pose.translation() = to_fcl(b.c);
}

FclTriangle::FclTriangle(const Triangle& t) : a(to_fcl(t.a)), b(to_fcl(t.b)), c(to_fcl(t.c)) {}

FclMesh::FclMesh(const TriangleMesh& m) {
  std::vector<fcl::Vector3d> points;
  points.reserve(m.vertices().size());
  for (const Vec3& v : m.vertices()) points.emplace_back(v.x, v.y, v.z);
  std::vector<fcl::Triangle> tris;
  tris.reserve(m.size());
  for (const MeshFace& f : m.faces()) tris.emplace_back(f[0], f[1], f[2]);
  model.beginModel(static_cast<int>(tris.size()), static_cast<int>(points.size()));
  model.addSubModel(points, tris);
  model.endModel();
}

PeerContact fcl_collide_prepared(const FclCylinder& cyl, const FclMesh& mesh, int max_contacts, int* contacts) {
  return guarded<PeerContact>([&]() -> PeerContact {
    fcl::CollisionRequestd req(static_cast<std::size_t>(std::max(max_contacts, 1)), true);
    req.gjk_solver_type = fcl::GST_LIBCCD;
    fcl::CollisionResultd res;
    fcl::collide(&mesh.model, fcl::Transform3d::Identity(), &cyl.shape, cyl.pose, req, res);
    if (contacts) *contacts = static_cast<int>(res.numContacts());
    if (!res.isCollision()) return no_contact();
    std::size_t deepest = 0;
    for (std::size_t i = 1; i < res.numContacts(); ++i)
      if (res.getContact(i).penetration_depth > res.getContact(deepest).penetration_depth) deepest = i;
    const fcl::Contactd& c = res.getContact(deepest);
    return contact_from(c.pos, -c.normal, c.penetration_depth, true);
  });
}

}  // namespace geomcheck::peers
