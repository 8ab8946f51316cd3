// geomcheck — generators of collide_cylinder_obb: targeted modes and wild doubles.
//
// targeted:
// Cylinder/box pairs. Box frames are orthonormal (to 4 eps; either
// handedness, axes stored in any order and sign): signed permutations,
// times a 3-4-5 or 5-12-13 rotation about a coordinate axis or a product of
// two, or rounded random rotations (unit quaternions). Modes, by tag:
// random                        random poses;
// corner-/edge-/face-<spot>     a box corner, edge or face at the rim
// (rim-above: just above the cap outside the
// rim, rim-side: beside the side, rim-diag),
// a cap or the side;
// corner-pocket                 a corner over the cap disc within r of the
// cap centre, the box beyond the cap plane
// (in the bounding capsule, not in the
// cylinder: a certain miss);
// offray                        a tilted box whose corner nearest the axis
// is above the cap while its section by the
// cap plane lies beside that corner's radial
// line (-deep: overlapping the disc, -gap:
// the mirrored near miss);
// capface-above|below           a box face on a cap plane (an edge or a
// corner of it at in-plane radius r + gap;
// capface-above-over: the face over the disc,
// touching the cap);
// cyl-in-box, box-in-cyl        containment (-snug: touching inside);
// thin-flat|tilted|edgewise     a disk-like cylinder (length 1e-6..1e-12
// of r) resting on a box face or its edge;
// axis-edge[-1e-8|-1e-16]       a box edge parallel (or nearly) to the
// axis beside the side;
// side-face[-aligned]           a box face tangent to the side;
// flat-box, segment-box, point-box, zero-radius  zero extents (one, two,
// three), zero cylinder radius, at a spot;
// pattern-kiss|slab-face|slab-side|stand|lie|f32  patterns from public
// bug reports (gaps ~1e-8 of the scene, thin
// slabs 100 x 100 x 0.1, resting on a big
// box, coordinates rounded to float at
// offsets 40..100);
// exact-...                     exact integer constructions (a corner on
// the rim of a Pythagorean radius at the cap
// height, faces tangent to the side or on a
// cap, inscribed and circumscribed boxes,
// zero extents, zero radius), exact moves.
// Suffixes: -touch (touching, then the radius and the extents grown or
// shrunk by up to 2 ulps), -gap / -deep (a small or large gap either way);
// exact touches: -touch / -ulps-in / -ulps-out (the radius or a cap moved
// by k ulps). Scales 2^-20..2^20, optionally far from the origin.
//
// wild:
// Wild doubles everywhere; a quarter of the boxes keep a valid frame with
// wild centre and extents.
#include "common.hpp"

