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
constexpr const char* kOutOfRange = "outside FCL safe range";

/// Coordinates beyond this are refused where libccd's iterative code would run.
const double kSafeCoordinate = std::ldexp(1.0, 500);

bool in_safe_range(const Vec3& v) { return max_abs(v) <= kSafeCoordinate; }

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

/// Does the prefix [a, a + t n] of a segment touch the cylinder, according to
/// fcl::collide (radius-0 capsule, or radius-0 sphere for a point)?
class SegmentPrefix {
 public:
  explicit SegmentPrefix(const Segment& s) : a_(s.a), n_(s.b - s.a), len_(norm(n_)) {
    if (len_ > 0) rot_ = fcl_rotation_z_to(unit(n_));
  }

  bool touches(const FclCylinder& cyl, double t) const {
    fcl::CollisionRequestd req(1, false);
    req.gjk_solver_type = fcl::GST_LIBCCD;
    fcl::CollisionResultd res;
    const double l = t * len_;
    if (!(l > 0)) {
      const fcl::Sphered point(0.0);
      fcl::Transform3d pose = fcl::Transform3d::Identity();
      pose.translation() = to_fcl(a_);
      return fcl::collide(&point, pose, &cyl.shape, cyl.pose, req, res) > 0;
    }
    const fcl::Capsuled segment(0.0, l);
    fcl::Transform3d pose = fcl::Transform3d::Identity();
    pose.linear() = rot_;
    pose.translation() = to_fcl(a_ + (0.5 * t) * n_);
    return fcl::collide(&segment, pose, &cyl.shape, cyl.pose, req, res) > 0;
  }

 private:
  Vec3 a_, n_;
  double len_;
  fcl::Matrix3d rot_ = fcl::Matrix3d::Identity();
};

PeerCast cast_capsule_bisection(const Segment& s, const Cylinder& c) {
  PeerCast out;
  out.supported = true;
  if (!in_safe_range(s.a) || !in_safe_range(s.b) || !in_safe_range(c.p) || !in_safe_range(c.q) ||
      !(c.r <= kSafeCoordinate)) {
    out.error = kOutOfRange;
    return out;
  }
  const FclCylinder cyl(c);
  const SegmentPrefix seg(s);
  out.ok = true;
  if (!seg.touches(cyl, 1.0)) return out;
  out.hit = true;
  if (seg.touches(cyl, 0.0)) {
    out.t = 0;
    return out;
  }
  // Invariant: the prefix up to lo misses, the prefix up to hi touches.
  double lo = 0, hi = 1;
  for (int i = 0; i < 64; ++i) {
    const double mid = lo + 0.5 * (hi - lo);
    if (!(mid > lo && mid < hi)) break;
    (seg.touches(cyl, mid) ? hi : lo) = mid;
  }
  out.t = hi;
  return out;
}

PeerCast cast_conservative_advancement(const Segment& s, const Cylinder& c) {
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

bool fcl_overlap_prepared(const FclCylinderSphere& pair) {
  fcl::CollisionRequestd req(1, false);
  req.gjk_solver_type = fcl::GST_LIBCCD;
  fcl::CollisionResultd res;
  return fcl::collide(&pair.a.shape, pair.a.pose, &pair.b.shape, pair.b.pose, req, res) > 0;
}

PeerContact fcl_collide_prepared(const FclCylinderSphere& pair) {
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
  PeerDistance out;
  if (!is_valid(a) || !is_valid(b)) {
    out.error = kInvalidInput;
    return out;
  }
  try {
    const FclCylinderSphere pair(a, b);
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

PeerCast fcl_cast(const Segment& s, const Cylinder& c, FclCastMethod method) {
  if (!is_valid(s) || !is_valid(c)) {
    PeerCast out;
    out.supported = true;
    out.error = kInvalidInput;
    return out;
  }
  try {
    switch (method) {
      case FclCastMethod::kConservativeAdvancement:
        return cast_conservative_advancement(s, c);
      case FclCastMethod::kCapsuleBisection:
      default:
        return cast_capsule_bisection(s, c);
    }
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
