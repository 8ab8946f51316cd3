#include "common.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>

#include "geomcheck/oracles/cylinder_sphere.hpp"
#include "geomcheck/properties/tolerances.hpp"

namespace geomcheck {

std::string fmt(const char* f, double a, double b, double c) {
  char buf[256];
  std::snprintf(buf, sizeof buf, f, a, b, c);
  return buf;
}
std::string vec(Vec3 v) { return fmt("(%.17g, %.17g, %.17g)", v.x, v.y, v.z); }

std::string describe(const Contact& c, bool overlap) {
  std::ostringstream o;
  o << "overlap=" << (overlap ? "yes" : "no") << " collide.hit=" << (c.hit ? "yes" : "no");
  if (c.hit) o << " depth=" << fmt("%.17g", c.depth) << " normal=" << vec(c.normal) << " point=" << vec(c.point);
  return o.str();
}

std::string describe(const CastHit& h) {
  std::ostringstream o;
  o << "hit=" << (h.hit ? "yes" : "no");
  if (h.hit)
    o << " t=" << fmt("%.17g", h.t) << " starts_inside=" << (h.starts_inside ? "yes" : "no")
      << " point=" << vec(h.point) << " normal=" << vec(h.normal);
  return o.str();
}

bool finite_contact(const Contact& c) { return is_finite(c.point) && is_finite(c.normal) && std::isfinite(c.depth); }
bool finite_hit(const CastHit& h) { return std::isfinite(h.t) && is_finite(h.point) && is_finite(h.normal); }

double rel_up(const oracle::Q& q, double scale) {
  // Outputs are doubles: in a subnormal scene they cannot be finer than a
  // few of the smallest subnormals, whatever the scale. That resolution is
  // not counted as error.
  const oracle::Q floor = oracle::to_q(4 * std::numeric_limits<double>::denorm_min());
  const oracle::Q above = q > floor ? q - floor : oracle::Q(0);
  return oracle::to_double_up(above / oracle::to_q(scale));
}

oracle::Q times_scale(double k, double scale) { return oracle::to_q(k) * oracle::to_q(scale); }

double rel_error(const oracle::QInterval& x, double v, double scale) {
  const oracle::Q qv = oracle::to_q(v);
  oracle::Q a = x.lo - qv, b = x.hi - qv;
  if (a < 0) a = -a;
  if (b < 0) b = -b;
  return rel_up(a > b ? a : b, scale);
}

void score_depth_sides(Evaluation& e, const QInterval& pd, double depth) {
  if (!std::isfinite(depth) || !std::isfinite(oracle::to_double(pd.hi))) return;
  const Q v = oracle::to_q(depth);
  e.depth_short = v < pd.lo ? rel_up(pd.lo - v, e.scale) : 0.0;
  e.depth_over = v > pd.hi ? rel_up(v - pd.hi, e.scale) : 0.0;
}

Tolerances tolerances(QueryId id) {
  return visit_query(id, [](auto q) { return spec_of<decltype(q)::value>().bounds; });
}

Tolerances bounds_of(QueryId id, const Claims* claims) {
  Tolerances t = tolerances(id);
  if (!claims) return t;
  const Precision& p = claims->precision;
  // A bound of 0 is no metric of the query (a collide query's t): it stays 0.
  auto derive = [&](double& b, bool scaled) {
    if (b == 0) return;
    b = std::max(p.ulps * p.unit_roundoff, b * (p.unit_roundoff / 0x1p-53));
    if (scaled && claims->margin > 0) b += claims->margin;
  };
  derive(t.verdict, true);
  derive(t.depth, true);
  derive(t.normal, true);
  derive(t.point, true);
  derive(t.t, true);
  derive(t.unit, false);
  t.input = p.unit_roundoff > 0x1p-53 ? p.unit_roundoff : 0.0;
  return t;
}

double input_motion(const Sphere&) { return 2; }
double input_motion(const Segment&) { return 2; }
double input_motion(const Capsule&) { return 2; }
double input_motion(const Triangle&) { return 2; }
double input_motion(const MovingSphere&) { return 4; }
double input_motion(const Obb&) { return 2 + 3 * 2; }
double input_motion(const Cylinder& s) {
  // The rim turns with the axis: each end moves by up to 2 (in u * scale),
  // so the axis turns by up to 4 / L radians and the rim point r away by
  // 4 r / L more. An axis so short that this is not finite: no bound.
  const double len = length(s.q - s.p);
  const double swing = len > 0 ? 4 * s.r / len : INFINITY;
  return 2 + (std::isfinite(swing) ? swing : INFINITY);
}

bool states_scale(const Claims* claims, double scale) {
  if (!claims) return true;
  return scale >= claims->precision.min_scale && scale <= claims->precision.max_scale;
}

namespace {

/// judge()'s depth: production's claim held by depth_err; a subject's own
/// depth claim by the side(s) of the penetration depth it claims.
CheckResult judge_depth(QueryId id, const Evaluation& e, const Claims* claims, double bound) {
  if (info(id).kind != QueryKind::Collide) {  // casts and sweeps: no depth; t is judged below
    if (std::isnan(e.depth_err) || e.depth_err <= bound) return std::nullopt;
    return Failure{"oracle-depth", fmt("depth error %.3g * scale exceeds bound %.3g", e.depth_err, bound) +
                                       "; oracle: " + e.truth_text + "; answer: " + e.prod_text};
  }
  using Depth = Claims::Depth;
  const Depth production = visit_query(id, [](auto q) { return spec_of<decltype(q)::value>().claims.depth; });
  const Depth claimed = claims ? claims->depth : production;
  double err = e.depth_err;
  const char* what = "depth error";
  if (claimed == Depth::None) return std::nullopt;
  if (claimed == Depth::UpperBound && production != Depth::UpperBound) {
    err = e.depth_short, what = "depth below the penetration depth by";
  } else if (claimed != Depth::UpperBound && production == Depth::UpperBound) {
    if (e.depth_over > e.depth_err || std::isnan(e.depth_err)) err = e.depth_over, what = "depth above the penetration depth by";
  }
  if (std::isnan(err) || err <= bound) return std::nullopt;
  return Failure{"oracle-depth", std::string(what) + fmt(" %.3g * scale exceeds bound %.3g", err, bound) +
                                     "; oracle: " + e.truth_text + "; answer: " + e.prod_text};
}

}  // namespace

std::vector<Failure> judge_every(QueryId id, const Evaluation& e, const Claims* claims) {
  std::vector<Failure> out;
  // The evaluation's own bounds (the subject's on that case, evaluate()
  // sets them); bounds_of the claims for one made otherwise.
  const Tolerances tol = e.tol.verdict > 0 ? e.tol : bounds_of(id, claims);
  const double margin = claims ? claims->margin : 0.0;
  if (!e.valid) {
    if (e.prod_hit || e.disagree) out.push_back({"invalid-input", "invalid input reported a hit: " + e.prod_text});
    return out;
  }
  // A disagreement the subject's claims allow: an inexact verdict, a miss
  // where the shapes only touch, or one within its margin of touching.
  const bool claimed_away =
      claims && (!claims->exact_verdict || (!claims->touching_is_contact && !e.prod_hit &&
                                            e.verdict == oracle::Verdict::Touching) ||
                 (margin > 0 && e.margin <= margin));
  if (e.disagree && !e.excused && !claimed_away)
    out.push_back({"oracle-verdict", "the subject says " + std::string(e.prod_hit ? "hit" : "no hit") +
                                         ", oracle: " + e.truth_text + fmt(" (margin %.3g * scale, band %.3g)", e.margin, tol.verdict) +
                                         "; answer: " + e.prod_text});
  auto over = [&](const char* what, double err, double bound) {
    if (std::isnan(err) || err <= bound) return;
    out.push_back({std::string("oracle-") + what,
                   std::string(what) + fmt(" error %.3g * scale exceeds bound %.3g", err, bound) +
                       "; oracle: " + e.truth_text + "; answer: " + e.prod_text});
  };
  const bool point_claimed = !claims || claims->point_in_both;
  over("unit", e.unit_err, tol.unit);
  if (auto f = judge_depth(id, e, claims, tol.depth)) out.push_back(*f);
  // A consistent contact's quality (production's claim: the depth at most
  // depth_ratio times the penetration depth), certainly exceeded.
  if (!claims && tol.depth_ratio > 0 && e.depth_ratio_lo > tol.depth_ratio)
    out.push_back({"oracle-depth-ratio",
                   fmt("depth / penetration depth at least %.4g exceeds bound %.3g", e.depth_ratio_lo, tol.depth_ratio) +
                       "; oracle: " + e.truth_text + "; answer: " + e.prod_text});
  over("normal", e.normal_err, tol.normal);
  if (point_claimed) over("point", e.point_err, tol.point);
  over("t", e.t_err, tol.t);
  if (!e.extra_failure.empty())
    out.push_back({"oracle-bracketing", e.extra_failure + "; oracle: " + e.truth_text + "; answer: " + e.prod_text});
  return out;
}

CheckResult judge(QueryId id, const Evaluation& e, const Claims* claims) {
  std::vector<Failure> all = judge_every(id, e, claims);
  if (all.empty()) return std::nullopt;
  return std::move(all.front());
}

namespace {
// Unit vector (as doubles) of an exact rational vector.
Vec3 unit_of(const oracle::QVec& v) {
  const oracle::QInterval len = oracle::sqrt_interval(oracle::dot(v, v));
  const oracle::Q l = (len.lo + len.hi) / 2;
  return {oracle::to_double(v.x / l), oracle::to_double(v.y / l), oracle::to_double(v.z / l)};
}

// Distance of unit n from the cone spanned by unit generators g1, g2 (orthogonal).
double cone_distance(Vec3 n, Vec3 g1, Vec3 g2) {
  const double a = dot(n, g1), b = dot(n, g2);
  const Vec3 proj = std::fmax(a, 0.0) * g1 + std::fmax(b, 0.0) * g2;
  const double pl = length(proj);
  if (pl == 0) return length(n);
  return length(n - (1.0 / pl) * proj);
}

}  // namespace

// Error of production's outward normal at its own hit point x (exact).
double cylinder_normal_error(const oracle::QCylinder& c, const oracle::QVec& x, Vec3 n, const oracle::Q& qnear,
                             const oracle::Q& qinput) {
  const oracle::QVec d = c.q - c.p;
  const oracle::Q dd = oracle::dot(d, d);
  const oracle::QVec xr = x - c.p;
  const oracle::Q ax = oracle::dot(xr, d);
  const oracle::QInterval len = oracle::sqrt_interval(dd);
  // Gaps to the two cap planes and to the side, certified.
  const oracle::QInterval gp = oracle::point(ax < 0 ? -ax : ax) / len;
  const oracle::Q axq = dd - ax;
  const oracle::QInterval gq = oracle::point(axq < 0 ? -axq : axq) / len;
  const oracle::QVec perp = xr - (ax / dd) * d;
  const oracle::Q rho2 = oracle::dot(perp, perp);
  oracle::QInterval gs = oracle::sqrt_interval(rho2) - oracle::point(c.r);
  if (gs.lo < 0 && gs.hi < 0) gs = -gs;
  else if (gs.lo < 0) gs = {oracle::Q(0), gs.hi > -gs.lo ? gs.hi : -gs.lo};
  const Vec3 u = unit_of(d);
  const bool near_p = gp.lo <= qnear, near_q = gq.lo <= qnear, near_s = gs.lo <= qnear;
  // A subject whose working precision moves the input by qinput knows the
  // axis only to within 2 qinput / L (radians): its cap normals may tilt so.
  const double tilt = qinput > 0 ? oracle::to_double(oracle::Q(2) * qinput / len.lo) * (1 + 0x1p-40) : 0.0;
  auto cap = [&](double dist) { return std::fmax(0.0, dist - tilt); };
  double best = INFINITY;
  if (near_p) best = std::fmin(best, cap(length(n - (-u))));
  if (near_q) best = std::fmin(best, cap(length(n - u)));
  // A cylinder thinner than `near` has no meaningful radial direction at
  // this tolerance (its hit point's offset from the axis is noise).
  if (rho2 > 0 && c.r > qnear) {
    const Vec3 radial = unit_of(perp);
    // The side's normals at the points within `near` of x turn by up to
    // near / r (radians) from x's: the truth cannot tell them apart.
    const double turn = oracle::to_double(qnear / c.r) * (1 + 0x1p-40);
    auto side = [&](double d) { return std::fmax(0.0, d - turn - tilt); };
    if (near_s) best = std::fmin(best, side(length(n - radial)));
    if (near_s && near_p) best = std::fmin(best, side(cone_distance(n, -u, radial)));
    if (near_s && near_q) best = std::fmin(best, side(cone_distance(n, u, radial)));
  } else if (near_s) {
    // On a cylinder thinner than `near` (r = 0: a segment):
    // every perpendicular is a side normal, and next to a cap the cone is
    // the whole hemisphere around the cap normal.
    best = std::fmin(best, cap(std::fabs(dot(n, u))));
    if (near_p) best = std::fmin(best, cap(std::fmax(0.0, dot(n, u))));
    if (near_q) best = std::fmin(best, cap(std::fmax(0.0, -dot(n, u))));
  }
  return best;  // INFINITY when x is near no feature (then t_err reports it)
}

const char* move_name(int move) {
  static const char* names[kNumMoves] = {"flip-x", "flip-xyz", "scale-2^8", "scale-2^-8", "permute-yzx", "rigid-motion"};
  return move >= 0 && move < kNumMoves ? names[move] : "?";
}

}  // namespace geomcheck
