// geomcheck — internal: fixed-width exact integers for the 3D predicates'
// big-integer stage (predicates3d.cpp), where the coordinates, scaled to
// integers by one power of two, span at most 125 bits: the common case of
// arbitrary doubles of one order of magnitude (points on a sphere, every
// in-sphere determinant of which the floating-point filters cannot
// decide). Each step of a determinant has a width known when it is
// compiled (a difference 2 limbs, a 2x2 minor 4, a 3x3 minor 6, the
// in-sphere determinant 10), so the products are unrolled schoolbook
// multiplications of two's-complement limbs; wider spans go to the
// arbitrary-precision stage.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>

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
  int sign() const {
    if (w[N - 1] >> 63) return -1;
    for (int i = 0; i < N; ++i)
      if (w[i] != 0) return 1;
    return 0;
  }
};


/// a * b modulo 2^(64 NR), NR <= NA + NB: the unsigned product of the
/// limbs, then a negative operand's weight taken off (a = a_u - 2^(64 NA)
/// when negative, so a b = a_u b_u - 2^(64 NA) b_u - 2^(64 NB) a_u, the
/// product of the two weights vanishing modulo 2^(64 NR)).
template <int NR, int NA, int NB>
__attribute__((always_inline)) inline Wide<NR> mul(const Wide<NA>& a, const Wide<NB>& b) {
  static_assert(NR <= NA + NB, "a product has at most NA + NB limbs");
  Wide<NR> r;
  for (int i = 0; i < NA; ++i) {
    unsigned __int128 carry = 0;
    for (int j = 0; j < NB && i + j < NR; ++j) {
      carry += static_cast<unsigned __int128>(a.w[i]) * b.w[j] + r.w[i + j];
      r.w[i + j] = static_cast<std::uint64_t>(carry);
      carry >>= 64;
    }
    if (i + NB < NR) r.w[i + NB] = static_cast<std::uint64_t>(carry);
  }
  auto take_shifted = [&r](const std::uint64_t* x, int nx, int shift) {  // r -= x 2^(64 shift)
    unsigned __int128 borrow = 0;
    for (int k = shift; k < NR; ++k) {
      const std::uint64_t xk = k - shift < nx ? x[k - shift] : 0;
      const unsigned __int128 d = static_cast<unsigned __int128>(r.w[k]) - xk - borrow;
      r.w[k] = static_cast<std::uint64_t>(d);
      borrow = (d >> 64) & 1;
    }
  };
  if (a.w[NA - 1] >> 63) take_shifted(b.w, NB, NA);
  if (b.w[NB - 1] >> 63) take_shifted(a.w, NA, NB);
  return r;
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
    int low[M];  // the exponent of each mantissa's unit: |xs[i]| = mant[i] 2^low[i]
    int emin = 0, emax = 0;
    bool any = false;
    for (std::size_t i = 0; i < M; ++i) {
      std::uint64_t u;
      std::memcpy(&u, &xs[i], sizeof u);
      const int field = static_cast<int>((u >> 52) & 0x7FF);
      const std::uint64_t frac = u & ((std::uint64_t(1) << 52) - 1);
      mant[i] = field == 0 ? frac : frac | (std::uint64_t(1) << 52);  // subnormal, or the hidden bit
      low[i] = field == 0 ? -1074 : field - 1075;
      if (mant[i] == 0) continue;
      const int top = low[i] + 64 - __builtin_clzll(mant[i]);  // |xs[i]| < 2^top
      const int lowest = low[i] + __builtin_ctzll(mant[i]);
      emin = any && emin < lowest ? emin : lowest;
      emax = any && emax > top ? emax : top;
      any = true;
    }
    bits = any ? emax - emin : 0;
    ok = bits <= 125;
    if (!ok) return;
    for (std::size_t i = 0; i < M; ++i) {
      v[i] = 0;
      if (mant[i] == 0) continue;
      const int shift = low[i] - emin;  // from -52 (only zero bits shifted out) to bits - 1
      const __int128 m = shift >= 0 ? static_cast<__int128>(mant[i]) << shift : static_cast<__int128>(mant[i] >> -shift);
      v[i] = xs[i] < 0 ? -m : m;
    }
  }
};

}  // namespace geomcheck::detail::exact_wide
