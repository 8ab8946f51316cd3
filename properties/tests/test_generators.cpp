// geomcheck — a seed's cases are the same on every compiler and build.
//
// The generators draw many numbers per case; where two draws sit in one
// expression (two arguments of a call, two operands of +) C++ leaves their
// order to the compiler, and g++ and clang took them in different orders, so
// that one seed gave other cases under clang (the sanitizer and fuzz builds)
// than under g++ (the default and release builds). Every draw is now a
// statement of its own or an element of a braced list (evaluated in order).
//
// This test pins the cases: a hash of the first kCases targeted and wild
// cases of every pair query (the case file text: every number bit for bit,
// and the mode), of the point sets and of the meshes, for the main job's
// seed, against the values below. CI runs it in the g++ build and in the
// clang sanitizer build, so a draw whose order depends on the compiler turns
// it red in one of them. The pinned values live in generator_hashes.txt; a
// change to a generator changes its hash on purpose, and a new query adds
// one: GEOMCHECK_WRITE_HASHES=1 test_generators rewrites the file.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <cstdio>
#include <map>
#include <string>

#include "geomcheck/casefile.hpp"
#include "geomcheck/properties/generators.hpp"

using namespace geomcheck;

namespace {

constexpr int kCases = 300;
constexpr std::uint64_t kSeed = 20261121;

struct Fnv {
  std::uint64_t h = 0xcbf29ce484222325ull;
  void add(const std::string& s) {
    for (unsigned char ch : s) h = (h ^ ch) * 0x100000001b3ull;
  }
};

std::string hex(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%a ", v);
  return buf;
}

template <QueryId Q>
std::uint64_t pair_hash() {
  Fnv f;
  rc::Random random = gen::sequence<Q>(kSeed);
  const auto targeted = gen::targeted<Q>();
  for (int i = 0; i < kCases; ++i) {
    const auto tc = targeted(random.split(), 50).value();
    f.add(tc.second);
    f.add(write_case(from_case<Q>(tc.first)));
  }
  const auto wild = gen::wild<Q>();
  for (int i = 0; i < kCases; ++i) f.add(write_case(from_case<Q>(wild(random.split(), 50).value())));
  return f.h;
}

std::map<std::string, std::uint64_t> actual() {
  std::map<std::string, std::uint64_t> out;
#define GEOMCHECK_X(id, kind, A, B, summary) out[#id] = pair_hash<QueryId::id>();
  GEOMCHECK_QUERY_LIST(GEOMCHECK_X)
#undef GEOMCHECK_X
  rc::Random random(kSeed);
  Fnv ps;
  const auto sets = gen::point_sets();
  for (int i = 0; i < kCases; ++i) {
    const auto t = sets(random.split(), 50).value();
    ps.add(t.second);
    for (const Vec2& p : t.first) ps.add(hex(p.x) + hex(p.y));
  }
  out["point_sets"] = ps.h;
  Fnv ms;
  const auto meshes = gen::meshes();
  for (int i = 0; i < kCases / 10; ++i) {
    const auto m = meshes(random.split(), 50).value();
    ms.add(m.mode);
    ms.add(hex(m.cyl.p.x) + hex(m.cyl.p.y) + hex(m.cyl.p.z) + hex(m.cyl.q.x) + hex(m.cyl.q.y) + hex(m.cyl.q.z) +
           hex(m.cyl.r));
    for (const Vec3& v : m.vertices) ms.add(hex(v.x) + hex(v.y) + hex(v.z));
    for (const auto& fc : m.faces) ms.add(std::to_string(fc[0]) + " " + std::to_string(fc[1]) + " " + std::to_string(fc[2]) + ";");
  }
  out["meshes"] = ms.h;
  return out;
}

// The hashes every build must give (g++ and clang, any optimisation level):
// generator_hashes.txt, beside this file.
const std::string kHashFile = GEOMCHECK_SOURCE_DIR "/properties/tests/generator_hashes.txt";

std::map<std::string, std::uint64_t> expected() {
  std::map<std::string, std::uint64_t> out;
  std::ifstream in(kHashFile);
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream words(line);
    std::string name, hash;
    if (!(words >> name >> hash) || name[0] == '#') continue;
    out[name] = std::stoull(hash, nullptr, 16);
  }
  return out;
}

}  // namespace

TEST(Generators, SameCasesOnEveryCompiler) {
  const auto got = actual();
  std::string table;
  for (const auto& [name, h] : got) {
    char line[96];
    std::snprintf(line, sizeof line, "%s 0x%016llx\n", name.c_str(), static_cast<unsigned long long>(h));
    table += line;
  }
  if (std::getenv("GEOMCHECK_WRITE_HASHES")) {  // the command that regenerates the file
    std::ifstream in(kHashFile);
    std::string head, line;
    while (std::getline(in, line) && (line.empty() || line[0] == '#')) head += line + "\n";
    std::ofstream(kHashFile) << head << table;
    std::printf("wrote %zu hashes to %s\n", got.size(), kHashFile.c_str());
    return;
  }
  const auto kExpected = expected();
  ASSERT_FALSE(kExpected.empty()) << "no hashes read from " << kHashFile;
  bool same = got.size() == kExpected.size();
  for (const auto& [name, h] : got) {
    const auto it = kExpected.find(name);
    if (it == kExpected.end() || it->second != h) {
      same = false;
      ADD_FAILURE() << name << ": the first " << kCases << " cases of seed " << kSeed
                    << " differ from the pinned ones (a draw whose order depends on the compiler, or a generator "
                       "changed on purpose)";
    }
  }
  if (!same)
    std::printf("The hashes of this build (if the generators changed on purpose or a query was registered, regenerate "
                "%s: GEOMCHECK_WRITE_HASHES=1 %s):\n%s",
                kHashFile.c_str(), ::testing::internal::GetArgvs()[0].c_str(), table.c_str());
}
