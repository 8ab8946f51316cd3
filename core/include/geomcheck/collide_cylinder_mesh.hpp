// geomcheck — collide_cylinder_mesh: cylinder (A) against a triangle mesh
// (B, triangle_mesh.hpp).
//
// Semantics: the mesh is the union of its closed triangles; the shapes
// overlap iff the cylinder overlaps some triangle, decided by
// collide_cylinder_triangle. `collide` returns the contact of the DEEPEST
// triangle (the largest collide_cylinder_triangle depth; the smallest face
// index on ties) and that face's index: every field is exactly that
// triangle's collide_cylinder_triangle answer, so the claims of that query
// hold for it (its penetration depth, its minimal translation, a point in
// both). That is the contact an engine resolves first; it is not the
// penetration depth of the union.
//
// Broad phase (as the engine does it): the hierarchy's boxes against the
// cylinder's bounding capsule, taken conservatively as the axis segment
// against each box grown by r plus a margin of 2^-30 times the scene's
// magnitude (a box the capsule meets is never skipped, whatever the
// rounding). Then each face of every leaf reached against three directions
// (the cylinder's axis, the face's normal, across the axis towards the
// face): a face apart along one of them by more than a margin far above the
// rounding (mesh_face_gap) is skipped. Narrow phase: the triangle query's
// verdict on every other face; `overlap` stops at the first hit. `collide`
// bounds the depth of each face kept from above, should it overlap (the
// overlap along +-u, +-its normal and +-u x each edge, which the triangle
// query also takes), and runs the full triangle collide (verdict and
// contact) in decreasing order of the bound, until the bound falls below
// the deepest depth found. The answers are therefore bit-identical to
// the brute force over all faces in index order (`overlap_brute_force`,
// `collide_brute_force`), which the properties check.
//
// Invalid input (an invalid cylinder, a non-finite vertex, an index out of
// range) gives "no overlap".
#pragma once

#include <cstdint>

#include "geomcheck/argument_order.hpp"
#include "geomcheck/results.hpp"
#include "geomcheck/shapes.hpp"
#include "geomcheck/triangle_mesh.hpp"

namespace geomcheck {

/// Does the closed cylinder meet some triangle of the mesh?
bool overlap(const Cylinder& a, const TriangleMesh& b);
/// The deepest triangle's contact (normal from the cylinder towards the
/// mesh); its face index in *triangle when given (left alone on no hit).
Contact collide(const Cylinder& a, const TriangleMesh& b, std::uint32_t* triangle = nullptr);

namespace detail {
/// The face filter's largest gap between the cylinder and the face along
/// its three directions, relative to each direction's scale (positive:
/// apart as computed); -inf where it does not apply. A face is skipped
/// when the gap exceeds mesh_face_margin() (2^-32).
double mesh_face_gap(const Cylinder& a, const Triangle& t);
double mesh_face_margin();
/// The same answers without the hierarchy: every face, in index order.
bool overlap_brute_force(const Cylinder& a, const TriangleMesh& b);
Contact collide_brute_force(const Cylinder& a, const TriangleMesh& b, std::uint32_t* triangle = nullptr);
}  // namespace detail

}  // namespace geomcheck
