// geomcheck — tests of the mesh case file (a cylinder and a triangle mesh,
// the mesh queries' input) and the mesh corpora.
//
// Fixed seeds throughout (printed with each randomized test). The corpus
// tests read GEOMCHECK_CORPORA_DIR (corpora/ in the source tree).
#include "geomcheck/mesh_file.hpp"

#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <random>
#include <set>
#include <string>

#include "format_test_support.hpp"

namespace fs = std::filesystem;
using namespace geomcheck;
using namespace geomcheck::test;

namespace {

double nan() { return std::numeric_limits<double>::quiet_NaN(); }

/// The example of the format documentation: a unit cylinder on a square.
MeshFile square_example() {
  MeshFile f;
  f.cylinder = {{0, 0, 0}, {0, 0, 1}, 1};
  f.vertices = {{-2, -2, 0.5}, {2, -2, 0.5}, {2, 2, 0.5}, {-2, 2, 0.5}};
  f.faces = {{0, 1, 2}, {0, 2, 3}};
  f.found_by = "hand";
  f.oracle_verdict = "overlapping";
  f.note = "a unit cylinder on a square of two faces";
  return f;
}

const char* const kSquareExampleText =
    "# geomcheck case file\n"
    "geomcheck-case 1\n"
    "query collide_cylinder_mesh\n"
    "found-by hand\n"
    "oracle-verdict overlapping\n"
    "note a unit cylinder on a square of two faces\n"
    "cylinder 0x0p+0 0x0p+0 0x0p+0 0x0p+0 0x0p+0 0x1p+0 0x1p+0   # 0 0 0 0 0 1 1\n"
    "vertex -0x1p+1 -0x1p+1 0x1p-1   # -2 -2 0.5\n"
    "vertex 0x1p+1 -0x1p+1 0x1p-1    # 2 -2 0.5\n"
    "vertex 0x1p+1 0x1p+1 0x1p-1     # 2 2 0.5\n"
    "vertex -0x1p+1 0x1p+1 0x1p-1    # -2 2 0.5\n"
    "face 0 1 2\n"
    "face 0 2 3\n"
    "end\n";

/// A minimal valid file around the given body lines (after the meta lines).
std::string with_body(const std::string& meta, const std::string& body) {
  return "geomcheck-case 1\nquery collide_cylinder_mesh\n" + meta + body + "end\n";
}
const std::string kCyl = "cylinder 0 0 0 0 0 1 1\n";

MeshParseResult round_trip(const MeshFile& f) { return parse_mesh_file(write_mesh_file(f)); }

}  // namespace

TEST(MeshWrite, ExactLayout) { EXPECT_EQ(write_mesh_file(square_example()), kSquareExampleText); }

TEST(MeshParse, DocumentationExample) {
  const MeshParseResult r = parse_mesh_file(kSquareExampleText);
  ASSERT_TRUE(r.ok()) << r.error;
  EXPECT_EQ(r.value, square_example());
  EXPECT_EQ(r.value.query, "collide_cylinder_mesh");
  ASSERT_EQ(r.value.faces.size(), 2u);
  EXPECT_EQ(r.value.faces[1], (MeshFace{0, 2, 3}));
  EXPECT_TRUE(mesh_of(r.value).valid());
}

TEST(MeshRoundTrip, SpecialValuesBitExact) {
  MeshFile f;
  f.cylinder = {{-0.0, DBL_TRUE_MIN, -DBL_MAX}, {inf(), -inf(), nan()}, from_bits(0xfffabcdef0123456ull)};
  f.vertices = {{-0.0, 0.0, DBL_MIN / 3}, {nan(), -nan(), from_bits(0x7ff0000000000001ull)}};
  f.faces = {{0, 1, 4294967295u}, {7, 7, 7}};
  f.found_by = "hand";
  const MeshParseResult r = round_trip(f);
  ASSERT_TRUE(r.ok()) << r.error << "\n" << write_mesh_file(f);
  EXPECT_EQ(r.value, f);
  EXPECT_TRUE(std::signbit(r.value.cylinder.p.x));
  EXPECT_EQ(bits(r.value.cylinder.r), 0xfffabcdef0123456ull);
  EXPECT_EQ(bits(r.value.vertices[1].z), 0x7ff0000000000001ull);
  EXPECT_EQ(r.value.faces[0][2], 4294967295u);
  EXPECT_FALSE(mesh_of(r.value).valid());  // non-finite vertices, indices out of range
  MeshFile g = f;
  g.vertices[0].x = 0.0;
  EXPECT_NE(g, f);
  g = f;
  g.faces[1][0] = 6;
  EXPECT_NE(g, f);
  g = f;
  g.cylinder.r = 1;
  EXPECT_NE(g, f);
}

