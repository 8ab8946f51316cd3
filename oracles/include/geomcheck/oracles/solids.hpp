// geomcheck — exact helpers on single solids, used by every oracle and check:
// the signed distance of a point, the support function, a case's extent.
#pragma once

#include "geomcheck/oracles/exact.hpp"

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

}  // namespace geomcheck::oracle
