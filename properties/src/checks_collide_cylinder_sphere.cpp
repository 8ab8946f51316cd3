// geomcheck — the checks of collide_cylinder_sphere (declared for every query in checks.hpp).
//
// check_oracle: Agreement with the exact oracle outside the band; depth,
// normal, point within bounds.
// check_consistency: overlap == collide.hit; unit normal; depth >= 0 equals
// the overlap along the normal; no NaN.
// check_symmetry: (A,B) and (B,A) agree, normal flips; caps swapped gives the
// same answer (to the band).
// check_metamorphic: Sign flips and power-of-two scales bit-identical; axis
// permutations and rigid motions agree outside the band.
// check_monotone: Growing the sphere or the cylinder radius never turns
// overlap into separation.
#include <cmath>
#include <cstdio>
#include <sstream>

#include "geomcheck/collide_cylinder_sphere.hpp"
#include "geomcheck/oracles/cylinder_sphere.hpp"
#include "geomcheck/properties/checks.hpp"
#include "geomcheck/properties/teeth.hpp"
#include "geomcheck/properties/tolerances.hpp"
#include "geomcheck/shape_traits.hpp"
#include "common.hpp"
#include "contact_checks.hpp"
#include "moves.hpp"

namespace geomcheck {

// The spec of collide_cylinder_sphere: cylinder/sphere: overlap and collide with the true penetration depth.
GEOMCHECK_SPEC(collide_cylinder_sphere, 100000,
               (Claims{true, Claims::Depth::Penetration, true, "unit, from the cylinder towards the sphere: the minimal translation", "closed form (oracles/src/cylinder_sphere.cpp): exact verdict, certified signed distance"}),
               (Tolerances{/*verdict*/ 1e-14, /*depth*/ 1e-14, /*normal*/ 1e-14, /*point*/ 1e-14, /*t*/ 0, /*unit*/ 1e-14}),
               &teeth::kCapsuleForCylinder)

void hold_to_truth(Evaluation& e, const CylinderSphereCase& c, const Contact& ct, const Contact* peer) {
  const Tolerances& tol = e.tol;
  const oracle::QCylinder qa = oracle::to_q(c.a);
  const oracle::QSphere qb = oracle::to_q(c.b);
  const auto truth = oracle::solve_cylinder_sphere(qa, qb);
  e.verdict = truth.verdict;
  e.truth_hit = truth.verdict != oracle::Verdict::Separated;
  e.signed_distance = truth.signed_distance.mid();
  e.truth_text = std::string(oracle::to_string(truth.verdict)) +
                 " signed_distance=" + oracle::to_string(truth.signed_distance);
  e.disagree = e.prod_hit != e.truth_hit;
  // Near the boundary unless certainly farther than the band from touching.
  const oracle::Q qband = times_scale(tol.verdict, e.scale);
  e.near_boundary = !(truth.signed_distance.lo > qband || truth.signed_distance.hi < -qband);
  if (e.disagree) {
    e.margin = std::fabs(e.signed_distance) / e.scale;
    e.excused = e.near_boundary;
  }
  if (truth.verdict == oracle::Verdict::Separated) e.distance = truth.signed_distance.mid();
  // One contact (production's or the peer's) against the truth.
  auto score = [&](const Contact& k, double& unit_err, double& depth_err, double& normal_err, double& point_err) {
    if (!k.hit || !finite_contact(k)) return;
    unit_err = std::fabs(length(k.normal) - 1);
    if (!e.truth_hit) return;
    const oracle::QInterval depth = -truth.signed_distance;
    // A depth beyond the largest double has no exact answer in doubles
    // (production saturates): no depth error is measured then.
    if (std::isfinite(oracle::to_double(depth.hi))) depth_err = rel_error(depth, k.depth, e.scale);
    if (max_abs(k.normal) > 0) {
      const oracle::QInterval along = oracle::overlap_along(qa, qb, oracle::to_q(k.normal));
      normal_err = rel_up(along.hi - depth.lo, e.scale);
    }
    const oracle::QVec x = oracle::to_q(k.point);
    const oracle::QInterval da = oracle::signed_distance(qa, x), db = oracle::signed_distance(qb, x);
    const oracle::Q out = da.hi > db.hi ? da.hi : db.hi;
    point_err = out > 0 ? rel_up(out, e.scale) : 0.0;
  };
  score(ct, e.unit_err, e.depth_err, e.normal_err, e.point_err);
  if (peer) score(*peer, e.peer.unit_err, e.peer.depth_err, e.peer.normal_err, e.peer.point_err);
  if (ct.hit && e.truth_hit) score_depth_sides(e, -truth.signed_distance, ct.depth);
}

CheckResult check_consistency(const CylinderSphereCase& c, const CylinderSphereImpl& impl) {
  const bool ov = impl.overlap(c.a, c.b);
  const Contact ct = impl.collide(c.a, c.b);
  if (ov != ct.hit) return Failure{"consistency-overlap-vs-collide", describe(ct, ov)};
  if (!ct.hit) return std::nullopt;
  if (!finite_contact(ct)) return Failure{"consistency-finite", describe(ct, ov)};
  const Tolerances tol = bounds(c, impl);
  if (std::fabs(length(ct.normal) - 1) > tol.unit) return Failure{"consistency-unit-normal", describe(ct, ov)};
  if (!(ct.depth >= 0)) return Failure{"consistency-depth-nonnegative", describe(ct, ov)};
  if (!valid_case(c)) return std::nullopt;
  // depth equals the overlap of the shapes along the returned normal.
  const double scale = oracle::case_scale(c.a, c.b);
  const oracle::QInterval along = oracle::overlap_along(oracle::to_q(c.a), oracle::to_q(c.b), oracle::to_q(ct.normal));
  const double err = rel_error(along, ct.depth, scale);
  const double bound = tol.depth;
  if (err > bound)
    return Failure{"consistency-depth-along-normal",
                   fmt("|depth - overlap along normal| = %.3g * scale > %.3g; ", err, bound) + describe(ct, ov)};
  return std::nullopt;
}

CheckResult check_symmetry(const CylinderSphereCase& c, const CylinderSphereImpl& impl) {
  if (auto f = argument_order(c, impl)) return f;
  const bool ov = impl.overlap(c.a, c.b);
  const Contact ct = impl.collide(c.a, c.b);
  // Same solid, caps swapped.
  const CylinderSphereCase s{{c.a.q, c.a.p, c.a.r}, c.b};
  if (!subject_states(s, impl)) return std::nullopt;
  const bool ov2 = impl.overlap(s.a, s.b);
  if (ov2 != ov && valid_case(c)) {
    // The truth is the same for both; the one that disagrees with it must be inside the band.
    const Evaluation e = evaluate(s, impl);
    const Evaluation e0 = evaluate(c, impl);
    if (!(e.excused || e0.excused))
      return Failure{"symmetry-caps-swapped", "overlap " + std::string(ov ? "yes" : "no") + " becomes " + (ov2 ? "yes" : "no") +
                                                  " with caps swapped; oracle: " + e0.truth_text, s};
  }
  if (ov == ov2 && ov && valid_case(c)) {
    const Contact c2 = impl.collide(s.a, s.b);
    const double scale = oracle::case_scale(c.a, c.b);
    const double d = std::fabs(c2.depth - ct.depth) / scale;
    if (d > 2 * bounds(c, impl).depth)
      return Failure{"symmetry-caps-swapped-depth", fmt("depth differs by %.3g * scale; ", d) + describe(ct, ov) + " vs " + describe(c2, ov2), s};
  }
  return std::nullopt;
}

CheckResult check_metamorphic(const CylinderSphereCase& c, int move, const CylinderSphereImpl& impl) {
  // On the axis the side normal is any perpendicular (a free choice), so
  // only there the normal may differ. Production treats a radial offset at
  // the rounding level of the case as no direction (then any perpendicular
  // is a minimal-translation normal, and check_oracle holds it to that); the
  // same notion here.
  auto kept = [&](const CylinderSphereCase&, const MovedAnswers& a) -> CheckResult {
    const Vec3 d = c.a.q - c.a.p;
    const double rho = length(cross(c.b.c - c.a.p, d)) / length(d);
    const bool free_normal = !(rho > 64 * 0x1p-52 * oracle::case_scale(c.a, c.b));
    if (a.m.pt(a.ct.point) == a.ct2.point && (free_normal || a.m.vec(a.ct.normal) == a.ct2.normal) &&
        a.m.len(a.ct.depth) == a.ct2.depth)
      return std::nullopt;
    return a.not_identical();
  };
  return collide_metamorphic(
      c, move, impl, valid_case<CylinderSphereCase>, [](const CylinderSphereCase& x) { return moves::rigid_slack(x.a); }, kept);
}

CheckResult check_monotone(const CylinderSphereCase& c, const CylinderSphereImpl& impl) {
  if (!valid_case(c) || !impl.overlap(c.a, c.b)) return std::nullopt;
  // An overlap lost by a bigger ball or cylinder is a failure unless one of
  // the two cases is within the subject's band of touching (overlap_lost).
  const double grow[] = {std::nextafter(c.b.r, INFINITY), c.b.r * 2 + 1e-300, c.b.r + 0.5 * c.a.r};
  for (double r : grow) {
    const CylinderSphereCase bigger{c.a, Sphere{c.b.c, r}};
    if (std::isfinite(r) && overlap_lost(c, bigger, impl))
      return Failure{"monotone-sphere-radius", fmt("overlap with sphere radius %.17g but not with %.17g", c.b.r, r),
                     bigger};
  }
  return cylinder_a_radius_kept(c, impl);
}

}  // namespace geomcheck
