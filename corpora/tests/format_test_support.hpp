// geomcheck — test helpers shared by the tests of the case-file formats
// (test_casefile.cpp, test_pointset_file.cpp, test_mesh_file.cpp): bit patterns, the corpora's
// files, and the checks that the formats must pass in the same way
// (rejections, mutated inputs, saving and loading).
//
// Each check takes the format's own functions (parse, write, load, save), so
// a test reads as "this format keeps the promise" and the promise is written
// once.
#pragma once

#include "geomcheck/casefile.hpp"
#include "geomcheck/detail/text_format.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <limits>
#include <optional>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include <unistd.h>

namespace geomcheck::test {

namespace fs = std::filesystem;

/// corpora/ in the source tree.
inline const fs::path kCorpora = GEOMCHECK_CORPORA_DIR;

/// The IEEE-754 bit pattern of `v`.
inline std::uint64_t bits(double v) { return detail::bits_of(v); }

using detail::from_bits;

/// +infinity.
inline double inf() { return std::numeric_limits<double>::infinity(); }

/// A random double biased towards the boundaries of each class: a quarter
/// zero or subnormal, a quarter infinite or NaN, the rest any bit pattern.
inline double random_boundary_double(std::mt19937_64& rng) {
  std::uint64_t u = rng();
  switch (rng() % 4) {
    case 0: u &= 0x800fffffffffffffull; break;  // zero / subnormal
    case 1: u |= 0x7ff0000000000000ull; break;  // inf / NaN
    default: break;
  }
  return from_bits(u);
}

/// The whole content of a file ("" when it cannot be read).
inline std::string read_file(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

/// The case files (kCaseFileExtension) directly in `dir`, sorted; none when
/// `dir` is not a folder.
inline std::vector<fs::path> case_files(const fs::path& dir) {
  std::vector<fs::path> out;
  if (!fs::is_directory(dir)) return out;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.is_regular_file() && e.path().extension() == kCaseFileExtension) out.push_back(e.path());
  std::sort(out.begin(), out.end());
  return out;
}

/// An empty folder of this process under the system's temporary folder.
inline fs::path fresh_temp_dir(const std::string& prefix) {
  const fs::path dir = fs::temp_directory_path() / (prefix + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

/// Checks that `r` is a rejection at line `line` ("line N: ..." and
/// error_line N) whose message contains `what`, with an empty value.
template <class File>
void expect_rejected(const BasicParseResult<File>& r, int line, const std::string& what) {
  ASSERT_FALSE(r.ok()) << "accepted";
  EXPECT_EQ(r.error_line, line) << r.error;
  EXPECT_EQ(r.error.rfind("line " + std::to_string(line) + ": ", 0), 0u) << r.error;
  EXPECT_NE(r.error.find(what), std::string::npos) << "message: " << r.error << "\nwanted: " << what;
  EXPECT_EQ(r.value, File{}) << "a failed parse returns an empty value";
}

/// A note that needs every escape of TEXT: leading and trailing blanks, '#',
/// an empty line, a backslash, control bytes, UTF-8 and a CR LF.
inline const char* const kAwkwardNote =
    "  leading blanks\nline two # not a comment\n\nback\\slash \x01 \x7f caf\xc3\xa9\r\ntrailing ";

/// `f` (whose found-by and note hold text to escape) written and parsed
/// back is equal to `f`, found-by and note included.
template <class File>
void expect_texts_round_trip(const File& f, BasicParseResult<File> (*parse)(std::string_view),
                             std::string (*write)(const File&)) {
  const BasicParseResult<File> r = parse(write(f));
  ASSERT_TRUE(r.ok()) << r.error;
  EXPECT_EQ(r.value.found_by, f.found_by);
  EXPECT_EQ(r.value.note, f.note);
  EXPECT_EQ(r.value, f);
}

/// expect_texts_round_trip of `f` with a found-by of two lines holding a
/// backslash, '#', a tab and a trailing blank, and the note kAwkwardNote.
template <class File>
void expect_awkward_texts_round_trip(File f, BasicParseResult<File> (*parse)(std::string_view),
                                     std::string (*write)(const File&)) {
  f.found_by = "fuzz crash-0123\n second line\\ with # and\ttab ";
  f.note = kAwkwardNote;
  expect_texts_round_trip(f, parse, write);
}

/// The statement lines `lines` framed as a hand-edited file may be: a UTF-8
/// byte-order mark and a comment line, a blank line, the header line with a
/// comment, then the lines, then "end # done", a comment line and a blank
/// line; every line ends in CR LF.
inline std::string hand_written(std::initializer_list<const char*> lines) {
  std::string text = "\xEF\xBB\xBF# written by hand\r\n\r\ngeomcheck-case 1   # version\r\n";
  for (const char* line : lines) text += std::string(line) + "\r\n";
  return text + "end # done\r\n# trailing comment\r\n\r\n";
}

/// A text a parser must reject: at line `line`, with a message that
/// contains `what`.
struct Rejection {
  std::string text;
  int line;
  const char* what;
};

/// expect_rejected for the parse of each text of `rejections` (stopping at
/// the first one accepted); the messages are added to `messages` when given.
template <class File>
void expect_all_rejected(const std::vector<Rejection>& rejections, BasicParseResult<File> (*parse)(std::string_view),
                         std::set<std::string>* messages = nullptr) {
  for (const auto& b : rejections) {
    SCOPED_TRACE(b.text.substr(0, 80));
    const BasicParseResult<File> r = parse(b.text);
    ASSERT_NO_FATAL_FAILURE(expect_rejected(r, b.line, b.what));
    if (messages) messages->insert(r.error);
  }
}

/// A small deterministic fuzz of a parser (the libFuzzer targets do the long
/// run): 20000 mutations of `base` (1 to 4 edits each: a byte replaced or
/// inserted from `alphabet`, up to 8 bytes erased, or the text cut) are each
/// accepted and round-trip through `write`, or rejected with a "line N: "
/// message; more than 100 are accepted and more than 10000 rejected.
template <class File>
void expect_mutations_round_trip_or_name_a_line(const std::string& base, std::string_view alphabet,
                                                std::uint64_t seed,
                                                BasicParseResult<File> (*parse)(std::string_view),
                                                std::string (*write)(const File&)) {
  SCOPED_TRACE("seed " + std::to_string(seed));
  std::mt19937_64 rng(seed);
  int accepted = 0, rejected = 0;
  for (int i = 0; i < 20000; ++i) {
    std::string s = base;
    const int edits = 1 + static_cast<int>(rng() % 4);
    for (int e = 0; e < edits && !s.empty(); ++e) {
      const std::size_t at = rng() % s.size();
      switch (rng() % 4) {
        case 0: s[at] = alphabet[rng() % alphabet.size()]; break;
        case 1: s.insert(at, 1, alphabet[rng() % alphabet.size()]); break;
        case 2: s.erase(at, 1 + rng() % 8); break;
        default: s.resize(at); break;
      }
    }
    const BasicParseResult<File> r = parse(s);
    if (r.ok()) {
      ++accepted;
      const BasicParseResult<File> again = parse(write(r.value));
      ASSERT_TRUE(again.ok()) << again.error;
      ASSERT_EQ(again.value, r.value) << s;
    } else {
      ++rejected;
      ASSERT_EQ(r.error.rfind("line ", 0), 0u) << r.error;
      ASSERT_GE(r.error_line, 1);
    }
  }
  EXPECT_GT(accepted, 100);
  EXPECT_GT(rejected, 10000);
}

/// The validation the formats share: `invalid` accepts `good`; with the
/// verdict `unknown_verdict`, `invalid` reports "unknown oracle verdict
/// '<verdict>'" and the written file is rejected at its verdict line (5);
/// with the verdict `two_lines` (a newline inside), `invalid` reports it and
/// the written file does not parse; with version 2, `invalid` names "version
/// 2" and the written file reads "line 2: unsupported case-file version 2
/// (this build reads version 1)".
template <class File>
void expect_invalid_values_reported(const File& good, const std::string& unknown_verdict,
                                    const std::string& two_lines,
                                    std::optional<std::string> (*invalid)(const File&),
                                    BasicParseResult<File> (*parse)(std::string_view),
                                    std::string (*write)(const File&)) {
  EXPECT_FALSE(invalid(good).has_value()) << *invalid(good);
  File f = good;
  f.oracle_verdict = unknown_verdict;
  ASSERT_TRUE(invalid(f).has_value());
  EXPECT_NE(invalid(f)->find("unknown oracle verdict '" + unknown_verdict + "'"), std::string::npos) << *invalid(f);
  EXPECT_EQ(parse(write(f)).error_line, 5);

  f = good;
  f.oracle_verdict = two_lines;
  EXPECT_TRUE(invalid(f).has_value());
  EXPECT_FALSE(parse(write(f)).ok());

  f = good;
  f.version = 2;
  ASSERT_TRUE(invalid(f).has_value());
  EXPECT_NE(invalid(f)->find("version 2"), std::string::npos);
  EXPECT_EQ(parse(write(f)).error, "line 2: unsupported case-file version 2 (this build reads version 1)");
}

/// The saving and loading the formats share, in the folder `dir`: `good`
/// saved as `name` leaves no "<name>.tmp" behind and loads back equal; the
/// invalid `bad` is refused ("refusing to write") and not written; saving
/// into a missing folder fails with "cannot create"; loading a missing file
/// fails with "cannot open case file '<path>'" and error_line 0.
template <class File>
void expect_save_and_load(const fs::path& dir, const std::string& name, const File& good, const File& bad,
                          bool (*save)(const fs::path&, const File&, std::string&),
                          BasicParseResult<File> (*load)(const fs::path&)) {
  const fs::path p = dir / name;
  std::string error;
  ASSERT_TRUE(save(p, good, error)) << error;
  EXPECT_FALSE(fs::exists(dir / (name + ".tmp")));
  const BasicParseResult<File> r = load(p);
  ASSERT_TRUE(r.ok()) << r.error;
  EXPECT_EQ(r.value, good);

  EXPECT_FALSE(save(dir / "bad.case", bad, error));
  EXPECT_NE(error.find("refusing to write"), std::string::npos) << error;
  EXPECT_FALSE(fs::exists(dir / "bad.case"));

  EXPECT_FALSE(save(dir / "no-such-dir" / "x.case", good, error));
  EXPECT_NE(error.find("cannot create"), std::string::npos) << error;

  const BasicParseResult<File> missing = load(dir / "missing.case");
  ASSERT_FALSE(missing.ok());
  EXPECT_NE(missing.error.find("cannot open case file '" + (dir / "missing.case").string() + "'"),
            std::string::npos)
      << missing.error;
  EXPECT_EQ(missing.error_line, 0);
}

/// Loading a file of `bytes` bytes ('#' each) from `dir`, beyond the
/// format's `limit`, fails with "<path>: line 1: file too large (<bytes>
/// bytes, limit <limit>)" and error_line 1.
template <class File>
void expect_too_large_refused(const fs::path& dir, std::size_t bytes, std::size_t limit,
                              BasicParseResult<File> (*load)(const fs::path&)) {
  const fs::path big = dir / "big.case";
  {
    std::ofstream out(big, std::ios::binary);
    out << std::string(bytes, '#');
  }
  const BasicParseResult<File> large = load(big);
  ASSERT_FALSE(large.ok());
  EXPECT_EQ(large.error, big.string() + ": line 1: file too large (" + std::to_string(bytes) + " bytes, limit " +
                             std::to_string(limit) + ")");
  EXPECT_EQ(large.error_line, 1);
}

}  // namespace geomcheck::test