TEST(MeshRoundTrip, EmptyAndRandomMeshes) {
  MeshFile empty;
  empty.note = "no faces";
  const MeshParseResult e = round_trip(empty);
  ASSERT_TRUE(e.ok()) << e.error;
  EXPECT_EQ(e.value, empty);

  const std::uint64_t seed = 20261127;
  SCOPED_TRACE("seed " + std::to_string(seed));
  std::mt19937_64 rng(seed);
  for (int round = 0; round < 20; ++round) {
    MeshFile m;
    double c[7];
    for (double& x : c) x = random_boundary_double(rng);
    m.cylinder = {{c[0], c[1], c[2]}, {c[3], c[4], c[5]}, c[6]};
    const int nv = static_cast<int>(rng() % 200), nf = static_cast<int>(rng() % 400);
    for (int i = 0; i < nv; ++i)
      m.vertices.push_back({random_boundary_double(rng), random_boundary_double(rng), random_boundary_double(rng)});
    for (int i = 0; i < nf; ++i)
      m.faces.push_back({static_cast<std::uint32_t>(rng() % (nv + 2)), static_cast<std::uint32_t>(rng() % (nv + 2)),
                         static_cast<std::uint32_t>(rng())});
    const MeshParseResult r = round_trip(m);
    ASSERT_TRUE(r.ok()) << r.error;
    EXPECT_EQ(r.value, m);
  }
}

TEST(MeshRoundTrip, Strings) {
  expect_awkward_texts_round_trip(square_example(), &parse_mesh_file, &write_mesh_file);
}

TEST(MeshParse, HandWrittenOrderDecimalsAndCrlf) {
  const MeshParseResult r = parse_mesh_file(hand_written({
      "note first",
      "query collide_cylinder_mesh # the mesh query",
      "oracle-verdict separated",
      "cylinder 0 0 0  0 0 1  .5",
      "face 0 1 2   # before its vertices: any order",
      "vertex 5 0 0",
      "\tvertex\t6 0 0",
      "   # a comment between vertices",
      "vertex 5 1 -0",
      "face 2 1 0"}));
  ASSERT_TRUE(r.ok()) << r.error;
  ASSERT_EQ(r.value.vertices.size(), 3u);
  ASSERT_EQ(r.value.faces.size(), 2u);
  EXPECT_EQ(r.value.faces[0], (MeshFace{0, 1, 2}));
  EXPECT_EQ(r.value.faces[1], (MeshFace{2, 1, 0}));
  EXPECT_EQ(r.value.cylinder.r, 0.5);
  // Leading zeros are fine.
  EXPECT_EQ(parse_mesh_file(with_body("", kCyl + "face 00 0001 0004294967295\n")).value.faces.at(0),
            (MeshFace{0, 1, 4294967295u}));
  EXPECT_TRUE(std::signbit(r.value.vertices[2].z));
  EXPECT_EQ(r.value.oracle_verdict, "separated");
  // The writer puts the vertices first; the value is the same.
  EXPECT_EQ(round_trip(r.value).value, r.value);
}

