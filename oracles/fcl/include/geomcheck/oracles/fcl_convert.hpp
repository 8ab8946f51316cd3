// geomcheck — conversion of geomcheck shapes to FCL geometry and poses, and
// the FCL calls on already converted shapes.
//
// This header includes FCL (and Eigen). Use fcl_adapter.hpp unless you need
// FCL types: the benchmarks convert their inputs once, outside the timed
// loop, so that they time FCL's query and not the conversion.
//
// Conventions and caveats are documented in fcl_adapter.hpp.
#pragma once

#include <fcl/geometry/bvh/BVH_model.h>
#include <fcl/geometry/shape/box.h>
#include <fcl/geometry/shape/capsule.h>
#include <fcl/geometry/shape/cylinder.h>
#include <fcl/geometry/shape/sphere.h>
#include <fcl/common/types.h>

#include "geomcheck/oracles/fcl_adapter.hpp"
#include "geomcheck/shapes.hpp"
#include "geomcheck/triangle_mesh.hpp"

namespace geomcheck::oracles {

/// Rotation whose third column is the unit vector `u` (it takes +z to u):
/// columns (e1, e2, u) with e1 = any_perpendicular(u), e2 = u x e1.
/// Right-handed and orthonormal to rounding for every direction, including
/// -z. `u` must be unit.
fcl::Matrix3d fcl_rotation_z_to(const Vec3& u);

/// A geomcheck shape as FCL sees it: FCL's shape and its pose.
template <class FclShape>
struct FclPosed {
  FclShape shape;
  fcl::Transform3d pose;
};

/// A geomcheck cylinder as FCL sees it. Requires is_valid(c).
struct FclCylinder : FclPosed<fcl::Cylinderd> {
  explicit FclCylinder(const Cylinder& c);
};

/// A geomcheck sphere as FCL sees it. Requires is_valid(s).
struct FclSphere : FclPosed<fcl::Sphered> {
  explicit FclSphere(const Sphere& s);
};

/// A geomcheck capsule as FCL sees it: fcl::Capsuled(r, |q - p|) at
/// (p + q)/2 with +z along q - p; p == q gives lz = 0 and the identity
/// rotation (a sphere, still an fcl::Capsuled). Requires is_valid(c).
struct FclCapsule : FclPosed<fcl::Capsuled> {
  explicit FclCapsule(const Capsule& c);
};

/// A geomcheck oriented box as FCL sees it: fcl::Boxd with FULL side
/// lengths 2 e_i (exact unless 2 e_i overflows), centred at c, rotation with
/// columns (axes[0], axes[1], axes[2]); a left-handed frame (det < 0) gets
/// axes[2] negated (the same set: the box is symmetric). Zero extents (flat
/// boxes, segments, points) are accepted by FCL. Requires is_valid(b) and
/// obb_axes_orthonormal(b) (FCL takes the matrix for a rotation).
struct FclBox : FclPosed<fcl::Boxd> {
  explicit FclBox(const Obb& b);
};

/// A geomcheck triangle as FCL's per-triangle narrow phase takes it: its
/// three vertices, exactly (world frame). Requires is_valid(t).
struct FclTriangle {
  fcl::Vector3d a, b, c;
  explicit FclTriangle(const Triangle& t);
};

/// A cylinder and a shape converted once (`FclB`: FclSphere, FclCylinder,
/// FclCapsule, FclBox or FclTriangle, built from the geomcheck shape); the
/// `*_prepared` calls run only FCL's query and the conversion of its result.
/// PeerContact's normal is from the cylinder towards the second shape.
/// Requires valid shapes (a box: orthonormal axes).
template <class FclB>
struct FclCylinderPair {
  FclCylinder a;
  FclB b;
  template <class B>
  FclCylinderPair(const Cylinder& cyl, const B& shape) : a(cyl), b(shape) {}
};

/// A cylinder/sphere pair converted once.
using FclCylinderSphere = FclCylinderPair<FclSphere>;
/// A cylinder/cylinder pair converted once (PeerContact's normal and
/// PeerDistance's points then refer to the first and second cylinder).
using FclCylinderCylinder = FclCylinderPair<FclCylinder>;
/// A cylinder/capsule pair converted once.
using FclCylinderCapsule = FclCylinderPair<FclCapsule>;
/// A cylinder/box pair converted once (orthonormal axes required).
using FclCylinderBox = FclCylinderPair<FclBox>;
/// A cylinder/triangle pair converted once.
using FclCylinderTriangle = FclCylinderPair<FclTriangle>;

/// A geomcheck triangle mesh as FCL's BVH model of oriented-box / swept-
/// sphere volumes (fcl::BVHModel<OBBRSSd>: beginModel, addSubModel with the
/// vertices and faces as they are, endModel). Constructing it is FCL's BVH
/// build. Requires is_valid(m) and at least one face.
struct FclMesh {
  fcl::BVHModel<fcl::OBBRSSd> model;
  explicit FclMesh(const TriangleMesh& m);
};

/// fcl::collide(mesh, cylinder) as shipped (GST_LIBCCD, the BVH traversal
/// and the per-triangle narrow phase shapeTriangleIntersect, unguarded).
/// max_contacts = 1 (the traversal stops at the first contact found) or more
/// (the contacts of up to that many triangles; the deepest is returned).
/// The normal is from the cylinder towards the mesh (FCL's, from the mesh,
/// flipped); `contacts` gets the number FCL reported.
PeerContact fcl_collide_prepared(const FclCylinder& cyl, const FclMesh& mesh, int max_contacts, int* contacts = nullptr);

/// fcl_overlap on a converted pair (no validity check; exceptions propagate).
bool fcl_overlap_prepared(const FclCylinderSphere& pair);
bool fcl_overlap_prepared(const FclCylinderCylinder& pair);
/// fcl::collide as shipped, enable_contact = false. Unlike the adapter's
/// fcl_overlap(Cylinder, Capsule) its support functions are not guarded: on
/// the inputs described in fcl_adapter.hpp ("Guarded support functions")
/// this call does not return.
bool fcl_overlap_prepared(const FclCylinderCapsule& pair);
/// fcl_collide on a converted pair (no validity check; exceptions are caught).
PeerContact fcl_collide_prepared(const FclCylinderSphere& pair);
PeerContact fcl_collide_prepared(const FclCylinderCylinder& pair);
/// fcl::collide as shipped (unguarded, see fcl_overlap_prepared); where
/// fcl_collide is ok, the same answer bit for bit.
PeerContact fcl_collide_prepared(const FclCylinderCapsule& pair);
/// fcl_distance on a converted pair (no validity check; exceptions are caught).
PeerDistance fcl_distance_prepared(const FclCylinderSphere& pair);
PeerDistance fcl_distance_prepared(const FclCylinderCylinder& pair);
/// fcl::distance as shipped (unguarded): ABORTS the process on the inputs
/// described in fcl_adapter.hpp; where fcl_distance is ok, the same answer.
PeerDistance fcl_distance_prepared(const FclCylinderCapsule& pair);

/// fcl::collide / fcl::distance as shipped (GST_LIBCCD: libccd's MPR and GJK
/// on FCL's support functions, unguarded, like the capsule's prepared calls:
/// they can hang or abort where the adapter's calls report not ok). MPR's
/// touching contact (zero normal, depth below CCD_EPS) is accepted as ok.
bool fcl_overlap_prepared(const FclCylinderBox& pair);
PeerContact fcl_collide_prepared(const FclCylinderBox& pair);
PeerDistance fcl_distance_prepared(const FclCylinderBox& pair);

/// FCL's per-triangle narrow phase as shipped (what its BVH traversal calls
/// for each triangle of a mesh): GJKSolver_libccd::shapeTriangleIntersect /
/// shapeTriangleDistance on the cylinder and the three vertices, with the
/// tolerances fcl::collide / fcl::distance give the solver (1e-6).
/// Unguarded; MPR's touching contact is accepted as ok.
bool fcl_overlap_prepared(const FclCylinderTriangle& pair);
PeerContact fcl_collide_prepared(const FclCylinderTriangle& pair);
PeerDistance fcl_distance_prepared(const FclCylinderTriangle& pair);

}  // namespace geomcheck::oracles
