// geomcheck — exact helpers on single solids, used by every oracle and check:
// the signed distance of a point, the support function, a shape's
// magnitude and a case's scale.
#pragma once

#include <algorithm>

#include "geomcheck/oracles/exact.hpp"
#include "geomcheck/shapes.hpp"

namespace geomcheck::oracle {

/// Signed distance from point x to the cylinder surface (< 0 inside).
QInterval signed_distance(const QCylinder& cyl, const QVec& x);
/// Signed distance from point x to the sphere surface (< 0 inside).
QInterval signed_distance(const QSphere& s, const QVec& x);

/// Support function of the cylinder along n (any non-zero n, not normalised):
/// max over the cylinder of n.x.
QInterval support(const QCylinder& cyl, const QVec& n);
/// Support function of the sphere along n (not normalised).
QInterval support(const QSphere& s, const QVec& n);

/// |b - a| computed without overflow, clamped to the largest double.
double extent(Vec3 a, Vec3 b);

/// A shape's magnitude: the largest of its coordinate magnitudes, its
/// radius and (cylinder, capsule) the extent of its axis.
double magnitude(const Cylinder& c);
double magnitude(const Capsule& c);
double magnitude(const Sphere& s);
double magnitude(const Segment& s);
double magnitude(const Obb& b);
double magnitude(const Triangle& t);
/// A moving sphere: its start, its end (when finite) and its radius.
double magnitude(const MovingSphere& s);

/// The scale of a case of shapes a and b, the unit its errors are measured
/// in: the larger magnitude, or 1 when both are zero.
template <class A, class B>
double case_scale(const A& a, const B& b) {
  const double m = std::max(magnitude(a), magnitude(b));
  return m > 0 ? m : 1.0;
}

}  // namespace geomcheck::oracle
