// geomcheck — internal: the last exact stage of the predicates
// (predicates2d.cpp, predicates3d.cpp): big integers on the coordinates
// scaled to integers by one power of two.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>

// Boost's big integers (the last exact stage) without coverage
// instrumentation under clang (the fuzz builds): libFuzzer is steered by
// this file's own branches, not by the limb loops of a third-party
// multiplication, which would otherwise dominate a fuzz run's time on
// huge-beside-tiny inputs. The sanitizers stay on.
#if defined(__clang__)
#pragma clang diagnostic push
#pragma clang diagnostic ignored "-Wignored-attributes"
#pragma clang attribute push(__attribute__((no_sanitize("coverage"))), apply_to = function)
#endif
#include <boost/multiprecision/cpp_int.hpp>
#if defined(__clang__)
#pragma clang attribute pop
#pragma clang diagnostic pop
#endif

namespace geomcheck::detail::exact_integers {

// ---- the last stage: every finite double is m * 2^e with an integer m of
// at most 53 bits; scaled by 2^-emin (the smallest exponent among the
// inputs) every coordinate is an integer, and the determinants, being
// homogeneous, keep their signs. Integer arithmetic, no normalisation.
//
// Width: a scaled coordinate is below 2^53 * 2^(1024 - 53 + 1126) = 2^2150
// (the largest exponent against the smallest subnormal's), a difference
// below 2^2151, a lift or a minor below 2^4303 and the in-circle
// determinant below 2^8608 (orient3d's below 2^6456). The integers keep
// 8704 bits in place, so no operation of the 2D predicates or of orient3d
// allocates (in-sphere's determinant, of degree 5, may: up to 2^10760); they are boost's arbitrary-precision integers all
// the same (the fixed-width variant trips an assertion in boost 1.74's
// subtraction), so a wider value would allocate, not wrap.
using Int = boost::multiprecision::number<
    boost::multiprecision::cpp_int_backend<8704, 0, boost::multiprecision::signed_magnitude,
                                           boost::multiprecision::unchecked, std::allocator<boost::multiprecision::limb_type>>>;

inline int sign_of(const Int& q) { return q > 0 ? 1 : (q < 0 ? -1 : 0); }

// The coordinates as integers, in place: no heap block per call (the
// integers are 1088 bytes each; a vector of them was an allocation of
// several kilobytes on every call of this stage).
template <std::size_t N>
class Scaled {
 public:
  explicit Scaled(const double (&xs)[N]) {
    int emin = 0;
    bool any = false;
    for (double x : xs) {
      if (x == 0) continue;
      int ex;
      std::frexp(x, &ex);
      emin = any ? std::min(emin, ex - 53) : ex - 53;
      any = true;
    }
    for (std::size_t i = 0; i < N; ++i) {
      const double x = xs[i];
      if (x == 0) continue;  // v_[i] is 0 already
      int ex;
      const double f = std::frexp(x, &ex);
      // The magnitude is shifted, then signed.
      Int& m = v_[i];
      m = static_cast<long long>(std::ldexp(std::fabs(f), 53));  // exact: |f| in [0.5, 1)
      m <<= (ex - 53 - emin);
      if (f < 0) m = -m;
    }
  }
  const Int& operator[](std::size_t i) const { return v_[i]; }

 private:
  std::array<Int, N> v_{};
};

}  // namespace geomcheck::detail::exact_integers
