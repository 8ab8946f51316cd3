// geomcheck — the text core of the case-file formats (declared in
// geomcheck/detail/text_format.hpp), the NUMBER writer and reader of
// casefile.hpp, and the loading and saving of files of every format
// (load_case, save_case, load_point_set, save_point_set, load_mesh_file,
// save_mesh_file).
#include "geomcheck/detail/text_format.hpp"

#include "geomcheck/mesh_file.hpp"
#include "geomcheck/pointset_file.hpp"

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <system_error>

namespace geomcheck {

namespace {

constexpr std::uint64_t kFractionMask = (std::uint64_t{1} << 52) - 1;
constexpr std::uint64_t kQuietBit = std::uint64_t{1} << 51;
constexpr std::uint64_t kExponentMask = std::uint64_t{0x7ff} << 52;
constexpr std::uint64_t kSignBit = std::uint64_t{1} << 63;

using detail::bits_of;
using detail::from_bits;

bool is_blank(char ch) { return ch == ' ' || ch == '\t'; }

}  // namespace

namespace detail {

bool is_hex_digit(char ch) {
  return (ch >= '0' && ch <= '9') || (ch >= 'a' && ch <= 'f') || (ch >= 'A' && ch <= 'F');
}

int hex_value(char ch) {
  if (ch >= '0' && ch <= '9') return ch - '0';
  if (ch >= 'a' && ch <= 'f') return ch - 'a' + 10;
  return ch - 'A' + 10;
}

bool iequals(std::string_view x, std::string_view y) {
  const auto lower = [](char ch) { return (ch >= 'A' && ch <= 'Z') ? static_cast<char>(ch - 'A' + 'a') : ch; };
  if (x.size() != y.size()) return false;
  for (std::size_t i = 0; i < x.size(); ++i)
    if (lower(x[i]) != lower(y[i])) return false;
  return true;
}

std::string join_list(const std::vector<std::string_view>& words) {
  std::string s;
  for (auto w : words) {
    if (!s.empty()) s += ", ";
    s += w;
  }
  return s;
}

std::optional<std::string> control_byte_error(std::string_view line) {
  for (char ch : line) {
    const auto u = static_cast<unsigned char>(ch);
    if ((u < 0x20 && ch != '\t') || u == 0x7f) {
      static const char* hex = "0123456789abcdef";
      std::string b = "0x";
      b += hex[u >> 4];
      b += hex[u & 15];
      return "control byte " + b + " in the line (only tab is allowed)";
    }
  }
  return std::nullopt;
}

std::string_view trim(std::string_view s) {
  while (!s.empty() && is_blank(s.front())) s.remove_prefix(1);
  while (!s.empty() && is_blank(s.back())) s.remove_suffix(1);
  return s;
}

std::string_view next_token(std::string_view& rest) {
  std::size_t i = 0;
  while (i < rest.size() && is_blank(rest[i])) ++i;
  std::size_t j = i;
  while (j < rest.size() && !is_blank(rest[j])) ++j;
  std::string_view tok = rest.substr(i, j - i);
  rest.remove_prefix(j);
  return tok;
}

std::string quote_token(std::string_view s) {
  static const char* hex = "0123456789abcdef";
  std::string out = "'";
  const std::size_t limit = 40;
  for (std::size_t i = 0; i < s.size() && i < limit; ++i) {
    const auto ch = static_cast<unsigned char>(s[i]);
    if (ch < 0x20 || ch >= 0x7f) {
      out += "\\x";
      out += hex[ch >> 4];
      out += hex[ch & 15];
    } else {
      out += static_cast<char>(ch);
    }
  }
  if (s.size() > limit) out += "...";
  out += "'";
  return out;
}

std::optional<std::string> trailing_text_error(std::string_view rest, const char* after) {
  const std::string_view t = next_token(rest);
  if (t.empty() || t[0] == '#') return std::nullopt;
  return "unexpected text " + quote_token(t) + " after " + after;
}

NumStatus parse_number(std::string_view s, double& out) {
  if (s.empty()) return NumStatus::Malformed;
  bool neg = false;
  if (s[0] == '+' || s[0] == '-') {
    neg = s[0] == '-';
    s.remove_prefix(1);
  }
  if (s.empty()) return NumStatus::Malformed;
  if (iequals(s, "inf") || iequals(s, "infinity")) {
    out = neg ? -std::numeric_limits<double>::infinity() : std::numeric_limits<double>::infinity();
    return NumStatus::Ok;
  }
  if (iequals(s, "nan")) {
    out = from_bits((neg ? kSignBit : 0) | kExponentMask | kQuietBit);
    return NumStatus::Ok;
  }
  if (s.size() >= 4 && iequals(s.substr(0, 4), "nan(")) {
    // nan(0xHHH): the 52-bit fraction field, non-zero.
    if (s.back() != ')' || s.size() < 8 || !iequals(s.substr(4, 2), "0x")) return NumStatus::Malformed;
    const std::string_view digits = s.substr(6, s.size() - 7);
    if (digits.empty() || digits.size() > 13) return NumStatus::BadNanPayload;
    std::uint64_t frac = 0;
    for (char ch : digits) {
      if (!is_hex_digit(ch)) return NumStatus::Malformed;
      frac = (frac << 4) | static_cast<std::uint64_t>(hex_value(ch));
    }
    if (frac == 0 || frac > kFractionMask) return NumStatus::BadNanPayload;
    out = from_bits((neg ? kSignBit : 0) | kExponentMask | frac);
    return NumStatus::Ok;
  }
  std::chars_format fmt = std::chars_format::general;
  if (s.size() >= 2 && s[0] == '0' && (s[1] == 'x' || s[1] == 'X')) {
    s.remove_prefix(2);
    fmt = std::chars_format::hex;
    if (s.empty() || !(is_hex_digit(s[0]) || s[0] == '.')) return NumStatus::Malformed;
  } else if (!((s[0] >= '0' && s[0] <= '9') || s[0] == '.')) {
    return NumStatus::Malformed;
  }
  double v = 0;
  const char* first = s.data();
  const char* last = s.data() + s.size();
  const auto res = std::from_chars(first, last, v, fmt);
  if (res.ec == std::errc::result_out_of_range) return NumStatus::OutOfRange;
  if (res.ec != std::errc() || res.ptr != last) return NumStatus::Malformed;
  out = neg ? -v : v;
  return NumStatus::Ok;
}

std::size_t value_tokens(std::string_view rest, std::string_view* tokens, std::size_t max) {
  std::size_t count = 0;
  for (;;) {
    const std::string_view t = next_token(rest);
    if (t.empty() || t[0] == '#') break;
    if (count < max) tokens[count] = t;
    ++count;
  }
  return count;
}

std::optional<std::string> parse_values(const std::string_view* tokens, std::size_t count, double* out,
                                        const std::string& place, const std::string& owner) {
  for (std::size_t k = 0; k < count; ++k) {
    switch (parse_number(tokens[k], out[k])) {
      case NumStatus::Ok: break;
      case NumStatus::Malformed: return "malformed number " + quote_token(tokens[k]) + " " + place + owner;
      case NumStatus::OutOfRange:
        return "number " + quote_token(tokens[k]) + " " + place +
               " is outside the double range (write inf, or a representable value)";
      case NumStatus::BadNanPayload:
        return "bad NaN payload " + quote_token(tokens[k]) + " " + place +
               " (nan(0xHHH) takes 1 to 13 hex digits, a non-zero 52-bit fraction)";
    }
  }
  return std::nullopt;
}

std::string escape_text(std::string_view s) {
  static const char* hex = "0123456789abcdef";
  std::string out;
  for (std::size_t i = 0; i < s.size(); ++i) {
    const auto ch = static_cast<unsigned char>(s[i]);
    if (ch == '\\') {
      out += "\\\\";
    } else if (ch == '\n') {
      out += "\\n";
    } else if (ch == '\r') {
      out += "\\r";
    } else if (ch == '\t') {
      out += "\\t";
    } else if (ch < 0x20 || ch == 0x7f || (ch == ' ' && (i == 0 || i + 1 == s.size()))) {
      out += "\\x";
      out += hex[ch >> 4];
      out += hex[ch & 15];
    } else {
      out += static_cast<char>(ch);
    }
  }
  return out;
}

bool unescape_text(std::string_view s, std::string& out, std::string& what) {
  out.clear();
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (s[i] != '\\') {
      out += s[i];
      continue;
    }
    if (i + 1 >= s.size()) {
      what = "backslash at the end of the text (write \\\\ for a backslash)";
      return false;
    }
    const char e = s[++i];
    switch (e) {
      case '\\': out += '\\'; break;
      case 'n': out += '\n'; break;
      case 'r': out += '\r'; break;
      case 't': out += '\t'; break;
      case 'x':
        if (i + 2 < s.size() && is_hex_digit(s[i + 1]) && is_hex_digit(s[i + 2])) {
          out += static_cast<char>(hex_value(s[i + 1]) * 16 + hex_value(s[i + 2]));
          i += 2;
          break;
        }
        what = "\\x must be followed by two hex digits";
        return false;
      default:
        what = "unknown escape " + quote_token(s.substr(i - 1, 2)) + " (known: \\\\ \\n \\r \\t \\xHH)";
        return false;
    }
  }
  return true;
}

std::optional<std::string> header_error(std::string_view key, std::string_view rest, int& version) {
  if (key != "geomcheck-case")
    return "expected 'geomcheck-case " + std::to_string(kCaseFileVersion) + "' as the first statement, got " +
           quote_token(key);
  const std::string_view v = next_token(rest);
  if (v.empty() || v[0] == '#') return std::string("missing version after 'geomcheck-case'");
  int parsed = 0;
  const auto r = std::from_chars(v.data(), v.data() + v.size(), parsed);
  if (r.ec != std::errc() || r.ptr != v.data() + v.size() || v[0] == '-' || v[0] == '+')
    return "malformed version " + quote_token(v);
  if (parsed != kCaseFileVersion)
    return "unsupported case-file version " + std::to_string(parsed) + " (this build reads version " +
           std::to_string(kCaseFileVersion) + ")";
  if (auto e = trailing_text_error(rest, "the version")) return e;
  version = parsed;
  return std::nullopt;
}

std::optional<std::string> write_version_error(int version) {
  if (version == kCaseFileVersion) return std::nullopt;
  return "unsupported case-file version " + std::to_string(version) + " (this build writes version " +
         std::to_string(kCaseFileVersion) + ")";
}

std::string unterminated_error(int line_count, bool header_seen) {
  if (!header_seen)
    return line_count == 0 ? "empty file, expected 'geomcheck-case " + std::to_string(kCaseFileVersion) + "'"
                           : "no 'geomcheck-case' header line";
  return "missing 'end' at the end of the file";
}

std::string too_large_error(std::size_t bytes, std::size_t limit) {
  return "file too large (" + std::to_string(bytes) + " bytes, limit " + std::to_string(limit) + ")";
}

std::string line_error(int line, const std::string& what) { return "line " + std::to_string(line) + ": " + what; }

std::optional<std::string> MetaLines::read(std::string_view key, std::string_view rest, int line) {
  if (key == "oracle-verdict") {
    if (have_verdict) return std::string("duplicate 'oracle-verdict' line");
    const std::string_view v = next_token(rest);
    if (v.empty() || v[0] == '#') return std::string("missing verdict after 'oracle-verdict'");
    if (auto e = trailing_text_error(rest, "the verdict")) return e;
    oracle_verdict = std::string(v);
    have_verdict = true;
    verdict_line = line;
    return std::nullopt;
  }
  // found-by / note: the rest of the line is TEXT.
  std::string text, what;
  if (!unescape_text(trim(rest), text, what)) return "in " + quote_token(key) + ": " + what;
  if (key == "found-by") {
    if (have_found_by) return std::string("duplicate 'found-by' line");
    found_by = std::move(text);
    have_found_by = true;
    return std::nullopt;
  }
  if (have_note) note += '\n';
  note += text;
  have_note = true;
  return std::nullopt;
}

void write_header(std::string& out, int version, std::string_view query_name) {
  out += "# geomcheck case file\n";
  out += "geomcheck-case " + std::to_string(version) + "\n";
  out += "query ";
  out += query_name;
  out += '\n';
}

void write_meta(std::string& out, const std::string& found_by, const std::string& oracle_verdict,
                const std::string& note) {
  if (!found_by.empty()) out += "found-by " + escape_text(found_by) + "\n";
  if (!oracle_verdict.empty()) out += "oracle-verdict " + escape_text(oracle_verdict) + "\n";
  if (!note.empty()) {
    std::size_t pos = 0;
    for (;;) {
      const std::size_t nl = note.find('\n', pos);
      const std::string_view part =
          std::string_view(note).substr(pos, nl == std::string::npos ? std::string::npos : nl - pos);
      out += part.empty() ? "note\n" : "note " + escape_text(part) + "\n";
      if (nl == std::string::npos) break;
      pos = nl + 1;
    }
  }
}

void ValueLines::add(std::string head, const double* values, std::size_t count) {
  std::string comment;
  for (std::size_t k = 0; k < count; ++k) {
    head += ' ';
    head += format_double(values[k]);
    if (k) comment += ' ';
    comment += format_decimal(values[k]);
  }
  lines_.push_back(std::move(head));
  comments_.push_back(std::move(comment));
}

void ValueLines::write(std::string& out) {
  std::size_t width = 0;
  for (const auto& h : lines_) width = std::max(width, h.size());
  for (std::size_t i = 0; i < lines_.size(); ++i) {
    out += lines_[i];
    if (!comments_[i].empty()) {
      out.append(width - lines_[i].size() + 3, ' ');
      out += "# " + comments_[i];
    }
    out += '\n';
  }
  lines_.clear();
  comments_.clear();
}

}  // namespace detail

