// geomcheck — the FCL adapter's guards (internal to peers/fcl/src): FCL's
// vectors, exceptions turned into answers that are not ok, the shapes FCL is
// not asked about, and FCL's answers checked for garbage. Every call of the
// adapter goes through these.
#pragma once

#include <cmath>
#include <exception>
#include <string>
#include <type_traits>
#include <utility>

#include <fcl/common/types.h>
#include <fcl/narrowphase/collision_result.h>

#include "geomcheck/peers/fcl_adapter.hpp"
#include "geomcheck/peers/fcl_convert.hpp"
#include "geomcheck/shapes.hpp"

namespace geomcheck::peers::fcl_detail {

inline Vec3 from_fcl(const fcl::Vector3d& v) { return {v.x(), v.y(), v.z()}; }
inline fcl::Vector3d to_fcl(const Vec3& v) { return {v.x, v.y, v.z}; }

/// Length of v, scaled first so that neither underflow nor overflow enters
/// the squares.
inline double norm(const Vec3& v) {
  const double m = max_abs(v);
  return m > 0 ? m * length((1.0 / m) * v) : 0.0;
}

/// Unit vector along a non-zero finite v (scaled like `norm`).
inline Vec3 unit(const Vec3& v) {
  const Vec3 s = (1.0 / max_abs(v)) * v;
  return (1.0 / length(s)) * s;
}

constexpr const char* kInvalidInput = "invalid input";
/// libccd's absolute zero (CCD_EPS, DBL_EPSILON in a double build).
constexpr double kCcdEps = 2.220446049250313e-16;
inline std::string describe(const std::exception& e) { return std::string("FCL threw: ") + e.what(); }
constexpr const char* kUnknownThrow = "FCL threw a non-standard exception";

/// An answer R that is not ok, saying `why` (its other fields as a default R).
template <class R>
R failed(std::string why) {
  R out;
  out.error = std::move(why);
  return out;
}

/// Runs f() and returns its answer; an exception (FCL's, Eigen's, a
/// conversion's) becomes an answer R that is not ok, saying why.
template <class R, class F>
R guarded(F&& f) {
  try {
    return f();
  } catch (const std::exception& e) {
    return failed<R>(describe(e));
  } catch (...) {
    return failed<R>(kUnknownThrow);
  }
}
/// guarded(f), an exception's reason kept in `out` (its other fields as they were).
template <class R, class F>
R guarded_into(R out, F&& f) {
  try {
    return f();
  } catch (const std::exception& e) {
    out.ok = false;
    out.error = describe(e);
  } catch (...) {
    out.ok = false;
    out.error = kUnknownThrow;
  }
  return out;
}
/// A yes/no answer of FCL's: false on an exception, its reason in *error.
template <class F>
bool guarded_bool(std::string* error, F&& f) {
  try {
    return f();
  } catch (const std::exception& e) {
    if (error) *error = describe(e);
  } catch (...) {
    if (error) *error = kUnknownThrow;
  }
  return false;
}

constexpr const char* kBoxAxesNotOrthonormal = "box axes not orthonormal";

/// Whether FCL can take s's frame for a rotation (a box's axes orthonormal
/// to rounding; every other shape has none of its own).
template <class S>
bool frame_ok(const S&) { return true; }
inline bool frame_ok(const Obb& b) { return obb_axes_orthonormal(b); }

/// Why FCL is not asked about a pair (nullptr: it is): invalid input first,
/// then a box frame FCL cannot take.
template <class A, class B>
const char* refusal(const A& a, const B& b) {
  if (!is_valid(a) || !is_valid(b)) return kInvalidInput;
  return frame_ok(a) && frame_ok(b) ? nullptr : kBoxAxesNotOrthonormal;
}

/// The answer R of a query on (a, b): not ok, saying why, when FCL is not
/// asked (see `refusal`); otherwise f()'s answer, guarded.
template <class R, class A, class B, class F>
R validated(const A& a, const B& b, F&& f) {
  if (const char* why = refusal(a, b)) return failed<R>(why);
  R out;
  return guarded_into(out, std::forward<F>(f));
}

/// A yes/no query on (a, b): false when FCL is not asked (see `refusal`),
/// the reason in *error; otherwise f()'s answer, guarded (*error cleared
/// first).
template <class A, class B, class F>
bool validated_bool(const A& a, const B& b, std::string* error, F&& f) {
  if (error) error->clear();
  if (const char* why = refusal(a, b)) {
    if (error) *error = why;
    return false;
  }
  return guarded_bool(error, std::forward<F>(f));
}

/// An answered contact query that found no hit.
inline PeerContact no_contact() {
  PeerContact out;
  out.ok = true;
  return out;
}

/// FCL's contact (a hit), checked for garbage. `zero_normal_touch`: accept
/// libccd MPR's touching contact (see below).
inline PeerContact contact_from(const fcl::Vector3d& pos, const fcl::Vector3d& normal, double depth,
                         bool zero_normal_touch = false) {
  PeerContact out;
  out.ok = true;
  out.hit = true;
  // FCL's normal points from o1 to o2 (A to B): this is geomcheck's
  // convention already, no flip.
  out.point = from_fcl(pos);
  out.normal = from_fcl(normal);
  out.depth = depth;
  // libccd's MPR sets no direction for a touching contact (depth below its
  // absolute zero, CCD_EPS): accepted, the normal stays zero.
  const bool touch = zero_normal_touch && out.normal == Vec3{} && out.depth >= 0 && out.depth < kCcdEps;
  if (!is_finite(out.point) || !is_finite(out.normal) || !std::isfinite(out.depth)) {
    out.ok = false;
    out.error = "FCL returned a non-finite contact";
  } else if (!touch && std::fabs(length(out.normal) - 1.0) > 1e-6) {
    out.ok = false;
    out.error = "FCL returned a non-unit normal";
  } else if (out.depth < 0) {
    out.ok = false;
    out.error = "FCL returned a negative depth";
  }
  return out;
}

/// FCL's contact, checked for garbage. `res` holds at most one contact.
inline PeerContact contact_from(const fcl::CollisionResultd& res, bool zero_normal_touch = false) {
  if (!res.isCollision()) return no_contact();
  if (res.numContacts() == 0) {
    PeerContact out;
    out.hit = true;
    out.error = "FCL reported a collision without a contact";
    return out;
  }
  const fcl::Contactd& c = res.getContact(0);
  return contact_from(c.pos, c.normal, c.penetration_depth, zero_normal_touch);
}

/// FCL's distance and nearest points, checked for garbage.
inline PeerDistance distance_from(double dist, const fcl::Vector3d& p1, const fcl::Vector3d& p2) {
  PeerDistance out;
  out.ok = true;
  out.distance = dist;
  out.p_a = from_fcl(p1);
  out.p_b = from_fcl(p2);
  if (!std::isfinite(out.distance) || !is_finite(out.p_a) || !is_finite(out.p_b)) {
    out.ok = false;
    out.error = "FCL returned a non-finite distance or point";
  }
  return out;
}



/// The largest of two shapes' sizes and of their points' offsets from a's
/// first point (NaN is ignored, as the inputs are checked valid first).
template <class A, class B>
double extent(const A& a, const B& b) {
  const Reach ra = reach(a), rb = reach(b);
  double e = std::fmax(ra.size, rb.size);
  for (int i = 0; i < ra.n; ++i) e = std::fmax(e, max_abs(ra.points[i] - ra.points[0]));
  for (int i = 0; i < rb.n; ++i) e = std::fmax(e, max_abs(rb.points[i] - ra.points[0]));
  return e;
}

}  // namespace geomcheck::peers::fcl_detail

