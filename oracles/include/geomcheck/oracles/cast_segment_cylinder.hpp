// geomcheck — closed-form exact oracle: segment cast against a cylinder.
//
// S(t) = a + t n, n = b - a, t in [0, 1]. With d = q - p, m = a - p:
//   axial(t)  = m.d + t n.d              in [0, d.d]            (linear)
//   radial(t) = |(m + t n) x d|^2 - r^2 d.d  <= 0                (quadratic
//             = qa t^2 + 2 qb t + qc,  qa = |n x d|^2, qb = (m x d).(n x d))
// The set of t where S(t) is in the cylinder is the part of the axial
// interval (clipped to [0, 1]) where the convex quadratic is <= 0. Whether it
// is empty, and which feature the first point lies on, is decided exactly in
// rationals; the first t is exact when it is an axial bound (cap or start) or
// a linear root, and otherwise the smaller quadratic root, certified by a
// square-root bracket in the cancellation-free form qc / (-qb + sqrt(D)).
#pragma once

#include <cstdint>
#include <optional>

#include "geomcheck/oracles/exact.hpp"
#include "geomcheck/oracles/solids.hpp"

namespace geomcheck::oracle {

/// Where the first point of the cast lies.
enum class CastFeature { None, StartInside, CapP, CapQ, Side };
const char* to_string(CastFeature f);

/// Exact answer for a cast.
struct CastTruth {
  bool hit = false;
  CastFeature feature = CastFeature::None;
  /// Certified enclosure of the first parameter t* (valid when hit).
  QInterval t;
};

/// Exact first hit of the segment with the closed cylinder. Valid input only.
CastTruth solve_cast(const QSegment& s, const QCylinder& c);
CastTruth solve_cast(const Segment& s, const Cylinder& c);

/// How many decisions of cast_hits and cast_meets_adjusted the interval
/// filter took, and how many fell back to rationals (this thread's, since it
/// started; the tests read them to see the filter decide).
struct CastFilterCounts {
  std::uint64_t decided = 0, exact = 0;
};
CastFilterCounts& cast_filter_counts();

/// Turns the interval filter of cast_hits and cast_meets_adjusted off (every
/// decision in rationals) or on (the default); bench_checks compares the two.
void set_cast_filter(bool on);

/// solve_cast(s, c).hit, decided in outward-rounded double intervals first
/// and in rationals only where the intervals cannot tell (the same answer).
bool cast_hits(const QSegment& s, const QCylinder& c);

/// Whether the segment meets `grown(c, delta)` (sign > 0) or `shrunk(c,
/// delta)` (sign < 0; false when that is empty), decided like cast_hits:
/// exactly, with the interval filter first.
bool cast_meets_adjusted(const QSegment& s, const QCylinder& c, const Q& delta, int sign);

/// The cylinder grown by at least `delta` (radius + delta, each cap moved
/// out by at least delta): contains every point within delta of `c`.
QCylinder grown(const QCylinder& c, const Q& delta);
/// The cylinder shrunk by at least `delta`: every point of it is at least
/// delta inside `c`. Empty (nullopt) when the cylinder is thinner than that.
std::optional<QCylinder> shrunk(const QCylinder& c, const Q& delta);

}  // namespace geomcheck::oracle