// --- NUMBER (casefile.hpp) ----------------------------------------------------

std::string format_double(double v) {
  const std::uint64_t u = bits_of(v);
  const bool neg = (u & kSignBit) != 0;
  if (std::isnan(v)) {
    const std::uint64_t frac = u & kFractionMask;
    if (frac == kQuietBit) return neg ? "-nan" : "nan";
    static const char* hex = "0123456789abcdef";
    std::string digits;
    for (std::uint64_t f = frac; f != 0; f >>= 4) digits.insert(digits.begin(), hex[f & 15]);
    return std::string(neg ? "-" : "") + "nan(0x" + digits + ")";
  }
  if (std::isinf(v)) return neg ? "-inf" : "inf";
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, std::fabs(v), std::chars_format::hex);
  return std::string(neg ? "-0x" : "0x") + std::string(buf, static_cast<std::size_t>(r.ptr - buf));
}

std::string format_decimal(double v) {
  if (std::isnan(v)) return std::signbit(v) ? "-nan" : "nan";
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::general, 17);
  return std::string(buf, static_cast<std::size_t>(r.ptr - buf));
}

std::optional<double> parse_double(std::string_view token) {
  double v = 0;
  if (detail::parse_number(token, v) != detail::NumStatus::Ok) return std::nullopt;
  return v;
}