TEST(MeshParse, RejectsMalformedInputs) {
  const std::vector<Rejection> bads = {
      {"", 1, "empty file"},
      {"geomcheck-case 1\nquery collide_cylinder_mesh\n" + kCyl, 3, "missing 'end'"},
      {with_body("", ""), 3, "missing 'cylinder' line before 'end'"},
      {"geomcheck-case 1\n" + kCyl + "end\n", 2, "'cylinder' before the 'query' line"},
      {"geomcheck-case 1\nquery collide_cylinder_obb\n" + kCyl + "end\n", 2,
       "query collide_cylinder_obb is not a mesh query: this is not a mesh file"},
      {"geomcheck-case 1\nquery delaunay_2d\nend\n", 2, "parse_point_set reads it"},
      {"geomcheck-case 1\nquery mesh\nend\n", 2, "unknown query 'mesh'"},
      {with_body("oracle-verdict hit\n", kCyl), 3, "unknown oracle verdict 'hit' for query collide_cylinder_mesh"},
      {with_body("", kCyl + kCyl), 4, "duplicate 'cylinder' line"},
      {with_body("", "cylinder 0 0 0 0 0 1\n"), 3, "'cylinder' takes 7 values (p, q, r), got 6"},
      {with_body("", "vertex 0 0 0\n"), 3, "'vertex' before the 'cylinder' line"},
      {with_body("", "face 0 0 0\n"), 3, "'face' before the 'cylinder' line"},
      {with_body("", kCyl + "vertex 0 0\n"), 4, "'vertex' takes 3 values (x y z), got 2"},
      {with_body("", kCyl + "vertex 0 0 x\n"), 4, "malformed number 'x' in 'vertex'"},
      {with_body("", kCyl + "vertex 0 0 1e400\n"), 4, "outside the double range"},
      {with_body("", kCyl + "face 0 1\n"), 4, "'face' takes 3 vertex indices, got 2"},
      {with_body("", kCyl + "face 0 1 -2\n"), 4, "malformed index '-2' in 'face'"},
      {with_body("", kCyl + "face 0 1 4294967296\n"), 4, "malformed index '4294967296'"},
      {with_body("", kCyl + "face 0 1 000004294967296\n"), 4, "malformed index '000004294967296'"},
      {with_body("", kCyl + "face 0 1 0x2\n"), 4, "malformed index '0x2'"},
      {with_body("", kCyl + "face 0 1 2.0\n"), 4, "malformed index '2.0'"},
      {with_body("", kCyl + "note late\n"), 4, "'note' must come before the first 'cylinder'"},
      {with_body("", kCyl + "point 0 0\n"), 4, "unknown keyword 'point' (expected vertex, face or end)"},
      {with_body("", kCyl) + "vertex 0 0 0\n", 5, "unexpected 'vertex' after 'end'"},
  };
  std::set<std::string> messages;
  expect_all_rejected(bads, &parse_mesh_file, &messages);
  EXPECT_EQ(messages.size(), bads.size()) << "every rejection has its own message";
}

TEST(MeshParse, TooManyVerticesNamesTheLine) {
  std::string body = kCyl;
  for (std::size_t i = 0; i <= kMaxMeshVertices; ++i) body += "vertex 0 0 0\n";
  const MeshParseResult r = parse_mesh_file(with_body("", body));
  ASSERT_NO_FATAL_FAILURE(expect_rejected(r, static_cast<int>(kMaxMeshVertices) + 4,
                                          "more than " + std::to_string(kMaxMeshVertices) +
                                              " vertices (the limit of a mesh file)"));
  MeshFile f;
  f.vertices.resize(kMaxMeshVertices + 1);
  ASSERT_TRUE(mesh_file_error(f).has_value());
  EXPECT_NE(mesh_file_error(f)->find("vertices"), std::string::npos);
  f.vertices.clear();
  f.faces.resize(kMaxMeshFaces + 1);
  ASSERT_TRUE(mesh_file_error(f).has_value());
  EXPECT_NE(mesh_file_error(f)->find("faces (the limit of a mesh file)"), std::string::npos);
}

