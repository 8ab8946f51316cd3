// geomcheck — tests of the point-set case file (the Delaunay query's input),
// its classification and the point-set corpora.
//
// Fixed seeds throughout (printed with each randomized test). The corpus
// tests read GEOMCHECK_CORPORA_DIR (corpora/ in the source tree).
#include "geomcheck/pointset_file.hpp"

#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <fstream>
#include <limits>
#include <map>
#include <random>
#include <set>
#include <string>

#include "format_test_support.hpp"

namespace fs = std::filesystem;
using namespace geomcheck;
using namespace geomcheck::test;

namespace {

double nan() { return std::numeric_limits<double>::quiet_NaN(); }
double up(double v) { return std::nextafter(v, inf()); }

/// The example of the format documentation: four cocircular points.
PointSetFile square_example() {
  PointSetFile f;
  f.points = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  f.found_by = "hand";
  f.oracle_verdict = "triangulated";
  f.note = "four cocircular points (a square)";
  return f;
}

const char* const kSquareExampleText =
    "# geomcheck case file\n"
    "geomcheck-case 1\n"
    "query delaunay_2d\n"
    "found-by hand\n"
    "oracle-verdict triangulated\n"
    "note four cocircular points (a square)\n"
    "point 0x0p+0 0x0p+0   # 0 0\n"
    "point 0x1p+0 0x0p+0   # 1 0\n"
    "point 0x1p+0 0x1p+0   # 1 1\n"
    "point 0x0p+0 0x1p+0   # 0 1\n"
    "end\n";

/// The header line followed by `rest`.
std::string after_header(const std::string& rest) { return "geomcheck-case 1\n" + rest; }

/// A minimal valid file around the given body lines (after the meta lines).
std::string with_body(const std::string& meta, const std::string& body) {
  return after_header("query delaunay_2d\n" + meta + body + "end\n");
}

PointSetParseResult round_trip(const PointSetFile& f) { return parse_point_set(write_point_set(f)); }

}  // namespace

// ---------------------------------------------------------------------------
// Writing and round trips

TEST(PointSetWrite, ExactLayout) { EXPECT_EQ(write_point_set(square_example()), kSquareExampleText); }

TEST(PointSetParse, DocumentationExample) {
  const PointSetParseResult r = parse_point_set(kSquareExampleText);
  ASSERT_TRUE(r.ok()) << r.error;
  EXPECT_EQ(r.value, square_example());
  ASSERT_EQ(r.value.points.size(), 4u);
  EXPECT_EQ(r.value.points[2], (Vec2{1, 1}));
  EXPECT_EQ(r.value.oracle_verdict, "triangulated");
  EXPECT_EQ(classify_point_set(r.value.points), "triangulated");
}

TEST(PointSetRoundTrip, SpecialValuesBitExact) {
  PointSetFile f;
  f.points = {{-0.0, 0.0},
              {DBL_TRUE_MIN, -DBL_TRUE_MIN},
              {DBL_MIN / 3, -DBL_MIN},
              {DBL_MAX, -DBL_MAX},
              {inf(), -inf()},
              {nan(), -nan()},
              {from_bits(0x7ff0000000000001ull) /* signalling */, from_bits(0xfffabcdef0123456ull)}};
  f.found_by = "hand";
  f.oracle_verdict = "rejected";
  const PointSetParseResult r = round_trip(f);
  ASSERT_TRUE(r.ok()) << r.error << "\n" << write_point_set(f);
  EXPECT_EQ(r.value, f);
  const auto& p = r.value.points;
  EXPECT_TRUE(std::signbit(p[0].x));
  EXPECT_FALSE(std::signbit(p[0].y));
  EXPECT_EQ(bits(p[1].x), 1u);
  EXPECT_EQ(bits(p[1].y), 0x8000000000000001ull);
  EXPECT_EQ(p[3].x, DBL_MAX);
  EXPECT_EQ(p[4].x, inf());
  EXPECT_EQ(p[4].y, -inf());
  EXPECT_EQ(bits(p[5].x), 0x7ff8000000000000ull);
  EXPECT_EQ(bits(p[5].y), 0xfff8000000000000ull);
  EXPECT_EQ(bits(p[6].x), 0x7ff0000000000001ull);
  EXPECT_EQ(bits(p[6].y), 0xfffabcdef0123456ull);
  const std::string text = write_point_set(f);
  EXPECT_NE(text.find("point 0x0.0000000000001p-1022 -0x0.0000000000001p-1022"), std::string::npos) << text;
  EXPECT_NE(text.find("point nan(0x1) -nan(0xabcdef0123456)"), std::string::npos) << text;
  EXPECT_NE(text.find("point inf -inf"), std::string::npos) << text;

  // Equality is bit equality: +0 and -0 differ, and so do NaN payloads.
  PointSetFile g = f;
  g.points[0].x = 0.0;
  EXPECT_NE(g, f);
  g = f;
  g.points[5].x = from_bits(0x7ff8000000000001ull);
  EXPECT_NE(g, f);
  g = f;
  g.points.pop_back();
  EXPECT_NE(g, f);
}

