// geomcheck — tests of the case-file format, the corpora and the converters.
//
// Fixed seeds throughout (printed with each randomized test). The corpus
// tests read GEOMCHECK_CORPORA_DIR (corpora/ in the source tree).
#include "geomcheck/casefile.hpp"

#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <cstdio>
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

/// The example of the format documentation: a sphere touching the rim circle.
CaseFile rim_example() {
  return from_case<QueryId::collide_cylinder_sphere>({Cylinder{{0, 0, 0}, {0, 0, 2}, 1}, Sphere{{2, 0, 2}, 1}}, "hand",
                                                     "touching", "sphere touching the rim circle from outside");
}

const char* const kRimExampleText =
    "# geomcheck case file\n"
    "geomcheck-case 1\n"
    "query collide_cylinder_sphere\n"
    "found-by hand\n"
    "oracle-verdict touching\n"
    "note sphere touching the rim circle from outside\n"
    "shape cylinder\n"
    "  p 0x0p+0 0x0p+0 0x0p+0   # 0 0 0\n"
    "  q 0x0p+0 0x0p+0 0x1p+1   # 0 0 2\n"
    "  r 0x1p+0                 # 1\n"
    "shape sphere\n"
    "  c 0x1p+1 0x0p+0 0x1p+1   # 2 0 2\n"
    "  r 0x1p+0                 # 1\n"
    "end\n";

ParseResult round_trip(const CaseFile& c) { return parse_case(write_case(c)); }

}  // namespace

// ---------------------------------------------------------------------------
// Numbers

TEST(CaseNumbers, FormatMatchesPrintfHexFloat) {
  const double values[] = {0.0,     1.0,      3.0,       0.1,       -2.5,     1.0 / 3,   1e300,
                           DBL_MAX, DBL_MIN,  DBL_TRUE_MIN, DBL_MIN / 3, 1e-310, -1e-310, 6.02214076e23};
  for (double v : values) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%a", v);
    EXPECT_EQ(format_double(v), buf) << "value " << buf;
    std::snprintf(buf, sizeof buf, "%.17g", v);
    EXPECT_EQ(format_decimal(v), buf) << "value " << buf;
  }
  EXPECT_EQ(format_double(3.0), "0x1.8p+1");
  EXPECT_EQ(format_double(-0.0), "-0x0p+0");
  EXPECT_EQ(format_double(0.0), "0x0p+0");
  EXPECT_EQ(format_double(DBL_TRUE_MIN), "0x0.0000000000001p-1022");
  EXPECT_EQ(format_double(DBL_MAX), "0x1.fffffffffffffp+1023");
  EXPECT_EQ(format_double(inf()), "inf");
  EXPECT_EQ(format_double(-inf()), "-inf");
  EXPECT_EQ(format_double(std::numeric_limits<double>::quiet_NaN()), "nan");
  EXPECT_EQ(format_double(-std::numeric_limits<double>::quiet_NaN()), "-nan");
  EXPECT_EQ(format_double(from_bits(0x7ff0000000000001ull)), "nan(0x1)");
  EXPECT_EQ(format_double(from_bits(0xfff8000000000abcull)), "-nan(0x8000000000abc)");
  EXPECT_EQ(format_decimal(0.1), "0.10000000000000001");
  EXPECT_EQ(format_decimal(-0.0), "-0");
  EXPECT_EQ(format_decimal(-inf()), "-inf");
}

