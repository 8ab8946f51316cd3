// geomcheck — generators of collide_cylinder_triangle: targeted modes and wild doubles.
//
// targeted:
// Cylinder/triangle pairs. Modes, by tag:
// random                        random triangles near the cylinder;
// vertex-/edge-/face-<spot>     a triangle vertex, edge or face at the rim
// (rim-above, rim-side, rim-diag), a cap or
// the side; edges along the rim's or the
// side's circle (-along: tangent to the
// rim, to the side), across it (-across:
// crossing the rim, along the axis on the
// side) or any way across the normal;
// point-|segment-|collinear-|sliver-<vertex|edge>-<spot>  degenerate
// triangles at the same contacts (a point,
// two equal vertices, three collinear, the
// third vertex 1e-8, 1e-16 or 2^-30..2^-60
// of the edge off the line);
// capplane-above|on|below-vertex|edge|over  a triangle parallel to a cap
// (above it: a certain miss; in its plane;
// inside the slab) with a vertex or an edge
// at in-plane radius r + gap, or over the
// disc;
// axisplane-through|chord-side|cap|corner-vertex|edge, -across,
// axisplane-through-axis-edge,
// axisplane-beside              a triangle in a plane parallel to the
// axis (through it, cutting a chord, at
// r + gap), a vertex or an edge at the
// section's long side, short side or
// corner (in-plane gap), covering a
// point of the section, or with an edge
// along the axis (-axis-edge: its ends a
// few ulps off the axis line);
// capcross-deep|gap|touch|outside  a tilted triangle through a cap plane
// whose point nearest the axis segment is
// beyond the cap (within r of its centre)
// while its vertex W pokes through the disc
// (-deep: overlapping), hovers over it
// (-gap), touches it, or pokes through just
// outside the rim (-outside: a miss); also
// collapsed (segment-, collinear-, sliver-);
// huge-stand|tilted|lie[-edge]  a small cylinder on a triangle 10^2..10^4
// times its size (touching, a tiny or small
// gap or penetration; -edge: the contact on
// the triangle's edge);
// thin-flat|tilted|edgewise[-edge]  a disk-like cylinder (length 1e-6..1e-12
// of r) on a triangle;
// pattern-f32                   vertex/edge/face contacts at offsets
// 40..100, every value rounded to float;
// exact-...                     exact integer constructions (a vertex on
// the rim, the side or a cap, edges tangent
// to the side or the rim, triangles in the
// cap plane at the rim or over the disc, an
// edge across a zero-radius cylinder; also
// point-, segment-, collinear-), exact moves.
// Suffixes: -touch (touching, then the radius grown or shrunk and the
// triangle moved by up to 2 ulps), -gap / -deep (a small or large gap
// either way); exact touches: -touch / -ulps-in / -ulps-out / -ulps-off,
// exact -gap / -deep (moved exactly: out along the contact normal, or from
// the contact 2^-1..2^-25 of the way towards the cylinder's centre). Scales
// 2^-20..2^20, optionally far from the origin.
//
// wild:
// Wild doubles everywhere; a quarter of the triangles repeat a vertex
// (segment and point triangles).
#include "common.hpp"

