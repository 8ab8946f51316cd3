// geomcheck — point-set case files: bit-exact, versioned text reproductions
// of one input of the 2D Delaunay triangulation (query delaunay_2d).
//
// The Delaunay query is not a registered pair of shapes (registry.hpp): its
// input is a list of 2D points. A point-set file is a sibling of the case
// file of casefile.hpp and follows all of its conventions (header line,
// NUMBER and TEXT grammar, '#' comments, escapes, "line N: ..." errors, hex
// floats with a "%.17g" comment, bit-exact round trip); only the body
// differs. Files live in corpora/seeds/delaunay_2d/ and
// corpora/regressions/delaunay_2d/NNNN-<slug>.case.
//
//   # geomcheck case file
//   geomcheck-case 1
//   query delaunay_2d
//   found-by hand
//   oracle-verdict triangulated
//   note four cocircular points (a square)
//   point 0x0p+0 0x0p+0   # 0 0
//   point 0x1p+0 0x0p+0   # 1 0
//   point 0x1p+0 0x1p+0   # 1 1
//   point 0x0p+0 0x1p+0   # 0 1
//   end
//
// Format, version 1 (lines, blanks, comments, control bytes, TEXT and
// NUMBER exactly as in casefile.hpp):
//
//   file      := header-line meta* point-line* "end" (blank|comment)*
//   header-line = "geomcheck-case" VERSION            first statement; VERSION = 1
//   meta      := "query" "delaunay_2d"                exactly once
//              | "found-by" TEXT                      at most once
//              | "oracle-verdict" VERDICT             at most once
//              | "note" TEXT                          any number; joined with "\n"
//   point-line := "point" NUMBER NUMBER               x then y; any number of
//                                                     them, zero included
//
//   * Every meta line comes before the first "point"; "query" is required
//     and must name delaunay_2d (a file of a pair query is a case file:
//     parse_case reads it; of a mesh query a mesh file: parse_mesh_file).
//   * VERDICT is the kind of the point set, a function of its content alone
//     (classify_point_set): "triangulated" (at least 3 distinct points, not
//     all on one line), "collinear" (at least 2 distinct points, all on one
//     line), "coincident" (exactly one distinct point, possibly repeated),
//     "empty" (no points), "rejected" (some coordinate is NaN or infinite).
//     Points are distinct when their coordinates differ in value (so -0.0
//     and 0.0 are the same coordinate).
//   * The whole file is at most kMaxPointSetFileBytes (8 MiB).
//
// Every parse error reads "line N: <what is wrong>"; for an error at the end
// of the file (missing "end"), N is the last line. The parser never throws.
// For every PointSetFile f with !point_set_error(f):
// parse_point_set(write_point_set(f)).value == f bit for bit (-0.0,
// subnormals, +-inf, NaN sign and payload included).
#pragma once

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "geomcheck/casefile.hpp"
#include "geomcheck/predicates2d.hpp"

namespace geomcheck {

/// The query id of a point-set file.
inline constexpr const char* kDelaunayQueryName = "delaunay_2d";
/// Largest accepted point-set file, in bytes.
inline constexpr std::size_t kMaxPointSetFileBytes = 8 * 1024 * 1024;

/// One input of the Delaunay query.
struct PointSetFile {
  int version = kCaseFileVersion;
  std::vector<Vec2> points;
  /// The kind of the point set when filed (one of point_set_verdicts()), or
  /// empty when not recorded.
  std::string oracle_verdict;
  /// How it was found: "hand", "fuzz sha1=...", ...
  std::string found_by;
  /// Free text; may span several lines.
  std::string note;
};

/// Bit-exact equality: coordinates compare by their bit patterns (so -0.0 !=
/// 0.0 and a NaN equals a NaN with the same bits).
bool operator==(const PointSetFile& x, const PointSetFile& y);
inline bool operator!=(const PointSetFile& x, const PointSetFile& y) { return !(x == y); }

/// Outcome of parse_point_set / load_point_set: the point set, or an error
/// (BasicParseResult of casefile.hpp).
using PointSetParseResult = BasicParseResult<PointSetFile>;

/// The verdict words a point-set file may record: "triangulated",
/// "collinear", "coincident", "empty", "rejected".
std::vector<std::string_view> point_set_verdicts();

/// What makes `f` unwritable as a valid file (unsupported version, unknown
/// verdict), or nullopt when it is valid.
std::optional<std::string> point_set_error(const PointSetFile& f);

/// The point set as file text (format above). Never fails; a file with
/// point_set_error(f) is written as faithfully as possible and will not parse.
std::string write_point_set(const PointSetFile& f);

/// Parses point-set file text. Never throws.
PointSetParseResult parse_point_set(std::string_view text);

/// Reads and parses a file. A parse error reads "<path>: line N: ...";
/// an unreadable file "cannot open case file '<path>': <reason>" (error_line 0).
PointSetParseResult load_point_set(const std::filesystem::path& path);

/// Writes `f` to `path` (through a temporary file and a rename, so a reader
/// never sees half a file). Refuses a file with point_set_error(f). On
/// failure returns false and sets `error`.
bool save_point_set(const std::filesystem::path& path, const PointSetFile& f, std::string& error);

/// True when the text's query line names delaunay_2d (so tools can dispatch
/// between the two parsers without parsing twice): the first statement line
/// whose first token is "query" has "delaunay_2d" as its second token.
bool is_point_set_text(std::string_view text);

/// The verdict word for a point set computed from its content alone by the
/// definitions above (exact: collinearity by orient2d of predicates2d.hpp).
std::string_view classify_point_set(const std::vector<Vec2>& points);

/// libFuzzer input of the Delaunay fuzz target that decodes to these points:
/// one mode byte 0x00, then each point as two 8-byte little-endian doubles
/// (x then y).
std::string fuzz_input_from_point_set(const std::vector<Vec2>& points);

}  // namespace geomcheck