TEST(CaseNumbers, ParseAcceptsHexDecimalAndNonFinite) {
  struct Ok {
    const char* text;
    std::uint64_t bits;
  };
  const Ok oks[] = {
      {"0x1.8p+1", bits(3.0)},
      {"0X1.8P+1", bits(3.0)},
      {"-0x0p+0", bits(-0.0)},
      {"-0", bits(-0.0)},
      {"+2", bits(2.0)},
      {"1.5", bits(1.5)},
      {".5", bits(0.5)},
      {"1e3", bits(1000.0)},
      {"0.1", bits(0.1)},
      {"0x1p-1074", bits(DBL_TRUE_MIN)},
      {"0x0.0000000000001p-1022", bits(DBL_TRUE_MIN)},
      {"4.9406564584124654e-324", bits(DBL_TRUE_MIN)},
      {"0x1.fffffffffffffp+1023", bits(DBL_MAX)},
      {"inf", bits(inf())},
      {"+INF", bits(inf())},
      {"-inf", bits(-inf())},
      {"Infinity", bits(inf())},
      {"nan", 0x7ff8000000000000ull},
      {"NaN", 0x7ff8000000000000ull},
      {"-nan", 0xfff8000000000000ull},
      {"nan(0x1)", 0x7ff0000000000001ull},
      {"-nan(0x8000000000abc)", 0xfff8000000000abcull},
      {"nan(0xFFFFFFFFFFFFF)", 0x7fffffffffffffffull},
  };
  for (const auto& ok : oks) {
    const auto v = parse_double(ok.text);
    ASSERT_TRUE(v.has_value()) << ok.text;
    EXPECT_EQ(bits(*v), ok.bits) << ok.text;
  }
  const char* bad[] = {"",        "+",        "-",         "0x",        "0xp1",      "1e",
                       "1.5.2",   "0x1.8q+1", "nan(0x0)",  "nan(1)",    "nan(0x)",   "nan(0x10000000000000)",
                       "1e400",   "-1e400",   "1e-400",    "0x1p+1024", "0x1p-1075", "--1",
                       "0x-1",    "inf1",     "infinite",  "1,5",       "abc",       "0x1p",
                       "nan(0x1", "1 ",       " 1",        "e5"};
  for (const char* b : bad) EXPECT_FALSE(parse_double(b).has_value()) << "'" << b << "'";
}

// ---------------------------------------------------------------------------
// Writing and round trips

TEST(CaseWrite, ExactLayout) {
  EXPECT_EQ(write_case(rim_example()), kRimExampleText);
}

TEST(CaseParse, DocumentationExample) {
  const ParseResult r = parse_case(kRimExampleText);
  ASSERT_TRUE(r.ok()) << r.error;
  EXPECT_EQ(r.value.query, QueryId::collide_cylinder_sphere);
  EXPECT_EQ(r.value.a, (std::vector<double>{0, 0, 0, 0, 0, 2, 1}));
  EXPECT_EQ(r.value.b, (std::vector<double>{2, 0, 2, 1}));
  EXPECT_EQ(r.value.oracle_verdict, "touching");
  EXPECT_EQ(r.value.found_by, "hand");
  EXPECT_EQ(r.value.note, "sphere touching the rim circle from outside");
  EXPECT_EQ(r.value, rim_example());
}

TEST(CaseRoundTrip, SpecialValuesBitExact) {
  CaseFile c;
  c.query = QueryId::collide_cylinder_sphere;
  c.a = {-0.0, DBL_TRUE_MIN, -DBL_MIN / 3, DBL_MAX, -DBL_MAX, inf(), -inf()};
  c.b = {std::numeric_limits<double>::quiet_NaN(), -std::numeric_limits<double>::quiet_NaN(),
         from_bits(0x7ff0000000000001ull) /* signalling */, from_bits(0xfffabcdef0123456ull)};
  const ParseResult r = round_trip(c);
  ASSERT_TRUE(r.ok()) << r.error << "\n" << write_case(c);
  EXPECT_EQ(r.value, c);
  EXPECT_TRUE(std::signbit(r.value.a[0]));
  EXPECT_EQ(r.value.a[0], 0.0);
  EXPECT_EQ(bits(r.value.a[1]), 1u);
  EXPECT_EQ(r.value.a[3], DBL_MAX);
  EXPECT_EQ(r.value.a[6], -inf());
  EXPECT_EQ(bits(r.value.b[0]), 0x7ff8000000000000ull);
  EXPECT_EQ(bits(r.value.b[1]), 0xfff8000000000000ull);
  EXPECT_EQ(bits(r.value.b[2]), 0x7ff0000000000001ull);
  EXPECT_EQ(bits(r.value.b[3]), 0xfffabcdef0123456ull);
  // Equality is bit equality: +0 and -0 differ.
  CaseFile d = c;
  d.a[0] = 0.0;
  EXPECT_NE(d, c);
}

