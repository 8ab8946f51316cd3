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

#include "geomcheck/peers/fcl_adapter.hpp"
#include "geomcheck/shapes.hpp"
#include "geomcheck/triangle_mesh.hpp"

namespace geomcheck::peers {

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

/// The FCL form of a geomcheck shape: FclSphere, FclCapsule, FclBox,
/// FclCylinder, FclTriangle.
template <class S> struct FclShapeOf;
template <> struct FclShapeOf<Sphere> { using type = FclSphere; };
template <> struct FclShapeOf<Capsule> { using type = FclCapsule; };
template <> struct FclShapeOf<Obb> { using type = FclBox; };
template <> struct FclShapeOf<Cylinder> { using type = FclCylinder; };
template <> struct FclShapeOf<Triangle> { using type = FclTriangle; };
template <class S>
using FclOf = typename FclShapeOf<S>::type;

namespace fcl_detail {
/// The points a shape is placed by and its size (a radius, a box's largest
/// extent): what FCL's range limits are measured on (fcl_guards.hpp's
/// extent).
struct Reach {
  Vec3 points[3];
  int n = 0;
  double size = 0;
};
inline Reach reach(const Cylinder& c) { return {{c.p, c.q, {}}, 2, c.r}; }
inline Reach reach(const Capsule& c) { return {{c.p, c.q, {}}, 2, c.r}; }
inline Reach reach(const Sphere& s) { return {{s.c, {}, {}}, 1, s.r}; }
inline Reach reach(const Obb& b) { return {{b.c, {}, {}}, 1, max_abs(b.e)}; }
inline Reach reach(const Triangle& t) { return {{t.a, t.b, t.c}, 3, 0.0}; }
}  // namespace fcl_detail

/// A pair of shapes converted once (`A`, `B`: geomcheck shapes with
/// kFclAsks<A, B>); the `*_prepared` calls run only FCL's query and the
/// conversion of its result. PeerContact's normal is from a towards b.
/// Requires valid shapes (a box: orthonormal axes).
template <class A, class B>
struct FclPair {
  using ShapeA = A;
  using ShapeB = B;
  FclOf<A> a;
  FclOf<B> b;
  FclPair(const A& x, const B& y) : a(x), b(y) {}
};

/// The pairs the benchmarks time, by name.
using FclCylinderSphere = FclPair<Cylinder, Sphere>;
using FclCylinderCylinder = FclPair<Cylinder, Cylinder>;
using FclCylinderCapsule = FclPair<Cylinder, Capsule>;
using FclCylinderBox = FclPair<Cylinder, Obb>;
using FclCylinderTriangle = FclPair<Cylinder, Triangle>;

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

/// fcl::collide without contact on a converted pair, as shipped: no
/// validity check, exceptions propagate. Where FCL runs libccd's MPR
/// (!kFclClosedFormCollide) its support functions are not guarded: on the
/// inputs described in fcl_adapter.hpp ("Guarded support functions") this
/// call does not return. A triangle: GJKSolver_libccd::shapeTriangleIntersect
/// with the tolerance fcl::collide gives the solver.
template <class A, class B>
bool fcl_overlap_prepared(const FclPair<A, B>& pair);

/// fcl::collide with contact on a converted pair, as shipped (unguarded, see
/// fcl_overlap_prepared; exceptions are caught). Where fcl_collide is ok,
/// the same answer bit for bit. MPR's touching contact (zero normal, depth
/// below CCD_EPS) is accepted as ok.
template <class A, class B>
PeerContact fcl_collide_prepared(const FclPair<A, B>& pair);

/// fcl::distance on a converted pair, as shipped (unguarded: where FCL runs
/// libccd's GJK it ABORTS the process on the inputs described in
/// fcl_adapter.hpp; exceptions are caught). Where fcl_distance is ok, the
/// same answer.
template <class A, class B>
PeerDistance fcl_distance_prepared(const FclPair<A, B>& pair);

}  // namespace geomcheck::peers
