// geomcheck — the checks of two balls swept along segments, written once for
// the queries over spheres and capsules: collide_sphere_sphere,
// collide_sphere_capsule, collide_capsule_capsule (their checks_<id>.cpp
// files call these; internal to properties/).
//
// check_oracle: Agreement with the closed form (oracles/ball_pairs.hpp)
// outside the band; the depth is the true penetration depth ra + rb - D and
// the normal a minimal translation (the overlap along it exceeds the depth
// by at most the normal bound), everywhere; the point lies in both.
// check_consistency: overlap == collide.hit; unit normal; depth >= 0 equals
// the overlap along the normal; no NaN.
// check_symmetry: (B, A) agrees: the same verdict (band), the same depth to
// the bound, and its normal flipped is as good for (A, B) (for a sphere and
// a capsule, production's (B, A) is the flipped contact, bit for bit); a
// capsule reversed (q, p) is the same solid: same verdict (band), same depth.
// check_metamorphic: Sign flips and power-of-two scales bit-identical (but
// for the normal and the point where the segments touch to the rounding of
// the scene, D <= 2^-49 * scale: any perpendicular is minimal there); axis
// permutations and rigid motions agree outside the band.
// check_monotone: Growing either radius never turns overlap into separation
// (outside the band).
#pragma once

#include <cmath>
#include <optional>
#include <type_traits>

#include "common.hpp"
#include "contact_checks.hpp"
#include "geomcheck/oracles/ball_pairs.hpp"
#include "geomcheck/properties/checks.hpp"
#include "geomcheck/properties/tolerances.hpp"
#include "moves.hpp"

