// geomcheck — case files: bit-exact, versioned text reproductions of one query case.
//
// A case file names a registered query (registry.hpp), holds the raw doubles
// of its two shapes in ShapeTraits order, and records how the case was found
// and what the exact oracle said when it was filed. Doubles are written as
// hex floats (C "%a" form in the C locale) followed by a "%.17g" decimal
// comment, so a file reproduces a case bit for bit and a person can still
// read it. Files live in corpora/seeds/<query-id>/ (hand cases, fuzz seeds)
// and corpora/regressions/<query-id>/NNNN-<slug>.case (counterexamples,
// never deleted). The Delaunay query's inputs (point lists, not a registered
// pair of shapes) use the sibling format of pointset_file.hpp, the mesh
// queries' (a cylinder and a triangle mesh) that of mesh_file.hpp; the text
// conventions the formats share are implemented once, in
// geomcheck/detail/text_format.hpp.
//
// Format, version 1. Lines end in LF (a CR before the LF is ignored); blank
// lines and lines whose first non-blank character is '#' are ignored
// anywhere; space and tab separate tokens; other control bytes are errors.
//
//   file      := header-line meta* shape-block shape-block "end" (blank|comment)*
//   header-line = "geomcheck-case" VERSION            first statement; VERSION = 1
//   meta      := "query" QUERY-ID                     exactly once
//              | "found-by" TEXT                      at most once
//              | "oracle-verdict" VERDICT             at most once
//              | "note" TEXT                          any number; joined with "\n"
//   shape-block := "shape" KIND field-line*           KIND of the query's shape A,
//                                                     then of its shape B
//   field-line  := NAME NUMBER{arity}                 each field of KIND exactly
//                                                     once, in any order
//
//   * Every meta line comes before the first "shape"; "query" is required.
//   * KIND, NAME and arity are ShapeTraits<S>::kind / ::fields.
//   * On statement lines other than found-by/note, a token starting with '#'
//     begins a comment that runs to the end of the line.
//   * TEXT (found-by, note) is the rest of the line, verbatim ('#' included),
//     without leading/trailing blanks, with the escapes \\ \n \r \t \xHH.
//     The writer escapes backslashes, control bytes, and a leading or
//     trailing space (\x20), and writes a note as one "note" line per line.
//   * VERDICT: for Collide queries "overlapping", "touching", "separated",
//     "undecided"; for Cast and Sweep queries "hit", "miss", "undecided".
//   * NUMBER: [+-] then a hex float ("0x1.8p+1", "0x1p-1074"), a decimal
//     ("1.5", "2e-3", ".5"), "inf"/"infinity", "nan", or "nan(0xHHH)" whose
//     hex digits are the 52-bit fraction field (non-zero). inf/nan are case
//     insensitive. A literal outside the double range ("1e400", "1e-400")
//     is an error, not a silent infinity or zero. Parsing is locale free.
//   * The whole file is at most kMaxCaseFileBytes (64 KiB).
//
// Every parse error reads "line N: <what is wrong>", N counting from 1: the
// offending line; for a shape missing a field, its "shape" line; for an
// error at the end of the file (missing "end"), the last line.
// The parser never throws and has no undefined behaviour on any input (it
// is fuzzed). For every CaseFile c with !case_error(c):
// parse_case(write_case(c)).value == c bit for bit (-0.0, subnormals, +-inf,
// NaN sign and payload included).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "geomcheck/registry.hpp"
#include "geomcheck/shape_traits.hpp"
#include "geomcheck/shapes.hpp"