// The largest counts with the longest numbers still write a file within
// the byte limit (so every file mesh_file_error accepts loads back), and a
// text beyond it (a note this long) is refused before it is written.
TEST(MeshFile, LimitsWriteWithinTheByteLimit) {
  MeshFile f;
  const double worst = -0x1.fffffffffffffp+1000;
  f.cylinder = {{worst, worst, worst}, {worst, worst, worst}, worst};
  f.vertices.assign(kMaxMeshVertices, Vec3{worst, -DBL_TRUE_MIN * 3, worst});
  f.faces.assign(kMaxMeshFaces, MeshFace{4294967295u, 4294967295u, 4294967295u});
  EXPECT_FALSE(mesh_file_error(f).has_value()) << *mesh_file_error(f);
  const std::size_t bytes = write_mesh_file(f).size();
  EXPECT_LE(bytes, kMaxMeshFileBytes);
  std::printf("largest counts, longest numbers: %zu bytes (limit %zu)\n", bytes, kMaxMeshFileBytes);
  f.note = std::string(kMaxMeshFileBytes - bytes + 1, 'x');
  ASSERT_TRUE(mesh_file_error(f).has_value());
  EXPECT_NE(mesh_file_error(f)->find("beyond the limit of a mesh file"), std::string::npos) << *mesh_file_error(f);
}

TEST(MeshParse, MutationsRoundTripOrNameALine) {
  expect_mutations_round_trip_or_name_a_line(kSquareExampleText, "0123456789 .-+xpe#\nfacevrtxyl", 20261127,
                                             &parse_mesh_file, &write_mesh_file);
}

TEST(MeshFile, InvalidValuesReported) {
  expect_invalid_values_reported(square_example(), "hit", "over\nlapping", &mesh_file_error, &parse_mesh_file,
                                 &write_mesh_file);
  MeshFile f = square_example();
  f.query = "collide_cylinder_triangle";
  ASSERT_TRUE(mesh_file_error(f).has_value());
  EXPECT_NE(mesh_file_error(f)->find("is not a mesh query"), std::string::npos);
}

TEST(MeshFile, SaveAndLoad) {
  const fs::path dir = fresh_temp_dir("geomcheck-meshfile");
  MeshFile bad = square_example();
  bad.oracle_verdict = "hit";
  expect_save_and_load(dir, "square.case", square_example(), bad, &save_mesh_file, &load_mesh_file);
  expect_too_large_refused(dir, kMaxMeshFileBytes + 1, kMaxMeshFileBytes, &load_mesh_file);
  fs::remove_all(dir);
}

TEST(MeshFile, FuzzInputOfSmallMeshes) {
  const auto in = fuzz_input_from_mesh(square_example());
  ASSERT_TRUE(in.has_value());
  ASSERT_EQ(in->size(), 3u + 8 * (7 + 3 * 4) + 6);
  EXPECT_EQ((*in)[0], '\0');
  EXPECT_EQ((*in)[1], 4);
  EXPECT_EQ((*in)[2], 2);
  EXPECT_EQ(in->substr(in->size() - 6), std::string("\0\1\2\0\2\3", 6));
  MeshFile big = square_example();
  big.vertices.resize(32);
  EXPECT_FALSE(fuzz_input_from_mesh(big).has_value());
}

// Every mesh file of the corpora parses and writes back to the same value.
TEST(MeshCorpora, EveryMeshFileParsesAndRoundTrips) {
  int n = 0;
  for (const char* sub : {"seeds", "regressions"}) {
    const fs::path root = fs::path(GEOMCHECK_CORPORA_DIR) / sub;
    for (const auto& q : kAllQueries) {
      if (q.family != QueryFamily::Mesh) continue;
      for (const fs::path& p : case_files(root / q.name)) {
        SCOPED_TRACE(p.string());
        const MeshParseResult r = load_mesh_file(p);
        ASSERT_TRUE(r.ok()) << r.error;
        EXPECT_EQ(r.value.query, q.name);
        EXPECT_EQ(round_trip(r.value).value, r.value);
        ++n;
      }
    }
  }
  EXPECT_GE(n, 3) << "the mesh seeds are missing";
}