// --- files of every format (casefile.hpp, pointset_file.hpp, mesh_file.hpp) --

namespace {

/// Reads the file into `text`. On failure returns false with `error` (and
/// `error_line`): "cannot open case file '<path>': <reason>" (0), "cannot
/// read case file '<path>'" (0), or "<path>: line 1: file too large (...)"
/// when it holds more than `limit` bytes (1).
bool read_case_text(const std::filesystem::path& path, std::size_t limit, std::string& text, std::string& error,
                    int& error_line) {
  error_line = 0;
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    error = "cannot open case file '" + path.string() + "': " + std::strerror(errno);
    return false;
  }
  text.clear();
  char buf[4096];
  while (in && text.size() <= limit) {
    in.read(buf, sizeof buf);
    text.append(buf, static_cast<std::size_t>(in.gcount()));
  }
  if (in.bad()) {
    error = "cannot read case file '" + path.string() + "'";
    return false;
  }
  if (text.size() > limit) {
    std::error_code ec;
    const auto bytes = std::filesystem::file_size(path, ec);
    error = path.string() + ": line 1: file too large (" +
            (ec ? "more than " + std::to_string(limit) : std::to_string(bytes)) + " bytes, limit " +
            std::to_string(limit) + ")";
    error_line = 1;
    return false;
  }
  return true;
}

