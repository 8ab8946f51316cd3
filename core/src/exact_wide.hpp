// geomcheck — internal: fixed-width exact integers for the 3D predicates'
// big-integer stage (predicates3d.cpp), where the coordinates, scaled to
// integers by one power of two, span at most 125 bits: the common case of
// arbitrary doubles of one order of magnitude (points on a sphere, whose
// in-sphere determinants the floating-point filters cannot decide). A
// determinant of degree k of such integers fits in a few 64-bit limbs, so
// it is computed in N limbs of two's complement, modulo 2^(64 N), which is
// exact when the caller has chosen N so that every intermediate value fits
// (`fits`); wider spans go to the arbitrary-precision stage.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>

namespace geomcheck::detail::exact_wide {

/// A signed integer in N 64-bit limbs, two's complement, arithmetic
/// modulo 2^(64 N).
template <int N>
struct Wide {
  std::uint64_t w[N];

  Wide() : w{} {}
  explicit Wide(__int128 v) {
    w[0] = static_cast<std::uint64_t>(v);
    w[1] = static_cast<std::uint64_t>(static_cast<unsigned __int128>(v) >> 64);
    const std::uint64_t fill = v < 0 ? ~std::uint64_t(0) : 0;
    for (int i = 2; i < N; ++i) w[i] = fill;
  }
  friend Wide operator+(const Wide& a, const Wide& b) {
    Wide r;
    unsigned __int128 carry = 0;
    for (int i = 0; i < N; ++i) {
      carry += static_cast<unsigned __int128>(a.w[i]) + b.w[i];
      r.w[i] = static_cast<std::uint64_t>(carry);
      carry >>= 64;
    }
    return r;
  }
  friend Wide operator-(const Wide& a, const Wide& b) {
    Wide r;
    unsigned __int128 carry = 1;  // a + ~b + 1
    for (int i = 0; i < N; ++i) {
      carry += static_cast<unsigned __int128>(a.w[i]) + ~b.w[i];
      r.w[i] = static_cast<std::uint64_t>(carry);
      carry >>= 64;
    }
    return r;
  }
  /// The negation modulo 2^(64 N).
  Wide operator-() const { return Wide() - *this; }
  /// The product modulo 2^(64 N) (the low N limbs). Computed on the
  /// magnitudes (a negative value's high limbs are all ones: its magnitude
  /// has as few limbs as the number), so a product of small values costs a
  /// few limb products, then signed.
  friend Wide operator*(const Wide& a, const Wide& b) {
    const bool na_neg = a.w[N - 1] >> 63, nb_neg = b.w[N - 1] >> 63;
    const Wide ma = na_neg ? -a : a, mb = nb_neg ? -b : b;
    int na = N, nb = N;  // zero high limbs contribute nothing
    while (na > 1 && ma.w[na - 1] == 0) --na;
    while (nb > 1 && mb.w[nb - 1] == 0) --nb;
    Wide r;
    for (int i = 0; i < na; ++i) {
      unsigned __int128 carry = 0;
      const int jend = N - i < nb ? N - i : nb;
      for (int j = 0; j < jend; ++j) {
        carry += static_cast<unsigned __int128>(ma.w[i]) * mb.w[j] + r.w[i + j];
        r.w[i + j] = static_cast<std::uint64_t>(carry);
        carry >>= 64;
      }
      if (i + jend < N) r.w[i + jend] = static_cast<std::uint64_t>(carry);  // above every earlier row's reach
    }
    return na_neg != nb_neg ? -r : r;
  }
  int sign() const {
    if (w[N - 1] >> 63) return -1;
    for (int i = 0; i < N; ++i)
      if (w[i] != 0) return 1;
    return 0;
  }
};

template <int N>
int sign_of(const Wide<N>& v) {
  return v.sign();
}

/// The coordinates as integers of one common scale 2^emin (emin the
/// lowest set bit among them), in __int128, and `bits`: every |integer| <
/// 2^bits. ok is false when they need more than 125 bits (a wider span of
/// exponents).
template <std::size_t M>
struct ScaledSmall {
  __int128 v[M];
  int bits = 0;
  bool ok = false;

  explicit ScaledSmall(const double (&xs)[M]) {
    std::uint64_t mant[M];
    int low[M];  // the exponent of each mantissa's unit
    int emin = 0, emax = 0;
    bool any = false;
    for (std::size_t i = 0; i < M; ++i) {
      mant[i] = 0, low[i] = 0;
      if (xs[i] == 0) continue;
      int ex;
      const double f = std::frexp(xs[i], &ex);  // |xs[i]| = |f| 2^ex < 2^ex
      mant[i] = static_cast<std::uint64_t>(std::ldexp(std::fabs(f), 53));  // exact: |f| in [0.5, 1)
      low[i] = ex - 53;
      const int lowest = low[i] + __builtin_ctzll(mant[i]);
      emin = any && emin < lowest ? emin : lowest;
      emax = any && emax > ex ? emax : ex;
      any = true;
    }
    bits = any ? emax - emin : 0;
    ok = bits <= 125;
    if (!ok) return;
    for (std::size_t i = 0; i < M; ++i) {
      v[i] = 0;
      if (mant[i] == 0) continue;
      const int shift = low[i] - emin;  // from -52 (only zero bits shifted out) to bits - 53
      const __int128 m = shift >= 0 ? static_cast<__int128>(mant[i]) << shift : static_cast<__int128>(mant[i] >> -shift);
      v[i] = xs[i] < 0 ? -m : m;
    }
  }
};

}  // namespace geomcheck::detail::exact_wide
