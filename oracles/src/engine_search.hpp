// geomcheck — certified convex engine: the floating-point search (GJK, MPR,
// EPA), templated on the number type: double for the filter, double-double
// (106 bits, hardware speed, a double's range) for the first high-precision
// round, MPFR floats of about 128 and 384 binary digits where that does not
// decide or the scale is out of the double-double's range (and about 512
// for a pair still undecided).
//
// Nothing here is trusted: every answer is a candidate that the callers
// certify in interval arithmetic or in rationals.
#pragma once

#include <boost/multiprecision/mpfr.hpp>
#include <algorithm>
#include <cmath>
#include <array>
#include <type_traits>
#include <vector>

#include "engine_dd.hpp"
#include "engine_internal.hpp"

namespace geomcheck::oracle::search {

namespace mp = boost::multiprecision;
// MPFR with the limbs in place (no allocation): 131, 387 and 513 bits (the
// nearest boost makes of 39, 116 and 154 decimal digits), correctly
// rounded like cpp_bin_float and 5 to 13 times faster than it at these
// widths.
using HP128 = mp::number<mp::mpfr_float_backend<39, mp::allocate_stack>, mp::et_off>;
using HP384 = mp::number<mp::mpfr_float_backend<116, mp::allocate_stack>, mp::et_off>;
using HP512 = mp::number<mp::mpfr_float_backend<154, mp::allocate_stack>, mp::et_off>;

template <class T> inline T from_q(const Q& q) { return q.template convert_to<T>(); }
template <> inline double from_q<double>(const Q& q) { return mpq_get_d(q.backend().data()); }
inline Q exact_q(double x) { return to_q(x); }
template <class T> inline Q exact_q(const T& x) { return Q(x); }
using DD = dd::DD;
/// hi, then the rest: about 106 bits of q (q within the range of doubles).
template <> inline DD from_q<DD>(const Q& q) {
  const double hi = mpq_get_d(q.backend().data());
  if (!std::isfinite(hi) || hi == 0) return DD(hi);
  const Q rest = q - to_q(hi);
  return dd::quick_two_sum(hi, mpq_get_d(rest.backend().data()));
}
inline Q exact_q(const DD& x) { return to_q(x.hi) + to_q(x.lo); }

template <class T> constexpr int bits_of() { return std::numeric_limits<T>::digits; }

template <class T>
struct V3 {
  T x{}, y{}, z{};
};
template <class T> V3<T> operator+(const V3<T>& a, const V3<T>& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
template <class T> V3<T> operator-(const V3<T>& a, const V3<T>& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
template <class T> V3<T> operator-(const V3<T>& a) { return {-a.x, -a.y, -a.z}; }
template <class T> V3<T> operator*(const T& s, const V3<T>& a) { return {s * a.x, s * a.y, s * a.z}; }
template <class T> T dot(const V3<T>& a, const V3<T>& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
template <class T> V3<T> cross(const V3<T>& a, const V3<T>& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
template <class T> V3<T> from_q(const QVec& v) { return {from_q<T>(v.x), from_q<T>(v.y), from_q<T>(v.z)}; }
template <class T> QVec exact_q(const V3<T>& v) { return {exact_q(v.x), exact_q(v.y), exact_q(v.z)}; }
template <class T> bool is_zero(const V3<T>& v) { return v.x == 0 && v.y == 0 && v.z == 0; }

/// The shape in the search's number type.
template <class T>
struct ShapeT {
  const ConvexShape* src = nullptr;
  std::vector<V3<T>> pts;
  T radius{};
  V3<T> unit_axis;  // Disc
  V3<T> inner;
  ConvexShape::Round round = ConvexShape::Round::None;
};

template <class T>
ShapeT<T> convert(const ConvexShape& s) {
  ShapeT<T> out;
  out.src = &s;
  for (const QVec& p : s.points) out.pts.push_back(from_q<T>(p));
  out.radius = from_q<T>(s.radius);
  out.round = s.radius == 0 ? ConvexShape::Round::None : s.round;
  out.inner = from_q<T>(inner_point(s));
  if (s.round == ConvexShape::Round::Disc) {
    using std::sqrt;
    // Scale the axis to avoid overflow in its square, then normalise.
    V3<T> a = from_q<T>(s.axis);
    T m = std::max({abs(a.x), abs(a.y), abs(a.z)});
    a = (T(1) / m) * a;
    out.unit_axis = (T(1) / sqrt(dot(a, a))) * a;
  }
  return out;
}

/// A support point: core index (or -1: the inner point) and the radial unit
/// vector of the ball/disc part.
template <class T>
struct Sup {
  int i = -1;
  bool half = false;  // the midpoint of the inner point and this support point
  V3<T> w;
  V3<T> p;
};

template <class T>
Sup<T> support(const ShapeT<T>& s, const V3<T>& d) {
  using std::sqrt;
  Sup<T> out;
  out.i = 0;
  T best = dot(d, s.pts[0]);
  for (std::size_t k = 1; k < s.pts.size(); ++k) {
    T v = dot(d, s.pts[k]);
    if (v > best) { best = v; out.i = static_cast<int>(k); }
  }
  out.p = s.pts[out.i];
  if (s.round != ConvexShape::Round::None) {
    V3<T> e = d;
    if (s.round == ConvexShape::Round::Disc) e = d - dot(d, s.unit_axis) * s.unit_axis;
    T m = std::max({abs(e.x), abs(e.y), abs(e.z)});
    if (m > 0) {
      e = (T(1) / m) * e;
      // Once more: for d nearly along the axis the first projection leaves
      // an axial residue comparable to e itself.
      if (s.round == ConvexShape::Round::Disc) {
        e = e - dot(e, s.unit_axis) * s.unit_axis;
        m = std::max({abs(e.x), abs(e.y), abs(e.z)});
        if (!(m > 0)) return out;
        e = (T(1) / m) * e;
      }
      out.w = (T(1) / sqrt(dot(e, e))) * e;
      out.p = out.p + s.radius * out.w;
    }
  }
  return out;
}

/// Midpoint of the inner point and the support point along d: a point of
/// the relative interior when the inner point is in it.
template <class T>
Sup<T> half_sup(const ShapeT<T>& s, const V3<T>& d) {
  Sup<T> out = support(s, d);
  out.half = true;
  out.p = T(0.5) * (s.inner + out.p);
  return out;
}

template <class T>
Sup<T> inner_sup(const ShapeT<T>& s) {
  Sup<T> out;
  out.i = -1;
  out.p = s.inner;
  return out;
}

/// The support point built inside the shape, exactly: core point plus
/// radius * w, w projected onto the disc plane (disc) and shrunk to norm <= 1
/// (in doubles and double-double: radial_point_dyadic).
template <class T>
QVec sup_point_q(const ConvexShape& s, const Sup<T>& sp) {
  if (sp.i < 0) return inner_point(s);  // -1: the inner point
  if (sp.half) {
    Sup<T> full = sp;
    full.half = false;
    return Q(1, 2) * (inner_point(s) + sup_point_q(s, full));
  }
  QVec base = s.points[sp.i];
  if (s.round == ConvexShape::Round::None || s.radius == 0 || is_zero(sp.w)) return base;
  // A non-finite radial vector (a search gone astray on a degenerate pair:
  // a subnormal radius on an axis of 1e10) proposes nothing: the core point
  // is still a point of the shape, and the certificate decides.
  if (!(std::isfinite(static_cast<double>(sp.w.x)) && std::isfinite(static_cast<double>(sp.w.y)) &&
        std::isfinite(static_cast<double>(sp.w.z))))
    return base;
  if constexpr (std::is_same_v<T, DD> || std::is_same_v<T, double>) {
    // In integers where the data is dyadic (the common case).
    Vec3 hi, lo;
    if constexpr (std::is_same_v<T, DD>) {
      hi = {sp.w.x.hi, sp.w.y.hi, sp.w.z.hi};
      lo = {sp.w.x.lo, sp.w.y.lo, sp.w.z.lo};
    } else {
      hi = {sp.w.x, sp.w.y, sp.w.z};
    }
    if (std::optional<QVec> x = radial_point_dyadic(s, sp.i, hi, lo, bits_of<T>() + 8)) return *x;
  }
  QVec w = exact_q(sp.w);
  if (s.round == ConvexShape::Round::Disc) w = w - (dot(w, s.axis) / dot(s.axis, s.axis)) * s.axis;
  Q ww = dot(w, w);
  if (ww > 1) {
    const Q f = Q(1) - Q(1) / Q(mp::mpz_int(1) << (bits_of<T>() - 6));
    w = (f / sqrt_interval(ww).hi) * w;
  }
  return base + s.radius * w;
}

/// A vertex of the Minkowski difference A - B.
template <class T>
struct Vert {
  Sup<T> a, b;
  V3<T> w;
};
template <class T>
Vert<T> make_vert(const Sup<T>& a, const Sup<T>& b) {
  return {a, b, a.p - b.p};
}
template <class T>
Vert<T> support_vert(const ShapeT<T>& A, const ShapeT<T>& B, const V3<T>& d) {
  return make_vert(support(A, d), support(B, -d));
}

/// A simplex of at most four Minkowski vertices (no heap allocation).
template <class T>
struct Simplex {
  struct List {
    std::array<Vert<T>, 4> items;
    int n = 0;
    std::size_t size() const { return static_cast<std::size_t>(n); }
    bool empty() const { return n == 0; }
    void push_back(const Vert<T>& x) { items[n++] = x; }
    const Vert<T>& operator[](std::size_t i) const { return items[i]; }
    Vert<T>& operator[](std::size_t i) { return items[i]; }
    const Vert<T>* begin() const { return items.data(); }
    const Vert<T>* end() const { return items.data() + n; }
  } v;
  std::array<T, 4> lambda{};
  V3<T> closest;
};

/// Closest point of the simplex hull to the origin; keeps the minimal face.
/// Every face is tried (at most 15): the closest point of the hull is the
/// nearest of the faces whose affine closest point has positive weights.
template <class T>
void closest_point(Simplex<T>& s) {
  const int n = s.v.n;
  const T tiny = ldexp(T(1), -(bits_of<T>() - 8));
  bool have = false;
  T best_nn{};
  int best_mask = 0;
  std::array<T, 4> best_l{};
  V3<T> best_p;
  for (int mask = 1; mask < (1 << n); ++mask) {
    int idx[4] = {0, 0, 0, 0};
    int k = 0;
    for (int q = 0; q < n; ++q)
      if (mask >> q & 1) idx[k++] = q;
    const V3<T>& w0 = s.v[idx[0]].w;
    std::array<T, 4> lam{};
    V3<T> p = w0;
    if (k == 1) {
      lam[0] = 1;
    } else {
      // Gram system for mu (w = w0 + sum mu_j D_j).
      V3<T> D[3];
      for (int j = 1; j < k; ++j) D[j - 1] = s.v[idx[j]].w - w0;
      const int m = k - 1;
      T G[3][4];
      T diag = 1;
      for (int r = 0; r < m; ++r) {
        for (int c = 0; c < m; ++c) G[r][c] = dot(D[r], D[c]);
        G[r][m] = -dot(D[r], w0);
        diag *= G[r][r];
      }
      // Gaussian elimination with partial pivoting.
      bool ok = diag > 0;
      T det = 1;
      for (int c = 0; ok && c < m; ++c) {
        int piv = c;
        for (int r = c + 1; r < m; ++r)
          if (abs(G[r][c]) > abs(G[piv][c])) piv = r;
        if (G[piv][c] == 0) { ok = false; break; }
        if (piv != c)
          for (int q = 0; q <= m; ++q) std::swap(G[piv][q], G[c][q]);
        det *= G[c][c];
        for (int r = c + 1; r < m; ++r) {
          const T f = G[r][c] / G[c][c];
          for (int q = c; q <= m; ++q) G[r][q] -= f * G[c][q];
        }
      }
      if (!ok || !(abs(det) > tiny * diag)) continue;
      T mu[3];
      for (int r = m - 1; r >= 0; --r) {
        T acc = G[r][m];
        for (int q = r + 1; q < m; ++q) acc -= G[r][q] * mu[q];
        mu[r] = acc / G[r][r];
      }
      T sum = 0;
      bool pos = true;
      for (int j = 0; j < m; ++j) {
        lam[j + 1] = mu[j];
        sum += mu[j];
        if (!(mu[j] > 0)) pos = false;
      }
      lam[0] = 1 - sum;
      if (!(lam[0] > 0)) pos = false;
      if (!pos) continue;
      for (int j = 0; j < m; ++j) p = p + mu[j] * D[j];
    }
    const T nn = dot(p, p);
    if (!have || nn < best_nn) {
      have = true;
      best_nn = nn;
      best_mask = mask;
      best_l = lam;
      best_p = p;
    }
  }
  if (!have) {  // keep the newest point
    best_mask = 1 << (n - 1);
    best_l = {T(1)};
    best_p = s.v[n - 1].w;
  }
  typename Simplex<T>::List keep;
  for (int q = 0; q < n; ++q)
    if (best_mask >> q & 1) keep.push_back(s.v[q]);
  s.v = keep;
  s.lambda = best_l;
  s.closest = best_p;
}

enum class GjkStatus { Separated, Inside, Contact, MaxIter };

template <class T>
struct GjkOut {
  GjkStatus status = GjkStatus::MaxIter;
  /// v.w and v.v of the last iteration: v.w / |v| is a lower bound of the
  /// distance (the support of A - B along -v), |v| an upper bound.
  T vw{}, vv{};
  Simplex<T> simplex;
  int iterations = 0;
};

/// GJK on A - B. `contact` is the squared distance below which the origin is
/// taken to be on the simplex.
/// `width` (> 0): also stop once the distance is bracketed that tightly
/// (|v| - v.w / |v| <= width: GJK converges only linearly on curved shapes,
/// and a caller that wants the distance to 1e-20 * scale need not wait for
/// the last bits).
template <class T>
GjkOut<T> gjk(const ShapeT<T>& A, const ShapeT<T>& B, const T& contact2, int max_iter, bool early_out = false,
              int tol_bits = bits_of<T>() - 6, const T& width = T(0)) {
  GjkOut<T> out;
  Simplex<T>& s = out.simplex;
  V3<T> v = A.inner - B.inner;
  if (is_zero(v)) v = {T(1), T(0), T(0)};
  const T rel = ldexp(T(1), -tol_bits);
  const T stall_rel = ldexp(T(1), -(bits_of<T>() - 20));
  T best_vv = dot(v, v);
  int stalled = 0;
  for (int it = 0; it < max_iter; ++it) {
    out.iterations = it + 1;
    const Vert<T> x = support_vert(A, B, -v);
    const T vv = dot(v, v);
    if (early_out) {
      // v.w > 0: the plane normal to v already separates (h_{A-B}(-v) < 0),
      // with a margin well above the rounding of the search.
      const T vw = dot(v, x.w);
      if (vw > 0 && vw * vw > ldexp(T(1), -2 * (bits_of<T>() - 12)) * vv * dot(x.w, x.w)) {
        out.status = GjkStatus::Separated;
        s.closest = v;  // the separating direction is -v
        return out;
      }
    }
    out.vw = dot(v, x.w);
    out.vv = vv;
    if (!s.v.empty()) {
      const T gap = vv - dot(v, x.w);
      if (gap <= rel * vv) { out.status = GjkStatus::Separated; return out; }
      if (width > 0 && gap > 0 && gap * gap <= width * width * vv) { out.status = GjkStatus::Separated; return out; }
      bool dup = false;
      for (const auto& y : s.v) dup = dup || (y.w.x == x.w.x && y.w.y == x.w.y && y.w.z == x.w.z);
      if (dup) { out.status = GjkStatus::Separated; return out; }
    }
    s.v.push_back(x);
    closest_point(s);
    v = s.closest;
    if (s.v.size() == 4) { out.status = GjkStatus::Inside; return out; }
    const T nv = dot(v, v);
    if (nv <= contact2) { out.status = GjkStatus::Contact; return out; }
    // Stalled at the precision of T (|v| no longer shrinks: the closest
    // point's rounding, about eps |w|^2 / |v|, dominates the gap): more
    // iterations gain nothing; a finer T may.
    if (it > 0 && !(nv < best_vv * (T(1) - stall_rel))) {
      if (++stalled >= 8) break;
    } else {
      stalled = 0;
      best_vv = nv;
    }
  }
  out.status = GjkStatus::MaxIter;
  return out;
}

enum class MprStatus { Hit, Miss, Unknown };
template <class T>
struct MprOut {
  MprStatus status = MprStatus::Unknown;
  std::array<Vert<T>, 4> tet;  // Hit: origin inside (v0..v3)
  V3<T> dir;                   // Miss: h_{A-B}(dir) < 0 (candidate)
};

/// Minkowski portal refinement from the interior point inner(A) - inner(B).
template <class T>
MprOut<T> mpr(const ShapeT<T>& A, const ShapeT<T>& B, int max_iter) {
  MprOut<T> out;
  auto perpendicular = [](const V3<T>& a) {
    const V3<T> e = abs(a.x) <= abs(a.y) && abs(a.x) <= abs(a.z) ? V3<T>{T(1), T(0), T(0)}
                    : abs(a.y) <= abs(a.z)                      ? V3<T>{T(0), T(1), T(0)}
                                                                 : V3<T>{T(0), T(0), T(1)};
    return cross(a, e);
  };
  auto sup = [&](const V3<T>& d) { return support_vert(A, B, d); };
  auto miss = [&](const V3<T>& d) {
    out.status = MprStatus::Miss;
    out.dir = d;
    return out;
  };
  Vert<T> v0 = make_vert(inner_sup(A), inner_sup(B));
  Vert<T> v1;
  V3<T> dir;
  // The interior point v0 must not be the origin, and the first support
  // point must not lie on the line through v0 and the origin (symmetric
  // pairs): then move v0 half-way to a support point in a perpendicular
  // direction (still interior, now off the line).
  for (int attempt = 0; attempt < 3; ++attempt) {
    if (!is_zero(v0.w)) {
      dir = -v0.w;
      v1 = sup(dir);
      if (dot(v1.w, dir) <= 0) return miss(dir);
      dir = cross(v0.w, v1.w);
      const T tiny = ldexp(T(1), -(bits_of<T>() - 4));
      if (dot(dir, dir) > tiny * dot(v0.w, v0.w) * dot(v1.w, v1.w)) break;
      dir = V3<T>{};
    }
    V3<T> d = is_zero(v0.w) ? V3<T>{T(1), T(0), T(0)} : perpendicular(v0.w);
    if (attempt == 1) d = -d;
    v0 = make_vert(half_sup(A, d), half_sup(B, -d));
  }
  if (is_zero(dir) || is_zero(v0.w)) return out;
  Vert<T> v2 = sup(dir);
  if (dot(v2.w, dir) <= 0) return miss(dir);
  dir = cross(v1.w - v0.w, v2.w - v0.w);
  if (dot(dir, v0.w) > 0) {
    std::swap(v1, v2);
    dir = -dir;
  }
  Vert<T> v3;
  int it = 0;
  for (; it < max_iter; ++it) {
    v3 = sup(dir);
    if (dot(v3.w, dir) <= 0) return miss(dir);
    if (dot(cross(v1.w, v3.w), v0.w) < 0) {
      v2 = v3;
      dir = cross(v1.w - v0.w, v3.w - v0.w);
      continue;
    }
    if (dot(cross(v3.w, v2.w), v0.w) < 0) {
      v1 = v3;
      dir = cross(v3.w - v0.w, v2.w - v0.w);
      continue;
    }
    break;
  }
  const T rel = ldexp(T(1), -(bits_of<T>() - 8));
  for (; it < max_iter; ++it) {
    dir = cross(v2.w - v1.w, v3.w - v1.w);
    if (is_zero(dir)) return out;
    if (dot(v1.w, dir) >= 0) {
      out.status = MprStatus::Hit;
      out.tet = {v0, v1, v2, v3};
      return out;
    }
    const Vert<T> v4 = sup(dir);
    const T d4 = dot(v4.w, dir);
    if (d4 < 0) return miss(dir);
    if (d4 - dot(v3.w, dir) <= rel * abs(d4)) return out;  // portal converged at the origin
    const V3<T> c = cross(v4.w, v0.w);
    if (dot(v1.w, c) > 0) {
      if (dot(v2.w, c) > 0) v1 = v4; else v3 = v4;
    } else {
      if (dot(v3.w, c) > 0) v2 = v4; else v1 = v4;
    }
  }
  return out;
}

/// enclosing_tet's prefilter: det(q - p, r - p, t - p) in doubles.
inline double volume_d(const V3<double>& p, const V3<double>& q, const V3<double>& r, const V3<double>& t) {
  return dot(q - p, cross(r - p, t - p));
}
/// Its error bound, for doubles within a relative u = 2^-53 of exact points
/// whose coordinates are at most M in magnitude. To first order: the
/// differences (at most 2M) err by 4uM (the inputs' rounding and their own);
/// a cross product's components (at most 8M^2) by 48uM^2; the dot product's
/// three terms (at most 16M^3) by 144uM^3 each, and its two sums by 80uM^3:
/// about 512uM^3 = 2^-44 M^3 in all. The bound is 16 times that. Meant for M
/// between 2^-300 and 2^300 (no cube under- or overflows). Searched towards
/// in test_filters (Filters.TetVolume).
inline double volume_d_bound(double M) { return 0x1p-40 * M * M * M; }

/// Fallback for symmetric and degenerate pairs (the origin on an edge of
/// every portal, e.g. at the centre of the ball part of A - B): support
/// points along two tetrahedral frames, plus the given candidates; returns
/// the four whose tetrahedron holds the origin with the largest smallest
/// barycentric weight.
template <class T>
bool enclosing_tet(const ShapeT<T>& A, const ShapeT<T>& B, std::vector<Vert<T>> cand, std::array<Vert<T>, 4>& best) {
  const T one(1), z(0);
  const V3<T> dirs[8] = {{one, one, one},  {one, -one, -one}, {-one, one, -one}, {-one, -one, one},
                         {one, z, z},      {-one, z, z},      {z, one, z},       {z, z, one}};
  for (const auto& d : dirs) cand.push_back(support_vert(A, B, d));
  cand.push_back(make_vert(inner_sup(A), inner_sup(B)));
  const int n = static_cast<int>(cand.size());
  T best_score(0);
  bool found = false;
  auto vol = [](const V3<T>& a, const V3<T>& b, const V3<T>& c, const V3<T>& d) {
    return dot(b - a, cross(c - a, d - a));
  };
  const V3<T> o{};
  // A prefilter in doubles: a tetrahedron whose barycentric volumes
  // certainly have both signs cannot hold the origin (its smallest weight is
  // negative, so T's scores below would reject it too). The doubles are
  // within a relative 2^-53 of T's values (volume_d_bound).
  std::vector<V3<double>> wd;
  double M = 0;
  if constexpr (!std::is_same_v<T, double>) {
    for (const auto& v : cand) {
      wd.push_back({static_cast<double>(v.w.x), static_cast<double>(v.w.y), static_cast<double>(v.w.z)});
      M = std::max({M, std::abs(wd.back().x), std::abs(wd.back().y), std::abs(wd.back().z)});
    }
  }
  const bool prefilter = M > 0x1p-300 && M < 0x1p300;
  const double err = prefilter ? volume_d_bound(M) : 0.0;
  auto outside = [&](int i, int j, int k, int l) {
    const V3<double> od{};
    const V3<double>&a = wd[i], &b = wd[j], &c = wd[k], &d = wd[l];
    const double v[4] = {volume_d(od, b, c, d), volume_d(a, od, c, d), volume_d(a, b, od, d), volume_d(a, b, c, od)};
    bool pos = false, neg = false;
    for (double x : v) pos = pos || x > err, neg = neg || x < -err;
    return pos && neg;
  };
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j)
      for (int k = j + 1; k < n; ++k)
        for (int l = k + 1; l < n; ++l) {
          if (prefilter && outside(i, j, k, l)) continue;
          const V3<T>&a = cand[i].w, &b = cand[j].w, &c = cand[k].w, &d = cand[l].w;
          const T v = vol(a, b, c, d);
          // Flat (or repeated-vertex) tetrahedra: rounding-level volume.
          const T p2 = dot(b - a, b - a) * dot(c - a, c - a) * dot(d - a, d - a);
          if (!(v * v > ldexp(T(1), -2 * (bits_of<T>() - 16)) * p2)) continue;
          const T l0 = vol(o, b, c, d) / v, l1 = vol(a, o, c, d) / v, l2 = vol(a, b, o, d) / v,
                  l3 = vol(a, b, c, o) / v;
          const T m = std::min({l0, l1, l2, l3});
          if (m > best_score) {
            best_score = m;
            best = {cand[i], cand[j], cand[k], cand[l]};
            found = true;
          }
        }
  return found;
}

}  // namespace geomcheck::oracle::search
