// geomcheck — the bit pattern of a double and back (internal to corpora/).
#pragma once

#include <cstdint>
#include <cstring>

namespace geomcheck::detail {

inline std::uint64_t bits_of(double v) {
  std::uint64_t u;
  std::memcpy(&u, &v, sizeof u);
  return u;
}

inline double from_bits(std::uint64_t u) {
  double v;
  std::memcpy(&v, &u, sizeof v);
  return v;
}

}  // namespace geomcheck::detail