TEST(PointSetRoundTrip, ZeroOneAndManyPoints) {
  PointSetFile empty;
  empty.found_by = "hand";
  empty.note = "nothing";
  const PointSetParseResult e = round_trip(empty);
  ASSERT_TRUE(e.ok()) << e.error;
  EXPECT_EQ(e.value, empty);
  EXPECT_TRUE(e.value.points.empty());
  EXPECT_EQ(write_point_set(empty),
            "# geomcheck case file\ngeomcheck-case 1\nquery delaunay_2d\nfound-by hand\nnote nothing\nend\n");

  PointSetFile one;
  one.points = {{0.1, -0.0}};
  EXPECT_EQ(round_trip(one).value, one);

  const std::uint64_t seed = 20261121;
  SCOPED_TRACE("seed " + std::to_string(seed));
  std::mt19937_64 rng(seed);
  PointSetFile many;
  many.found_by = "campaign seed=" + std::to_string(seed);
  for (int i = 0; i < 1000; ++i) {
    double c[2];
    for (double& x : c) x = random_boundary_double(rng);
    many.points.push_back({c[0], c[1]});
  }
  const PointSetParseResult r = round_trip(many);
  ASSERT_TRUE(r.ok()) << r.error;
  ASSERT_EQ(r.value.points.size(), 1000u);
  EXPECT_EQ(r.value, many);
}

TEST(PointSetRoundTrip, Strings) {
  expect_awkward_texts_round_trip(square_example(), &parse_point_set, &write_point_set);
}

TEST(PointSetParse, HandWrittenDecimalsCommentsAndCrlf) {
  const PointSetParseResult r = parse_point_set(hand_written({
      "note first",
      "oracle-verdict collinear # exact",
      "query delaunay_2d  # the Delaunay query",
      "note   second, # kept  ",
      "found-by hand",
      "point 1.5 -2   # decimals",
      "\tpoint\t.5 1e3",
      "   # a comment between points",
      "point -0 0x1p-1074",
      "point 0.1 +2"}));
  ASSERT_TRUE(r.ok()) << r.error;
  ASSERT_EQ(r.value.points.size(), 4u);
  EXPECT_EQ(r.value.points[0], (Vec2{1.5, -2}));
  EXPECT_EQ(r.value.points[1], (Vec2{0.5, 1000}));
  EXPECT_TRUE(std::signbit(r.value.points[2].x));
  EXPECT_EQ(bits(r.value.points[2].y), 1u);
  EXPECT_EQ(bits(r.value.points[3].x), bits(0.1));
  EXPECT_EQ(r.value.points[3].y, 2.0);
  EXPECT_EQ(r.value.oracle_verdict, "collinear");
  EXPECT_EQ(r.value.note, "first\nsecond, # kept");
  EXPECT_EQ(r.value.found_by, "hand");
  // Nothing but the header, the query and 'end'.
  const PointSetParseResult bare = parse_point_set("geomcheck-case 1\nquery delaunay_2d\nend");
  ASSERT_TRUE(bare.ok()) << bare.error;
  EXPECT_EQ(bare.value, PointSetFile{});
}

// ---------------------------------------------------------------------------
// Rejections