TEST(CaseRoundTrip, RandomBitPatterns) {
  const std::uint64_t seed = 20240601;
  SCOPED_TRACE("seed " + std::to_string(seed));
  std::mt19937_64 rng(seed);
  int checked = 0;
  for (int i = 0; i < 2000; ++i) {
    CaseFile c;
    c.query = kQueries[static_cast<std::size_t>(i) % kNumQueries].id;
    c.a.resize(query_shape(c.query, 0).size);
    c.b.resize(query_shape(c.query, 1).size);
    for (auto* v : {&c.a, &c.b})
      for (double& x : *v) x = random_boundary_double(rng);
    c.found_by = "campaign seed=" + std::to_string(seed) + " case=" + std::to_string(i);
    const ParseResult r = round_trip(c);
    ASSERT_TRUE(r.ok()) << r.error << "\n" << write_case(c);
    ASSERT_EQ(r.value, c) << write_case(c);
    ++checked;
  }
  EXPECT_EQ(checked, 2000);
}

TEST(CaseRoundTrip, Strings) {
  CaseFile c = rim_example();
  c.found_by = "rapidcheck reproduce=BchdlNGdvJ3XzxWY\n and a second line\\ with # and\ttab ";
  c.note = kAwkwardNote;
  ASSERT_NO_FATAL_FAILURE(expect_texts_round_trip(c, &parse_case, &write_case));
  const std::string text = write_case(c);
  EXPECT_NE(text.find("note \\x20 leading blanks\n"), std::string::npos) << text;
  EXPECT_NE(text.find("note line two # not a comment\nnote\nnote back\\\\slash \\x01 \\x7f caf\xc3\xa9\\r\n"),
            std::string::npos)
      << text;

  // A note of empty lines only, and an empty note.
  for (const char* note : {"\n", "\n\n", "", "x\n"}) {
    c.note = note;
    const ParseResult n = round_trip(c);
    ASSERT_TRUE(n.ok()) << n.error;
    EXPECT_EQ(n.value.note, note);
  }
}

TEST(CaseParse, HandWrittenDecimalsCommentsAndCrlf) {
  const ParseResult r = parse_case(hand_written({
      "note first",
      "oracle-verdict hit # exact",
      "query cast_segment_cylinder",
      "note   second, # kept  ",
      "shape segment  # A",
      "b 1.5 -2 3e0",
      "\ta\t0x1p-1 .25 -0",
      "   # a comment inside a block",
      "shape cylinder",
      "  r inf",
      "  q -inf nan 1",
      "  p 0 0 0"}));
  ASSERT_TRUE(r.ok()) << r.error;
  EXPECT_EQ(r.value.query, QueryId::cast_segment_cylinder);
  ASSERT_EQ(r.value.a.size(), 6u);
  EXPECT_EQ(r.value.a[0], 0.5);
  EXPECT_EQ(r.value.a[1], 0.25);
  EXPECT_TRUE(std::signbit(r.value.a[2]));
  EXPECT_EQ(r.value.a[3], 1.5);
  EXPECT_EQ(r.value.a[4], -2.0);
  EXPECT_EQ(r.value.a[5], 3.0);
  ASSERT_EQ(r.value.b.size(), 7u);
  EXPECT_EQ(r.value.b[0], 0.0);
  EXPECT_EQ(r.value.b[3], -inf());
  EXPECT_TRUE(std::isnan(r.value.b[4]));
  EXPECT_EQ(r.value.b[5], 1.0);
  EXPECT_EQ(r.value.b[6], inf());
  EXPECT_EQ(r.value.oracle_verdict, "hit");
  EXPECT_EQ(r.value.note, "first\nsecond, # kept");
  EXPECT_EQ(r.value.found_by, "");
  const auto typed = to_case<QueryId::cast_segment_cylinder>(r.value);
  EXPECT_EQ(typed.a.b.y, -2.0);
  EXPECT_EQ(typed.b.r, inf());
}

// ---------------------------------------------------------------------------
// Rejections

