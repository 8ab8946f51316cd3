// Reference subjects: code written the way a user writes it (its own vector
// and shape types, its own algorithm, not production's), correct but not
// exact, once for any floating-point type T (double, float), with the
// adapters that make them subjects and their known-wrong siblings.
//
//   collide(Cyl, Ball)  sphere against cylinder: the closest point of the
//                       cylinder to the ball's centre; a centre inside
//                       leaves through the nearest face.
//   cast(Seg, Cyl)      segment against cylinder: the slab between the cap
//                       planes intersected with the infinite cylinder's
//                       interval, the side's roots taken about the line's
//                       closest approach to the axis (no cancellation far
//                       from the hit).
//
// And for every registered pair query, production seen the way another
// engine sees the scene (production_seen_in<Q, T>): in float, every input
// coordinate rounded to float and every output number too (a float engine's
// input and answer); in double, every input coordinate moved one ulp up (an
// answer for a neighbouring scene). Both are correct but not exact, and
// exercise every query's checks on answers that are not production's bit
// for bit; they are not user-style code.
//
// Each is declared with its precision (Precision::double_precision or
// single_precision, and valid scenes only) and nothing else: test_reference_subjects holds them to every
// property on three seeds and expects no failure, and expects each sibling
// to fail the property that names its flaw.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstring>
#include <type_traits>
#include <limits>

#include <geomcheck/verify.hpp>

