// geomcheck — the text core shared by the case-file formats: the shape-pair
// case file (casefile.hpp), the point-set file (pointset_file.hpp) and the
// mesh file (mesh_file.hpp).
//
// The formats are read by the same statement loop and written by the same
// helpers; only the body (shape blocks, point lines, cylinder, vertex and
// face lines) and the query line's
// check differ. This header holds everything else, so that a convention is
// stated and implemented once:
//
//   * Lines: LF-separated, a leading UTF-8 byte-order mark skipped, a CR
//     before the LF dropped; control bytes other than tab are errors.
//   * Tokens: separated by space and tab; a token starting with '#' begins
//     a comment that runs to the end of the line (except in TEXT).
//   * NUMBER and TEXT: the grammar of casefile.hpp (hex floats, decimals,
//     inf, nan, nan(0xHHH); TEXT with the escapes \\ \n \r \t \xHH).
//   * Statements the formats share: the header "geomcheck-case VERSION",
//     "query ID", "found-by", "oracle-verdict", "note", "end".
//   * Errors: "line N: <what is wrong>" from the parser; a file reader adds
//     "<path>: " in front. The wording of every message lives here or in the
//     format's own source, never in two places.
//   * Writing: the comment line, the header and meta lines, body lines with
//     their "%.17g" comments aligned in one column, "end".
//
// Everything here is internal to corpora/ (the library and its tests) and
// the two parsers' fuzz targets; the formats' promises (grammar, round trip) are those of casefile.hpp and
// pointset_file.hpp.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "geomcheck/casefile.hpp"

namespace geomcheck::detail {

// --- bits of a double -------------------------------------------------------

/// The IEEE-754 bit pattern of `v`.
inline std::uint64_t bits_of(double v) {
  std::uint64_t u;
  std::memcpy(&u, &v, sizeof u);
  return u;
}

/// The double whose IEEE-754 bit pattern is `u`.
inline double from_bits(std::uint64_t u) {
  double v;
  std::memcpy(&v, &u, sizeof v);
  return v;
}

// --- characters ---------------------------------------------------------------

/// True for 0-9, a-f, A-F.
bool is_hex_digit(char ch);

/// The value of a hex digit (is_hex_digit(ch) must hold).
int hex_value(char ch);

/// ASCII case-insensitive equality (the inf/nan spellings of NUMBER).
bool iequals(std::string_view x, std::string_view y);

/// `words` joined with ", " (the "known: ..." lists of error messages).
std::string join_list(const std::vector<std::string_view>& words);

// --- lines and tokens -------------------------------------------------------

/// Calls statement(line, n) for every line of `text` (n from 1; a leading
/// UTF-8 byte-order mark skipped, a CR before the LF dropped) until it
/// returns false. Returns the number of lines visited.
template <class F>
int for_each_line(std::string_view text, F&& statement) {
  std::size_t pos = 0;
  if (text.substr(0, 3) == "\xEF\xBB\xBF") pos = 3;
  int line_no = 0;
  while (pos < text.size()) {
    std::size_t nl = text.find('\n', pos);
    if (nl == std::string_view::npos) nl = text.size();
    std::string_view line = text.substr(pos, nl - pos);
    pos = nl + 1;
    ++line_no;
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    if (!statement(line, line_no)) break;
  }
  return line_no;
}

/// "control byte 0xHH in the line (only tab is allowed)" for the first
/// control byte of `line`, or nullopt when it has none.
std::optional<std::string> control_byte_error(std::string_view line);

/// `s` without leading and trailing blanks (space, tab).
std::string_view trim(std::string_view s);

/// Next blank-separated token of `rest` (advancing it), empty at the end.
std::string_view next_token(std::string_view& rest);

/// A token for an error message: quoted, at most 40 bytes, non-ASCII escaped.
std::string quote_token(std::string_view s);

/// "unexpected text 'x' after <after>" when `rest` holds a token that does
/// not start a comment, else nullopt.
std::optional<std::string> trailing_text_error(std::string_view rest, const char* after);

// --- NUMBER and TEXT --------------------------------------------------------

/// Outcome of parse_number.
enum class NumStatus { Ok, Malformed, OutOfRange, BadNanPayload };

/// Parses one NUMBER token (grammar in casefile.hpp) into `out`.
NumStatus parse_number(std::string_view s, double& out);

/// Stores in `tokens` the first `max` tokens of `rest` before the end of the
/// line or a comment; returns how many tokens there are in all (which may
/// be more than `max`).
std::size_t value_tokens(std::string_view rest, std::string_view* tokens, std::size_t max);

/// Parses `count` NUMBER tokens into `out`. For the first token that does
/// not parse, returns "malformed number 'T' <place><owner>", "number 'T'
/// <place> is outside the double range (...)" or "bad NaN payload 'T'
/// <place> (...)"; nullopt when all parse. `place` reads like "in 'point'"
/// or "in field 'r'", `owner` like " of cylinder" (or empty).
std::optional<std::string> parse_values(const std::string_view* tokens, std::size_t count, double* out,
                                        const std::string& place, const std::string& owner);

/// Escapes TEXT so that it stays on one line and survives the parser's trim.
std::string escape_text(std::string_view s);

/// Undoes escape_text; false (with `what`) on a bad escape.
bool unescape_text(std::string_view s, std::string& out, std::string& what);

// --- errors shared by the formats ------------------------------------------

/// Checks the first statement (`key` and the rest of its line) as the header
/// "geomcheck-case VERSION" and stores VERSION; the error, or nullopt.
std::optional<std::string> header_error(std::string_view key, std::string_view rest, int& version);

/// "unsupported case-file version N (this build writes version 1)" when a
/// value to be written has a version other than kCaseFileVersion, else nullopt.
std::optional<std::string> write_version_error(int version);

/// The error for a file that ended before its 'end' line: empty, without a
/// header line (`header_seen` false), or without 'end'.
std::string unterminated_error(int line_count, bool header_seen);

/// "file too large (N bytes, limit L)".
std::string too_large_error(std::size_t bytes, std::size_t limit);

/// "line N: <what>", the form of every parse error.
std::string line_error(int line, const std::string& what);

// --- the statement loop -----------------------------------------------------

/// The found-by, oracle-verdict and note lines of a file being parsed.
struct MetaLines {
  std::string found_by, oracle_verdict, note;
  bool have_found_by = false, have_verdict = false, have_note = false;
  int verdict_line = 0;  ///< line of the oracle-verdict statement

