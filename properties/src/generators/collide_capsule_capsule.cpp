// geomcheck — generators of collide_capsule_capsule: targeted modes and wild doubles.
//
// targeted (a scene of size 2^-20..2^20, sometimes far from the origin; the
// gap to touching is zero, tiny either way or large either way):
//   random      two capsules anywhere in the scene
//   parallel    B's segment along A's direction (same or reversed), offset
//               across by ra + rb + gap and along by anything: the segments'
//               extents overlapping, meeting end to end or apart
//   near-par    as parallel, B's direction turned by 2^-10..2^-50 rad
//   crossing    the lines' common perpendicular between interior points,
//               ra + rb + gap long (gap < 0: segments crossing closer)
//   end-side    B's end against A's interior, B leaving at any angle
//   end-end     B's end against A's end, out of A's end cap
//   collinear   both segments on one line (D = 0 when they overlap)
//   inside      B wholly inside A
//   degenerate  a zero-length segment (a ball), zero radii, or both
//   exact       integer constructions (parallel at distance c of a
//               Pythagorean triple, crossing at height c, end against end
//               along a triple) with ra + rb = c, the radius nudged by
//               -2..2 ulps, under an exact move (permutation, flips,
//               power-of-two scale, integer offset)
//
// wild:
// Any capsules, valid or not, from wild doubles (robustness).
#include "common.hpp"