namespace geomcheck {

/// The case-file format version this build writes and reads.
inline constexpr int kCaseFileVersion = 1;
/// Largest accepted case file, in bytes.
inline constexpr std::size_t kMaxCaseFileBytes = 64 * 1024;
/// The extension of case files under corpora/.
inline constexpr const char* kCaseFileExtension = ".case";

/// One reproduction case of a registered query, shape-generic.
struct CaseFile {
  int version = kCaseFileVersion;
  QueryId query = QueryId::collide_cylinder_sphere;
  /// Raw doubles of shape A and shape B, in ShapeTraits order.
  std::vector<double> a, b;
  /// The oracle's verdict when filed ("overlapping", "touching", "separated",
  /// "hit", "miss", "undecided"), or empty when unknown.
  std::string oracle_verdict;
  /// How it was found: "hand", "rapidcheck reproduce=...", "fuzz sha1=...",
  /// "campaign seed=42 case=17", ...
  std::string found_by;
  /// Free text; may span several lines.
  std::string note;
};

/// Bit-exact equality: doubles compare by their bit patterns (so -0.0 != 0.0
/// and a NaN equals a NaN with the same bits).
bool operator==(const CaseFile& x, const CaseFile& y);
inline bool operator!=(const CaseFile& x, const CaseFile& y) { return !(x == y); }

/// Outcome of parsing or loading a file of any format (ParseResult here,
/// PointSetParseResult in pointset_file.hpp, MeshParseResult in
/// mesh_file.hpp): the parsed value, or an error.
template <class T>
struct BasicParseResult {
  T value;            ///< the parsed value when ok(); T{} when !ok()
  std::string error;  ///< "line N: what is wrong" (when loading: "<path>: line N: ...") when !ok()
  int error_line = 0; ///< N of the error; 0 when ok() or the file could not be read
  /// True when the text parsed.
  bool ok() const { return error.empty(); }
  /// ok().
  explicit operator bool() const { return ok(); }
};

/// Outcome of parse_case / load_case: the case, or an error.
using ParseResult = BasicParseResult<CaseFile>;

// ----------------------------------------------------------------------------
// Shape layouts (runtime view of ShapeTraits)

/// Kind name, fields and total number of doubles of one shape type.
struct ShapeLayout {
  std::string_view kind;
  const ShapeField* fields = nullptr;
  std::size_t num_fields = 0;
  std::size_t size = 0;

