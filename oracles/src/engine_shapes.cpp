// geomcheck — certified convex engine: shapes and their exact primitives.
//
// Everything here is exact rational arithmetic: containment of a rational
// point, the sign of h(n) - d, the sign of h_A(n) + h_B(-n). Square roots
// are never taken; a term r*sqrt(u) is compared by squaring with its sign
// handled first (sign_sqrt below).
#include <gmp.h>

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <stdexcept>

#include "engine_interval.hpp"
#include "engine_internal.hpp"

namespace geomcheck::oracle {

namespace {

int sgn(const Q& x) { return x > 0 ? 1 : (x < 0 ? -1 : 0); }

/// Exact sign of c + e*sqrt(w) with e >= 0, w >= 0.
int sign_sqrt1(const Q& c, const Q& e, const Q& w) {
  if (e == 0 || w == 0) return sgn(c);
  if (c >= 0) return 1;
  return sgn(e * e * w - c * c);
}

QVec box_vertex(const QVec& c, const std::array<QVec, 3>& s, int i) {
  QVec v = c;
  for (int k = 0; k < 3; ++k) v = (i >> k & 1) ? v + s[k] : v - s[k];
  return v;
}

bool on_segment(const QVec& a, const QVec& b, const QVec& x) {
  const QVec d = b - a, y = x - a;
  if (!is_zero(cross(y, d))) return false;
  const Q t = dot(y, d);
  return t >= 0 && t <= dot(d, d);
}

Q segment_dist2_times(const QVec& p, const QVec& q, const QVec& x, Q& denom) {
  // Squared distance from x to segment pq, as num/denom with denom > 0.
  const QVec d = q - p, y = x - p;
  const Q dd = dot(d, d);
  if (dd == 0) { denom = 1; return dot(y, y); }
  const Q t = dot(y, d);
  if (t <= 0) { denom = 1; return dot(y, y); }
  if (t >= dd) { const QVec z = x - q; denom = 1; return dot(z, z); }
  denom = dd;
  return dot(y, y) * dd - t * t;
}

bool in_triangle(const QVec& a, const QVec& b, const QVec& c, const QVec& x) {
  const QVec n = cross(b - a, c - a);
  if (is_zero(n)) {
    // Collinear (or coincident) vertices: the longest of the three segments.
    const Q ab = dot(b - a, b - a), bc = dot(c - b, c - b), ca = dot(a - c, a - c);
    if (ab >= bc && ab >= ca) return on_segment(a, b, x);
    if (bc >= ca) return on_segment(b, c, x);
    return on_segment(c, a, x);
  }
  if (dot(n, x - a) != 0) return false;
  return dot(cross(b - a, x - a), n) >= 0 && dot(cross(c - b, x - b), n) >= 0 &&
         dot(cross(a - c, x - c), n) >= 0;
}

bool in_box(const QVec& c, const std::array<QVec, 3>& s, const QVec& x) {
  const QVec y = x - c;
  const Q det = dot(s[0], cross(s[1], s[2]));
  if (det != 0) {
    const Q d0 = dot(y, cross(s[1], s[2]));
    const Q d1 = dot(s[0], cross(y, s[2]));
    const Q d2 = dot(s[0], cross(s[1], y));
    const Q ad = abs(det);
    return abs(d0) <= ad && abs(d1) <= ad && abs(d2) <= ad;
  }
  // Flat box: keep the non-zero spans.
  std::vector<QVec> nz;
  for (const QVec& v : s)
    if (!is_zero(v)) nz.push_back(v);
  if (nz.empty()) return is_zero(y);
  if (nz.size() == 1) {
    // y = t * s, |t| <= 1.
    if (!is_zero(cross(y, nz[0]))) return false;
    const Q t = dot(y, nz[0]), ss = dot(nz[0], nz[0]);
    return abs(t) <= ss;
  }
  // Two (or three, one dependent) spans: find an independent pair.
  for (std::size_t i = 0; i < nz.size(); ++i)
    for (std::size_t j = i + 1; j < nz.size(); ++j) {
      const QVec n = cross(nz[i], nz[j]);
      if (is_zero(n)) continue;
      if (nz.size() == 3) throw std::domain_error("degenerate box: dependent non-zero spans");
      if (dot(y, n) != 0) return false;
      const Q nn = dot(n, n);
      const Q ti = dot(cross(y, nz[j]), n), tj = dot(cross(nz[i], y), n);
      return abs(ti) <= nn && abs(tj) <= nn;
    }
  throw std::domain_error("degenerate box: parallel non-zero spans");
}

void fill_doubles(ConvexShape& s) {
  s.lo.clear();
  s.hi.clear();
  for (const QVec& p : s.points) {
    Vec3 l, h;
    bracket(p.x, l.x, h.x);
    bracket(p.y, l.y, h.y);
    bracket(p.z, l.z, h.z);
    s.lo.push_back(l);
    s.hi.push_back(h);
  }
  double rlo;
  bracket(s.radius, rlo, s.radius_hi);
  double ahi;
  bracket(s.axis.x, s.axis_d.x, ahi);
  bracket(s.axis.y, s.axis_d.y, ahi);
  bracket(s.axis.z, s.axis_d.z, ahi);
}

}  // namespace

void bracket(const Q& q, double& lo, double& hi) {
  // mpq_get_d truncates towards zero; one ulp outwards brackets the value.
  const double d = mpq_get_d(q.backend().data());
  if (!std::isfinite(d)) {
    lo = to_double_down(q);
    hi = to_double_up(q);
    return;
  }
  if (Q(d) == q) {
    lo = hi = d;
  } else if (q > 0) {
    lo = d;
    hi = std::nextafter(d, INFINITY);
  } else {
    hi = d;
    lo = std::nextafter(d, -INFINITY);
  }
}

int sign_sqrt2(const Q& alpha, const Q& beta, const Q& u, const Q& gamma, const Q& v) {
  // sign(alpha + beta*sqrt(u) + gamma*sqrt(v)), beta, gamma, u, v >= 0.
  const bool s_zero = (beta == 0 || u == 0) && (gamma == 0 || v == 0);
  if (alpha >= 0) return (alpha > 0 || !s_zero) ? 1 : 0;
  if (s_zero) return -1;
  // alpha < 0: sign(S - |alpha|) = sign(S^2 - alpha^2), S >= 0.
  return sign_sqrt1(beta * beta * u + gamma * gamma * v - alpha * alpha, 2 * beta * gamma, u * v);
}

const char* kind_name(ConvexShape::Kind k) {
  switch (k) {
    case ConvexShape::Kind::Point: return "point";
    case ConvexShape::Kind::Segment: return "segment";
    case ConvexShape::Kind::Sphere: return "sphere";
    case ConvexShape::Kind::Capsule: return "capsule";
    case ConvexShape::Kind::Cylinder: return "cylinder";
    case ConvexShape::Kind::Box: return "box";
    case ConvexShape::Kind::Triangle: return "triangle";
    case ConvexShape::Kind::Hull: return "hull";
  }
  return "?";
}

namespace {

/// A shape whose core points and radius are the given doubles: exact
/// rationals, and their double enclosures are the doubles themselves.
ConvexShape from_doubles(ConvexShape::Kind kind, ConvexShape::Round round, std::initializer_list<Vec3> pts,
                         double radius) {
  ConvexShape s;
  s.kind = kind;
  s.round = round;
  for (const Vec3& p : pts) s.points.push_back(to_q(p));
  s.radius = to_q(radius);
  s.lo.assign(pts.begin(), pts.end());
  s.hi = s.lo;
  s.radius_hi = radius;
  return s;
}

}  // namespace

ConvexShape make_point(Vec3 x) {
  return from_doubles(ConvexShape::Kind::Point, ConvexShape::Round::None, {x}, 0);
}

ConvexShape make_shape(const Segment& g) {
  return from_doubles(ConvexShape::Kind::Segment, ConvexShape::Round::None, {g.a, g.b}, 0);
}

ConvexShape make_shape(const Sphere& g) {
  return from_doubles(ConvexShape::Kind::Sphere, ConvexShape::Round::Ball, {g.c}, g.r);
}

ConvexShape make_shape(const Capsule& g) {
  return from_doubles(ConvexShape::Kind::Capsule, ConvexShape::Round::Ball, {g.p, g.q}, g.r);
}

ConvexShape make_shape(const Cylinder& g) {
  ConvexShape s = from_doubles(ConvexShape::Kind::Cylinder, ConvexShape::Round::Disc, {g.p, g.q}, g.r);
  s.axis = s.points[1] - s.points[0];
  if (is_zero(s.axis)) throw std::domain_error("cylinder with p == q");
  s.axis_d = g.q - g.p;  // only steers the search
  return s;
}

ConvexShape make_shape(const Obb& g) {
  ConvexShape s;
  s.kind = ConvexShape::Kind::Box;
  s.centre = to_q(g.c);
  const double e[3] = {g.e.x, g.e.y, g.e.z};
  for (int k = 0; k < 3; ++k) s.spans[k] = to_q(e[k]) * to_q(g.axes[k]);
  for (int i = 0; i < 8; ++i) s.points.push_back(box_vertex(s.centre, s.spans, i));
  // Enclosures of the vertices by interval arithmetic on the doubles: no
  // rational rounding.
  IV3 span[3];
  for (int k = 0; k < 3; ++k) span[k] = Iv::exact(e[k]) * iv3(g.axes[k]);
  bool finite = true;
  for (int i = 0; i < 8; ++i) {
    IV3 v = iv3(g.c);
    for (int k = 0; k < 3; ++k) v = (i >> k & 1) ? v + span[k] : v - span[k];
    for (const Iv& c : {v.x, v.y, v.z}) finite = finite && std::isfinite(c.lo) && std::isfinite(c.hi);
    s.lo.push_back({v.x.lo, v.y.lo, v.z.lo});
    s.hi.push_back({v.x.hi, v.y.hi, v.z.hi});
  }
  s.radius_hi = 0;
  if (!finite) fill_doubles(s);  // overflow: the rational brackets
  return s;
}

ConvexShape make_shape(const Triangle& g) {
  return from_doubles(ConvexShape::Kind::Triangle, ConvexShape::Round::None, {g.a, g.b, g.c}, 0);
}

ConvexShape make_capsule(const QVec& p, const QVec& q, const Q& r) {
  if (r < 0) throw std::domain_error("capsule with a negative radius");
  ConvexShape s;
  s.kind = r == 0 ? ConvexShape::Kind::Segment : ConvexShape::Kind::Capsule;
  s.round = r == 0 ? ConvexShape::Round::None : ConvexShape::Round::Ball;
  s.points = {p, q};
  s.radius = r;
  fill_doubles(s);
  return s;
}

ConvexShape translated(const ConvexShape& s, const QVec& t) {
  ConvexShape out = s;
  for (QVec& p : out.points) p = p + t;
  out.centre = s.centre + t;
  fill_doubles(out);
  return out;
}

ConvexShape swept(const ConvexShape& s, const QVec& delta) {
  ConvexShape out = s;
  out.kind = ConvexShape::Kind::Hull;
  for (const QVec& p : s.points) out.points.push_back(p + delta);
  fill_doubles(out);
  return out;
}

bool contains(const ConvexShape& s, const QVec& x) {
  using K = ConvexShape::Kind;
  const auto& P = s.points;
  switch (s.kind) {
    case K::Point: return is_zero(x - P[0]);
    case K::Segment: return on_segment(P[0], P[1], x);
    case K::Sphere: {
      const QVec y = x - P[0];
      return dot(y, y) <= s.radius * s.radius;
    }
    case K::Capsule: {
      Q den;
      const Q num = segment_dist2_times(P[0], P[1], x, den);
      return num <= s.radius * s.radius * den;
    }
    case K::Cylinder: {
      const QVec a = s.axis, y = x - P[0];
      const Q t = dot(y, a), aa = dot(a, a);
      if (t < 0 || t > aa) return false;
      const QVec c = cross(y, a);
      return dot(c, c) <= s.radius * s.radius * aa;
    }
    case K::Box: return in_box(s.centre, s.spans, x);
    case K::Triangle: return in_triangle(P[0], P[1], P[2], x);
    case K::Hull: break;
  }
  throw std::logic_error("contains: no exact containment test for a swept hull");
}

Q core_max(const ConvexShape& s, const QVec& n) {
  Q m = dot(n, s.points[0]);
  for (std::size_t i = 1; i < s.points.size(); ++i) {
    Q v = dot(n, s.points[i]);
    if (v > m) m = std::move(v);
  }
  return m;
}

void round_term(const ConvexShape& s, const QVec& n, Q& beta, Q& u) {
  // h(n) = core_max + beta * sqrt(u).
  beta = s.radius;
  if (s.round == ConvexShape::Round::None || s.radius == 0) {
    beta = 0;
    u = 0;
  } else if (s.round == ConvexShape::Round::Ball) {
    u = dot(n, n);
  } else {
    const QVec c = cross(n, s.axis);
    u = dot(c, c) / dot(s.axis, s.axis);
  }
}

int support_sign(const ConvexShape& s, const QVec& n, const Q& d) {
  Q beta, u;
  round_term(s, n, beta, u);
  return sign_sqrt2(core_max(s, n) - d, beta, u, Q(0), Q(0));
}

QInterval support_value(const ConvexShape& s, const QVec& n) {
  Q beta, u;
  round_term(s, n, beta, u);
  QInterval h = point(core_max(s, n));
  if (beta != 0 && u != 0) h = h + point(beta) * sqrt_interval(u);
  return h;
}

int separation_sign(const ConvexShape& a, const ConvexShape& b, const QVec& n) {
  const QVec m{-n.x, -n.y, -n.z};
  Q ba, ua, bb, ub;
  round_term(a, n, ba, ua);
  round_term(b, m, bb, ub);
  return sign_sqrt2(core_max(a, n) + core_max(b, m), ba, ua, bb, ub);
}

QVec inner_point(const ConvexShape& s) {
  QVec c = s.points[0];
  for (std::size_t i = 1; i < s.points.size(); ++i) c = c + s.points[i];
  return Q(1, static_cast<long>(s.points.size())) * c;
}

bool check_separation(const ConvexShape& a, const ConvexShape& b, const SeparationCertificate& c, bool strict) {
  if (is_zero(c.n)) return false;
  const int s = separation_sign(a, b, c.n);
  return strict ? s < 0 : s <= 0;
}

Q signed_volume(const QVec& p0, const QVec& p1, const QVec& p2, const QVec& p3) {
  return dot(p1 - p0, cross(p2 - p0, p3 - p0));
}

bool origin_strictly_inside(const std::array<QVec, 4>& w) {
  const Q v = signed_volume(w[0], w[1], w[2], w[3]);
  if (v == 0) return false;
  const QVec o{0, 0, 0};
  for (int i = 0; i < 4; ++i) {
    std::array<QVec, 4> t = w;
    t[i] = o;
    const Q vi = signed_volume(t[0], t[1], t[2], t[3]);
    if (sgn(vi) != sgn(v)) return false;
  }
  return true;
}

bool check_overlap_impl(const ConvexShape& a, const ConvexShape& b, const OverlapCertificate& c, bool trust_members) {
  if (!trust_members)
    for (int i = 0; i < 4; ++i)
      if (!contains(a, c.a[i]) || !contains(b, c.b[i])) return false;
  std::array<QVec, 4> w;
  for (int i = 0; i < 4; ++i) w[i] = c.a[i] - c.b[i];
  return origin_strictly_inside(w);
}

bool check_overlap(const ConvexShape& a, const ConvexShape& b, const OverlapCertificate& c) {
  return check_overlap_impl(a, b, c, false);
}

bool check_common_point(const ConvexShape& a, const ConvexShape& b, const QVec& x) {
  return contains(a, x) && contains(b, x);
}

Q pair_scale(const ConvexShape& a, const ConvexShape& b) {
  Q s = 0;
  for (const ConvexShape* sh : {&a, &b}) {
    for (const QVec& p : sh->points)
      for (const Q* c : {&p.x, &p.y, &p.z}) s = std::max(s, Q(abs(*c)));
    s = std::max(s, sh->radius);
  }
  return s;
}

// ---- support points in integers ---------------------------------------------

namespace {

/// Scratch integers of this thread (GMP keeps their limbs between calls).
struct RadialScratch {
  mpz_t A[3], W[3], C[3], T[3], V[3], aa, vv, tmp;
  RadialScratch() {
    for (auto* v : {A, W, C, T, V})
      for (int k = 0; k < 3; ++k) mpz_init(v[k]);
    mpz_init(aa), mpz_init(vv), mpz_init(tmp);
  }
  ~RadialScratch() {
    for (auto* v : {A, W, C, T, V})
      for (int k = 0; k < 3; ++k) mpz_clear(v[k]);
    mpz_clear(aa), mpz_clear(vv), mpz_clear(tmp);
  }
};

/// x = num / 2^e (e >= 0 when the denominator is a power of two): the
/// exponent, or -1 when the denominator is not a power of two.
long dyadic_exponent(const Q& x) {
  const mpz_srcptr den = mpq_denref(x.backend().data());
  const mp_bitcnt_t e = mpz_scan1(den, 0);
  return mpz_sizeinbase(den, 2) == e + 1 ? static_cast<long>(e) : -1;
}

/// out = round(x * 2^s) towards zero, for a double x.
void scaled_double(mpz_t out, double x, long s) {
  if (x == 0) { mpz_set_ui(out, 0); return; }
  int k = 0;
  const double m = std::frexp(x, &k);  // x = m 2^k, 0.5 <= |m| < 1
  // x * 2^s = (m 2^53) * 2^(k + s - 53)
  mpz_set_d(out, std::ldexp(m, 53));
  const long sh = k + s - 53;
  if (sh >= 0) mpz_mul_2exp(out, out, static_cast<mp_bitcnt_t>(sh));
  else mpz_tdiv_q_2exp(out, out, static_cast<mp_bitcnt_t>(-sh));
}

/// out = a x b.
void zcross3(mpz_t* out, mpz_t* a, mpz_t* b, mpz_t tmp) {
  mpz_mul(out[0], a[1], b[2]), mpz_mul(tmp, a[2], b[1]), mpz_sub(out[0], out[0], tmp);
  mpz_mul(out[1], a[2], b[0]), mpz_mul(tmp, a[0], b[2]), mpz_sub(out[1], out[1], tmp);
  mpz_mul(out[2], a[0], b[1]), mpz_mul(tmp, a[1], b[0]), mpz_sub(out[2], out[2], tmp);
}
void zdot3(mpz_t out, mpz_t* a, mpz_t* b, mpz_t tmp) {
  mpz_mul(out, a[0], b[0]);
  mpz_mul(tmp, a[1], b[1]), mpz_add(out, out, tmp);
  mpz_mul(tmp, a[2], b[2]), mpz_add(out, out, tmp);
}
/// x <= 2^e for x >= 0.
bool at_most_pow2(mpz_t x, long e) {
  if (mpz_sgn(x) == 0) return true;
  const long n = static_cast<long>(mpz_sizeinbase(x, 2));  // 2^(n-1) <= x < 2^n
  if (n <= e) return true;
  return n == e + 1 && mpz_scan1(x, 0) == static_cast<mp_bitcnt_t>(e);
}
/// Q of x / 2^e.
Q q_of_scaled(mpz_t x, long e) {
  Q out;
  mpq_set_z(out.backend().data(), x);
  if (e > 0) mpq_div_2exp(out.backend().data(), out.backend().data(), static_cast<mp_bitcnt_t>(e));
  else if (e < 0) mpq_mul_2exp(out.backend().data(), out.backend().data(), static_cast<mp_bitcnt_t>(-e));
  return out;
}

}  // namespace

std::optional<QVec> radial_point_dyadic(const ConvexShape& s, int i, const Vec3& hi, const Vec3& lo, int bits) {
  const double mx = std::max({std::abs(hi.x), std::abs(hi.y), std::abs(hi.z)});
  if (!(mx > 0) || !std::isfinite(mx) || bits < 40 || bits > 400) return std::nullopt;
  thread_local RadialScratch z;
  // w ~ W / 2^sw, W of about `bits` bits.
  int kw = 0;
  std::frexp(mx, &kw);
  const long sw = bits - kw;
  const double h[3] = {hi.x, hi.y, hi.z}, l[3] = {lo.x, lo.y, lo.z};
  for (int k = 0; k < 3; ++k) {
    scaled_double(z.W[k], h[k], sw);
    scaled_double(z.tmp, l[k], sw);
    mpz_add(z.W[k], z.W[k], z.tmp);
  }
  // The shrink 1 - 2^-(bits - 14), only where the norm check needs it (an
  // exact unit vector stays exact: a touching point found by the search
  // stays on the boundary).
  const mp_bitcnt_t shrink = static_cast<mp_bitcnt_t>(bits - 14);
  auto shrunk = [&](mpz_t* X) {
    for (int k = 0; k < 3; ++k) {
      mpz_tdiv_q_2exp(z.tmp, X[k], shrink);
      mpz_sub(X[k], X[k], z.tmp);
    }
  };
  auto norm_ok = [&](mpz_t* X, long sx) {
    zdot3(z.vv, X, X, z.tmp);
    return at_most_pow2(z.vv, 2 * sx);
  };
  long sv = sw;  // v = V / 2^sv
  mpz_t* V = z.W;
  if (s.round == ConvexShape::Round::Disc) {
    // a = A / 2^ea.
    const Q* ac[3] = {&s.axis.x, &s.axis.y, &s.axis.z};
    long ea = 0;
    for (const Q* c : ac) {
      const long e = dyadic_exponent(*c);
      if (e < 0) return std::nullopt;
      ea = std::max(ea, e);
    }
    for (int k = 0; k < 3; ++k)
      mpz_mul_2exp(z.A[k], mpq_numref(ac[k]->backend().data()),
                   static_cast<mp_bitcnt_t>(ea - dyadic_exponent(*ac[k])));
    zdot3(z.aa, z.A, z.A, z.tmp);
    if (mpz_sgn(z.aa) == 0) return std::nullopt;
    zdot3(z.vv, z.W, z.A, z.tmp);
    const bool perpendicular = mpz_sgn(z.vv) == 0;
    if (!(perpendicular && norm_ok(z.W, sw))) {
      // t = (w x a) / (a . a) ~ T / 2^st: C = W x A is (w x a) 2^(sw + ea),
      // A.A is (a.a) 2^(2 ea), so T = C 2^K / (A.A) is t 2^(sw - ea + K);
      // v = a x t = (A x T) / 2^(sw + K).
      zcross3(z.C, z.W, z.A, z.tmp);
      const long cbits = static_cast<long>(std::max(
          {mpz_sizeinbase(z.C[0], 2), mpz_sizeinbase(z.C[1], 2), mpz_sizeinbase(z.C[2], 2)}));
      const long K = std::max(0L, bits + static_cast<long>(mpz_sizeinbase(z.aa, 2)) - cbits);
      for (int k = 0; k < 3; ++k) {
        mpz_mul_2exp(z.T[k], z.C[k], static_cast<mp_bitcnt_t>(K));
        mpz_tdiv_q(z.T[k], z.T[k], z.aa);
      }
      zcross3(z.V, z.A, z.T, z.tmp);
      V = z.V;
      sv = sw + K;
      if (!norm_ok(V, sv)) {
        shrunk(z.T);
        zcross3(z.V, z.A, z.T, z.tmp);
        if (!norm_ok(V, sv)) return std::nullopt;
      }
    }
  } else if (!norm_ok(z.W, sw)) {
    shrunk(z.W);  // towards zero coordinate by coordinate: only shorter
    if (!norm_ok(z.W, sw)) return std::nullopt;
  }
  // x = base + r v in integers too where base and r are dyadic: base =
  // B / 2^eb, r = R / 2^er, x = (B 2^(E - eb) + R V 2^(E - er - sv)) / 2^E.
  const QVec& base = s.points[i];
  const long er = dyadic_exponent(s.radius);
  long eb = 0;
  for (const Q* c : {&base.x, &base.y, &base.z}) {
    const long e = dyadic_exponent(*c);
    eb = e < 0 || eb < 0 ? -1 : std::max(eb, e);
  }
  if (er < 0 || eb < 0) {
    const QVec v{q_of_scaled(V[0], sv), q_of_scaled(V[1], sv), q_of_scaled(V[2], sv)};
    return base + s.radius * v;
  }
  const long E = std::max(eb, er + sv);
  const Q* bc[3] = {&base.x, &base.y, &base.z};
  QVec out;
  Q* oc[3] = {&out.x, &out.y, &out.z};
  for (int k = 0; k < 3; ++k) {
    mpz_mul(z.C[k], mpq_numref(s.radius.backend().data()), V[k]);
    mpz_mul_2exp(z.C[k], z.C[k], static_cast<mp_bitcnt_t>(E - er - sv));
    mpz_mul_2exp(z.tmp, mpq_numref(bc[k]->backend().data()),
                 static_cast<mp_bitcnt_t>(E - dyadic_exponent(*bc[k])));
    mpz_add(z.C[k], z.C[k], z.tmp);
    *oc[k] = q_of_scaled(z.C[k], E);
  }
  return out;
}

}  // namespace geomcheck::oracle
