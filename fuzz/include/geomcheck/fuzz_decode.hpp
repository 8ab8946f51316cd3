// geomcheck — decoding a fuzz input into a case of a registered query.
//
// Input layout: byte 0 chooses the mode, the rest is the payload.
//   even: RAW. The payload is raw little-endian doubles (decode_raw_doubles:
//         shape A's doubles, then shape B's; missing bytes are zero), any bit
//         pattern: NaN, inf, subnormal, huge. Used for robustness.
//   odd:  STRUCTURED near-degenerate cases. The payload drives
//         FuzzedDataProvider: small-integer geometry (exact touches at caps,
//         rims and sides are common there), each coordinate nudged by a few
//         ulps, then exact moves (axis permutation, sign flips, power-of-two
//         scale). Used for the differential check against the oracle.
//         A box's axes are never drawn as values: they come from a fixed
//         table of orthonormal frames (table_frame), are permuted and
//         flipped with the scene but never scaled; only its centre and
//         extents are scaled. A triangle's vertices are drawn like any
//         values, then half of the time put in a special position
//         (repeated vertex, point, collinear, in a coordinate plane, an
//         edge along an axis; structured_shape<Triangle>).
// The fuzz targets and `geomcheck from-fuzz` both decode with this header,
// so a crash file always turns into the case the target saw.
#pragma once

#include <fuzzer/FuzzedDataProvider.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <optional>

#include "geomcheck/casefile.hpp"
#include "geomcheck/shape_traits.hpp"

namespace geomcheck::fuzz {

/// Which decoding an input selects.
enum class Mode { Raw, Structured };

inline Mode mode_of(const std::uint8_t* data, std::size_t size) {
  return size > 0 && (data[0] & 1) ? Mode::Structured : Mode::Raw;
}

/// v moved by k ulps (towards +inf for k > 0).
inline double nudge(double v, int k) {
  for (; k > 0; --k) v = std::nextafter(v, INFINITY);
  for (; k < 0; ++k) v = std::nextafter(v, -INFINITY);
  return v;
}

inline double structured_value(FuzzedDataProvider& p) {
  // Halves of small integers, nudged by up to 4 ulps.
  const double v = 0.5 * p.ConsumeIntegralInRange<int>(-40, 40);
  return nudge(v, p.ConsumeIntegralInRange<int>(-4, 4));
}

/// Every value of a shape drawn, then exact moves applied field by field.
template <class S>
S structured_fields(FuzzedDataProvider& p, int perm, int flips, int e) {
  double v[ShapeTraits<S>::size];
  for (auto& x : v) x = structured_value(p);
  // Exact moves applied field by field: vectors permuted and flipped, all scaled.
  std::size_t i = 0;
  for (const auto& f : ShapeTraits<S>::fields) {
    if (f.arity == 3) {
      double w[3] = {v[i + perm % 3], v[i + (perm + 1) % 3], v[i + (perm + 2) % 3]};
      for (int j = 0; j < 3; ++j) v[i + j] = std::ldexp((flips >> j) & 1 ? -w[j] : w[j], e);
    } else {
      v[i] = std::ldexp(std::fabs(v[i]), e);  // radii and extents
    }
    i += f.arity;
  }
  return ShapeTraits<S>::from(v);
}

/// Any shape but a box or a triangle (see the specialisations below):
/// structured_fields.
template <class S>
S structured_shape(FuzzedDataProvider& p, int perm, int flips, int e) {
  return structured_fields<S>(p, perm, flips, e);
}

/// Number of rotations table_frame knows (index 0 is the identity).
inline constexpr int kNumTableRotations = 25;

/// An orthonormal box frame from a fixed table: the columns of P R1 R2, P
/// the signed permutation (perm 0..5 of the coordinates, signs 0..7: either
/// handedness), R1 and R2 rotations by index: 0 the identity, 1..24 about
/// coordinate axis (i-1)/8 by a 3-4-5 (((i-1)/4)%2 == 0) or 5-12-13 angle
/// with (cos, sin) = (a, b), (b, a), (a, -b), (b, -a) over c for (i-1)%4.
/// Every entry is an integer over the product of the denominators, rounded
/// once: signed permutations are exact, one rotation is exactly orthogonal
/// with unit lengths to rounding, products of two are orthonormal to a few
/// eps (inside production's 16 eps contract).
inline std::array<Vec3, 3> table_frame(int perm, int signs, int r1, int r2) {
  struct Rot {
    long m[3][3];
    long den;
  };
  const auto rotation = [](int index) {
    Rot r{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, 1};
    if (index <= 0 || index >= kNumTableRotations) return r;
    static constexpr long kTriples[2][3] = {{3, 4, 5}, {5, 12, 13}};
    const int axis = (index - 1) / 8, tr = ((index - 1) / 4) % 2, var = (index - 1) % 4;
    const long a = kTriples[tr][0], b = kTriples[tr][1], c = kTriples[tr][2];
    const long co = var % 2 == 0 ? a : b;
    const long si = (var % 2 == 0 ? b : a) * (var >= 2 ? -1 : 1);
    const int j = (axis + 1) % 3, k = (axis + 2) % 3;
    r = Rot{{{0, 0, 0}, {0, 0, 0}, {0, 0, 0}}, c};
    r.m[axis][axis] = c;
    r.m[j][j] = co;
    r.m[j][k] = -si;
    r.m[k][j] = si;
    r.m[k][k] = co;
    return r;
  };
  const Rot x = rotation(r1), y = rotation(r2);
  Rot r{{{0, 0, 0}, {0, 0, 0}, {0, 0, 0}}, x.den * y.den};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) r.m[i][j] += x.m[i][k] * y.m[k][j];
  static constexpr int kPerms[6][3] = {{0, 1, 2}, {1, 2, 0}, {2, 0, 1}, {0, 2, 1}, {2, 1, 0}, {1, 0, 2}};
  perm = ((perm % 6) + 6) % 6;
  std::array<Vec3, 3> axes;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const double v = double(r.m[kPerms[perm][j]][i]) / double(r.den);
      axes[i][j] = (signs >> j) & 1 ? -v : v;
    }
  return axes;
}

