// geomcheck — libFuzzer target for collide(Cylinder, TriangleMesh).
//
// Input: byte 0 chooses the mode (as fuzz_decode.hpp), byte 1 the number of
// vertices (0..31), byte 2 the number of faces (0..63).
//   even (RAW): then the cylinder's 7 doubles and the vertices' doubles, raw
//         little-endian (any bit pattern), then one byte per face index
//         (taken modulo the vertex count + 1: out of range sometimes).
//   odd (STRUCTURED): the cylinder and the vertices as small half-integers
//         nudged by a few ulps (structured_value), the whole scene scaled by
//         a power of two; faces from the remaining bytes (index up to the
//         vertex count: out of range sometimes), repeated indices and
//         duplicate faces common.
// Checks, both modes: invalid input (non-finite vertex, index out of range,
// invalid cylinder) gives no hit; the hierarchy's overlap and collide equal
// the brute force over every face bit for bit (face index included); the
// contact is the deepest face's own triangle answer (smallest index on
// ties); collide(mesh, cylinder) is the flipped collide(cylinder, mesh).
// Structured mode also runs every collide_cylinder_triangle property
// against the exact oracle (check_all) on the reported face. A failure
// prints the mesh and aborts; the crash input replays with this binary.
#include <fuzzer/FuzzedDataProvider.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "geomcheck/collide_cylinder_mesh.hpp"
#include "geomcheck/collide_cylinder_triangle.hpp"
#include "geomcheck/fuzz_decode.hpp"
#include "geomcheck/properties/checks.hpp"