  /// True for the keys read() takes.
  static bool is_text_meta(std::string_view key) {
    return key == "found-by" || key == "oracle-verdict" || key == "note";
  }
  /// Reads one found-by, oracle-verdict or note statement (`rest`: the line
  /// after the key). The verdict word is stored unchecked. Returns the error,
  /// or nullopt.
  std::optional<std::string> read(std::string_view key, std::string_view rest, int line);
};

/// The parser of the formats, minus their bodies. Derived (CRTP) supplies:
///   - `static constexpr const char* kBodyKeyword`: "shape", "point" or "cylinder", the
///     statement after which meta lines are refused;
///   - `bool query_id(std::string_view id, int n)`: checks the query line's
///     id (the duplicate, missing-id and trailing-text errors are handled
///     here) and stores it, or fails;
///   - `bool after_meta(std::string_view key, int n)`: called after each
///     found-by, oracle-verdict or note line was read into meta_;
///   - `bool body(std::string_view key, std::string_view rest, int n)`: any
///     other statement after the header, "end" included.
/// `File` has the members version, found_by, oracle_verdict and note.
template <class Derived, class File>
class LineParser {
 public:
  /// Parses `text` (at most `limit` bytes) into a File, or the first error.
  BasicParseResult<File> run(std::string_view text, std::size_t limit) {
    BasicParseResult<File> res;
    if (text.size() > limit) {
      fail(1, too_large_error(text.size(), limit));
    } else {
      const int lines = for_each_line(text, [this](std::string_view line, int n) { return statement(line, n); });
      if (error_.empty() && stage_ != Stage::Done)
        fail(lines == 0 ? 1 : lines, unterminated_error(lines, stage_ != Stage::Header));
    }
    if (!error_.empty()) {
      res.error = std::move(error_);
      res.error_line = error_line_;
      return res;
    }
    file_.found_by = std::move(meta_.found_by);
    file_.oracle_verdict = std::move(meta_.oracle_verdict);
    file_.note = std::move(meta_.note);
    res.value = std::move(file_);
    return res;
  }

 protected:
  /// Header: before the "geomcheck-case" line; Meta: query and meta lines;
  /// Body: after the first body statement; Done: after "end".
  enum class Stage { Header, Meta, Body, Done };

  /// Records the first error (later ones are dropped); returns false.
  bool fail(int line, std::string what) {
    if (error_.empty()) {
      error_ = line_error(line, what);
      error_line_ = line;
    }
    return false;
  }

  /// Fails with the trailing-text error of `rest`, if any; else true.
  bool no_trailing(std::string_view rest, int n, const char* after) {
    if (auto e = trailing_text_error(rest, after)) return fail(n, *e);
    return true;
  }

  /// Splits `rest`, the values of a `word` line, into tokens[0..k); unless
  /// there are exactly k, fails with "'word' takes k <what>, got N".
  template <std::size_t k>
  bool exactly(std::string_view (&tokens)[k], std::string_view rest, int n, const char* word, const char* what) {
    const std::size_t count = value_tokens(rest, tokens, k);
    if (count == k) return true;
    return fail(n, std::string("'") + word + "' takes " + std::to_string(k) + " " + what + ", got " +
                       std::to_string(count));
  }

  File file_;                    ///< the value being parsed (meta lines aside)
  MetaLines meta_;               ///< found-by, oracle-verdict and note so far
  Stage stage_ = Stage::Header;  ///< where in the file the next line is
  bool have_query_ = false;      ///< a valid query line was read

