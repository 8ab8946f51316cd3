// geomcheck — FCL asked about a pair of shapes (fcl_adapter.hpp): collide,
// overlap and distance, on every pair with kFclAsks, written once. Where FCL
// has a closed form of its own the adapter calls FCL (fcl::collide,
// fcl::distance, the per-triangle solver) guarded against exceptions; where
// FCL runs libccd's MPR or GJK the adapter runs them itself as FCL does,
// on guarded support functions (fcl_libccd.hpp). The prepared calls
// (fcl_convert.hpp) are FCL as shipped, for the benchmarks.
#include <type_traits>

#include <fcl/narrowphase/collision.h>
#include <fcl/narrowphase/distance.h>

#include "fcl_guards.hpp"
#include "fcl_libccd.hpp"
#include "geomcheck/peers/fcl_convert.hpp"

namespace geomcheck::peers {

namespace {

using namespace fcl_detail;

/// The solver of FCL's per-triangle narrow phase as fcl::collide and
/// fcl::distance set it up before a mesh traversal (GST_LIBCCD, the
/// requests' default tolerances copied in).
fcl::detail::GJKSolver_libccdd triangle_solver() {
  fcl::detail::GJKSolver_libccdd solver;
  solver.collision_tolerance = fcl::CollisionRequestd().gjk_tolerance;
  solver.distance_tolerance = fcl::DistanceRequestd(true).distance_tolerance;
  return solver;
}

template <class B>
constexpr bool kTriangle = std::is_same_v<B, Triangle>;

}  // namespace

template <class A, class B>
bool fcl_overlap_prepared(const FclPair<A, B>& pair) {
  if constexpr (kTriangle<B>) {
    return triangle_solver().shapeTriangleIntersect(pair.a.shape, pair.a.pose, pair.b.a, pair.b.b, pair.b.c);
  } else {
    fcl::CollisionRequestd req(1, false);
    req.gjk_solver_type = fcl::GST_LIBCCD;
    fcl::CollisionResultd res;
    return fcl::collide(&pair.a.shape, pair.a.pose, &pair.b.shape, pair.b.pose, req, res) > 0;
  }
}

template <class A, class B>
PeerContact fcl_collide_prepared(const FclPair<A, B>& pair) {
  // libccd's MPR sets no normal for a touching contact: accepted where it runs.
  constexpr bool kMpr = !kFclClosedFormCollide<A, B>;
  return guarded<PeerContact>([&]() -> PeerContact {
    if constexpr (kTriangle<B>) {
      fcl::Vector3d point = fcl::Vector3d::Zero(), normal = fcl::Vector3d::Zero();
      double depth = 0;
      if (!triangle_solver().shapeTriangleIntersect(pair.a.shape, pair.a.pose, pair.b.a, pair.b.b, pair.b.c, &point,
                                                    &depth, &normal)) {
        return no_contact();
      }
      return contact_from(point, normal, depth, kMpr);
    } else {
      fcl::CollisionRequestd req(1, true);
      req.gjk_solver_type = fcl::GST_LIBCCD;
      fcl::CollisionResultd res;
      fcl::collide(&pair.a.shape, pair.a.pose, &pair.b.shape, pair.b.pose, req, res);
      return contact_from(res, kMpr);
    }
  });
}

template <class A, class B>
PeerDistance fcl_distance_prepared(const FclPair<A, B>& pair) {
  return guarded<PeerDistance>([&]() -> PeerDistance {
    if constexpr (kTriangle<B>) {
      double dist = 0;
      fcl::Vector3d p1 = fcl::Vector3d::Zero(), p2 = fcl::Vector3d::Zero();
      triangle_solver().shapeTriangleDistance(pair.a.shape, pair.a.pose, pair.b.a, pair.b.b, pair.b.c, &dist, &p1,
                                              &p2);
      return distance_from(dist, p1, p2);
    } else {
      fcl::DistanceRequestd req(true);
      req.gjk_solver_type = fcl::GST_LIBCCD;
      fcl::DistanceResultd res;
      fcl::distance(&pair.a.shape, pair.a.pose, &pair.b.shape, pair.b.pose, req, res);
      return distance_from(res.min_distance, res.nearest_points[0], res.nearest_points[1]);
    }
  });
}

template <class A, class B>
PeerContact fcl_collide(const A& a, const B& b) {
  return validated<PeerContact>(a, b, [&]() -> PeerContact {
    const FclPair<A, B> pair(a, b);
    if constexpr (kFclClosedFormCollide<A, B>) {
      return fcl_collide_prepared(pair);
    } else {
      const MprAnswer r = guarded_mpr(libccd(pair.a), libccd(pair.b), true);
      if (r.error) return failed<PeerContact>(r.error);
      if (!r.hit) return no_contact();
      return contact_from(r.point, r.normal, r.depth, true);
    }
  });
}

template <class A, class B>
bool fcl_overlap(const A& a, const B& b, std::string* error) {
  return validated_bool(a, b, error, [&]() -> bool {
    const FclPair<A, B> pair(a, b);
    if constexpr (kFclClosedFormCollide<A, B>) {
      return fcl_overlap_prepared(pair);
    } else {
      const MprAnswer r = guarded_mpr(libccd(pair.a), libccd(pair.b), false);
      if (!r.error) return r.hit;
      if (error) *error = r.error;
      return false;
    }
  });
}

template <class A, class B>
PeerDistance fcl_distance(const A& a, const B& b) {
  return validated<PeerDistance>(a, b, [&]() -> PeerDistance {
    const FclPair<A, B> pair(a, b);
    if constexpr (kFclClosedFormDistance<A, B>) {
      return fcl_distance_prepared(pair);
    } else {
      if (!within_gjk_range(a, b)) return failed<PeerDistance>("outside FCL's range");
      return guarded_gjk_distance(libccd(pair.a), libccd(pair.b));
    }
  });
}

#define GEOMCHECK_FCL_PAIR(A, B)                                                    \
  static_assert(kFclAsks<A, B>);                                                    \
  template bool fcl_overlap_prepared(const FclPair<A, B>&);                        \
  template PeerContact fcl_collide_prepared(const FclPair<A, B>&);                 \
  template PeerDistance fcl_distance_prepared(const FclPair<A, B>&);               \
  template PeerContact fcl_collide(const A&, const B&);                            \
  template bool fcl_overlap(const A&, const B&, std::string*);                     \
  template PeerDistance fcl_distance(const A&, const B&);
GEOMCHECK_FCL_PAIRS
#undef GEOMCHECK_FCL_PAIR

}  // namespace geomcheck::peers
