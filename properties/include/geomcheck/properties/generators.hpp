// geomcheck — RapidCheck generators that reach the hard places.
//
// Every generator draws from rc::gen::inRange (size-independent, shrinks
// towards the first choice), so shrunk counterexamples go to the simplest
// mode, scale and offset.
#pragma once

#include <rapidcheck.h>

#include <cstdint>
#include <string>

#include "geomcheck/properties/checks.hpp"

namespace geomcheck::gen {

/// Uniform double in [lo, hi).
rc::Gen<double> real(double lo, double hi);
/// A value nudged by k ulps, k in [-kmax, kmax].
double nudge(double v, int k);

/// Cylinder/sphere pairs: random, at the rim, on a cap plane, on the side
/// (touching +- k ulps, or a small or large gap either way), exactly touching
/// Pythagorean constructions, centre inside, sphere containing the
/// cylinder, zero radii; scales 2^-20..2^20, optionally far from the origin.
rc::Gen<std::pair<CylinderSphereCase, std::string>> cylinder_sphere_case();
/// Segment/cylinder casts: random, parallel to the axis into a cap, grazing
/// the side, tangent to the rim, aimed at the rim +- a gap, starting
/// inside, zero length, through both caps, exact Pythagorean touches.
rc::Gen<std::pair<SegmentCylinderCase, std::string>> segment_cylinder_case();
/// Cylinder/capsule pairs: random, parallel, anti-parallel and coaxial to
/// the axis (exactly and 1e-8 / 1e-16 from parallel), perpendicular to it,
/// an end sphere at the rim, cap or side, grazing the rim, crossing a cap
/// plane, the segment inside the cylinder (touching +- k ulps, or a small or
/// large gap either way), exact Pythagorean touches, zero capsule radius (a
/// segment), zero cylinder radius, p == q (a sphere).
rc::Gen<std::pair<CylinderCapsuleCase, std::string>> cylinder_capsule_case();
/// Sphere sweeps against a cylinder: random, aimed past the rim corner from
/// above the cap, from the side and diagonally (touching +- k ulps, a gap
/// either way, or inside the corner pocket of the augmented cylinder),
/// along the axis into a cap, grazing the side and the rim, starting inside
/// or touching, ending touching, zero, tiny and huge displacements, exact
/// Pythagorean constructions; scales 2^-20..2^20, optionally far from the
/// origin.
rc::Gen<std::pair<SweepCylinderCase, std::string>> sweep_cylinder_case();
/// Cylinder/box pairs. Box frames are orthonormal (to 4 eps; either
/// handedness, axes stored in any order and sign): signed permutations,
/// times a 3-4-5 or 5-12-13 rotation about a coordinate axis or a product of
/// two, or rounded random rotations (unit quaternions). Modes, by tag:
///   random                        random poses;
///   corner-/edge-/face-<spot>     a box corner, edge or face at the rim
///                                 (rim-above: just above the cap outside the
///                                 rim, rim-side: beside the side, rim-diag),
///                                 a cap or the side;
///   corner-pocket                 a corner over the cap disc within r of the
///                                 cap centre, the box beyond the cap plane
///                                 (in the bounding capsule, not in the
///                                 cylinder: a certain miss);
///   offray                        a tilted box whose corner nearest the axis
///                                 is above the cap while its section by the
///                                 cap plane lies beside that corner's radial
///                                 line (-deep: overlapping the disc, -gap:
///                                 the mirrored near miss);
///   capface-above|below           a box face on a cap plane (an edge or a
///                                 corner of it at in-plane radius r + gap;
///                                 capface-above-over: the face over the disc,
///                                 touching the cap);
///   cyl-in-box, box-in-cyl        containment (-snug: touching inside);
///   thin-flat|tilted|edgewise     a disk-like cylinder (length 1e-6..1e-12
///                                 of r) resting on a box face or its edge;
///   axis-edge[-1e-8|-1e-16]       a box edge parallel (or nearly) to the
///                                 axis beside the side;
///   side-face[-aligned]           a box face tangent to the side;
///   flat-box, segment-box, point-box, zero-radius  zero extents (one, two,
///                                 three), zero cylinder radius, at a spot;
///   pattern-kiss|slab-face|slab-side|stand|lie|f32  patterns from public
///                                 bug reports (gaps ~1e-8 of the scene, thin
///                                 slabs 100 x 100 x 0.1, resting on a big
///                                 box, coordinates rounded to float at
///                                 offsets 40..100);
///   exact-...                     exact integer constructions (a corner on
///                                 the rim of a Pythagorean radius at the cap
///                                 height, faces tangent to the side or on a
///                                 cap, inscribed and circumscribed boxes,
///                                 zero extents, zero radius), exact moves.
/// Suffixes: -touch (touching, then the radius and the extents grown or
/// shrunk by up to 2 ulps), -gap / -deep (a small or large gap either way);
/// exact touches: -touch / -ulps-in / -ulps-out (the radius or a cap moved
/// by k ulps). Scales 2^-20..2^20, optionally far from the origin.
rc::Gen<std::pair<CylinderObbCase, std::string>> cylinder_obb_case();
/// Cylinder/triangle pairs. Modes, by tag:
///   random                        random triangles near the cylinder;
///   vertex-/edge-/face-<spot>     a triangle vertex, edge or face at the rim
///                                 (rim-above, rim-side, rim-diag), a cap or
///                                 the side; edges along the rim's or the
///                                 side's circle (-along: tangent to the
///                                 rim, to the side), across it (-across:
///                                 crossing the rim, along the axis on the
///                                 side) or any way across the normal;
///   point-|segment-|collinear-|sliver-<vertex|edge>-<spot>  degenerate
///                                 triangles at the same contacts (a point,
///                                 two equal vertices, three collinear, the
///                                 third vertex 1e-8, 1e-16 or 2^-30..2^-60
///                                 of the edge off the line);
///   capplane-above|on|below-vertex|edge|over  a triangle parallel to a cap
///                                 (above it: a certain miss; in its plane;
///                                 inside the slab) with a vertex or an edge
///                                 at in-plane radius r + gap, or over the
///                                 disc;
///   axisplane-through|chord-side|cap|corner-vertex|edge, -across,
///   axisplane-through-axis-edge,
///   axisplane-beside              a triangle in a plane parallel to the
///                                 axis (through it, cutting a chord, at
///                                 r + gap), a vertex or an edge at the
///                                 section's long side, short side or
///                                 corner (in-plane gap), covering a
///                                 point of the section, or with an edge
///                                 along the axis (-axis-edge: its ends a
///                                 few ulps off the axis line);
///   capcross-deep|gap|touch|outside  a tilted triangle through a cap plane
///                                 whose point nearest the axis segment is
///                                 beyond the cap (within r of its centre)
///                                 while its vertex W pokes through the disc
///                                 (-deep: overlapping), hovers over it
///                                 (-gap), touches it, or pokes through just
///                                 outside the rim (-outside: a miss); also
///                                 collapsed (segment-, collinear-, sliver-);
///   huge-stand|tilted|lie[-edge]  a small cylinder on a triangle 10^2..10^4
///                                 times its size (touching, a tiny or small
///                                 gap or penetration; -edge: the contact on
///                                 the triangle's edge);
///   thin-flat|tilted|edgewise[-edge]  a disk-like cylinder (length 1e-6..1e-12
///                                 of r) on a triangle;
///   pattern-f32                   vertex/edge/face contacts at offsets
///                                 40..100, every value rounded to float;
///   exact-...                     exact integer constructions (a vertex on
///                                 the rim, the side or a cap, edges tangent
///                                 to the side or the rim, triangles in the
///                                 cap plane at the rim or over the disc, an
///                                 edge across a zero-radius cylinder; also
///                                 point-, segment-, collinear-), exact moves.
/// Suffixes: -touch (touching, then the radius grown or shrunk and the
/// triangle moved by up to 2 ulps), -gap / -deep (a small or large gap
/// either way); exact touches: -touch / -ulps-in / -ulps-out / -ulps-off,
/// exact -gap / -deep (moved exactly: out along the contact normal, or from
/// the contact 2^-1..2^-25 of the way towards the cylinder's centre). Scales
/// 2^-20..2^20, optionally far from the origin.
rc::Gen<std::pair<CylinderTriangleCase, std::string>> cylinder_triangle_case();
/// Cylinder/cylinder pairs. Modes, by tag:
///   random[-through]              random poses in scenes of 2^-60..2^60
///                                 (some far from the origin; disks and
///                                 needles among them); -through: B's middle
///                                 inside A;
///   [anti-]parallel-side[-ANGLE-radial|tangential]  side by side, the axes
///                                 rA + rB (+ gap) apart, ANGLE 1e-4, 1e-8,
///                                 1e-12 or 1e-16 radians from parallel, made
///                                 exactly (a coordinate that is zero at one
///                                 end: nothing rounds it away);
///   coaxial|stacked|stacked-rim[-anti][-ANGLE]  B's cap on A's top cap plane
///                                 (exactly, k ulps off, a gap or overlapping),
///                                 on the axis, beside it, or rA + rB beside
///                                 it (the rims meet at a point);
///   perp-side-side|side-on-cap|cap-on-side|through  perpendicular crossings;
///   cap-|side-|rim-on-<spot>      B's cap, side or rim at A's rim
///                                 (rim-above, rim-side, rim-diag), a cap or
///                                 its side (touching +- ulps, a gap either
///                                 way);
///   ratio-...                     the same with both cylinders disks or
///                                 needles (length / radius 1e-6..1e6);
///   exact-...                     exact integer constructions (parallel
///                                 sides rA + rB apart, stacked caps, rims
///                                 meeting, perpendicular sides, a side on a
///                                 cap, a cap tangent to a side, zero radii),
///                                 exact moves; -touch / -ulps-in / -ulps-out.
/// Suffixes: -touch, -ulps-in / -ulps-out (k ulps), -gap / -deep. Exact
/// moves (permutation, flips, 2^-60..2^60) keep ulp-sized features; other
/// constructions are also placed by a rounded rigid motion. Either cylinder
/// comes first.
rc::Gen<std::pair<CylinderCylinderCase, std::string>> cylinder_cylinder_case();
/// Raw doubles with NaN, +-inf, subnormals, zeros, huge and tiny values.
rc::Gen<double> wild_double();
/// Any shapes, valid or not, from wild doubles (robustness).
rc::Gen<CylinderSphereCase> wild_cylinder_sphere();
rc::Gen<SegmentCylinderCase> wild_segment_cylinder();
rc::Gen<CylinderCapsuleCase> wild_cylinder_capsule();
rc::Gen<SweepCylinderCase> wild_sweep_cylinder();
/// Wild doubles everywhere; a quarter of the boxes keep a valid frame with
/// wild centre and extents.
rc::Gen<CylinderObbCase> wild_cylinder_obb();
/// Wild doubles everywhere; a quarter of the triangles repeat a vertex
/// (segment and point triangles).
rc::Gen<CylinderTriangleCase> wild_cylinder_triangle();
/// Wild doubles everywhere; a quarter of the pairs keep one ordinary cylinder.
rc::Gen<CylinderCylinderCase> wild_cylinder_cylinder();

}  // namespace geomcheck::gen