TEST(CaseParse, MalformedCorpusFiles) {
  const auto files = case_files(kCorpora / "tests" / "malformed");
  ASSERT_GE(files.size(), 25u) << "malformed corpus missing from " << kCorpora;
  std::set<std::string> messages;
  for (const auto& f : files) {
    SCOPED_TRACE(f.filename().string());
    const std::string text = read_file(f);
    // First line: "# expect-error: line N: <text the message must contain>".
    const std::string tag = "# expect-error: ";
    ASSERT_EQ(text.rfind(tag, 0), 0u) << "no expect-error line";
    const std::string expect = text.substr(tag.size(), text.find('\n') - tag.size());
    const std::size_t colon = expect.find(": ");
    ASSERT_EQ(expect.rfind("line ", 0), 0u);
    ASSERT_NE(colon, std::string::npos);
    const int line = std::stoi(expect.substr(5, colon - 5));
    const std::string what = expect.substr(colon + 2);
    ASSERT_FALSE(what.empty());

    const ParseResult r = parse_case(text);
    ASSERT_NO_FATAL_FAILURE(expect_rejected(r, line, what));
    messages.insert(r.error);

    const ParseResult l = load_case(f);
    ASSERT_FALSE(l.ok());
    EXPECT_EQ(l.error, f.string() + ": " + r.error);
    EXPECT_EQ(l.error_line, line);
  }
  EXPECT_EQ(messages.size(), files.size()) << "two malformed files give the same message";
}

TEST(CaseParse, RejectsGeneratedInputs) {
  const std::string ok = kRimExampleText;
  const std::vector<Rejection> bads = {
      {"", 1, "empty file"},
      {"# only a comment\n\n", 2, "no 'geomcheck-case' header"},
      {std::string(kMaxCaseFileBytes + 1, '#'), 1, "file too large (65537 bytes, limit 65536)"},
      {ok.substr(0, ok.size() - 4), 13, "missing 'end'"},
      {std::string("geomcheck-case 1\nquery collide_cylinder_sphere\nnote a") + '\0' + "b\n", 3,
       "control byte 0x00"},
      {"geomcheck-case 1\nquery collide_cylinder_sphere\nend\n", 3, "missing shape A (cylinder)"},
      {"geomcheck-case 1\nend\n", 2, "missing 'query'"},
      {"geomcheck-case 99999999999999999999\n", 1, "malformed version"},
      {"geomcheck-case\n", 1, "missing version"},
      {"geomcheck-case 1\nquery\n", 2, "missing query id"},
      {"geomcheck-case 1\nshape\n", 2, "missing shape kind"},
      {"geomcheck-case 1\nquery collide_cylinder_sphere\nfound-by a\\\n", 3, "backslash at the end"},
      {"geomcheck-case 1\nquery collide_cylinder_sphere\nnote \\x4\n", 3, "two hex digits"},
  };
  ASSERT_NO_FATAL_FAILURE(expect_all_rejected(bads, &parse_case));

  // Fine variation of the same file.
  const ParseResult unterminated_line = parse_case(ok.substr(0, ok.size() - 1));
  EXPECT_TRUE(unterminated_line.ok()) << "no final newline: " << unterminated_line.error;
}

TEST(CaseParse, MutatedFilesNeverCrash) {
  // A small deterministic fuzz of the parser (fuzz_casefile does the long run).
  expect_mutations_round_trip_or_name_a_line(kRimExampleText,
                                             " \t\n#0123456789abcdefpx.+-nanifcqrshapeendquery\\\r\x01\xff", 7,
                                             &parse_case, &write_case);
}

// ---------------------------------------------------------------------------
// Validation, typed views

TEST(CaseValidate, CaseError) {
  ASSERT_NO_FATAL_FAILURE(
      expect_invalid_values_reported(rim_example(), "hit", "touching\nend", &case_error, &parse_case, &write_case));

  CaseFile c = rim_example();
  c.a.pop_back();
  ASSERT_TRUE(case_error(c).has_value());
  EXPECT_NE(case_error(c)->find("needs 7 doubles, the case has 6"), std::string::npos) << *case_error(c);
  // Written as it is, it does not parse back.
  const ParseResult r = round_trip(c);
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error, "line 10: field 'r' of cylinder takes 1 value, got 0");

  c = rim_example();
  c.b.push_back(1.0);
  EXPECT_NE(case_error(c)->find("shape B"), std::string::npos);
  EXPECT_FALSE(round_trip(c).ok());

  c = rim_example();
  c.query = static_cast<QueryId>(1000);
  EXPECT_FALSE(is_registered(c.query));
  EXPECT_NE(case_error(c)->find("unregistered"), std::string::npos);
  EXPECT_NE(round_trip(c).error.find("unknown query 'unregistered-query-1000'"), std::string::npos);
  EXPECT_EQ(query_shape(c.query, 0).size, 0u);
}

