// geomcheck — the checks of collide_cylinder_capsule (declared for every query in checks.hpp).
//
// check_oracle: Agreement with the engine outside the band; the depth claim
// (shallow contacts: true depth and minimal-translation normal), point in
// both.
// check_consistency: overlap == collide.hit; unit normal; depth >= 0 equals
// the overlap along the normal; no NaN.
// check_symmetry: (A,B) and (B,A) agree, normal flips; caps swapped, capsule
// reversed: same verdict (band), same depth.
// check_monotone: Growing either radius never turns overlap into separation
// (outside the band).
#include <cmath>
#include <sstream>

#include "truth.hpp"
#include "common.hpp"
#include "contact_checks.hpp"
#include "geomcheck/collide_cylinder_capsule.hpp"
#include "geomcheck/oracles/cylinder_sphere.hpp"
#include "geomcheck/properties/checks.hpp"
#include "geomcheck/properties/teeth.hpp"
#include "geomcheck/properties/tolerances.hpp"
#include "moves.hpp"

namespace geomcheck {

// The spec of collide_cylinder_capsule: cylinder/capsule: exact verdict; the true depth while the capsule's segment stays outside the cylinder.
GEOMCHECK_SPEC(collide_cylinder_capsule, 100000,
               (Claims{true, Claims::Depth::Shallow, true, "unit, from the cylinder towards the capsule", "certified engine (capsule = segment + ball): exact verdict, certified signed distance and penetration depth"}),
               (Tolerances{/*verdict*/ 1e-14, /*depth*/ 1e-14, /*normal*/ 1e-12, /*point*/ 1e-14, /*t*/ 0, /*unit*/ 1e-14}),
               &teeth::kCapsuleCapsule)

void hold_to_truth(Evaluation& e, const CylinderCapsuleCase& c, const Contact& ct, const Contact* peer) {
  const Tolerances& tol = e.tol;
  const oracle::ConvexShape cyl = oracle::make_shape(c.a);
  const QVec p = oracle::to_q(c.b.p), q = oracle::to_q(c.b.q);
  const Q r = oracle::to_q(c.b.r);
  const Q band = times_scale(tol.verdict, e.scale);
  const CapsuleTruth truth = capsule_truth(cyl, p, q, r, band);
  settle_verdict(e, truth, band);
  // One contact (production's or the peer's) against the truth.
  auto score = [&](const Contact& k, double& unit_err, double& depth_err, double& normal_err, double& point_err) {
    if (!k.hit || !finite_contact(k)) return;
    unit_err = std::fabs(length(k.normal) - 1);
    if (!e.truth_hit) return;
    // The depth claim holds for shallow contacts: the segment certainly
    // outside the cylinder by 1e-6 * scale (production's shallow branch
    // starts at 2^-20 * scene, just below).
    if (truth.core_outside && truth.core_distance.lo > times_scale(1e-6, e.scale)) {
      const QInterval depth = -truth.signed_distance;
      if (std::isfinite(oracle::to_double(depth.hi))) depth_err = rel_error(depth, k.depth, e.scale);
      // The normal is the direction between the closest points: its angle
      // is only as good as eps * scale / D, and the capsule's extent turns
      // an angle into excess overlap. It is held to the claim where the
      // segment is at least 1e-6 * scale outside (see the header).
      if (max_abs(k.normal) > 0) {
        const QInterval along = overlap_along(cyl, oracle::make_capsule(p, q, r), oracle::to_q(k.normal));
        normal_err = rel_up(along.hi - depth.lo, e.scale);
      }
    }
    const QVec x = oracle::to_q(k.point);
    const QInterval da = oracle::signed_distance(oracle::to_q(c.a), x);
    const QInterval db = capsule_signed_distance(p, q, r, x);
    const Q out = da.hi > db.hi ? da.hi : db.hi;
    point_err = out > 0 ? rel_up(out, e.scale) : 0.0;
  };
  score(ct, e.unit_err, e.depth_err, e.normal_err, e.point_err);
  if (peer) score(*peer, e.peer.unit_err, e.peer.depth_err, e.peer.normal_err, e.peer.point_err);
  // The sides of the penetration depth where the truth gives it (shallow).
  if (ct.hit && e.truth_hit && truth.core_outside && truth.core_distance.lo > times_scale(1e-6, e.scale))
    score_depth_sides(e, -truth.signed_distance, ct.depth);
}

CheckResult check_consistency(const CylinderCapsuleCase& c, const CylinderCapsuleImpl& impl) {
  // The overlap along the normal is the true depth plus the normal's excess
  // (first order in its angle for a capsule), in the shallow and the deep
  // branch alike: both bounds together.
  const bool exact = valid_case(c);
  return consistent_contact(kId, c, impl, exact, bounds(c, impl).depth + bounds(c, impl).normal);
}

namespace {
// Same solid, other representation: depths are compared where they are
// claimed (shallow contacts): a deep contact's depth is the best of a few
// candidate directions, not canonical.
CheckResult same_answer(const char* what, const CylinderCapsuleCase& c0, const CylinderCapsuleCase& c1,
                        const CylinderCapsuleImpl& impl) {
  auto claimed = [&](const CylinderCapsuleCase& k) { return !std::isnan(evaluate(k, impl).depth_err); };
  return geomcheck::same_answer(what, c0, c1, impl, 2 * bounds(c0, impl).depth, claimed);
}
}  // namespace

CheckResult check_symmetry(const CylinderCapsuleCase& c, const CylinderCapsuleImpl& impl) {
  if (auto f = argument_order(c, impl)) return f;
  if (!valid_case(c)) return std::nullopt;
  if (auto f = same_answer("symmetry-caps-swapped", c, {{c.a.q, c.a.p, c.a.r}, c.b}, impl)) return f;
  return same_answer("symmetry-capsule-reversed", c, {c.a, {c.b.q, c.b.p, c.b.r}}, impl);
}

CheckResult check_metamorphic(const CylinderCapsuleCase& c, int move, const CylinderCapsuleImpl& impl) {
  auto kept = [&](const CylinderCapsuleCase&, const MovedAnswers& a) -> CheckResult {
    // The normal is a free choice where the contact's radial offset is at
    // the rounding level (then any perpendicular serves): production's
    // contact point on the axis line.
    const Vec3 d = c.a.q - c.a.p;
    const double rho = length(cross(a.ct.point - c.a.p, d)) / length(d);
    const bool free_normal = !(rho > 64 * 0x1p-52 * oracle::case_scale(c.a, c.b));
    const bool same_but_normal = a.m.pt(a.ct.point) == a.ct2.point && a.m.len(a.ct.depth) == a.ct2.depth;
    if (same_but_normal && (free_normal || a.m.vec(a.ct.normal) == a.ct2.normal)) return std::nullopt;
    // A deep contact's normal is the best of a few candidate directions:
    // on a tie (a symmetric scene) either is right, and consistency holds
    // each to depth = overlap along it. Point and depth stay bit-identical.
    if (same_but_normal && std::isnan(evaluate(c, impl).depth_err)) return std::nullopt;
    return a.not_identical();
  };
  return collide_metamorphic(
      c, move, impl, valid_case<CylinderCapsuleCase>, [](const CylinderCapsuleCase& x) { return moves::rigid_slack(x.a); }, kept);
}

CheckResult check_monotone(const CylinderCapsuleCase& c, const CylinderCapsuleImpl& impl) {
  if (!valid_case(c) || !impl.overlap(c.a, c.b)) return std::nullopt;
  // The distance of the capsule's segment is a minimum over candidates that
  // move with the radii, so production is monotone only outside the band:
  // an overlap lost by a bigger radius is a failure unless one of the two
  // cases is within the band of touching.
  auto lost = [&](const CylinderCapsuleCase& bigger) { return overlap_lost(c, bigger, impl); };
  const double grow[] = {std::nextafter(c.b.r, INFINITY), c.b.r * 2 + 1e-300, c.b.r + 0.5 * c.a.r};
  for (double r : grow) {
    const CylinderCapsuleCase bigger{c.a, Capsule{c.b.p, c.b.q, r}};
    if (std::isfinite(r) && lost(bigger))
      return Failure{"monotone-capsule-radius", fmt("overlap with capsule radius %.17g but not with %.17g", c.b.r, r),
                     bigger};
  }
  const double rc = std::nextafter(c.a.r, INFINITY);
  const CylinderCapsuleCase wider{Cylinder{c.a.p, c.a.q, rc}, c.b};
  if (std::isfinite(rc) && lost(wider))
    return Failure{"monotone-cylinder-radius", fmt("overlap with cylinder radius %.17g but not with %.17g", c.a.r, rc),
                   wider};
  return std::nullopt;
}

}  // namespace geomcheck