TEST(PointSetParse, RejectsMalformedInputs) {
  const std::string ok = kSquareExampleText;
  const std::vector<Rejection> bads = {
      {"", 1, "empty file"},
      {"# only a comment\n\n", 2, "no 'geomcheck-case' header"},
      {"query delaunay_2d\ngeomcheck-case 1\nend\n", 1,
       "expected 'geomcheck-case 1' as the first statement, got 'query'"},
      {"geomcheck-case 2\nquery delaunay_2d\nend\n", 1, "unsupported case-file version 2"},
      {"geomcheck-case one\n", 1, "malformed version 'one'"},
      {"geomcheck-case\n", 1, "missing version"},
      {"geomcheck-case 1 1\n", 1, "unexpected text '1' after the version"},
      {after_header("geomcheck-case 1\n"), 2, "duplicate 'geomcheck-case' line"},
      {after_header("query collide_cylinder_sphere\nend\n"), 2,
       "query collide_cylinder_sphere is not a point-set query: this is not a point-set file"},
      {after_header("query delaunay_3d\nend\n"), 2,
       "unknown query 'delaunay_3d': this is not a point-set file"},
      {after_header("query\n"), 2, "missing query id"},
      {after_header("query delaunay_2d extra\n"), 2, "unexpected text 'extra' after the query id"},
      {after_header("query delaunay_2d\nquery delaunay_2d\n"), 3, "duplicate 'query' line"},
      {after_header("found-by hand\nend\n"), 3, "missing 'query' line"},
      {after_header("point 0 0\nquery delaunay_2d\nend\n"), 2, "'point' before the 'query' line"},
      {with_body("", "point 0 0\nnote late\n"), 4, "'note' must come before the first 'point'"},
      {with_body("", "point 0 0\nfound-by hand\n"), 4, "'found-by' must come before the first 'point'"},
      {with_body("", "point 0 0\noracle-verdict empty\n"), 4, "'oracle-verdict' must come before the first 'point'"},
      {with_body("", "point 0 0\nquery delaunay_2d\n"), 4, "'query' must come before the first 'point'"},
      {with_body("", "point 0 0\npoint 1\n"), 4, "'point' takes 2 values (x y), got 1"},
      {with_body("", "point 1 2 3\n"), 3, "'point' takes 2 values (x y), got 3"},
      {with_body("", "point\n"), 3, "'point' takes 2 values (x y), got 0"},
      {with_body("", "point 1 # 2\n"), 3, "'point' takes 2 values (x y), got 1"},
      {with_body("", "point 1 0x1.8q+1\n"), 3, "malformed number '0x1.8q+1' in 'point'"},
      {with_body("", "point 1,5 2\n"), 3, "malformed number '1,5' in 'point'"},
      {with_body("", "point 1e400 0\n"), 3, "number '1e400' in 'point' is outside the double range"},
      {with_body("", "point 0 -1e-400\n"), 3, "number '-1e-400' in 'point' is outside the double range"},
      {with_body("", "point nan(0x0) 0\n"), 3, "bad NaN payload 'nan(0x0)' in 'point'"},
      {with_body("found-by a\nfound-by b\n", ""), 4, "duplicate 'found-by' line"},
      {with_body("oracle-verdict empty\noracle-verdict empty\n", ""), 4, "duplicate 'oracle-verdict' line"},
      {with_body("oracle-verdict overlapping\n", ""), 3,
       "unknown oracle verdict 'overlapping' for query delaunay_2d (known: triangulated, collinear, coincident, "
       "empty, rejected)"},
      {with_body("oracle-verdict\n", ""), 3, "missing verdict after 'oracle-verdict'"},
      {with_body("oracle-verdict empty now\n", ""), 3, "unexpected text 'now' after the verdict"},
      {with_body("note a\\q\n", ""), 3, "in 'note': unknown escape '\\q'"},
      {with_body("found-by a\\\n", ""), 3, "backslash at the end"},
      {with_body("", "shape sphere\n"), 3, "unknown keyword 'shape' (expected query, found-by, oracle-verdict"},
      {with_body("", "point 0 0\npoints 1 1\n"), 4, "unknown keyword 'points' (expected point or end)"},
      {ok.substr(0, ok.size() - 4), 10, "missing 'end' at the end of the file"},
      {"geomcheck-case 1\nquery delaunay_2d\npoint 0 0\n", 3, "missing 'end'"},
      {ok + "point 2 2\n", 12, "unexpected 'point' after 'end'"},
      {ok + "\n# fine\nend\n", 14, "unexpected 'end' after 'end'"},
      {with_body("", "end now\n"), 3, "unexpected text 'now' after 'end'"},
      {with_body(std::string("note a") + '\0' + "b\n", ""), 3, "control byte 0x00 in the line"},
      {with_body("", "point 0\x01 0\n"), 3, "control byte 0x01"},
      {with_body("", "point 0 0\x7f\n"), 3, "control byte 0x7f"},
      {"geomcheck-case 1\r\rquery delaunay_2d\n", 1, "control byte 0x0d"},
      {std::string(kMaxPointSetFileBytes + 1, '#'), 1, "file too large (8388609 bytes, limit 8388608)"},
  };
  std::set<std::string> messages;
  ASSERT_NO_FATAL_FAILURE(expect_all_rejected(bads, &parse_point_set, &messages));
  EXPECT_GE(messages.size(), bads.size() - 4) << "distinct errors should read differently";

  // Fine variations of the same file.
  EXPECT_TRUE(parse_point_set(ok.substr(0, ok.size() - 1)).ok()) << "no final newline";
  EXPECT_TRUE(parse_point_set(std::string(kMaxCaseFileBytes + 1, '#') + "\n" + ok).ok())
      << "beyond the shape-pair limit is fine";
}

