#include "common.hpp"

namespace geomcheck::gen {

using namespace detail;

rc::Gen<double> real(double lo, double hi) {
  return rc::gen::map(rc::gen::inRange<std::int64_t>(0, std::int64_t(1) << 52), [lo, hi](std::int64_t k) {
    return lo + (hi - lo) * std::ldexp(double(k), -52);
  });
}

double nudge(double v, int k) {
  for (; k > 0; --k) v = std::nextafter(v, INFINITY);
  for (; k < 0; ++k) v = std::nextafter(v, -INFINITY);
  return v;
}

rc::Gen<double> wild_double() {
  return rc::gen::resize(100, rc::gen::exec([]() -> double {
    switch (pick_int(0, 9)) {
      case 0: return std::numeric_limits<double>::quiet_NaN();
      case 1: return pick_int(0, 1) ? INFINITY : -INFINITY;
      case 2: return std::ldexp(double(pick_int(-1000, 1000)), -1074);          // subnormal
      case 3: return pick_int(0, 1) ? 0.0 : -0.0;
      case 4: {  // huge
        const int e = pick_int(900, 1023);
        return std::ldexp(pick_real(-1, 1), e);
      }
      case 5: {  // tiny
        const int e = pick_int(-1022, -900);
        return std::ldexp(pick_real(-1, 1), e);
      }
      case 6: return std::numeric_limits<double>::max() * (pick_int(0, 1) ? 1 : -1);
      default: return pick_real(-10, 10);
    }
  }));
}

}  // namespace geomcheck::gen