namespace ref {

template <class T>
struct V {
  T x, y, z;
};
template <class T> V<T> operator+(V<T> a, V<T> b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
template <class T> V<T> operator-(V<T> a, V<T> b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
template <class T> V<T> operator*(T s, V<T> a) { return {s * a.x, s * a.y, s * a.z}; }
template <class T> T dot(V<T> a, V<T> b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
template <class T> T max_abs(V<T> a) { return std::max({std::fabs(a.x), std::fabs(a.y), std::fabs(a.z)}); }
/// Length without overflow or underflow of the squares.
template <class T> T len(V<T> a) {
  const T m = max_abs(a);
  if (!(m > 0)) return 0;
  const V<T> s = (1 / m) * a;
  return m * std::sqrt(dot(s, s));
}
/// Unit vector (a != 0), scaled first.
template <class T> V<T> unit(V<T> a) {
  const V<T> s = (1 / max_abs(a)) * a;
  return (1 / std::sqrt(dot(s, s))) * s;
}
/// The part of w across direction d (any length), projected out twice:
/// perpendicular to d even where it is rounding noise (d is scaled first, so
/// its square neither overflows nor underflows; u = unit(d) is unit only to
/// rounding, and w - (w.u) u would keep a part along it).
/// At the rounding level of w the part across is noise in any direction
/// (a vector along d leaves a residue along d): then it is zero.
template <class T> V<T> across(V<T> w, V<T> d) {
  const V<T> s = (1 / max_abs(d)) * d;
  const T ss = dot(s, s);
  const V<T> once = w - (dot(w, s) / ss) * s;
  const V<T> twice = once - (dot(once, s) / ss) * s;
  return max_abs(twice) > 16 * std::numeric_limits<T>::epsilon() * max_abs(w) ? twice : V<T>{0, 0, 0};
}
/// A unit vector perpendicular to unit u.
template <class T> V<T> any_perp(V<T> u) {
  return unit(std::fabs(u.x) < T(0.5) ? V<T>{0, u.z, -u.y} : V<T>{-u.z, 0, u.x});
}

template <class T> struct Cyl { V<T> p, q; T r; };
template <class T> struct Ball { V<T> c; T r; };
template <class T> struct Seg { V<T> a, b; };
template <class T> struct Touch { bool hit = false; V<T> normal{}, point{}; T depth = 0; };
template <class T> struct Ray { bool hit = false, inside = false; T t = 0; V<T> point{}, normal{}; };

/// Which flaw a sibling carries (none: the correct subject).
enum class Flaw {
  None,
  DeepPointOnFace,  ///< a centre inside: the point on the nearest face, outside a small ball
  RoundedCaps,      ///< the cylinder taken as a capsule (round ends)
  NoCaps,           ///< the cast ignores the cap planes (an infinite cylinder)
  Unguarded,        ///< segments' closest points without the parallel guard
};

/// Sphere against cylinder; the normal from the cylinder towards the ball.
template <class T>
Touch<T> collide(const Cyl<T>& cy, const Ball<T>& b, Flaw flaw = Flaw::None) {
  const V<T> d = cy.q - cy.p, u = unit(d), w = b.c - cy.p;
  const T length = len(d), t = dot(w, u);
  const V<T> radial = across(w, d);
  const T rho = len(radial);
  const V<T> e = rho > 0 ? unit(radial) : any_perp(u);
  Touch<T> out;
  if (flaw == Flaw::RoundedCaps) {  // the capsule's closest point
    const V<T> x = cy.p + std::min(std::max(t, T(0)), length) * u;
    const T dist = len(b.c - x);
    if (dist > b.r + cy.r) return out;
    out.hit = true;
    out.normal = dist > 0 ? unit(b.c - x) : e;
    out.depth = b.r + cy.r - dist;
    out.point = x + std::min(cy.r, dist) * out.normal;
    return out;
  }
  const bool inside = t >= 0 && t <= length && rho <= cy.r;
  if (!inside) {
    // The centre's offsets from the closest point, in the frame (u, e): along
    // the axis beyond a cap, radially beyond the side. Built from them, the
    // normal lies in the normal cone of the closest feature even where the
    // offsets are at the rounding level (b.c - x would be noise there).
    const T axial = t < 0 ? t : (t > length ? t - length : T(0));
    const T out_radial = std::max(rho - cy.r, T(0));
    const V<T> off = axial * u + out_radial * e;
    const T dist = len(off);
    if (dist > b.r) return out;
    out.hit = true;
    if (dist > 0) {
      out.normal = unit(off);
      out.depth = b.r - dist;
      out.point = cy.p + std::min(std::max(t, T(0)), length) * u + std::min(rho, cy.r) * e;
      return out;
    }
  }
  // The centre inside (or on the surface): out through the nearest face.
  const T side = cy.r - rho, bottom = t, top = length - t;
  const T m = std::max(T(0), std::min(side, std::min(bottom, top)));
  out.hit = true;
  out.normal = m == side ? e : (m == bottom ? T(-1) * u : u);
  out.depth = m + b.r;
  out.point = flaw == Flaw::DeepPointOnFace ? b.c + m * out.normal : b.c;
  return out;
}

/// Segment cast against the cylinder: the first t of S(t) = a + t (b - a)
/// in the solid.
template <class T>
Ray<T> cast(const Seg<T>& s, const Cyl<T>& cy, Flaw flaw = Flaw::None) {
  Ray<T> out;
  const V<T> d = cy.q - cy.p, u = unit(d), v = s.b - s.a, m = s.a - cy.p;
  const T length = len(d);
  // The slab 0 <= (S(t) - p).u <= L: entry t0, exit t1, and which cap enters.
  T t0 = 0, t1 = 1;
  int cap = 0;  // the entry's feature: 0 the start or the side, -1 the p cap, +1 the q cap
  const T ms = dot(m, u), vs = dot(v, u);
  if (flaw != Flaw::NoCaps) {
    if (vs == 0) {
      if (ms < 0 || ms > length) return out;
    } else {
      T lo = -ms / vs, hi = (length - ms) / vs;
      int lo_cap = -1;
      if (lo > hi) std::swap(lo, hi), lo_cap = +1;
      if (lo > t0) t0 = lo, cap = lo_cap;
      t1 = std::min(t1, hi);
    }
  }
  // The infinite cylinder: about the line's closest approach to the axis.
  const V<T> mp = m - ms * u, vp = v - vs * u;
  const T a2 = dot(vp, vp);
  if (!(a2 > 0)) {
    if (len(mp) > cy.r) return out;
  } else {
    const T tc = -dot(mp, vp) / a2;
    const T rho0 = len(mp + tc * vp);
    if (rho0 > cy.r) return out;
    const T half = std::sqrt((cy.r - rho0) * (cy.r + rho0)) / std::sqrt(a2);
    if (tc - half > t0) t0 = tc - half, cap = 0;
    t1 = std::min(t1, tc + half);
  }
  if (t0 > t1) return out;
  out.hit = true;
  if (t0 == 0 && cap == 0) {  // the start is inside
    out.inside = true;
    out.point = s.a;
    return out;
  }
  out.t = t0;
  out.point = s.a + t0 * v;
  if (cap != 0) {
    out.normal = cap < 0 ? T(-1) * u : u;
  } else {
    const V<T> x = out.point - cy.p;
    const V<T> radial = across(x, d);
    out.normal = max_abs(radial) > 0 ? unit(radial) : any_perp(u);
  }
  return out;
}

// --- adapters: geomcheck's shapes in, geomcheck's answers out ------------------

template <class T> V<T> mine(geomcheck::Vec3 v) { return {T(v.x), T(v.y), T(v.z)}; }
template <class T> geomcheck::Vec3 theirs(V<T> v) { return {double(v.x), double(v.y), double(v.z)}; }
/// A hit as the door takes it.
template <class T> geomcheck::CastHit theirs(const Ray<T>& h) {
  geomcheck::CastHit out;
  out.hit = h.hit;
  out.starts_inside = h.inside;
  out.t = double(h.t);
  out.point = theirs(h.point);
  out.normal = theirs(h.normal);
  return out;
}

/// The claims of a subject computing in T: production's, at T's precision.
template <geomcheck::QueryId Q, class T>
geomcheck::Claims claims_in() {
  geomcheck::Claims c = geomcheck::production_claims<Q>();
  c.any_input = false;  // valid scenes only: no NaN, no negative radius
  c.precision = sizeof(T) == sizeof(float) ? geomcheck::Precision::single_precision()
                                           : geomcheck::Precision::double_precision();
  return c;
}

/// The sphere query's subject in T (with a flaw: a known-wrong sibling).
template <class T>
auto sphere_subject(const char* name, Flaw flaw = Flaw::None) {
  using namespace geomcheck;
  auto collide_fn = [flaw](const Cylinder& c, const Sphere& s) {
    const Touch<T> k = ref::collide<T>({mine<T>(c.p), mine<T>(c.q), T(c.r)}, {mine<T>(s.c), T(s.r)}, flaw);
    return Contact{k.hit, theirs(k.point), theirs(k.normal), double(k.depth)};
  };
  auto overlap_fn = [collide_fn](const Cylinder& c, const Sphere& s) { return collide_fn(c, s).hit; };
  return subject<QueryId::collide_cylinder_sphere>(name, overlap_fn, collide_fn,
                                                   claims_in<QueryId::collide_cylinder_sphere, T>());
}

/// The cast query's subject in T (with a flaw: a known-wrong sibling).
template <class T>
auto cast_subject(const char* name, Flaw flaw = Flaw::None) {
  using namespace geomcheck;
  auto cast_fn = [flaw](const Segment& s, const Cylinder& c) {
    return theirs(ref::cast<T>({mine<T>(s.a), mine<T>(s.b)}, {mine<T>(c.p), mine<T>(c.q), T(c.r)}, flaw));
  };
  return subject<QueryId::cast_segment_cylinder>(name, cast_fn, claims_in<QueryId::cast_segment_cylinder, T>());
}

// --- production as another engine sees the scene -----------------------------

/// Every double of a shape (shapes are plain doubles) through f.
template <class S, class F>
S map_doubles(const S& s, F f) {
  static_assert(std::is_trivially_copyable_v<S> && sizeof(S) % sizeof(double) == 0, "a shape of doubles");
  double a[sizeof(S) / sizeof(double)];
  std::memcpy(a, &s, sizeof s);
  for (double& x : a) x = f(x);
  S out;
  std::memcpy(&out, a, sizeof s);
  return out;
}
/// The input as a subject computing in T sees it: rounded to float, or (T
/// double) moved one ulp up (strictly monotone: distinct points stay
/// distinct).
template <class T>
double seen(double x) {
  if constexpr (sizeof(T) == sizeof(float)) return double(float(x));
  else return std::nextafter(x, INFINITY);
}
/// An output number as a subject computing in T gives it.
template <class T>
double given(double x) {
  return double(T(x));
}
template <class T>
geomcheck::Vec3 given(geomcheck::Vec3 v) {
  return {given<T>(v.x), given<T>(v.y), given<T>(v.z)};
}

/// Production of query Q, asked about the scene as seen in T, answering in
/// T. `stretch` != 1: a known-wrong sibling, every number of the first
/// shape (a cylinder, segment or moving sphere: points and radii) scaled by
/// it about the origin, so that it answers for a shape up to
/// (stretch - 1) * scale away.
template <geomcheck::QueryId Q, class T>
auto production_seen_in(const char* name, double stretch = 1) {
  using namespace geomcheck;
  using A = typename QueryTraits<Q>::ShapeA;
  using B = typename QueryTraits<Q>::ShapeB;
  const ImplOf<Q>& prod = production_of<Q>();
  auto a_of = [stretch](const A& a) { return map_doubles(a, [stretch](double x) { return seen<T>(x * stretch); }); };
  auto b_of = [](const B& b) { return map_doubles(b, seen<T>); };
  // The moved scene must still be a valid one: an axis shorter than float's
  // resolution collapses, and that scene is not stated.
  auto expresses = [a_of, b_of](const A& a, const B& b) { return is_valid(a_of(a)) && is_valid(b_of(b)); };
  if constexpr (QueryTraits<Q>::kind == QueryKind::Collide) {
    auto collide_fn = [prod, a_of, b_of](const A& a, const B& b) {
      Contact k = prod.collide(a_of(a), b_of(b));
      k.point = given<T>(k.point), k.normal = given<T>(k.normal), k.depth = given<T>(k.depth);
      return k;
    };
    auto overlap_fn = [prod, a_of, b_of](const A& a, const B& b) { return prod.overlap(a_of(a), b_of(b)); };
    return subject<Q>(name, overlap_fn, collide_fn, claims_in<Q, T>(), expresses);
  } else {
    auto answer = [prod, a_of, b_of](const A& a, const B& b) {
      CastHit h;
      if constexpr (QueryTraits<Q>::kind == QueryKind::Cast) h = prod.cast(a_of(a), b_of(b));
      else h = prod.sweep(a_of(a), b_of(b));
      h.t = given<T>(h.t), h.point = given<T>(h.point), h.normal = given<T>(h.normal);
      return h;
    };
    return subject<Q>(name, answer, claims_in<Q, T>(), expresses);
  }
}

}  // namespace ref
