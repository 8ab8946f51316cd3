// geomcheck — libccd re-entered (internal to peers/fcl/src): FCL's own MPR
// and GJK calls made as FCL makes them, on FCL's support functions wrapped
// in a budget and a finiteness check, so that a call that would hang or
// abort the process answers "not ok" instead.
#pragma once

#include <cmath>
#include <type_traits>

#include <ccd/vec3.h>
#include <fcl/narrowphase/collision_request.h>
#include <fcl/narrowphase/detail/convexity_based_algorithm/gjk_libccd.h>
#include <fcl/narrowphase/detail/gjk_solver_libccd.h>
#include <fcl/narrowphase/distance_request.h>

#include "fcl_guards.hpp"
#include "geomcheck/peers/fcl_convert.hpp"

namespace geomcheck::peers::fcl_detail {

// --- libccd's MPR and GJK with guarded support functions ----------------------
//
// For every pair without a closed form of FCL's own (fcl_adapter.hpp,
// kFclClosedForm) FCL runs libccd's MPR (collide) and GJK (distance) on
// support functions, and so does its per-triangle narrow phase. Two defects of FCL 0.7 / libccd 2.1 make the raw
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
/// The guard of the calling thread's current libccd call (nullptr outside one).
extern thread_local SupportGuard* t_support_guard;

/// FCL's support function of the guarded object, budgeted and checked (see above).
void guarded_support(const void* obj, const ccd_vec3_t* dir, ccd_vec3_t* v);

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
inline LibccdTriangle libccd(const FclTriangle& t) { return {t.a, t.b, t.c}; }

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
inline const double kGjkMaxExtent = std::ldexp(1.0, 250);

/// Whether (a, b) lies within GJK's range: the shapes' offsets and sizes
/// (`extent`) at most kGjkMaxExtent (false for NaN too).
template <class A, class B>
bool within_gjk_range(const A& a, const B& b) {
  return extent(a, b) <= kGjkMaxExtent;
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

}  // namespace geomcheck::peers::fcl_detail
