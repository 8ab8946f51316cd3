// geomcheck — the body shared by every query's libFuzzer target.
//
// Input layout: byte 0 chooses the mode, the rest is the payload.
//   even: ROBUSTNESS. The payload is raw little-endian doubles
//         (decode_raw_doubles: shape A's doubles, then shape B's; missing
//         bytes are zero), any bit pattern: NaN, inf, subnormal, huge.
//         Property: check_robust (no crash, no UB, invalid input gives no
//         hit, finite output, unit normals).
//   odd:  DIFFERENTIAL on structured near-degenerate cases. The payload
//         drives FuzzedDataProvider: small-integer geometry (exact touches
//         at caps, rims and sides are common there), each coordinate nudged
//         by a few ulps, then exact moves (axis permutation, sign flips,
//         power-of-two scale). Property: check_all against the exact oracle.
// A failure prints the property, the case file and aborts, so libFuzzer
// keeps the input; `geomcheck from-fuzz QUERY CRASH` turns it into a case.
#pragma once

#include <fuzzer/FuzzedDataProvider.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "geomcheck/casefile.hpp"
#include "geomcheck/properties/checks.hpp"
#include "geomcheck/shape_traits.hpp"

namespace geomcheck::fuzz {

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

template <QueryId Q>
[[noreturn]] void report(const typename QueryTraits<Q>::Case& c, const Failure& f, const char* mode) {
  const CaseFile cf = from_case<Q>(c, std::string("fuzz ") + mode, "", f.property + ": " + f.detail);
  std::fprintf(stderr, "\n==== geomcheck %s property failed: %s\n%s\n---- case file:\n%s====\n", info(Q).name,
               f.property.c_str(), f.detail.c_str(), write_case(cf).c_str());
  std::abort();
}

template <QueryId Q>
int run_one(const std::uint8_t* data, std::size_t size) {
  using A = typename QueryTraits<Q>::ShapeA;
  using B = typename QueryTraits<Q>::ShapeB;
  using Case = typename QueryTraits<Q>::Case;
  if (size < 1) return 0;
  if ((data[0] & 1) == 0) {
    const auto v = decode_raw_doubles(data + 1, size - 1, ShapeTraits<A>::size + ShapeTraits<B>::size);
    const Case c{ShapeTraits<A>::from(v.data()), ShapeTraits<B>::from(v.data() + ShapeTraits<A>::size)};
    if (auto f = check_robust(c)) report<Q>(c, *f, "robustness");
    return 0;
  }
  FuzzedDataProvider p(data + 1, size - 1);
  const int perm = p.ConsumeIntegralInRange<int>(0, 2);
  const int flips = p.ConsumeIntegralInRange<int>(0, 7);
  const int e = p.ConsumeIntegralInRange<int>(-30, 30);
  const Case c{structured_shape<A>(p, perm, flips, e), structured_shape<B>(p, perm, flips, e)};
  if (!is_valid(c.a) || !is_valid(c.b)) return 0;
  if (auto f = check_all(c)) report<Q>(c, *f, "differential");
  return 0;
}

}  // namespace geomcheck::fuzz
