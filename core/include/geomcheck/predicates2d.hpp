// geomcheck — exact 2D predicates on doubles: orientation and in-circle.
//
// Every answer is the sign of the exact determinant of the input doubles
// (no tolerance, no perturbation), for every finite input:
//   1. a floating-point filter (Shewchuk's static bounds ccwerrboundA and
//      iccerrboundA, which cover the rounding of the differences as well);
//      it answers when the computed value is farther from zero than the
//      bound and nothing overflowed or underflowed;
//   2. otherwise exact expansion arithmetic (error-free sums and products,
//      products by fma) on the points scaled by one power of two, when the
//      magnitudes of the involved coordinates span few enough binades that
//      no partial product can overflow or lose bits to underflow;
//   3. otherwise exact rationals (boost::multiprecision::cpp_rational),
//      which cover any mix of magnitudes (1e300 beside 1e-300).
// The caller checks finiteness (non-finite input has no exact answer: the
// result is then unspecified but the call returns).
#pragma once

namespace geomcheck {

struct Vec2 {
  double x = 0, y = 0;
};
inline bool operator==(Vec2 a, Vec2 b) { return a.x == b.x && a.y == b.y; }
inline bool operator!=(Vec2 a, Vec2 b) { return !(a == b); }

/// Sign of det [b - a, c - a]: +1 when a, b, c turn counter-clockwise, -1
/// clockwise, 0 collinear (or coincident points). Exact.
int orient2d(Vec2 a, Vec2 b, Vec2 c);

/// For a, b, c counter-clockwise: +1 when d is strictly inside their
/// circumcircle, -1 strictly outside, 0 on it (the sign flips for a
/// clockwise triangle; 0 for collinear a, b, c means d is on their line or
/// the determinant vanishes). Exact.
int incircle(Vec2 a, Vec2 b, Vec2 c, Vec2 d);

namespace detail {
/// The exact stages alone (tests compare them with each other and with an
/// independent exact kernel): expansions (nullopt-like 2 when the range of
/// magnitudes does not allow them), and rationals.
int orient2d_expansion(Vec2 a, Vec2 b, Vec2 c);  ///< 2 = not applicable
int incircle_expansion(Vec2 a, Vec2 b, Vec2 c, Vec2 d);  ///< 2 = not applicable
int orient2d_rational(Vec2 a, Vec2 b, Vec2 c);
int incircle_rational(Vec2 a, Vec2 b, Vec2 c, Vec2 d);
}  // namespace detail

}  // namespace geomcheck