namespace geomcheck::ball_checks {

/// The shape with its segment reversed (a capsule), or itself (a sphere).
inline Sphere reversed(const Sphere& s) { return s; }
inline Capsule reversed(const Capsule& c) { return {c.q, c.p, c.r}; }
inline double& radius(Sphere& s) { return s.r; }
inline double& radius(Capsule& c) { return c.r; }

template <class Case>
void hold_to_truth(Evaluation& e, const Case& c, const Contact& ct, const Contact* peer) {
  const oracle::QBallSegment qa = oracle::to_ball_segment(c.a), qb = oracle::to_ball_segment(c.b);
  const oracle::BallPairTruth truth = oracle::solve_ball_pair(qa, qb);
  settle_verdict(e, truth, times_scale(e.tol.verdict, e.scale));
  const QInterval depth = -truth.signed_distance;
  // One contact (production's or the peer's) against the truth.
  auto score = [&](const Contact& k, double& unit_err, double& depth_err, double& normal_err, double& point_err) {
    if (!k.hit || !finite_contact(k)) return;
    unit_err = std::fabs(length(k.normal) - 1);
    if (!e.truth_hit) return;
    // A depth beyond the largest double has no answer in doubles (it
    // saturates): not measured then.
    if (std::isfinite(oracle::to_double(depth.hi))) depth_err = rel_error(depth, k.depth, e.scale);
    if (max_abs(k.normal) > 0) {
      const QInterval along = oracle::overlap_along(qa, qb, oracle::to_q(k.normal));
      normal_err = rel_up(along.hi - depth.lo, e.scale);
    }
    const QVec x = oracle::to_q(k.point);
    const QInterval da = oracle::signed_distance(qa, x), db = oracle::signed_distance(qb, x);
    const Q out = da.hi > db.hi ? da.hi : db.hi;
    point_err = out > 0 ? rel_up(out, e.scale) : 0.0;
  };
  score(ct, e.unit_err, e.depth_err, e.normal_err, e.point_err);
  if (peer) score(*peer, e.peer.unit_err, e.peer.depth_err, e.peer.normal_err, e.peer.point_err);
  if (ct.hit && e.truth_hit) score_depth_sides(e, depth, ct.depth);
}

template <class Case, class Impl>
CheckResult consistency(const Case& c, const Impl& impl) {
  return consistent_contact(query_of_case<Case>, c, impl, valid_case(c), bounds(c, impl).depth);
}

template <class Case, class Impl>
CheckResult symmetry(const Case& c, const Impl& impl) {
  using A = typename Case::ShapeA;
  using B = typename Case::ShapeB;
  const Tolerances tol = bounds(c, impl);
  if constexpr (!std::is_same_v<A, B>) {
    if (auto f = argument_order(c, impl)) return f;
  } else if (valid_case(c)) {
    // (B, A): the same pair, the roles exchanged.
    const Case s{c.b, c.a};
    if (subject_states(s, impl)) {
      const bool ov = impl.overlap(c.a, c.b), sov = impl.overlap(s.a, s.b);
      const Contact ct = impl.collide(c.a, c.b), sw = impl.collide(s.a, s.b);
      if (ov != sov) {
        if (!evaluate(c, impl).near_boundary)
          return Failure{"symmetry-argument-order",
                         "verdict changed outside the band: " + describe(ct, ov) + " vs swapped " + describe(sw, sov), s};
      } else if (ct.hit && sw.hit && finite_contact(ct) && finite_contact(sw)) {
        const double scale = oracle::case_scale(c.a, c.b);
        const double d = std::fabs(ct.depth - sw.depth) / scale;
        if (!(d <= 2 * tol.depth))
          return Failure{"symmetry-argument-order-depth",
                         fmt("depth differs by %.3g * scale; ", d) + describe(ct, ov) + " vs swapped " + describe(sw, sov),
                         s};
        // The swapped normal, flipped, is as good for (A, B).
        if (max_abs(sw.normal) > 0) {
          const QInterval along = oracle::overlap_along(oracle::to_ball_segment(c.a), oracle::to_ball_segment(c.b),
                                                        oracle::to_q(-sw.normal));
          const double excess = rel_up(along.hi - oracle::to_q(ct.depth), scale);
          if (std::isfinite(oracle::to_double(along.hi)) && excess > tol.depth + tol.normal)
            return Failure{"symmetry-argument-order-normal",
                           fmt("the swapped normal, flipped, overlaps %.3g * scale more than the depth; ", excess) +
                               describe(ct, ov) + " vs swapped " + describe(sw, sov),
                           s};
        }
      }
    }
  }
  if (!valid_case(c)) return std::nullopt;
  // Same solids, segments reversed.
  const double bound = 2 * tol.depth;
  if constexpr (std::is_same_v<A, Capsule>) {
    if (auto f = same_answer("symmetry-a-reversed", c, Case{reversed(c.a), c.b}, impl, bound)) return f;
  }
  if constexpr (std::is_same_v<B, Capsule>) {
    if (auto f = same_answer("symmetry-b-reversed", c, Case{c.a, reversed(c.b)}, impl, bound)) return f;
  }
  return std::nullopt;
}

template <class Case, class Impl>
CheckResult metamorphic(const Case& c, int move, const Impl& impl) {
  // Where the segments touch, or come within the rounding of the scene of
  // it (D <= 2^-49 * scale, exactly: production takes D <= 2^-50 of its
  // scene for touching), every perpendicular is minimal: the normal is a
  // free choice, and so is the point, which lies along it; the depth stays
  // bit-identical.
  auto kept = [&](const Case&, const MovedAnswers& a) -> CheckResult {
    if (a.identical()) return std::nullopt;
    if (a.m.len(a.ct.depth) == a.ct2.depth) {
      const oracle::QBallSegment qa = oracle::to_ball_segment(c.a), qb = oracle::to_ball_segment(c.b);
      const Q near = times_scale(0x1p-49, oracle::case_scale(c.a, c.b));
      if (oracle::segment_distance2(qa.p, qa.q, qb.p, qb.q) <= near * near) return std::nullopt;
    }
    return a.not_identical();
  };
  // The rounded rigid motion moves the ends by a few ulps of the scene; a
  // radius is a length, unchanged: the surface moves by as much.
  return collide_metamorphic(c, move, impl, valid_case<Case>, [](const Case&) { return 8 * 0x1p-52; }, kept);
}

template <class Case, class Impl>
CheckResult monotone(const Case& c, const Impl& impl) {
  if (!valid_case(c) || !impl.overlap(c.a, c.b)) return std::nullopt;
  // An overlap lost by a bigger radius (of either shape) is a failure unless
  // one of the two cases is within the subject's band of touching.
  for (int which = 0; which < 2; ++which) {
    const double r = which == 0 ? c.a.r : c.b.r, other = which == 0 ? c.b.r : c.a.r;
    const double grow[] = {std::nextafter(r, INFINITY), r * 2 + 1e-300, r + 0.5 * other};
    for (double g : grow) {
      Case bigger = c;
      if (which == 0) radius(bigger.a) = g;
      else radius(bigger.b) = g;
      if (std::isfinite(g) && overlap_lost(c, bigger, impl))
        return Failure{which == 0 ? "monotone-a-radius" : "monotone-b-radius",
                       fmt("overlap with radius %.17g but not with %.17g", r, g), bigger};
    }
  }
  return std::nullopt;
}

}  // namespace geomcheck::ball_checks
