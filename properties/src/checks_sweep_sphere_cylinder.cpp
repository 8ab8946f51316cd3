// geomcheck — the checks of sweep_sphere_cylinder (declared for every query in checks.hpp).
//
// check_oracle: Hit/miss agrees with the engine (the swept capsule against the
// cylinder) outside the band; t: the ball at t touches (to the bound) and the
// sweep up to t stays out (bracketing, certified by the engine); point on the
// cylinder at the ball; normal in the normal cone there.
// check_consistency: t in [0,1]; starts_inside iff the ball meets the cylinder
// at t = 0 (overlap(Cylinder, Sphere)); the ball at t meets the cylinder and
// just before t does not (collide(Cylinder, Sphere)); the swept capsule up to
// 1 agrees with overlap(Cylinder, Capsule) outside the band.
// check_symmetry: Caps swapped: same answer to the bounds.
// check_monotone: A bigger ball, a wider cylinder or a longer sweep never
// turns a hit into a miss (outside the band).
#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "truth.hpp"
#include "common.hpp"
#include "geomcheck/collide_cylinder_capsule.hpp"
#include "geomcheck/collide_cylinder_sphere.hpp"
#include "geomcheck/oracles/cast_segment_cylinder.hpp"
#include "geomcheck/oracles/cylinder_sphere.hpp"
#include "geomcheck/properties/checks.hpp"
#include "geomcheck/properties/teeth.hpp"
#include "geomcheck/properties/tolerances.hpp"
#include "geomcheck/sweep_sphere_cylinder.hpp"
#include "moves.hpp"
#include "moving_checks.hpp"

