#include "geomcheck/collide_cylinder_sphere.hpp"
#include "geomcheck/collide_many.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "geomcheck/detail/frame.hpp"

namespace geomcheck {

namespace {

// The sphere centre relative to the cylinder, measured from p in units of
// d = q - p (no normalisation, no square root):
//   t = m.d, |m x d|^2 = rho^2 d.d, en = max(-t, t - d.d, 0) = ea |d|.
// The sphere meets the cylinder iff ea^2 + er^2 <= s^2 with
// er = max(rho - r, 0); inside the radius that is en^2 <= s^2 d.d.
struct Axial {
  Vec3 d, m;
  double dd, t, cr2, en;
  Axial(const Cylinder& c, const Sphere& s) : Axial(c.q - c.p, s.c - c.p) {}
  // From the axis d and the centre's offset m from p (overlap_many forms d
  // once per batch: the same operations as the constructor above).
  Axial(const Vec3& axis, const Vec3& offset) : d(axis), m(offset) {
    dd = dot(d, d);
    t = dot(m, d);
    const Vec3 x = cross(m, d);
    cr2 = dot(x, x);
    en = t < 0 ? -t : (t > dd ? t - dd : 0.0);
  }
  // Every square and product the predicate forms is a normal double (no
  // overflow, no underflow of the axis): then no rescaling is needed, and
  // the result is bit-identical to that of the rescaled scene.
  bool safe(double r, double s) const {
    return dd >= 0x1p-600 && dd <= 0x1p+600 && cr2 <= 0x1p+1000 && en <= 0x1p+500 && r <= 0x1p+200 &&
           s <= 0x1p+200;
  }
  bool meets(double r, double s) const {
    if (cr2 <= r * r * dd) return en * en <= s * s * dd;
    const double er = std::sqrt(cr2 / dd) - r;
    return en * en / dd + er * er <= s * s;
  }
};

// Offsets of the sphere centre in the cylinder's frame (mid point, unit
// axis): robust for any axis length; used for axes too short to square and
// for the contacts the fast path leaves alone.
struct Offsets {
  detail::AxisFrame f;
  Vec3 w;       // radial vector from the axis to the centre
  double ax;    // axial offset from the mid point
  double rho;   // |w|
  double ea;    // beyond a cap plane (>= 0)
  double er;    // beyond the side (>= 0)
  explicit Offsets(const Cylinder& cyl, const Sphere& s) : f(cyl) {
    const Vec3 v = s.c - f.mid;
    ax = dot(v, f.u);
    w = v - ax * f.u;
    rho = detail::safe_length(w);
    ea = std::max(std::fabs(ax) - f.half, 0.0);
    er = std::max(rho - cyl.r, 0.0);
  }
  // ea^2 + er^2 <= r^2; outside the safe range of squares, scaled by an
  // exact power of two (bit-identical to the plain form wherever both apply).
  bool within(double r) const {
    const double m = std::max({ea, er, r});
    if (m <= detail::kSafeHi && (m >= detail::kSafeLo || m == 0)) return ea * ea + er * er <= r * r;
    if (!std::isfinite(m)) return false;
    const int e = std::ilogb(m);
    const double a = std::ldexp(ea, -e), b = std::ldexp(er, -e), c = std::ldexp(r, -e);
    return a * a + b * b <= c * c;
  }
};

// The predicate through the frame, for axes too short to square. Out of
// line and cold, so that the common path stays small.
[[gnu::noinline, gnu::cold]] bool meets_frame(const Cylinder& cyl, const Sphere& s) {
  return Offsets(cyl, s).within(s.r);
}

// The overlap predicate on a scene already rescaled (or safe as it is),
// shared by overlap() and collide() so that the two decide bit for bit alike.
bool meets(const Cylinder& cyl, const Sphere& s, const Axial& a) {
  return a.dd >= 0x1p-600 ? a.meets(cyl.r, s.r) : meets_frame(cyl, s);
}

// The contact from the p-based quantities, for well-conditioned cases: the
// centre clearly off the axis (rho > 2^-20 |m|, so the radial direction is
// accurate once re-projected), and, outside, offsets beyond a cap and beyond
// the side that are each zero or well above the rounding level. Returns
// false for the rest (the frame code's business). The shapes meet.
bool fast_contact(const Cylinder& cyl, const Sphere& s, const Axial& a, Contact& out) {
  const double dd = a.dd, t = a.t;
  if (!(dd >= 0x1p-600) || !(a.cr2 > 0x1p-40 * dot(a.m, a.m) * dd)) return false;
  const double len = std::sqrt(dd), inv_len = 1.0 / len;
  const Vec3 u = inv_len * a.d;
  const double rho = std::sqrt(a.cr2) * inv_len;
  const Vec3 w = a.m - (t / dd) * a.d;  // from the axis to the centre
  // Radial direction: w re-projected (perpendicular to rounding) and
  // normalised by its own length (w carries up to eps |m| of rounding).
  // Its squared length may be subnormal where the radius is tiny against the
  // axis after rescaling (regression 0005): normalized() scales it first.
  const Vec3 wp = w - dot(w, u) * u;
  const Vec3 rad = detail::normalized(wp);
  if (t >= 0 && t <= dd && a.cr2 <= cyl.r * cyl.r * dd) {
    // Centre inside: leave through the nearer cap or the side. (rho and the
    // inside test round differently: the side gap is clamped at zero.)
    const double cap_gap = std::min(t, dd - t) * inv_len, side_gap = std::max(cyl.r - rho, 0.0);
    out.hit = true;
    out.point = s.c;
    if (cap_gap <= side_gap) {
      out.normal = 2 * t >= dd ? u : -u;
      out.depth = s.r + cap_gap;
    } else {
      out.normal = rad;
      out.depth = s.r + side_gap;
    }
    return true;
  }
  const double ea = a.en * inv_len, er = std::max(rho - cyl.r, 0.0);
  // Both offsets zero (on the surface by rounding) or one at the rounding
  // level of |m| and |d|: the direction is the frame code's business.
  const double noise = 0x1p-40 * std::max(max_abs(a.m), len);
  if ((ea == 0 && er == 0) || (ea != 0 && ea <= noise) || (er != 0 && er <= noise)) return false;
  const double dist = std::sqrt(ea * ea + er * er), inv_dist = 1.0 / dist;
  out.hit = true;
  out.point = cyl.p + std::clamp(t / dd, 0.0, 1.0) * a.d + (rho > cyl.r ? (cyl.r / rho) * w : w);
  out.normal = (ea * inv_dist) * (t > dd ? u : -u) + (er * inv_dist) * rad;
  out.depth = std::max(s.r - dist, 0.0);
  return true;
}

// The contact through the cylinder's frame: any axis length, any position.
[[gnu::noinline]] Contact frame_contact(const Cylinder& cyl, const Sphere& s) {
  Contact out;
  const Offsets o(cyl, s);
  const detail::AxisFrame& f = o.f;
  const double ax = o.ax, rho = o.rho, aax = std::fabs(ax);
  // Offsets at the rounding level of the case carry no direction
  // (regression 0002): a radial offset below it gives no radial direction.
  const double largest = std::max(detail::largest(cyl), detail::largest(s));
  const double noise = 16 * 0x1p-52 * std::max(largest, f.half);
  auto radial_dir = [&] { return rho > noise ? detail::unit_perpendicular_part(o.w, f.u) : any_perpendicular(f.u); };
  out.hit = true;

  if (aax <= f.half && rho <= cyl.r) {
    // Centre inside the cylinder: leave through the nearer cap or the side.
    const double cap_gap = f.half - aax;
    const double side_gap = cyl.r - rho;
    out.point = s.c;
    if (cap_gap <= side_gap) {
      out.normal = ax >= 0 ? f.u : -f.u;
      out.depth = s.r + cap_gap;
    } else {
      out.normal = radial_dir();
      out.depth = s.r + side_gap;
    }
    return out;
  }

  // Centre outside: the closest point of the cylinder clamps both offsets.
  const double cax = std::clamp(ax, -f.half, f.half);
  out.point = f.mid + cax * f.u + (rho > cyl.r ? (cyl.r / rho) * o.w : o.w);
  // The normal is built from the offsets along the exact cap and radial
  // directions, so that a tiny gap does not lose it to cancellation. Offsets
  // at the rounding level are dropped; if both vanish the centre is on the
  // surface and the normal of the face it is farther out of is valid.
  const double ea = o.ea, er = o.er;
  const double ean = ea > noise ? ea : 0.0, ern = er > noise ? er : 0.0;
  const Vec3 cap = ax >= 0 ? f.u : -f.u;
  Vec3 n;
  if (ern == 0) n = ean > 0 || ea >= er ? cap : radial_dir();
  else if (ean == 0) n = radial_dir();
  else {
    const double big = std::max(ean, ern);  // scaled so that huge offsets do not overflow
    n = detail::normalized((ean / big) * cap + (ern / big) * radial_dir());
  }
  out.normal = n;
  out.depth = std::max(s.r - detail::safe_length(Vec3{ea, er, 0}), 0.0);
  return out;
}

// Contact on a scene that needs no rescaling (or has been rescaled).
Contact contact(const Cylinder& cyl, const Sphere& s, const Axial& a) {
  Contact out;
  if (!meets(cyl, s, a)) return out;  // the same predicate as overlap()
  if (fast_contact(cyl, s, a, out)) return out;
  return frame_contact(cyl, s);
}

// The scene rescaled by an exact power of two (magnitudes whose squares
// would overflow or underflow): cylinder, sphere and the scale used.
struct Rescaled {
  detail::SceneScale sc;
  Cylinder cyl;
  Sphere s;
  Rescaled(const Cylinder& c, const Sphere& sp)
      : sc(std::max(detail::largest(c), detail::largest(sp))), cyl(sc.in(c)), s(sc.in(sp)) {}
};

[[gnu::noinline, gnu::cold]] bool overlap_rescaled(const Cylinder& cyl, const Sphere& s) {
  const Rescaled r(cyl, s);
  if (!is_valid(r.cyl)) return false;  // an axis far below the scene's magnitude vanishes
  return meets(r.cyl, r.s, Axial(r.cyl, r.s));
}

[[gnu::noinline, gnu::cold]] Contact collide_rescaled(const Cylinder& cyl, const Sphere& s) {
  const Rescaled r(cyl, s);
  if (!is_valid(r.cyl)) return {};
  Contact out = contact(r.cyl, r.s, Axial(r.cyl, r.s));
  out.point = r.sc.out(out.point);
  // A depth beyond the largest double (shapes near DBL_MAX) saturates.
  out.depth = std::min(r.sc.out(out.depth), std::numeric_limits<double>::max());
  return out;
}

}  // namespace

void overlap_many(const Cylinder& cyl, const Sphere* b, std::size_t n, bool* out) {
  if (!is_valid(cyl)) {
    std::fill(out, out + n, false);
    return;
  }
  // overlap()'s own arithmetic (Axial: safe, meets), with the axis, d.d and
  // r^2 d.d formed once and both sides of meets' branch evaluated, so that
  // the loop has no data-dependent branch. A sphere outside the range where
  // that arithmetic needs no rescaling (Axial::safe, or a little narrower),
  // or invalid, is marked and answered by the scalar query in a second pass.
  const Vec3 p = cyl.p, d = cyl.q - cyl.p;
  const double dd = dot(d, d), r = cyl.r, rrdd = r * r * dd;
  const bool axis_safe = dd >= 0x1p-600 && dd <= 0x1p+600 && r <= 0x1p+200;
  // Element i's verdict by the batch arithmetic; `fast` false where the
  // scalar query must answer instead.
  const auto batch = [&](const Sphere& s, bool& fast) {
    const Vec3 m = s.c - p;
    const double t = dot(m, d);
    const Vec3 x = cross(m, d);
    const double cr2 = dot(x, x);
    const double en = t < 0 ? -t : (t > dd ? t - dd : 0.0);
    const bool inside_radius = cr2 <= rrdd;
    const bool meets_inside = en * en <= s.r * s.r * dd;
    const double er = std::sqrt(cr2 / dd) - r;
    const bool meets_outside = en * en / dd + er * er <= s.r * s.r;
    // Within Axial::safe, and a finite centre (a NaN or infinite coordinate
    // makes t NaN or infinite).
    fast = axis_safe & (cr2 <= 0x1p+1000) & (en <= 0x1p+500) & (s.r <= 0x1p+200) & (s.r >= 0) &
           (std::fabs(t) <= 0x1p+1000);
    return (inside_radius & meets_inside) | (!inside_radius & meets_outside);
  };
  bool all_fast = true;
  std::size_t i = 0;
#if defined(__SSE2__)
  // Two spheres at a time: the same operations on each lane as `batch`
  // (dot and cross in vec3.hpp's order, the same products and quotients),
  // so every lane's verdict is batch's, bit for bit.
  {
    const __m128d px = _mm_set1_pd(p.x), py = _mm_set1_pd(p.y), pz = _mm_set1_pd(p.z);
    const __m128d dx = _mm_set1_pd(d.x), dy = _mm_set1_pd(d.y), dz = _mm_set1_pd(d.z);
    const __m128d ddv = _mm_set1_pd(dd), rrddv = _mm_set1_pd(rrdd), rv = _mm_set1_pd(r), zero = _mm_setzero_pd();
    const __m128d big_cr2 = _mm_set1_pd(0x1p+1000), big_en = _mm_set1_pd(0x1p+500), big_r = _mm_set1_pd(0x1p+200);
    const __m128d abs_mask = _mm_castsi128_pd(_mm_set1_epi64x(0x7FFFFFFFFFFFFFFFll));
    const __m128d axis_ok = axis_safe ? _mm_castsi128_pd(_mm_set1_epi64x(-1)) : zero;
    for (; i + 2 <= n; i += 2) {
      const Sphere& s0 = b[i];
      const Sphere& s1 = b[i + 1];
      const __m128d mx = _mm_sub_pd(_mm_set_pd(s1.c.x, s0.c.x), px);
      const __m128d my = _mm_sub_pd(_mm_set_pd(s1.c.y, s0.c.y), py);
      const __m128d mz = _mm_sub_pd(_mm_set_pd(s1.c.z, s0.c.z), pz);
      const __m128d sr = _mm_set_pd(s1.r, s0.r);
      const __m128d t = _mm_add_pd(_mm_add_pd(_mm_mul_pd(mx, dx), _mm_mul_pd(my, dy)), _mm_mul_pd(mz, dz));
      const __m128d xx = _mm_sub_pd(_mm_mul_pd(my, dz), _mm_mul_pd(mz, dy));
      const __m128d xy = _mm_sub_pd(_mm_mul_pd(mz, dx), _mm_mul_pd(mx, dz));
      const __m128d xz = _mm_sub_pd(_mm_mul_pd(mx, dy), _mm_mul_pd(my, dx));
      const __m128d cr2 = _mm_add_pd(_mm_add_pd(_mm_mul_pd(xx, xx), _mm_mul_pd(xy, xy)), _mm_mul_pd(xz, xz));
      // en = t < 0 ? -t : (t > dd ? t - dd : 0)
      const __m128d neg = _mm_cmplt_pd(t, zero), beyond = _mm_cmpgt_pd(t, ddv);
      const __m128d past = _mm_and_pd(beyond, _mm_sub_pd(t, ddv));
      const __m128d en = _mm_or_pd(_mm_and_pd(neg, _mm_sub_pd(zero, t)), _mm_andnot_pd(neg, past));
      const __m128d inside = _mm_cmple_pd(cr2, rrddv);
      const __m128d en2 = _mm_mul_pd(en, en), sr2 = _mm_mul_pd(sr, sr);
      const __m128d meets_in = _mm_cmple_pd(en2, _mm_mul_pd(sr2, ddv));
      const __m128d er = _mm_sub_pd(_mm_sqrt_pd(_mm_div_pd(cr2, ddv)), rv);
      const __m128d meets_out = _mm_cmple_pd(_mm_add_pd(_mm_div_pd(en2, ddv), _mm_mul_pd(er, er)), sr2);
      const __m128d fast = _mm_and_pd(
          _mm_and_pd(_mm_and_pd(axis_ok, _mm_cmple_pd(cr2, big_cr2)), _mm_and_pd(_mm_cmple_pd(en, big_en), _mm_cmple_pd(sr, big_r))),
          _mm_and_pd(_mm_cmpge_pd(sr, zero), _mm_cmple_pd(_mm_and_pd(t, abs_mask), big_cr2)));
      const __m128d hit = _mm_or_pd(_mm_and_pd(inside, meets_in), _mm_andnot_pd(inside, meets_out));
      const int f = _mm_movemask_pd(fast), h = _mm_movemask_pd(_mm_and_pd(fast, hit));
      all_fast &= f == 3;
      out[i] = (h & 1) != 0;
      out[i + 1] = (h & 2) != 0;
    }
  }
#endif
  for (; i < n; ++i) {
    bool fast;
    const bool hit = batch(b[i], fast);
    all_fast &= fast;
    out[i] = fast & hit;
  }
  if (all_fast) return;
  for (std::size_t i = 0; i < n; ++i) {
    bool fast;
    batch(b[i], fast);
    if (!fast) out[i] = overlap(cyl, b[i]);
  }
}

void collide_many(const Cylinder& cyl, const Sphere* b, std::size_t n, Contact* out) {
  detail::each_scalar(cyl, b, n, out, [](const Cylinder& c, const Sphere& x) { return collide(c, x); });
}

bool overlap(const Cylinder& cyl, const Sphere& s) {
  if (!is_valid(cyl) || !is_valid(s)) return false;
  const Axial a(cyl, s);
  if (a.safe(cyl.r, s.r)) return a.meets(cyl.r, s.r);
  return overlap_rescaled(cyl, s);
}

Contact collide(const Cylinder& cyl, const Sphere& s) {
  if (!is_valid(cyl) || !is_valid(s)) return {};
  const Axial a(cyl, s);
  if (a.safe(cyl.r, s.r)) return contact(cyl, s, a);
  return collide_rescaled(cyl, s);
}

}  // namespace geomcheck
