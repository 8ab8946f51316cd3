// geomcheck — generators of collide_cylinder_cylinder: targeted modes and wild doubles.
//
// targeted:
// Cylinder/cylinder pairs. Modes, by tag:
// random[-through]              random poses in scenes of 2^-60..2^60
// (some far from the origin; disks and
// needles among them); -through: B's middle
// inside A;
// [anti-]parallel-side[-ANGLE-radial|tangential]  side by side, the axes
// rA + rB (+ gap) apart, ANGLE 1e-4, 1e-8,
// 1e-12 or 1e-16 radians from parallel, made
// exactly (a coordinate that is zero at one
// end: nothing rounds it away);
// coaxial|stacked|stacked-rim[-anti][-ANGLE]  B's cap on A's top cap plane
// (exactly, k ulps off, a gap or overlapping),
// on the axis, beside it, or rA + rB beside
// it (the rims meet at a point);
// perp-side-side|side-on-cap|cap-on-side|through  perpendicular crossings;
// cap-|side-|rim-on-<spot>      B's cap, side or rim at A's rim
// (rim-above, rim-side, rim-diag), a cap or
// its side (touching +- ulps, a gap either
// way);
// ratio-...                     the same with both cylinders disks or
// needles (length / radius 1e-6..1e6);
// exact-...                     exact integer constructions (parallel
// sides rA + rB apart, stacked caps, rims
// meeting, perpendicular sides, a side on a
// cap, a cap tangent to a side, zero radii),
// exact moves; -touch / -ulps-in / -ulps-out.
// Suffixes: -touch, -ulps-in / -ulps-out (k ulps), -gap / -deep. Exact
// moves (permutation, flips, 2^-60..2^60) keep ulp-sized features; other
// constructions are also placed by a rounded rigid motion. Either cylinder
// comes first.
//
// wild:
// Wild doubles everywhere; a quarter of the pairs keep one ordinary cylinder.
#include "common.hpp"

