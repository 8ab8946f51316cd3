// geomcheck — the checks of cast_segment_cylinder (declared for every query in checks.hpp).
//
// check_consistency: t in [0,1]; point == S(t) (to the bound); starts_inside
// iff t == 0 from inside; unit normal.
// check_symmetry: Segment reversed: same hit/miss outside the band; caps
// swapped: same answer to the bounds.
// check_monotone: A wider cylinder or a longer segment never turns a hit into
// a miss (outside the band).
#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "common.hpp"
#include "geomcheck/cast_segment_cylinder.hpp"
#include "geomcheck/oracles/cast_segment_cylinder.hpp"
#include "geomcheck/oracles/cylinder_sphere.hpp"
#include "geomcheck/properties/checks.hpp"
#include "geomcheck/properties/teeth.hpp"
#include "geomcheck/properties/tolerances.hpp"
#include "geomcheck/shape_traits.hpp"
#include "moves.hpp"
#include "moving_checks.hpp"

namespace geomcheck {

// The spec of cast_segment_cylinder: segment cast against a cylinder: the first hit from the segment start.
GEOMCHECK_SPEC(cast_segment_cylinder, 100000,
               (Claims{true, Claims::Depth::None, true, "the cylinder's outward surface normal at the hit (zero when the segment starts inside)", "closed form (oracles/src/cast_segment_cylinder.cpp): exact hit or miss, certified t"}),
               (Tolerances{/*verdict*/ 1e-14, /*depth*/ 0, /*normal*/ 1e-14, /*point*/ 1e-14, /*t*/ 1e-14, /*unit*/ 1e-14}),
               &teeth::kInfiniteCylinder, &teeth::kEricsonPrinted)

namespace {

// Does the segment meet the cylinder grown (sign > 0) or shrunk (sign < 0) by delta?
bool meets_adjusted(const oracle::QSegment& s, const oracle::QCylinder& c, const Q& delta, int sign) {
  return oracle::cast_meets_adjusted(s, c, delta, sign);
}

// How far from touching a disagreeing case is, as a multiple of scale: the
// smallest delta (found by bisection on log2 delta, to about 2%) such that a
// false hit meets the cylinder grown by delta, or a missed hit never gets
// delta deep (misses the cylinder shrunk by delta).
double disagreement_margin(const oracle::QSegment& s, const oracle::QCylinder& c, bool false_hit, double scale) {
  auto explained = [&](double lg) {
    const Q delta = times_scale(std::exp2(lg), scale);
    return false_hit ? meets_adjusted(s, c, delta, +1) : !meets_adjusted(s, c, delta, -1);
  };
  double lo = -100, hi = 2;
  if (explained(lo)) return std::exp2(lo);
  if (!explained(hi)) return std::exp2(hi);
  for (int i = 0; i < 14; ++i) {
    const double mid = 0.5 * (lo + hi);
    (explained(mid) ? hi : lo) = mid;
  }
  return std::exp2(hi);
}

}  // namespace

void hold_to_truth(Evaluation& e, const SegmentCylinderCase& c, const CastHit& h, const double* peer_t) {
  const Tolerances& tol = e.tol;
  const oracle::QSegment qs = oracle::to_q(c.a);
  const oracle::QCylinder qc = oracle::to_q(c.b);
  const oracle::CastTruth truth = oracle::solve_cast(qs, qc);
  e.truth_hit = truth.hit;
  if (truth.hit) e.t_true = truth.t.mid();
  e.verdict = truth.hit ? oracle::Verdict::Overlapping : oracle::Verdict::Separated;
  e.truth_text = truth.hit ? std::string("hit ") + oracle::to_string(truth.feature) + " t=" + oracle::to_string(truth.t)
                           : std::string("miss");
  e.disagree = e.prod_hit != e.truth_hit;
  if (peer_t && truth.hit && *peer_t >= 0 && *peer_t <= 1) {
    // The peer's t, by production's yardstick: the gap of S(t); starting
    // inside, how far S moved before t.
    const QVec x = qs.a + oracle::to_q(*peer_t) * (qs.b - qs.a);
    if (oracle::signed_distance(qc, qs.a).hi <= 0) {
      const QVec d = x - qs.a;
      e.peer.t_err = rel_up(oracle::sqrt_interval(oracle::dot(d, d)).hi, e.scale);
    } else {
      const QInterval sd = oracle::signed_distance(qc, x);
      const Q a = sd.lo < 0 ? -sd.lo : sd.lo, b = sd.hi < 0 ? -sd.hi : sd.hi;
      e.peer.t_err = rel_up(a > b ? a : b, e.scale);
    }
  }
  const Q band = times_scale(tol.verdict, e.scale);
  // Within the band of touching: a miss that meets the grown cylinder, or a
  // hit that never gets band-deep into the cylinder.
  e.near_boundary = truth.hit ? !meets_adjusted(qs, qc, band, -1) : meets_adjusted(qs, qc, band, +1);
  if (e.disagree) {
    e.excused = e.near_boundary;
    e.margin = disagreement_margin(qs, qc, h.hit, e.scale);
    return;
  }
  if (!h.hit || !truth.hit) return;
  if (!finite_hit(h) || !(h.t >= 0 && h.t <= 1)) {
    e.extra_failure = "t outside [0, 1] or non-finite output";
    return;
  }
  // Production's hit point, exactly: S(t) for its own t.
  const QVec x = qs.a + oracle::to_q(h.t) * (qs.b - qs.a);
  const QInterval sd = oracle::signed_distance(qc, x);
  if (h.starts_inside) {
    e.t_err = sd.hi > 0 ? rel_up(sd.hi, e.scale) : 0.0;
  } else {
    const Q a = sd.lo < 0 ? -sd.lo : sd.lo, b = sd.hi < 0 ? -sd.hi : sd.hi;
    e.t_err = rel_up(a > b ? a : b, e.scale);
    // Bracketing: no point of S([0, t]) is more than the t bound inside.
    const oracle::QSegment prefix{qs.a, x};
    if (meets_adjusted(prefix, qc, times_scale(tol.t, e.scale), -1))
      e.extra_failure = "S([0, t]) reaches deeper than the t bound into the cylinder (hit reported too late)";
    e.unit_err = std::fabs(length(h.normal) - 1);
    // "Near a feature": within 4x the t bound, which is t_err's own reach
    // (its bound plus the output resolution of 4 smallest subnormals).
    const Q near = times_scale(4 * tol.t, e.scale) + oracle::to_q(16 * std::numeric_limits<double>::denorm_min());
    e.normal_err = cylinder_normal_error(qc, x, h.normal, near, times_scale(tol.input, e.scale));
  }
  // point must be S(t).
  const QVec dp = oracle::to_q(h.point) - x;
  e.point_err = rel_up(oracle::sqrt_interval(oracle::dot(dp, dp)).hi, e.scale);
}

CheckResult check_consistency(const SegmentCylinderCase& c, const CastSegmentCylinderImpl& impl) {
  const CastHit h = impl.cast(c.a, c.b);
  if (auto f = consistent_hit(kId, h, impl.claims)) return f;
  if (!h.hit || !valid_case(c)) return std::nullopt;
  const double scale = oracle::case_scale(c.a, c.b);
  const Vec3 s = c.a.a + h.t * (c.a.b - c.a.a);
  if (length(h.point - s) > bounds(c, impl).point * scale)
    return Failure{"consistency-point-is-S(t)", describe(h) + " but S(t) = " + vec(s)};
  return std::nullopt;
}

CheckResult check_symmetry(const SegmentCylinderCase& c, const CastSegmentCylinderImpl& impl) {
  if (!valid_case(c)) return std::nullopt;
  if (auto f = same_verdict("symmetry-segment-reversed", c, {{c.a.b, c.a.a}, c.b}, impl)) return f;
  return caps_swapped(c, impl);
}

CheckResult check_metamorphic(const SegmentCylinderCase& c, int move, const CastSegmentCylinderImpl& impl) {
  // The rigid motion moves the solid by rigid_slack: a change of verdict is a
  // failure only when the original case is certain beyond band + slack. The
  // moved coordinates round at the moved scene's magnitude (the motion
  // translates), so the slack is taken at the larger of the two scales.
  auto rigid_certain = [&](const SegmentCylinderCase& t, const std::string& what, const CastHit& h0,
                           const CastHit& h1) -> CheckResult {
    const double scale = oracle::case_scale(c.a, c.b);
    const double moved_scale = std::max(scale, oracle::case_scale(t.a, t.b));
    // The subject answers the moved case to its band at the moved scale.
    const Q delta = times_scale(std::max(bounds(c, impl).verdict, bounds(t, impl).verdict), moved_scale) + times_scale(moves::rigid_slack(c.b), moved_scale);
    const oracle::QSegment qs = oracle::to_q(c.a);
    const oracle::QCylinder qc = oracle::to_q(c.b);
    const bool truth = oracle::cast_hits(qs, qc);
    const bool certain = truth ? meets_adjusted(qs, qc, delta, -1) : !meets_adjusted(qs, qc, delta, +1);
    if (!certain) return std::nullopt;
    return Failure{what, "verdict changed beyond the band and the motion's rounding: " + describe(h0) + " vs " + describe(h1)};
  };
  return moving_metamorphic(c, move, impl, rigid_certain);
}

CheckResult check_monotone(const SegmentCylinderCase& c, const CastSegmentCylinderImpl& impl) {
  if (!valid_case(c) || !impl.cast(c.a, c.b).hit) return std::nullopt;
  // A hit that becomes a miss in a larger problem is a failure unless one of
  // the two cases is within the band of touching.
  if (auto f = cylinder_b_radius_kept(c, impl)) return f;
  const Vec3 far = c.a.a + 2.0 * (c.a.b - c.a.a);
  const SegmentCylinderCase longer{{c.a.a, far}, c.b};
  if (is_finite(far) && hit_lost(c, longer, impl))
    return Failure{"monotone-segment-length", "hit, but the segment extended to twice its length misses", longer};
  return std::nullopt;
}

}  // namespace geomcheck
