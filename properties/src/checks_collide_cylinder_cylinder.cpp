// geomcheck — the checks of collide_cylinder_cylinder (declared for every query in checks.hpp).
//
// check_oracle: Agreement with the engine outside the band; the point in both
// cylinders; the depth never below the certified penetration depth by more
// than the bound (it is the overlap along the returned normal, an upper bound
// of the penetration depth, and need not equal it: see the query's header),
// and never above 1.5 times it (tolerances.hpp, depth_ratio; where it is at
// least 1e-9 * scale).
// check_consistency: overlap == collide.hit; unit normal; depth >= 0 equals
// the overlap along the normal; no NaN.
// check_symmetry: (A,B) and (B,A): the same verdict (band), the normal flipped
// and the depth equal to the bounds; caps swapped (either cylinder): same
// verdict (band), same depth to the bound.
// check_metamorphic: As for the other queries, but for a reflection of a scene
// whose two axes lie exactly in one plane: there the normal may be the other
// of a mirror pair (point bit-identical, depth to the bound); and for any
// reflection, a tie: another normal with the point and the depth bit-
// identical, as good as the returned one (the overlap along it, exactly,
// equals the depth).
// check_monotone: A wider or longer cylinder (either one) never turns overlap
// into separation (outside the band).
#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>

#include "truth.hpp"
#include "common.hpp"
#include "contact_checks.hpp"
#include "geomcheck/collide_cylinder_cylinder.hpp"
#include "geomcheck/oracles/cylinder_sphere.hpp"
#include "geomcheck/properties/checks.hpp"
#include "geomcheck/properties/teeth.hpp"
#include "geomcheck/properties/tolerances.hpp"
#include "moves.hpp"