TEST(CaseTyped, ToAndFromCase) {
  using Q = QueryTraits<QueryId::cast_segment_cylinder>;
  Q::Case k{Segment{{1, 2, 3}, {4, 5, 6}}, Cylinder{{7, 8, 9}, {10, 11, 12}, 13}};
  const CaseFile f = from_case<QueryId::cast_segment_cylinder>(k, "hand", "miss", "n");
  EXPECT_EQ(f.query, QueryId::cast_segment_cylinder);
  EXPECT_EQ(f.a, (std::vector<double>{1, 2, 3, 4, 5, 6}));
  EXPECT_EQ(f.b, (std::vector<double>{7, 8, 9, 10, 11, 12, 13}));
  EXPECT_EQ(f.found_by, "hand");
  EXPECT_EQ(f.oracle_verdict, "miss");
  EXPECT_EQ(f.note, "n");
  const auto back = to_case<QueryId::cast_segment_cylinder>(f);
  EXPECT_EQ(back.a.b, (Vec3{4, 5, 6}));
  EXPECT_EQ(back.b.q, (Vec3{10, 11, 12}));
  EXPECT_EQ(back.b.r, 13.0);

  // Short vectors are zero padded (no out-of-range read).
  CaseFile s = f;
  s.a = {1};
  s.b.clear();
  const auto padded = to_case<QueryId::cast_segment_cylinder>(s);
  EXPECT_EQ(padded.a.a, (Vec3{1, 0, 0}));
  EXPECT_EQ(padded.b.r, 0.0);

  // visit_case dispatches on the runtime id.
  const double r = visit_case(rim_example(), [](auto q, const auto& typed) -> double {
    if constexpr (decltype(q)::value == QueryId::collide_cylinder_sphere) return typed.b.c.x;
    return -1;
  });
  EXPECT_EQ(r, 2.0);

  const ShapeLayout cyl = query_shape(QueryId::collide_cylinder_sphere, 0);
  EXPECT_EQ(cyl.kind, "cylinder");
  EXPECT_EQ(cyl.size, 7u);
  EXPECT_EQ(query_shape(QueryId::cast_segment_cylinder, 0).kind, "segment");
  EXPECT_EQ(query_shape(QueryId::cast_segment_cylinder, 1).kind, "cylinder");
  EXPECT_TRUE(is_known_verdict(QueryKind::Cast, "miss"));
  EXPECT_FALSE(is_known_verdict(QueryKind::Collide, "miss"));
}

// ---------------------------------------------------------------------------
// Files

TEST(CaseFiles, SaveAndLoad) {
  const fs::path dir = fresh_temp_dir("geomcheck_casefile_test_");
  CaseFile c = rim_example();
  c.a[0] = -0.0;
  CaseFile bad = c;
  bad.b.clear();
  ASSERT_NO_FATAL_FAILURE(expect_save_and_load(dir, "0001-rim.case", c, bad, &save_case, &load_case));
  expect_too_large_refused(dir, 200000, 65536, &load_case);
  fs::remove_all(dir);
}

// ---------------------------------------------------------------------------
// The corpora

TEST(Corpus, SeedsParseAndMatchTheirQuery) {
  std::map<std::string, int> per_query;
  for (const auto& q : kQueries) {
    for (const auto& f : case_files(kCorpora / "seeds" / q.name)) {
      SCOPED_TRACE(f.string());
      const ParseResult r = load_case(f);
      ASSERT_TRUE(r.ok()) << r.error;
      EXPECT_EQ(r.value.query, q.id) << "seed filed under the wrong query folder";
      EXPECT_FALSE(case_error(r.value).has_value());
      EXPECT_FALSE(r.value.found_by.empty()) << "every case says how it was found";
      EXPECT_FALSE(r.value.note.empty()) << "every seed says what it exercises";
      EXPECT_EQ(round_trip(r.value).value, r.value);
      ++per_query[q.name];
    }
  }
  EXPECT_GE(per_query["collide_cylinder_sphere"], 8);
  EXPECT_GE(per_query["cast_segment_cylinder"], 8);
  EXPECT_GE(per_query["collide_cylinder_cylinder"], 8);
  // Every seed folder is a registered pair query's, or another family's
  // (point sets, meshes: their own formats and tests, test_pointset_file and
  // test_mesh_file).
  for (const auto& dir : fs::directory_iterator(kCorpora / "seeds")) {
    if (!dir.is_directory()) continue;
    const auto family = family_of(dir.path().filename().string());
    if (family && *family != QueryFamily::Pair) continue;
    EXPECT_TRUE(query_from_name(dir.path().filename().string()).has_value())
        << "seeds folder of an unknown query: " << dir.path();
  }
}