TEST(PointSetParse, LargestFileAccepted) {
  // Just under the limit: many short point lines.
  std::string text = "geomcheck-case 1\nquery delaunay_2d\n";
  const std::string line = "point 1 2\n";
  while (text.size() + line.size() + 4 <= kMaxPointSetFileBytes) text += line;
  text += "end\n";
  ASSERT_LE(text.size(), kMaxPointSetFileBytes);
  const PointSetParseResult r = parse_point_set(text);
  ASSERT_TRUE(r.ok()) << r.error;
  EXPECT_GT(r.value.points.size(), 800000u);
  EXPECT_EQ(classify_point_set(r.value.points), "coincident");
  const PointSetParseResult over = parse_point_set(text + std::string(kMaxPointSetFileBytes + 1 - text.size(), '#'));
  ASSERT_FALSE(over.ok());
  EXPECT_EQ(over.error, "line 1: file too large (8388609 bytes, limit 8388608)");
}

TEST(PointSetParse, MutatedFilesNeverCrash) {
  // A small deterministic fuzz of the parser (fuzz_pointset_file does the long run).
  expect_mutations_round_trip_or_name_a_line(kSquareExampleText,
                                             " \t\n#0123456789abcdefpx.+-nanifpointqueryend\\\r\x01\xff", 11,
                                             &parse_point_set, &write_point_set);
}

// ---------------------------------------------------------------------------
// Validation, dispatch between the two formats

TEST(PointSetValidate, PointSetError) {
  PointSetFile f = square_example();
  f.oracle_verdict = "";
  EXPECT_FALSE(point_set_error(f).has_value());
  for (auto v : point_set_verdicts()) {
    f.oracle_verdict = std::string(v);
    EXPECT_FALSE(point_set_error(f).has_value()) << v;
  }
  EXPECT_EQ(point_set_verdicts().size(), 5u);

  expect_invalid_values_reported(square_example(), "touching", "empty\nend", &point_set_error, &parse_point_set,
                                 &write_point_set);
}

TEST(PointSetDispatch, IsPointSetText) {
  EXPECT_TRUE(is_point_set_text(kSquareExampleText));
  EXPECT_TRUE(is_point_set_text("\xEF\xBB\xBF# c\r\ngeomcheck-case 1\r\n\tquery\tdelaunay_2d # x\r\n"));
  EXPECT_TRUE(is_point_set_text("query delaunay_2d"));
  EXPECT_FALSE(is_point_set_text(""));
  EXPECT_FALSE(is_point_set_text("geomcheck-case 1\nquery collide_cylinder_sphere\nend\n"));
  EXPECT_FALSE(is_point_set_text("geomcheck-case 1\n# query delaunay_2d\nquery cast_segment_cylinder\n"));
  EXPECT_FALSE(is_point_set_text("geomcheck-case 1\nquery delaunay_2dx\n"));
  EXPECT_FALSE(is_point_set_text("geomcheck-case 1\nquery\nquery delaunay_2d\n")) << "the first query line decides";
  EXPECT_FALSE(is_point_set_text("geomcheck-case 1\nnote query delaunay_2d\n"));
}