 private:
  /// This parser as the format's own (Derived).
  Derived& derived() { return static_cast<Derived&>(*this); }

  /// One line (`n` from 1): control bytes, blank and comment lines, the
  /// header, and the statements the formats share; the rest goes to body().
  bool statement(std::string_view line, int n) {
    if (auto e = control_byte_error(line)) return fail(n, *e);
    std::string_view rest = line;
    const std::string_view key = next_token(rest);
    if (key.empty() || key[0] == '#') return true;  // blank or comment line

    if (stage_ == Stage::Done) return fail(n, "unexpected " + quote_token(key) + " after 'end'");

    if (stage_ == Stage::Header) {
      if (auto e = header_error(key, rest, file_.version)) return fail(n, *e);
      stage_ = Stage::Meta;
      return true;
    }

    if (key == "geomcheck-case") return fail(n, "duplicate 'geomcheck-case' line");
    if (key == "query" || MetaLines::is_text_meta(key)) {
      if (stage_ == Stage::Body)
        return fail(n, quote_token(key) + " must come before the first '" + Derived::kBodyKeyword + "'");
      if (key == "query") return query(rest, n);
      if (auto e = meta_.read(key, rest, n)) return fail(n, *e);
      return derived().after_meta(key, n);
    }
    return derived().body(key, rest, n);
  }

  /// The "query" statement (`rest`: the line after the key).
  bool query(std::string_view rest, int n) {
    if (have_query_) return fail(n, "duplicate 'query' line");
    const std::string_view id = next_token(rest);
    if (id.empty() || id[0] == '#') return fail(n, "missing query id after 'query'");
    if (!derived().query_id(id, n)) return false;
    if (!no_trailing(rest, n, "the query id")) return false;
    have_query_ = true;
    return true;
  }

  std::string error_;   ///< the first error, "line N: ..."; empty while none
  int error_line_ = 0;  ///< N of error_
};

// --- writing ----------------------------------------------------------------

/// Appends the comment line, the header line and "query NAME".
void write_header(std::string& out, int version, std::string_view query_name);

/// Appends the found-by, oracle-verdict and note lines (each only when
/// non-empty; one note line per line of the note).
void write_meta(std::string& out, const std::string& found_by, const std::string& oracle_verdict,
                const std::string& note);

/// Appends the header, query and meta lines of `f` (a File as for
/// LineParser): write_header, then write_meta.
template <class File>
void write_preamble(std::string& out, const File& f, std::string_view query_name) {
  write_header(out, f.version, query_name);
  write_meta(out, f.found_by, f.oracle_verdict, f.note);
}

/// Body lines of a file being written: each a head ("point", "  r") and
/// NUMBERs in format_double form, with the NUMBERs in format_decimal form as
/// its comment; the comments are aligned in one column.
class ValueLines {
 public:
  /// Adds the line `head` followed by the `count` values (a line without
  /// values gets no comment).
  void add(std::string head, const double* values, std::size_t count);
  /// Appends the lines added since the last write to `out` and forgets them.
  void write(std::string& out);

 private:
  std::vector<std::string> lines_, comments_;
};

// --- the promise on any text ------------------------------------------------

/// What the fuzz targets of the formats check for one input: `r` (the
/// parse of the input by `parse`) is either an error that names its line
/// (or is about the file's size or emptiness), or a value that `write`
/// writes back as text that `parse` reads as the same value, bit for bit.
/// Returns nullopt when the promise holds, else the report (ending in a
/// newline): "parse error without a line number: <error>", or "round trip
/// failed: <error of the re-parse>" followed by the written text.
template <class File>
std::optional<std::string> broken_round_trip(const BasicParseResult<File>& r,
                                             BasicParseResult<File> (*parse)(std::string_view),
                                             std::string (*write)(const File&)) {
  if (!r.ok()) {
    if (r.error.rfind("line ", 0) != 0 && r.error.find("too large") == std::string::npos &&
        r.error.find("empty") == std::string::npos)
      return "parse error without a line number: " + r.error + "\n";
    return std::nullopt;
  }
  const std::string written = write(r.value);
  const BasicParseResult<File> again = parse(written);
  if (!again.ok() || !(again.value == r.value)) return "round trip failed: " + again.error + "\n" + written + "\n";
  return std::nullopt;
}

/// The body of a format's fuzz target: parses the input `data` (`size`
/// bytes, as text) with `parse` and, where broken_round_trip finds the
/// promise broken, prints its report to stderr and aborts (so that libFuzzer
/// keeps the input). Returns the parse, for the target's further checks.
template <class File>
BasicParseResult<File> parse_or_abort(const std::uint8_t* data, std::size_t size,
                                      BasicParseResult<File> (*parse)(std::string_view),
                                      std::string (*write)(const File&)) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  BasicParseResult<File> r = parse(text);
  if (const auto broken = broken_round_trip(r, parse, write)) {
    std::fputs(broken->c_str(), stderr);
    std::abort();
  }
  return r;
}

}  // namespace geomcheck::detail
