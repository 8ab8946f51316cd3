// geomcheck — certified convex engine: classification (verdict + signed
// distance), the double filter, and the rational certificates.
#include <atomic>
#include <cmath>
#include <limits>
#include <sstream>
#include <tuple>
#include <stdexcept>

#include "engine_interval.hpp"
#include "engine_search.hpp"

namespace geomcheck::oracle {

using namespace search;

namespace {

Iv iv(const Q& q) {
  Iv out;
  bracket(q, out.lo, out.hi);
  return out;
}
Q q_of(double v) { return to_q(v); }

/// The shape in intervals.
struct ShapeI {
  const ConvexShape* src;
  std::vector<IV3> pts;
  Iv radius;
  IV3 axis, inner;
  ConvexShape::Round round;
};
ShapeI to_iv(const ConvexShape& s) {
  ShapeI out;
  out.src = &s;
  out.radius = iv(s.radius);
  out.round = s.radius == 0 ? ConvexShape::Round::None : s.round;
  for (std::size_t i = 0; i < s.points.size(); ++i) out.pts.push_back(iv3(s.lo[i], s.hi[i]));
  IV3 sum = out.pts[0];
  for (std::size_t i = 1; i < out.pts.size(); ++i) sum = sum + out.pts[i];
  const Iv n = Iv::exact(static_cast<double>(out.pts.size()));
  out.inner = {iv_div(sum.x, n), iv_div(sum.y, n), iv_div(sum.z, n)};
  out.axis = s.round == ConvexShape::Round::Disc ? out.pts[1] - out.pts[0] : IV3{};
  return out;
}

/// The shape in doubles for the filter's search (nearest values; nothing
/// here needs to be exact).
ShapeT<double> to_search(const ConvexShape& s) {
  ShapeT<double> out;
  out.src = &s;
  V3<double> sum{};
  for (std::size_t i = 0; i < s.points.size(); ++i) {
    const V3<double> p{s.lo[i].x, s.lo[i].y, s.lo[i].z};
    out.pts.push_back(p);
    sum = sum + p;
  }
  out.inner = (1.0 / static_cast<double>(s.points.size())) * sum;
  out.radius = s.radius_hi;
  out.round = s.radius == 0 ? ConvexShape::Round::None : s.round;
  if (out.round == ConvexShape::Round::Disc) {
    V3<double> a{s.axis_d.x, s.axis_d.y, s.axis_d.z};
    const double m = std::max({std::abs(a.x), std::abs(a.y), std::abs(a.z)});
    a = (1 / m) * a;
    out.unit_axis = (1 / std::sqrt(dot(a, a))) * a;
  }
  return out;
}

/// Enclosure of h_s(n).
Iv support_iv(const ShapeI& s, const IV3& n) {
  Iv m = dot(n, s.pts[0]);
  for (std::size_t i = 1; i < s.pts.size(); ++i) m = iv_max(m, dot(n, s.pts[i]));
  if (s.round == ConvexShape::Round::Ball) return m + s.radius * iv_sqrt(dot(n, n));
  if (s.round == ConvexShape::Round::Disc) {
    const IV3 c = cross(n, s.axis);
    const Iv aa = dot(s.axis, s.axis);
    if (!aa.certainly_pos()) return {-INFINITY, INFINITY};
    return m + s.radius * iv_div(iv_sqrt(dot(c, c)), iv_sqrt(aa));
  }
  return m;
}

/// Enclosure of a support point built inside the shape: core point plus
/// radius times a radial vector of norm <= 1 (shrunk; for a disc projected
/// exactly onto the disc plane, which only shortens it). Returns false when
/// the norm bound cannot be shown.
bool sup_box(const ShapeI& s, const Sup<double>& sp, IV3& out) {
  if (sp.i < 0) { out = s.inner; return true; }
  if (sp.half) {
    Sup<double> full = sp;
    full.half = false;
    IV3 p;
    if (!sup_box(s, full, p)) return false;
    const Iv h = Iv::exact(0.5);
    out = h * (s.inner + p);
    return true;
  }
  out = s.pts[sp.i];
  if (s.round == ConvexShape::Round::None || (sp.w.x == 0 && sp.w.y == 0 && sp.w.z == 0)) return true;
  const double f = 1 - 0x1p-48;
  IV3 w = iv3(Vec3{sp.w.x * f, sp.w.y * f, sp.w.z * f});  // exact doubles
  if (!(dot(w, w).hi <= 1)) return false;
  if (s.round == ConvexShape::Round::Disc) {
    const Iv aa = dot(s.axis, s.axis);
    if (!aa.certainly_pos()) return false;
    w = w - iv_div(dot(w, s.axis), aa) * s.axis;
  }
  out = out + s.radius * w;
  return true;
}

/// The exact point that sup_box encloses.
QVec filter_point_q(const ConvexShape& s, const Sup<double>& sp) {
  if (sp.i < 0) return inner_point(s);
  if (sp.half) {
    Sup<double> full = sp;
    full.half = false;
    return Q(1, 2) * (inner_point(s) + filter_point_q(s, full));
  }
  QVec base = s.points[sp.i];
  if (s.radius == 0 || s.round == ConvexShape::Round::None || (sp.w.x == 0 && sp.w.y == 0 && sp.w.z == 0)) return base;
  const double f = 1 - 0x1p-48;
  QVec w = to_q(Vec3{sp.w.x * f, sp.w.y * f, sp.w.z * f});
  if (s.round == ConvexShape::Round::Disc) w = w - (dot(w, s.axis) / dot(s.axis, s.axis)) * s.axis;
  return base + s.radius * w;
}

Iv volume_iv(const IV3& p0, const IV3& p1, const IV3& p2, const IV3& p3) {
  return dot(p1 - p0, cross(p2 - p0, p3 - p0));
}

/// Origin certainly strictly inside the tetrahedron of boxes; `face_lo` gets
/// a lower bound on the distance from the origin to its boundary.
bool tet_iv(const std::array<IV3, 4>& w, double& face_lo) {
  const Iv v = volume_iv(w[0], w[1], w[2], w[3]);
  const int s = v.certainly_pos() ? 1 : (v.certainly_neg() ? -1 : 0);
  if (s == 0) return false;
  const IV3 o{Iv::exact(0), Iv::exact(0), Iv::exact(0)};
  face_lo = INFINITY;
  for (int i = 0; i < 4; ++i) {
    std::array<IV3, 4> t = w;
    t[i] = o;
    const Iv vi = volume_iv(t[0], t[1], t[2], t[3]);
    if (s > 0 ? !vi.certainly_pos() : !vi.certainly_neg()) return false;
    // Distance to the face opposite i: |6 vol_i| / |face normal|.
    const IV3& a = w[(i + 1) % 4];
    const IV3& b = w[(i + 2) % 4];
    const IV3& c = w[(i + 3) % 4];
    const IV3 n = cross(b - a, c - a);
    const Iv nn = iv_sqrt(dot(n, n));
    const Iv av = s > 0 ? vi : -vi;
    const double d = av.lo / nn.hi;
    face_lo = std::min(face_lo, d > 0 ? dn(d) : 0.0);
  }
  return true;
}

// ---- exact construction of certificate points -------------------------------

/// Lower bound of the distance from the origin to the plane of (a, b, c),
/// the origin on the side with positive orientation `vol`.
Q face_distance_lo(const QVec& a, const QVec& b, const QVec& c) {
  const QVec n = cross(b - a, c - a);
  const Q num = abs(dot(n, a));
  const Q nn = dot(n, n);
  if (nn == 0) return 0;
  return num / sqrt_interval(nn).hi;
}

struct Ctx {
  const ConvexShape& A;
  const ConvexShape& B;
  Q scale;
  bool trust;  // a swept hull: members built inside by construction
  bool early_out = true;  // stop GJK at the first separating plane
  bool certificates = true;
  std::ostringstream note;
  Q width = 0;  // the distance wanted to this width (0: the verdict suffices)
};

/// Exact separation: n with h_A(n) + h_B(-n) < 0. Fills the result.
bool certify_separation_q(Ctx& c, const QVec& n, DistanceResult& r, int bits) {
  if (is_zero(n)) return false;
  if (separation_sign(c.A, c.B, n) >= 0) return false;
  const QVec m{-n.x, -n.y, -n.z};
  const QInterval h = support_value(c.A, n) + support_value(c.B, m);
  Q lo = h.hi < 0 ? Q(-h.hi / sqrt_interval(dot(n, n)).hi) : Q(0);
  r.verdict = Verdict::Separated;
  r.separation = SeparationCertificate{n};
  if (!r.witness_a) {  // fallback upper bound: the inner points
    r.witness_a = inner_point(c.A);
    r.witness_b = inner_point(c.B);
  }
  const QVec d = *r.witness_a - *r.witness_b;
  r.distance = {lo, sqrt_interval(dot(d, d)).hi};
  r.bits = bits;
  return true;
}

template <class T>
void witnesses_q(const ConvexShape& A, const ConvexShape& B, const Simplex<T>& s, DistanceResult& r) {
  const std::size_t k = s.v.size();
  std::vector<Q> lam(k);
  Q sum = 0;
  for (std::size_t i = 0; i + 1 < k; ++i) {
    lam[i] = s.lambda[i] > 0 ? exact_q(s.lambda[i]) : Q(0);
    sum += lam[i];
  }
  if (sum > 1)
    for (std::size_t i = 0; i + 1 < k; ++i) lam[i] /= sum;
  lam[k - 1] = sum > 1 ? Q(0) : Q(1 - sum);
  QVec a{0, 0, 0}, b{0, 0, 0};
  for (std::size_t i = 0; i < k; ++i) {
    a = a + lam[i] * sup_point_q(A, s.v[i].a);
    b = b + lam[i] * sup_point_q(B, s.v[i].b);
  }
  r.witness_a = a;
  r.witness_b = b;
}

/// Exact overlap: the tetrahedron of four Minkowski vertices holds the origin.
template <class T>
bool certify_overlap_q(Ctx& c, const std::array<Vert<T>, 4>& tet, DistanceResult& r, int bits) {
  OverlapCertificate cert;
  for (int i = 0; i < 4; ++i) {
    cert.a[i] = sup_point_q(c.A, tet[i].a);
    cert.b[i] = sup_point_q(c.B, tet[i].b);
  }
  if (!check_overlap_impl(c.A, c.B, cert, c.trust)) return false;
  std::array<QVec, 4> w;
  for (int i = 0; i < 4; ++i) w[i] = cert.a[i] - cert.b[i];
  // Barycentric weights of the origin and the common point.
  const Q vol = signed_volume(w[0], w[1], w[2], w[3]);
  QVec x{0, 0, 0};
  Q pd_lo;
  bool first = true;
  for (int i = 0; i < 4; ++i) {
    std::array<QVec, 4> t = w;
    t[i] = QVec{0, 0, 0};
    x = x + (signed_volume(t[0], t[1], t[2], t[3]) / vol) * cert.a[i];
    const Q d = face_distance_lo(w[(i + 1) % 4], w[(i + 2) % 4], w[(i + 3) % 4]);
    if (first || d < pd_lo) pd_lo = d;
    first = false;
  }
  // Upper bound of the depth: the support of A - B along a face normal.
  QInterval best;
  bool have = false;
  for (int i = 0; i < 4; ++i) {
    const QVec& a = w[(i + 1) % 4];
    QVec n = cross(w[(i + 2) % 4] - a, w[(i + 3) % 4] - a);
    if (dot(n, a) < 0) n = Q(-1) * n;
    const Q nn = dot(n, n);
    if (nn == 0) continue;
    const QInterval h = (support_value(c.A, n) + support_value(c.B, Q(-1) * n)) / sqrt_interval(nn);
    if (!have || h.hi < best.hi) best = h;
    have = true;
  }
  r.verdict = Verdict::Overlapping;
  r.overlap = cert;
  r.common_point = x;
  r.distance = {have ? Q(-best.hi) : Q(-2 * c.scale * 4), Q(-pd_lo)};
  r.bits = bits;
  return true;
}

// ---- touching ------------------------------------------------------------------

std::vector<QVec> feature_directions(const ConvexShape& s) {
  using K = ConvexShape::Kind;
  std::vector<QVec> d;
  const auto& P = s.points;
  switch (s.kind) {
    case K::Segment: case K::Capsule: case K::Cylinder:
      d.push_back(P[1] - P[0]);
      break;
    case K::Triangle:
      d.push_back(P[1] - P[0]);
      d.push_back(P[2] - P[1]);
      d.push_back(P[0] - P[2]);
      d.push_back(cross(P[1] - P[0], P[2] - P[0]));
      break;
    case K::Box:
      for (int i = 0; i < 3; ++i) d.push_back(s.spans[i]);
      for (int i = 0; i < 3; ++i) d.push_back(cross(s.spans[i], s.spans[(i + 1) % 3]));
      break;
    default: break;
  }
  return d;
}

QVec snap_double(const QVec& v) { return {q_of(to_double(v.x)), q_of(to_double(v.y)), q_of(to_double(v.z))}; }

/// Coordinates rounded to the nearest multiple of 2^e.
Q snap_grid(const Q& x, long e) {
  Q step = e >= 0 ? Q(mp::mpz_int(1) << e) : Q(1) / Q(mp::mpz_int(1) << -e);
  const Q y = x / step + Q(1, 2);
  mp::mpz_int f = mp::numerator(y) / mp::denominator(y);  // truncates towards zero
  if (y < 0 && Q(f) != y) f -= 1;                          // floor
  return Q(f) * step;
}
QVec snap_grid(const QVec& v, long e) { return {snap_grid(v.x, e), snap_grid(v.y, e), snap_grid(v.z, e)}; }

// The directions tried for a touching certificate (and for an undecided
// pair's lower bound): the searched ones, the shapes' feature directions and
// their cross products, the coordinate axes and the features crossed with
// them, the line of centres and its parts across each feature, and the
// searched directions snapped to doubles and to floats.
std::vector<QVec> touching_directions(const Ctx& c, const std::vector<QVec>& dirs_in) {
  std::vector<QVec> dirs = dirs_in;
  const auto fa = feature_directions(c.A), fb = feature_directions(c.B);
  dirs.insert(dirs.end(), fa.begin(), fa.end());
  dirs.insert(dirs.end(), fb.begin(), fb.end());
  for (const QVec& a : fa)
    for (const QVec& b : fb) dirs.push_back(cross(a, b));
  // The coordinate axes, and each feature direction crossed with them (a
  // plane through a segment: A - B is a segment or a point when both shapes
  // lie on one line).
  const QVec axes[3] = {QVec{1, 0, 0}, QVec{0, 1, 0}, QVec{0, 0, 1}};
  for (const QVec& e : axes) dirs.push_back(e);
  for (const auto* f : {&fa, &fb})
    for (const QVec& a : *f)
      for (const QVec& e : axes) dirs.push_back(cross(a, e));
  // The line of centres, and its parts perpendicular to each feature direction.
  const QVec d = inner_point(c.B) - inner_point(c.A);
  dirs.push_back(d);
  for (const auto* f : {&fa, &fb})
    for (const QVec& a : *f)
      if (!is_zero(a)) dirs.push_back(d - (dot(d, a) / dot(a, a)) * a);
  // A core point of one shape lying exactly on the other's rounded surface
  // (a box corner on a cylinder's rim or side, a triangle's vertex on a
  // capsule): the normals there are rational. On a side, the radial
  // direction; on a ball, the offset from the core; on a rim, the cone of
  // the axis and the radial direction, whose rays across the other shape's
  // feature directions e are (a x rho) x e.
  for (const auto& [s, o, fo] : {std::make_tuple(&c.A, &c.B, &fb), std::make_tuple(&c.B, &c.A, &fa)}) {
    if (s->round == ConvexShape::Round::None || s->radius == 0 || s->points.size() > 2 ||
        s->kind == ConvexShape::Kind::Hull || o->kind == ConvexShape::Kind::Hull)
      continue;
    const QVec& p = s->points.front();
    const QVec a = s->points.back() - p;
    const Q aa = dot(a, a);
    const Q rr = s->radius * s->radius;
    for (const QVec& x : o->points) {
      Q t = aa > 0 ? dot(x - p, a) / aa : Q(0);
      if (s->round == ConvexShape::Round::Ball) t = t < 0 ? Q(0) : (t > 1 ? Q(1) : t);
      else if (t < 0 || t > 1) continue;
      const QVec rho = x - (p + t * a);
      if (dot(rho, rho) != rr) continue;
      dirs.push_back(rho);
      if (s->round == ConvexShape::Round::Disc && (t == 0 || t == 1)) {
        dirs.push_back(t == 0 ? Q(-1) * a : a);
        const QVec plane = cross(a, rho);
        for (const QVec& e : *fo) dirs.push_back(cross(plane, e));
      }
    }
  }
  // Searched directions snapped to doubles and to floats.
  for (const QVec& n : dirs_in) {
    const double m = std::max({std::abs(to_double(n.x)), std::abs(to_double(n.y)), std::abs(to_double(n.z))});
    if (!(m > 0) || !std::isfinite(m)) continue;
    const Vec3 u{to_double(n.x) / m, to_double(n.y) / m, to_double(n.z) / m};
    dirs.push_back(to_q(u));
    dirs.push_back(to_q(Vec3{static_cast<float>(u.x), static_cast<float>(u.y), static_cast<float>(u.z)}));
  }
  return dirs;
}

/// Touching: a common point and n with h_A(n) + h_B(-n) <= 0, both exact.
bool try_touching(Ctx& c, const std::vector<QVec>& dirs_in, const std::vector<QVec>& points_in, DistanceResult& r) {
  const std::vector<QVec> dirs = touching_directions(c, dirs_in);
  std::optional<QVec> n_ok;
  for (const QVec& n : dirs) {
    if (is_zero(n)) continue;
    for (const Q& sgnq : {Q(1), Q(-1)}) {
      const QVec m = sgnq * n;
      if (separation_sign(c.A, c.B, m) <= 0) { n_ok = m; break; }
    }
    if (n_ok) break;
  }
  if (!n_ok) return false;
  std::vector<QVec> pts = points_in;
  // Where the shapes touch at a rim or on a ball, the common point is a core
  // point plus radius times the unit radial direction of n: exact when that
  // direction's squared length is the square of a short rational (n across
  // a disc's axis, or along a coordinate axis). The searches only approach
  // such a point along a line of near-contact (two nearly parallel sides),
  // where their witnesses drift.
  for (const ConvexShape* s : {&c.A, &c.B}) {
    if (s->round == ConvexShape::Round::None || s->radius == 0 || s->kind == ConvexShape::Kind::Hull) continue;
    QVec w = *n_ok;
    if (s->round == ConvexShape::Round::Disc) w = w - (dot(w, s->axis) / dot(s->axis, s->axis)) * s->axis;
    const Q ww = dot(w, w);
    if (ww == 0) continue;
    const QInterval root = sqrt_interval(ww);
    if (!root.exact()) continue;
    const QVec u = (s->radius / root.lo) * w;
    for (const QVec& p : s->points) {
      pts.push_back(p + u);
      pts.push_back(p - u);
    }
  }
  for (const QVec& p : points_in) pts.push_back(snap_double(p));
  // Rounded to grids of 2^-k * scale: exact constructions have short
  // coordinates, the searched witnesses only approach them.
  const long e = static_cast<long>(std::floor(std::log2(to_double(c.scale))));
  for (const QVec& p : points_in)
    for (int k : {8, 16, 24, 32, 40, 48, 52}) pts.push_back(snap_grid(p, e - k));
  if (c.A.kind != ConvexShape::Kind::Hull)
    for (const QVec& p : c.B.points) pts.push_back(p);
  for (const QVec& p : c.A.points) pts.push_back(p);
  for (const QVec& p : pts) {
    bool in = false;
    try {
      in = (c.trust || contains(c.A, p)) && contains(c.B, p);
    } catch (const std::exception&) {
      in = false;
    }
    if (in) {
      r.verdict = Verdict::Touching;
      r.separation = SeparationCertificate{*n_ok};
      r.common_point = p;
      r.distance = point(Q(0));
      return true;
    }
  }
  return false;
}

// ---- one round of search + certificate at precision T -------------------------

enum class Round { Decided, Tiny, Open };

// Undecided with the loosest certified enclosure: the inner points bound
// the distance from above, the support of A - B along any direction bounds
// the depth.
DistanceResult loose_enclosure(const Ctx& c) {
  DistanceResult r;
  r.verdict = Verdict::Undecided;
  const QVec d = inner_point(c.A) - inner_point(c.B);
  const QVec n{1, 0, 0}, m{-1, 0, 0};
  const QInterval h = support_value(c.A, n) + support_value(c.B, m);
  r.distance = {Q(-h.hi), sqrt_interval(dot(d, d)).hi};
  return r;
}

// An undecided pair's enclosure from what the searches found: any a in A
// and b in B bound the signed distance from above by |a - b|, and any
// direction n from below by -(h_A(n) + h_B(-n)) / |n| (the signed distance
// is the largest such value). Where no certificate exists (a contact at an
// irrational point, a flat Minkowski difference), the search's directions
// and witnesses still enclose the distance about as narrowly as the search
// came near it. A witness the rounding left just outside its shape is
// pulled towards the shape's inner point by 2^-260, 2^-230, then 2^-210
// of the way, until it is inside (checked exactly).
void narrow_undecided(const Ctx& c, const std::vector<QVec>& dirs_in, const std::vector<QVec>& pts, DistanceResult& r) {
  for (const QVec& n : touching_directions(c, dirs_in)) {
    if (is_zero(n)) continue;
    const QInterval h = (support_value(c.A, n) + support_value(c.B, Q(-1) * n)) / sqrt_interval(dot(n, n));
    if (Q(-h.hi) > r.distance.lo) r.distance.lo = -h.hi;
  }
  const QVec ia = inner_point(c.A), ib = inner_point(c.B);
  for (std::size_t i = 0; i + 1 < pts.size(); i += 2) {  // (witness in A, witness in B) per round
    for (const int k : {0, 260, 230, 210}) {
      QVec a = pts[i], b = pts[i + 1];
      if (k > 0) {
        const Q t = Q(1) / Q(mp::mpz_int(1) << k);
        a = a + t * (ia - a);
        b = b + t * (ib - b);
      }
      bool in = false;
      try {
        in = (c.trust || contains(c.A, a)) && contains(c.B, b);
      } catch (const std::exception&) {
        in = false;
      }
      if (!in) continue;
      const QVec d = a - b;
      const Q up = sqrt_interval(dot(d, d)).hi;
      if (up < r.distance.hi) r.distance.hi = up;
      break;
    }
  }
}

template <class T>
Round search_round_impl(Ctx& c, DistanceResult& r, std::vector<QVec>& dirs, std::vector<QVec>& pts, Q& dist_est) {
  const int bits = bits_of<T>();
  const ShapeT<T> A = convert<T>(c.A), B = convert<T>(c.B);
  const T sc = from_q<T>(c.scale);
  const T contact = ldexp(sc, -(bits - 8));
  // A quarter of the wanted width: the certificates' bounds, recomputed
  // exactly from the search's direction and witnesses, stay within it.
  const T width = c.width > 0 ? T(from_q<T>(c.width) / 4) : T(0);
  const GjkOut<T> g = gjk(A, B, contact * contact, 64 + 2 * bits, c.early_out, bits - 6, width);
  const Simplex<T>& s = g.simplex;
  c.note << " gjk" << bits << ":" << g.iterations;
  if (g.status == GjkStatus::Inside) {
    std::array<Vert<T>, 4> tet{s.v[0], s.v[1], s.v[2], s.v[3]};
    if (certify_overlap_q(c, tet, r, bits)) return Round::Decided;
  }
  if (!s.v.empty()) {
    witnesses_q(c.A, c.B, s, r);
    pts.push_back(*r.witness_a);
    pts.push_back(*r.witness_b);
  }
  if (g.status == GjkStatus::Separated || g.status == GjkStatus::MaxIter) {
    const QVec n = exact_q(-s.closest);
    dirs.push_back(n);
    if (certify_separation_q(c, n, r, bits)) return Round::Decided;
  }
  r.witness_a.reset();
  r.witness_b.reset();
  {
    using std::sqrt;
    dist_est = exact_q(T(sqrt(dot(s.closest, s.closest))));
  }
  // Near contact or undecided: the portal method.
  const MprOut<T> m = mpr(A, B, 64 + 2 * bits);
  if (m.status == MprStatus::Hit && certify_overlap_q(c, m.tet, r, bits)) return Round::Decided;
  if (m.status == MprStatus::Miss) {
    const QVec n = exact_q(m.dir);
    dirs.push_back(n);
    if (certify_separation_q(c, n, r, bits)) return Round::Decided;
  }
  {
    std::vector<Vert<T>> cand(s.v.begin(), s.v.end());
    if (m.status == MprStatus::Hit) cand.insert(cand.end(), m.tet.begin(), m.tet.end());
    std::array<Vert<T>, 4> tet;
    if (enclosing_tet(A, B, cand, tet) && certify_overlap_q(c, tet, r, bits)) return Round::Decided;
  }
  const Q tiny = c.scale / Q(mp::mpz_int(1) << 200);
  return dist_est < tiny ? Round::Tiny : Round::Open;
}

/// One round; a search that proposes a non-finite value (a direction or a
/// weight gone astray on a degenerate pair: an axis of 1e10 with a radius of
/// 1e-314) leaves the round open instead of ending the classification.
template <class T>
Round search_round(Ctx& c, DistanceResult& r, std::vector<QVec>& dirs, std::vector<QVec>& pts, Q& dist_est) {
  try {
    return search_round_impl<T>(c, r, dirs, pts, dist_est);
  } catch (const std::invalid_argument&) {
    c.note << " (" << bits_of<T>() << " bits: a non-finite proposal)";
    r.witness_a.reset();
    r.witness_b.reset();
    return Round::Open;
  }
}

/// The double filter: GJK in doubles, certificates in interval arithmetic.
bool filter_round(Ctx& c, DistanceResult& r) {
  for (const ConvexShape* s : {&c.A, &c.B})
    for (std::size_t i = 0; i < s->points.size(); ++i)
      if (!(std::isfinite(s->lo[i].x) && std::isfinite(s->hi[i].x) && std::isfinite(s->lo[i].y) &&
            std::isfinite(s->hi[i].y) && std::isfinite(s->lo[i].z) && std::isfinite(s->hi[i].z)))
        return false;
  const ShapeT<double> A = to_search(c.A), B = to_search(c.B);
  const ShapeI AI = to_iv(c.A), BI = to_iv(c.B);
  double sc = 0;
  for (const ConvexShape* s : {&c.A, &c.B}) {
    for (std::size_t i = 0; i < s->points.size(); ++i)
      sc = std::max({sc, std::abs(s->lo[i].x), std::abs(s->lo[i].y), std::abs(s->lo[i].z), std::abs(s->hi[i].x),
                     std::abs(s->hi[i].y), std::abs(s->hi[i].z)});
    sc = std::max(sc, s->radius_hi);
  }
  if (!(sc < 1e150 && sc > 1e-150)) return false;  // squares stay normal
  const double contact = sc * 0x1p-45;
  const GjkOut<double> g = gjk(A, B, contact * contact, 96, c.early_out);
  const Simplex<double>& s = g.simplex;
  auto tet_cert = [&](const std::array<Vert<double>, 4>& tet) {
    std::array<IV3, 4> w;
    std::array<IV3, 4> pa, pb;
    for (int i = 0; i < 4; ++i) {
      if (!sup_box(AI, tet[i].a, pa[i]) || !sup_box(BI, tet[i].b, pb[i])) return false;
      w[i] = pa[i] - pb[i];
    }
    double face_lo = 0;
    if (!tet_iv(w, face_lo)) return false;
    // Depth upper bound: support of A - B along the GJK/MPR face normals.
    double hi = INFINITY;
    for (int i = 0; i < 4; ++i) {
      const IV3& a = w[(i + 1) % 4];
      IV3 n = cross(w[(i + 2) % 4] - a, w[(i + 3) % 4] - a);
      const Vec3 nd{(n.x.lo + n.x.hi) / 2, (n.y.lo + n.y.hi) / 2, (n.z.lo + n.z.hi) / 2};
      const IV3 ne = iv3(nd), me = iv3(Vec3{-nd.x, -nd.y, -nd.z});
      const Iv h = support_iv(AI, ne) + support_iv(BI, me);
      const Iv nn = iv_sqrt(dot(ne, ne));
      if (!nn.certainly_pos() || !(h.lo > 0)) continue;
      hi = std::min(hi, up(h.hi / nn.lo));
    }
    if (!std::isfinite(hi)) hi = up(up(8 * sc));
    // The rational points the interval proof was about.
    if (c.certificates) {
      OverlapCertificate cert;
      for (int i = 0; i < 4; ++i) {
        cert.a[i] = filter_point_q(c.A, tet[i].a);
        cert.b[i] = filter_point_q(c.B, tet[i].b);
      }
      r.overlap = cert;
    }
    r.verdict = Verdict::Overlapping;
    r.distance = {q_of(-hi), q_of(-face_lo)};
    r.bits = 53;
    r.by_filter = true;
    return true;
  };
  // Separated: h_A(n) + h_B(-n) certainly negative; wa, wb enclose points
  // of A and B (the upper bound of the distance).
  auto sep_cert = [&](const Vec3& nd, const IV3& wa, const IV3& wb) {
    const IV3 n = iv3(nd), m = iv3(-nd);
    const Iv h = support_iv(AI, n) + support_iv(BI, m);
    const Iv nn = iv_sqrt(dot(n, n));
    const IV3 d = wa - wb;
    const Iv hi = iv_sqrt(dot(d, d));
    if (!h.certainly_neg() || !nn.certainly_pos() || !std::isfinite(hi.hi)) return false;
    r.verdict = Verdict::Separated;
    r.separation = SeparationCertificate{to_q(nd)};
    r.distance = {q_of(std::max(0.0, dn(-h.hi / nn.hi))), q_of(hi.hi)};
    r.bits = 53;
    r.by_filter = true;
    return true;
  };
  if (g.status == GjkStatus::Inside) {
    if (tet_cert({s.v[0], s.v[1], s.v[2], s.v[3]})) return true;
  }
  if (g.status != GjkStatus::Separated) {
    // Origin on a face of the simplex (e.g. a mirror-symmetric pair keeps
    // GJK in a plane): the portal method leaves the plane.
    const MprOut<double> m = mpr(A, B, 96);
    if (m.status == MprStatus::Hit && tet_cert(m.tet)) return true;
    std::vector<Vert<double>> cand(s.v.begin(), s.v.end());
    if (m.status == MprStatus::Hit) cand.insert(cand.end(), m.tet.begin(), m.tet.end());
    std::array<Vert<double>, 4> tet;
    if (enclosing_tet(A, B, cand, tet) && tet_cert(tet)) return true;
    if (m.status == MprStatus::Miss && sep_cert(Vec3{m.dir.x, m.dir.y, m.dir.z}, AI.inner, BI.inner)) return true;
  }
  if (g.status == GjkStatus::Separated || g.status == GjkStatus::MaxIter) {
    // Witness points: convex combinations of points built inside (GJK's
    // early exit may come before any point: then the inner points).
    IV3 wa = AI.inner, wb = BI.inner;
    bool ok = true;
    Iv rest = Iv::exact(1);
    for (std::size_t i = 0; i < s.v.size() && ok; ++i) {
      IV3 a, b;
      ok = sup_box(AI, s.v[i].a, a) && sup_box(BI, s.v[i].b, b);
      Iv l = Iv::exact(s.lambda[i] > 0 ? s.lambda[i] : 0);
      if (i + 1 == s.v.size()) l = rest;
      else rest = rest - l;
      if (!(l.lo >= 0)) ok = false;
      wa = i == 0 ? l * a : wa + l * a;
      wb = i == 0 ? l * b : wb + l * b;
    }
    if (ok && sep_cert(Vec3{-s.closest.x, -s.closest.y, -s.closest.z}, wa, wb)) return true;
  }
  return false;
}

}  // namespace

namespace {

thread_local Stage tl_deepest = Stage::None;
std::atomic<bool> g_double_double{true};
void reached(Stage s) {
  if (static_cast<int>(s) > static_cast<int>(tl_deepest)) tl_deepest = s;
}

}  // namespace

const char* to_string(Stage s) {
  switch (s) {
    case Stage::None: return "closed form";
    case Stage::Filter: return "interval filter";
    case Stage::Double: return "doubles";
    case Stage::DoubleDouble: return "double-double";
    case Stage::Soft128: return "128 digits";
    case Stage::Soft384: return "384 digits";
    case Stage::Soft512: return "512 digits";
    case Stage::Touching: return "touching";
    case Stage::Undecided: return "undecided";
  }
  return "?";
}
void reset_deepest_stage() { tl_deepest = Stage::None; }
bool double_double_default() { return g_double_double.load(std::memory_order_relaxed); }
void set_double_double_default(bool on) { g_double_double = on; }
Stage deepest_stage() { return tl_deepest; }
void note_stage(Stage s) { reached(s); }

namespace {

DistanceResult decide(const ConvexShape& a, const ConvexShape& b, const EngineOptions& opt, bool early_out) {
  Ctx c{a, b, Q(0), a.kind == ConvexShape::Kind::Hull || b.kind == ConvexShape::Kind::Hull, early_out,
        opt.certificates, {}};
  DistanceResult r;
  if (opt.filter && filter_round(c, r)) {
    r.note = "filter";
    reached(Stage::Filter);
    return r;
  }
  c.scale = pair_scale(a, b);
  if (opt.rel_width > 0) c.width = c.scale * to_q(opt.rel_width);
  if (c.scale == 0) {  // two points at the origin
    r.verdict = Verdict::Touching;
    r.common_point = QVec{0, 0, 0};
    r.separation = SeparationCertificate{QVec{1, 0, 0}};
    r.distance = point(Q(0));
    return r;
  }
  std::vector<QVec> dirs, pts;
  Q est;
  Round rd = Round::Open;
  try {
    Stage stage = Stage::Double;
    // The round in doubles only where double-double does not run: after the
    // filter it decided under 1% of the cases, at the cost of rational
    // certificates that double-double's round builds again (ENGINE.md).
    const bool dd_round = opt.double_double && dd::in_range(to_double(c.scale));
    if (opt.exact_small && !dd_round) rd = search_round<double>(c, r, dirs, pts, est);
    // Double-double decides the verdict; where a width is wanted it must
    // also reach it, else the software floats search again (and its answer
    // stays the fallback).
    std::optional<DistanceResult> dd_answer;
    if (rd != Round::Decided && dd_round) {
      stage = Stage::DoubleDouble;
      rd = search_round<DD>(c, r, dirs, pts, est);
      // (An overlap's width is classify's to refine, by penetration().)
      if (rd == Round::Decided && c.width > 0 && r.verdict == Verdict::Separated &&
          r.distance.hi - r.distance.lo > c.width) {
        dd_answer = r;
        r = DistanceResult{};
        rd = Round::Open;
      }
      // Near touching: exact touching is tried before the software floats
      // (which cannot decide a distance of exactly 0). From 2^-60 * scale:
      // at a curved contact double-double's search stalls above 2^-90 *
      // scale, its witnesses still snap to the exact point, and a failed
      // try costs far less than the rounds in 128 and 384 digits
      // (bench_checks' time per stage: the touching cases of the capsule
      // 61 -> 160 cases/s, of cylinder/cylinder 42 -> 75, in one run).
      if (rd != Round::Decided && !dd_answer && est < c.scale / Q(mp::mpz_int(1) << 60) &&
          try_touching(c, dirs, pts, r)) {
        rd = Round::Decided;
        stage = Stage::Touching;
      }
    }
    if (rd != Round::Decided) stage = Stage::Soft128, rd = search_round<HP128>(c, r, dirs, pts, est);
    // Within 2^-70 scale of touching: exact touching before 384 digits.
    if (rd != Round::Decided && est < c.scale / Q(mp::mpz_int(1) << 70) && try_touching(c, dirs, pts, r)) {
      rd = Round::Decided;
      stage = Stage::Touching;
    }
    if (rd != Round::Decided) stage = Stage::Soft384, rd = search_round<HP384>(c, r, dirs, pts, est);
    if (rd != Round::Decided) stage = Stage::Touching;
    if (rd != Round::Decided && try_touching(c, dirs, pts, r)) rd = Round::Decided;
    // Still undecided, and the searches so far enclose the distance no
    // narrower than 2^-200 * scale (384 digits stall near 2^-192 * scale at
    // a curved contact): 512 digits to 2^-204 * scale, then touching again.
    if (rd != Round::Decided && !dd_answer && opt.narrow_undecided) {
      DistanceResult probe = loose_enclosure(c);
      narrow_undecided(c, dirs, pts, probe);
      if (probe.distance.hi - probe.distance.lo > c.scale / Q(mp::mpz_int(1) << 200)) {
        // The searches stop at a wanted width: here 2^-204 * scale, so that
        // the enclosure they leave is within 2^-200 * scale.
        c.width = c.scale / Q(mp::mpz_int(1) << 204);
        stage = Stage::Soft512, rd = search_round<HP512>(c, r, dirs, pts, est);
        if (rd != Round::Decided && try_touching(c, dirs, pts, r)) rd = Round::Decided, stage = Stage::Touching;
      }
    }
    if (rd == Round::Decided && dd_answer && dd_answer->verdict == r.verdict &&
        dd_answer->distance.hi - dd_answer->distance.lo < r.distance.hi - r.distance.lo)
      r = *dd_answer;
    if (rd != Round::Decided && dd_answer) {
      r = *dd_answer;
      rd = Round::Decided;
      stage = Stage::DoubleDouble;
    }
    if (rd == Round::Decided) reached(stage);
  } catch (const std::domain_error& e) {
    c.note << " unsupported: " << e.what();
  }
  if (rd != Round::Decided) {
    // Certified: the loose enclosure, narrowed by what the searches found.
    r = loose_enclosure(c);
    reached(Stage::Undecided);
    if (opt.narrow_undecided) narrow_undecided(c, dirs, pts, r);
    c.note << (rd == Round::Tiny ? " |distance| < 2^-200 scale" : " search did not converge")
           << " (estimate " << to_double(est) << ")";
  }
  r.note = c.note.str();
  return r;
}

}  // namespace

DistanceResult classify(const ConvexShape& a, const ConvexShape& b, const EngineOptions& opt) {
  DistanceResult r = decide(a, b, opt, opt.rel_width == 0);
  if (opt.rel_width == 0 || r.verdict == Verdict::Touching || r.verdict == Verdict::Undecided) return r;
  const Q target = pair_scale(a, b) * to_q(opt.rel_width);
  if (r.distance.hi - r.distance.lo <= target) return r;
  if (r.verdict == Verdict::Overlapping) {
    if (opt.refine_overlap_within && Q(-r.distance.hi) > *opt.refine_overlap_within) return r;
    const PenetrationResult p = penetration(a, b, opt.rel_width, opt.double_double);
    if (p.overlapping && p.depth.hi - p.depth.lo < r.distance.hi - r.distance.lo) {
      r.distance = {Q(-p.depth.hi), Q(-p.depth.lo)};
      r.note += " depth: " + p.note;
    }
    return r;
  }
  // Separated: GJK to convergence without the filter, in 128 then 384 digits.
  EngineOptions o = opt;
  o.filter = false;
  o.exact_small = false;
  const DistanceResult t = decide(a, b, o, false);
  if (t.verdict == Verdict::Separated && t.distance.hi - t.distance.lo < r.distance.hi - r.distance.lo) {
    DistanceResult out = t;
    out.note = r.note + " refined:" + t.note;
    return out;
  }
  return r;
}

}  // namespace geomcheck::oracle
