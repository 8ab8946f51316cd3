// geomcheck — ODE (Open Dynamics Engine 0.16, Debian's libode-dev 0.16.2)
// as a peer subject: its answers to the registered queries it can express,
// held to the same truth and properties as production's (peer.hpp), under
// claims that say what ODE promises.
//
// Nothing here names an ODE type; src/ode.cpp includes <ode/ode.h>. The
// statements below were checked on hand cases (tests/test_peer_ode.cpp) and
// on the installed library; where a statement is an observation rather than
// ODE's documentation it says so.
//
// ---------------------------------------------------------------------------
// The engine
//   Debian's build: dReal is double (ode.pc: precision=dDOUBLE, precision.h
//   defines dDOUBLE; the adapter static_asserts it). dGetConfiguration()
//   says "ODE ODE_EXT_trimesh ODE_EXT_opcode ODE_OPC_new_collider
//   ODE_EXT_threading ODE_THR_builtin_impl ODE_double_precision": no
//   ODE_EXT_no_debug, so ODE's internal assertions are live, and trimeshes
//   are OPCODE's. libode.so.8 links the system libccd (libccd.so.2,
//   CCD_DOUBLE). dInitODE2(0) is called once (a function-local static),
//   dAllocateODEDataForThread(dAllocateMaskAll) once per calling thread.
//   Every call builds its geoms afresh (no space, no body) and destroys them
//   after dCollide: no state is kept between calls.
//
// The colliders dCollide dispatches to (observed for sphere, capsule, box
// and cylinder: dCollide's contacts are bit for bit those of the named
// collider, called directly, on an oblique hand case, and the libccd
// alternative dCollideBoxCylinderCCD differs; the trimesh and ray colliders
// are the library's only ones for those pairs):
//   cylinder/sphere    dCollideCylinderSphere      native closed form
//   cylinder/capsule   dCollideCapsuleCylinder     libccd MPR (ccdMPRPenetration)
//   cylinder/box       dCollideCylinderBox         native: separating axes and
//                                                  clipping (NOT the libccd
//                                                  dCollideBoxCylinderCCD, which
//                                                  the library also holds)
//   cylinder/triangle  dCollideCylinderTrimesh     native: separating axes per
//                                                  triangle, OPCODE for culling
//   cylinder/cylinder  dCollideCylinderCylinder    libccd MPR, plus a contact
//                                                  ring for (nearly) parallel
//                                                  axes (8 rim points, coaxial)
//   segment cast       dCollideRayCylinder         native (a ray of length |b - a|)
//   sphere/sphere      dCollideSphereSphere        native closed form
//   sphere/capsule     dCollideCapsuleSphere       native closed form (dCollide
//                                                  swaps the arguments)
//   capsule/capsule    dCollideCapsuleCapsule      native closed form, two
//                                                  contacts for parallel segments
//   (these three named from ODE's collider table, not observed bit for bit)
// ODE has no continuous collision and no sweep: sweep_sphere_cylinder is
// not expressed (null subject).
//
// ---------------------------------------------------------------------------
// Conversion of the shapes (every value rounds once or twice: ODE answers for
// shapes within a few ulps of geomcheck's, never exactly them):
//   Cylinder{p, q, r} -> dCreateCylinder(radius r, length L = |q - p|)
//     (ODE's cylinder is centred on its position, axis its local z, length
//     the FULL length between the caps), at (p + q)/2 (computed p/2 + q/2)
//     with the rotation whose columns are (e1, e2, u): u = (q - p)/L, e1 =
//     any_perpendicular(u), e2 = u x e1. L and u are computed after dividing
//     q - p by its largest component (no overflow or underflow of the
//     squares). r == 0 is passed as is (ODE accepts it: the segment pq).
//   Sphere{c, r} -> dCreateSphere(r) at c (r == 0 accepted: a point).
//   Capsule{p, q, r} -> dCreateCapsule(radius r, length L = |q - p|) (ODE's
//     capsule: axis local z, length that of its segment, caps excluded),
//     placed and rotated as the cylinder; p == q: length 0, identity
//     rotation (a ball; ODE accepts it).
//   Obb{c, axes, e} -> dCreateBox(2 e0, 2 e1, 2 e2) (ODE takes FULL side
//     lengths; doubling is exact) at c, the rotation's columns the axes; a
//     left-handed frame gets axes[2] negated (the same set). Refused (not
//     expressed): axes not orthonormal to 1e-12 (|a_i.a_j - delta_ij| <=
//     1e-12; ODE takes the matrix as a rotation and would answer for
//     another box), and a zero or subnormal extent (below DBL_MIN): ODE's
//     box collider then trips its own assertion `!bSafeNormalize3Fault` in
//     dxNormalize3 (sides 1 x 1 x 0, 1 x 0 x 0, 1e-320 x 1 x 1, ...).
//     Other tiny extents are asked; some still trip it (a cube of half
//     extent 5e-301; 1e-200 x 1e-200 x 1 does not): that is the engine's
//     failure (see "Errors").
//   Triangle{a, b, c} -> a trimesh (dGeomTriMeshDataBuildDouble, OPCODE) of
//     TWO faces, (a, b, c) and (a, c, b), at the identity pose. ODE's
//     trimesh is one-sided: a single face (a, b, c) reports no contact with
//     a cylinder whose centre is behind it (on the side its normal
//     (b - a) x (c - a) points away from): a triangle at z = 0.75 across
//     the cylinder z in [-1, 1], r = 1 gives 8 contacts of depth 0.25 wound
//     clockwise seen from above and none wound counter-clockwise. Both
//     windings make geomcheck's closed, two-sided triangle; the deepest
//     contact of either face is taken. Refused: a degenerate triangle
//     ((b - a) x (c - a) zero or not finite), which has no face for ODE:
//     a point or segment triangle through the cylinder is silently "no
//     contact".
//   Segment{a, b} -> dCreateRay(length L = |b - a|), dGeomRaySet(a, unit
//     direction (b - a)/L) (normalised by the adapter as the cylinder's
//     axis). Refused: a == b (a ray has no direction).
//   The cylinders of the pairs ODE answers with libccd (cylinder/capsule:
//     the cylinder; cylinder/cylinder: both): refused when shorter than
//     2^-51 (absolute): ODE's ccdGeomToCyl stops with its FATAL error
//     "Invalid cylinder has been passed in ccdGeomToCyl()" (dError; abort
//     without a handler) when half the length is below DBL_EPSILON,
//     whatever the radius and the scene's scale. 2^-51 itself is taken.
//   Every shape: refused where a converted value is not finite (a length
//   |q - p| beyond the largest double, a side 2e that overflows). Invalid
//   input (shapes.hpp's is_valid) is not expressed either; the callables
//   answer it, and every refused case, with "no hit" without asking ODE.
//
// ---------------------------------------------------------------------------
// Collide queries (dCollide(cylinder, B, 32 contacts)):
//   ODE's convention (contact.h): "if body 1 is moved along the normal
//   vector by a distance depth (or equivalently if body 2 is moved the same
//   distance in the opposite direction) then the contact depth will be
//   reduced to zero. This means that the normal vector points 'in' to body
//   1." With the cylinder as g1, ODE's normal points from B into the
//   cylinder: a sphere of radius 1 at x = 1.5 beside the unit cylinder gets
//   (-1, 0, 0), depth 0.5, pos (0.5, 0, 0). geomcheck's normal points from
//   the cylinder towards B, so the adapter NEGATES it (and dCollide itself
//   swaps and negates for pairs registered the other way round, e.g.
//   capsule/cylinder: observed). No other change: `depth` is ODE's
//   (>= 0 documented; grazing contacts have depth 0), `point` ODE's `pos`.
//   ODE reports a contact manifold (up to 8 rim points for coaxial
//   cylinders, 4 clipped corners for a box face on a cap, one per triangle
//   point or edge for a trimesh): the adapter returns the DEEPEST contact
//   (the first of equal depths), its own normal and position.
//   `overlap` is dCollide(cylinder, B, 1 contact) > 0 (the same colliders,
//   asked for one contact).
//   Claims (the same for the five collide queries):
//     - verdict not exact (floating point; libccd's MPR stops on a
//       tolerance: its hand-case depths are 1e-8..1e-6 off; the trimesh
//       collider's 1e-8..1e-7);
//     - depth: UpperBound. ODE documents a consistent contact (the depth
//       along the normal that separates the shapes), not a minimal
//       translation; held only to not falling below the penetration depth,
//       and (consistency) to being the overlap along its normal;
//     - point not claimed in both shapes: ODE documents only a "contact
//       position" (the sphere collider returns the ball's deepest point
//       along the normal, pos (0.2, 0, -0.5) for a ball of radius 1 at
//       (0.2, 0, 0.5) inside the unit cylinder: in the cylinder there, not
//       in general; box contacts are clipped face corners);
//     - touching: a contact for cylinder/sphere (a ball touching the side
//       gives depth 0); not reliably for the others (observed misses: a box
//       face on the cap, a capsule or a parallel cylinder touching the side,
//       a triangle in the cap plane), so not claimed there;
//     - margin 0: ODE adds no collision margin (no envelope) to these geoms.
//
// The cast (cast_segment_cylinder):
//   ODE's ray is a surface query: dCollide(ray, cylinder) reports the first
//   crossing of the cylinder's SURFACE within the ray's length; `depth` is
//   the distance from the ray's start to it, `normal` the surface normal
//   oriented against the ray ("for ray reflection"; the outward normal at
//   an entry: a ray from (5, 0, 0) along -x gets pos (1, 0, 0), normal
//   (1, 0, 0), depth 4). A ray starting inside reports its EXIT with the
//   inward normal (from (0.5, 0, 0) along +x: pos (1, 0, 0), normal
//   (-1, 0, 0)), and a ray wholly inside reports nothing. geomcheck's cast is
//   against the solid, so the adapter first asks ODE whether the start lies
//   in the cylinder, by dCollide(cylinder, sphere of radius 0 at a) (the
//   native sphere collider; a start on the surface is a contact of depth
//   0); if so the answer is t = 0, starts_inside, point a, zero normal.
//   Otherwise t = depth / L (clamped to [0, 1] against the division's
//   rounding), point = pos, normal = ODE's (no flip: the ray is g1, so it is
//   the outward surface normal). Claims: verdict not exact; point claimed
//   on B (ODE's ray contact lies on the surface it hits); touching is a
//   hit (a ray tangent to the side is reported, depth to the tangent
//   point); margin 0.
//
// ---------------------------------------------------------------------------
// Observed (verify() of every expressed query, 500 targeted cases, seed
// 20261121; hand cases; the truth is the query's oracle):
//   - cylinder/box misses a box that passes THROUGH the cylinder with no
//     corner inside it: the unit cylinder (z in [-1, 1], r = 1) against the
//     plate |x| <= 0.1, |y|, |z| <= 2 gives no contact (true depth 1.1);
//     ODE's separating axes find no gap, its clipping finds no point, and
//     dCollide returns 0. The same makes verdicts non-monotone (a contact at
//     radius 2 lost at radius 4; lost when the cylinder is lengthened).
//   - cylinder/triangle misses likewise: a disc (z in [0, 0.2], r = 8)
//     against the triangle (-3, 0, -5), (3, 0, -5), (0, 0, 5) crossing it:
//     no contact (true depth 5); with r = 4 it is found. Its depths and
//     normals carry ~1e-7 errors, its contact points can lie outside the
//     cylinder (the side is an octagon: pos (-1.0824, 0, 0) for a triangle
//     across the unit cylinder at z = 0).
//   - cylinder/capsule and cylinder/cylinder (libccd's MPR) miss an
//     obvious overlap when the centres' difference lies along the
//     cylinder's axis and rounding leaves MPR's first portal degenerate:
//     kOblique = {(10, -4, 3), (12, -1, 9), 0.5} against a capsule (or a
//     cylinder) of radius 0.5 across its q cap, centre q + 0.3 u, segment
//     +-0.4 along a perpendicular: no contact (true depth 0.2); moved 0.1
//     off the axis line, or translated, it is found. MPR's depth is not
//     the overlap along its normal (as ODE's convention says it is) on
//     about a fifth of the random cases, and can fall below the
//     penetration depth (by up to 7.6e-4 * scale: a contact 3.33e-5 deep
//     reported 3.27e-5 deep).
//   - cylinder/cylinder: dCollide asked for ONE contact (overlap) can say
//     no where asked for 32 (collide) it says yes: {(0, 0, 0), (0, 0,
//     0.0117), 0.04} against {(0.027, 0, 0.012), (0.03, 0, 0.09), 0.008}
//     (overlapping by 7.5e-6): overlap no, collide depth 3.6e-5.
//   - cylinder/sphere: a ball whose centre is on the axis, the side nearer
//     than (or as near as) the caps, gets a NaN normal: the unit cylinder
//     against the ball of radius 0.5 at the origin: depth 1.5, normal
//     (nan, nan, nan). Otherwise to ~1e-13 of the truth.
//   - the ray misses through the rim: a ray entering the cylinder within
//     rounding of the rim fails both ODE's cap test and its side test
//     (9.3% of 100 000 rays through rim points of the unit cylinder, each
//     ending 0.5 inside): a = (2.2121738489444116, 0.4268160072874585, 4),
//     b = (0.7878065483895661, 0.082531809055429978, 0.5): no hit (true
//     t = 6/7). A ray crossing the axis of a cylinder of radius 0 gets a
//     NaN normal.
//   In those runs no case crashed, hung or threw with the refusals above in
//   place; before them, ODE's box assertion (1 case) and ccdGeomToCyl's
//   fatal error (8 cylinder/cylinder cases) were thrown (aborts without the
//   adapter's handlers).
//
// Errors: ODE's error and debug handlers (dSetErrorHandler,
// dSetDebugHandler; process-wide, set once) throw std::runtime_error with
// ODE's message ("ODE error 1: assertion \"...\" failed in ..."; ODE says
// these handlers must not return, and aborts if they do), so an ODE assertion
// ends the call, not the process; the geoms are destroyed on the way out.
// The callables let it propagate: verify() counts it as "subject-threw".
// ODE's informational messages (dSetMessageHandler) are dropped.
#pragma once

#include "geomcheck/peers/peer.hpp"

/// peer_ode<Q>(): ODE's subject of query Q (its claims above), the cases it
/// expresses and "ODE 0.16.2"; a null subject where ODE cannot express Q
/// (sweep_sphere_cylinder). Found from the query's entry point and shapes
/// (src/ode.cpp), so a new query needs no code here; instantiated for every
/// registered query there.
GEOMCHECK_DECLARE_PEER(ode)

namespace geomcheck::peers {

/// ODE's build configuration, as dGetConfiguration() states it (initialises
/// ODE on first use).
const char* ode_configuration();

}  // namespace geomcheck::peers