namespace geomcheck {

// The spec of sweep_sphere_cylinder: a moving sphere swept against a cylinder: the first time of contact.
GEOMCHECK_SPEC(sweep_sphere_cylinder, 100000,
               (Claims{true, Claims::Depth::None, true, "the cylinder's outward surface normal at the contact (zero when the ball starts inside)", "certified engine: the swept ball (a capsule) against the cylinder; t bracketed"}),
               (Tolerances{/*verdict*/ 1e-14, /*depth*/ 0, /*normal*/ 1e-14, /*point*/ 1e-12, /*t*/ 1e-12, /*unit*/ 1e-14}),
               &teeth::kSweepNoCornerStage, &teeth::kSweepTalkRimPoint)

namespace {

// The ball's centre at parameter t, exactly.
QVec centre_at(const SweepCylinderCase& c, double t) {
  return oracle::to_q(c.a.c) + oracle::to_q(t) * oracle::to_q(c.a.delta);
}

// The path of the ball from 0 to t (a capsule), its radius changed by dr,
// certainly meets the cylinder? (dr < 0 shrinks; a radius below zero is the
// segment against the cylinder shrunk by the rest, by the closed form.)
bool path_meets(const SweepCylinderCase& c, double t, const Q& dr) {
  const QVec a = oracle::to_q(c.a.c), b = centre_at(c, t);
  const Q r = oracle::to_q(c.a.r) + dr;
  if (r >= 0) {
    const oracle::DistanceResult d = oracle::classify(oracle::make_shape(c.b), oracle::make_capsule(a, b, r));
    return d.verdict != oracle::Verdict::Separated;
  }
  return oracle::cast_meets_adjusted(oracle::QSegment{a, b}, oracle::to_q(c.b), -r, -1);
}

}  // namespace

double exact_first_touch(const SweepCylinderCase& c) {
  // The gap at a peer's t alone cannot see a t past a first crossing that
  // was missed: |t_peer - t_exact| needs the first touch itself.
  const oracle::ImpactResult toi = oracle::time_of_impact(oracle::make_shape(Sphere{c.a.c, c.a.r}),
                                                          oracle::to_q(c.a.delta), oracle::make_shape(c.b));
  if (toi.kind == oracle::ImpactResult::Kind::Hit && toi.t.hi - toi.t.lo <= oracle::to_q(1e-12)) return toi.t.mid();
  if (toi.kind == oracle::ImpactResult::Kind::StartsInside) return 0;
  return NAN;
}

void hold_to_truth(Evaluation& e, const SweepCylinderCase& c, const CastHit& h, const double* peer_t) {
  const Tolerances& tol = e.tol;
  const oracle::ConvexShape cyl = oracle::make_shape(c.b);
  const QVec a = oracle::to_q(c.a.c), b = centre_at(c, 1.0);
  const Q r = oracle::to_q(c.a.r);
  // Hit iff the ball's path (the capsule from c to c + delta) meets the cylinder.
  const Q band = times_scale(tol.verdict, e.scale);
  const CapsuleTruth truth = capsule_truth(cyl, a, b, r, band);
  e.truth_hit = truth.verdict != oracle::Verdict::Separated;
  e.verdict = truth.verdict;
  e.signed_distance = nearest_to_zero(truth.signed_distance, e.scale);
  e.truth_text = std::string(e.truth_hit ? "hit" : "miss") + " (path " + truth.text + ")";
  e.disagree = e.prod_hit != e.truth_hit;
  e.near_boundary = !(truth.signed_distance.lo > band || truth.signed_distance.hi < -band);
  if (peer_t && e.truth_hit && *peer_t >= 0 && *peer_t <= 1) {
    // The peer's t, by production's yardstick: the ball's gap at t; starting
    // inside (touching included), how far the centre moved before t.
    const oracle::QCylinder qc = oracle::to_q(c.b);
    const QVec x = centre_at(c, *peer_t);
    if ((oracle::signed_distance(qc, a) - oracle::point(r)).hi <= 0) {
      const QVec d = x - a;
      e.peer.t_err = rel_up(oracle::sqrt_interval(oracle::dot(d, d)).hi, e.scale);
    } else {
      const QInterval gap = oracle::signed_distance(qc, x) - oracle::point(r);
      const Q lo = gap.lo < 0 ? -gap.lo : gap.lo, hi = gap.hi < 0 ? -gap.hi : gap.hi;
      e.peer.t_err = rel_up(lo > hi ? lo : hi, e.scale);
    }
  }
  if (e.disagree) {
    e.margin = std::fabs(e.signed_distance) / e.scale;
    e.excused = e.near_boundary;
    return;
  }
  if (!h.hit || !e.truth_hit) return;
  if (!finite_hit(h) || !(h.t >= 0 && h.t <= 1)) {
    e.extra_failure = "t outside [0, 1] or non-finite output";
    return;
  }
  const oracle::QCylinder qc = oracle::to_q(c.b);
  const QVec x = centre_at(c, h.t);
  // The ball at production's t: its signed distance from the cylinder.
  const QInterval gap = oracle::signed_distance(qc, x) - oracle::point(r);
  if (h.starts_inside) {
    e.t_err = gap.hi > 0 ? rel_up(gap.hi, e.scale) : 0.0;
  } else {
    const Q lo = gap.lo < 0 ? -gap.lo : gap.lo, hi = gap.hi < 0 ? -gap.hi : gap.hi;
    e.t_err = rel_up(lo > hi ? lo : hi, e.scale);
    // Bracketing: the ball's path up to t never gets the t bound deep.
    if (path_meets(c, h.t, -times_scale(tol.t, e.scale)))
      e.extra_failure = "the ball's path up to t reaches deeper than the t bound into the cylinder (hit reported too late)";
    e.unit_err = std::fabs(length(h.normal) - 1);
    // Normal: as for collide, conditioning-free. The ball's centre x is
    // dist(x, C) from the cylinder; along a unit n the cylinder reaches
    // h_C(n) - n.x short of it, which is -dist exactly for the true normal
    // (the direction from the closest point), more for any other:
    // error = h_C(n) - n.x + dist(x, C) >= 0.
    if (max_abs(h.normal) > 0) {
      const QVec n = oracle::to_q(h.normal);
      const QInterval len = oracle::sqrt_interval(oracle::dot(n, n));
      const QInterval excess = (oracle::support(qc, n) - oracle::point(oracle::dot(n, x))) / len + oracle::signed_distance(qc, x);
      e.normal_err = excess.hi > 0 ? rel_up(excess.hi, e.scale) : 0.0;
    }
  }
  // point: on the cylinder's surface (in it when starting inside) and on the ball at t.
  const QVec px = oracle::to_q(h.point);
  const QInterval on_cyl = oracle::signed_distance(qc, px);
  const QVec off = px - x;
  const QInterval on_ball = oracle::sqrt_interval(oracle::dot(off, off)) - oracle::point(r);
  auto abs_hi = [](const QInterval& v) { const Q a = v.lo < 0 ? -v.lo : v.lo, b = v.hi < 0 ? -v.hi : v.hi; return a > b ? a : b; };
  const Q pe = h.starts_inside ? std::max(on_cyl.hi, on_ball.hi) : std::max(abs_hi(on_cyl), abs_hi(on_ball));
  e.point_err = pe > 0 ? rel_up(pe, e.scale) : 0.0;
}

CheckResult check_consistency(const SweepCylinderCase& c, const SweepSphereCylinderImpl& impl) {
  const CastHit h = impl.sweep(c.a, c.b);
  if (auto f = consistent_hit(kId, h, impl.claims)) return f;
  if (!valid_case(c)) return std::nullopt;
  const Tolerances tol = bounds(c, impl);
  const double scale = oracle::case_scale(c.a, c.b);
  // starts_inside is the sphere query's verdict at t = 0.
  // Production's verdict at t = 0, unless the ball starts within the
  // subject's band of touching (then either answer is the subject's to give).
  const bool at0 = overlap(c.b, Sphere{c.a.c, c.a.r});
  auto start_in_band = [&] {
    const oracle::QInterval sd = oracle::solve_cylinder_sphere(c.b, Sphere{c.a.c, c.a.r}).signed_distance;
    const Q band = times_scale(tol.verdict, scale);
    return !(sd.lo > band || sd.hi < -band);
  };
  if (at0 != (h.hit && h.starts_inside) && !start_in_band())
    return Failure{"consistency-starts-inside-vs-overlap", describe(h) + std::string("; overlap(Cylinder, Sphere) at t = 0: ") + (at0 ? "yes" : "no")};
  // The swept capsule: the same hit/miss outside the band.
  const Vec3 end = c.a.c + c.a.delta;
  const bool cap = overlap(c.b, Capsule{c.a.c, end, c.a.r});
  if (cap != h.hit) {
    const SweepCylinderCase rounded{{c.a.c, c.a.r, end - c.a.c}, c.b};
    const Evaluation e = evaluate(c, impl);
    if (!e.near_boundary && !evaluate(rounded, impl).near_boundary)
      return Failure{"consistency-sweep-vs-capsule", describe(h) + std::string("; overlap(Cylinder, Capsule) of the path: ") + (cap ? "yes" : "no")};
  }
  if (!h.hit || h.starts_inside) return std::nullopt;
  // Repeated collide(Cylinder, Sphere): the ball at t, grown by the t bound,
  // meets the cylinder; just before t, shrunk by it, it does not.
  const double slack = tol.t * scale;
  const Vec3 xt = c.a.c + h.t * c.a.delta;
  if (!collide(c.b, Sphere{xt, c.a.r + 4 * slack}).hit)
    return Failure{"consistency-collide-at-t", describe(h) + ": the ball at t (grown by the t bound) does not meet the cylinder"};
  const double tb = h.t * (1 - 0x1p-20);
  if (c.a.r > 4 * slack && collide(c.b, Sphere{c.a.c + tb * c.a.delta, c.a.r - 4 * slack}).hit)
    return Failure{"consistency-collide-before-t", describe(h) + fmt(": the ball at t = %.17g (shrunk by the t bound) already meets the cylinder", tb)};
  return std::nullopt;
}

CheckResult check_symmetry(const SweepCylinderCase& c, const SweepSphereCylinderImpl& impl) {
  if (!valid_case(c)) return std::nullopt;
  return caps_swapped(c, impl);
}

CheckResult check_metamorphic(const SweepCylinderCase& c, int move, const SweepSphereCylinderImpl& impl) {
  // The rigid motion: a change of verdict is a failure beyond the band plus
  // the motion's rounding (at the larger of the two scales).
  auto rigid_certain = [&](const SweepCylinderCase& t, const std::string& what, const CastHit& h0,
                           const CastHit& h1) -> CheckResult {
    const Evaluation e0 = evaluate(c, impl);
    const double moved_scale = std::max(e0.scale, oracle::case_scale(t.a, t.b));
    // The subject answers the moved case to its band at the moved scale.
    const double slack = std::max(bounds(c, impl).verdict, bounds(t, impl).verdict) * moved_scale + moves::rigid_slack(c.b) * moved_scale;
    if (std::fabs(e0.signed_distance) <= slack || e0.near_boundary) return std::nullopt;
    return Failure{what, "verdict changed beyond the band and the motion's rounding: " + describe(h0) + " vs " + describe(h1)};
  };
  return moving_metamorphic(c, move, impl, rigid_certain);
}

CheckResult check_monotone(const SweepCylinderCase& c, const SweepSphereCylinderImpl& impl) {
  if (!valid_case(c) || !impl.sweep(c.a, c.b).hit) return std::nullopt;
  const double big = c.a.r * 2 + 0x1p-20 * oracle::case_scale(c.a, c.b);
  const SweepCylinderCase bigger{{c.a.c, big, c.a.delta}, c.b};
  if (std::isfinite(big) && hit_lost(c, bigger, impl))
    return Failure{"monotone-ball-radius", "hit with radius " + fmt("%.17g", c.a.r) + " but not with " + fmt("%.17g", big),
                   bigger};
  if (auto f = cylinder_b_radius_kept(c, impl)) return f;
  const MovingSphere longer{c.a.c, c.a.r, 2.0 * c.a.delta};
  if (is_valid(longer) && hit_lost(c, {longer, c.b}, impl))
    return Failure{"monotone-sweep-length", "hit, but the sweep extended to twice its length misses",
                   SweepCylinderCase{longer, c.b}};
  return std::nullopt;
}

}  // namespace geomcheck
