// geomcheck — FCL (Flexible Collision Library 0.7) as an independent peer.
//
// FCL is NOT an oracle: it is a widely used engine whose answers the harness
// reports beside production and the exact oracle, so that every report also
// measures FCL. Nothing here includes FCL headers; see fcl_convert.hpp for
// the shape conversion and the pre-converted ("prepared") calls used by the
// benchmarks.
//
// ---------------------------------------------------------------------------
// Conversion (fcl_convert.hpp)
//   Cylinder{p, q, r} -> fcl::Cylinderd(radius r, lz = |q - p|) placed at
//   (p + q)/2 (computed as p/2 + q/2, which cannot overflow) with a rotation
//   taking +z to (q - p)/|q - p|, built from an orthonormal frame around the
//   axis (no special case: anti-parallel axes are as accurate as any other).
//   Sphere{c, r} -> fcl::Sphered(r) translated to c.
//   Capsule{p, q, r} -> fcl::Capsuled(radius r, lz = |q - p|) (FCL's capsule
//   is centred, axis +z, lz the length of its segment), placed and rotated
//   as the cylinder. p == q (a ball) -> fcl::Capsuled(r, 0) at p with the
//   identity rotation: still a capsule, so that one FCL algorithm answers
//   the whole cylinder/capsule query (an fcl::Sphered would switch FCL to
//   its closed-form sphere/cylinder code, measured under
//   collide_cylinder_sphere). fcl::Capsuled accepts lz = 0 and r = 0.
//   Obb{c, axes, e} -> fcl::Boxd(2 e_0, 2 e_1, 2 e_2) (FCL takes FULL side
//   lengths; doubling is exact) at c with the rotation whose columns are the
//   axes. FCL turns the matrix into a quaternion, so the frame must be a
//   rotation: a left-handed frame (det < 0) gets axes[2] negated (the same
//   set, the box being symmetric; the answers are then bit for bit those of
//   the right-handed twin), and axes that are not orthonormal to rounding
//   (obb_axes_orthonormal: |a_i.a_j - delta_ij| <= 16 * 2^-52) are refused.
//   Zero extents need no special case: FCL's box support function returns
//   the corner (+-e_0, +-e_1, +-e_2) chosen by the signs of the direction,
//   with no division, so flat boxes, segments and points have finite
//   supports and are answered like their solid neighbours (a flat box
//   0.25 into the cap: depth 0.25, normal +z; a point box 0.5 above it:
//   distance 0.5).
//   Triangle{a, b, c} -> its three vertices, unchanged (FCL's triangle
//   object is built in the world frame; only its centre, the vertex mean,
//   is computed by FCL and rounds).
//   The conversion rounds (|q - p|, the unit axis, the frame, the midpoint):
//   FCL answers for a shape within a few ulps of ours, never exactly ours.
//
// Solver: every call uses GST_LIBCCD. (GST_INDEP returns negative depths and
// can abort on FCL's asserts.) For cylinder/sphere FCL 0.7 does not run GJK
// at all: with GST_LIBCCD it dispatches to its closed-form
// sphereCylinderIntersect / sphereCylinderDistance. For cylinder/capsule it
// has no closed form: collide runs libccd's MPR (ccdMPRIntersect without
// contact, ccdMPRPenetration with), distance runs libccd's GJK
// (ccdGJKDist2), both with FCL's absolute tolerance 1e-6.
// Cylinder/box: no closed form either (GJKSolver_libccd has none for a
// cylinder); fcl::collide and fcl::distance run the same generic MPR / GJK
// on FCL's cylinder and box support functions.
// Cylinder/triangle: fcl::collide has no such pair (FCL's collision and
// distance matrices have no GEOM_TRIANGLE entries; a TriangleP against a
// cylinder is not supported). The adapter runs instead what FCL's mesh
// traversal runs for each triangle of a BVHModel against a cylinder
// (ShapeMeshCollisionTraversalNode / ShapeMeshDistanceTraversalNode):
// GJKSolver_libccd::shapeTriangleIntersect -> ShapeTriangleIntersectLibccdImpl
// (libccd's MPR on the cylinder's object and triCreateGJKObject(a, b, c):
// triGetSupportFunction returns the vertex with the largest dot product,
// triGetCenterFunction the vertex mean) and shapeTriangleDistance (libccd's
// GJK on the same objects), with the solver's tolerances as fcl::collide /
// fcl::distance set them before a traversal: 1e-6 (the solver's own
// default collision_tolerance, eps^(7/8) ~ 2e-14, is overwritten there).
//
// ---------------------------------------------------------------------------
// Normal convention (checked empirically, see tests/test_fcl_adapter.cpp):
//   fcl::collide(cylinder, sphere) returns Contact::normal pointing from o1
//   (the cylinder) towards o2 (the sphere), as FCL's contact.h documents.
//   A sphere above the top cap (+z) gives normal (0, 0, +1); with the
//   arguments swapped it gives (0, 0, -1). This is geomcheck's convention
//   (from A towards B), so no flip is applied. `depth` is FCL's
//   penetration_depth; `point` is FCL's contact position: the middle of the
//   overlap along the normal (for a centre outside the cylinder, the closest
//   cylinder point moved depth/2 into the cylinder: sphere at z = 1.8, r = 1,
//   above a cap at z = 1 gives z = 0.9), NOT production's closest point.
//   Centre inside the cylinder: FCL exits through the nearer cap unless the
//   side is nearer by more than 16 eps; a centre on the axis, nearer the
//   side, gets the cylinder frame's +x axis (column 0 of
//   fcl_rotation_z_to, i.e. any_perpendicular of the axis).
//
//   fcl::collide(cylinder, capsule): libccd documents MPR's direction as
//   pointing from object 1 to object 2, and so it is: from the cylinder
//   towards the capsule (a capsule over the top cap gives (0, 0, +1), under
//   the bottom cap (0, 0, -1), beside the side the outward radial), no flip.
//   With the arguments swapped the shallow normals flip; deep ones need not
//   (MPR searches from the difference of the centres, which changes too).
//   What the contact means (MPR, not a minimal translation):
//     - depth: the distance from the origin to the face of the Minkowski
//       difference that MPR's ray (from the difference of the centres
//       through the origin) reaches, refined to the tolerance. In
//       symmetric hand cases it is the true depth within 1e-6 (from below);
//       in general it is NOT the penetration depth: on 20 000 random
//       cylinder/capsule pairs (the benchmark's generator: 3 037
//       overlapping), against the certified engine (oracles/engine.hpp):
//       FCL depth - true depth in [-9e-7, 1.59], median 4.9e-3 for the
//       shallow contacts (the capsule's segment outside the cylinder) and
//       0.11 for the deep ones. It is not the overlap along FCL's normal
//       either: always less, by up to 0.60 (median 0.022), so translating
//       the capsule by depth * normal does NOT separate the shapes.
//       Deep and centred it can be far off: a capsule of radius 0.2 through
//       the cylinder z in [-1, 1], r = 1 along x gets 4.2 (along x; true
//       1.2), because coinciding centres make libccd nudge its ray to +x.
//     - normal: the direction of that closest portal point; |normal -
//       true minimal-translation direction| median 0.24 on the shallow
//       random contacts, about 3e-4 off radial in the side hand case.
//     - point: libccd's barycentric point of the final portal (world
//       frame), roughly inside the overlap; not production's point.
//     - touching: exact touching is "no hit" (an overlap must exceed about
//       1e-7..1e-9 absolute to be seen); verdicts otherwise agreed with the
//       certified engine on all 20 000 random pairs. When MPR's depth is
//       below CCD_EPS (2.2e-16, absolute) libccd sets no direction: the
//       adapter reports hit with that depth and a ZERO normal (ok).
//   About 2-2.5 us per collide on random poses, 3.3-4.5 us on pairs in
//   contact, 0.6-1 us per overlap (enable_contact = false)
//   (bench_collide_cylinder_capsule, Release, shared two-core machine).
//
//   fcl::collide(cylinder, box) and shapeTriangleIntersect(cylinder,
//   triangle): the same MPR, the same direction, from the cylinder towards
//   B, no flip: a box (a triangle) reaching 0.25 into the top cap gives
//   (0, 0, +1), under the bottom cap (0, 0, -1), beside the side the outward
//   radial (within 1e-7 for a box face or a triangle vertex, 6e-4 for a
//   triangle edge parallel to the axis). FCL itself keeps this direction
//   for (shape, mesh) contacts and negates it for (mesh, shape). There are
//   no swapped-argument wrappers; FCL's
//   collide(box, cylinder) gives (0, 0, -1) for the box over the cap. The
//   contact means what it means for the capsule (MPR's ray, not the minimal
//   translation). Measured against the certified engine on 20 000 random
//   pairs each (the shapes of bench_engine's random set, without its
//   half-overlapping selection: cylinder length 0.5..1.5, radius 0.2..0.6;
//   box half extents 0.2..0.6, random rotation; triangle vertices 0.7 from
//   a centre; centres in [-2, 2]^3):
//     - verdicts (overlap, collide's hit, distance < 0) agreed with the
//       engine on every pair (1 194 box and 484 triangle overlaps); also on
//       20 000 each of degenerate triangles (a == b == c; a == c; c rounded
//       onto ab);
//     - depth: FCL - true penetration depth in [-8.8e-7, 0.49], median
//       1.6e-4 (box), [-8.8e-7, 0.54], median 1.8e-3 (triangle); |normal -
//       true direction| median 0.066 (box), 0.21 (triangle), up to 1.41;
//       the overlap along FCL's normal exceeds FCL's depth by up to 0.33
//       (median 8e-5 box, 2.6e-3 triangle; never less, beyond 1.5e-14), so
//       translating B by depth * normal does NOT separate the shapes. Deep:
//       a box [-2, 2]^3 holding the cylinder z in [-1, 1], r = 1 gets 4.12
//       along a diagonal (true 3); a triangle through the whole cylinder
//       6 (true 1).
//     - touching (exact touching, small integer and half coordinates,
//       certified by the engine): about half are hits (box 165 of 300,
//       triangle 78 of 189). Flat contacts on a cap (a box face, a triangle
//       vertex or face) tend to be hits: MPR finds the origin on its portal
//       and reports a rounding-sized depth (below 4e-16 in the hand cases)
//       with a ZERO normal when below CCD_EPS, otherwise a unit normal that
//       means nothing (a box face on the cap: (-0.8, 0.6, 0)). Contacts
//       with the curved side tend to be "no hit" (a box face tangent to the
//       side; a triangle vertex on it; but a point triangle on the side is
//       a hit of depth 2.7e-14, normal about (0, 1, 0)). Hand thresholds: a box 1e-12 into the cap is seen,
//       1e-12 above it is not; a box face 1e-9 into the side is missed,
//       1e-7 is seen; a triangle vertex 1e-12 into the cap or the side is
//       seen. Off touching, overlap's verdicts were all right in these
//       batches (20 000 scenes of small integer, half and random
//       coordinates of size ~1; distance: see below).
//       When both shapes are lower-dimensional (r = 0 against a point or
//       segment box or triangle) MPR's depth is the extent along its ray:
//       a point on an r = 0 cylinder's axis is touching, FCL answers depth
//       1.41 there; such pairs are also where the guard most often reports
//       a non-finite support.
//   About 0.7-1 us per overlap, 7-8 us per collide on pairs in contact,
//   3.5-4.5 us per distance (median, guarded calls, RelWithDebInfo, shared
//   two-core machine).
//
//
//   fcl::collide(cylinder, cylinder): FCL 0.7's GJKSolver_libccd has no
//   closed form for two cylinders either; collide runs the same MPR on the
//   two cylinders' support functions (the adapter's guarded call, as for
//   the capsule), the direction from the first cylinder towards the second,
//   no flip; distance runs libccd's GJK. The contact means what it means
//   for the capsule (MPR's ray, not the minimal translation); production's
//   contact is no minimal translation either (an overlap along one of a few
//   candidate directions, see collide_cylinder_cylinder.hpp), and the
//   campaign scores both against the certified penetration depth.
//
// ---------------------------------------------------------------------------
// Distance:
//   fcl::distance with enable_nearest_points and GST_LIBCCD. When the shapes
//   are separated, `distance` > 0 and p_a (on the cylinder), p_b (on the
//   sphere) are world-frame nearest points. When they touch or overlap FCL
//   does not compute a signed distance for this pair: it returns exactly -1
//   and leaves the nearest points zero. The adapter passes that through
//   unchanged (ok = true, distance = -1): read `distance < 0` as "FCL says
//   overlapping or touching", never as a penetration depth.
//   Cylinder/capsule: the same convention (libccd's GJK: exactly -1 and
//   zero points as soon as its GJK finds the origin in the difference;
//   enable_signed_distance is not set). Separated: GJK stops on a 1e-6
//   improvement, from above: on the 16 963 separated random pairs FCL
//   distance - true distance in [1.6e-12, 0.138], median 4.7e-7, 99th
//   percentile 3.2e-5. A touching pair can get a rounding-sized positive
//   distance (while collide says no hit), or no answer at all (see
//   "Guarded support functions": FCL as shipped aborts on some). -1 also
//   comes back, undistinguishable, when GJK's distance phase runs out of
//   its 1 000 iterations. The verdicts (distance < 0 versus overlapping)
//   agreed with the engine on all 20 000 random pairs.
//   Cylinder/box and cylinder/triangle (shapeTriangleDistance): the same
//   convention. On the random pairs above, FCL distance - true distance in
//   [-1.3e-15, 6.9e-3], median 1.6e-7, 99th percentile 1.3e-5 (box, 18 806
//   separated) and [-1.0e-15, 0.10], median 1.9e-7, 99th percentile 1.25e-5
//   (triangle, 19 516). Hand cases 0.25 above the cap or beside the side:
//   0.25 within 1e-6. Touching: more often -1 than collide's hit (box 225
//   of 300, triangle 121 of 189): a box face on the cap or tangent to the
//   side gets -1, an edge on the rim a positive 1.9e-13. One overlapping
//   pair of small integer coordinates (a segment box piercing a cap
//   centre) got a positive 3e-16.
//
// ---------------------------------------------------------------------------
// Guarded support functions (cylinder/capsule, cylinder/box,
// cylinder/triangle): what keeps the harness from hanging or aborting. Two
// defects of FCL 0.7 / libccd 2.1, both found here:
//   1. HANG. libccd's MPR portal discovery and refinement loops have no
//      iteration cap (only the penetration phase stops after
//      max_collision_iterations = 500), and in floating point the refinement
//      can cycle for ever: it does on elongated scenes (3 of 2 000 random
//      scenes with a cylinder 2^0..2^20 long, e.g. 2^18 long and 1.2 wide;
//      31 of 2 000 with lengths and offsets 2^20..2^50). fcl::collide, with
//      or without contact, then never returns.
//   2. ABORT. FCL's capsule support function normalises the search
//      direction. GJK (distance) starts from minus its first Minkowski
//      support point, which is exactly zero when the support points of the
//      two shapes along +x coincide: a vertical capsule (1.5, 0, 0) ->
//      (1.5, 0, 2) of radius 0.5 touching the side of the cylinder z in
//      [-1, 1], r = 1, or a ball (p == q) touching it. The support point is
//      then NaN and FCL's assert "A is not in region 1" (gjk_libccd-inl.h)
//      aborts the process. The same happens when the Minkowski points round
//      to zero far from the origin (offset 1e17, shapes of size 1), when
//      directions underflow (subnormal scenes) and when GJK's products of
//      squared lengths overflow (sizes beyond about 2^250).
//   The box and the triangle show both. HANG: on elongated scenes
//   (cylinders 2^0..2^50 long, the box or the triangle near a point of the
//   axis) fcl::collide(cylinder, box) and shapeTriangleIntersect did not
//   return in 10 of 12 batches of 2 000; the adapter's budget stopped 0-3
//   scenes per batch (e.g. a cylinder 2^48 long of radius 1.0). ABORT:
//   fcl::distance(cylinder, box) and shapeTriangleDistance abort on the same
//   assert in subnormal scenes (every batch of 2 000 with scales
//   2^-1070..2^430 and offsets to 2^1000 aborted); at ordinary scales a
//   triangle vertex (or a point or collinear triangle) touching the side
//   where both shapes' supports along +x coincide (the vertex (1, 0, 0) on
//   the cylinder z in [-1, 1], r = 1) gives NaN nearest points and distance
//   0 instead (refused as well).
//   The adapter therefore makes FCL's own calls (GJKSolver_libccd's
//   ShapeIntersectLibccdImpl / ShapeDistanceLibccdImpl, for the triangle
//   ShapeTriangleIntersectLibccdImpl / ShapeTriangleDistanceLibccdImpl:
//   GJKCollide / GJKDistance on the libccd objects FCL builds, with FCL's
//   centre functions, iteration caps and tolerances) with FCL's support
//   functions wrapped:
//     - a budget of 20 000 support evaluations (a returning MPR call uses at
//       most about 1 040, GJK's distance at most about 4 000 by its
//       iteration caps); past it every
//       support point lies 2e300 behind the search direction, which ends
//       every MPR loop: ok = false, "FCL did not terminate (libccd MPR
//       exceeded its support budget)", after about 3 ms;
//     - a non-finite support point is replaced by the origin (with finite
//       points GJK's first step keeps the assert true: its test
//       A.(-B) >= 0 and the assert A.B <= |B|^2 eps round alike): ok =
//       false, "FCL's support function returned a non-finite point ...";
//       so is the support along a non-finite direction, without asking
//       FCL (the box's support turns NaN into a finite corner, the
//       triangle's leaves its output unset; the cylinder's and the
//       capsule's return NaN there anyway), and a support function that
//       leaves its output unset is seen as non-finite;
//     - distance refuses a relative size (offsets from the cylinder's p,
//       axis, radii, the box's extents) above 2^250: ok = false, "outside
//       FCL's range".
//   Otherwise the answer is bit for bit fcl::collide's / fcl::distance's
//   (for the triangle shapeTriangleIntersect's / shapeTriangleDistance's;
//   tests GuardedCallsAreFcls). 1.8 million adversarial scenes (small
//   integer and half coordinates, exact touching, p == q, r = 0, scales
//   2^-400..2^200, offsets to 2^300) ran without a hang or an abort, where
//   fcl::distance as shipped aborted in every batch of 2 000. For the box
//   and the triangle, 1.8 million guarded calls (collide, overlap,
//   distance; small integer and half coordinates, flat and point boxes,
//   degenerate triangles, r = 0, scales 2^-1070..2^430, offsets to 2^1000,
//   cylinders to 2^50 long) all returned, the slowest in 5 ms; 3.6% were
//   not ok: outside the range or non-finite in the scaled and offset
//   scenes, and 674 of 600 000 calls on cylinders 2^0..2^50 long (584
//   budget stops, 90 non-finite). The prepared
//   calls (fcl_convert.hpp) are FCL as shipped, unguarded, for the
//   benchmarks only.
//
// ---------------------------------------------------------------------------
// Cast (segment against cylinder): what FCL can and cannot answer.
//   FCL 0.7 has no ray or segment query returning a first-hit parameter.
//   What it has is continuous collision. fcl_cast runs
//   fcl::continuousCollide of an fcl::Sphered of radius 0 translated from a
//   to b (CCDM_TRANS, CCDC_CONSERVATIVE_ADVANCEMENT, GST_LIBCCD) against the
//   resting cylinder: hit = is_collide, t = time_of_contact. For this pair
//   every step uses the closed-form sphere/cylinder distance, so it is
//   scale-free, assert-free and bounded (each step advances t by at least
//   FCL's t_err = 1e-4, or stops). No contact point or normal comes back.
//
//   Measured against production's cast, 20 000 random segments against the
//   cylinder z in [-1, 1], r = 1 (A) and 20 000 against random cylinders
//   (B), Release build:
//     - t is early, never late (beyond 1e-13 rounding): FCL stops when a step
//       falls under t_err = 1e-4. |t - t_production| max 1.0e-4, mean
//       7.9e-6 (A) / 7.2e-6 (B). On the axis-parallel segment
//       (0.3,0.2,5)->(0.3,0.2,-5) the first step lands exactly: t = 0.4.
//     - by the same stopping rule, a segment that ends or passes within
//       about 1e-4 |b - a| of the surface can be reported as a hit (none in
//       the random sets).
//     - FCL DEFECT: asked once, FCL misses real hits: 203 of 20 000 (A) and
//       207 of 20 000 (B), 3% and 5.5% of the hits; never a false hit. Two
//       mechanisms, both when an advancement step lands the point on the
//       surface: (1) sphereCylinderDistance returns -1 and leaves the
//       nearest points zero, so the motion bound is (b - a).(0,0,0) + 0,
//       which is -0 when every component of b - a is negative, and the next
//       step is -1/-0 = +inf; (2) the distance is a rounding-sized positive
//       number while both nearest points round to the same point, so the
//       direction is zero, the bound 0 <= distance, and FCL concludes the
//       point is not approaching. Either way FCL jumps past t = 1 and
//       reports no collision.
//       kConservativeAdvancement (default) therefore asks again after a
//       miss, in up to three exactly equivalent frames (the scene negated,
//       and/or its coordinates cyclically permuted: no rounding in the
//       re-expression, different rounding in FCL's steps), and takes the
//       first hit. Misses drop to 0 of 20 000 (A) and 8 of 20 000 (B,
//       0.2% of the hits). kConservativeAdvancementOnce is the single
//       raw call, for measuring FCL as shipped.
//     - ~2 us per FCL call: a hit ~2 us, a miss up to 4 calls (~8 us).
//
//   Considered and rejected:
//     - a radius-0 fcl::Capsuled for the segment, hit/miss by fcl::collide
//       (libccd's MPR) and t by bisection on it: accurate for ordinary
//       scenes (hit/miss agreed 40 000/40 000, |dt| <= 9e-6, but the MPR
//       tolerance is absolute, 1e-6, so small scenes are wrong), but
//       libccd's MPR portal refinement has no iteration cap and HANGS on
//       elongated or far-from-origin scenes: in random scenes with
//       max|coordinate| / r between 2^10 and 2^20 it did not return in 3 of
//       904 cases, above 2^40 in about 1 case in 9 (e.g. the segment
//       p -> q along the axis of a cylinder of length about 2^29 and
//       radius 0.64). A harness that must never hang cannot call it.
//     - CCDC_NAIVE only samples N poses (t quantised to 1/(N-1): 0.4004
//       for 0.4 with N = 1000) and misses crossings thinner than a step.
//     - GST_INDEP: runs EPA, which can abort on FCL's asserts.
//
// ---------------------------------------------------------------------------
// Sweep (sphere moving against a cylinder): what FCL can and cannot answer.
//   fcl_sweep is fcl_cast with a radius: fcl::continuousCollide of an
//   fcl::Sphered(r) translated from c to c + delta (the end rounded once,
//   then FCL's own interpolation) against the resting cylinder, same
//   request, same closed-form sphere/cylinder distance in every step, same
//   range refusal (the radius counts), same re-asking in equivalent frames
//   after a miss (FclCastMethod).
//   It answers hit and t only. It cannot express:
//     - the contact point and the cylinder's normal there (none come back);
//     - "starts inside": a ball meeting the cylinder at t = 0, touching
//       included, is a hit at t = 0 whatever the motion, so t = 0 cannot be
//       told from a first touch exactly at the start;
//     - an exact t: conservative advancement stops when a step falls under
//       t_err = 1e-4, so t is early by up to 1e-4 and a sweep passing
//       within about 1e-4 |delta| of the cylinder can be reported as a hit.
//   Measured against the certified engine (time_of_impact of the ball),
//   20 000 random sweeps (the cast benchmark's generator, radius 0.05 to
//   1.5; 4 941 hits): never late (FCL t - true t <= 5.2e-15), early by at
//   most 9.98e-5 (mean 1.1e-5); no false hit; missed hits 5 (0.1% of the
//   hits) by default, 92 (1.9%) asked once (kConservativeAdvancementOnce),
//   by the two mechanisms of the cast. Hand cases whose first step lands on
//   the contact are exact: down onto a cap (t = 0.35), at a rim point along
//   the diagonal (t = (2 sqrt 2 - 0.5) / (4 sqrt 2)).
//   About 2-3.5 us per FCL call (bench_sweep_sphere_cylinder, Release,
//   shared two-core machine); a miss asked again costs up to 4 calls.
//
// ---------------------------------------------------------------------------
// Validity and safety:
//   * Shapes failing is_valid (shapes.hpp) are never passed to FCL: the call
//     returns ok = false, error = "invalid input" (fcl_overlap: false).
//     Valid boxes whose axes are not orthonormal to rounding
//     (obb_axes_orthonormal) are refused next: "box axes not orthonormal".
//     Degenerate triangles (collinear or coincident vertices) are valid and
//     are passed: FCL answers them as their segment or point (see above;
//     no crash, no NaN at ordinary scales beyond the zero-direction case
//     of "Guarded support functions").
//   * FCL's Debian build keeps its asserts. Every path used here is free of
//     them and of unbounded loops for valid input: sphere/cylinder collide
//     and distance are closed form, the cast and the sweep are conservative
//     advancement on that closed-form distance; cylinder/capsule, /box and
//     /triangle collide, overlap (libccd's MPR) and distance (libccd's GJK,
//     iteration caps) run with guarded support functions (see above). No
//     EPA runs.
//   * Range. collide/overlap, and distance against a sphere, accept every
//     valid input; overflow inside FCL (relative offsets or radii beyond
//     ~1e154, whose squares overflow) shows up as a non-finite output and
//     is reported as ok = false. Distance against a capsule, a box or a
//     triangle refuses a relative size above 2^250 (see "Guarded support
//     functions"). The cast
//     and the sweep refuse (ok = false, error = "outside FCL's range") a
//     cylinder radius, axis, ball radius or start/end-to-cylinder offset
//     above 2^500 (~3e150) in any coordinate: FCL's bounding-volume fit for
//     continuous collision squares them, overflows, prints "eigen: too many
//     iterations in Jacobi transform." on stderr and answers garbage.
//   * Every FCL exception is caught and reported in `error`.
//   * "Garbage" (ok = false, fields still hold FCL's converted output):
//     non-finite numbers, a contact normal whose length is off 1 by more
//     than 1e-6, a negative depth, a collision with no contact, a time of
//     contact outside [0, 1].
#pragma once

