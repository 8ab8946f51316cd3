// geomcheck — libFuzzer target for delaunay_2d.
//
// Input: byte 0 chooses the mode.
//   0 (RAW, as fuzz_input_from_point_set writes): then each point as two
//     8-byte little-endian doubles (any bit pattern; a trailing partial
//     point is dropped).
//   1..255 (STRUCTURED, mode % 5): near-degenerate point sets built from the
//     remaining bytes:
//     0: an integer grid (up to 16 x 16, points kept by a bit mask);
//     1: points on one line, k * (dx, dy) + (ox, oy);
//     2: the integer points of a circle of radius 5, 25 or 65, and its centre;
//     3: a few base points repeated;
//     4: small integers;
//     then every coordinate is nudged by -3..3 ulps (or not), and the set is
//     scaled by 2^e with e from -1070 to 1000, point by point when the mode
//     byte's top bit is set (mixing huge and tiny).
// Checks: the family's (properties/pointset_checks.hpp): a non-finite
// coordinate gives DelaunayInputError naming the first bad index; otherwise
// no exception, and the exact validity checker (oracles/delaunay_2d.hpp,
// CGAL's exact predicates) accepts the result; for sets of at most 300
// points the triangles also agree with CGAL's Delaunay_triangulation_2 up to
// cocircular choices. A failure prints the
// point set as a case file and aborts; the crash input replays with this
// binary.
#include <fuzzer/FuzzedDataProvider.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "geomcheck/delaunay_2d.hpp"
#include "geomcheck/fuzz_decode.hpp"
#include "geomcheck/properties/pointset_checks.hpp"
#include "geomcheck/pointset_file.hpp"

namespace {
using geomcheck::Vec2;

[[noreturn]] void fail(const std::vector<Vec2>& p, const std::string& why) {
  geomcheck::PointSetFile f;
  f.points = p;
  f.found_by = "fuzz fuzz_delaunay_2d";
  f.note = why;
  std::fprintf(stderr, "fuzz_delaunay_2d: %s\n%s", why.c_str(), geomcheck::write_point_set(f).c_str());
  std::abort();
}

std::vector<Vec2> structured(std::uint8_t mode, FuzzedDataProvider& in) {
  std::vector<Vec2> p;
  switch (mode % 5) {
    case 0: {
      const int w = in.ConsumeIntegralInRange(1, 16), h = in.ConsumeIntegralInRange(1, 16);
      const std::uint64_t mask = in.ConsumeIntegral<std::uint64_t>();
      for (int i = 0; i < w; ++i)
        for (int j = 0; j < h; ++j)
          if (mask == 0 || ((mask >> ((i * h + j) % 64)) & 1)) p.push_back({double(i), double(j)});
      break;
    }
    case 1: {
      const int dx = in.ConsumeIntegralInRange(-9, 9), dy = in.ConsumeIntegralInRange(-9, 9);
      const double ox = in.ConsumeIntegralInRange(-100, 100) * 0.125, oy = in.ConsumeIntegralInRange(-100, 100) * 0.125;
      const int k = in.ConsumeIntegralInRange(2, 40);
      for (int i = 0; i < k; ++i) {
        const int t = in.ConsumeIntegralInRange(-500, 500);
        p.push_back({ox + t * dx, oy + t * dy});
      }
      break;
    }
    case 2: {
      const int radii[] = {5, 25, 65};
      const int r = radii[in.ConsumeIntegralInRange(0, 2)];
      for (int x = -r; x <= r; ++x)
        for (int y = -r; y <= r; ++y)
          if (x * x + y * y == r * r && in.ConsumeIntegralInRange(0, 3) != 0) p.push_back({double(x), double(y)});
      p.push_back({0, 0});
      break;
    }
    case 3: {
      Vec2 base[4];
      for (Vec2& b : base) b = {in.ConsumeIntegralInRange(-20, 20) * 0.5, in.ConsumeIntegralInRange(-20, 20) * 0.5};
      const int k = in.ConsumeIntegralInRange(1, 40);
      for (int i = 0; i < k; ++i) p.push_back(base[in.ConsumeIntegralInRange(0, 3)]);
      break;
    }
    default: {
      const int k = in.ConsumeIntegralInRange(0, 60);
      for (int i = 0; i < k; ++i)
        p.push_back({double(in.ConsumeIntegralInRange(-8, 8)), double(in.ConsumeIntegralInRange(-8, 8))});
      break;
    }
  }
  if (in.ConsumeBool())
    for (Vec2& q : p) {
      q.x = geomcheck::fuzz::nudge(q.x, in.ConsumeIntegralInRange(-3, 3));
      q.y = geomcheck::fuzz::nudge(q.y, in.ConsumeIntegralInRange(-3, 3));
    }
  const bool per_point = (mode & 0x80) != 0;
  int e = in.ConsumeIntegralInRange(-1070, 1000);
  for (Vec2& q : p) {
    if (per_point) e = in.ConsumeBool() ? in.ConsumeIntegralInRange(900, 1000) : in.ConsumeIntegralInRange(-1070, -900);
    q = {std::ldexp(q.x, e), std::ldexp(q.y, e)};
  }
  return p;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  std::vector<Vec2> p;
  if (data[0] == 0) {
    for (std::size_t off = 1; off + 16 <= size; off += 16) {
      double x, y;
      std::memcpy(&x, data + off, 8);
      std::memcpy(&y, data + off + 8, 8);
      p.push_back({x, y});
    }
  } else {
    FuzzedDataProvider in(data + 1, size - 1);
    p = structured(data[0], in);
  }
  // The family's checks, written once (pointset_checks.hpp); CGAL for sets
  // of at most 300 points.
  const geomcheck::PointSetOutcome o = geomcheck::check_point_set(p, geomcheck::production_point_set(), 300, false);
  if (o.failure) fail(p, o.failure->property + ": " + o.failure->detail);
  return 0;
}
