// geomcheck — cylinder against cylinder, the slice method (internal; see
// collide_cylinder_cylinder.hpp for the algorithm and its claims).
//
// Exposed as a header so that the teeth can run the same code with one of
// its parts switched off, and the near-parallel measurement with the plain
// frame.
#pragma once

#include "geomcheck/results.hpp"
#include "geomcheck/shapes.hpp"

namespace geomcheck::detail {

/// Parts of the method that can be switched off (teeth, measurements).
struct CylinderPairOptions {
  /// The u_B and u_A cap terms (the false-positive planes), both as the
  /// early-out and inside every slice.
  bool false_positive_planes = true;
  /// Exactly parallel axes get their own frame (else: the general frame,
  /// from a zero cross product).
  bool parallel_branch = true;
  /// The common perpendicular as u_B x (u_A -+ u_B), which keeps its
  /// digits at small angles (else the plain u_B x u_A).
  bool accurate_frame = true;
  /// Newton steps on each great circle of side normals at most (contact
  /// only); before 2026-11-27 one.
  int newton_steps = 8;
  /// The Newton search stops when a step would lower the overlap by less
  /// than 2^-12 of it (relative to the depth: shallow contacts of large
  /// cylinders are searched as far as deep ones); off: the earlier stop at a
  /// half-angle step below 2^-10 rad.
  bool relative_stop = true;
  /// The rim x rim candidate at the common point (contact only).
  bool rim_rim = true;
  /// Newton steps on the sphere of directions in the rim x rim patch, from
  /// the best direction, where the rim x rim candidate is tried (0: none).
  int rim_steps = 16;
};

/// The query with the given parts. `want_contact` false: only `hit` is set.
Contact cylinder_pair(const Cylinder& a, const Cylinder& b, bool want_contact, const CylinderPairOptions& opt);

}  // namespace geomcheck::detail