TEST(PointSetDispatch, EachParserPointsAtTheOther) {
  const ParseResult c = parse_case(kSquareExampleText);
  ASSERT_FALSE(c.ok());
  EXPECT_EQ(c.error_line, 3);
  EXPECT_EQ(c.error.rfind("line 3: query delaunay_2d is a point-set case (see pointset_file.hpp", 0), 0u)
      << c.error;

  const PointSetParseResult p = parse_point_set(
      "geomcheck-case 1\nquery cast_segment_cylinder\nshape segment\n  a 0 0 0\n  b 1 1 1\nend\n");
  ASSERT_FALSE(p.ok());
  EXPECT_EQ(p.error_line, 2);
  EXPECT_NE(p.error.find("not a point-set file"), std::string::npos) << p.error;
  EXPECT_NE(p.error.find("parse_case"), std::string::npos) << p.error;
}

// ---------------------------------------------------------------------------
// Classification

TEST(PointSetClassify, EachVerdict) {
  EXPECT_EQ(classify_point_set({}), "empty");
  EXPECT_EQ(classify_point_set({{3, 4}}), "coincident");
  EXPECT_EQ(classify_point_set({{3, 4}, {3, 4}, {3, 4}}), "coincident");
  EXPECT_EQ(classify_point_set({{0.0, -0.0}, {-0.0, 0.0}}), "coincident") << "-0 and 0 are the same coordinate";
  EXPECT_EQ(classify_point_set({{0, 0}, {1, 0}}), "collinear");
  EXPECT_EQ(classify_point_set({{0, 0}, {0, 0}, {1, 0}, {1, 0}}), "collinear");
  EXPECT_EQ(classify_point_set({{0, 0}, {1, 1}, {2, 2}, {-5, -5}}), "collinear");
  EXPECT_EQ(classify_point_set({{1, 1}, {1, 1}, {0, 0}, {2, 2}}), "collinear") << "repeats before the second point";
  EXPECT_EQ(classify_point_set({{0, 0}, {1, 0}, {0, 1}}), "triangulated");
  EXPECT_EQ(classify_point_set({{5, 5}, {5, 5}, {6, 5}, {7, 5}, {7, 6}}), "triangulated");
  EXPECT_EQ(classify_point_set({{0, 0}, {1, 0}, {1, 1}, {0, 1}}), "triangulated");

  // Rejected wins over everything else, whatever the position of the point.
  EXPECT_EQ(classify_point_set({{nan(), 0}}), "rejected");
  EXPECT_EQ(classify_point_set({{0, 0}, {1, 0}, {0, 1}, {0, -inf()}}), "rejected");
  EXPECT_EQ(classify_point_set({{inf(), inf()}, {0, 0}}), "rejected");
  EXPECT_EQ(classify_point_set({{0, 0}, {from_bits(0xfff0000000000001ull), 1}}), "rejected");
  EXPECT_EQ(classify_point_set({{DBL_MAX, -DBL_MAX}}), "coincident") << "DBL_MAX is finite";
}

TEST(PointSetClassify, OneUlpFromCollinearIsNotCollinear) {
  // Exactly collinear, then one coordinate nudged by one ulp.
  const std::vector<Vec2> line = {{0, 0}, {1, 1}, {2, 2}, {3, 3}};
  EXPECT_EQ(classify_point_set(line), "collinear");
  for (std::size_t i = 0; i < line.size(); ++i)
    for (int c = 0; c < 2; ++c) {
      std::vector<Vec2> p = line;
      double& v = c ? p[i].y : p[i].x;
      v = up(v);
      EXPECT_EQ(classify_point_set(p), "triangulated") << "point " << i << " coordinate " << c;
    }

  // The classroom example: (12, 12), (24, 24) and p near (0.5, 0.5) on the
  // grid of step 2^-53; only the points with k == l are on the line.
  for (int k = 0; k < 5; ++k)
    for (int l = 0; l < 5; ++l) {
      const Vec2 p{0.5 + k * 0x1p-53, 0.5 + l * 0x1p-53};
      EXPECT_EQ(classify_point_set({p, {12, 12}, {24, 24}}), k == l ? "collinear" : "triangulated")
          << "k " << k << " l " << l;
    }

  // Wide magnitudes: exact in spite of overflowing and underflowing products.
  EXPECT_EQ(classify_point_set({{-1e300, -1e300}, {0, 0}, {1e300, 1e300}}), "collinear");
  EXPECT_EQ(classify_point_set({{-1e300, -1e300}, {DBL_TRUE_MIN, 0}, {1e300, 1e300}}), "triangulated");
  EXPECT_EQ(classify_point_set({{0, 0}, {DBL_TRUE_MIN, DBL_TRUE_MIN}, {1e300, 1e300}}), "collinear");
  EXPECT_EQ(classify_point_set({{0, 0}, {DBL_TRUE_MIN, 2 * DBL_TRUE_MIN}, {1e300, 1e300}}), "triangulated");
  EXPECT_EQ(classify_point_set({{DBL_MAX, DBL_MAX}, {-DBL_MAX, -DBL_MAX}, {0, 0}}), "collinear");
  EXPECT_EQ(classify_point_set({{DBL_MAX, DBL_MAX}, {-DBL_MAX, -DBL_MAX}, {0, DBL_TRUE_MIN}}), "triangulated");
}

