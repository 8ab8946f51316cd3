// geomcheck — the checks of collide_capsule_capsule (declared for every query
// in checks.hpp): written once for the ball pairs in ball_checks.hpp, which
// says what each means.
//
// Known-wrong variants: the textbook closest points of two segments without
// the guard for parallel ones (the determinant a e - b^2 divides: NaN on
// parallel segments, noise on nearly parallel ones), and the closest points
// of the two lines clamped to the segments each on its own (right only when
// the crossing lies inside both).
#include <algorithm>
#include <cmath>

#include "ball_checks.hpp"
#include "geomcheck/collide_capsule_capsule.hpp"

namespace geomcheck {

namespace {
using Case = QueryTraits<QueryId::collide_capsule_capsule>::Case;

// The contact of closest points a, b: the depth ra + rb - |b - a|.
Contact contact_of(Vec3 a, Vec3 b, double ra, double rb) {
  Contact out;
  const Vec3 v = b - a;
  const double l = length(v);
  out.hit = l <= ra + rb;
  if (!out.hit) return {};
  out.normal = l > 0 ? (1.0 / l) * v : Vec3{0, 0, 1};
  out.depth = ra + rb - l;
  out.point = a + ra * out.normal;
  return out;
}

// Closest points of the segments, textbook form (the parameter of the first
// from the 2x2 system, the second from the first, each clamped and the
// first recomputed once), with no guard for a vanishing determinant.
Contact textbook_unguarded(const Capsule& x, const Capsule& y) {
  if (!is_valid(x) || !is_valid(y)) return {};
  const Vec3 d1 = x.q - x.p, d2 = y.q - y.p, r = x.p - y.p;
  const double a = dot(d1, d1), e = dot(d2, d2), f = dot(d2, r), c = dot(d1, r), b = dot(d1, d2);
  const double denom = a * e - b * b;
  double s = std::clamp((b * f - c * e) / denom, 0.0, 1.0);
  double t = (b * s + f) / e;
  if (t < 0) t = 0, s = std::clamp(-c / a, 0.0, 1.0);
  else if (t > 1) t = 1, s = std::clamp((b - c) / a, 0.0, 1.0);
  return contact_of(x.p + s * d1, y.p + t * d2, x.r, y.r);
}

// The lines' closest points, each parameter clamped to [0, 1] on its own.
Contact clamped_lines(const Capsule& x, const Capsule& y) {
  if (!is_valid(x) || !is_valid(y)) return {};
  const Vec3 d1 = x.q - x.p, d2 = y.q - y.p, r = x.p - y.p;
  const double a = dot(d1, d1), e = dot(d2, d2), f = dot(d2, r), c = dot(d1, r), b = dot(d1, d2);
  const double denom = a * e - b * b;
  double s = 0, t = 0;
  if (denom > 0) {
    s = std::clamp((b * f - c * e) / denom, 0.0, 1.0);
    t = std::clamp((a * f - b * c) / denom, 0.0, 1.0);
  } else if (e > 0) {
    t = std::clamp(f / e, 0.0, 1.0);
  }
  return contact_of(x.p + s * d1, y.p + t * d2, x.r, y.r);
}

const ImplOf<QueryId::collide_capsule_capsule> kTextbookUnguarded = {
    "textbook-closest-points-unguarded", [](const Capsule& x, const Capsule& y) { return textbook_unguarded(x, y).hit; },
    textbook_unguarded};
const ImplOf<QueryId::collide_capsule_capsule> kClampedLines = {
    "lines-clamped-independently", [](const Capsule& x, const Capsule& y) { return clamped_lines(x, y).hit; },
    clamped_lines};
}  // namespace

// The spec of collide_capsule_capsule: capsule/capsule: exact verdict; the true penetration depth.
GEOMCHECK_SPEC(collide_capsule_capsule, 20000,
               (Claims{true, Claims::Depth::Penetration, true, "unit, from A towards B: the minimal translation", "closed form (oracles/src/ball_pairs.cpp): exact squared distance of the segments, exact verdict, certified depth"}),
               (Tolerances{/*verdict*/ 1e-14, /*depth*/ 1e-14, /*normal*/ 1e-14, /*point*/ 1e-14, /*t*/ 0, /*unit*/ 1e-14}),
               &kTextbookUnguarded, &kClampedLines)

GEOMCHECK_PAIR_CHECKS(ball_checks)

}  // namespace geomcheck
