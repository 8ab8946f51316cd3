#include "geomcheck/oracles/fcl_adapter.hpp"

#include <cmath>
#include <exception>
#include <string>

#include <fcl/narrowphase/collision.h>
#include <fcl/narrowphase/continuous_collision.h>
#include <fcl/narrowphase/distance.h>

#include "geomcheck/oracles/fcl_convert.hpp"

namespace geomcheck::oracles {

namespace {

Vec3 from_fcl(const fcl::Vector3d& v) { return {v.x(), v.y(), v.z()}; }
fcl::Vector3d to_fcl(const Vec3& v) { return {v.x, v.y, v.z}; }

/// Length of v, scaled first so that neither underflow nor overflow enters
/// the squares.
double norm(const Vec3& v) {
  const double m = max_abs(v);
  return m > 0 ? m * length((1.0 / m) * v) : 0.0;
}

/// Unit vector along a non-zero finite v (scaled like `norm`).
Vec3 unit(const Vec3& v) {
  const Vec3 s = (1.0 / max_abs(v)) * v;
  return (1.0 / length(s)) * s;
}

constexpr const char* kInvalidInput = "invalid input";
std::string describe(const std::exception& e) { return std::string("FCL threw: ") + e.what(); }
const char* kUnknownThrow = "FCL threw a non-standard exception";

/// FCL's contact, checked for garbage. `res` holds at most one contact.
PeerContact contact_from(const fcl::CollisionResultd& res) {
  PeerContact out;
  out.ok = true;
  out.hit = res.isCollision();
  if (!out.hit) return out;
  if (res.numContacts() == 0) {
    out.ok = false;
    out.error = "FCL reported a collision without a contact";
    return out;
  }
  const fcl::Contactd& c = res.getContact(0);
  // FCL's normal points from o1 (the cylinder) to o2 (the sphere): this is
  // geomcheck's convention already, no flip.
  out.point = from_fcl(c.pos);
  out.normal = from_fcl(c.normal);
  out.depth = c.penetration_depth;
  if (!is_finite(out.point) || !is_finite(out.normal) || !std::isfinite(out.depth)) {
    out.ok = false;
    out.error = "FCL returned a non-finite contact";
  } else if (std::fabs(length(out.normal) - 1.0) > 1e-6) {
    out.ok = false;
    out.error = "FCL returned a non-unit normal";
  } else if (out.depth < 0) {
    out.ok = false;
    out.error = "FCL returned a negative depth";
  }
  return out;
}

/// One fcl::continuousCollide call: a radius-0 sphere moving from s.a to s.b
/// against the resting cylinder.
PeerCast continuous_collide_once(const Segment& s, const Cylinder& c) {
  PeerCast out;
  out.supported = true;
  const FclCylinder cyl(c);
  const fcl::Sphered point(0.0);
  fcl::Transform3d begin = fcl::Transform3d::Identity(), end = fcl::Transform3d::Identity();
  begin.translation() = to_fcl(s.a);
  end.translation() = to_fcl(s.b);
  const fcl::ContinuousCollisionRequestd req(10, 1e-4, fcl::CCDM_TRANS, fcl::GST_LIBCCD,
                                             fcl::CCDC_CONSERVATIVE_ADVANCEMENT);
  fcl::ContinuousCollisionResultd res;
  fcl::continuousCollide(&point, begin, end, &cyl.shape, cyl.pose, cyl.pose, req, res);
  out.ok = true;
  out.hit = res.is_collide;
  out.t = res.is_collide ? res.time_of_contact : 0.0;
  if (!std::isfinite(out.t) || out.t < 0 || out.t > 1) {
    out.ok = false;
    out.error = "FCL returned a time of contact outside [0, 1]";
  }
  return out;
}

/// Exact re-expressions of the same scene (negations and a cyclic
/// permutation of the coordinates only): frame k of 4.
Vec3 in_frame(const Vec3& v, int k) {
  const Vec3 w = (k & 1) ? -v : v;
  return (k & 2) ? Vec3{w.y, w.z, w.x} : w;
}
Segment in_frame(const Segment& s, int k) { return {in_frame(s.a, k), in_frame(s.b, k)}; }
Cylinder in_frame(const Cylinder& c, int k) { return {in_frame(c.p, k), in_frame(c.q, k), c.r}; }

/// Largest size FCL's continuous collision is given: its bounding-volume
/// fit squares the cylinder's dimensions (beyond this it overflows, prints
/// "eigen: too many iterations in Jacobi transform." and answers garbage).
const double kCastMaxExtent = std::ldexp(1.0, 500);

bool within_cast_range(const Segment& s, const Cylinder& c) {
  const double extent = std::fmax(std::fmax(max_abs(c.q - c.p), c.r),
                                  std::fmax(max_abs(s.a - c.p), max_abs(s.b - c.p)));
  return extent <= kCastMaxExtent;  // false for NaN too
}

PeerCast cast_conservative_advancement(const Segment& s, const Cylinder& c, bool more_frames) {
  if (!within_cast_range(s, c)) {
    PeerCast out;
    out.supported = true;
    out.error = "outside FCL's range";
    return out;
  }
  const PeerCast first = continuous_collide_once(s, c);
  if (!more_frames || !first.ok || first.hit) return first;
  // FCL misses some hits (see the header): ask again in exactly equivalent
  // frames, where the rounding of the advancement steps differs.
  for (int k = 1; k < 4; ++k) {
    const PeerCast again = continuous_collide_once(in_frame(s, k), in_frame(c, k));
    if (again.ok && again.hit) return again;
  }
  return first;
}

}  // namespace

fcl::Matrix3d fcl_rotation_z_to(const Vec3& u) {
  const Vec3 e1 = any_perpendicular(u);
  const Vec3 e2 = cross(u, e1);
  fcl::Matrix3d r;
  r.col(0) = to_fcl(e1);
  r.col(1) = to_fcl(e2);
  r.col(2) = to_fcl(u);
  return r;
}

FclCylinder::FclCylinder(const Cylinder& c)
    : shape(c.r, norm(c.q - c.p)), pose(fcl::Transform3d::Identity()) {
  pose.linear() = fcl_rotation_z_to(unit(c.q - c.p));
  pose.translation() = to_fcl(0.5 * c.p + 0.5 * c.q);
}

FclSphere::FclSphere(const Sphere& s) : shape(s.r), pose(fcl::Transform3d::Identity()) {
  pose.translation() = to_fcl(s.c);
}

namespace {

// The FCL calls on any converted pair (members a, b with shape and pose).
template <class Pair>
bool overlap_on(const Pair& pair) {
  fcl::CollisionRequestd req(1, false);
  req.gjk_solver_type = fcl::GST_LIBCCD;
  fcl::CollisionResultd res;
  return fcl::collide(&pair.a.shape, pair.a.pose, &pair.b.shape, pair.b.pose, req, res) > 0;
}

template <class Pair>
PeerContact collide_on(const Pair& pair) {
  try {
    fcl::CollisionRequestd req(1, true);
    req.gjk_solver_type = fcl::GST_LIBCCD;
    fcl::CollisionResultd res;
    fcl::collide(&pair.a.shape, pair.a.pose, &pair.b.shape, pair.b.pose, req, res);
    return contact_from(res);
  } catch (const std::exception& e) {
    PeerContact out;
    out.error = describe(e);
    return out;
  } catch (...) {
    PeerContact out;
    out.error = kUnknownThrow;
    return out;
  }
}

template <class Pair>
PeerDistance distance_on(const Pair& pair) {
  PeerDistance out;
  try {
    fcl::DistanceRequestd req(true);
    req.gjk_solver_type = fcl::GST_LIBCCD;
    fcl::DistanceResultd res;
    fcl::distance(&pair.a.shape, pair.a.pose, &pair.b.shape, pair.b.pose, req, res);
    out.ok = true;
    out.distance = res.min_distance;
    out.p_a = from_fcl(res.nearest_points[0]);
    out.p_b = from_fcl(res.nearest_points[1]);
    if (!std::isfinite(out.distance) || !is_finite(out.p_a) || !is_finite(out.p_b)) {
      out.ok = false;
      out.error = "FCL returned a non-finite distance or point";
    }
  } catch (const std::exception& e) {
    out.ok = false;
    out.error = describe(e);
  } catch (...) {
    out.ok = false;
    out.error = kUnknownThrow;
  }
  return out;
}

}  // namespace

bool fcl_overlap_prepared(const FclCylinderSphere& pair) { return overlap_on(pair); }
PeerContact fcl_collide_prepared(const FclCylinderSphere& pair) { return collide_on(pair); }
PeerDistance fcl_distance_prepared(const FclCylinderSphere& pair) { return distance_on(pair); }
bool fcl_overlap_prepared(const FclCylinderCylinder& pair) { return overlap_on(pair); }
PeerContact fcl_collide_prepared(const FclCylinderCylinder& pair) { return collide_on(pair); }
PeerDistance fcl_distance_prepared(const FclCylinderCylinder& pair) { return distance_on(pair); }

PeerContact fcl_collide(const Cylinder& a, const Sphere& b) {
  if (!is_valid(a) || !is_valid(b)) {
    PeerContact out;
    out.error = kInvalidInput;
    return out;
  }
  try {
    return fcl_collide_prepared(FclCylinderSphere(a, b));
  } catch (const std::exception& e) {
    PeerContact out;
    out.error = describe(e);
    return out;
  } catch (...) {
    PeerContact out;
    out.error = kUnknownThrow;
    return out;
  }
}

bool fcl_overlap(const Cylinder& a, const Sphere& b, std::string* error) {
  if (error) error->clear();
  if (!is_valid(a) || !is_valid(b)) {
    if (error) *error = kInvalidInput;
    return false;
  }
  try {
    return fcl_overlap_prepared(FclCylinderSphere(a, b));
  } catch (const std::exception& e) {
    if (error) *error = describe(e);
  } catch (...) {
    if (error) *error = kUnknownThrow;
  }
  return false;
}

PeerDistance fcl_distance(const Cylinder& a, const Sphere& b) {
  if (!is_valid(a) || !is_valid(b)) {
    PeerDistance out;
    out.error = kInvalidInput;
    return out;
  }
  try {
    return distance_on(FclCylinderSphere(a, b));
  } catch (const std::exception& e) {  // the conversion
    PeerDistance out;
    out.error = describe(e);
    return out;
  } catch (...) {
    PeerDistance out;
    out.error = kUnknownThrow;
    return out;
  }
}

PeerCast fcl_cast(const Segment& s, const Cylinder& c, FclCastMethod method) {
  if (!is_valid(s) || !is_valid(c)) {
    PeerCast out;
    out.supported = true;
    out.error = kInvalidInput;
    return out;
  }
  try {
    return cast_conservative_advancement(s, c, method != FclCastMethod::kConservativeAdvancementOnce);
  } catch (const std::exception& e) {
    PeerCast out;
    out.supported = true;
    out.error = describe(e);
    return out;
  } catch (...) {
    PeerCast out;
    out.supported = true;
    out.error = kUnknownThrow;
    return out;
  }
}

}  // namespace geomcheck::oracles