namespace {
using namespace geomcheck;

struct MeshInput {
  Cylinder cyl;
  std::vector<Vec3> v;
  std::vector<MeshFace> f;
};

[[noreturn]] void fail(const MeshInput& in, const std::string& what, const char* mode) {
  std::fprintf(stderr, "\n==== geomcheck collide_cylinder_mesh property failed (mode=%s): %s\n", mode, what.c_str());
  std::fprintf(stderr, "cylinder p=(%a, %a, %a) q=(%a, %a, %a) r=%a\n", in.cyl.p.x, in.cyl.p.y, in.cyl.p.z, in.cyl.q.x,
               in.cyl.q.y, in.cyl.q.z, in.cyl.r);
  for (std::size_t i = 0; i < in.v.size(); ++i)
    std::fprintf(stderr, "v%zu (%a, %a, %a)\n", i, in.v[i].x, in.v[i].y, in.v[i].z);
  for (std::size_t i = 0; i < in.f.size(); ++i) std::fprintf(stderr, "f%zu %u %u %u\n", i, in.f[i][0], in.f[i][1], in.f[i][2]);
  std::fprintf(stderr, "====\n");
  std::abort();
}

bool same(const Contact& a, const Contact& b) {
  if (a.hit != b.hit) return false;
  if (!a.hit) return true;
  auto eq = [](double x, double y) { return x == y || (std::isnan(x) && std::isnan(y)); };
  return eq(a.depth, b.depth) && eq(a.normal.x, b.normal.x) && eq(a.normal.y, b.normal.y) &&
         eq(a.normal.z, b.normal.z) && eq(a.point.x, b.point.x) && eq(a.point.y, b.point.y) && eq(a.point.z, b.point.z);
}

MeshInput decode(const std::uint8_t* data, std::size_t size, bool& structured) {
  MeshInput in;
  structured = fuzz::mode_of(data, size) == fuzz::Mode::Structured;
  const std::size_t nv = size > 1 ? data[1] % 32 : 0, nf = size > 2 ? data[2] % 64 : 0;
  const std::uint8_t* p = data + std::min<std::size_t>(size, 3);
  std::size_t n = size > 3 ? size - 3 : 0;
  if (!structured) {
    const auto d = decode_raw_doubles(p, n, 7 + 3 * nv);
    in.cyl = {{d[0], d[1], d[2]}, {d[3], d[4], d[5]}, d[6]};
    for (std::size_t i = 0; i < nv; ++i) in.v.push_back({d[7 + 3 * i], d[8 + 3 * i], d[9 + 3 * i]});
    const std::size_t used = std::min(n, 8 * (7 + 3 * nv));
    p += used, n -= used;
    for (std::size_t i = 0; i < nf; ++i) {
      MeshFace f{};
      for (auto& k : f) k = n > 0 ? static_cast<std::uint32_t>(*p++ % (nv + 1)) : 0, n -= n > 0;
      in.f.push_back(f);
    }
    return in;
  }
  FuzzedDataProvider fp(p, n);
  const int e = fp.ConsumeIntegralInRange<int>(-30, 30);
  auto val = [&] { return std::ldexp(fuzz::structured_value(fp), e); };
  auto vec = [&] { return Vec3{val(), val(), val()}; };
  in.cyl.p = vec(), in.cyl.q = vec(), in.cyl.r = std::fabs(val());
  for (std::size_t i = 0; i < nv; ++i) in.v.push_back(vec());
  for (std::size_t i = 0; i < nf; ++i) {
    MeshFace f{};
    for (auto& k : f) k = fp.ConsumeIntegralInRange<std::uint32_t>(0, static_cast<std::uint32_t>(nv));
    in.f.push_back(f);
  }
  return in;
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  bool structured = false;
  const MeshInput in = decode(data, size, structured);
  const char* mode = structured ? "structured" : "raw";
  const TriangleMesh mesh(in.v, in.f);
  const bool o = overlap(in.cyl, mesh);
  std::uint32_t idx = 0xffffffffu, idx_b = 0xffffffffu, idx_s = 0xffffffffu;
  const Contact k = collide(in.cyl, mesh, &idx);
  if (o != detail::overlap_brute_force(in.cyl, mesh)) fail(in, "overlap differs from the brute force", mode);
  if (!same(k, detail::collide_brute_force(in.cyl, mesh, &idx_b)) || idx != idx_b)
    fail(in, "collide differs from the brute force", mode);
  if (k.hit != o) fail(in, "collide.hit differs from overlap", mode);
  const Contact s = collide(mesh, in.cyl, &idx_s);
  if (s.hit != k.hit || idx_s != idx || (k.hit && !(s.normal == -k.normal && s.depth == k.depth && s.point == k.point)))
    fail(in, "collide(mesh, cylinder) is not the flipped collide(cylinder, mesh)", mode);
  const bool valid_input = is_valid(in.cyl) && mesh.valid();
  if (!valid_input) {
    if (o) fail(in, "invalid input gives a hit", mode);
    return 0;
  }
  // The deepest face (smallest index on ties), its own answer.
  bool any = false;
  double deepest = -INFINITY;
  std::uint32_t first = 0xffffffffu;
  for (std::uint32_t f = 0; f < mesh.size(); ++f) {
    const Triangle t = mesh.triangle(f);
    if (!overlap(in.cyl, t)) continue;
    any = true;
    const double d = collide(in.cyl, t).depth;
    if (d > deepest) deepest = d, first = f;
  }
  if (any != o) fail(in, "mesh verdict is not 'some face overlaps'", mode);
  if (!o) return 0;
  if (idx != first) fail(in, "reported face " + std::to_string(idx) + ", deepest " + std::to_string(first), mode);
  if (!same(k, collide(in.cyl, mesh.triangle(idx)))) fail(in, "contact differs from the face's own", mode);
  if (!std::isfinite(k.depth) || !is_finite(k.normal) || !is_finite(k.point)) fail(in, "non-finite contact", mode);
  if (structured)
    if (auto f = check_all(CylinderTriangleCase{in.cyl, mesh.triangle(idx)}))
      fail(in, "face " + std::to_string(idx) + ": " + f->property + ": " + f->detail, mode);
  return 0;
}