#include <cmath>
#include <string>
#include <type_traits>

#include "geomcheck/shapes.hpp"
#include "geomcheck/vec3.hpp"

namespace geomcheck::peers {

/// FCL's contact for a pair (A, B), in geomcheck's convention (normal from
/// A towards B).
struct PeerContact {
  bool ok = false;    ///< false if the input was invalid, FCL threw or returned garbage
  std::string error;  ///< why not ok; empty when ok
  bool hit = false;   ///< FCL says the shapes intersect (touching: sphere yes, capsule no, box/triangle either)
  Vec3 point;         ///< FCL's contact position (world frame)
  Vec3 normal;        ///< unit, from A towards B (MPR pairs: zero for its touching contact)
  double depth = 0;   ///< FCL's penetration depth
};

/// FCL's separation distance for a pair (A, B).
struct PeerDistance {
  bool ok = false;    ///< false if the input was invalid, FCL threw or returned garbage
  std::string error;  ///< why not ok; empty when ok
  double distance = 0;  ///< > 0 separated; exactly -1 when FCL sees overlap/touching
  Vec3 p_a;           ///< nearest point on A (zero when distance < 0)
  Vec3 p_b;           ///< nearest point on B (zero when distance < 0)
};

/// FCL's answer to a segment cast or a sphere sweep.
struct PeerCast {
  bool ok = false;         ///< false if the input was invalid, FCL threw or returned garbage
  std::string error;       ///< why not ok; empty when ok
  bool supported = false;  ///< FCL can express this query (kFclCasts)
  bool hit = false;        ///< FCL says the segment (the ball) touches the resting shape
  double t = 0;            ///< first-touch parameter in [0, 1] when hit: FCL's time of contact
};

/// How fcl_cast and fcl_sweep ask FCL (see the header notes).
enum class FclCastMethod {
  kConservativeAdvancement,      ///< continuousCollide; after a miss, again in up to 3 equivalent frames
  kConservativeAdvancementOnce,  ///< one continuousCollide call on the scene as given (FCL as shipped)
};

/// True when the box's stored axes are orthonormal to rounding:
/// |axes_i . axes_j - delta_ij| <= 16 * 2^-52 for every i, j (false for
/// non-finite axes). Either handedness. FCL takes the box's frame for a
/// rotation, so the adapter refuses boxes outside this contract.
inline bool obb_axes_orthonormal(const Obb& b) {
  constexpr double kTol = 16 * 0x1p-52;
  for (int i = 0; i < 3; ++i) {
    for (int j = i; j < 3; ++j) {
      const double d = dot(b.axes[i], b.axes[j]) - (i == j ? 1.0 : 0.0);
      if (!(std::fabs(d) <= kTol)) return false;  // NaN too
    }
  }
  return true;
}

/// Whether s is one of the shapes FCL is asked about as a solid (fcl::Sphered,
/// Capsuled, Boxd, Cylinderd; fcl_convert.hpp): the first shape of every
/// pair, and the second of every pair but the triangle's.
/// The list: X(S) for each solid (the adapter's explicit instantiations and
/// kFclSolid follow from it).
#define GEOMCHECK_FCL_SOLIDS(X) X(Sphere) X(Capsule) X(Obb) X(Cylinder)
/// The shapes a solid A is asked against (the solids again, and the
/// triangle), and from the two lists every pair the adapter asks FCL about
/// (kFclAsks): GEOMCHECK_FCL_PAIRS expands to GEOMCHECK_FCL_PAIR(A, B) for
/// each, a macro its user defines first (the explicit instantiations;
/// fcl_pairs.cpp checks each pair is kFclAsks). A new solid is its name in
/// both lists.
#define GEOMCHECK_FCL_SECONDS(A)                                                                       \
  GEOMCHECK_FCL_PAIR(A, Sphere) GEOMCHECK_FCL_PAIR(A, Capsule) GEOMCHECK_FCL_PAIR(A, Obb)                \
  GEOMCHECK_FCL_PAIR(A, Cylinder) GEOMCHECK_FCL_PAIR(A, Triangle)
#define GEOMCHECK_FCL_PAIRS GEOMCHECK_FCL_SOLIDS(GEOMCHECK_FCL_SECONDS)
#define GEOMCHECK_FCL_IS(T) || std::is_same_v<S, T>
template <class S>
inline constexpr bool kFclSolid = false GEOMCHECK_FCL_SOLIDS(GEOMCHECK_FCL_IS);
#undef GEOMCHECK_FCL_IS

/// Whether the adapter asks FCL about the pair (A, B): a solid against a
/// solid or a triangle (FCL's per-triangle narrow phase). Other pairs have no
/// FCL answer (a peer reports them not supported) and need no code.
template <class A, class B>
inline constexpr bool kFclAsks = kFclSolid<A> && (kFclSolid<B> || std::is_same_v<B, Triangle>);

/// Whether FCL answers (A, B)'s collide with a closed form of its own
/// (GJKSolver_libccd's shapeIntersect specialisations: sphere/sphere,
/// box/box, a sphere against a capsule, box or cylinder, either order;
/// shapeTriangleIntersect's sphere/triangle). Otherwise FCL runs libccd's
/// MPR on the shapes' support functions, which the adapter runs guarded
/// (never hangs, never aborts; the header notes), and its depth and normal
/// are MPR's estimate, not the minimal translation; MPR's touching contact
/// (zero normal, depth below libccd's CCD_EPS) is accepted.
template <class A, class B>
inline constexpr bool kFclClosedFormCollide =
    (std::is_same_v<A, Sphere> && std::is_same_v<B, Sphere>) || (std::is_same_v<A, Obb> && std::is_same_v<B, Obb>) ||
    (std::is_same_v<A, Sphere> && (std::is_same_v<B, Capsule> || std::is_same_v<B, Obb> ||
                                   std::is_same_v<B, Cylinder> || std::is_same_v<B, Triangle>)) ||
    (std::is_same_v<B, Sphere> && (std::is_same_v<A, Capsule> || std::is_same_v<A, Obb> || std::is_same_v<A, Cylinder>));

/// Whether FCL answers (A, B)'s distance with a closed form of its own
/// (shapeDistance's sphere/sphere, capsule/capsule, a sphere against a box,
/// capsule or cylinder, either order; shapeTriangleDistance's
/// sphere/triangle). Otherwise libccd's GJK, run guarded.
template <class A, class B>
inline constexpr bool kFclClosedFormDistance =
    (std::is_same_v<A, Sphere> && std::is_same_v<B, Sphere>) ||
    (std::is_same_v<A, Capsule> && std::is_same_v<B, Capsule>) ||
    (std::is_same_v<A, Sphere> && (std::is_same_v<B, Capsule> || std::is_same_v<B, Obb> ||
                                   std::is_same_v<B, Cylinder> || std::is_same_v<B, Triangle>)) ||
    (std::is_same_v<B, Sphere> && (std::is_same_v<A, Capsule> || std::is_same_v<A, Obb> || std::is_same_v<A, Cylinder>));

/// fcl::collide(a, b), num_max_contacts = 1, enable_contact, GST_LIBCCD (for
/// a triangle B: GJKSolver_libccd::shapeTriangleIntersect with contact, what
/// fcl::collide calls per triangle of a mesh; fcl::collide has no shape/
/// triangle pair). The normal from a towards b. FCL's closed form where it
/// has one, else libccd's MPR, guarded (kFclClosedFormCollide). Not ok:
/// invalid input, "box axes not orthonormal", FCL threw, returned garbage or
/// the guard stopped it. Defined for every pair with kFclAsks<A, B>.
template <class A, class B>
PeerContact fcl_collide(const A& a, const B& b);

/// The same without contact (enable_contact = false), guarded the same way.
/// false for invalid input, when FCL throws or the guard stopped it; then
/// `*error` (if given) says why.
template <class A, class B>
bool fcl_overlap(const A& a, const B& b, std::string* error = nullptr);

/// fcl::distance(a, b), enable_nearest_points, GST_LIBCCD (a triangle B:
/// shapeTriangleDistance): > 0 separated, exactly -1 when FCL sees them
/// meet. FCL's closed form where it has one, else libccd's GJK, guarded and
/// within its range (kFclClosedFormDistance).
template <class A, class B>
PeerDistance fcl_distance(const A& a, const B& b);

/// Whether FCL's continuous collision is asked about a ball (a segment: a
/// ball of radius 0) moving against a resting B: a solid B.
template <class B>
inline constexpr bool kFclCasts = kFclSolid<B>;

/// First touch of segment `s` (from s.a towards s.b) with the resting b, as
/// far as FCL can tell: t within 1e-4, early (see the header notes).
/// Defined for every B with kFclCasts<B>.
template <class B>
PeerCast fcl_cast(const Segment& s, const B& b, FclCastMethod method = FclCastMethod::kConservativeAdvancement);

/// First touch of the moving ball `m` (centre m.c, radius m.r, moving by
/// m.delta) with the resting b, as far as FCL can tell: hit and t only, t
/// within about 1e-4, early (see the header notes). Defined for every B with
/// kFclCasts<B>.
template <class B>
PeerCast fcl_sweep(const MovingSphere& m, const B& b, FclCastMethod method = FclCastMethod::kConservativeAdvancement);

}  // namespace geomcheck::peers
