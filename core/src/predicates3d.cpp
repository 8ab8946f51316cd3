#include "geomcheck/predicates3d.hpp"

#include <cmath>

#include "exact_integers.hpp"
#include "exact_steps.hpp"
#include "exact_wide.hpp"

namespace geomcheck::detail {

using exact_integers::Int;
using exact_integers::Scaled;
using exact_integers::sign_of;

namespace {

// ---- stage 2: the filter on the points scaled by one power of two (their
// largest magnitude into [1, 2)), where that is exact (no non-zero
// coordinate leaves the normal range): a set far from 1 in scale, whose
// products overflow or underflow, answers as fast as one near 1. False
// (nothing to retry) when the scaling is not exact, or is by 2^0: the points
// already in [1, 2) (as delaunay_3d scales its points) would give the first
// filter's answer again.
template <std::size_t N>
bool common_scale(Vec3 (&p)[N]) {
  double m = 0;
  for (const Vec3& v : p) m = std::max(m, max_abs(v));
  if (!(m > 0) || !std::isfinite(m)) return false;
  const int e = std::ilogb(m);
  if (e == 0) return false;
  for (const Vec3& v : p)
    for (double c : {v.x, v.y, v.z})
      if (c != 0 && std::ilogb(c) - e < -1022) return false;
  for (Vec3& v : p) v = {std::ldexp(v.x, -e), std::ldexp(v.y, -e), std::ldexp(v.z, -e)};
  return true;
}
int decided(const FilterValue& f) {
  return f.usable && (f.value > f.bound || -f.value > f.bound) ? (f.value > 0 ? 1 : -1) : 2;
}

// ---- stage 3: the determinant in doubles, every step checked error-free
// (exact_steps.hpp): integer grids and other small exact coordinates, the
// common degenerate input, without big integers.
struct Steps {
  bool ok = true;
  double diff(double a, double b) {
    double d = 0;
    ok = ok && exact_steps::exact_diff(a, b, d);
    return d;
  }
  double prod(double a, double b) {
    double p = 0;
    ok = ok && exact_steps::exact_prod(a, b, p);
    return p;
  }
  double add(double a, double b) {
    double s = 0;
    ok = ok && exact_steps::exact_add(a, b, s);
    return s;
  }
  double minor(double a, double b, double c, double d) { return add(prod(a, b), -prod(c, d)); }  // ab - cd
};
int sign_if(const Steps& st, double det) { return !st.ok ? 2 : (det > 0 ? 1 : (det < 0 ? -1 : 0)); }

int orient3d_in_doubles(Vec3 a, Vec3 b, Vec3 c, Vec3 d) {
  Steps st;
  const double adx = st.diff(a.x, d.x), ady = st.diff(a.y, d.y), adz = st.diff(a.z, d.z);
  const double bdx = st.diff(b.x, d.x), bdy = st.diff(b.y, d.y), bdz = st.diff(b.z, d.z);
  const double cdx = st.diff(c.x, d.x), cdy = st.diff(c.y, d.y), cdz = st.diff(c.z, d.z);
  if (!st.ok) return 2;
  const double t1 = st.prod(adz, st.minor(bdx, cdy, cdx, bdy));
  const double t2 = st.prod(bdz, st.minor(cdx, ady, adx, cdy));
  const double t3 = st.prod(cdz, st.minor(adx, bdy, bdx, ady));
  return sign_if(st, st.add(st.add(t1, t2), t3));
}

int insphere_in_doubles(Vec3 a, Vec3 b, Vec3 c, Vec3 d, Vec3 e) {
  Steps st;
  const double aex = st.diff(a.x, e.x), aey = st.diff(a.y, e.y), aez = st.diff(a.z, e.z);
  const double bex = st.diff(b.x, e.x), bey = st.diff(b.y, e.y), bez = st.diff(b.z, e.z);
  const double cex = st.diff(c.x, e.x), cey = st.diff(c.y, e.y), cez = st.diff(c.z, e.z);
  const double dex = st.diff(d.x, e.x), dey = st.diff(d.y, e.y), dez = st.diff(d.z, e.z);
  if (!st.ok) return 2;
  const double ab = st.minor(aex, bey, bex, aey), bc = st.minor(bex, cey, cex, bey), cd = st.minor(cex, dey, dex, cey);
  const double da = st.minor(dex, aey, aex, dey), ac = st.minor(aex, cey, cex, aey), bd = st.minor(bex, dey, dex, bey);
  const double abc = st.add(st.add(st.prod(aez, bc), -st.prod(bez, ac)), st.prod(cez, ab));
  const double bcd = st.add(st.add(st.prod(bez, cd), -st.prod(cez, bd)), st.prod(dez, bc));
  const double cda = st.add(st.add(st.prod(cez, da), st.prod(dez, ac)), st.prod(aez, cd));
  const double dab = st.add(st.add(st.prod(dez, ab), st.prod(aez, bd)), st.prod(bez, da));
  auto lift = [&](double x, double y, double z) { return st.add(st.add(st.prod(x, x), st.prod(y, y)), st.prod(z, z)); };
  const double al = lift(aex, aey, aez), bl = lift(bex, bey, bez), cl = lift(cex, cey, cez), dl = lift(dex, dey, dez);
  const double det = st.add(st.add(st.prod(dl, abc), -st.prod(cl, dab)), st.add(st.prod(bl, cda), -st.prod(al, bcd)));
  return sign_if(st, det);
}

}  // namespace

int orient3d_exact(Vec3 a, Vec3 b, Vec3 c, Vec3 d) {
  Vec3 p[4] = {a, b, c, d};
  if (common_scale(p)) {
    const int s = decided(orient3d_filter(p[0], p[1], p[2], p[3]));
    if (s != 2) return s;
  }
  const int s = orient3d_in_doubles(a, b, c, d);
  return s != 2 ? s : orient3d_rational(a, b, c, d);
}

int insphere_exact(Vec3 a, Vec3 b, Vec3 c, Vec3 d, Vec3 e) {
  Vec3 p[5] = {a, b, c, d, e};
  if (common_scale(p)) {
    const int s = decided(insphere_filter(p[0], p[1], p[2], p[3], p[4]));
    if (s != 2) return s;
  }
  const int s = insphere_in_doubles(a, b, c, d, e);
  return s != 2 ? s : insphere_rational(a, b, c, d, e);
}

namespace {

// The determinants on integer coordinates s[0..12) (orient3d: a, b, c, d)
// and s[0..15) (insphere: a, b, c, d, e), in any exact integer type T.
template <class T, class S>
int orient3d_sign(const S& s) {
  const T adx = T(s[0]) - T(s[9]), ady = T(s[1]) - T(s[10]), adz = T(s[2]) - T(s[11]);
  const T bdx = T(s[3]) - T(s[9]), bdy = T(s[4]) - T(s[10]), bdz = T(s[5]) - T(s[11]);
  const T cdx = T(s[6]) - T(s[9]), cdy = T(s[7]) - T(s[10]), cdz = T(s[8]) - T(s[11]);
  return sign_of(T(adz * (bdx * cdy - cdx * bdy) + bdz * (cdx * ady - adx * cdy) + cdz * (adx * bdy - bdx * ady)));
}

template <class T, class S>
int insphere_sign(const S& s) {
  const T aex = T(s[0]) - T(s[12]), aey = T(s[1]) - T(s[13]), aez = T(s[2]) - T(s[14]);
  const T bex = T(s[3]) - T(s[12]), bey = T(s[4]) - T(s[13]), bez = T(s[5]) - T(s[14]);
  const T cex = T(s[6]) - T(s[12]), cey = T(s[7]) - T(s[13]), cez = T(s[8]) - T(s[14]);
  const T dex = T(s[9]) - T(s[12]), dey = T(s[10]) - T(s[13]), dez = T(s[11]) - T(s[14]);
  const T ab = aex * bey - bex * aey, bc = bex * cey - cex * bey, cd = cex * dey - dex * cey;
  const T da = dex * aey - aex * dey, ac = aex * cey - cex * aey, bd = bex * dey - dex * bey;
  const T abc = aez * bc - bez * ac + cez * ab;
  const T bcd = bez * cd - cez * bd + dez * bc;
  const T cda = cez * da + dez * ac + aez * cd;
  const T dab = dez * ab + aez * bd + bez * da;
  const T alift = aex * aex + aey * aey + aez * aez, blift = bex * bex + bey * bey + bez * bez;
  const T clift = cex * cex + cey * cey + cez * cez, dlift = dex * dex + dey * dey + dez * dez;
  return sign_of(T((dlift * abc - clift * dab) + (blift * cda - alift * bcd)));
}

// Fixed-width limbs where the coordinates span at most 125 bits
// (exact_wide.hpp). With every |coordinate| < 2^b, b <= 125, and b' = b + 1:
// a difference is below 2^b' (2 limbs); a 2x2 minor below 2^(2b'+1) and a
// lift below 3 2^(2b') (4 limbs, 255 bits); a 3x3 minor below 6 2^(3b')
// (6 limbs, 383 bits); orient3d is one, and insphere's four terms of a lift
// times a 3x3 minor are below 72 2^(5b') <= 2^637 (10 limbs, 639 bits).
// Every step fits its width, so nothing wraps. 2 when the span is wider.
int orient3d_limbs(const __int128 (&s)[12]) {
  using namespace exact_wide;
  using W2 = Wide<2>;
  const W2 adx(s[0] - s[9]), ady(s[1] - s[10]), adz(s[2] - s[11]);
  const W2 bdx(s[3] - s[9]), bdy(s[4] - s[10]), bdz(s[5] - s[11]);
  const W2 cdx(s[6] - s[9]), cdy(s[7] - s[10]), cdz(s[8] - s[11]);
  const Wide<4> bc = mul<4>(bdx, cdy) - mul<4>(cdx, bdy), ca = mul<4>(cdx, ady) - mul<4>(adx, cdy);
  const Wide<4> ab = mul<4>(adx, bdy) - mul<4>(bdx, ady);
  return (mul<6>(adz, bc) + mul<6>(bdz, ca) + mul<6>(cdz, ab)).sign();
}

int insphere_limbs(const __int128 (&s)[15]) {
  using namespace exact_wide;
  using W2 = Wide<2>;
  using W4 = Wide<4>;
  using W6 = Wide<6>;
  const W2 aex(s[0] - s[12]), aey(s[1] - s[13]), aez(s[2] - s[14]);
  const W2 bex(s[3] - s[12]), bey(s[4] - s[13]), bez(s[5] - s[14]);
  const W2 cex(s[6] - s[12]), cey(s[7] - s[13]), cez(s[8] - s[14]);
  const W2 dex(s[9] - s[12]), dey(s[10] - s[13]), dez(s[11] - s[14]);
  auto minor = [](const W2& p, const W2& q, const W2& r, const W2& t) { return mul<4>(p, q) - mul<4>(r, t); };
  const W4 ab = minor(aex, bey, bex, aey), bc = minor(bex, cey, cex, bey), cd = minor(cex, dey, dex, cey);
  const W4 da = minor(dex, aey, aex, dey), ac = minor(aex, cey, cex, aey), bd = minor(bex, dey, dex, bey);
  const W6 abc = mul<6>(aez, bc) - mul<6>(bez, ac) + mul<6>(cez, ab);
  const W6 bcd = mul<6>(bez, cd) - mul<6>(cez, bd) + mul<6>(dez, bc);
  const W6 cda = mul<6>(cez, da) + mul<6>(dez, ac) + mul<6>(aez, cd);
  const W6 dab = mul<6>(dez, ab) + mul<6>(aez, bd) + mul<6>(bez, da);
  auto lift = [](const W2& x, const W2& y, const W2& z) { return mul<4>(x, x) + mul<4>(y, y) + mul<4>(z, z); };
  const W4 al = lift(aex, aey, aez), bl = lift(bex, bey, bez), cl = lift(cex, cey, cez), dl = lift(dex, dey, dez);
  return ((mul<10>(dl, abc) - mul<10>(cl, dab)) + (mul<10>(bl, cda) - mul<10>(al, bcd))).sign();
}

template <std::size_t M>
int sign_in_limbs(const double (&xs)[M]) {
  const exact_wide::ScaledSmall<M> s(xs);
  if (!s.ok) return 2;
  if constexpr (M == 12) return orient3d_limbs(s.v);
  else return insphere_limbs(s.v);
}

}  // namespace

int orient3d_rational(Vec3 a, Vec3 b, Vec3 c, Vec3 d) {
  const double xs[] = {a.x, a.y, a.z, b.x, b.y, b.z, c.x, c.y, c.z, d.x, d.y, d.z};
  const int w = sign_in_limbs<12>(xs);
  return w != 2 ? w : orient3d_sign<Int>(Scaled<12>(xs));
}

int insphere_rational(Vec3 a, Vec3 b, Vec3 c, Vec3 d, Vec3 e) {
  const double xs[] = {a.x, a.y, a.z, b.x, b.y, b.z, c.x, c.y, c.z, d.x, d.y, d.z, e.x, e.y, e.z};
  const int w = sign_in_limbs<15>(xs);
  return w != 2 ? w : insphere_sign<Int>(Scaled<15>(xs));
}

}  // namespace geomcheck::detail
