#include "truth.hpp"

#include "common.hpp"

#include <sstream>

namespace geomcheck {

using oracle::Q;
using oracle::QInterval;
using oracle::QVec;
using oracle::Verdict;

QInterval overlap_along(const oracle::ConvexShape& a, const oracle::ConvexShape& b, const QVec& n) {
  const QVec m{-n.x, -n.y, -n.z};
  const QInterval h = oracle::support_value(a, n) + oracle::support_value(b, m);
  return h / oracle::sqrt_interval(oracle::dot(n, n));
}

QInterval capsule_signed_distance(const QVec& p, const QVec& q, const Q& r, const QVec& x) {
  const QVec d = q - p;
  const Q dd = oracle::dot(d, d);
  Q t = dd > 0 ? oracle::dot(x - p, d) / dd : Q(0);
  if (t < 0) t = 0;
  if (t > 1) t = 1;
  const QVec off = x - (p + t * d);
  return oracle::sqrt_interval(oracle::dot(off, off)) - oracle::point(r);
}

CapsuleTruth capsule_truth(const oracle::ConvexShape& cyl, const QVec& p, const QVec& q, const Q& r, const Q& band) {
  CapsuleTruth t;
  std::ostringstream o;
  // The capsule is pq (+) r Ball, so its signed distance from the cylinder
  // is the segment's minus r, on both sides of zero: outside, D - r; when
  // pq meets the cylinder, the depth of the origin in C (-) pq grows by
  // exactly r when the ball is added (h(n) + r for every n), so -PD - r.
  oracle::EngineOptions opt;
  opt.certificates = false;
  const oracle::ConvexShape seg = oracle::make_capsule(p, q, Q(0));
  // The distance to 1e-20 * scale where it matters: always outside (GJK to
  // convergence is cheap); inside only when the depth can still be within
  // the band (r <= 2 band), since that refinement runs EPA. One call.
  opt.rel_width = 1e-20;
  if (!(r <= 2 * band)) opt.refine_overlap_within = Q(-1);
  oracle::DistanceResult s = oracle::classify(cyl, seg, opt);
  // The capsule itself, below, at the width the segment was refined to.
  if (!(s.verdict == Verdict::Separated || (s.verdict == Verdict::Overlapping && r <= 2 * band))) opt.rel_width = 0;
  opt.refine_overlap_within.reset();
  t.core_outside = s.verdict == Verdict::Separated;
  if (t.core_outside) t.core_distance = s.distance;
  t.signed_distance = s.distance - oracle::point(r);
  if (s.verdict == Verdict::Touching) t.signed_distance = oracle::point(-r);
  if (s.verdict != Verdict::Undecided && t.signed_distance.lo > 0) {
    t.verdict = Verdict::Separated;
  } else if (s.verdict != Verdict::Undecided && t.signed_distance.hi < 0) {
    t.verdict = Verdict::Overlapping;
  } else {
    // The capsule within reach of touching (or the segment undecided): the
    // capsule itself, exactly (touching is certified there).
    const oracle::DistanceResult c = oracle::classify(cyl, oracle::make_capsule(p, q, r), opt);
    t.verdict = c.verdict;
    if (c.verdict == Verdict::Touching) t.signed_distance = oracle::point(Q(0));
    else if (s.verdict == Verdict::Undecided) t.signed_distance = c.distance;
  }
  o << oracle::to_string(t.verdict) << " signed_distance=" << oracle::to_string(t.signed_distance)
    << (t.core_outside ? " (segment outside)" : " (segment meets the cylinder)");
  t.text = o.str();
  return t;
}

PolytopeTruth polytope_truth(const oracle::ConvexShape& cyl, const oracle::ConvexShape& shape, const Q& band) {
  PolytopeTruth t;
  oracle::EngineOptions opt;
  opt.certificates = false;
  // Refined to 1e-20 * scale where separated, and where overlapping only if
  // the overlap may be within 2 band: that refinement (EPA) is classify's,
  // done here so that its answer is kept for the contact's scoring.
  opt.rel_width = 1e-20;
  opt.refine_overlap_within = Q(-1);
  oracle::DistanceResult d = oracle::classify(cyl, shape, opt);
  if (d.verdict == Verdict::Overlapping && d.distance.hi - d.distance.lo > oracle::pair_scale(cyl, shape) * oracle::to_q(opt.rel_width) &&
      !(Q(-d.distance.hi) > 2 * band)) {
    oracle::PenetrationResult p = oracle::penetration(cyl, shape, opt.rel_width, opt.double_double);
    if (p.overlapping && p.depth.hi - p.depth.lo < d.distance.hi - d.distance.lo) {
      d.distance = {Q(-p.depth.hi), Q(-p.depth.lo)};
      d.note += " depth: " + p.note;
    }
    t.penetration = std::move(p);
  }
  t.verdict = d.verdict;
  t.signed_distance = d.verdict == Verdict::Touching ? oracle::point(Q(0)) : d.distance;
  t.text = std::string(oracle::to_string(t.verdict)) + " signed_distance=" + oracle::to_string(t.signed_distance);
  return t;
}

double nearest_to_zero(const QInterval& x, double scale) {
  // A wide enclosure (deep contacts are not refined) is reported by its end
  // nearest to zero: a certified bound, where the midpoint would be a guess.
  const Q width = x.hi - x.lo;
  if (width <= oracle::to_q(1e-6 * scale)) return x.mid();
  if (x.lo > 0) return oracle::to_double(x.lo);
  if (x.hi < 0) return oracle::to_double(x.hi);
  return 0.0;
}

UpperBoundScore score_upper_bound(double depth, const QInterval& pd, double scale) {
  UpperBoundScore out;
  const Q v = oracle::to_q(depth);
  out.shortfall = v < pd.lo ? rel_up(pd.lo - v, scale) : 0.0;
  // The ratio where it measures the direction rather than rounding: the
  // penetration depth enclosed within 1% and at least 1e-9 * scale (a
  // rounding-sized depth, a few eps * scale, over a rounding-sized
  // penetration depth is noise).
  if (pd.lo >= times_scale(1e-9, scale) && (pd.hi - pd.lo) * 100 <= pd.lo) {
    out.ratio = depth / oracle::to_double(pd.mid());
    const Q lo = v / pd.hi;  // depth over the largest penetration depth the enclosure allows
    double d = oracle::to_double(lo);
    if (Q(d) > lo) d = std::nextafter(d, 0.0);
    out.ratio_lo = d;
  }
  return out;
}

ContactErrors score_polytope_contact(const Contact& k, bool truth_hit, const PolytopeTruth& truth,
                                     const oracle::QCylinder& qcyl, const oracle::ConvexShape& cyl,
                                     const oracle::ConvexShape& shape, double scale, double depth_bound,
                                     std::optional<oracle::PenetrationResult>& pd,
                                     const std::function<Q(Vec3)>& outside_b, std::string* wide, bool upper_bound) {
  ContactErrors out;
  if (!k.hit || !finite_contact(k)) return out;
  out.unit = std::fabs(length(k.normal) - 1);
  if (!truth_hit) return out;
  // The penetration depth, certified (EPA): the headers claim depth and
  // normal minimal. Where EPA cannot narrow the enclosure below the bound
  // (it stops at its iteration caps: 4.7e-14 wide on a cap coplanar with a
  // box face), the errors are taken as the distance from the contact's
  // value to the enclosure: certain, a lower bound, so a failure is always
  // the contact's.
  if (truth.verdict == Verdict::Overlapping) {
    if (!pd) pd = oracle::penetration(cyl, shape, 1e-20);
    if (pd->overlapping && std::isfinite(oracle::to_double(pd->depth.hi))) {
      const QInterval& depth = pd->depth;
      const bool narrow = depth.hi - depth.lo <= times_scale(0.01 * depth_bound, scale);
      const Q v = oracle::to_q(k.depth);
      if (upper_bound) {
        // A consistent contact, as cylinder/cylinder's (score_upper_bound).
        const UpperBoundScore u = score_upper_bound(k.depth, depth, scale);
        out.depth = u.shortfall, out.ratio = u.ratio, out.ratio_lo = u.ratio_lo;
      } else if (narrow) {
        out.depth = rel_error(depth, k.depth, scale);
      } else {
        out.depth = v > depth.hi ? rel_up(v - depth.hi, scale) : (v < depth.lo ? rel_up(depth.lo - v, scale) : 0.0);
      }
      if (!upper_bound && max_abs(k.normal) > 0) {
        const QInterval along = overlap_along(cyl, shape, oracle::to_q(k.normal));
        const Q excess = narrow ? along.hi - depth.lo : along.lo - depth.hi;
        out.normal = excess > 0 ? rel_up(excess, scale) : 0.0;
      }
      if (!narrow && !upper_bound && wide) *wide = "; penetration depth " + oracle::to_string(depth) + " (EPA enclosure wider than the bound)";
    }
  }
  const QInterval da = oracle::signed_distance(qcyl, oracle::to_q(k.point));
  const Q db_hi = outside_b(k.point);
  const Q worst = da.hi > db_hi ? da.hi : db_hi;
  out.point = worst > 0 ? rel_up(worst, scale) : 0.0;
  return out;
}

void score_polytope_contacts(Evaluation& e, const Contact& mine, const Contact* peer, const PolytopeTruth& truth,
                             const oracle::QCylinder& qcyl, const oracle::ConvexShape& cyl,
                             const oracle::ConvexShape& shape, double depth_bound,
                             const std::function<Q(Vec3)>& outside_b, bool upper_bound) {
  std::optional<oracle::PenetrationResult> pd = truth.penetration;
  std::string wide;
  const ContactErrors m = score_polytope_contact(mine, e.truth_hit, truth, qcyl, cyl, shape, e.scale, depth_bound, pd,
                                                 outside_b, &wide, upper_bound);
  e.unit_err = m.unit, e.depth_err = m.depth, e.normal_err = m.normal, e.point_err = m.point;
  e.depth_ratio = m.ratio, e.depth_ratio_lo = m.ratio_lo;
  if (mine.hit && e.truth_hit) {
    if (truth.verdict == Verdict::Touching) score_depth_sides(e, oracle::point(Q(0)), mine.depth);
    else if (pd && pd->overlapping) score_depth_sides(e, pd->depth, mine.depth);
  }
  if (peer) {
    const ContactErrors t = score_polytope_contact(*peer, e.truth_hit, truth, qcyl, cyl, shape, e.scale, depth_bound,
                                                   pd, outside_b, &wide, upper_bound);
    e.peer.unit_err = t.unit, e.peer.depth_err = t.depth, e.peer.normal_err = t.normal, e.peer.point_err = t.point;
  }
  e.truth_text += wide;
}

}  // namespace geomcheck