TEST(Corpus, SelectedSeedValues) {
  // Spot checks that the seeds hold the exact values their names promise.
  const fs::path seeds = kCorpora / "seeds";
  {
    const ParseResult r = load_case(seeds / "collide_cylinder_sphere" / "rim-touch-outside.case");
    ASSERT_TRUE(r.ok()) << r.error;
    const auto k = to_case<QueryId::collide_cylinder_sphere>(r.value);
    EXPECT_EQ(r.value.oracle_verdict, "touching");
    // Rim point (3, 4, 10); centre 5 further out radially and 12 up: 5-12-13.
    EXPECT_EQ(k.a.r, 5.0);
    EXPECT_EQ(k.b.c, (Vec3{6, 8, 22}));
    EXPECT_EQ(k.b.r, 13.0);
  }
  {
    const ParseResult r = load_case(seeds / "collide_cylinder_sphere" / "cap-separated-by-one-ulp.case");
    ASSERT_TRUE(r.ok()) << r.error;
    const auto k = to_case<QueryId::collide_cylinder_sphere>(r.value);
    EXPECT_EQ(r.value.oracle_verdict, "separated");
    EXPECT_EQ(k.b.c.z, std::nextafter(3.0, 4.0));
  }
  {
    const ParseResult r = load_case(seeds / "cast_segment_cylinder" / "miss-just-past-rim.case");
    ASSERT_TRUE(r.ok()) << r.error;
    const auto k = to_case<QueryId::cast_segment_cylinder>(r.value);
    EXPECT_EQ(r.value.oracle_verdict, "miss");
    EXPECT_EQ(k.a.a.x, std::nextafter(1.0, 2.0));
  }
}

TEST(Corpus, RegressionsParseAndMatchTheirQuery) {
  const fs::path root = kCorpora / "regressions";
  int n = 0;
  if (fs::is_directory(root)) {
    for (const auto& dir : fs::directory_iterator(root)) {
      if (!dir.is_directory()) continue;
      // Point sets and meshes have their own formats and tests (test_pointset_file, test_mesh_file).
      const auto family = family_of(dir.path().filename().string());
      if (family && *family != QueryFamily::Pair) continue;
      const auto q = query_from_name(dir.path().filename().string());
      EXPECT_TRUE(q.has_value()) << "regressions folder of an unknown query: " << dir.path();
      for (const auto& f : case_files(dir.path())) {
        SCOPED_TRACE(f.string());
        const ParseResult r = load_case(f);
        ASSERT_TRUE(r.ok()) << r.error;
        if (q) {
          EXPECT_EQ(r.value.query, *q);
        }
        EXPECT_FALSE(r.value.found_by.empty());
        ++n;
      }
    }
  }
  std::printf("%d regression case files\n", n);
}

// ---------------------------------------------------------------------------
// Converters

TEST(CaseConvert, DecodeRawDoubles) {
  const std::uint8_t one[] = {0, 0, 0, 0, 0, 0, 0xf0, 0x3f};  // 1.0
  auto v = decode_raw_doubles(one, sizeof one, 2);
  ASSERT_EQ(v.size(), 2u);
  EXPECT_EQ(v[0], 1.0);
  EXPECT_EQ(bits(v[1]), 0u);
  // Missing high bytes are zero: 7 bytes of 1.0 give 0x00f0000000000000.
  v = decode_raw_doubles(one, 7, 1);
  EXPECT_EQ(bits(v[0]), 0x00f0000000000000ull);
  // Bytes beyond 8 * count are ignored; null data with size 0 is all zeros.
  const std::uint8_t two[] = {0, 0, 0, 0, 0, 0, 0, 0x80, 0xff, 0xff};
  v = decode_raw_doubles(two, sizeof two, 1);
  EXPECT_EQ(bits(v[0]), 0x8000000000000000ull);
  v = decode_raw_doubles(nullptr, 0, 3);
  EXPECT_EQ(v, (std::vector<double>{0, 0, 0}));
  // encode is the inverse.
  const std::vector<double> w = {-0.0, 1.5, from_bits(0x7ff0000000000001ull)};
  const auto bytes = encode_raw_doubles(w);
  ASSERT_EQ(bytes.size(), 24u);
  EXPECT_EQ(bytes[7], 0x80);
  EXPECT_EQ(bytes[16], 0x01);
  const auto back = decode_raw_doubles(bytes.data(), bytes.size(), 3);
  for (int i = 0; i < 3; ++i) EXPECT_EQ(bits(back[i]), bits(w[i]));
}

