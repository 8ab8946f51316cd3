// geomcheck — known-wrong variants of production: each property suite must
// catch them (the teeth), and `geomcheck campaign --variant NAME` runs one in
// production's place.
#pragma once

#include "geomcheck/properties/checks.hpp"

namespace geomcheck::teeth {

/// collide_cylinder_sphere computed as sphere vs capsule (round caps).
extern const CylinderSphereImpl kCapsuleForCylinder;
/// cast_segment_cylinder against the infinite cylinder, no cap test.
extern const CastSegmentCylinderImpl kInfiniteCylinder;
/// cast_segment_cylinder as printed in the book (known errata).
extern const CastSegmentCylinderImpl kEricsonPrinted;

/// collide_cylinder_capsule computed as capsule vs capsule (the cylinder's
/// caps rounded): closest points of the two segments against r + r'.
extern const CylinderCapsuleImpl kCapsuleCapsule;
/// sweep_sphere_cylinder without its corner stage: stage 1 (the augmented
/// cylinder) accepted as it is.
extern const SweepSphereCylinderImpl kSweepNoCornerStage;
/// sweep_sphere_cylinder with the talk's stage 2 as stated: one sphere test
/// at the stage-1 point clamped to the rim.
extern const SweepSphereCylinderImpl kSweepTalkRimPoint;
/// collide_cylinder_obb computed as box vs capsule: the query without its
/// cap stage (the bounding capsule's answer).
extern const CylinderObbImpl kBoxAsCapsule;
/// collide_cylinder_obb with the talk's step 3 as stated (direction
/// corrected to Pbox's radial line): one ray per box plane through Pbox.
extern const CylinderObbImpl kBoxTalkRays;
/// collide_cylinder_obb without the EPA steps on its circles of normals: the
/// best of the closed-form candidates (+-u, the box axes, u x the box axes,
/// the directions across u in each box plane, the side x vertex radial
/// directions), no rim x edge direction (caught by the depth-ratio bound).
extern const CylinderObbImpl kBoxNoCircleSearch;
/// collide_cylinder_triangle without its cap stage: a triangle whose point
/// nearest the axis segment lies beyond a cap is taken as a miss (the talk's
/// steps 1 and 2 only), though it may still cut into the cap's disc.
extern const CylinderTriangleImpl kTriangleNoCapStage;
/// collide_cylinder_triangle without the EPA steps on its circles of
/// normals: the best of the closed-form candidates (+-u, the face normal,
/// u x each edge, the directions across u and along the face in each
/// edge's plane, the side x vertex radial directions), no rim x edge
/// direction (caught by the depth-ratio bound).
extern const CylinderTriangleImpl kTriangleNoCircleSearch;

/// collide_cylinder_cylinder without its false-positive planes: every slice
/// holds A to B's cap planes pushed out by A's full reach r_A sin theta (and
/// B to A's by r_B sin theta), the augmented cylinders' square ends.
extern const CylinderCylinderImpl kCylinderNoPlanes;
/// collide_cylinder_cylinder without its parallel-axis branch: the general
/// frame from the common perpendicular, which is zero for parallel axes.
extern const CylinderCylinderImpl kCylinderNoParallelBranch;
/// collide_cylinder_cylinder with the plain frame u_B x u_A (the common
/// perpendicular loses digits as 1 / theta near parallel axes).
extern const CylinderCylinderImpl kCylinderPlainFrame;
/// collide_cylinder_cylinder with the normal search it had before the depth
/// ratio was bounded: one Newton step per circle of side normals, stopped at
/// a half-angle of 2^-10 rad whatever the depth, no search off the circles
/// (its depth reached 3.9e6 times the penetration depth; caught by the
/// depth-ratio bound).
extern const CylinderCylinderImpl kCylinderShortSearch;

}  // namespace geomcheck::teeth
