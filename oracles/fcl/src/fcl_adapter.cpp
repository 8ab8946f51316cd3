#include "geomcheck/oracles/fcl_adapter.hpp"

#include <algorithm>
#include <cmath>
#include <exception>
#include <limits>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include <ccd/vec3.h>
#include <fcl/narrowphase/collision.h>
#include <fcl/narrowphase/continuous_collision.h>
#include <fcl/narrowphase/detail/convexity_based_algorithm/gjk_libccd.h>
#include <fcl/narrowphase/detail/gjk_solver_libccd.h>
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
/// libccd's absolute zero (CCD_EPS, DBL_EPSILON in a double build).
constexpr double kCcdEps = 2.220446049250313e-16;
std::string describe(const std::exception& e) { return std::string("FCL threw: ") + e.what(); }
const char* kUnknownThrow = "FCL threw a non-standard exception";

/// Runs f() and returns its answer; an exception (FCL's, Eigen's, a
/// conversion's) becomes an answer R that is not ok, saying why.
template <class R, class F>
R guarded(F&& f) {
  try {
    return f();
  } catch (const std::exception& e) {
    R out;
    out.error = describe(e);
    return out;
  } catch (...) {
    R out;
    out.error = kUnknownThrow;
    return out;
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

/// An answered contact query that found no hit.
PeerContact no_contact() {
  PeerContact out;
  out.ok = true;
  return out;
}

/// FCL's contact (a hit), checked for garbage. `zero_normal_touch`: accept
/// libccd MPR's touching contact (see below).
PeerContact contact_from(const fcl::Vector3d& pos, const fcl::Vector3d& normal, double depth,
                         bool zero_normal_touch = false) {
  PeerContact out;
  out.ok = true;
  out.hit = true;
  // FCL's normal points from o1 (the cylinder) to o2 (the sphere or the
  // capsule): this is geomcheck's convention already, no flip.
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
PeerContact contact_from(const fcl::CollisionResultd& res, bool zero_normal_touch = false) {
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
PeerDistance distance_from(double dist, const fcl::Vector3d& p1, const fcl::Vector3d& p2) {
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

constexpr const char* kBoxAxesNotOrthonormal = "box axes not orthonormal";

/// Why FCL is not asked about a pair (nullptr: it is).
template <class B>
const char* refusal(const Cylinder& a, const B& b) {
  return is_valid(a) && is_valid(b) ? nullptr : kInvalidInput;
}
const char* refusal(const Cylinder& a, const Obb& b) {
  if (!is_valid(a) || !is_valid(b)) return kInvalidInput;
  return obb_axes_orthonormal(b) ? nullptr : kBoxAxesNotOrthonormal;
}

/// The answer R of a query on (a, b): not ok, saying why, when FCL is not
/// asked (see `refusal`); otherwise f()'s answer, guarded.
template <class R, class B, class F>
R validated(const Cylinder& a, const B& b, F&& f) {
  R out;
  if (const char* why = refusal(a, b)) {
    out.error = why;
    return out;
  }
  return guarded_into(out, std::forward<F>(f));
}

/// A yes/no query on (a, b): false when FCL is not asked (see `refusal`),
/// the reason in *error; otherwise f()'s answer, guarded (*error cleared
/// first).
template <class B, class F>
bool validated_bool(const Cylinder& a, const B& b, std::string* error, F&& f) {
  if (error) error->clear();
  if (const char* why = refusal(a, b)) {
    if (error) *error = why;
    return false;
  }
  return guarded_bool(error, std::forward<F>(f));
}

// --- libccd's MPR and GJK with guarded support functions ----------------------
//
// For cylinder/capsule and cylinder/box FCL runs libccd's MPR (collide) and
// GJK (distance) on support functions, and so does its per-triangle narrow
// phase for cylinder/triangle. Two defects of FCL 0.7 / libccd 2.1 make the raw
// calls unsafe for a harness (see the header): MPR's portal loops have no
// iteration cap and can cycle for ever, and a support function that returns
// a non-finite point (FCL's capsule support normalises a zero or underflowing
// direction) makes FCL's GJK fail an assert and abort the process. The same
// calls are made here as FCL makes them (GJKSolver_libccd's
// ShapeIntersectLibccdImpl / ShapeDistanceLibccdImpl: the same libccd
// objects, centre functions, iteration caps and tolerances; for a triangle
// ShapeTriangleIntersectLibccdImpl / ShapeTriangleDistanceLibccdImpl), with
// FCL's support functions wrapped:
//   - a budget of evaluations; once spent, every further support point lies
//     far behind the search direction, on which every MPR loop exits;
//   - a non-finite support point is replaced by the origin (any finite point
//     keeps GJK's "A is not in region 1" assert true, see the header);
//   - so is the support along a non-finite direction, without asking FCL
//     (the box's support turns NaN into a finite corner, the triangle's
//     leaves its output unset).
// Either event makes the answer "not ok". Otherwise it is bit for bit
// FCL's.

/// Support evaluations (one per shape, two per Minkowski point) allowed in
/// one call: about twenty times the most seen in a returning MPR call (about
/// 1,040: FCL caps the penetration phase at 500 Minkowski points); GJK's
/// distance, capped at 1,000 + 1,000 iterations, needs at most about 4,000.
constexpr long kSupportBudget = 20000;

struct SupportGuard {
  const void* obj1 = nullptr;
  fcl::detail::GJKSupportFunction support1 = nullptr, support2 = nullptr;
  long left = kSupportBudget;
  bool spent = false;       ///< the budget ran out
  bool non_finite = false;  ///< a support point was not finite
};
thread_local SupportGuard* t_support_guard = nullptr;

bool finite3(const ccd_vec3_t* v) {
  return std::isfinite(v->v[0]) && std::isfinite(v->v[1]) && std::isfinite(v->v[2]);
}

void guarded_support(const void* obj, const ccd_vec3_t* dir, ccd_vec3_t* v) {
  SupportGuard& g = *t_support_guard;
  if (g.left <= 0) {
    // Shape 1 is asked along dir, shape 2 along -dir: the Minkowski point is
    // then -2e300 dir, behind every portal and beyond every tolerance.
    g.spent = true;
    ccdVec3Copy(v, dir);
    ccdVec3Scale(v, -1e300);
    return;
  }
  --g.left;
  if (!finite3(dir)) {
    g.non_finite = true;
    ccdVec3Set(v, 0, 0, 0);
    return;
  }
  // A support function that leaves its output unset is seen as non-finite.
  const double nan = std::numeric_limits<double>::quiet_NaN();
  ccdVec3Set(v, nan, nan, nan);
  (obj == g.obj1 ? g.support1 : g.support2)(obj, dir, v);
  if (!finite3(v)) {
    g.non_finite = true;
    ccdVec3Set(v, 0, 0, 0);
  }
}

/// FCL's libccd object of a converted shape, as GJKSolver_libccd's
/// ShapeIntersectLibccdImpl / ShapeDistanceLibccdImpl build it.
template <class Shape>
struct LibccdShape {
  using Init = fcl::detail::GJKInitializer<double, Shape>;
  const Shape& shape;
  const fcl::Transform3d& pose;
  void* create() const { return Init::createGJKObject(shape, pose); }
  static void destroy(void* o) { Init::deleteGJKObject(o); }
  static fcl::detail::GJKSupportFunction support() { return Init::getSupportFunction(); }
  static fcl::detail::GJKCenterFunction center() { return Init::getCenterFunction(); }
};

/// FCL's libccd triangle, as ShapeTriangleIntersectLibccdImpl /
/// ShapeTriangleDistanceLibccdImpl build it (world-frame vertices, no
/// transform).
struct LibccdTriangle {
  const fcl::Vector3d &a, &b, &c;
  void* create() const { return fcl::detail::triCreateGJKObject(a, b, c); }
  static void destroy(void* o) { fcl::detail::triDeleteGJKObject(o); }
  static fcl::detail::GJKSupportFunction support() { return fcl::detail::triGetSupportFunction(); }
  static fcl::detail::GJKCenterFunction center() { return fcl::detail::triGetCenterFunction(); }
};

/// The libccd object description of a converted shape (members shape, pose)
/// or of a triangle.
template <class Converted>
LibccdShape<std::decay_t<decltype(Converted::shape)>> libccd(const Converted& x) {
  return {x.shape, x.pose};
}
LibccdTriangle libccd(const FclTriangle& t) { return {t.a, t.b, t.c}; }

/// Installs a guard around FCL's support functions of two libccd objects
/// for the lifetime of the scope.
template <class Obj1, class Obj2>
class GuardedObjects {
 public:
  GuardedObjects(const Obj1& d1, const Obj2& d2) : o1_(d1.create()), o2_(d2.create()), outer_(t_support_guard) {
    guard_.obj1 = o1_;
    guard_.support1 = Obj1::support();
    guard_.support2 = Obj2::support();
    t_support_guard = &guard_;
  }
  ~GuardedObjects() {
    t_support_guard = outer_;
    Obj1::destroy(o1_);
    Obj2::destroy(o2_);
  }
  GuardedObjects(const GuardedObjects&) = delete;
  GuardedObjects& operator=(const GuardedObjects&) = delete;

  void* o1() const { return o1_; }
  void* o2() const { return o2_; }
  const SupportGuard& guard() const { return guard_; }

 private:
  void* o1_;
  void* o2_;
  SupportGuard guard_;
  SupportGuard* outer_;
};

/// Largest relative size given to FCL's GJK distance: its simplex tests
/// multiply squared lengths of Minkowski points (fourth powers of the
/// scene's offsets and sizes); beyond 2^250 the products overflow, a dot
/// product turns NaN and FCL's "A is not in region 1" assert aborts.
const double kGjkMaxExtent = std::ldexp(1.0, 250);

/// A capsule or a second cylinder: its end points' offsets and its radius.
template <class B>
bool within_gjk_range(const Cylinder& c, const B& k) {
  const double offsets = std::fmax(max_abs(c.q - c.p), std::fmax(max_abs(k.p - c.p), max_abs(k.q - c.p)));
  const double extent = std::fmax(offsets, std::fmax(c.r, k.r));
  return extent <= kGjkMaxExtent;  // false for NaN too
}

/// The box: its centre's offset, its extents (FCL's corners are c +- e_i
/// axes_i, within 3 max e of the centre).
bool within_gjk_range(const Cylinder& c, const Obb& b) {
  const double offsets = std::fmax(max_abs(c.q - c.p), max_abs(b.c - c.p));
  const double extent = std::fmax(offsets, std::fmax(c.r, max_abs(b.e)));
  return extent <= kGjkMaxExtent;  // false for NaN too
}

bool within_gjk_range(const Cylinder& c, const Triangle& t) {
  const double offsets = std::fmax(std::fmax(max_abs(c.q - c.p), max_abs(t.a - c.p)),
                                   std::fmax(max_abs(t.b - c.p), max_abs(t.c - c.p)));
  const double extent = std::fmax(offsets, c.r);
  return extent <= kGjkMaxExtent;  // false for NaN too
}

constexpr const char* kSupportSpent = "FCL did not terminate (libccd MPR exceeded its support budget)";
constexpr const char* kSupportNonFinite =
    "FCL's support function returned a non-finite point or was asked along a non-finite direction (FCL as "
    "shipped aborts or answers garbage here)";

struct MprAnswer {
  bool hit = false;
  const char* error = nullptr;  ///< kSupportSpent or kSupportNonFinite: no answer
  fcl::Vector3d point = fcl::Vector3d::Zero(), normal = fcl::Vector3d::Zero();
  double depth = 0;
};

/// FCL's libccd intersection test (MPR) of two libccd objects (LibccdShape,
/// LibccdTriangle), with the penetration phase when `contact`, under the
/// guard.
template <class Obj1, class Obj2>
MprAnswer guarded_mpr(const Obj1& d1, const Obj2& d2, bool contact) {
  using Objects = GuardedObjects<Obj1, Obj2>;
  // FCL's parameters: GJKSolver_libccd's iteration cap, the request's
  // tolerance (fcl::collide copies request.gjk_tolerance into the solver,
  // also before a mesh traversal's per-triangle calls).
  const fcl::detail::GJKSolver_libccdd solver;
  const fcl::CollisionRequestd request;
  const Objects objs(d1, d2);
  MprAnswer out;
  out.hit = fcl::detail::GJKCollide<double>(objs.o1(), &guarded_support, Obj1::center(),
                                            objs.o2(), &guarded_support, Obj2::center(),
                                            solver.max_collision_iterations, request.gjk_tolerance,
                                            contact ? &out.point : nullptr, contact ? &out.depth : nullptr,
                                            contact ? &out.normal : nullptr);
  if (objs.guard().spent) out.error = kSupportSpent;
  else if (objs.guard().non_finite) out.error = kSupportNonFinite;
  return out;
}

/// FCL's libccd distance (GJK, unsigned) of two libccd objects, under the
/// guard, as fcl::distance with enable_nearest_points reports it.
template <class Obj1, class Obj2>
PeerDistance guarded_gjk_distance(const Obj1& d1, const Obj2& d2) {
  using Objects = GuardedObjects<Obj1, Obj2>;
  // FCL's parameters: GJKSolver_libccd's iteration cap, the request's
  // tolerance (fcl::distance copies request.distance_tolerance).
  const fcl::detail::GJKSolver_libccdd solver;
  const fcl::DistanceRequestd request(true);
  const Objects objs(d1, d2);
  double dist = 0;
  fcl::Vector3d p1 = fcl::Vector3d::Zero(), p2 = fcl::Vector3d::Zero();
  fcl::detail::GJKDistance<double>(objs.o1(), &guarded_support, objs.o2(), &guarded_support,
                                   solver.max_distance_iterations, request.distance_tolerance, &dist, &p1, &p2);
  if (objs.guard().spent || objs.guard().non_finite) {
    PeerDistance out;
    out.error = objs.guard().spent ? kSupportSpent : kSupportNonFinite;
    return out;
  }
  return distance_from(dist, p1, p2);
}

/// A sphere of radius r translated from `from` to `to` (a segment cast: r = 0).
struct Motion {
  Vec3 from, to;
  double r = 0;
};
Motion motion_of(const Segment& s) { return {s.a, s.b, 0.0}; }
Motion motion_of(const MovingSphere& m) { return {m.c, m.c + m.delta, m.r}; }

/// One fcl::continuousCollide call: the sphere of the motion against the
/// resting cylinder.
PeerCast continuous_collide_once(const Motion& m, const Cylinder& c) {
  PeerCast out;
  out.supported = true;
  const FclCylinder cyl(c);
  const fcl::Sphered point(m.r);
  fcl::Transform3d begin = fcl::Transform3d::Identity(), end = fcl::Transform3d::Identity();
  begin.translation() = to_fcl(m.from);
  end.translation() = to_fcl(m.to);
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
Motion in_frame(const Motion& m, int k) { return {in_frame(m.from, k), in_frame(m.to, k), m.r}; }
Cylinder in_frame(const Cylinder& c, int k) { return {in_frame(c.p, k), in_frame(c.q, k), c.r}; }

/// Largest size FCL's continuous collision is given: its bounding-volume
/// fit squares the cylinder's dimensions (beyond this it overflows, prints
/// "eigen: too many iterations in Jacobi transform." and answers garbage).
const double kCastMaxExtent = std::ldexp(1.0, 500);

bool within_cast_range(const Motion& m, const Cylinder& c) {
  const double extent = std::fmax(std::fmax(std::fmax(max_abs(c.q - c.p), c.r), m.r),
                                  std::fmax(max_abs(m.from - c.p), max_abs(m.to - c.p)));
  return extent <= kCastMaxExtent;  // false for NaN too
}

PeerCast cast_conservative_advancement(const Motion& m, const Cylinder& c, bool more_frames) {
  if (!within_cast_range(m, c)) {
    PeerCast out;
    out.supported = true;
    out.error = "outside FCL's range";
    return out;
  }
  const PeerCast first = continuous_collide_once(m, c);
  if (!more_frames || !first.ok || first.hit) return first;
  // FCL misses some hits (see the header): ask again in exactly equivalent
  // frames, where the rounding of the advancement steps differs.
  for (int k = 1; k < 4; ++k) {
    const PeerCast again = continuous_collide_once(in_frame(m, k), in_frame(c, k));
    if (again.ok && again.hit) return again;
  }
  return first;
}

/// fcl_cast and fcl_sweep: validation, range, exceptions.
template <class Moving>
PeerCast continuous_collide(const Moving& moving, const Cylinder& c, FclCastMethod method) {
  PeerCast out;
  out.supported = true;
  if (!is_valid(moving) || !is_valid(c)) {
    out.error = kInvalidInput;
    return out;
  }
  return guarded_into(out, [&]() -> PeerCast {
    return cast_conservative_advancement(motion_of(moving), c,
                                         method != FclCastMethod::kConservativeAdvancementOnce);
  });
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
    : FclPosed{fcl::Cylinderd(c.r, norm(c.q - c.p)), fcl::Transform3d::Identity()} {
  pose.linear() = fcl_rotation_z_to(unit(c.q - c.p));
  pose.translation() = to_fcl(0.5 * c.p + 0.5 * c.q);
}

FclSphere::FclSphere(const Sphere& s) : FclPosed{fcl::Sphered(s.r), fcl::Transform3d::Identity()} {
  pose.translation() = to_fcl(s.c);
}

FclCapsule::FclCapsule(const Capsule& c)
    : FclPosed{fcl::Capsuled(c.r, norm(c.q - c.p)), fcl::Transform3d::Identity()} {
  if (c.p != c.q) pose.linear() = fcl_rotation_z_to(unit(c.q - c.p));
  pose.translation() = to_fcl(0.5 * c.p + 0.5 * c.q);
}

FclBox::FclBox(const Obb& b)
    : FclPosed{fcl::Boxd(2 * b.e.x, 2 * b.e.y, 2 * b.e.z), fcl::Transform3d::Identity()} {
  // FCL takes the frame for a rotation: a left-handed one gets its third
  // axis negated, which leaves the (symmetric) box the same set.
  const bool left_handed = dot(cross(b.axes[0], b.axes[1]), b.axes[2]) < 0;
  fcl::Matrix3d r;
  r.col(0) = to_fcl(b.axes[0]);
  r.col(1) = to_fcl(b.axes[1]);
  r.col(2) = to_fcl(left_handed ? -b.axes[2] : b.axes[2]);
  pose.linear() = r;
  pose.translation() = to_fcl(b.c);
}

FclTriangle::FclTriangle(const Triangle& t) : a(to_fcl(t.a)), b(to_fcl(t.b)), c(to_fcl(t.c)) {}

namespace {

// The FCL calls on any converted pair (members a, b with shape and pose).
template <class Pair>
bool overlap_on(const Pair& pair) {
  fcl::CollisionRequestd req(1, false);
  req.gjk_solver_type = fcl::GST_LIBCCD;
  fcl::CollisionResultd res;
  return fcl::collide(&pair.a.shape, pair.a.pose, &pair.b.shape, pair.b.pose, req, res) > 0;
}

/// `zero_normal_touch`: accept libccd MPR's touching contact (pairs that run
/// MPR).
template <class Pair>
PeerContact collide_on(const Pair& pair, bool zero_normal_touch = false) {
  return guarded<PeerContact>([&]() -> PeerContact {
    fcl::CollisionRequestd req(1, true);
    req.gjk_solver_type = fcl::GST_LIBCCD;
    fcl::CollisionResultd res;
    fcl::collide(&pair.a.shape, pair.a.pose, &pair.b.shape, pair.b.pose, req, res);
    return contact_from(res, zero_normal_touch);
  });
}

template <class Pair>
PeerDistance distance_on(const Pair& pair) {
  return guarded<PeerDistance>([&]() -> PeerDistance {
    fcl::DistanceRequestd req(true);
    req.gjk_solver_type = fcl::GST_LIBCCD;
    fcl::DistanceResultd res;
    fcl::distance(&pair.a.shape, pair.a.pose, &pair.b.shape, pair.b.pose, req, res);
    return distance_from(res.min_distance, res.nearest_points[0], res.nearest_points[1]);
  });
}

/// The solver of FCL's per-triangle narrow phase as fcl::collide and
/// fcl::distance set it up before a mesh traversal (GST_LIBCCD, the
/// requests' default tolerances copied in).
fcl::detail::GJKSolver_libccdd triangle_solver() {
  fcl::detail::GJKSolver_libccdd solver;
  solver.collision_tolerance = fcl::CollisionRequestd().gjk_tolerance;
  solver.distance_tolerance = fcl::DistanceRequestd(true).distance_tolerance;
  return solver;
}

}  // namespace

// The converted pairs' calls, query by query (the triangle's and the
// mesh's are below).
bool fcl_overlap_prepared(const FclCylinderSphere& pair) { return overlap_on(pair); }
bool fcl_overlap_prepared(const FclCylinderCylinder& pair) { return overlap_on(pair); }
bool fcl_overlap_prepared(const FclCylinderCapsule& pair) { return overlap_on(pair); }
bool fcl_overlap_prepared(const FclCylinderBox& pair) { return overlap_on(pair); }
PeerContact fcl_collide_prepared(const FclCylinderSphere& pair) { return collide_on(pair); }
PeerContact fcl_collide_prepared(const FclCylinderCylinder& pair) { return collide_on(pair, true); }
PeerContact fcl_collide_prepared(const FclCylinderCapsule& pair) { return collide_on(pair); }
PeerContact fcl_collide_prepared(const FclCylinderBox& pair) { return collide_on(pair, true); }
PeerDistance fcl_distance_prepared(const FclCylinderSphere& pair) { return distance_on(pair); }
PeerDistance fcl_distance_prepared(const FclCylinderCylinder& pair) { return distance_on(pair); }
PeerDistance fcl_distance_prepared(const FclCylinderCapsule& pair) { return distance_on(pair); }
PeerDistance fcl_distance_prepared(const FclCylinderBox& pair) { return distance_on(pair); }

FclMesh::FclMesh(const TriangleMesh& m) {
  std::vector<fcl::Vector3d> points;
  points.reserve(m.vertices().size());
  for (const Vec3& v : m.vertices()) points.emplace_back(v.x, v.y, v.z);
  std::vector<fcl::Triangle> tris;
  tris.reserve(m.size());
  for (const MeshFace& f : m.faces()) tris.emplace_back(f[0], f[1], f[2]);
  model.beginModel(static_cast<int>(tris.size()), static_cast<int>(points.size()));
  model.addSubModel(points, tris);
  model.endModel();
}

PeerContact fcl_collide_prepared(const FclCylinder& cyl, const FclMesh& mesh, int max_contacts, int* contacts) {
  return guarded<PeerContact>([&]() -> PeerContact {
    fcl::CollisionRequestd req(static_cast<std::size_t>(std::max(max_contacts, 1)), true);
    req.gjk_solver_type = fcl::GST_LIBCCD;
    fcl::CollisionResultd res;
    fcl::collide(&mesh.model, fcl::Transform3d::Identity(), &cyl.shape, cyl.pose, req, res);
    if (contacts) *contacts = static_cast<int>(res.numContacts());
    if (!res.isCollision()) return no_contact();
    std::size_t deepest = 0;
    for (std::size_t i = 1; i < res.numContacts(); ++i)
      if (res.getContact(i).penetration_depth > res.getContact(deepest).penetration_depth) deepest = i;
    const fcl::Contactd& c = res.getContact(deepest);
    return contact_from(c.pos, -c.normal, c.penetration_depth, true);
  });
}

bool fcl_overlap_prepared(const FclCylinderTriangle& pair) {
  return triangle_solver().shapeTriangleIntersect(pair.a.shape, pair.a.pose, pair.b.a, pair.b.b, pair.b.c);
}

PeerContact fcl_collide_prepared(const FclCylinderTriangle& pair) {
  return guarded<PeerContact>([&]() -> PeerContact {
    fcl::Vector3d point = fcl::Vector3d::Zero(), normal = fcl::Vector3d::Zero();
    double depth = 0;
    if (!triangle_solver().shapeTriangleIntersect(pair.a.shape, pair.a.pose, pair.b.a, pair.b.b, pair.b.c, &point,
                                                  &depth, &normal)) {
      return no_contact();
    }
    return contact_from(point, normal, depth, true);
  });
}

PeerDistance fcl_distance_prepared(const FclCylinderTriangle& pair) {
  return guarded<PeerDistance>([&]() -> PeerDistance {
    double dist = 0;
    fcl::Vector3d p1 = fcl::Vector3d::Zero(), p2 = fcl::Vector3d::Zero();
    triangle_solver().shapeTriangleDistance(pair.a.shape, pair.a.pose, pair.b.a, pair.b.b, pair.b.c, &dist, &p1, &p2);
    return distance_from(dist, p1, p2);
  });
}

PeerContact fcl_collide(const Cylinder& a, const Sphere& b) {
  return validated<PeerContact>(a, b, [&]() -> PeerContact {
    return fcl_collide_prepared(FclCylinderSphere(a, b));
  });
}

bool fcl_overlap(const Cylinder& a, const Sphere& b, std::string* error) {
  return validated_bool(a, b, error, [&]() -> bool {
    return fcl_overlap_prepared(FclCylinderSphere(a, b));
  });
}

PeerDistance fcl_distance(const Cylinder& a, const Sphere& b) {
  return validated<PeerDistance>(a, b, [&]() -> PeerDistance {
    return distance_on(FclCylinderSphere(a, b));
  });
}

PeerCast fcl_cast(const Segment& s, const Cylinder& c, FclCastMethod method) {
  return continuous_collide(s, c, method);
}

PeerCast fcl_sweep(const MovingSphere& m, const Cylinder& c, FclCastMethod method) {
  return continuous_collide(m, c, method);
}

// The pairs that run libccd's MPR and GJK, guarded: one template per query,
// each followed by its overloads.

namespace {

/// The converted pair of a cylinder and B.
template <class B> struct PairOf;
template <> struct PairOf<Capsule> { using type = FclCylinderCapsule; };
template <> struct PairOf<Obb> { using type = FclCylinderBox; };
template <> struct PairOf<Triangle> { using type = FclCylinderTriangle; };
template <> struct PairOf<Cylinder> { using type = FclCylinderCylinder; };

/// fcl_collide of the pairs that run libccd's MPR: guarded, validated.
template <class B>
PeerContact guarded_collide(const Cylinder& a, const B& b) {
  return validated<PeerContact>(a, b, [&]() -> PeerContact {
    const typename PairOf<B>::type pair(a, b);
    const MprAnswer r = guarded_mpr(libccd(pair.a), libccd(pair.b), true);
    if (r.error) {
      PeerContact out;
      out.error = r.error;
      return out;
    }
    if (!r.hit) return no_contact();
    return contact_from(r.point, r.normal, r.depth, true);
  });
}

}  // namespace

PeerContact fcl_collide(const Cylinder& a, const Capsule& b) { return guarded_collide(a, b); }
PeerContact fcl_collide(const Cylinder& a, const Obb& b) { return guarded_collide(a, b); }
PeerContact fcl_collide(const Cylinder& a, const Triangle& b) { return guarded_collide(a, b); }
PeerContact fcl_collide(const Cylinder& a, const Cylinder& b) { return guarded_collide(a, b); }

namespace {

/// fcl_overlap of the pairs that run libccd's MPR: guarded, validated.
template <class B>
bool guarded_overlap(const Cylinder& a, const B& b, std::string* error) {
  return validated_bool(a, b, error, [&]() -> bool {
    const typename PairOf<B>::type pair(a, b);
    const MprAnswer r = guarded_mpr(libccd(pair.a), libccd(pair.b), false);
    if (!r.error) return r.hit;
    if (error) *error = r.error;
    return false;
  });
}

}  // namespace

bool fcl_overlap(const Cylinder& a, const Capsule& b, std::string* error) { return guarded_overlap(a, b, error); }
bool fcl_overlap(const Cylinder& a, const Obb& b, std::string* error) { return guarded_overlap(a, b, error); }
bool fcl_overlap(const Cylinder& a, const Triangle& b, std::string* error) { return guarded_overlap(a, b, error); }
bool fcl_overlap(const Cylinder& a, const Cylinder& b, std::string* error) { return guarded_overlap(a, b, error); }

namespace {

/// fcl_distance of the pairs that run libccd's GJK: guarded, validated,
/// within GJK's range.
template <class B>
PeerDistance guarded_distance(const Cylinder& a, const B& b) {
  return validated<PeerDistance>(a, b, [&]() -> PeerDistance {
    if (!within_gjk_range(a, b)) {
      PeerDistance out;
      out.error = "outside FCL's range";
      return out;
    }
    const typename PairOf<B>::type pair(a, b);
    return guarded_gjk_distance(libccd(pair.a), libccd(pair.b));
  });
}

}  // namespace

PeerDistance fcl_distance(const Cylinder& a, const Capsule& b) { return guarded_distance(a, b); }
PeerDistance fcl_distance(const Cylinder& a, const Obb& b) { return guarded_distance(a, b); }
PeerDistance fcl_distance(const Cylinder& a, const Triangle& b) { return guarded_distance(a, b); }
PeerDistance fcl_distance(const Cylinder& a, const Cylinder& b) { return guarded_distance(a, b); }

}  // namespace geomcheck::oracles