TEST(CaseConvert, Sha1) {
  const std::string abc = "abc";
  EXPECT_EQ(sha1_hex(reinterpret_cast<const std::uint8_t*>(abc.data()), abc.size()),
            "a9993e364706816aba3e25717850c26c9cd0d89d");
  EXPECT_EQ(sha1_hex(nullptr, 0), "da39a3ee5e6b4b0d3255bfef95601890afd80709");
  const std::string s56 = "abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq";
  EXPECT_EQ(sha1_hex(reinterpret_cast<const std::uint8_t*>(s56.data()), s56.size()),
            "84983e441c3bd26ebaae4aa1f95129e5e54670f1");
  const std::string million(1000000, 'a');
  EXPECT_EQ(sha1_hex(reinterpret_cast<const std::uint8_t*>(million.data()), million.size()),
            "34aa973cd4c4daa4f61eeb2bdbad27316534016f");
}

TEST(CaseConvert, FromFuzzInput) {
  const CaseFile want = rim_example();
  const auto bytes = fuzz_input_from_case(want);
  ASSERT_EQ(bytes.size(), 8u * 11);
  const CaseFile c = case_from_fuzz_input(QueryId::collide_cylinder_sphere, bytes.data(), bytes.size());
  EXPECT_EQ(c.query, QueryId::collide_cylinder_sphere);
  EXPECT_EQ(c.a, want.a);
  EXPECT_EQ(c.b, want.b);
  EXPECT_EQ(c.found_by, "fuzz sha1=" + sha1_hex(bytes.data(), bytes.size()));
  EXPECT_EQ(c.found_by.size(), 5u + 5u + 40u);
  EXPECT_FALSE(case_error(c).has_value());
  EXPECT_EQ(round_trip(c).value, c);

  // Short input: the segment takes the first 6 doubles, the cylinder the next
  // 7, the missing ones are zero.
  const std::uint8_t short_input[] = {0, 0, 0, 0, 0, 0, 0xf0, 0x3f, 0, 0, 0, 0, 0, 0, 0, 0xc0};
  const CaseFile s = case_from_fuzz_input(QueryId::cast_segment_cylinder, short_input, sizeof short_input,
                                          "crash-0123456789abcdef0123456789abcdef01234567");
  EXPECT_EQ(s.a, (std::vector<double>{1, -2, 0, 0, 0, 0}));
  EXPECT_EQ(s.b, std::vector<double>(7, 0.0));
  EXPECT_EQ(s.found_by, "fuzz crash-0123456789abcdef0123456789abcdef01234567");
  EXPECT_NE(s.note.find("zero-padded"), std::string::npos);
}

TEST(CaseConvert, DescribeShape) {
  EXPECT_EQ(describe_shape(Cylinder{{0, 0, 0}, {0, 0, 2}, 1}),
            "cylinder{p=(0x0p+0, 0x0p+0, 0x0p+0), q=(0x0p+0, 0x0p+0, 0x1p+1), r=0x1p+0}");
  EXPECT_EQ(describe_shape(Sphere{{-0.0, 0.5, 3}, inf()}), "sphere{c=(-0x0p+0, 0x1p-1, 0x1.8p+1), r=inf}");
  EXPECT_EQ(describe_shape(Segment{{1, 1, 1}, {2, 2, 2}}),
            "segment{a=(0x1p+0, 0x1p+0, 0x1p+0), b=(0x1p+1, 0x1p+1, 0x1p+1)}");
  EXPECT_EQ(describe_shape(Capsule{{0, 0, 0}, {1, 0, 0}, 0.25}),
            "capsule{p=(0x0p+0, 0x0p+0, 0x0p+0), q=(0x1p+0, 0x0p+0, 0x0p+0), r=0x1p-2}");
  EXPECT_EQ(describe_shape(Triangle{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}),
            "triangle{a=(0x0p+0, 0x0p+0, 0x0p+0), b=(0x1p+0, 0x0p+0, 0x0p+0), c=(0x0p+0, 0x1p+0, 0x0p+0)}");
  const std::string obb = describe_shape(Obb{});
  EXPECT_EQ(obb.rfind("obb{c=(0x0p+0, 0x0p+0, 0x0p+0), u0=(0x1p+0, 0x0p+0, 0x0p+0), u1=", 0), 0u) << obb;
}