/// Writes `text` to `path` through "<path>.tmp" and a rename; on failure
/// returns false with `error`.
bool save_text(const std::filesystem::path& path, const std::string& text, std::string& error) {
  std::filesystem::path tmp = path;
  tmp += ".tmp";
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) {
      error = "cannot create '" + tmp.string() + "': " + std::strerror(errno);
      return false;
    }
    out.write(text.data(), static_cast<std::streamsize>(text.size()));
    out.flush();
    if (!out) {
      error = "cannot write '" + tmp.string() + "'";
      std::error_code ec;
      std::filesystem::remove(tmp, ec);
      return false;
    }
  }
  std::error_code ec;
  std::filesystem::rename(tmp, path, ec);
  if (ec) {
    error = "cannot rename '" + tmp.string() + "' to '" + path.string() + "': " + ec.message();
    std::filesystem::remove(tmp, ec);
    return false;
  }
  return true;
}

/// Reads the file (at most `limit` bytes) and parses it with `parse`, a parse
/// error prefixed with "<path>: ".
template <class File>
BasicParseResult<File> load_file(const std::filesystem::path& path, std::size_t limit,
                                 BasicParseResult<File> (*parse)(std::string_view)) {
  BasicParseResult<File> res;
  std::string text;
  if (!read_case_text(path, limit, text, res.error, res.error_line)) return res;
  res = parse(text);
  if (!res.ok()) res.error = path.string() + ": " + res.error;
  return res;
}