namespace geomcheck::gen {

using namespace detail;

namespace {


// The same box stored another way: (axis, extent) pairs permuted, axes
// negated (exact).
Obb restate(const Obb& b) {
  const int perm = pick_int(0, 5), signs = pick_int(0, 7);
  Obb o = b;
  for (int j = 0; j < 3; ++j) {
    const int i = kPerms[perm][j];
    o.axes[j] = (signs >> j) & 1 ? -b.axes[i] : b.axes[i];
    o.e[j] = b.e[i];
  }
  return o;
}

// The box of frame a and half extents e whose point of box coordinates s
// (|s_i| <= 1) is x.
Obb box_at(Vec3 x, const Axes& a, Vec3 e, Vec3 s) {
  Obb b;
  b.axes = a;
  b.e = e;
  b.c = x - (s.x * e.x) * a[0] - (s.y * e.y) * a[1] - (s.z * e.z) * a[2];
  return b;
}
// Box coordinates of a corner minimising n.x: from it every edge goes in a
// direction with a non-negative n component, so the box lies in n.(y - x) >= 0.
Vec3 lowest(const Axes& a, Vec3 n) {
  return {dot(n, a[0]) > 0 ? -1.0 : 1.0, dot(n, a[1]) > 0 ? -1.0 : 1.0, dot(n, a[2]) > 0 ? -1.0 : 1.0};
}
Vec3 pick_extents(double size) { return size * Vec3{pick_real(0.05, 2), pick_real(0.05, 2), pick_real(0.05, 2)}; }


// The gap's tag; a touch (gap 0) is nudged by k ulps in [-2, 2] first: the
// cylinder radius and the box extents grow (k > 0: towards overlap, both
// shapes only grow) or shrink. (In these constructions rounding is of the
// same order as the nudge, so the tag stays "-touch".)
std::string touch_or_gap(Cylinder& c, Obb& b, double gap) {
  if (gap == 0) {
    const int k = pick_int(-2, 2);
    c.r = std::max(0.0, nudge(c.r, k));
    b.e = {std::max(0.0, nudge(b.e.x, k)), std::max(0.0, nudge(b.e.y, k)), std::max(0.0, nudge(b.e.z, k))};
  }
  return gap_tag(gap);
}

const char* const kFeatureNames[3] = {"corner", "edge", "face"};

// A box corner (feature 0), edge (1) or face (2) at a cylinder spot: the box
// lies in out.(y - at) >= gap and holds at + gap out, so for gap >= 0 its
// distance to the cylinder is gap (to rounding). Corner: any frame, the
// corner lowest along `out`; edge: an axis across `out`, the other two turned
// about it by a random angle; face: an axis along `out`.
Obb box_feature_at(const Spot& sp, double gap, int feature, Vec3 e) {
  Axes a;
  if (feature == 0) {
    a = pick_box_frame();
  } else if (feature == 1) {
    const Vec3 d0 = across(sp), w = cross(d0, sp.out);
    const double g = pick_real(0, kTwoPi);
    a = settle({d0, std::cos(g) * sp.out + std::sin(g) * w, std::cos(g) * w - std::sin(g) * sp.out});
  } else {
    const Vec3 d0 = across(sp);
    a = settle({sp.out, d0, cross(sp.out, d0)});
  }
  Vec3 s = lowest(a, sp.out);
  if (feature == 1) s.x = pick_real(-1, 1);
  if (feature == 2) s.y = pick_real(-1, 1), s.z = pick_real(-1, 1);
  return box_at(sp.at + gap * sp.out, a, e, s);
}

// Random poses: any box frame, the centre within 4 scene sizes of the
// cylinder's middle (true hit rate about 40%).
ObbCase obb_random(const Scene& sc, const Frame& f) {
  Obb b;
  b.axes = pick_box_frame();
  b.e = pick_extents(sc.size);
  b.c = 0.5 * (f.c.p + f.c.q) + sc.size * Vec3{pick_real(-4, 4), pick_real(-4, 4), pick_real(-4, 4)};
  return {{f.c, restate(b)}, "random"};
}

// A box corner, edge or face at the rim (above the cap outside the rim,
// beside the side, diagonal), on a cap or on the side; corners also in the
// capsule pocket: over the cap disc, within r of the cap centre, the box
// wholly beyond the cap plane (in the bounding capsule, not in the
// cylinder: a certain miss).
ObbCase obb_feature(const Scene& sc, const Frame& f, int feature) {
  Cylinder c = f.c;
  if (feature == 0 && c.r > 0 && pick_int(0, 3) == 0) {
    const bool top = pick_int(0, 1);
    const Vec3 capn = top ? f.u : -f.u;
    const double rho = c.r * std::sqrt(pick_real(0, 0.99));
    const double hgt = pick_real(0.02, 0.98) * std::sqrt(std::max(0.0, c.r * c.r - rho * rho));
    const Vec3 x = (top ? c.q : c.p) + rho * radial_dir(f, pick_real(0, kTwoPi)) + hgt * capn;
    const Axes a = pick_box_frame();
    return {{c, restate(box_at(x, a, pick_extents(sc.size), lowest(a, capn)))}, "corner-pocket"};
  }
  const Spot sp = pick_spot(f, pick_region());
  const double gap = pick_gap(sc.size);
  Obb b = box_feature_at(sp, gap, feature, pick_extents(sc.size));
  const std::string t = touch_or_gap(c, b, gap);
  return {{c, restate(b)}, std::string(kFeatureNames[feature]) + "-" + sp.name + t};
}

// A box section off the corner's radial line. In the cap plane, the corner
// W lowest along the cap normal sits over the disc at radius rho; from it the
// long edge rises at a small slope and passes the axis at rho * sin(alpha),
// ending near there, so the box corner nearest the axis (and the box point
// nearest the axis segment) is above the cap, about 60-90 degrees round from
// W. W pokes through the cap plane by delta ("-deep": the section, a small
// polygon around W, overlaps the disc beside that corner's radial line: a
// one-ray-per-plane step 3 misses it), hovers delta above ("-gap": the
// mirrored near miss, distance delta) or touches (+- ulps).
ObbCase obb_offray(const Scene& sc, const Frame& f) {
  Cylinder c = f.c;
  if (c.r == 0) c.r = sc.size;
  const bool top = pick_int(0, 1);
  const Vec3 capn = top ? f.u : -f.u;
  const Vec3 rad = radial_dir(f, pick_real(0, kTwoPi)), tng = cross(f.u, rad);
  const double rho = c.r * pick_real(0.3, 0.95);
  const double sin_a = pick_real(0.05, 0.5), cos_a = std::sqrt(1 - sin_a * sin_a);
  const Vec3 t = -cos_a * rad + (pick_int(0, 1) ? sin_a : -sin_a) * tng;
  const double slope = pick_real(0.02, 0.3);
  const Vec3 d0 = unit(t + slope * capn);
  const Vec3 w = unit(cross(d0, capn)), v = cross(w, d0);  // v: mostly along capn
  const double g = pick_real(0.2, 1.37);                  // the other edges rise at slopes >= 0.2
  const Axes a = settle({d0, std::cos(g) * w + std::sin(g) * v, std::cos(g) * v - std::sin(g) * w});
  const Vec3 e{0.5 * rho * cos_a * pick_real(0.8, 1.2) * std::hypot(1.0, slope), c.r * pick_real(0.05, 1),
               c.r * pick_real(0.05, 1)};
  const int kind = pick_int(0, 2);
  const double delta = pick_int(0, 1) ? std::ldexp(sc.size, -pick_int(20, 50)) : pick_real(0.001, 0.05) * slope * rho;
  const double gap = kind == 0 ? -delta : (kind == 1 ? delta : 0.0);
  Obb b = box_at((top ? c.q : c.p) + rho * rad + gap * capn, a, e, lowest(a, capn));
  const std::string tag = "offray" + touch_or_gap(c, b, gap);
  return {{c, restate(b)}, tag};
}

// A box face on a cap plane, the box beyond the cap ("above": the face and
// the cap are coplanar) or on the cylinder's side of it ("below": the box's
// face flush with the cap). In the plane the rectangle lies in
// rad.y >= r + gap with its edge (across rad) or corner at (r + gap) rad:
// gap > 0 clear of the rim, 0 touching it, < 0 reaching over the disc (by up
// to r a third of the time). "capface-above-over": the face over the disc,
// touching the cap (+- ulps); below, reaching over the disc overlaps
// ("-deep").
ObbCase obb_cap_face(const Scene& sc, const Frame& f) {
  Cylinder c = f.c;
  const bool top = pick_int(0, 1), above = pick_int(0, 1), edge = pick_int(0, 1);
  const Vec3 capn = top ? f.u : -f.u;
  const Vec3 rad = radial_dir(f, pick_real(0, kTwoPi));
  const double gamma = pick_int(0, 2) == 0 ? 0.0 : pick_real(0, kTwoPi);
  const Vec3 d0 = edge ? cross(f.u, rad) : std::cos(gamma) * f.e1 + std::sin(gamma) * f.e2;
  const Axes a = settle({capn, d0, cross(capn, d0)});
  const double gap = pick_int(0, 2) == 0 ? -c.r * pick_real(0, 1) : pick_gap(sc.size);
  Vec3 s = lowest(a, rad);
  s.x = above ? -1 : 1;
  if (edge) s.y = pick_real(-1, 1);
  Obb b = box_at((top ? c.q : c.p) + (c.r + gap) * rad, a, pick_extents(sc.size), s);
  std::string tag = above ? "capface-above" : "capface-below";
  if (above && gap < 0) {
    touch_or_gap(c, b, 0);
    tag += "-over";
  } else {
    tag += touch_or_gap(c, b, gap);
  }
  return {{c, restate(b)}, tag};
}

// The cylinder inside the box (the box's half widths are the cylinder's
// along each axis, plus a margin; "-snug": no margin, touching inside), or
// the box inside the cylinder (the largest scale that keeps every corner in,
// times a factor; "-snug": factor 1). Certain overlaps.
ObbCase obb_contain(const Scene& sc, const Frame& f) {
  Cylinder c = f.c;
  const Vec3 mid = 0.5 * (c.p + c.q);
  const double len = length(c.q - c.p);
  const bool snug = pick_int(0, 2) == 0;
  if (pick_int(0, 1)) {
    const Axes a = pick_int(0, 2) == 0 ? settle({f.u, f.e1, f.e2}) : pick_box_frame();
    Vec3 e;
    for (int i = 0; i < 3; ++i) {
      const double cu = std::fabs(dot(f.u, a[i]));
      e[i] = 0.5 * len * cu + c.r * std::sqrt(std::max(0.0, 1 - cu * cu));
      if (!snug) e[i] += pick_int(0, 1) ? std::ldexp(sc.size, -pick_int(20, 50)) : pick_real(0, 1) * sc.size;
    }
    Obb b;
    b.c = mid;
    b.axes = a;
    b.e = e;
    return {{c, restate(b)}, std::string("cyl-in-box") + (snug ? "-snug" : "")};
  }
  if (c.r == 0) c.r = sc.size;
  const Axes a = pick_box_frame();
  const Vec3 shape{pick_real(0.1, 1), pick_real(0.1, 1), pick_real(0.1, 1)};
  const double angle = pick_real(0, kTwoPi), across = pick_real(0, 0.5), along = pick_real(-0.4, 0.4);
  const Vec3 ctr = mid + (along * len) * f.u + (across * c.r) * radial_dir(f, angle);
  const double zc = dot(ctr - mid, f.u);
  const Vec3 pc = (ctr - mid) - zc * f.u;
  double tmax = INFINITY;
  for (int k = 0; k < 8; ++k) {
    const Vec3 v = ((k & 1) ? 1.0 : -1.0) * shape.x * a[0] + ((k & 2) ? 1.0 : -1.0) * shape.y * a[1] +
                   ((k & 4) ? 1.0 : -1.0) * shape.z * a[2];
    const double zv = dot(v, f.u);
    if (zv != 0) tmax = std::min(tmax, (0.5 * len - (zv > 0 ? zc : -zc)) / std::fabs(zv));
    const Vec3 pv = v - zv * f.u;
    const double qa = length2(pv), qb = dot(pc, pv), qc = length2(pc) - c.r * c.r;
    if (qa > 0) tmax = std::min(tmax, (-qb + std::sqrt(std::max(0.0, qb * qb - qa * qc))) / qa);
  }
  const double t = snug ? tmax : tmax * pick_real(0.1, 0.99);
  Obb b;
  b.c = ctr;
  b.axes = a;
  b.e = t * shape;
  return {{c, restate(b)}, std::string("box-in-cyl") + (snug ? "-snug" : "")};
}

// A thin disk-like cylinder (length 1e-6..1e-12 of r, at least 2^-44 of its
// coordinates) resting on a box face: flat (axis along the face normal),
// tilted, or edgewise (axis in the face plane), the contact inside the face
// or on its edge (a fifth of the time), touching (+- ulps) or a tiny gap
// either way.
// The box is placed under the stored cylinder's lowest point.
ObbCase obb_thin(const Scene& sc) {
  const Axes a = pick_box_frame();
  const int i = pick_int(0, 2), j = (i + 1) % 3, k = (i + 2) % 3;
  const double sg = pick_int(0, 1) ? 1.0 : -1.0;
  const Vec3 n = sg * a[i];
  const int orient = pick_int(0, 2);
  const Vec3 w = orient == 0 ? Vec3{} : [&] {
    const double th = pick_int(0, 2) == 0 ? 0.0 : pick_real(0, kTwoPi);
    return std::cos(th) * a[j] + std::sin(th) * a[k];
  }();
  const Vec3 u = orient == 0 ? (pick_int(0, 1) ? n : -n) : (orient == 1 ? unit(n + pick_real(0.01, 2) * w) : w);
  const double r = pick_real(0.05, 2) * sc.size;
  const Vec3 p = sc.offset + sc.size * Vec3{pick_real(-2, 2), pick_real(-2, 2), pick_real(-2, 2)};
  const double len = std::max(r * std::pow(10.0, -pick_real(6, 12)), std::ldexp(max_abs(p), -44));
  Cylinder c{p, p + len * u, r};
  if (pick_int(0, 1)) std::swap(c.p, c.q);
  const bool overhang = pick_int(0, 4) == 0;
  Vec3 s;
  s[i] = sg;
  s[j] = overhang ? (pick_int(0, 1) ? 1.0 : -1.0) : pick_real(-0.95, 0.95);
  s[k] = pick_real(-0.95, 0.95);
  const int gk = pick_int(0, 2);
  const double gap = gk == 0 ? 0.0 : (gk == 1 ? 1.0 : -1.0) * std::ldexp(sc.size, -pick_int(20, 50));
  const Vec3 e{pick_real(0.3, 3) * sc.size, pick_real(0.3, 3) * sc.size, pick_real(0.3, 3) * sc.size};
  Obb b = box_at(cylinder_lowest(c, n) - gap * n, a, e, s);
  const char* names[3] = {"thin-flat", "thin-tilted", "thin-edgewise"};
  const std::string tag = names[orient] + touch_or_gap(c, b, gap);
  return {{c, restate(b)}, tag};
}

// A box edge along the axis (exactly, or 1e-8 / 1e-16 from it) beside the
// side, the box's faces turned away from tangent, touching (+- ulps) or a gap.
ObbCase obb_axis_edge(const Scene& sc, const Frame& f) {
  Cylinder c = f.c;
  const Spot sp = pick_spot(f, 2);
  const double tilt = pick_tilt(), phi = pick_real(0, kTwoPi);
  const Vec3 d0 = tilt == 0 ? f.u : unit(f.u + tilt * (std::cos(phi) * sp.tan + std::sin(phi) * sp.out));
  const double g = pick_real(0.05, 1.52);
  const Axes a = settle({d0, std::cos(g) * sp.out + std::sin(g) * sp.tan, std::cos(g) * sp.tan - std::sin(g) * sp.out});
  const double len = length(c.q - c.p);
  const Vec3 e{pick_real(0.1, 1.5) * len, pick_real(0.05, 2) * sc.size, pick_real(0.05, 2) * sc.size};
  Vec3 s = lowest(a, sp.out);
  s.x = pick_real(-1, 1);
  const double gap = pick_gap(sc.size);
  Obb b = box_at(sp.at + gap * sp.out, a, e, s);
  const std::string tag = "axis-edge" + tilt_tag(tilt) + touch_or_gap(c, b, gap);
  return {{c, restate(b)}, tag};
}

// A box face tangent to the side: face normal radial, the face parallel to
// the axis at distance r + gap, its edges along the axis ("-aligned") or
// turned in the tangent plane.
ObbCase obb_side_face(const Scene& sc, const Frame& f) {
  Cylinder c = f.c;
  const Spot sp = pick_spot(f, 2);
  const bool aligned = pick_int(0, 1);
  const double g = aligned ? 0.0 : pick_real(0, kTwoPi);
  const Vec3 d0 = aligned ? f.u : std::cos(g) * f.u + std::sin(g) * sp.tan;
  const Axes a = settle({sp.out, d0, cross(sp.out, d0)});
  Vec3 s = lowest(a, sp.out);
  s.y = pick_real(-1, 1), s.z = pick_real(-1, 1);
  const double gap = pick_gap(sc.size);
  Obb b = box_at(sp.at + gap * sp.out, a, pick_extents(sc.size), s);
  const std::string tag = std::string("side-face") + (aligned ? "-aligned" : "") + touch_or_gap(c, b, gap);
  return {{c, restate(b)}, tag};
}

// Flat boxes (one extent 0), segment boxes (two), point boxes (three) at a
// cylinder spot, and boxes at a zero-radius cylinder (a segment).
ObbCase obb_degenerate(const Scene& sc, const Frame& f) {
  Frame g = f;
  const int kind = pick_int(0, 3);
  if (kind == 3) g.c.r = 0;
  const Spot sp = pick_spot(g, pick_region());
  const double gap = pick_gap(sc.size);
  Vec3 e = pick_extents(sc.size);
  if (kind < 3) {
    const int z = pick_int(0, 2);
    for (int m = 0; m <= kind; ++m) e[(z + m) % 3] = 0;
  }
  const int feature = pick_int(0, 2);
  Cylinder c = g.c;
  Obb b = box_feature_at(sp, gap, feature, e);
  const char* names[4] = {"flat-box", "segment-box", "point-box", "zero-radius"};
  const std::string tag = names[kind] + touch_or_gap(c, b, gap);
  return {{c, restate(b)}, tag};
}

// Exact integer constructions: the cylinder along +z from z0 to top = z0 + h,
// radius c k for a Pythagorean triple (a, b, c) (k = 0: zero radius); the
// box [lo, hi] with integer bounds, stored with a signed-permutation frame;
// then exact moves. In the cap plane the box section is "rim-corner" (corner
// at (a k, b k) on the rim), "tangent" (face x = c k, across y = 0),
// "inscribed" ([-a k, a k] x [-b k, b k], corners on the rim),
// "circumscribed" ([-c k, c k]^2, faces tangent), "over" (around an integer
// point of the inscribed rectangle) or "outside" (x >= c k + 1..3: a certain
// gap); along the axis "above" (z >= top: a face coplanar with the cap),
// "below" (z <= z0), "across" (the top cap plane), "within" or "through".
// Tags: exact-<section>-<axial> for touches, exact-<section>-overlap for
// certain overlaps, exact-outside, exact-zero-extent (some extents 0: flat,
// segment and point boxes). Exact touches are nudged by k ulps towards
// overlap (k > 0) or away: the radius for rim and side contacts, the cap
// along the axis for face contacts on a cap.
ObbCase exact_cylinder_obb() {
  const auto& t1 = kTriples[pick_int(0, kNumTriples - 1)];
  const int k = pick_int(0, 12) == 0 ? 0 : pick_int(1, 4);
  const int h = pick_int(1, 20), z0 = pick_int(-10, 10), top = z0 + h;
  const int A = t1[0] * k, B = t1[1] * k, C = t1[2] * k;
  const Exact ex = pick_exact();
  Cylinder cyl{ex.apply({0, 0, double(z0)}), ex.apply({0, 0, double(top)}), ex.len(C)};
  int lo[3], hi[3];
  const int xk = pick_int(0, 5);
  int pi = 0, pj = 0;
  switch (xk) {
    case 0:
      lo[0] = A, hi[0] = A + pick_int(1, 20), lo[1] = B, hi[1] = B + pick_int(1, 20);
      break;
    case 1:
    case 5:
      lo[0] = C + (xk == 5 ? pick_int(1, 3) : 0), hi[0] = lo[0] + pick_int(1, 20);
      lo[1] = -pick_int(0, 10), hi[1] = pick_int(0, 10);
      break;
    case 2:
      lo[0] = -A, hi[0] = A, lo[1] = -B, hi[1] = B;
      break;
    case 3:
      lo[0] = -C, hi[0] = C, lo[1] = -C, hi[1] = C;
      break;
    default:
      pi = pick_int(-A, A), pj = pick_int(-B, B);
      lo[0] = pi - pick_int(0, 10), hi[0] = pi + pick_int(0, 10);
      lo[1] = pj - pick_int(0, 10), hi[1] = pj + pick_int(0, 10);
      break;
  }
  const int zk = pick_int(0, 4);
  switch (zk) {
    case 0: lo[2] = top, hi[2] = top + pick_int(1, 20); break;
    case 1: hi[2] = z0, lo[2] = z0 - pick_int(1, 20); break;
    case 2: lo[2] = top - pick_int(1, h), hi[2] = top + pick_int(1, 20); break;
    case 3: lo[2] = z0 + pick_int(0, h), hi[2] = pick_int(lo[2], top); break;
    default: lo[2] = z0 - pick_int(0, 5), hi[2] = top + pick_int(0, 5); break;
  }
  // 0: touching through the radius, 1: through a cap, 2: certain overlap, 3: certain gap.
  int contact = xk <= 1 ? 0 : (xk == 5 ? 3 : (zk <= 1 ? 1 : 2));
  int zeros = 0;
  if (pick_int(0, 4) == 0) {
    for (int i = 0; i < 3; ++i) {
      if (pick_int(0, 2) != 0 || (i == 2 && zk == 2)) continue;
      ++zeros;
      if (i == 2) {
        if (zk == 1) lo[2] = hi[2];
        else if (zk == 4) lo[2] = hi[2] = pick_int(z0, top);
        else hi[2] = lo[2];
      } else if (xk == 1 || xk == 5) {
        if (i == 0) hi[0] = lo[0];
        else lo[1] = hi[1] = 0;
      } else if (xk == 4) {
        lo[i] = hi[i] = i == 0 ? pi : pj;
      } else {
        hi[i] = lo[i];
        if (xk == 3) contact = 0;  // a face of the circumscribed square: tangent to the side
      }
    }
  }
  Obb b;
  Vec3 cc;
  for (int i = 0; i < 3; ++i) {
    cc[i] = 0.5 * (lo[i] + hi[i]);
    b.e[i] = ex.len(0.5 * (hi[i] - lo[i]));
    b.axes[i] = ex.turn({i == 0 ? 1.0 : 0.0, i == 1 ? 1.0 : 0.0, i == 2 ? 1.0 : 0.0});
  }
  b.c = ex.apply(cc);
  const char* xy[6] = {"rim-corner", "tangent", "inscribed", "circumscribed", "over", "outside"};
  const char* zs[5] = {"above", "below", "across", "within", "through"};
  std::string tag = zeros > 0 ? "exact-zero-extent"
                    : contact == 3 ? "exact-outside"
                    : contact == 2 ? std::string("exact-") + xy[xk] + "-overlap"
                                   : std::string("exact-") + xy[xk] + "-" + zs[zk];
  if (contact <= 1) {
    const int ulps = C == 0 && contact == 0 ? pick_int(0, 2) : pick_int(-2, 2);
    if (contact == 0) {
      cyl.r = std::max(0.0, nudge(cyl.r, ulps));
    } else {
      const int s = ex.slot(2);
      Vec3& cap = zk == 0 ? cyl.q : cyl.p;
      const double out = (zk == 0 ? 1.0 : -1.0) * ex.sign(2);  // away from the cylinder, in world
      cap[s] = nudge(cap[s], out > 0 ? ulps : -ulps);
    }
    tag += ulps_tag(ulps);
  }
  return {{cyl, restate(b)}, tag};
}


// Patterns seen in public bug reports of collision libraries: boxes kissing
// a cylinder with gaps ~1e-8 of the scene; thin slabs (100 x 100 x 0.1)
// under the cylinder (on the big face or the thin side); a cylinder standing
// or lying on a big box; and float32-valued coordinates (every position,
// radius and extent rounded to float) at offsets 40..100.
ObbCase obb_pattern() {
  const int kind = pick_int(0, 4);
  Scene sc = pick_scene();
  if (kind == 4) {
    sc.size = 1;
    for (int i = 0; i < 3; ++i) {
      const double sign = pick_int(0, 1) ? 1 : -1;
      sc.offset[i] = sign * pick_real(40, 100);
    }
  }
  const Frame f = pick_cylinder(sc);
  Cylinder c = f.c;
  if (kind == 0) {
    const Spot sp = pick_spot(f, pick_region());
    const double sign = pick_int(0, 1) ? 1 : -1, gap = sign * 1e-8 * pick_real(0.5, 2) * sc.size;
    const int feature = pick_int(0, 2);
    Obb b = box_feature_at(sp, gap, feature, pick_extents(sc.size));
    return {{c, restate(b)}, "pattern-kiss" + gap_tag(gap)};
  }
  const int sub = kind == 4 ? pick_int(0, 2) : kind;  // 1 slab, 2 stand or lie, (f32) 0 corner
  Axes a;
  if (kind == 4 && pick_int(0, 1)) {
    const int signs = pick_int(0, 7), perm = pick_int(0, 5);
    a = rat_frame(pyth_rotation(0), perm, signs);
  } else {
    a = pick_box_frame();
  }
  const double gap = pick_gap(sc.size);
  Obb b;
  std::string what;
  if (sub == 0) {
    const Spot sp = pick_spot(f, pick_region());
    b = box_feature_at(sp, gap, 0, pick_extents(sc.size));
    what = "corner";
  } else {
    const int i = pick_int(0, 2), j = (i + 1) % 3, k = (i + 2) % 3;
    const double sg = pick_int(0, 1) ? 1.0 : -1.0;
    const Vec3 n = sg * a[i];
    Vec3 e, s;
    s[i] = sg;
    s[j] = pick_real(-0.9, 0.9);
    s[k] = pick_real(-0.9, 0.9);
    if (sub == 1) {  // slab: thin along a[2]; the cylinder on its big face (i == 2) or its thin side
      const double unit_len = pick_real(0.05, 0.3) * sc.size;
      e = {50 * unit_len, 50 * unit_len, 0.05 * unit_len};
      if (i != 2) s[2] = pick_real(-1, 1);
      what = i == 2 ? "slab-face" : "slab-side";
    } else {  // a big box; the cylinder stands (axis along n) or lies (axis across n) on the face
      e[i] = pick_real(1, 5) * sc.size;
      e[j] = pick_real(10, 100) * sc.size;
      e[k] = pick_real(10, 100) * sc.size;
      const bool stand = pick_int(0, 1);
      const double th = pick_int(0, 2) == 0 ? 0.0 : pick_real(0, kTwoPi);
      const Vec3 u = stand ? (pick_int(0, 1) ? n : -n) : std::cos(th) * a[j] + std::sin(th) * a[k];
      c.q = c.p + f.len * u;
      what = stand ? "stand" : "lie";
    }
    b = box_at(cylinder_lowest(c, n) - gap * n, a, e, s);
  }
  if (kind == 4) {
    c = {to_f32(c.p), to_f32(c.q), to_f32(c.r)};
    b.c = to_f32(b.c);
    b.e = to_f32(b.e);
    return {{c, restate(b)}, "pattern-f32" + gap_tag(gap)};
  }
  const std::string t = touch_or_gap(c, b, gap);
  return {{c, restate(b)}, "pattern-" + what + t};
}

}  // namespace

template <>
rc::Gen<Tagged<QueryTraits<QueryId::collide_cylinder_obb>::Case>> targeted<QueryId::collide_cylinder_obb>() {
  return rc::gen::resize(100, rc::gen::exec([]() -> std::pair<CylinderObbCase, std::string> {
    const int mode = pick_int(0, 13);
    if (mode == 12 || mode == 13) return exact_cylinder_obb();
    if (mode == 11) return obb_pattern();
    const Scene sc = pick_scene();
    if (mode == 7) return obb_thin(sc);
    const Frame f = pick_cylinder(sc);
    switch (mode) {
      case 0: return obb_random(sc, f);
      case 1:
      case 2:
      case 3: return obb_feature(sc, f, mode - 1);
      case 4: return obb_offray(sc, f);
      case 5: return obb_cap_face(sc, f);
      case 6: return obb_contain(sc, f);
      case 8: return obb_axis_edge(sc, f);
      case 9: return obb_side_face(sc, f);
      default: return obb_degenerate(sc, f);
    }
  }));
}

template <>
rc::Gen<QueryTraits<QueryId::collide_cylinder_obb>::Case> wild<QueryId::collide_cylinder_obb>() {
  return rc::gen::resize(100, rc::gen::exec([]() -> CylinderObbCase {
    const Cylinder a{wild_vec(), wild_vec(), *wild_double()};
    Obb b;
    b.c = wild_vec();
    if (pick_int(0, 3) == 0) {  // a valid frame, wild extents
      b.axes = pick_box_frame();
    } else {
      b.axes = {wild_vec(), wild_vec(), wild_vec()};
    }
    b.e = wild_vec();
    return {a, b};
  }));
}

}  // namespace geomcheck::gen
