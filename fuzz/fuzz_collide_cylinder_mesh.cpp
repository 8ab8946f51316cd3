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
// Checks (mesh_checks.hpp), both modes: check_mesh_consistency (invalid
// input gives no hit; the hierarchy's overlap and collide equal the brute
// force bit for bit, face index included; the contact is the deepest face's
// own triangle answer; collide(mesh, cylinder) is the flipped answer).
// Structured mode also holds the answer to the truth face by face
// (check_mesh_all). A failure prints the case as a mesh file (geomcheck
// replay reads it) and aborts; the crash input replays with this binary.
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
#include "geomcheck/mesh_file.hpp"
#include "geomcheck/properties/mesh_checks.hpp"

namespace {
using namespace geomcheck;

struct MeshInput {
  Cylinder cyl;
  std::vector<Vec3> v;
  std::vector<MeshFace> f;
};

[[noreturn]] void fail(const MeshInput& in, const std::string& what, const char* mode) {
  MeshFile f;
  f.cylinder = in.cyl, f.vertices = in.v, f.faces = in.f;
  f.found_by = std::string("fuzz_collide_cylinder_mesh (") + mode + " mode)";
  f.note = what;
  std::fprintf(stderr,
               "\n==== geomcheck collide_cylinder_mesh property failed (mode=%s): %s\n---- case file (save it as "
               "FILE.case; geomcheck replay FILE.case replays it):\n%s====\n",
               mode, what.c_str(), write_mesh_file(f).c_str());
  std::abort();
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
  // Structured inputs are also held to the truth face by face (the engine
  // on every face whose box meets the cylinder's); raw ones, mostly far
  // apart or invalid, to the exact consistency checks.
  const CheckResult f = structured ? check_mesh_all(in.cyl, mesh) : check_mesh_consistency(in.cyl, mesh);
  if (f) fail(in, f->property + ": " + f->detail, mode);
  return 0;
}