  /// Index of the first double of field `field` (< num_fields) in the shape's doubles.
  constexpr std::size_t offset(std::size_t field) const {
    std::size_t off = 0;
    for (std::size_t i = 0; i < field; ++i) off += static_cast<std::size_t>(fields[i].arity);
    return off;
  }
};

/// The layout of ShapeTraits<S>.
template <class S>
constexpr ShapeLayout shape_layout() {
  return {ShapeTraits<S>::kind, ShapeTraits<S>::fields.data(), ShapeTraits<S>::fields.size(),
          ShapeTraits<S>::size};
}

/// Layout of the query's shape A (`which` == 0) or shape B (`which` == 1).
ShapeLayout query_shape(QueryId query, int which);

/// True when `query` is one of the registered ids (guards casts from integers).
bool is_registered(QueryId query);

/// The verdict words a case of this query kind may record.
std::vector<std::string_view> known_verdicts(QueryKind kind);
/// True when `verdict` is one of known_verdicts(kind).
bool is_known_verdict(QueryKind kind, std::string_view verdict);

// ----------------------------------------------------------------------------
// Reading and writing

/// What makes `c` unwritable as a valid file (unregistered query, wrong
/// number of doubles for a shape, unsupported version, unknown verdict), or
/// nullopt when it is valid.
std::optional<std::string> case_error(const CaseFile& c);

/// The case as file text (format above). Never fails; a case with
/// case_error(c) is written as faithfully as possible and will not parse.
std::string write_case(const CaseFile& c);

/// Parses case-file text. Never throws.
ParseResult parse_case(std::string_view text);

/// The query a case file of any family declares in its header (its first
/// `query NAME` line, among the first 4 KiB), without parsing the file: it
/// decides the file's family and so its parser. Empty when the header names
/// none or the file cannot be read (the parser then says why).
std::string declared_query(const std::filesystem::path& path);

/// Reads and parses a file. A parse error reads "<path>: line N: ...";
/// an unreadable file "cannot open case file '<path>': <reason>" (error_line 0).
ParseResult load_case(const std::filesystem::path& path);

/// Writes `c` to `path` (through a temporary file and a rename, so a reader
/// never sees half a file). Refuses a case with case_error(c). On failure
/// returns false and sets `error`.
bool save_case(const std::filesystem::path& path, const CaseFile& c, std::string& error);

/// One double in the writer's form: "%a" hex float ("0x1.8p+1", "-0x0p+0",
/// "0x0.0000000000001p-1022"), "inf", "-inf", "nan", "-nan", or
/// "nan(0xHHH)" for a NaN whose fraction field is not the default quiet NaN.
std::string format_double(double v);
/// One double as "%.17g" ("3", "0.10000000000000001", "inf", "nan").
std::string format_decimal(double v);
/// Parses one NUMBER token (grammar above); nullopt when malformed or out of range.
std::optional<double> parse_double(std::string_view token);

// ----------------------------------------------------------------------------
// Typed views

/// The typed case of query Q. `f.query` should be Q; a shape vector shorter
/// than the shape is zero padded and a longer one truncated (check
/// case_error(f) first to rule that out).
template <QueryId Q>
typename QueryTraits<Q>::Case to_case(const CaseFile& f) {
  using A = typename QueryTraits<Q>::ShapeA;
  using B = typename QueryTraits<Q>::ShapeB;
  std::array<double, ShapeTraits<A>::size> va{};
  std::array<double, ShapeTraits<B>::size> vb{};
  for (std::size_t i = 0; i < va.size() && i < f.a.size(); ++i) va[i] = f.a[i];
  for (std::size_t i = 0; i < vb.size() && i < f.b.size(); ++i) vb[i] = f.b[i];
  return {ShapeTraits<A>::from(va.data()), ShapeTraits<B>::from(vb.data())};
}

/// The case file of a typed case of query Q (call as from_case<Q>(c, ...)).
template <QueryId Q>
CaseFile from_case(const typename QueryTraits<Q>::Case& c, std::string found_by = {},
                   std::string oracle_verdict = {}, std::string note = {}) {
  using A = typename QueryTraits<Q>::ShapeA;
  using B = typename QueryTraits<Q>::ShapeB;
  CaseFile f;
  f.query = Q;
  f.a.resize(ShapeTraits<A>::size);
  f.b.resize(ShapeTraits<B>::size);
  ShapeTraits<A>::to(c.a, f.a.data());
  ShapeTraits<B>::to(c.b, f.b.data());
  f.found_by = std::move(found_by);
  f.oracle_verdict = std::move(oracle_verdict);
  f.note = std::move(note);
  return f;
}

/// Calls fn(std::integral_constant<QueryId, Q>{}, to_case<Q>(f)) for f's query Q.
template <class F>
decltype(auto) visit_case(const CaseFile& f, F&& fn) {
  return visit_query(f.query, [&](auto q) -> decltype(auto) {
    return fn(q, to_case<decltype(q)::value>(f));
  });
}

// ----------------------------------------------------------------------------
// Shape descriptions (RapidCheck counterexamples, reports)

/// "kind{f1=(x, y, z), f2=s}" with every double in format_double form, e.g.
/// "cylinder{p=(0x0p+0, 0x0p+0, 0x0p+0), q=(0x0p+0, 0x0p+0, 0x1p+1), r=0x1p+0}".
std::string describe_shape(const Segment& s);
std::string describe_shape(const Sphere& s);
std::string describe_shape(const Capsule& s);
std::string describe_shape(const Cylinder& s);
std::string describe_shape(const Obb& s);
std::string describe_shape(const Triangle& s);
std::string describe_shape(const MovingSphere& s);
/// The same form from a layout and its raw doubles (layout.size of them).
std::string describe_shape(const ShapeLayout& layout, const double* values);

// ----------------------------------------------------------------------------
// Converters

/// Raw-double decoding shared by the fuzz targets: the input is cut into
/// consecutive 8-byte chunks, each read as a little-endian IEEE-754 binary64
/// (byte 0 least significant); chunk i is double i. Bytes missing at the end
/// (including whole chunks) are zero; bytes beyond 8 * count are ignored.
/// `data` may be null when `size` is 0. Returns exactly `count` doubles.
std::vector<double> decode_raw_doubles(const std::uint8_t* data, std::size_t size, std::size_t count);
/// Inverse of decode_raw_doubles: 8 little-endian bytes per double.
std::vector<std::uint8_t> encode_raw_doubles(const std::vector<double>& values);

/// The case a raw-mode fuzz payload stands for (the bytes after the fuzz
/// targets' mode byte; fuzz/include/geomcheck/fuzz_decode.hpp decodes whole
/// inputs of either mode): decode_raw_doubles(data, size, |A| + |B|); shape A
/// takes the first ShapeTraits<A>::size doubles, shape B the next. found_by = "fuzz " + artifact_name when given (e.g. the crash
/// file's name "crash-<sha1>"), else "fuzz sha1=<sha1 of the input>".
CaseFile case_from_fuzz_input(QueryId query, const std::uint8_t* data, std::size_t size,
                              std::string_view artifact_name = {});
/// The raw fuzz input of a case: encode_raw_doubles(a ++ b).
std::vector<std::uint8_t> fuzz_input_from_case(const CaseFile& c);

/// Extracts a counterexample from RapidCheck output (or any text): the first
/// well-formed describe_shape() text of the query's shape A, then the first
/// one of shape B after it. found_by = "rapidcheck reproduce=<token>" when
/// the text holds "reproduce=<token>", else "rapidcheck". nullopt when
/// either shape is not found.
std::optional<CaseFile> case_from_rapidcheck_text(QueryId query, std::string_view text);

/// Lower-case hex SHA-1 of the bytes (libFuzzer names artifacts by it).
std::string sha1_hex(const std::uint8_t* data, std::size_t size);

}  // namespace geomcheck
