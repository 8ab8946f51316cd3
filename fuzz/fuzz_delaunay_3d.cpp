// geomcheck — libFuzzer target for delaunay_3d.
//
// Input: byte 0 chooses the mode.
//   0 (RAW): then each point as three 8-byte little-endian doubles (any bit
//     pattern; a trailing partial point is dropped).
//   1..255 (STRUCTURED, mode % 6): near-degenerate point sets built from the
//     remaining bytes:
//     0: an integer grid (up to 6 x 6 x 6, points kept by a bit mask; every
//        cube's corners cospherical);
//     1: points on one line, t * (dx, dy, dz) + o;
//     2: integer points of the sphere |p|^2 = 3, 50 or 325, and its centre;
//     3: a few base points repeated;
//     4: small integers;
//     5: integer points of the plane a x + b y + c z = d (c = 1), and one off it or none;
//     then every coordinate is nudged by -3..3 ulps (or not), and the set is
//     scaled by 2^e with e from -1070 to 1000, point by point when the mode
//     byte's top bit is set (mixing huge and tiny).
// Checks: a non-finite coordinate gives DelaunayInputError naming the first
// bad index; otherwise no exception, the exact validity checker
// (oracles/delaunay_3d.hpp, CGAL's exact predicates) accepts the
// tetrahedra, and the reversed input gives the same tetrahedra (relabelled).
// A failure prints the points (hex floats) and aborts; the crash input
// replays with this binary.
#include <fuzzer/FuzzedDataProvider.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "geomcheck/delaunay_3d.hpp"
#include "geomcheck/fuzz_decode.hpp"
#include "geomcheck/oracles/delaunay_3d.hpp"