namespace geomcheck {

// The spec of collide_cylinder_cylinder: cylinder/cylinder: exact verdict; a consistent contact (depth = overlap along the normal).
GEOMCHECK_SPEC(collide_cylinder_cylinder, 100000,
               (Claims{true, Claims::Depth::UpperBound, true, "unit, from the first cylinder towards the second: a consistent contact, not the minimal translation", "certified engine: exact verdict, certified signed distance, EPA penetration depth as a lower bound of the depth"}),
               // The contact is consistent, not minimal (see the query's header):
               // depth is the overlap along the returned normal, an upper bound of
               // the penetration depth. `depth` bounds only how far it may fall BELOW
               // the certified penetration depth (no direction overlaps less); how
               // far above is reported (depth / penetration depth, Evaluation::
               // depth_ratio) and bounded: at most 1.5 times the penetration depth
               // (where that is at least 1e-9 * scale: the depth_ratio row). No
               // normal bound (0: not a metric of this query): consistency holds
               // depth to the overlap along the normal, to the depth bound.
               (Tolerances{/*verdict*/ 1e-14, /*depth*/ 1e-14, /*normal*/ 0, /*point*/ 1e-14, /*t*/ 0, /*unit*/ 1e-14, /*depth_ratio*/ 1.5}),
               &teeth::kCylinderNoPlanes, &teeth::kCylinderNoParallelBranch, &teeth::kCylinderPlainFrame,
               &teeth::kCylinderShortSearch)

namespace {

// The two axes in one plane, decided exactly: orient3d(p_A, q_A, p_B, q_B)
// is zero (parallel axes always are). The reflection in that plane maps
// both cylinders onto themselves, so their candidate directions come in
// mirror pairs, and a reflected scene may pick the other one of a tie.
bool axes_coplanar(const CylinderCylinderCase& c) {
  const QVec p = oracle::to_q(c.a.p);
  const QVec u = oracle::to_q(c.a.q) - p, v = oracle::to_q(c.b.p) - p, w = oracle::to_q(c.b.q) - p;
  return oracle::dot(oracle::cross(u, v), w) == 0;
}

// The unit normal of the plane through both axes of a coplanar scene, in
// doubles (for the mirror image of a normal only); zero when the four end
// points are collinear (coaxial: every plane through the axis is a mirror).
Vec3 common_plane_normal(const CylinderCylinderCase& c) {
  const Vec3 u = c.a.q - c.a.p;
  Vec3 w = cross(u, c.b.q - c.b.p);
  if (!(max_abs(w) > 0)) w = cross(u, (c.b.p - c.a.p) + (c.b.q - c.a.p));  // parallel axes
  const double m = max_abs(w);
  if (!(m > 0) || !std::isfinite(m)) return {0, 0, 0};
  const Vec3 s = (1.0 / m) * w;
  return (1.0 / length(s)) * s;
}

// Production's contact (or a peer's) against the truth: unit error; the
// shortfall of the depth below the certified penetration depth (the depth
// is an overlap along a direction, so it can only be >= the penetration
// depth; a certain shortfall, depth < lo of the enclosure, is an error);
// the point's distance outside either cylinder. The ratio depth / PD where
// the enclosure is within 1%.
struct Score {
  double unit = NAN, depth = NAN, point = NAN, ratio = NAN, ratio_lo = NAN;
};
Score score_contact(const Contact& k, bool truth_hit, Verdict verdict, const oracle::QCylinder& qa,
                    const oracle::QCylinder& qb, const oracle::ConvexShape& sa, const oracle::ConvexShape& sb,
                    double scale, std::optional<oracle::PenetrationResult>& pd) {
  Score out;
  if (!k.hit || !finite_contact(k)) return out;
  out.unit = std::fabs(length(k.normal) - 1);
  if (!truth_hit) return out;
  if (verdict == Verdict::Overlapping) {
    if (!pd) pd = oracle::penetration(sa, sb, 1e-20);
    if (pd->overlapping && std::isfinite(oracle::to_double(pd->depth.hi))) {
      const UpperBoundScore u = score_upper_bound(k.depth, pd->depth, scale);
      out.depth = u.shortfall, out.ratio = u.ratio, out.ratio_lo = u.ratio_lo;
    }
  } else {
    out.depth = 0;  // touching: the penetration depth is 0 <= depth
  }
  const QVec x = oracle::to_q(k.point);
  const QInterval da = oracle::signed_distance(qa, x), db = oracle::signed_distance(qb, x);
  const Q worst = da.hi > db.hi ? da.hi : db.hi;
  out.point = worst > 0 ? rel_up(worst, scale) : 0.0;
  return out;
}

}  // namespace

void hold_to_truth(Evaluation& e, const CylinderCylinderCase& c, const Contact& ct, const Contact* peer) {
  const Tolerances& tol = e.tol;
  const oracle::ConvexShape sa = oracle::make_shape(c.a), sb = oracle::make_shape(c.b);
  const Q band = times_scale(tol.verdict, e.scale);
  const PolytopeTruth truth = polytope_truth(sa, sb, band);
  // The margin of a disagreement is the certain part of the enclosure, its
  // distance from zero. Two curved surfaces nearly parallel can leave GJK's
  // enclosure wide (2.4e-20 to 2.5e-8 for axes 1e-12 from parallel touching
  // to 2e-20), and its midpoint would be a guess.
  settle_verdict(e, truth, band, true);
  // The depth is not claimed minimal (see the query's header): the normal
  // has no error of its own (consistency holds the depth to the overlap
  // along it); the depth only fails below the penetration depth.
  const oracle::QCylinder qa = oracle::to_q(c.a), qb = oracle::to_q(c.b);
  std::optional<oracle::PenetrationResult> pd = truth.penetration;
  const Score m = score_contact(ct, e.truth_hit, truth.verdict, qa, qb, sa, sb, e.scale, pd);
  e.unit_err = m.unit, e.depth_err = m.depth, e.point_err = m.point, e.depth_ratio = m.ratio;
  e.depth_ratio_lo = m.ratio_lo;
  if (ct.hit && e.truth_hit) {
    if (truth.verdict == Verdict::Touching) score_depth_sides(e, oracle::point(Q(0)), ct.depth);
    else if (pd && pd->overlapping) score_depth_sides(e, pd->depth, ct.depth);
  }
  if (peer) {
    const Score p = score_contact(*peer, e.truth_hit, truth.verdict, qa, qb, sa, sb, e.scale, pd);
    e.peer.unit_err = p.unit, e.peer.depth_err = p.depth, e.peer.point_err = p.point;
  }
  if (pd && pd->overlapping) e.truth_text += "; penetration depth " + oracle::to_string(pd->depth);
}

double depth_ratio(const CylinderCylinderCase& c, const CylinderCylinderImpl& impl) {
  return evaluate(c, impl).depth_ratio;
}

CheckResult check_consistency(const CylinderCylinderCase& c, const CylinderCylinderImpl& impl) {
  const bool exact = valid_case(c);
  return consistent_contact(kId, c, impl, exact, bounds(c, impl).depth);
}

CheckResult check_symmetry(const CylinderCylinderCase& c, const CylinderCylinderImpl& impl) {
  const Tolerances tol = bounds(c, impl);
  // (B, A): the same pair with the roles exchanged. The verdict agrees
  // outside the band; both hitting, the depths agree to the bound and the
  // normal is flipped, or (a tie between candidate directions) the flipped
  // normal of (B, A) is as good for (A, B): the overlap along it equals
  // (A, B)'s depth to the bound.
  const bool ov = impl.overlap(c.a, c.b), sov = impl.overlap(c.b, c.a);
  const Contact ct = impl.collide(c.a, c.b), sw = impl.collide(c.b, c.a);
  if (ov != sov) {
    if (!valid_case(c) || !evaluate(c, impl).near_boundary)
      return Failure{"symmetry-argument-order",
                     "verdict changed outside the band: " + describe(ct, ov) + " vs swapped " + describe(sw, sov),
                     CylinderCylinderCase{c.b, c.a}};
  } else if (ov && ct.hit && sw.hit && valid_case(c)) {
    const double scale = oracle::case_scale(c.a, c.b);
    const double d = std::fabs(ct.depth - sw.depth) / scale;
    if (!(d <= 2 * tol.depth))
      return Failure{"symmetry-argument-order-depth",
                     fmt("depth differs by %.3g * scale; ", d) + describe(ct, ov) + " vs swapped " + describe(sw, sov),
                     CylinderCylinderCase{c.b, c.a}};
    if (!(length(ct.normal + sw.normal) <= 64 * 0x1p-52)) {
      const QInterval along =
          overlap_along(oracle::make_shape(c.a), oracle::make_shape(c.b), oracle::to_q(-sw.normal));
      if (std::isfinite(oracle::to_double(along.hi)) && rel_error(along, ct.depth, scale) > 2 * tol.depth)
        return Failure{"symmetry-argument-order-normal",
                       "the swapped normal, flipped, is not as good a direction: " + describe(ct, ov) +
                           " vs swapped " + describe(sw, sov),
                       CylinderCylinderCase{c.b, c.a}};
    }
  }
  if (!valid_case(c)) return std::nullopt;
  // Same solid, other representation (contact_checks.hpp).
  const double bound = 2 * tol.depth;
  if (auto f = same_answer("symmetry-caps-swapped-a", c, {{c.a.q, c.a.p, c.a.r}, c.b}, impl, bound)) return f;
  if (auto f = same_answer("symmetry-caps-swapped-b", c, {c.a, {c.b.q, c.b.p, c.b.r}}, impl, bound)) return f;
  return same_answer("symmetry-caps-swapped-both", c, {{c.a.q, c.a.p, c.a.r}, {c.b.q, c.b.p, c.b.r}}, impl, bound);
}

CheckResult check_metamorphic(const CylinderCylinderCase& c, int move, const CylinderCylinderImpl& impl) {
  auto kept = [&](const CylinderCylinderCase& t, const MovedAnswers& a) -> CheckResult {
    // A tie between candidate directions, certified: the moved normal,
    // measured exactly in the moved scene, overlaps the shapes as much as
    // the depth returned there (to the bound). Consistency holds the
    // returned normal to that depth, so both are answers.
    auto moved_normal_as_good = [&] {
      const QInterval along =
          overlap_along(oracle::make_shape(t.a), oracle::make_shape(t.b), oracle::to_q(a.m.vec(a.ct.normal)));
      return std::isfinite(oracle::to_double(along.hi)) &&
             rel_error(along, a.ct2.depth, oracle::case_scale(t.a, t.b)) <= 2 * bounds(c, impl).depth;
    };
    if ((move == 0 || move == 1) && axes_coplanar(c) && !(a.m.vec(a.ct.normal) == a.ct2.normal)) {
      // A reflection of a scene symmetric in the plane of the two axes: the
      // normal may be the other of a mirror pair (and the depth, computed
      // along it, differ by rounding). The point does not depend on the
      // normal: still bit-identical.
      if (!(a.m.pt(a.ct.point) == a.ct2.point))
        return Failure{a.what, "point not bit-identical (axes in one plane): " + describe(a.ct, a.ov) + " vs " +
                                 describe(a.ct2, a.ov2)};
      const double d = std::fabs(a.m.len(a.ct.depth) - a.ct2.depth) / oracle::case_scale(c.a, c.b);
      if (!(d <= 2 * bounds(c, impl).depth))
        return Failure{a.what + "-depth", fmt("depth differs by %.3g * scale (axes in one plane); ", d) +
                                            describe(a.ct, a.ov) + " vs " + describe(a.ct2, a.ov2)};
      const Vec3 w = common_plane_normal(t), n = a.m.vec(a.ct.normal);
      const Vec3 mirror = n - (2 * dot(n, w)) * w;
      // Coaxial (w = 0): every plane through the axis is a mirror; the
      // normal's axial part and its length are what is left to compare.
      const bool coaxial = max_abs(w) == 0;
      const Vec3 u = t.a.q - t.a.p;
      const bool ok = coaxial ? std::fabs(dot(n - a.ct2.normal, u)) <= 64 * 0x1p-52 * length(u) &&
                                    std::fabs(length(a.ct2.normal) - 1) <= bounds(c, impl).unit
                              : length(mirror - a.ct2.normal) <= 64 * 0x1p-52;
      // Or a tie of another pair: a scene may have a second symmetry
      // (regression 0016: A a disk across B, its centre in B's mid plane to
      // rounding, so that +-A's axis overlap equally).
      if (!ok && !moved_normal_as_good())
        return Failure{a.what + "-normal", "normal neither the moved one nor its mirror image (axes in one plane): " +
                                             describe(a.ct, a.ov) + " vs " + describe(a.ct2, a.ov2)};
      return std::nullopt;
    }
    if (a.m.pt(a.ct.point) == a.ct2.point && a.m.vec(a.ct.normal) == a.ct2.normal && a.m.len(a.ct.depth) == a.ct2.depth)
      return std::nullopt;
    // A tie: the normal is the best of a few candidate directions, and a
    // reflection turns the common perpendicular (a cross product) round, so
    // where two candidates overlap the shapes equally (e.g. +-n across a
    // segment through B's centre) the reflected scene may pick the other.
    // Accepted only with the point and the depth bit-identical and the
    // moved normal, measured exactly in the moved scene, as good as the one
    // returned there (consistency holds that one to the depth).
    if ((move == 0 || move == 1) && a.m.pt(a.ct.point) == a.ct2.point && a.m.len(a.ct.depth) == a.ct2.depth &&
        moved_normal_as_good())
      return std::nullopt;
    return a.not_identical();
  };
  auto slack = [](const CylinderCylinderCase& x) { return std::max(moves::rigid_slack(x.a), moves::rigid_slack(x.b)); };
  return collide_metamorphic(c, move, impl, valid_case<CylinderCylinderCase>, slack, kept);
}

CheckResult check_monotone(const CylinderCylinderCase& c, const CylinderCylinderImpl& impl) {
  if (!valid_case(c) || !impl.overlap(c.a, c.b)) return std::nullopt;
  // A superset never loses the overlap, except within the band of touching.
  auto lost = [&](const CylinderCylinderCase& bigger) { return overlap_lost(c, bigger, impl); };
  for (int which = 0; which < 2; ++which) {
    const Cylinder& k = which == 0 ? c.a : c.b;
    auto with = [&](const Cylinder& g) { return which == 0 ? CylinderCylinderCase{g, c.b} : CylinderCylinderCase{c.a, g}; };
    const char* name = which == 0 ? "A" : "B";
    const double rc[] = {std::nextafter(k.r, INFINITY), k.r * 2 + 1e-300};
    for (double r : rc)
      if (std::isfinite(r) && lost(with(Cylinder{k.p, k.q, r})))
        return Failure{std::string("monotone-radius-") + name,
                       fmt("overlap with radius %.17g but not with %.17g", k.r, r), with(Cylinder{k.p, k.q, r})};
    // Longer: q moved outwards by q - p (and p by p - q), only where that is
    // exact (else the axis direction rounds and the result is no superset).
    const Vec3 d = k.q - k.p, q2 = k.q + d, p2 = k.p - d;
    if (is_finite(q2) && d + k.p == k.q && q2 - k.q == d && lost(with(Cylinder{k.p, q2, k.r})))
      return Failure{std::string("monotone-length-") + name, "overlap lost when the cylinder is extended beyond q",
                     with(Cylinder{k.p, q2, k.r})};
    if (is_finite(p2) && k.q - d == k.p && k.p - p2 == d && lost(with(Cylinder{p2, k.q, k.r})))
      return Failure{std::string("monotone-length-") + name, "overlap lost when the cylinder is extended beyond p",
                     with(Cylinder{p2, k.q, k.r})};
  }
  return std::nullopt;
}

}  // namespace geomcheck
