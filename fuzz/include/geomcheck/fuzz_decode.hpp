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
// The fuzz targets and `geomcheck from-fuzz` both decode with this header,
// so a crash file always turns into the case the target saw.
#pragma once

#include <fuzzer/FuzzedDataProvider.h>

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

inline double structured_value(FuzzedDataProvider& p) {
  // Halves of small integers, nudged by up to 4 ulps.
  double v = 0.5 * p.ConsumeIntegralInRange<int>(-40, 40);
  int k = p.ConsumeIntegralInRange<int>(-4, 4);
  for (; k > 0; --k) v = std::nextafter(v, INFINITY);
  for (; k < 0; ++k) v = std::nextafter(v, -INFINITY);
  return v;
}

template <class S>
S structured_shape(FuzzedDataProvider& p, int perm, int flips, int e) {
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