// ---------------------------------------------------------------------------
// Fuzz input

TEST(PointSetConvert, FuzzInput) {
  EXPECT_EQ(fuzz_input_from_point_set({}), std::string(1, '\0'));
  const std::string in = fuzz_input_from_point_set({{1.0, -0.0}, {from_bits(0x7ff0000000000001ull), 2.0}});
  ASSERT_EQ(in.size(), 1u + 32u);
  EXPECT_EQ(in[0], '\0');
  const auto byte = [&](std::size_t i) { return static_cast<unsigned char>(in[i]); };
  // 1.0 = 0x3ff0000000000000, little-endian.
  for (std::size_t i = 1; i <= 6; ++i) EXPECT_EQ(byte(i), 0u) << i;
  EXPECT_EQ(byte(7), 0xf0u);
  EXPECT_EQ(byte(8), 0x3fu);
  EXPECT_EQ(byte(16), 0x80u);  // -0.0: sign bit in the last byte
  EXPECT_EQ(byte(17), 0x01u);  // NaN payload 1 in the first byte
  EXPECT_EQ(byte(24), 0x7fu);
  const std::vector<double> back = decode_raw_doubles(reinterpret_cast<const std::uint8_t*>(in.data()) + 1,
                                                      in.size() - 1, 4);
  EXPECT_EQ(bits(back[0]), bits(1.0));
  EXPECT_EQ(bits(back[1]), bits(-0.0));
  EXPECT_EQ(bits(back[2]), 0x7ff0000000000001ull);
  EXPECT_EQ(bits(back[3]), bits(2.0));
}

// ---------------------------------------------------------------------------
// Files

TEST(PointSetFiles, SaveAndLoad) {
  const fs::path dir = fresh_temp_dir("geomcheck_pointset_test_");
  PointSetFile f = square_example();
  f.points[0].x = -0.0;
  PointSetFile bad = f;
  bad.oracle_verdict = "hit";
  ASSERT_NO_FATAL_FAILURE(expect_save_and_load(dir, "0001-square.case", f, bad, &save_point_set, &load_point_set));

  {
    std::ofstream o(dir / "broken.case", std::ios::binary);
    o << "geomcheck-case 1\nquery delaunay_2d\npoint 1\nend\n";
  }
  const PointSetParseResult broken = load_point_set(dir / "broken.case");
  ASSERT_FALSE(broken.ok());
  EXPECT_EQ(broken.error, (dir / "broken.case").string() + ": line 3: 'point' takes 2 values (x y), got 1");
  EXPECT_EQ(broken.error_line, 3);

  expect_too_large_refused(dir, kMaxPointSetFileBytes + 100, 8388608, &load_point_set);
  fs::remove_all(dir);
}

// ---------------------------------------------------------------------------
// The corpora