namespace geomcheck::gen {

using namespace detail;

namespace {

using TriCase = std::pair<CylinderTriangleCase, std::string>;

// The same triangle stored another way: the vertices shifted cyclically and
// reversed or not (both orientations of its normal).
Triangle restate(const Triangle& t) {
  Triangle o = t;
  for (int i = pick_int(0, 2); i > 0; --i) o = {o.b, o.c, o.a};
  if (pick_int(0, 1)) std::swap(o.b, o.c);
  return o;
}

// The gap's tag; a touch (gap 0) is nudged by k ulps in [-2, 2] first: the
// cylinder radius grows (k > 0) or shrinks by k ulps, and the triangle moves
// by k ulps of the scene's largest coordinate along -out, `out` pointing from
// the cylinder towards the triangle (k > 0: towards overlap).
std::string tri_touch_or_gap(Cylinder& c, Triangle& t, Vec3 out, double gap) {
  if (gap == 0) {
    const int k = pick_int(-2, 2);
    c.r = std::max(0.0, nudge(c.r, k));
    const double m = std::max({max_abs(c.p), max_abs(c.q), c.r, max_abs(t.a), max_abs(t.b), max_abs(t.c)});
    const Vec3 step = (k * std::ldexp(m, -52)) * out;
    t = {t.a - step, t.b - step, t.c - step};
  }
  return gap_tag(gap);
}

// Edge lengths: 0.05..3 scene sizes, a sixth of the time 10..100.
double tri_len(double size) { return (pick_int(0, 5) == 0 ? pick_real(10, 100) : pick_real(0.05, 3)) * size; }

// A unit direction in the plane of the unit vectors e and w (perpendicular),
// with a non-negative e component.
Vec3 half_dir(Vec3 e, Vec3 w) {
  const double phi = pick_real(-1.5707963267948966, 1.5707963267948966);
  return std::cos(phi) * e + std::sin(phi) * w;
}

// A triangle in the plane of the unit vectors e1, e2 (perpendicular) holding
// x strictly inside: vertices at distances 0.3..1 times len, about 120
// degrees apart (every angle between neighbours below 180 degrees).
Triangle face_around(Vec3 x, Vec3 e1, Vec3 e2, double len) {
  const double th = pick_real(0, kTwoPi);
  Vec3 v[3];
  for (int i = 0; i < 3; ++i) {
    const double a = th + i * (kTwoPi / 3) + pick_real(-0.4, 0.4);
    v[i] = x + (len * pick_real(0.3, 1)) * (std::cos(a) * e1 + std::sin(a) * e2);
  }
  return {v[0], v[1], v[2]};
}

// Edge directions at a spot: along `tan` (tangent to the rim or the side's
// circle), along `bi` (across the rim or the side, in the plane of the axis),
// or any direction across `out`.
const char* const kTriEdgeDirs[3] = {"-along", "-across", ""};

// A triangle vertex (feature 0), edge (1) or face (2) at the point x of a
// spot's half-space out.(y - x) >= 0: x is vertex a, lies on edge ab (the
// edge across `out`, direction by edge_dir), or lies inside the face (the
// plane across `out`). With x = at + gap out the triangle's distance to the
// cylinder is gap for gap >= 0 (to rounding).
Triangle tri_feature_at(const Spot& sp, Vec3 x, int feature, int edge_dir, double size) {
  if (feature == 0) {
    const Vec3 db = pick_int(0, 3) == 0 ? across(sp) : away(sp);
    const Vec3 b = x + tri_len(size) * db;
    const Vec3 dc = away(sp);
    return {x, b, x + tri_len(size) * dc};
  }
  if (feature == 1) {
    const Vec3 d = edge_dir == 0 ? sp.tan : (edge_dir == 1 ? sp.bi : across(sp));
    const double la = tri_len(size), lb = tri_len(size);
    const Vec3 dc = away(sp);
    return {x - la * d, x + lb * d, x + tri_len(size) * dc};
  }
  return face_around(x, sp.tan, sp.bi, tri_len(size));
}

// Degenerate triangles at the same contact x (vertex a, or a point of edge
// ab), staying in out.(y - x) >= 0: "point" (every vertex at x), "segment"
// (c repeats a or b), "collinear" (c on line ab, from a, or from 0.5 |ab|
// before a when ab lies across `out`, to 0.5 |ab| beyond b: inside the edge
// or extending it either way), "sliver" (collinear, then moved off the line
// by 1e-8, 1e-16 or 2^-30..2^-60 of |ab| to the side of `out`). Returns the
// tag prefix.
std::string collapse(Triangle& t, Vec3 x, Vec3 out, bool two_sided, bool allow_point = true) {
  const int kind = pick_int(allow_point ? 0 : 1, 3);
  if (kind == 0) {
    t = {x, x, x};
    return "point-";
  }
  if (kind == 1) {
    t.c = pick_int(0, 1) ? t.a : t.b;
    return "segment-";
  }
  const Vec3 ab = t.b - t.a;
  t.c = t.a + pick_real(two_sided ? -0.5 : 0.0, 1.5) * ab;
  if (kind == 2) return "collinear-";
  const double l = length(ab);
  if (l > 0) {
    const Vec3 p1 = any_perpendicular(ab), p2 = (1 / l) * cross(ab, p1);
    const double th = pick_real(0, kTwoPi);
    Vec3 w = std::cos(th) * p1 + std::sin(th) * p2;
    if (dot(w, out) < 0) w = -w;
    const int e = pick_int(0, 2);
    t.c = t.c + (l * (e == 0 ? 1e-8 : (e == 1 ? 1e-16 : std::ldexp(1.0, -pick_int(30, 60))))) * w;
  }
  return "sliver-";
}

// Random poses: vertices within 2 scene sizes of a point within 3 of the
// cylinder's middle.
TriCase tri_random(const Scene& sc, const Frame& f) {
  const Vec3 m = 0.5 * (f.c.p + f.c.q) + sc.size * Vec3{pick_real(-3, 3), pick_real(-3, 3), pick_real(-3, 3)};
  auto v = [&] { return m + sc.size * Vec3{pick_real(-2, 2), pick_real(-2, 2), pick_real(-2, 2)}; };
  return {{f.c, Triangle{v(), v(), v()}}, "random"};
}

// A triangle vertex, edge or face at the rim (rim-above, rim-side,
// rim-diag), on a cap or on the side, touching (+- ulps) or a gap either way.
// Edges along the rim's or the side's circle ("-along": tangent to the rim,
// to the side), across it ("-across": crossing the rim, or along the axis on
// the side) or any direction across the normal. With `degenerate`, the
// triangle collapsed at the contact (collapse()).
TriCase tri_feature(const Scene& sc, const Frame& f, int feature, bool degenerate) {
  Cylinder c = f.c;
  const Spot sp = pick_spot(f, pick_region());
  const double gap = pick_gap(sc.size);
  const int edge_dir = pick_int(0, 2);
  const Vec3 x = sp.at + gap * sp.out;
  Triangle t = tri_feature_at(sp, x, feature, edge_dir, sc.size);
  std::string tag = std::string(feature == 0 ? "vertex-" : (feature == 1 ? "edge-" : "face-")) + sp.name +
                    (feature == 1 ? kTriEdgeDirs[edge_dir] : "");
  if (degenerate) tag = collapse(t, x, sp.out, feature == 1) + tag;
  tag += tri_touch_or_gap(c, t, sp.out, gap);
  return {{c, restate(t)}, tag};
}

// A triangle parallel to a cap: above it ("above": a tiny or a large height,
// a certain miss), in the cap plane ("on") or inside the slab ("below": a
// tiny depth or up to the length). In its plane it has a vertex ("-vertex")
// or an edge across the radius ("-edge") at in-plane radius r + gap, the
// triangle beyond (gap > 0 clear of the rim's circle, 0 touching it, < 0
// reaching over the disc), or it covers a point of the disc ("-over": "on"
// touches the cap face, "below" a certain overlap).
TriCase tri_cap_parallel(const Scene& sc, const Frame& f) {
  Cylinder c = f.c;
  const bool top = pick_int(0, 1);
  const Vec3 capn = top ? f.u : -f.u, capc = top ? c.q : c.p;
  const Vec3 rad = radial_dir(f, pick_real(0, kTwoPi)), tng = cross(f.u, rad);
  const int level = pick_int(0, 2), feature = pick_int(0, 2);
  const bool tiny = pick_int(0, 1);
  const double height = level == 1   ? 0.0
                        : level == 0 ? (tiny ? std::ldexp(sc.size, -pick_int(20, 50)) : pick_real(0.01, 2) * sc.size)
                                     : -(tiny ? std::ldexp(sc.size, -pick_int(20, 50)) : pick_real(0, 1) * f.len);
  const Vec3 o = capc + height * capn;
  const double gap = feature == 2 ? 0.0 : pick_gap(sc.size);
  Triangle t;
  if (feature == 2) {
    const double len = tri_len(sc.size), rho = c.r * std::sqrt(pick_real(0, 1));
    t = face_around(o + rho * rad, rad, tng, len);
  } else {
    const Vec3 x = o + (c.r + gap) * rad;
    // (Each direction drawn before its length: the order g++ took them in
    // before the draws were sequenced.)
    if (feature == 0) {
      const Vec3 db = half_dir(rad, tng);
      const Vec3 b = x + tri_len(sc.size) * db;
      const Vec3 dc = half_dir(rad, tng);
      t = {x, b, x + tri_len(sc.size) * dc};
    } else {
      const double la = tri_len(sc.size), lb = tri_len(sc.size);
      const Vec3 dc = half_dir(rad, tng);
      t = {x - la * tng, x + lb * tng, x + tri_len(sc.size) * dc};
    }
  }
  const char* levels[3] = {"capplane-above", "capplane-on", "capplane-below"};
  const char* features[3] = {"-vertex", "-edge", "-over"};
  std::string tag = std::string(levels[level]) + features[feature];
  if (level == 1 && feature == 2) tag += tri_touch_or_gap(c, t, capn, 0);
  else if (level != 0 && feature != 2) tag += tri_touch_or_gap(c, t, rad, gap);
  return {{c, restate(t)}, tag};
}

// A triangle in a plane parallel to the axis: through the axis ("through"),
// cutting a chord ("chord": at 0.05..0.95 r from the axis), or at r + gap
// from it ("beside": tangent to the side, clear of it, or cutting it near
// the side; the triangle covers a point of the plane's line nearest the
// axis, between the caps). Through and chord: the section is the rectangle
// [0, len] x [-w, w] (along the axis, across it); the triangle has a vertex
// or an edge at its long side ("-side"), its short side ("-cap") or a
// corner ("-corner": a rim point) with the triangle beyond the in-plane gap,
// or it covers a point of the section ("-across": a certain overlap).
TriCase tri_axis_plane(const Scene& sc, const Frame& f) {
  Cylinder c = f.c;
  const Vec3 rad = radial_dir(f, pick_real(0, kTwoPi)), tng = cross(f.u, rad);
  const int kind = pick_int(0, 2);
  const double len = length(c.q - c.p);
  if (kind == 2) {
    const double gap = pick_gap(sc.size);
    const double len = tri_len(sc.size), along = pick_real(0, 1);
    Triangle t = face_around(c.p + along * (c.q - c.p) + (c.r + gap) * rad, f.u, tng, len);
    const std::string tag = "axisplane-beside" + tri_touch_or_gap(c, t, rad, gap);
    return {{c, restate(t)}, tag};
  }
  const double s = kind == 0 ? 0.0 : c.r * pick_real(0.05, 0.95);
  const double w = kind == 0 ? c.r : std::sqrt(std::max(0.0, c.r * c.r - s * s));
  const Vec3 o = c.p + s * rad;
  auto at = [&](double along, double acr) { return o + along * f.u + acr * tng; };
  std::string tag = kind == 0 ? "axisplane-through" : "axisplane-chord";
  const int place = pick_int(0, kind == 0 ? 4 : 3);
  if (place == 4) {
    // An edge along the axis line (its ends computed from p and q, so a few
    // ulps off it), the third vertex in the plane across it: the edge's
    // direction in a cap plane is rounding noise.
    auto on_axis = [&](double t) { return t <= 0.5 ? c.p + t * (c.q - c.p) : c.q - (1 - t) * (c.q - c.p); };
    const double t0 = pick_int(0, 2) == 0 ? 0.0 : pick_real(-0.5, 0.5);
    const double t1 = pick_int(0, 2) == 0 ? 1.0 : pick_real(0.5, 1.5);
    const double across = pick_real(0.1, 3), sign = pick_int(0, 1) ? 1 : -1, along = pick_real(-0.5, 1.5);
    const Triangle t{on_axis(t0), on_axis(t1), at(along * len, across * w * sign)};
    return {{c, restate(t)}, tag + "-axis-edge"};
  }
  if (place == 3) {
    const double size = tri_len(sc.size), across = pick_real(-1, 1), along = pick_real(0, 1);
    Triangle t = face_around(at(along * len, across * w), f.u, tng, size);
    return {{c, restate(t)}, tag + "-across"};
  }
  const double gap = pick_gap(sc.size);
  const double sa = pick_int(0, 1) ? 1.0 : -1.0, st = pick_int(0, 1) ? 1.0 : -1.0;
  Vec3 x, out;
  if (place == 0) {
    out = sa * tng;
    x = at(pick_real(0, 1) * len, sa * (w + gap));
    tag += "-side";
  } else if (place == 1) {
    out = st * f.u;
    x = at(st > 0 ? len + gap : -gap, pick_real(-1, 1) * w);
    tag += "-cap";
  } else {
    const double psi = pick_real(0, 1.5707963267948966);
    out = std::cos(psi) * (st * f.u) + std::sin(psi) * (sa * tng);
    x = at(st > 0 ? len : 0.0, sa * w) + gap * out;
    tag += "-corner";
  }
  const Vec3 perp = cross(rad, out);  // in the plane, across `out`
  Triangle t;
  if (pick_int(0, 1)) {
    const Vec3 db = half_dir(out, perp);
    const Vec3 b = x + tri_len(sc.size) * db;
    const Vec3 dc = half_dir(out, perp);
    t = {x, b, x + tri_len(sc.size) * dc};
    tag += "-vertex";
  } else {
    const double la = tri_len(sc.size), lb = tri_len(sc.size);
    const Vec3 dc = half_dir(out, perp);
    t = {x - la * perp, x + lb * perp, x + tri_len(sc.size) * dc};
    tag += "-edge";
  }
  tag += tri_touch_or_gap(c, t, out, gap);
  return {{c, restate(t)}, tag};
}

// A tilted triangle through a cap plane whose point nearest the axis segment
// lies beyond the cap. Vertex W is over the cap disc at radius rho (0.3..0.95
// r); the other two rise from it at slopes 0.02..0.3 towards the axis and past
// it (horizontally 10..50 degrees either side of the inward radius), so the
// triangle passes over the axis at a height of about slope * rho: its point
// nearest the axis segment is beyond the cap, within r of the cap centre,
// while its section by the cap plane is a short segment next to W. W pokes
// through the cap plane by delta ("capcross-deep": the section lies in the
// disc, overlapping; a query without its cap stage misses it), hovers delta
// above it ("-gap": the near miss), touches it ("-touch", +- ulps), or pokes
// through just outside the rim's circle ("-outside": W at radius r + 1.5..3
// delta / slope, the section clear of the disc, a miss). A fifth of the time
// the triangle is collapsed onto its edges from W (segment, collinear,
// sliver).
TriCase tri_cap_cross(const Scene& sc, const Frame& f) {
  Cylinder c = f.c;
  if (c.r == 0) c.r = sc.size;
  const bool top = pick_int(0, 1);
  const Vec3 capn = top ? f.u : -f.u, capc = top ? c.q : c.p;
  const Vec3 rad = radial_dir(f, pick_real(0, kTwoPi)), tng = cross(f.u, rad);
  const int kind = pick_int(0, 4);  // 0, 1 deep, 2 gap, 3 touch, 4 outside
  const double s1 = pick_real(0.02, 0.3), s2 = pick_real(0.02, 0.3), smin = std::min(s1, s2);
  double rho = c.r * pick_real(0.3, 0.95);
  const double delta =
      pick_int(0, 1) ? std::ldexp(sc.size, -pick_int(20, 50)) : pick_real(0.001, 0.05) * smin * rho;
  if (kind == 4) rho = c.r + pick_real(1.5, 3) * delta / smin;
  const double gap = kind <= 1 || kind == 4 ? -delta : (kind == 2 ? delta : 0.0);
  const double a1 = pick_real(0.17, 0.87), a2 = pick_real(0.17, 0.87);
  const Vec3 h1 = -std::cos(a1) * rad + std::sin(a1) * tng, h2 = -std::cos(a2) * rad - std::sin(a2) * tng;
  const double l = rho * pick_real(1.3, 2.5) / std::cos(std::max(a1, a2));
  const Vec3 w = capc + rho * rad + gap * capn;
  Triangle t{w, w + l * (h1 + s1 * capn), w + l * (h2 + s2 * capn)};
  std::string tag = "capcross";
  if (pick_int(0, 4) == 0) tag = collapse(t, w, capn, false, false) + tag;
  if (kind == 4) tag += "-outside";
  else tag += tri_touch_or_gap(c, t, capn, gap);
  return {{c, restate(t)}, tag};
}

// A triangle in the plane n.(y - x) = -gap (x the cylinder's lowest point
// along n: the cylinder lies in n.(y - x) >= 0), holding x - gap n inside
// (four times in five; vertex distances 0.3..1 times len) or on its edge ab
// ("-edge"). Returns the tag suffix.
Triangle tri_under(Vec3 x, Vec3 n, double gap, double len, std::string& tag) {
  const Vec3 e1 = any_perpendicular(n), e2 = cross(n, e1), y = x - gap * n;
  if (pick_int(0, 4) != 0) return face_around(y, e1, e2, len);
  tag += "-edge";
  const double th = pick_real(0, kTwoPi);
  const Vec3 d = std::cos(th) * e1 + std::sin(th) * e2, w = cross(n, d);
  const double back = pick_real(0.1, 1), ahead = pick_real(0.1, 1), slant = pick_real(-1, 1), out = pick_real(0.3, 1);
  return {y - (len * back) * d, y + (len * ahead) * d, y + (len * out) * (w + slant * d)};
}

// The axis of a cylinder lying on a plane of normal n: along n ("flat",
// "stand"), tilted, or across n ("edgewise", "lie").
Vec3 axis_on(Vec3 n, int orient) {
  if (orient == 0) return pick_int(0, 1) ? n : -n;
  const Vec3 e1 = any_perpendicular(n), e2 = cross(n, e1);
  const double th = pick_int(0, 2) == 0 ? 0.0 : pick_real(0, kTwoPi);
  const Vec3 w = std::cos(th) * e1 + std::sin(th) * e2;
  return orient == 1 ? unit(n + pick_real(0.01, 2) * w) : w;
}

// A small cylinder resting on a huge triangle (10^2..10^4 times the
// cylinder's size): standing on a cap, lying on its side or tilted on its
// rim, touching (+- ulps), a tiny gap or penetration, or 0.001..0.1 of its
// size either way.
TriCase tri_huge(const Scene& sc) {
  const Vec3 n = pick_dir();
  const int orient = pick_int(0, 2);
  const double r = pick_real(0.05, 2) * sc.size, len = pick_real(0.05, 4) * sc.size;
  const Vec3 p = sc.offset + sc.size * Vec3{pick_real(-2, 2), pick_real(-2, 2), pick_real(-2, 2)};
  Cylinder c{p, p + len * axis_on(n, orient), r};
  if (pick_int(0, 1)) std::swap(c.p, c.q);
  const double size = std::max(r, len);
  double gap = 0;
  switch (pick_int(0, 4)) {
    case 0: gap = 0; break;
    case 1: gap = std::ldexp(size, -pick_int(20, 50)); break;
    case 2: gap = -std::ldexp(size, -pick_int(20, 50)); break;
    case 3: gap = pick_real(0.001, 0.1) * size; break;
    default: gap = -pick_real(0.001, 0.1) * size; break;
  }
  const char* names[3] = {"huge-stand", "huge-tilted", "huge-lie"};
  std::string tag = names[orient];
  Triangle t = tri_under(cylinder_lowest(c, n), n, gap, size * std::pow(10.0, pick_real(2, 4)), tag);
  tag += tri_touch_or_gap(c, t, -n, gap);
  return {{c, restate(t)}, tag};
}

// A thin disk-like cylinder (length 1e-6..1e-12 of r, at least 2^-44 of its
// coordinates) on a triangle: flat (axis along the triangle's normal),
// tilted, or edgewise (axis in the triangle's plane), the contact inside the
// triangle or on its edge, touching (+- ulps) or a tiny gap either way.
TriCase tri_thin(const Scene& sc) {
  const Vec3 n = pick_dir();
  const int orient = pick_int(0, 2);
  const double r = pick_real(0.05, 2) * sc.size;
  const Vec3 p = sc.offset + sc.size * Vec3{pick_real(-2, 2), pick_real(-2, 2), pick_real(-2, 2)};
  const double len = std::max(r * std::pow(10.0, -pick_real(6, 12)), std::ldexp(max_abs(p), -44));
  Cylinder c{p, p + len * axis_on(n, orient), r};
  if (pick_int(0, 1)) std::swap(c.p, c.q);
  const int gk = pick_int(0, 2);
  const double gap = gk == 0 ? 0.0 : (gk == 1 ? 1.0 : -1.0) * std::ldexp(sc.size, -pick_int(20, 50));
  const char* names[3] = {"thin-flat", "thin-tilted", "thin-edgewise"};
  std::string tag = names[orient];
  Triangle t = tri_under(cylinder_lowest(c, n), n, gap, pick_real(0.3, 3) * sc.size, tag);
  tag += tri_touch_or_gap(c, t, -n, gap);
  return {{c, restate(t)}, tag};
}

// Triangle-mesh data: a vertex, edge or face at a spot with scene size 1 at
// offsets 40..100, every coordinate and the radius rounded to float.
TriCase tri_f32() {
  Scene sc{1, {}};
  for (int i = 0; i < 3; ++i) {
    const double sign = pick_int(0, 1) ? 1 : -1;
    sc.offset[i] = sign * pick_real(40, 100);
  }
  const Frame f = pick_cylinder(sc);
  const Spot sp = pick_spot(f, pick_region());
  const double sign = pick_int(0, 1) ? 1 : -1, gap = sign * pick_real(0.001, 0.3);
  const int feature = pick_int(0, 2), level = pick_int(0, 2);
  const Triangle t = tri_feature_at(sp, sp.at + gap * sp.out, level, feature, sc.size);
  const Cylinder c{to_f32(f.c.p), to_f32(f.c.q), to_f32(f.c.r)};
  return {{c, restate(Triangle{to_f32(t.a), to_f32(t.b), to_f32(t.c)})}, "pattern-f32" + gap_tag(gap)};
}

// Exact integer constructions: the cylinder along +z from z0 to top = z0 + h,
// radius C = c k for a Pythagorean triple (a, b, c), the rim point
// R = (a k, b k, top), then exact moves. Triangles by tag:
//   exact-vertex-rim    vertex R, the others strictly beyond the plane across
//                       a rim direction (the triples, straight up, straight
//                       out);
//   exact-vertex-side   vertex (a k, b k, z), z0 <= z <= top, the others
//                       strictly outwards along the radius;
//   exact-vertex-cap    vertex at an integer point of the cap within the
//                       disc, the others above the cap plane;
//   exact-edge-side     an edge through (a k, b k, z) tangent to the side
//                       (along the circle's tangent, the axis or a mix);
//   exact-edge-rim      an edge through R along the rim's tangent (or, for
//                       a diagonal rim direction, any direction across it);
//   exact-inplane-rim   in the cap plane, a vertex or a tangent edge at R,
//                       the triangle outside the disc;
//   exact-face-cap      in the cap plane, a vertex within the disc;
//   exact-zero-radius   k = 0 (the cylinder is its segment): an edge across
//                       the axis at height z0..top, the triangle on one side.
// A quarter of the triangles are degenerate at the contact ("point-",
// "segment-", "collinear-" after "exact-"). Touches are nudged by k ulps
// towards overlap (k > 0: "-ulps-in") or away ("-ulps-out"): the radius for
// rim and side contacts, the top cap along the axis for cap contacts, the
// triangle across the axis for the zero radius ("-ulps-off": a degenerate
// triangle moved off the axis either way). A fifth of the non-zero-radius
// triangles are moved instead, exactly: out of the cylinder along the
// contact's normal ("-gap", at most half of r and h), or from the contact
// 2^-1..2^-25 of the way towards the cylinder's centre ("-deep").
TriCase exact_cylinder_triangle() {
  const auto& t1 = kTriples[pick_int(0, kNumTriples - 1)];
  const double a = t1[0], b = t1[1], cc = t1[2];
  const int k = pick_int(0, 12) == 0 ? 0 : pick_int(1, 4);
  const int h = pick_int(1, 20), z0 = pick_int(-10, 10), top = z0 + h;
  const double A = a * k, B = b * k, C = cc * k;
  const Exact ex = pick_exact();
  Cylinder cyl{ex.apply({0, 0, double(z0)}), ex.apply({0, 0, double(top)}), ex.len(C)};
  const Vec3 R{A, B, double(top)}, rad{a, b, 0}, tng{-b, a, 0}, up{0, 0, 1};
  auto n = [](int lo, int hi) { return double(pick_int(lo, hi)); };
  Vec3 va, vb, vc, x, out;  // the vertices; the contact x (vertex a or on edge ab); its normal
  int nudged = 0;           // 0: the radius, 1: the top cap, 2: the triangle along +x
  std::string what;
  switch (k == 0 ? 7 : pick_int(0, 6)) {
    case 0:
    case 4: {
      const auto& t2 = kRimDirs[pick_int(0, kNumRimDirs - 1)];
      out = {t2[0] * a, t2[0] * b, t2[1] * cc};
      const Vec3 bin{-t2[1] * a, -t2[1] * b, t2[0] * cc};  // across out and tng
      x = R;
      {
        const double w3 = n(-5, 5), w2 = n(-5, 5), w1 = n(1, 4);
        vc = R + w1 * out + w2 * tng + w3 * bin;
      }
      if (pick_int(0, 1) == 0) {  // vertex at R
        va = R;
        {
          const double w3 = n(-5, 5), w2 = n(-5, 5), w1 = n(1, 4);
          vb = R + w1 * out + w2 * tng + w3 * bin;
        }
        what = "vertex-rim";
      } else {  // an edge through R across out
        const bool diag = t2[0] > 0 && t2[1] > 0;
        Vec3 e = tng;
        if (diag && pick_int(0, 1)) {
          const double w2 = n(-3, 3), w1 = n(-3, 3);
          e = w1 * tng + w2 * bin;
        }
        if (e == Vec3{}) e = tng;
        va = R - n(0, 5) * e;
        vb = R + n(1, 5) * e;
        what = "edge-rim";
      }
      break;
    }
    case 1:
    case 3: {
      const Vec3 v{A, B, n(z0, top)};
      out = rad;
      x = v;
      {
        const double w3 = n(-5, 5), w2 = n(-5, 5), w1 = n(1, 4);
        vc = v + w1 * rad + w2 * tng + w3 * up;
      }
      if (pick_int(0, 1) == 0) {
        va = v;
        {
          const double w3 = n(-5, 5), w2 = n(-5, 5), w1 = n(1, 4);
          vb = v + w1 * rad + w2 * tng + w3 * up;
        }
        what = "vertex-side";
      } else {
        const double w2 = n(-3, 3), w1 = n(-3, 3);
        Vec3 e = w1 * tng + w2 * up;
        if (e == Vec3{}) e = tng;
        va = v - n(0, 5) * e;
        vb = v + n(1, 5) * e;
        what = "edge-side";
      }
      break;
    }
    case 2: {
      va = x = {n(-int(A), int(A)), n(-int(B), int(B)), double(top)};
      out = up;
      vb = va + Vec3{n(-5, 5), n(-5, 5), n(1, 5)};
      vc = va + Vec3{n(-5, 5), n(-5, 5), n(1, 5)};
      nudged = 1;
      what = "vertex-cap";
      break;
    }
    case 5: {
      x = R;
      out = rad;
      {
        const double w2 = n(-5, 5), w1 = n(1, 5);
        vc = R + w1 * rad + w2 * tng;
      }
      if (pick_int(0, 1)) {
        va = R;
        {
          const double w2 = n(-5, 5), w1 = n(1, 5);
          vb = R + w1 * rad + w2 * tng;
        }
      } else {
        va = R - n(0, 5) * tng;
        vb = R + n(1, 5) * tng;
      }
      what = "inplane-rim";
      break;
    }
    case 6: {
      const int m = int(C) + 10;
      va = x = {n(-int(A), int(A)), n(-int(B), int(B)), double(top)};
      out = up;
      vb = {n(-m, m), n(-m, m), double(top)};
      vc = {n(-m, m), n(-m, m), double(top)};
      nudged = 1;
      what = "face-cap";
      break;
    }
    default: {
      const double zc = n(z0, top);
      x = {0, 0, zc};
      out = {1, 0, 0};
      va = {0, -n(1, 5), zc};  // the axis strictly inside the edge
      vb = {0, n(1, 5), zc};
      vc = {n(1, 5), n(-5, 5), zc > z0 && zc < top ? zc + n(-5, 5) : zc};  // crossing the axis between the caps
      nudged = 2;
      what = "zero-radius";
      break;
    }
  }
  bool collapsed = false;
  if (pick_int(0, 3) == 0) {
    collapsed = true;
    switch (pick_int(0, 2)) {
      case 0: va = vb = vc = x; what = "point-" + what; break;
      case 1: vc = pick_int(0, 1) ? va : vb; what = "segment-" + what; break;
      default: vc = pick_int(0, 1) ? 0.5 * (va + vb) : va + 2.0 * (vb - va); what = "collinear-" + what; break;
    }
  }
  std::string tag = "exact-" + what;
  if (nudged != 2 && pick_int(0, 4) == 0) {
    // Out along the contact normal by 2^-s |out| (at most half of min(C, h)),
    // or into the cylinder towards its centre m by 2^-s |x - m|, s >= 1 (x
    // goes strictly inside: along the normal it could slide on the surface).
    Vec3 step;
    const bool into = pick_int(0, 1);
    if (into) {
      step = std::ldexp(1.0, -pick_int(2, 26)) * (2.0 * x - Vec3{0, 0, double(z0 + top)});
    } else {
      const double lo = std::ceil(std::log2(2 * length(out) / std::min(C, double(h))));
      step = -std::ldexp(1.0, -int(lo) - pick_int(0, 24)) * out;
    }
    for (Vec3* v : {&va, &vb, &vc}) *v = *v - step;
    tag += into ? "-deep" : "-gap";
    nudged = -1;
  }
  Triangle t{ex.apply(va), ex.apply(vb), ex.apply(vc)};
  const int ulps = pick_int(-2, 2);
  if (nudged == 0) {
    cyl.r = nudge(cyl.r, ulps);
    tag += ulps_tag(ulps);
  } else if (nudged == 1) {
    const int s = ex.slot(2);
    cyl.q[s] = nudge(cyl.q[s], ex.sign(2) > 0 ? ulps : -ulps);
    tag += ulps_tag(ulps);
  } else if (nudged == 2) {
    const int s = ex.slot(0);
    for (Vec3* v : {&t.a, &t.b, &t.c}) (*v)[s] = nudge((*v)[s], ex.sign(0) > 0 ? ulps : -ulps);
    tag += ulps == 0 ? "-touch" : (collapsed ? "-ulps-off" : ulps_tag(-ulps));
  }
  if (pick_int(0, 1)) std::swap(cyl.p, cyl.q);
  return {{cyl, restate(t)}, tag};
}

}  // namespace

template <>
rc::Gen<Tagged<QueryTraits<QueryId::collide_cylinder_triangle>::Case>> targeted<QueryId::collide_cylinder_triangle>() {
  return rc::gen::resize(100, rc::gen::exec([]() -> std::pair<CylinderTriangleCase, std::string> {
    const int mode = pick_int(0, 14);
    if (mode == 12 || mode == 13) return exact_cylinder_triangle();
    if (mode == 14) return tri_f32();
    const Scene sc = pick_scene();
    if (mode == 10) return tri_huge(sc);
    if (mode == 11) return tri_thin(sc);
    const Frame f = pick_cylinder(sc);
    switch (mode) {
      case 0: return tri_random(sc, f);
      case 1:
      case 2:
      case 3: return tri_feature(sc, f, mode - 1, false);
      case 4: return tri_feature(sc, f, pick_int(0, 1), true);
      case 5: return tri_cap_parallel(sc, f);
      case 6: return tri_axis_plane(sc, f);
      default: return tri_cap_cross(sc, f);  // 7, 8, 9
    }
  }));
}

template <>
rc::Gen<QueryTraits<QueryId::collide_cylinder_triangle>::Case> wild<QueryId::collide_cylinder_triangle>() {
  return rc::gen::resize(100, rc::gen::exec([]() -> CylinderTriangleCase {
    const Cylinder a{wild_vec(), wild_vec(), *wild_double()};
    Triangle b{wild_vec(), wild_vec(), wild_vec()};
    if (pick_int(0, 3) == 0) {  // repeated vertices: segment and point triangles
      b.c = pick_int(0, 1) ? b.a : b.b;
      if (pick_int(0, 1)) b.b = b.a;
    }
    return {a, b};
  }));
}



}  // namespace geomcheck::gen