namespace {
using geomcheck::Vec3;

[[noreturn]] void fail(const std::vector<Vec3>& p, const std::string& why) {
  std::fprintf(stderr, "fuzz_delaunay_3d: %s\n%zu points:\n", why.c_str(), p.size());
  for (const Vec3& q : p) std::fprintf(stderr, "%a %a %a\n", q.x, q.y, q.z);
  std::abort();
}

std::vector<Vec3> structured(std::uint8_t mode, FuzzedDataProvider& in) {
  std::vector<Vec3> p;
  switch (mode % 6) {
    case 0: {
      const int w = in.ConsumeIntegralInRange(1, 6), h = in.ConsumeIntegralInRange(1, 6), d = in.ConsumeIntegralInRange(1, 6);
      const std::uint64_t mask = in.ConsumeIntegral<std::uint64_t>();
      for (int i = 0; i < w; ++i)
        for (int j = 0; j < h; ++j)
          for (int k = 0; k < d; ++k)
            if (mask == 0 || ((mask >> ((i * 36 + j * 6 + k) % 64)) & 1)) p.push_back({double(i), double(j), double(k)});
      break;
    }
    case 1: {
      const int dx = in.ConsumeIntegralInRange(-9, 9), dy = in.ConsumeIntegralInRange(-9, 9), dz = in.ConsumeIntegralInRange(-9, 9);
      const Vec3 o{in.ConsumeIntegralInRange(-100, 100) * 0.125, in.ConsumeIntegralInRange(-100, 100) * 0.125,
                   in.ConsumeIntegralInRange(-100, 100) * 0.125};
      const int k = in.ConsumeIntegralInRange(2, 40);
      for (int i = 0; i < k; ++i) {
        const int t = in.ConsumeIntegralInRange(-500, 500);
        p.push_back({o.x + t * dx, o.y + t * dy, o.z + t * dz});
      }
      break;
    }
    case 2: {
      const int r2s[] = {3, 50, 325};
      const int r2 = r2s[in.ConsumeIntegralInRange(0, 2)];
      for (int x = -18; x <= 18; ++x)
        for (int y = -18; y <= 18; ++y)
          for (int z = -18; z <= 18; ++z)
            if (x * x + y * y + z * z == r2 && in.ConsumeIntegralInRange(0, 3) != 0)
              p.push_back({double(x), double(y), double(z)});
      p.push_back({0, 0, 0});
      break;
    }
    case 3: {
      Vec3 base[5];
      for (Vec3& b : base)
        b = {in.ConsumeIntegralInRange(-20, 20) * 0.5, in.ConsumeIntegralInRange(-20, 20) * 0.5,
             in.ConsumeIntegralInRange(-20, 20) * 0.5};
      const int k = in.ConsumeIntegralInRange(1, 40);
      for (int i = 0; i < k; ++i) p.push_back(base[in.ConsumeIntegralInRange(0, 4)]);
      break;
    }
    case 4: {
      const int k = in.ConsumeIntegralInRange(0, 60);
      for (int i = 0; i < k; ++i)
        p.push_back({double(in.ConsumeIntegralInRange(-4, 4)), double(in.ConsumeIntegralInRange(-4, 4)),
                     double(in.ConsumeIntegralInRange(-4, 4))});
      break;
    }
    default: {
      const int a = in.ConsumeIntegralInRange(-5, 5), b = in.ConsumeIntegralInRange(-5, 5), d = in.ConsumeIntegralInRange(-9, 9);
      const int k = in.ConsumeIntegralInRange(3, 50);
      for (int i = 0; i < k; ++i) {
        const int x = in.ConsumeIntegralInRange(-9, 9), y = in.ConsumeIntegralInRange(-9, 9);
        p.push_back({double(x), double(y), double(d - a * x - b * y)});
      }
      if (in.ConsumeBool()) p.push_back({0, 0, d + 0.5});
      break;
    }
  }
  if (in.ConsumeBool())
    for (Vec3& q : p) {
      q.x = geomcheck::fuzz::nudge(q.x, in.ConsumeIntegralInRange(-3, 3));
      q.y = geomcheck::fuzz::nudge(q.y, in.ConsumeIntegralInRange(-3, 3));
      q.z = geomcheck::fuzz::nudge(q.z, in.ConsumeIntegralInRange(-3, 3));
    }
  const bool per_point = (mode & 0x80) != 0;
  int e = in.ConsumeIntegralInRange(-1070, 1000);
  for (Vec3& q : p) {
    if (per_point) e = in.ConsumeBool() ? in.ConsumeIntegralInRange(900, 1000) : in.ConsumeIntegralInRange(-1070, -900);
    q = {std::ldexp(q.x, e), std::ldexp(q.y, e), std::ldexp(q.z, e)};
  }
  return p;
}

std::vector<geomcheck::oracle::Tetrahedron> canonical(const std::vector<std::array<std::uint32_t, 4>>& tets) {
  std::vector<geomcheck::oracle::Tetrahedron> out;
  out.reserve(tets.size());
  for (const auto& t : tets) out.push_back(geomcheck::oracle::canonical_tetrahedron(t));
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  std::vector<Vec3> p;
  if (data[0] == 0) {
    for (std::size_t off = 1; off + 24 <= size; off += 24) {
      Vec3 v;
      std::memcpy(&v.x, data + off, 8);
      std::memcpy(&v.y, data + off + 8, 8);
      std::memcpy(&v.z, data + off + 16, 8);
      p.push_back(v);
    }
  } else {
    FuzzedDataProvider in(data + 1, size - 1);
    p = structured(data[0], in);
  }
  std::size_t bad = p.size();
  for (std::size_t i = 0; i < p.size() && bad == p.size(); ++i)
    if (!std::isfinite(p[i].x) || !std::isfinite(p[i].y) || !std::isfinite(p[i].z)) bad = i;
  geomcheck::DelaunayTetrahedralization d;
  try {
    d = geomcheck::delaunay_3d(p);
  } catch (const geomcheck::DelaunayInputError& e) {
    if (e.index() != bad) fail(p, std::string("DelaunayInputError naming the wrong point: ") + e.what());
    return 0;
  } catch (const std::exception& e) {
    fail(p, std::string("exception: ") + e.what());
  }
  if (bad != p.size()) fail(p, "a non-finite coordinate was accepted");
  const std::string why = geomcheck::oracle::check_delaunay_3d(p, d.tetrahedra);
  if (!why.empty()) fail(p, "check_delaunay_3d: " + why);
  // The reversed input: the same tetrahedra, relabelled (index i is n-1-i).
  const std::size_t n = p.size();
  std::vector<Vec3> r(p.rbegin(), p.rend());
  const geomcheck::DelaunayTetrahedralization dr = geomcheck::delaunay_3d(r);
  std::vector<std::array<std::uint32_t, 4>> mapped;
  for (const auto& t : dr.tetrahedra) {
    std::array<std::uint32_t, 4> m{};
    for (int i = 0; i < 4; ++i) m[i] = d.vertex_of[n - 1 - t[i]];
    mapped.push_back(m);
  }
  if (canonical(mapped) != canonical(d.tetrahedra)) fail(p, "the reversed input gives other tetrahedra");
  return 0;
}
