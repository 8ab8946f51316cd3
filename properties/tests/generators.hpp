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
/// Raw doubles with NaN, +-inf, subnormals, zeros, huge and tiny values.
rc::Gen<double> wild_double();
/// Any shapes, valid or not, from wild doubles (robustness).
rc::Gen<CylinderSphereCase> wild_cylinder_sphere();
rc::Gen<SegmentCylinderCase> wild_segment_cylinder();
rc::Gen<CylinderCapsuleCase> wild_cylinder_capsule();
rc::Gen<SweepCylinderCase> wild_sweep_cylinder();

}  // namespace geomcheck::gen