/// Boxes: centre and extents from structured values (extents >= 0), the
/// axes from table_frame chosen by the input; then the scene's exact moves:
/// the centre and every axis permuted and flipped alike (a signed
/// permutation of an orthonormal frame stays orthonormal), the centre and
/// the extents scaled by 2^e, the axes never scaled. The extents stay with
/// their axes.
template <>
inline Obb structured_shape<Obb>(FuzzedDataProvider& p, int perm, int flips, int e) {
  const auto move = [&](Vec3 v, bool scale) {
    Vec3 w{v[perm % 3], v[(perm + 1) % 3], v[(perm + 2) % 3]};
    for (int j = 0; j < 3; ++j) {
      if ((flips >> j) & 1) w[j] = -w[j];
      if (scale) w[j] = std::ldexp(w[j], e);
    }
    return w;
  };
  Obb b;
  const Vec3 c{structured_value(p), structured_value(p), structured_value(p)};
  const Vec3 ext{std::fabs(structured_value(p)), std::fabs(structured_value(p)), std::fabs(structured_value(p))};
  const int kind = p.ConsumeIntegralInRange<int>(0, 2);  // a signed permutation, times one or two rotations
  const int fperm = p.ConsumeIntegralInRange<int>(0, 5);
  const int fsigns = p.ConsumeIntegralInRange<int>(0, 7);
  const int r1 = kind >= 1 ? p.ConsumeIntegralInRange<int>(1, kNumTableRotations - 1) : 0;
  const int r2 = kind == 2 ? p.ConsumeIntegralInRange<int>(1, kNumTableRotations - 1) : 0;
  const std::array<Vec3, 3> frame = table_frame(fperm, fsigns, r1, r2);
  b.c = move(c, true);
  for (int i = 0; i < 3; ++i) b.axes[i] = move(frame[i], false);
  b.e = {std::ldexp(ext.x, e), std::ldexp(ext.y, e), std::ldexp(ext.z, e)};
  return b;
}