namespace geomcheck::gen {

using namespace detail;

namespace {

using CylCase = std::pair<CylinderCylinderCase, std::string>;

// A scene as pick_scene, or a third of the time one of size 2^-60..2^60,
// optionally 2^10..2^40 sizes from the origin.
Scene pick_wide_scene() {
  if (pick_int(0, 2) != 0) return pick_scene();
  Scene s;
  s.size = std::ldexp(1.0, pick_int(-60, 60));
  s.offset = {0, 0, 0};
  if (pick_int(0, 2) == 0) {
    const double far = std::ldexp(s.size, pick_int(10, 40));
    s.offset = {pick_real(-far, far), pick_real(-far, far), pick_real(-far, far)};
  }
  return s;
}

// The same cylinder with its caps stored the other way round, half the time.
Cylinder restate(const Cylinder& c) { return pick_int(0, 1) ? Cylinder{c.q, c.p, c.r} : c; }

// An angle from parallel: exactly none, or 1e-4, 1e-8, 1e-12, 1e-16 radians.
double pick_angle() {
  switch (pick_int(0, 4)) {
    case 0: return 0;
    case 1: return 1e-4;
    case 2: return 1e-8;
    case 3: return 1e-12;
    default: return 1e-16;
  }
}
std::string angle_tag(double a) {
  if (a == 0) return "";
  if (a > 1e-6) return "-1e-4";
  if (a > 1e-10) return "-1e-8";
  if (a > 1e-14) return "-1e-12";
  return "-1e-16";
}

// A dyadic value in [lo, hi] with three fractional bits: sums of a few of
// them are exact.
double pick_dyadic(int lo8, int hi8) { return pick_int(lo8, hi8) / 8.0; }

// Where an axis-aligned construction lands: exact moves (coordinate
// permutation, sign flips, a power-of-two scale 2^-60..2^60, no offset, so
// that ulp-sized features and tiny angles survive bit for bit), or a
// rounded rigid motion into a random frame of a scene.
struct Place {
  bool exact = true;
  Exact ex{};
  Vec3 o, e1, e2, u;
  double s = 1;
  Vec3 pt(Vec3 v) const { return exact ? ex.apply(v) : o + s * (v.x * e1 + v.y * e2 + v.z * u); }
  double len(double r) const { return exact ? ex.len(r) : s * r; }
  Cylinder cyl(Vec3 p, Vec3 q, double r) const { return {pt(p), pt(q), len(r)}; }
};
Place pick_place(bool exact) {
  Place pl;
  pl.exact = exact;
  pl.ex = pick_exact();
  pl.ex.off = {0, 0, 0};
  if (pick_int(0, 3) == 0) pl.ex.e = pick_int(-60, 60);
  if (!exact) {
    const Scene sc = pick_wide_scene();
    pl.o = sc.offset;
    pl.s = sc.size;
    pl.u = pick_dir();
    pl.e1 = any_perpendicular(pl.u);
    pl.e2 = cross(pl.u, pl.e1);
  }
  return pl;
}
// Exact moves for the constructions whose point is an ulp or a tiny angle;
// a rounded rigid motion for a third of the others.
Place place_for(bool fine) { return pick_place(fine || pick_int(0, 2) != 0); }

// A gap along a construction coordinate: exactly zero, k ulps either way of
// a touching coordinate v (returned as the moved coordinate), or a small or
// large gap either way.
struct Gap {
  double v;
  std::string tag;
};
Gap pick_coordinate_gap(double v, double size) {
  switch (pick_int(0, 4)) {
    case 0: return {v, "-touch"};
    case 1: {
      const int m = pick_int(1, 4), k = m * (pick_int(0, 1) ? 1 : -1);
      return {nudge(v, k), k > 0 ? "-ulps-out" : "-ulps-in"};
    }
    case 2: {
      const double m = std::ldexp(size, -pick_int(20, 50)), g = m * (pick_int(0, 1) ? 1 : -1);
      return {v + g, g > 0 ? "-gap" : "-deep"};
    }
    default: {
      const double m = pick_real(0.01, 2) * size, g = m * (pick_int(0, 1) ? 1 : -1);
      return {v + g, g > 0 ? "-gap" : "-deep"};
    }
  }
}

// Parallel, anti-parallel and nearly parallel cylinders side by side: A on
// the z axis, B's axis at x = d = rA + rB (+ gap, or k ulps), an axial
// offset either way. The angle is made exactly: a tangential tilt moves B's
// top cap centre to y = lB * angle (B's bottom at y = 0, so nothing rounds
// it away), a radial one A's top cap centre to x = -lA * angle (A leaning
// away from B, both axes in the plane y = 0). Exact moves only when tilted
// below 1e-8 (a rotation in doubles would round those angles).
CylCase cyl_parallel() {
  const double rA = pick_int(0, 10) == 0 ? 0.0 : pick_dyadic(1, 24), rB = pick_dyadic(1, 24);
  const double lA = pick_dyadic(2, 40), lB = pick_dyadic(2, 40);
  const double angle = pick_angle();
  const bool radial = pick_int(0, 1), anti = pick_int(0, 1);
  const Gap g = pick_coordinate_gap(rA + rB, 1.0);
  const double z0 = pick_dyadic(-8 * int(lB) - 4, 8 * int(lA) + 4);
  const Place pl = place_for(angle != 0 && angle < 1e-6);
  Vec3 aq{0, 0, lA}, bp{g.v, 0, z0}, bq{g.v, 0, z0 + lB};
  if (angle != 0 && radial) aq.x = -lA * angle;
  if (angle != 0 && !radial) bq.y = lB * angle;
  if (anti) std::swap(bp, bq);
  const std::string tilt = angle == 0 ? "" : angle_tag(angle) + (radial ? "-radial" : "-tangential");
  return {{pl.cyl({0, 0, 0}, aq, rA), pl.cyl(bp, bq, rB)},
          std::string(anti ? "anti-parallel-side" : "parallel-side") + tilt + g.tag};
}

// Coaxial and stacked cylinders: B's bottom cap on A's top cap plane (z =
// lA, exactly; k ulps above or below; a small or large gap; overlapping),
// B's axis on A's (coaxial) or beside it within rA + rB (stacked; at exactly
// rA + rB the rims meet at a point), B the same way up or upside down
// (anti), optionally tilted about its bottom cap centre (tangentially: the
// rim dips by rB sin(angle)).
CylCase cyl_coaxial() {
  const double rA = pick_dyadic(0, 24), rB = pick_dyadic(1, 24);
  const double lA = pick_dyadic(1, 40), lB = pick_dyadic(1, 40);
  const double angle = pick_angle();
  const bool anti = pick_int(0, 1);
  const int lat = pick_int(0, 3);  // coaxial, inside, at the rim sum, beyond
  double x = 0;
  if (lat == 1) x = pick_dyadic(0, int(8 * (rA + rB)));
  if (lat == 2) x = rA + rB;
  if (lat == 3) x = rA + rB + pick_dyadic(1, 16);
  Gap g = pick_coordinate_gap(lA, 1.0);
  if (pick_int(0, 5) == 0) g = {pick_dyadic(0, int(8 * lA)), "-overlap"};  // B's cap inside A's length
  const Place pl = place_for(true);
  Vec3 bp{x, 0, g.v}, bq{x, 0, g.v + lB};
  if (angle != 0) bq.y = lB * angle;
  if (anti) std::swap(bp, bq);
  const std::string where = lat == 0 ? "coaxial" : (lat == 2 ? "stacked-rim" : "stacked");
  return {{pl.cyl({0, 0, 0}, {0, 0, lA}, rA), pl.cyl(bp, bq, rB)},
          where + (anti ? "-anti" : "") + angle_tag(angle) + g.tag};
}

// Perpendicular crossings, A on the z axis: B along x with its side against
// A's side (the axes rA + rB apart: a point contact) or lying on A's top
// cap; B along y with its bottom cap against A's side (the cap plane
// tangent to the side along a line), or crossing A's axis (through).
CylCase cyl_perpendicular() {
  const double rA = pick_dyadic(0, 24), rB = pick_dyadic(0, 24);
  const double lA = pick_dyadic(2, 40), lB = pick_dyadic(2, 40);
  const double s = pick_dyadic(0, int(8 * lB));
  const Place pl = place_for(pick_int(0, 1));
  Vec3 bp, bq;
  std::string tag;
  switch (pick_int(0, 3)) {
    case 0: {
      const Gap g = pick_coordinate_gap(rA + rB, 1.0);
      const double z = pick_dyadic(-8, int(8 * lA) + 8);
      bp = {-s, g.v, z}, bq = {lB - s, g.v, z};
      tag = "perp-side-side" + g.tag;
      break;
    }
    case 1: {
      const Gap g = pick_coordinate_gap(lA + rB, 1.0);
      const double y = pick_dyadic(-int(8 * rA) - 8, int(8 * rA) + 8);
      bp = {-s, y, g.v}, bq = {lB - s, y, g.v};
      tag = "perp-side-on-cap" + g.tag;
      break;
    }
    case 2: {
      const Gap g = pick_coordinate_gap(rA, 1.0);
      const double x = pick_dyadic(-int(8 * rB) - 4, int(8 * rB) + 4), z = pick_dyadic(-8, int(8 * lA) + 8);
      bp = {x, g.v, z}, bq = {x, g.v + lB, z};
      tag = "perp-cap-on-side" + g.tag;
      break;
    }
    default: {
      const double z = pick_dyadic(0, int(8 * lA));
      bp = {-s, pick_dyadic(-int(8 * rA), int(8 * rA)), z}, bq = {lB - s, bp.y, z};
      tag = "perp-through";
      break;
    }
  }
  if (pick_int(0, 1)) std::swap(bp, bq);
  return {{pl.cyl({0, 0, 0}, {0, 0, lA}, rA), pl.cyl(bp, bq, rB)}, tag};
}

// B's cap (feature 0), side (1) or rim (2) at a spot of A: B lies in
// out.(y - at) >= gap and holds at + gap out, so for gap >= 0 their
// distance is gap (to rounding). Cap: B's axis along `out`, the spot inside
// its cap disc; side: B's axis across `out`, rB above the plane; rim: B's
// axis leaning away from A (w.out in [0.1, 0.95]), the point of its rim
// lowest along `out` at the spot.
Cylinder cylinder_feature_at(const Spot& sp, double gap, int feature, double rB, double lB) {
  const Vec3 x = sp.at + gap * sp.out;
  if (feature == 0) {
    const Vec3 dir = across(sp);
    const Vec3 p = x + (rB * std::sqrt(pick_real(0, 1))) * dir;
    return {p, p + lB * sp.out, rB};
  }
  if (feature == 1) {
    const Vec3 v = across(sp), c = x + rB * sp.out;
    const double t = pick_real(0, 1) * lB;
    return {c - t * v, c + (lB - t) * v, rB};
  }
  const double co = pick_real(0.1, 0.95), si = std::sqrt(1 - co * co);
  const Vec3 w = co * sp.out + si * across(sp);
  const Vec3 p = x + (rB / si) * (sp.out - co * w);
  return {p, p + lB * w, rB};
}
const char* const kCylFeatureNames[3] = {"cap", "side", "rim"};

// Radius and length of a cylinder whose length over radius is 10^-6..10^6
// (a disk to a needle), the larger of the two size * 0.5..4.
std::pair<double, double> pick_proportions(double size, bool extreme) {
  if (!extreme) return {pick_int(0, 15) == 0 ? 0.0 : pick_real(0.05, 4) * size, pick_real(0.05, 8) * size};
  const double ratio = std::pow(10.0, pick_real(-6, 6));
  const double big = pick_real(0.5, 4) * size;
  return ratio >= 1 ? std::pair<double, double>{big / ratio, big} : std::pair<double, double>{big, big * ratio};
}

// Features against features (see cylinder_feature_at) at a spot of A (its
// rim, a cap or its side); `extreme`: both cylinders disks or needles.
CylCase cyl_feature(int feature, bool extreme) {
  const Scene sc = pick_wide_scene();
  Frame f = pick_cylinder(sc);
  if (extreme) {
    const auto [r, len] = pick_proportions(sc.size, true);
    f.c = {f.c.p, f.c.p + len * f.u, r};
    f.u = (1.0 / length(f.c.q - f.c.p)) * (f.c.q - f.c.p);
    f.e1 = any_perpendicular(f.u);
    f.e2 = cross(f.u, f.e1);
  }
  const Spot sp = pick_spot(f, pick_region());
  const double gap = pick_gap(extreme ? std::min(f.c.r + length(f.c.q - f.c.p), sc.size) : sc.size);
  const auto [rB, lB] = pick_proportions(sc.size, extreme);
  Cylinder a = f.c, b = cylinder_feature_at(sp, gap, feature, rB, lB);
  if (gap == 0) {  // touching, then both radii grown or shrunk by k ulps
    const int k = pick_int(-2, 2);
    a.r = std::max(0.0, nudge(a.r, k));
    b.r = std::max(0.0, nudge(b.r, k));
  }
  return {{restate(a), restate(b)},
          std::string(extreme ? "ratio-" : "") + kCylFeatureNames[feature] + "-on-" + sp.name + gap_tag(gap)};
}

// Random pairs in a scene (2^-60..2^60, possibly far from the origin): B's
// middle within 3 sizes of A's; a quarter of the time through A (B's
// middle inside A: overlapping).
CylCase cyl_random() {
  const Scene sc = pick_wide_scene();
  const Frame f = pick_cylinder(sc);
  const bool through = pick_int(0, 3) == 0;
  const Vec3 mid = through ? inside_point(f)
                           : 0.5 * (f.c.p + f.c.q) + sc.size * Vec3{pick_real(-3, 3), pick_real(-3, 3), pick_real(-3, 3)};
  const Vec3 v = pick_dir();
  const auto [r, len] = pick_proportions(sc.size, pick_int(0, 4) == 0);
  const Cylinder b{mid - (0.5 * len) * v, mid + (0.5 * len) * v, r};
  return {{restate(f.c), b}, through ? "random-through" : "random"};
}

// Exact integer constructions (a Pythagorean triple a, b, c; rA + rB = c m),
// then exact moves (no offset where a coordinate is nudged). Touching
// exactly; the radius of B (or B's cap coordinate) moved by k ulps.
CylCase exact_cylinder_cylinder() {
  const auto& t = kTriples[pick_int(0, kNumTriples - 1)];
  const int m = pick_int(1, 3), a = t[0] * m, b = t[1] * m, c = t[2] * m;
  const int rA = pick_int(0, 8) == 0 ? 0 : pick_int(1, c - 1), rB = c - rA;
  const int h = pick_int(1, 20), hB = pick_int(1, 20);
  Exact ex = pick_exact();
  const int ulps = pick_int(-2, 2);
  double rb = rB;
  Vec3 bp, bq;
  std::string tag;
  bool radius_nudge = true;
  switch (pick_int(0, 5)) {
    case 0: {  // parallel, the axes (a m, b m) apart: sides touching along a segment (or a point at the ends)
      const int zb = pick_int(-hB, h);
      bp = {double(a), double(b), double(zb)}, bq = {double(a), double(b), double(zb + hB)};
      tag = "exact-parallel-side";
      break;
    }
    case 1: {  // stacked caps at z = h, lateral offset j (a, b), j <= m (j == m: the rims meet at a point)
      const int j = pick_int(0, m);
      ex.off = {0, 0, 0};
      const double z = nudge(double(h), ulps);  // k > 0: a gap of k ulps
      bp = {double(t[0] * j), double(t[1] * j), z}, bq = {bp.x, bp.y, z + hB};
      tag = j == m ? "exact-rim-rim" : "exact-stacked-caps";
      radius_nudge = false;
      break;
    }
    case 2: {  // perpendicular, the axes rA + rB apart: sides touching at a point
      const int z = pick_int(0, h), s = pick_int(0, hB);
      bp = {double(-s), double(c), double(z)}, bq = {double(hB - s), double(c), double(z)};
      tag = "exact-perp-side";
      break;
    }
    case 3: {  // B lying on A's top cap, along (a, b, 0) over the cap's centre
      const int s = pick_int(0, 3);
      bp = {double(-t[0] * s), double(-t[1] * s), double(h + rB)};
      bq = bp + double(s + pick_int(1, 3)) * Vec3{double(t[0]), double(t[1]), 0};
      tag = "exact-side-on-cap";
      break;
    }
    case 4: {  // B's cap tangent to A's side at (a k, b k) (rA = c k), B reaching out along (a, b, 0)
      const int k = pick_int(1, 3);
      const Vec3 at{double(t[0] * k), double(t[1] * k), double(pick_int(0, h))};
      const Cylinder A{ex.apply({0, 0, 0}), ex.apply({0, 0, double(h)}), nudge(ex.len(double(t[2] * k)), ulps)};
      const Cylinder B{ex.apply(at), ex.apply(at + double(pick_int(1, 3)) * Vec3{double(t[0]), double(t[1]), 0}),
                       ex.len(double(pick_int(1, 10)))};
      return {{restate(A), B}, "exact-cap-on-side" + ulps_tag(ulps)};
    }
    default: {  // zero radii: two segments crossing at a point, or B's side touching A's segment
      const int z = pick_int(0, h);
      const bool seg = pick_int(0, 1);
      const double x = seg ? 0.0 : double(c);
      const Vec3 p0{x, double(-pick_int(1, 5)), double(z)}, q0{x, double(pick_int(1, 5)), double(z)};
      const Cylinder A{ex.apply({0, 0, 0}), ex.apply({0, 0, double(h)}), 0.0};
      if (seg)  // B's segment moved off A's by k ulps (along construction x)
        return {{A, Cylinder{ex.nudge_x(ex.apply(p0), ulps), ex.nudge_x(ex.apply(q0), ulps), 0.0}},
                std::string("exact-zero-radius-cross") + (ulps == 0 ? "-touch" : "-ulps-off")};
      return {{A, Cylinder{ex.apply(p0), ex.apply(q0), nudge(ex.len(double(c)), ulps)}},
              "exact-zero-radius-side" + ulps_tag(ulps)};
    }
  }
  const Cylinder A{ex.apply({0, 0, 0}), ex.apply({0, 0, double(h)}), ex.len(rA)};
  const Cylinder B{ex.apply(bp), ex.apply(bq), radius_nudge ? nudge(ex.len(rb), ulps) : ex.len(rb)};
  const std::string ut = radius_nudge ? ulps_tag(ulps) : (ulps == 0 ? "-touch" : (ulps > 0 ? "-ulps-out" : "-ulps-in"));
  const bool anti = pick_int(0, 1);  // B stored the other way round: the same set
  return {{A, anti ? Cylinder{B.q, B.p, B.r} : B}, tag + ut};
}

}  // namespace

template <>
rc::Gen<Tagged<QueryTraits<QueryId::collide_cylinder_cylinder>::Case>> targeted<QueryId::collide_cylinder_cylinder>() {
  return rc::gen::resize(100, rc::gen::exec([]() -> std::pair<CylinderCylinderCase, std::string> {
    CylCase c;
    switch (pick_int(0, 12)) {
      case 0:
      case 1: c = cyl_random(); break;
      case 2:
      case 3: c = cyl_parallel(); break;
      case 4: c = cyl_coaxial(); break;
      case 5: c = cyl_perpendicular(); break;
      case 6: c = cyl_feature(0, false); break;
      case 7: c = cyl_feature(1, false); break;
      case 8: c = cyl_feature(2, false); break;
      case 9: c = cyl_feature(pick_int(0, 2), true); break;
      default: c = exact_cylinder_cylinder(); break;
    }
    // Either cylinder first: the query is symmetric, production's roles need not be.
    if (pick_int(0, 1)) std::swap(c.first.a, c.first.b);
    return c;
  }));
}

template <>
rc::Gen<QueryTraits<QueryId::collide_cylinder_cylinder>::Case> wild<QueryId::collide_cylinder_cylinder>() {
  return rc::gen::resize(100, rc::gen::exec([]() -> CylinderCylinderCase {
    Cylinder a{wild_vec(), wild_vec(), *wild_double()}, b{wild_vec(), wild_vec(), *wild_double()};
    if (pick_int(0, 3) == 0) {  // one of them an ordinary cylinder
      a = {{0, 0, 0}, {0, 0, 1}, 0.5};
      if (pick_int(0, 1)) std::swap(a, b);
    }
    return {a, b};
  }));
}


}  // namespace geomcheck::gen