/// Refuses `f` when `invalid` holds its error ("refusing to write '<path>':
/// <error>"), else saves write(f) through save_text.
template <class File>
bool save_file(const std::filesystem::path& path, const File& f, const std::optional<std::string>& invalid,
               std::string (*write)(const File&), std::string& error) {
  if (invalid) {
    error = "refusing to write '" + path.string() + "': " + *invalid;
    return false;
  }
  return save_text(path, write(f), error);
}

}  // namespace

ParseResult load_case(const std::filesystem::path& path) {
  return load_file(path, kMaxCaseFileBytes, &parse_case);
}

PointSetParseResult load_point_set(const std::filesystem::path& path) {
  return load_file(path, kMaxPointSetFileBytes, &parse_point_set);
}

bool save_case(const std::filesystem::path& path, const CaseFile& c, std::string& error) {
  return save_file(path, c, case_error(c), &write_case, error);
}

bool save_point_set(const std::filesystem::path& path, const PointSetFile& f, std::string& error) {
  return save_file(path, f, point_set_error(f), &write_point_set, error);
}

MeshParseResult load_mesh_file(const std::filesystem::path& path) {
  return load_file(path, kMaxMeshFileBytes, &parse_mesh_file);
}

bool save_mesh_file(const std::filesystem::path& path, const MeshFile& f, std::string& error) {
  return save_file(path, f, mesh_file_error(f), &write_mesh_file, error);
}

}  // namespace geomcheck
