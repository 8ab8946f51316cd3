#include "common.hpp"

#include <cmath>
#include <cstdio>
#include <limits>

#include "geomcheck/properties/tolerances.hpp"

namespace geomcheck {

std::string fmt(const char* f, double a, double b, double c) {
  char buf[256];
  std::snprintf(buf, sizeof buf, f, a, b, c);
  return buf;
}
std::string vec(Vec3 v) { return fmt("(%.17g, %.17g, %.17g)", v.x, v.y, v.z); }

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

CheckResult judge(QueryId id, const Evaluation& e) {
  const Tolerances tol = tolerances(id);
  if (!e.valid) {
    if (e.prod_hit || e.disagree) return Failure{"invalid-input", "invalid input reported a hit: " + e.prod_text};
    return std::nullopt;
  }
  if (e.disagree && !e.excused)
    return Failure{"oracle-verdict", "production says " + std::string(e.prod_hit ? "hit" : "no hit") +
                                         ", oracle: " + e.truth_text + fmt(" (margin %.3g * scale, band %.3g)", e.margin, tol.verdict) +
                                         "; production: " + e.prod_text};
  auto over = [&](const char* what, double err, double bound) -> CheckResult {
    if (std::isnan(err) || err <= bound) return std::nullopt;
    return Failure{std::string("oracle-") + what,
                   std::string(what) + fmt(" error %.3g * scale exceeds bound %.3g", err, bound) +
                       "; oracle: " + e.truth_text + "; production: " + e.prod_text};
  };
  if (auto f = over("unit", e.unit_err, tol.unit)) return f;
  if (auto f = over("depth", e.depth_err, tol.depth)) return f;
  if (auto f = over("normal", e.normal_err, tol.normal)) return f;
  if (auto f = over("point", e.point_err, tol.point)) return f;
  if (auto f = over("t", e.t_err, tol.t)) return f;
  if (!e.extra_failure.empty()) return Failure{"oracle-bracketing", e.extra_failure + "; oracle: " + e.truth_text + "; production: " + e.prod_text};
  return std::nullopt;
}

const char* move_name(int move) {
  static const char* names[kNumMoves] = {"flip-x", "flip-xyz", "scale-2^8", "scale-2^-8", "permute-yzx", "rigid-motion"};
  return move >= 0 && move < kNumMoves ? names[move] : "?";
}

}  // namespace geomcheck