namespace {

/// Checks one point-set file of the corpora; returns its parsed content.
PointSetFile check_corpus_file(const fs::path& f) {
  SCOPED_TRACE(f.string());
  const PointSetParseResult r = load_point_set(f);
  EXPECT_TRUE(r.ok()) << r.error;
  if (!r.ok()) return {};
  EXPECT_FALSE(point_set_error(r.value).has_value());
  EXPECT_FALSE(r.value.found_by.empty()) << "every case says how it was found";
  EXPECT_FALSE(r.value.note.empty()) << "every case says what it exercises";
  if (!r.value.oracle_verdict.empty()) {
    EXPECT_EQ(r.value.oracle_verdict, classify_point_set(r.value.points)) << "filed verdict against the content";
  }
  EXPECT_EQ(round_trip(r.value).value, r.value);
  EXPECT_TRUE(is_point_set_text(read_file(f)));
  return r.value;
}

}  // namespace

TEST(PointSetCorpus, SeedsParseAndMatchTheirVerdicts) {
  const auto files = case_files(kCorpora / "seeds" / kDelaunayQueryName);
  ASSERT_GE(files.size(), 20u) << "point-set seeds missing from " << kCorpora;
  std::map<std::string, int> per_verdict;
  for (const auto& f : files) {
    const PointSetFile p = check_corpus_file(f);
    EXPECT_FALSE(p.oracle_verdict.empty()) << f << ": every seed records its verdict";
    ++per_verdict[p.oracle_verdict];
  }
  for (auto v : point_set_verdicts()) EXPECT_GE(per_verdict[std::string(v)], 1) << "no seed of verdict " << v;
}

TEST(PointSetCorpus, SelectedSeedValues) {
  // Spot checks that the seeds hold the exact values their names promise.
  const fs::path seeds = kCorpora / "seeds" / kDelaunayQueryName;
  auto load = [&](const char* name) {
    const PointSetParseResult r = load_point_set(seeds / name);
    EXPECT_TRUE(r.ok()) << r.error;
    return r.value;
  };
  {
    const PointSetFile f = load("square-cocircular.case");
    EXPECT_EQ(f.points, square_example().points);
  }
  {
    const PointSetFile f = load("circle-radius-5-twelve-integer-points-and-centre.case");
    ASSERT_EQ(f.points.size(), 13u);
    for (std::size_t i = 0; i + 1 < f.points.size(); ++i)
      EXPECT_EQ(f.points[i].x * f.points[i].x + f.points[i].y * f.points[i].y, 25.0) << i;
    EXPECT_EQ(f.points.back(), (Vec2{0, 0}));
  }
  {
    const PointSetFile f = load("collinear-diagonal-3-5.case");
    ASSERT_EQ(f.points.size(), 21u);
    EXPECT_EQ(f.points[20], (Vec2{60, 100}));
    EXPECT_EQ(f.oracle_verdict, "collinear");
  }
  {
    const PointSetFile f = load("almost-collinear-one-ulp.case");
    EXPECT_EQ(f.oracle_verdict, "triangulated");
    bool nudged = false;
    for (const Vec2& p : f.points) nudged = nudged || p.y == up(p.x) || p.x == up(p.y);
    EXPECT_TRUE(nudged);
  }
  {
    const PointSetFile f = load("classroom-5x5-near-diagonal.case");
    ASSERT_EQ(f.points.size(), 27u);
    EXPECT_EQ(f.points[0], (Vec2{12, 12}));
    EXPECT_EQ(f.points[1], (Vec2{24, 24}));
    EXPECT_EQ(f.points[26], (Vec2{0.5 + 4 * 0x1p-53, 0.5 + 4 * 0x1p-53}));
  }
  {
    const PointSetFile f = load("tiny-subnormal.case");
    bool subnormal = false;
    for (const Vec2& p : f.points)
      subnormal = subnormal || std::fpclassify(p.x) == FP_SUBNORMAL || std::fpclassify(p.y) == FP_SUBNORMAL;
    EXPECT_TRUE(subnormal);
  }
  EXPECT_EQ(load("nan-coordinate.case").oracle_verdict, "rejected");
  EXPECT_EQ(load("infinite-coordinate.case").oracle_verdict, "rejected");
  EXPECT_EQ(load("empty.case").points.size(), 0u);
}

TEST(PointSetCorpus, RegressionsParseAndMatchTheirVerdicts) {
  int n = 0;
  for (const auto& f : case_files(kCorpora / "regressions" / kDelaunayQueryName)) {
    check_corpus_file(f);
    ++n;
  }
  std::printf("%d point-set regression files\n", n);
}