namespace geomcheck::gen {

using namespace detail;

namespace {
using CapsulesCase = QueryTraits<QueryId::collide_capsule_capsule>::Case;

// A unit vector perpendicular to unit u, at a drawn angle.
Vec3 across_of(Vec3 u) {
  const Vec3 e1 = (1.0 / length(any_perpendicular(u))) * any_perpendicular(u);
  const Vec3 e2 = cross(u, e1);
  const double a = pick_real(0, 6.283185307179586);
  return std::cos(a) * e1 + std::sin(a) * e2;
}

// A drawn direction reflected into the half-space of unit n (n . w >= 0).
Vec3 dir_away_from(Vec3 n) {
  const Vec3 w = pick_dir();
  return dot(w, n) < 0 ? w - 2 * dot(w, n) * n : w;
}

CapsulesCase exact_case(std::string& tag) {
  const auto& t = kTriples[pick_int(0, kNumTriples - 1)];
  const int k = pick_int(1, 4), len = pick_int(1, 30), kind = pick_int(0, 2);
  const Exact ex = pick_exact();
  const double c = t[2] * k;
  const double ra = pick_int(0, double(c) > 1 ? int(c) - 1 : 0), rb = c - ra;
  Vec3 p1{0, 0, 0}, q1{double(len), 0, 0}, p2, q2;
  if (kind == 0) {  // parallel at offset (0, a k, b k), shifted along x
    const double sh = pick_int(-len - 5, len + 5);
    p2 = {sh, double(t[0] * k), double(t[1] * k)};
    q2 = {sh + pick_int(0, 20), p2.y, p2.z};
    tag = "exact-parallel";
  } else if (kind == 1) {  // crossing: B along y at height c over an interior point of A
    const double x = pick_int(0, len);
    p2 = {x, double(-pick_int(0, 20)), c};
    q2 = {x, double(pick_int(0, 20)), c};
    tag = "exact-crossing";
  } else {  // end against end: B starts at q1 + (a, b, 0) k and leaves outward
    p2 = {len + double(t[0] * k), double(t[1] * k), 0};
    q2 = p2 + Vec3{double(pick_int(0, 10)), double(pick_int(-10, 10)), double(pick_int(-10, 10))};
    tag = "exact-end-end";
  }
  const int ulps = pick_int(-2, 2);
  const Capsule a{ex.apply(p1), ex.apply(q1), ex.len(ra)};
  const Capsule b{ex.apply(p2), ex.apply(q2), nudge(ex.len(rb), ulps)};
  tag += ulps == 0 ? "-touch" : (ulps > 0 ? "-ulps-in" : "-ulps-out");
  return pick_int(0, 1) ? CapsulesCase{a, b} : CapsulesCase{b, a};
}
}  // namespace

template <>
rc::Gen<Tagged<CapsulesCase>> targeted<QueryId::collide_capsule_capsule>() {
  return rc::gen::resize(100, rc::gen::exec([]() -> std::pair<CapsulesCase, std::string> {
    const int mode = pick_int(0, 9);
    std::string tag;
    if (mode == 9) {
      const CapsulesCase c = exact_case(tag);
      return {c, tag};
    }
    const Scene sc = pick_scene();
    const Vec3 u = pick_dir();
    const double la = pick_int(0, 12) == 0 ? 0.0 : pick_real(0.05, 8) * sc.size;
    const double ra = pick_int(0, 12) == 0 ? 0.0 : pick_real(0.01, 3) * sc.size;
    double rb = pick_int(0, 12) == 0 ? 0.0 : pick_real(0.01, 3) * sc.size;
    const double gap = pick_gap(sc.size);
    const Vec3 p1 = sc.offset + sc.size * Vec3{pick_real(-2, 2), pick_real(-2, 2), pick_real(-2, 2)};
    const Vec3 q1 = p1 + la * u;
    const double lb = pick_int(0, 12) == 0 ? 0.0 : pick_real(0.05, 8) * sc.size;
    const double R = ra + rb;
    Vec3 p2, q2;
    switch (mode) {
      case 0: {
        p2 = p1 + sc.size * Vec3{pick_real(-6, 6), pick_real(-6, 6), pick_real(-6, 6)};
        q2 = p2 + lb * pick_dir();
        tag = "random";
        break;
      }
      case 1:
      case 2: {
        Vec3 v = pick_int(0, 1) ? u : -u;
        if (mode == 2) {
          const double tilt = std::ldexp(1.0, -pick_int(10, 50));  // one draw per statement
          v = v + tilt * across_of(u);
          v = (1.0 / length(v)) * v;
        }
        const Vec3 n = across_of(u);
        const double shift = pick_real(-1.5, 1.5);
        p2 = p1 + (R + gap) * n + shift * (la + lb) * u;
        q2 = p2 + lb * v;
        tag = mode == 1 ? "parallel" : "near-parallel";
        break;
      }
      case 3: {
        Vec3 v = pick_dir();
        Vec3 n = cross(u, v);
        if (length(n) < 1e-3) v = across_of(u), n = cross(u, v);
        n = (1.0 / length(n)) * n;
        const Vec3 x = p1 + pick_real(0, 1) * la * u;
        p2 = x + (R + gap) * n - pick_real(0, 1) * lb * v;
        q2 = p2 + lb * v;
        tag = "crossing";
        break;
      }
      case 4: {
        const Vec3 n = across_of(u);
        p2 = p1 + pick_real(0, 1) * la * u + (R + gap) * n;
        q2 = p2 + lb * dir_away_from(n);
        tag = "end-side";
        break;
      }
      case 5: {
        const Vec3 out = dir_away_from(u);
        p2 = q1 + (R + gap) * out;
        q2 = p2 + lb * dir_away_from(out);
        tag = "end-end";
        break;
      }
      case 6: {
        const double s = pick_real(-1.5, 1.5) * (la + lb + sc.size);
        p2 = p1 + s * u;
        q2 = p2 + (pick_int(0, 1) ? lb : -lb) * u;
        tag = "collinear";
        break;
      }
      case 7: {
        // Points of A's solid, one draw per statement (the order of draws
        // within an expression is the compiler's).
        auto inside_a = [&]() {
          const double along = pick_real(0, 1), out = pick_real(0, 1);
          return p1 + along * la * u + out * ra * across_of(u);
        };
        p2 = inside_a();
        q2 = inside_a();
        rb = ra * pick_real(0, 1);
        tag = "inside";
        break;
      }
      default: {
        p2 = p1 + (R + gap) * pick_dir();
        q2 = pick_int(0, 1) ? p2 : p2 + lb * pick_dir();
        tag = "degenerate";
        break;
      }
    }
    if (mode >= 1 && mode <= 5) tag += gap == 0 ? "-touch" : (gap > 0 ? "-gap" : "-deep");
    const Capsule a{p1, q1, ra}, b{p2, q2, rb};
    return {pick_int(0, 1) ? CapsulesCase{a, b} : CapsulesCase{b, a}, tag};
  }));
}

template <>
rc::Gen<CapsulesCase> wild<QueryId::collide_capsule_capsule>() {
  return rc::gen::exec([]() -> CapsulesCase {
    return {{wild_vec(), wild_vec(), *wild_double()}, {wild_vec(), wild_vec(), *wild_double()}};
  });
}

}  // namespace geomcheck::gen
