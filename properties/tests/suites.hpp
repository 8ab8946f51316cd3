// geomcheck — per-query facts the generic suites need: generators, how a
// case "hits", production.
#pragma once

#include "generators.hpp"
#include "geomcheck/cast_segment_cylinder.hpp"
#include "geomcheck/collide_cylinder_capsule.hpp"
#include "geomcheck/collide_cylinder_cylinder.hpp"
#include "geomcheck/collide_cylinder_obb.hpp"
#include "geomcheck/collide_cylinder_sphere.hpp"
#include "geomcheck/collide_cylinder_triangle.hpp"
#include "support.hpp"

namespace geomcheck {

template <QueryId Q> struct Suite;

template <> struct Suite<QueryId::collide_cylinder_sphere> {
  using Case = CylinderSphereCase;
  using Impl = CylinderSphereImpl;
  static rc::Gen<std::pair<Case, std::string>> targeted() { return gen::cylinder_sphere_case(); }
  static rc::Gen<Case> wild() { return gen::wild_cylinder_sphere(); }
  static bool hit(const Case& c, const Impl& impl = kProductionCylinderSphere) { return impl.overlap(c.a, c.b); }
};

template <> struct Suite<QueryId::cast_segment_cylinder> {
  using Case = SegmentCylinderCase;
  using Impl = CastSegmentCylinderImpl;
  static rc::Gen<std::pair<Case, std::string>> targeted() { return gen::segment_cylinder_case(); }
  static rc::Gen<Case> wild() { return gen::wild_segment_cylinder(); }
  static bool hit(const Case& c, const Impl& impl = kProductionCastSegmentCylinder) { return impl.cast(c.a, c.b).hit; }
};

template <> struct Suite<QueryId::collide_cylinder_capsule> {
  using Case = CylinderCapsuleCase;
  using Impl = CylinderCapsuleImpl;
  static rc::Gen<std::pair<Case, std::string>> targeted() { return gen::cylinder_capsule_case(); }
  static rc::Gen<Case> wild() { return gen::wild_cylinder_capsule(); }
  static bool hit(const Case& c, const Impl& impl = kProductionCylinderCapsule) { return impl.overlap(c.a, c.b); }
};

template <> struct Suite<QueryId::sweep_sphere_cylinder> {
  using Case = SweepCylinderCase;
  using Impl = SweepSphereCylinderImpl;
  static rc::Gen<std::pair<Case, std::string>> targeted() { return gen::sweep_cylinder_case(); }
  static rc::Gen<Case> wild() { return gen::wild_sweep_cylinder(); }
  static bool hit(const Case& c, const Impl& impl = kProductionSweepSphereCylinder) { return impl.sweep(c.a, c.b).hit; }
};

template <> struct Suite<QueryId::collide_cylinder_obb> {
  using Case = CylinderObbCase;
  using Impl = CylinderObbImpl;
  static rc::Gen<std::pair<Case, std::string>> targeted() { return gen::cylinder_obb_case(); }
  static rc::Gen<Case> wild() { return gen::wild_cylinder_obb(); }
  static bool hit(const Case& c, const Impl& impl = kProductionCylinderObb) { return impl.overlap(c.a, c.b); }
};

template <> struct Suite<QueryId::collide_cylinder_triangle> {
  using Case = CylinderTriangleCase;
  using Impl = CylinderTriangleImpl;
  static rc::Gen<std::pair<Case, std::string>> targeted() { return gen::cylinder_triangle_case(); }
  static rc::Gen<Case> wild() { return gen::wild_cylinder_triangle(); }
  static bool hit(const Case& c, const Impl& impl = kProductionCylinderTriangle) { return impl.overlap(c.a, c.b); }
};

template <> struct Suite<QueryId::collide_cylinder_cylinder> {
  using Case = CylinderCylinderCase;
  using Impl = CylinderCylinderImpl;
  static rc::Gen<std::pair<Case, std::string>> targeted() { return gen::cylinder_cylinder_case(); }
  static rc::Gen<Case> wild() { return gen::wild_cylinder_cylinder(); }
  static bool hit(const Case& c, const Impl& impl = kProductionCylinderCylinder) { return impl.overlap(c.a, c.b); }
};

/// Half wild raw doubles (NaN, inf, subnormal, huge), half targeted cases.
template <QueryId Q>
rc::Gen<std::pair<typename Suite<Q>::Case, std::string>> robust_gen() {
  using Case = typename Suite<Q>::Case;
  return rc::gen::oneOf(
      Suite<Q>::targeted(),
      rc::gen::map(Suite<Q>::wild(), [](const Case& c) { return std::pair<Case, std::string>{c, "wild"}; }));
}

}  // namespace geomcheck