/// Triangles: the vertices as for any shape (structured_fields), then, by one
/// more byte, half of the time a special position that independent vertices
/// would almost never take:
///   6, 11  a repeated vertex (b = a: the triangle is its segment ac; c = b:
///          its segment ab);
///   7      a point triangle (b = c = a);
///   8      c on the line ab: the rounded a + t (b - a), t in {1/2, 2, -1}
///          (collinear, or within rounding of it);
///   9      all three vertices in one coordinate plane (parallel to the caps
///          of an axis-aligned cylinder);
///   10     the edge ab parallel to a coordinate axis.
/// They are made after the scene's exact moves (copying coordinates commutes
/// with them). An exhausted input gives the vertices as drawn.
template <>
inline Triangle structured_shape<Triangle>(FuzzedDataProvider& p, int perm, int flips, int e) {
  Triangle t = structured_fields<Triangle>(p, perm, flips, e);
  const int kind = p.ConsumeIntegralInRange<int>(0, 11);
  const int k = p.ConsumeIntegralInRange<int>(0, 2);  // a coordinate, or which t
  switch (kind) {
    case 6: t.b = t.a; break;
    case 7: t.b = t.a, t.c = t.a; break;
    case 8: {
      static constexpr double kT[3] = {0.5, 2.0, -1.0};
      t.c = t.a + kT[k] * (t.b - t.a);
      break;
    }
    case 9: t.b[k] = t.a[k], t.c[k] = t.a[k]; break;
    case 10: {
      const double keep = t.b[k];
      t.b = t.a;
      t.b[k] = keep;
      break;
    }
    case 11: t.c = t.b; break;
    default: break;  // 0..5: as drawn
  }
  return t;
}

/// The case an input of query Q's fuzz target stands for.
template <QueryId Q>
typename QueryTraits<Q>::Case decode(const std::uint8_t* data, std::size_t size) {
  using A = typename QueryTraits<Q>::ShapeA;
  using B = typename QueryTraits<Q>::ShapeB;
  const std::uint8_t* payload = size > 0 ? data + 1 : data;
  const std::size_t n = size > 0 ? size - 1 : 0;
  if (mode_of(data, size) == Mode::Raw) {
    const auto v = decode_raw_doubles(payload, n, ShapeTraits<A>::size + ShapeTraits<B>::size);
    return {ShapeTraits<A>::from(v.data()), ShapeTraits<B>::from(v.data() + ShapeTraits<A>::size)};
  }
  FuzzedDataProvider p(payload, n);
  const int perm = p.ConsumeIntegralInRange<int>(0, 2);
  const int flips = p.ConsumeIntegralInRange<int>(0, 7);
  const int e = p.ConsumeIntegralInRange<int>(-30, 30);
  A a = structured_shape<A>(p, perm, flips, e);
  B b = structured_shape<B>(p, perm, flips, e);
  return {a, b};
}

/// The same, as a case file (found_by names the input's SHA-1 and mode).
inline CaseFile case_from_input(QueryId q, const std::uint8_t* data, std::size_t size, const std::string& artifact = {}) {
  if (mode_of(data, size) == Mode::Raw) {
    CaseFile f = case_from_fuzz_input(q, size > 0 ? data + 1 : data, size > 0 ? size - 1 : 0, artifact);
    if (artifact.empty()) f.found_by = "fuzz sha1=" + sha1_hex(data, size);  // of the whole input, as libFuzzer names it
    f.found_by += " mode=raw";
    return f;
  }
  return visit_query(q, [&](auto qc) {
    constexpr QueryId Q = decltype(qc)::value;
    const std::string who = artifact.empty() ? "sha1=" + sha1_hex(data, size) : artifact;
    return from_case<Q>(decode<Q>(data, size),
                        "fuzz " + who + (mode_of(data, size) == Mode::Raw ? " mode=raw" : " mode=structured"));
  });
}

/// A raw-mode fuzz input for a case file (mode byte 0, then the doubles).
inline std::vector<std::uint8_t> raw_input(const CaseFile& c) {
  std::vector<std::uint8_t> out{0};
  const auto bytes = fuzz_input_from_case(c);
  out.insert(out.end(), bytes.begin(), bytes.end());
  return out;
}

}  // namespace geomcheck::fuzz