TEST(CaseConvert, FromRapidCheckText) {
  const Cylinder cyl{{0, 0, 0}, {0, 0, 2}, std::nextafter(1.0, 0.0)};
  const Sphere sph{{2, -0.0, 2}, 1};
  const std::string text =
      "Using configuration: seed=9811620496233405862\n"
      "Falsifiable after 31 tests and 7 shrinks\n\n"
      "std::tuple<geomcheck::Cylinder, geomcheck::Sphere>:\n"
      "(hypercylinder{p=(0x1p+0, 0, 0), q=(0, 0, 0), r=0}, cylinder{p=broken}, " +
      describe_shape(cyl) + ", " + describe_shape(sph) +
      ")\n\n"
      "properties/tests/test_properties.cpp:120:\n"
      "RC_ASSERT(agrees)\n\n"
      "Some of your RapidCheck properties had failures. To reproduce these, run with:\n"
      "RC_PARAMS=\"reproduce=BchdlNGdvJ3XzxWYoRHIvZGIpNnbl9FajlGc0lmbkBSYg42bgI3bvN2bl92Y\"\n";
  const auto c = case_from_rapidcheck_text(QueryId::collide_cylinder_sphere, text);
  ASSERT_TRUE(c.has_value());
  const CaseFile want = from_case<QueryId::collide_cylinder_sphere>({cyl, sph});
  EXPECT_EQ(c->a, want.a);
  EXPECT_EQ(c->b, want.b);
  EXPECT_TRUE(std::signbit(c->b[1]));
  EXPECT_EQ(c->found_by,
            "rapidcheck reproduce=BchdlNGdvJ3XzxWYoRHIvZGIpNnbl9FajlGc0lmbkBSYg42bgI3bvN2bl92Y");
  EXPECT_FALSE(case_error(*c).has_value());

  // Hand-edited spacing, fields in another order, decimals and non-finite values.
  const auto d = case_from_rapidcheck_text(
      QueryId::cast_segment_cylinder,
      "segment{ b = ( 1 , 2 , 3 ) , a=(nan(0x1), -inf, 0.5) } then cylinder{r=2, p=(0,0,0), q=(0,0,1)}");
  ASSERT_TRUE(d.has_value());
  EXPECT_EQ(bits(d->a[0]), 0x7ff0000000000001ull);
  EXPECT_EQ(d->a[1], -inf());
  EXPECT_EQ(d->a[2], 0.5);
  EXPECT_EQ(d->a[5], 3.0);
  EXPECT_EQ(d->b, (std::vector<double>{0, 0, 0, 0, 0, 1, 2}));
  EXPECT_EQ(d->found_by, "rapidcheck");

  // B must follow A; missing or malformed shapes give nothing.
  EXPECT_FALSE(case_from_rapidcheck_text(QueryId::collide_cylinder_sphere,
                                         describe_shape(sph) + " " + describe_shape(cyl)));
  EXPECT_FALSE(case_from_rapidcheck_text(QueryId::collide_cylinder_sphere, describe_shape(cyl)));
  EXPECT_FALSE(case_from_rapidcheck_text(QueryId::collide_cylinder_sphere,
                                         "cylinder{p=(0,0,0), q=(0,0,1)} sphere{c=(0,0,0), r=1}"));
  EXPECT_FALSE(case_from_rapidcheck_text(QueryId::collide_cylinder_sphere, ""));
  EXPECT_FALSE(case_from_rapidcheck_text(static_cast<QueryId>(99), text));
}
