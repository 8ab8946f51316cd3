// geomcheck — the text conventions shared by the case-file formats (internal
// to corpora/): lines, tokens, NUMBER and TEXT, the header and meta lines,
// the writer's comment column, reading and saving files. The grammar is in
// casefile.hpp; casefile.cpp and pointset_file.cpp both build on these.
#pragma once

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace geomcheck::detail {

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

/// Escapes TEXT so that it stays on one line and survives the parser's trim.
std::string escape_text(std::string_view s);

/// Undoes escape_text; false (with `what`) on a bad escape.
bool unescape_text(std::string_view s, std::string& out, std::string& what);

// --- statements shared by both formats --------------------------------------

/// Checks the first statement (`key` and the rest of its line) as the header
/// "geomcheck-case VERSION" and stores VERSION; the error, or nullopt.
std::optional<std::string> header_error(std::string_view key, std::string_view rest, int& version);

/// The error for a file that ended before its 'end' line: empty, without a
/// header line (`header_seen` false), or without 'end'.
std::string unterminated_error(int line_count, bool header_seen);

/// "file too large (N bytes, limit L)".
std::string too_large_error(std::size_t bytes, std::size_t limit);

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

// --- writing ----------------------------------------------------------------

/// Appends the comment line, the header line and "query NAME".
void write_header(std::string& out, int version, std::string_view query_name);

/// Appends the found-by, oracle-verdict and note lines (each only when
/// non-empty; one note line per line of the note).
void write_meta(std::string& out, const std::string& found_by, const std::string& oracle_verdict,
                const std::string& note);

/// Appends lhs[i] + "   # " + rhs[i] for each i, the comments aligned in one
/// column (just lhs[i] when rhs[i] is empty).
void write_commented_lines(std::string& out, const std::vector<std::string>& lhs,
                           const std::vector<std::string>& rhs);

// --- files ------------------------------------------------------------------

/// Reads the file into `text`. On failure returns false with `error` (and
/// `error_line`): "cannot open case file '<path>': <reason>" (0), "cannot
/// read case file '<path>'" (0), or "<path>: line 1: file too large (...)"
/// when it holds more than `limit` bytes (1).
bool read_case_text(const std::filesystem::path& path, std::size_t limit, std::string& text, std::string& error,
                    int& error_line);

/// Writes `text` to `path` through "<path>.tmp" and a rename; on failure
/// returns false with `error`.
bool save_text(const std::filesystem::path& path, const std::string& text, std::string& error);

}  // namespace geomcheck::detail
