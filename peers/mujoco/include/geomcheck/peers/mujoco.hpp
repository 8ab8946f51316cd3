// geomcheck — MuJoCo 2.2.2 (Debian libmujoco-dev, linked with the
// system's libccd 2.1, double precision) as a peer subject of the
// registered queries it can express. Nothing here includes MuJoCo headers.
//
// ---------------------------------------------------------------------------
// What MuJoCo is asked
//   The adapter compiles one model, once (mj_loadXML on an in-memory VFS
//   file): five geoms, each in a mocap body of its own: cylinder A, a
//   sphere, a capsule, a box, cylinder B; geom margin and gap 0; default
//   options (opt.mpr_tolerance 1e-6, opt.mpr_iterations 50, multi-point
//   CCD off). Every thread copies it (mj_copyModel, mj_makeData; a
//   thread_local pair): before each call the adapter writes the case's
//   sizes into the copy's geom_size and the poses straight into the data's
//   geom_xpos / geom_xmat (no quaternion, no mj_kinematics: the frame is
//   exactly the adapter's, unrounded by a conversion), then calls
//     collide: the pair function mjCOLLISIONFUNC[type1][type2](m, d, con,
//              g1, g2, margin = 0), which mj_collision would call. For
//              every pair asked it is mjc_Convex: libccd's MPR
//              (ccdMPRPenetration) on MuJoCo's support functions
//              (mjccd_support), its centres the geoms' positions. MuJoCo
//              2.2.2 has no closed form for any cylinder pair (the
//              sphere/cylinder and capsule/cylinder entries of the table
//              are mjc_Convex too). overlap(A, B) is collide(A, B).hit:
//              MuJoCo has no separate boolean test.
//     cast:    mju_rayGeom(pos, mat, size, pnt, vec, mjGEOM_CYLINDER), the
//              cylinder ray of mj_ray, from a along the UNIT direction of
//              b - a (mj_ray's own use, e.g. its rangefinder; with a unit
//              vec the ray's absolute thresholds, mjMINVAL = 1e-15 on its
//              discriminant and on the direction's axial component, are
//              in units of length squared and of cosine, not of |b - a|);
//              t = x / |b - a|, a hit when x <= |b - a|.
//
// Conversions
//   Cylinder{p, q, r}: geom type cylinder, size (r, |q - p| / 2), position
//     p/2 + q/2 (cannot overflow), frame: z = (q - p)/|q - p|, x =
//     any_perpendicular(z), y = z x x (|q - p| and the unit axis computed
//     scaled; q - p overflowing is taken as q/2 - p/2). MuJoCo's cylinder
//     is centred, its axis the local z, its flat caps at +-size[1].
//   Sphere{c, r}: geom sphere, size r, at c.
//   Capsule{p, q, r}: geom capsule, size (r, |q - p| / 2), placed as the
//     cylinder; p == q (a ball) is MuJoCo's sphere of radius r (MuJoCo's
//     compiler refuses a capsule of half length 0; the same function,
//     mjc_Convex, answers either).
//   Obb{c, axes, e}: geom box, size e (MuJoCo's box takes HALF sizes), at
//     c, the stored axes as the columns of geom_xmat; a left-handed frame
//     gets axes[2] negated (the same set, the box being symmetric).
//   Segment{a, b}: the ray above; a == b (a point) casts along the
//     cylinder's axis, both ways, for the inside test only.
//   The conversion rounds (|q - p|, the unit axis, the frame, the
//   midpoint): MuJoCo answers for shapes within a few ulps of ours.
//
// `expresses` refuses what MuJoCo's model cannot hold: its compiler's
//   "sizes must be positive" (a cylinder or capsule of radius 0, a sphere
//   of radius 0, a box with a zero half extent; a cylinder whose half
//   length underflows to 0), a box whose stored axes are not orthonormal
//   to 1e-12 (MuJoCo keeps a geom's frame as a rotation), and invalid or
//   non-finite input. Asked anyway (verify() does not consult
//   `expresses`), the callables still answer: they write those sizes and
//   frames into the model as given and report what the engine computes
//   (its box support function, fed a non-orthonormal frame, is the
//   parallelepiped's).
//
// Not expressible (peer_mujoco<Q>() returns a null subject):
//   collide_cylinder_triangle: MuJoCo's only triangle is a mesh face, and
//     its compiler refuses a flat mesh (mj_loadXML, tried): three
//     vertices get "Error: at least 4 verices required" (sic), four
//     coplanar ones "Error: qhull error" (Qhull: "Initial simplex is
//     flat"); past Qhull its mesh must still have a volume (user_mesh.cc:
//     "mesh volume is too small").
//   sweep_sphere_cylinder: MuJoCo 2.2.2 has no continuous collision (no
//     sweep, no time of impact); mj_ray is for lines only.
//
// ---------------------------------------------------------------------------
// Conventions (source: MuJoCo 2.2.2's engine_collision_convex.c,
// engine_collision_driver.c, engine_ray.c, mjdata.h; checked on the hand
// cases of tests/test_peer_mujoco.cpp)
//   Normal: mjContact.frame[0..2], "normal is in [0-2]", pointing from geom
//     1 to geom 2 (a sphere at x = 1.5 beside the unit cylinder, geom 1 the
//     sphere: (-1, 0, 0)). mjCOLLISIONFUNC is upper triangular in the geom
//     types (plane < hfield < sphere < capsule < ellipsoid < cylinder < box
//     < mesh), so for a sphere or a capsule B is geom 1 and the adapter
//     negates the normal; for a box and for cylinder/cylinder the cylinder
//     (the first) is geom 1 and the normal is kept. Either way geomcheck's:
//     from the cylinder (A) towards B. The sphere and capsule pairs
//     (sphere/sphere, sphere/capsule, capsule/capsule) put A in geoms of its
//     own (sphere_a, capsule_a; a zero-length capsule is a sphere geom) and
//     follow the same rule: from A towards B.
//     The direction is MPR's (the direction of the portal point nearest
//     the origin, MPR's ray starting from the difference of the geoms'
//     centres), then mjc_fixNormal replaces it by an analytic one where it
//     can: for a sphere, the direction from its centre to the contact
//     point; for a capsule, from its segment; for a cylinder, radial, only
//     when the contact point lies within 95% of the half length from the
//     middle AND the cap's plane is not 4x nearer than the curved side;
//     when both geoms are processed, the normalized difference of the two.
//     Not a minimal-translation direction in general. A defect follows
//     (tests: DeepCapContactOnTheAxisGetsAFortyFiveDegreeNormal): the
//     contact point is the middle of the overlap, so a contact 0.5 deep
//     into a unit cylinder's cap puts it 0.25 inside the cap, which the
//     test above takes for the curved side; on the axis the radial
//     direction is zero, mju_normalize3 makes it the local x axis, and
//     the averaged normal is 45 degrees off (unit cylinder z in [-1, 1],
//     sphere (0, 0, 1.5) radius 1: depth 0.5, right; normal (0, 1, 1)/sqrt 2
//     in the adapter's frame instead of (0, 0, 1)).
//   Depth: mjContact.dist, "distance between nearest points; neg:
//     penetration"; for mjc_Convex dist = margin - depth = -depth (margin
//     0), depth being libccd's MPR depth: the distance from the origin to
//     the final portal, refined until it improves by less than
//     mpr_tolerance = 1e-6 (ABSOLUTE, in units of length) or after 50
//     iterations. The adapter reports depth = -dist > 0. MuJoCo calls it
//     the penetration (claimed below as the penetration depth); MPR's depth
//     is in general not the minimal translation.
//   Point: mjContact.pos, "position of contact point: midpoint between
//     geoms": libccd's barycentric point of the final portal, the mean of
//     the two geoms' support points.
//   Touching: libccd's MPR reports a touching contact with depth 0 and a
//     zero direction, which mjc_Convex drops ("contact is found but normal
//     is undefined"): exact touching is no contact (a sphere of radius 1
//     at z = 2 on the unit cylinder's cap: none).
//   Margins: 0 (geom margin and gap 0, the pair function given margin 0).
//     With a margin MuJoCo would grow each geom's support by margin/2 and
//     report contacts up to that distance; none here.
//   Tolerances and limits: MPR's refinement stops at 1e-6 absolute (depth
//     from below to about that); libccd's zero tests (CCD_EPS, DBL_EPSILON)
//     and MuJoCo's mjMINVAL = 1e-15 (the cylinder's support treats a
//     direction within 1e-15 of the axis as the axis; mju_normalize3 of a
//     vector shorter than 1e-15 gives (1, 0, 0)) are absolute too, so very
//     small or very large scenes are answered with errors not relative to
//     their scale (tests: MprToleranceIsAbsoluteSoTinyScenesGetCoarseContacts:
//     the unit scene scaled by 1e-6, a sphere 0.2 deep into the cap, gets
//     depth 0.908 and a normal 19 degrees off; scaled by 1e3, 0.2 and +z).
//     libccd 2.1's MPR portal discovery and refinement loops have no
//     iteration cap (only the penetration phase stops after 50; see
//     peers/fcl/include/geomcheck/peers/fcl_adapter.hpp): seen here on
//     two segments (a cylinder and a capsule of radius 0, which MuJoCo's
//     compiler would refuse) 1.9e5 long, which never return; verify()
//     contains it ("subject-hung").
//   Cast: mju_rayGeom returns the distance to the NEAREST SURFACE crossing
//     at x >= 0 (mj_ray: "Return distance (x) to nearest surface"): a ray
//     starting inside returns its exit. The adapter asks again the other
//     way (-dir from a): in a convex solid both rays meet the surface, a
//     start outside meets it on one side at most; both: starts_inside,
//     t = 0, point a, zero normal. Caps are hit within the closed disk
//     (p0^2 + p1^2 <= r^2); the curved side needs a discriminant of at
//     least mjMINVAL (1e-15, in squared units of length with a unit
//     direction), so a ray grazing the side is a miss, and at small scales
//     not only a grazing one (tests: RayDiscriminantThresholdIsAbsolute: a
//     ray 0.999 r off the axis of a cylinder of radius 1e-9 misses). The cap
//     test and the side's slab test (|z| <= h) can both reject a hit at the
//     rim by one rounding (tests: RayMissesARimHitThroughRounding, found by
//     verify()): the gap of Ericson's printed test that
//     cast_segment_cylinder.hpp describes. mju_rayGeom returns
//     no normal: the adapter takes the outward normal of the surface
//     (cap plane or curved side) nearer to the engine's hit point a + x
//     dir. point = S(t) = a + t (b - a).
//
// Claims (what the engine promises; judged by judge(), checks.hpp)
//   collide: exact_verdict false (floating point, MPR's tolerance);
//     depth Penetration (MuJoCo documents dist < 0 as the penetration);
//     point_in_both true (MuJoCo documents pos as the midpoint between the
//     geoms); touching_is_contact false (above); margin 0.
//   cast: exact_verdict false; depth None; point on the cylinder's surface
//     (point_in_both true); touching_is_contact false (a grazing ray
//     misses); margin 0.
//
// Threads: one model and data copy per thread (thread_local); the base
// model is compiled once. MuJoCo's error and warning handlers are left as
// they are (none of the functions called here raises them on finite input).
#pragma once

#include "geomcheck/peers/peer.hpp"

/// peer_mujoco<Q>(): MuJoCo's subject of query Q (null where MuJoCo cannot
/// express Q), its `expresses` and "MuJoCo 2.2.2"; defined for every
/// registered query in src/mujoco_peer.cpp.
GEOMCHECK_DECLARE_PEER(mujoco)
