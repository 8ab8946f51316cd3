// geomcheck — closed-form exact oracle: balls swept along segments against
// each other (sphere/sphere, sphere/capsule, capsule/capsule).
//
// A capsule is its segment swept by a ball (a sphere: a segment of zero
// length). The squared distance D^2 of two segments with rational ends is
// rational: the minimum of the convex quadratic |w + t v - s u|^2 over the
// unit square is at the crossing of the lines when that lies inside (then
// D^2 = (w . m)^2 / m . m with m = u x v), else on an edge of the square, a
// point against a segment (a clamped rational projection). The verdict
// compares D^2 with (ra + rb)^2, exactly; the penetration depth is
// ra + rb - D for every configuration (detail/segment_pair.hpp in core says
// why), so the signed distance D - (ra + rb) is the only square root, and
// it is a certified interval (exact.hpp).
#pragma once

#include <string>

#include "geomcheck/oracles/exact.hpp"
#include "geomcheck/shapes.hpp"

namespace geomcheck::oracle {

/// Exact squared distance of x from the segment [p, q] (p == q: a point).
Q point_segment_distance2(const QVec& x, const QVec& p, const QVec& q);
/// Exact squared distance of the segments [p1, q1] and [p2, q2].
Q segment_distance2(const QVec& p1, const QVec& q1, const QVec& p2, const QVec& q2);

/// A ball of radius r swept along [p, q], exactly.
struct QBallSegment {
  QVec p, q;
  Q r;
};
QBallSegment to_ball_segment(const Sphere& s);
QBallSegment to_ball_segment(const Capsule& c);

/// The truth of two swept balls.
struct BallPairTruth {
  Verdict verdict = Verdict::Undecided;
  Q dist2;                    ///< D^2, the segments' squared distance, exact
  QInterval dist;             ///< D, certified
  QInterval signed_distance;  ///< D - (ra + rb): > 0 gap, < 0 minus the penetration depth
  std::string text;           ///< human readable
};
BallPairTruth solve_ball_pair(const QBallSegment& a, const QBallSegment& b);

/// Overlap of A and B measured along unit(n): (h_A(n) + h_B(-n)) / |n|, with
/// h of a swept ball max(p . n, q . n) + r |n|. Its minimum over n is the
/// penetration depth ra + rb - D.
QInterval overlap_along(const QBallSegment& a, const QBallSegment& b, const QVec& n);

/// Certified signed distance of x from the swept ball (< 0 inside).
QInterval signed_distance(const QBallSegment& s, const QVec& x);

}  // namespace geomcheck::oracle
