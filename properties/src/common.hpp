// geomcheck — helpers shared by the check functions (internal to properties/).
#pragma once

#include <string>

#include "geomcheck/oracles/solids.hpp"
#include "geomcheck/properties/checks.hpp"

namespace geomcheck {

using oracle::Q;
using oracle::QInterval;
using oracle::QVec;
using oracle::Verdict;

/// Both shapes of a case valid (is_valid): the input every exact check is owed.
template <class Case>
bool valid_case(const Case& c) {
  return is_valid(c.a) && is_valid(c.b);
}

/// snprintf into a string, up to three double arguments.
std::string fmt(const char* f, double a, double b = 0, double c = 0);
/// "(x, y, z)" with round-trip precision.
std::string vec(Vec3 v);
/// One line for a failure message: the overlap verdict and the contact.
std::string describe(const Contact& c, bool overlap);
/// One line for a failure message: a cast or sweep hit.
std::string describe(const CastHit& h);
/// Every output number of a contact is finite.
bool finite_contact(const Contact& c);
/// Every output number of a hit is finite.
bool finite_hit(const CastHit& h);

/// q / scale rounded up to a double, after subtracting the resolution of a
/// double output (4 x the smallest subnormal). The division happens in
/// rationals first: rounding a tiny q up to a double and then dividing
/// would turn one subnormal ulp into a large relative error.
double rel_up(const oracle::Q& q, double scale);
/// k * scale in rationals: a bound k * scale formed in doubles underflows
/// to zero in a subnormal scene.
oracle::Q times_scale(double k, double scale);
/// max |x - v| over the enclosure x, divided by scale, rounded up.
double rel_error(const oracle::QInterval& x, double v, double scale);

/// Error of an outward normal n of the cylinder at a point x on (or near) its
/// surface: its distance from the normal cone of the features (caps, side,
/// rims) within qnear of x; INFINITY when x is near no feature. The side's
/// normals within qnear of x count (they turn by qnear / r); `qinput`, how
/// far the subject's precision moves the input (Tolerances::input * scale),
/// tilts the cap normals by up to 2 qinput / L.
double cylinder_normal_error(const oracle::QCylinder& c, const oracle::QVec& x, Vec3 n, const oracle::Q& qnear,
                             const oracle::Q& qinput = oracle::Q(0));

/// Sets e.depth_short and e.depth_over: where the subject's depth lies
/// certainly below or above the certified penetration depth `pd`.
void score_depth_sides(Evaluation& e, const oracle::QInterval& pd, double depth);

/// How far rounding every coordinate of a shape by u * scale (a subject
/// narrower than double reading its input) can move its surface, in units
/// of u * scale: points 2 (sqrt 3 per point, rounded up), a cylinder's rim
/// swings about its axis by 2 r / L as much again, a box's corners move
/// with its axes by its extents (at most 3 scale), a sweep's end position
/// with its start and its displacement.
double input_motion(const Sphere& s);
double input_motion(const Segment& s);
double input_motion(const Capsule& s);
double input_motion(const Triangle& s);
double input_motion(const MovingSphere& s);
double input_motion(const Cylinder& s);
double input_motion(const Obb& s);

/// The bounds subject `impl` is held to on case c: bounds_of its claims,
/// and, for a subject narrower than double (Tolerances::input > 0), every
/// scaled bound widened by how far rounding the input moves the two solids
/// apart or together (input_motion of both, times input; the normal's
/// overlap twice that: it moves at both ends). For production and double
/// subjects, bounds_of alone.
template <class Case, class Impl>
Tolerances bounds(const Case& c, const Impl& impl) {
  Tolerances t = bounds_of(query_of_case<Case>, impl.claims);
  if (!(t.input > 0) || !is_valid(c.a) || !is_valid(c.b)) return t;
  const double m = t.input * (input_motion(c.a) + input_motion(c.b));
  auto widen = [](double& b, double by) {
    if (b > 0) b += by;
  };
  widen(t.verdict, m), widen(t.depth, m), widen(t.point, m), widen(t.t, m), widen(t.normal, 2 * m);
  return t;
}

/// Whether exact moves of the scene must move the subject's answer bit for
/// bit (Precision::exact_moves; production: yes).
template <class Impl>
bool exact_moves(const Impl& impl) {
  return !impl.claims || impl.claims->precision.exact_moves;
}

/// The subject's answer of a query kind: a contact, or a cast's or sweep's hit.
template <QueryKind K>
struct SubjectAnswerOf {
  using type = CastHit;
};
template <>
struct SubjectAnswerOf<QueryKind::Collide> {
  using type = Contact;
};

/// The part of each query's evaluate that is its own (defined in
/// properties/src/checks_<id>.cpp): after start_evaluation (the subject's
/// answer, validity, scale; kind_checks.cpp) on a valid case, the truth
/// computed, the verdict settled and the subject's and the peer's errors
/// measured into `e`.
#define GEOMCHECK_X(id, kind, A, B, summary)                                                          \
  void hold_to_truth(Evaluation& e, const PairCase<A, B, QueryId::id>& c, const SubjectAnswerOf<kind_of(EntryPoint::kind)>::type& answer, \
                     const PeerAnswerOf<kind_of(EntryPoint::kind)>::type* peer);
GEOMCHECK_QUERY_LIST(GEOMCHECK_X)
#undef GEOMCHECK_X

}  // namespace geomcheck
