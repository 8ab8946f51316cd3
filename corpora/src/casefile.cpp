// geomcheck — case files: writer, parser and converters (format in casefile.hpp).
#include "geomcheck/casefile.hpp"

#include "bits.hpp"
#include "case_text.hpp"
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

bool is_hex_digit(char ch) {
  return (ch >= '0' && ch <= '9') || (ch >= 'a' && ch <= 'f') || (ch >= 'A' && ch <= 'F');
}
int hex_value(char ch) {
  if (ch >= '0' && ch <= '9') return ch - '0';
  if (ch >= 'a' && ch <= 'f') return ch - 'a' + 10;
  return ch - 'A' + 10;
}
char lower(char ch) { return (ch >= 'A' && ch <= 'Z') ? static_cast<char>(ch - 'A' + 'a') : ch; }
bool iequals(std::string_view x, std::string_view y) {
  if (x.size() != y.size()) return false;
  for (std::size_t i = 0; i < x.size(); ++i)
    if (lower(x[i]) != lower(y[i])) return false;
  return true;
}

bool is_blank(char ch) { return ch == ' ' || ch == '\t'; }

}  // namespace

// --- the shared text conventions (case_text.hpp) ------------------------------

namespace detail {

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

std::string unterminated_error(int line_count, bool header_seen) {
  if (!header_seen)
    return line_count == 0 ? "empty file, expected 'geomcheck-case " + std::to_string(kCaseFileVersion) + "'"
                           : "no 'geomcheck-case' header line";
  return "missing 'end' at the end of the file";
}

std::string too_large_error(std::size_t bytes, std::size_t limit) {
  return "file too large (" + std::to_string(bytes) + " bytes, limit " + std::to_string(limit) + ")";
}

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

void write_commented_lines(std::string& out, const std::vector<std::string>& lhs,
                           const std::vector<std::string>& rhs) {
  std::size_t width = 0;
  for (const auto& h : lhs) width = std::max(width, h.size());
  for (std::size_t i = 0; i < lhs.size(); ++i) {
    out += lhs[i];
    if (i < rhs.size() && !rhs[i].empty()) {
      out.append(width - lhs[i].size() + 3, ' ');
      out += "# " + rhs[i];
    }
    out += '\n';
  }
}

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

}  // namespace detail

namespace {

using detail::NumStatus;
using detail::next_token;
using detail::parse_number;
using detail::quote_token;

// --- shape kinds ------------------------------------------------------------

constexpr ShapeLayout kAllShapes[] = {
    shape_layout<Segment>(), shape_layout<Sphere>(), shape_layout<Capsule>(),
    shape_layout<Cylinder>(), shape_layout<Obb>(),   shape_layout<Triangle>(),
    shape_layout<MovingSphere>(),
};

bool is_shape_kind(std::string_view kind) {
  for (const auto& l : kAllShapes)
    if (l.kind == kind) return true;
  return false;
}

std::string field_list(const ShapeLayout& l) {
  std::string s;
  for (std::size_t i = 0; i < l.num_fields; ++i) {
    if (i) s += ", ";
    s += l.fields[i].name;
  }
  return s;
}

std::size_t field_offset(const ShapeLayout& l, std::size_t field) {
  std::size_t off = 0;
  for (std::size_t i = 0; i < field; ++i) off += static_cast<std::size_t>(l.fields[i].arity);
  return off;
}

std::string known_query_list() {
  std::string s;
  for (const auto& q : kQueries) {
    if (!s.empty()) s += ", ";
    s += q.name;
  }
  return s;
}

std::string verdict_list(QueryKind kind) {
  std::string s;
  for (auto v : known_verdicts(kind)) {
    if (!s.empty()) s += ", ";
    s += v;
  }
  return s;
}

const char* const kShapeRole[2] = {"A", "B"};

// --- parser -----------------------------------------------------------------

class Parser {
 public:
  explicit Parser(std::string_view text) : text_(text) {}

  ParseResult run() {
    ParseResult res;
    if (text_.size() > kMaxCaseFileBytes) {
      fail(1, detail::too_large_error(text_.size(), kMaxCaseFileBytes));
    } else {
      parse_lines();
    }
    if (!error_.empty()) {
      res.error = std::move(error_);
      res.error_line = error_line_;
      return res;
    }
    case_.found_by = std::move(meta_.found_by);
    case_.oracle_verdict = std::move(meta_.oracle_verdict);
    case_.note = std::move(meta_.note);
    res.value = std::move(case_);
    return res;
  }

 private:
  enum class Stage { Header, Meta, Shapes, Done };

  bool fail(int line, std::string what) {
    if (error_.empty()) {
      error_ = "line " + std::to_string(line) + ": " + what;
      error_line_ = line;
    }
    return false;
  }

  void parse_lines() {
    const int lines = detail::for_each_line(text_, [this](std::string_view line, int n) { return statement(line, n); });
    if (!error_.empty() || stage_ == Stage::Done) return;
    fail(lines == 0 ? 1 : lines, detail::unterminated_error(lines, stage_ != Stage::Header));
  }

  bool statement(std::string_view line, int n) {
    if (auto e = detail::control_byte_error(line)) return fail(n, *e);
    std::string_view rest = line;
    const std::string_view key = next_token(rest);
    if (key.empty() || key[0] == '#') return true;  // blank or comment line

    if (stage_ == Stage::Done) return fail(n, "unexpected " + quote_token(key) + " after 'end'");

    if (stage_ == Stage::Header) {
      if (auto e = detail::header_error(key, rest, case_.version)) return fail(n, *e);
      stage_ = Stage::Meta;
      return true;
    }

    if (key == "geomcheck-case") return fail(n, "duplicate 'geomcheck-case' line");
    if (key == "query" || detail::MetaLines::is_text_meta(key)) {
      if (stage_ == Stage::Shapes) return fail(n, quote_token(key) + " must come before the first 'shape'");
      return meta(key, rest, n);
    }
    if (key == "shape") return shape(rest, n);
    if (key == "end") {
      if (!no_trailing(rest, n, "'end'")) return false;
      if (stage_ == Stage::Meta) {
        if (!have_query_) return fail(n, "missing 'query' line");
        return fail(n, "missing shape A (" + std::string(query_shape(case_.query, 0).kind) + ") before 'end'");
      }
      if (!close_shape()) return false;
      if (shape_index_ == 0)
        return fail(n, "missing shape B (" + std::string(query_shape(case_.query, 1).kind) + ") before 'end'");
      stage_ = Stage::Done;
      return true;
    }
    if (stage_ == Stage::Shapes) return field(key, rest, n);
    return fail(n, "unknown keyword " + quote_token(key) +
                       " (expected query, found-by, oracle-verdict, note or shape)");
  }

  bool no_trailing(std::string_view rest, int n, const char* after) {
    if (auto e = detail::trailing_text_error(rest, after)) return fail(n, *e);
    return true;
  }

  bool meta(std::string_view key, std::string_view rest, int n) {
    if (key == "query") {
      if (have_query_) return fail(n, "duplicate 'query' line");
      const std::string_view id = next_token(rest);
      if (id.empty() || id[0] == '#') return fail(n, "missing query id after 'query'");
      if (id == kDelaunayQueryName)
        return fail(n, "query " + std::string(kDelaunayQueryName) +
                           " is a point-set case (see pointset_file.hpp: parse it with parse_point_set)");
      const auto q = query_from_name(id);
      if (!q) return fail(n, "unknown query " + quote_token(id) + " (known: " + known_query_list() + ")");
      if (!no_trailing(rest, n, "the query id")) return false;
      case_.query = *q;
      have_query_ = true;
      return true;
    }
    if (auto e = meta_.read(key, rest, n)) return fail(n, *e);
    return true;
  }

  bool shape(std::string_view rest, int n) {
    const std::string_view kind = next_token(rest);
    if (kind.empty() || kind[0] == '#') return fail(n, "missing shape kind after 'shape'");
    if (!no_trailing(rest, n, "the shape kind")) return false;
    if (stage_ == Stage::Meta) {
      if (!have_query_) return fail(n, "'shape' before the 'query' line");
      const QueryKind qk = info(case_.query).kind;
      if (meta_.have_verdict && !is_known_verdict(qk, meta_.oracle_verdict))
        return fail(meta_.verdict_line, "unknown oracle verdict " + quote_token(meta_.oracle_verdict) + " for query " +
                                       info(case_.query).name + " (known: " + verdict_list(qk) + ")");
      stage_ = Stage::Shapes;
    } else {
      if (!close_shape()) return false;
      if (shape_index_ == 1)
        return fail(n, std::string("too many shapes: query ") + info(case_.query).name + " takes two (" +
                           std::string(query_shape(case_.query, 0).kind) + ", " +
                           std::string(query_shape(case_.query, 1).kind) + ")");
    }
    ++shape_index_;
    layout_ = query_shape(case_.query, shape_index_);
    if (kind != layout_.kind) {
      const std::string expect = std::string("query ") + info(case_.query).name + " takes a " +
                                 std::string(layout_.kind) + " as shape " + kShapeRole[shape_index_];
      if (!is_shape_kind(kind)) return fail(n, "unknown shape kind " + quote_token(kind) + "; " + expect);
      return fail(n, expect + ", got " + quote_token(kind));
    }
    if (layout_.num_fields > seen_.size()) return fail(n, "shape " + std::string(kind) + " has too many fields");
    shape_line_ = n;
    seen_.fill(false);
    values_.assign(layout_.size, 0.0);
    return true;
  }

  bool field(std::string_view name, std::string_view rest, int n) {
    std::size_t index = layout_.num_fields;
    for (std::size_t i = 0; i < layout_.num_fields; ++i)
      if (name == layout_.fields[i].name) index = i;
    const std::string shape_name(layout_.kind);
    if (index == layout_.num_fields)
      return fail(n, "unknown field " + quote_token(name) + " for shape " + shape_name + " (fields: " +
                         field_list(layout_) + ")");
    if (seen_[index]) return fail(n, "duplicate field " + quote_token(name) + " in shape " + shape_name);
    const auto arity = static_cast<std::size_t>(layout_.fields[index].arity);
    std::string_view tokens[3];
    std::size_t count = 0;
    for (std::string_view r = rest;;) {
      const std::string_view t = next_token(r);
      if (t.empty() || t[0] == '#') break;
      if (count < arity) tokens[count] = t;
      ++count;
    }
    if (count != arity)
      return fail(n, "field " + quote_token(name) + " of " + shape_name + " takes " + std::to_string(arity) +
                         (arity == 1 ? " value" : " values") + ", got " + std::to_string(count));
    const std::size_t off = field_offset(layout_, index);
    for (std::size_t k = 0; k < arity; ++k) {
      double v = 0;
      switch (parse_number(tokens[k], v)) {
        case NumStatus::Ok: break;
        case NumStatus::Malformed:
          return fail(n, "malformed number " + quote_token(tokens[k]) + " in field " + quote_token(name) + " of " +
                             shape_name);
        case NumStatus::OutOfRange:
          return fail(n, "number " + quote_token(tokens[k]) + " in field " + quote_token(name) +
                             " is outside the double range (write inf, or a representable value)");
        case NumStatus::BadNanPayload:
          return fail(n, "bad NaN payload " + quote_token(tokens[k]) + " in field " + quote_token(name) +
                             " (nan(0xHHH) takes 1 to 13 hex digits, a non-zero 52-bit fraction)");
      }
      values_[off + k] = v;
    }
    seen_[index] = true;
    return true;
  }

  /// Ends the current shape block, storing its values.
  bool close_shape() {
    for (std::size_t i = 0; i < layout_.num_fields; ++i)
      if (!seen_[i])
        return fail(shape_line_, "shape " + std::string(layout_.kind) + " is missing field " +
                                     quote_token(layout_.fields[i].name));
    (shape_index_ == 0 ? case_.a : case_.b) = values_;
    return true;
  }

  std::string_view text_;
  std::string error_;
  int error_line_ = 0;
  CaseFile case_;
  Stage stage_ = Stage::Header;
  detail::MetaLines meta_;
  bool have_query_ = false;
  int shape_index_ = -1;
  int shape_line_ = 0;
  ShapeLayout layout_;
  std::array<bool, 16> seen_{};
  std::vector<double> values_;
};

}  // namespace

// --- public -----------------------------------------------------------------

bool operator==(const CaseFile& x, const CaseFile& y) {
  auto same = [](const std::vector<double>& u, const std::vector<double>& v) {
    if (u.size() != v.size()) return false;
    for (std::size_t i = 0; i < u.size(); ++i)
      if (bits_of(u[i]) != bits_of(v[i])) return false;
    return true;
  };
  return x.version == y.version && x.query == y.query && same(x.a, y.a) && same(x.b, y.b) &&
         x.oracle_verdict == y.oracle_verdict && x.found_by == y.found_by && x.note == y.note;
}

bool is_registered(QueryId query) { return static_cast<std::size_t>(query) < kNumQueries; }

ShapeLayout query_shape(QueryId query, int which) {
  if (!is_registered(query)) return {};
  return visit_query(query, [which](auto q) {
    using T = QueryTraits<decltype(q)::value>;
    return which == 0 ? shape_layout<typename T::ShapeA>() : shape_layout<typename T::ShapeB>();
  });
}

std::vector<std::string_view> known_verdicts(QueryKind kind) {
  if (kind == QueryKind::Collide) return {"overlapping", "touching", "separated", "undecided"};
  return {"hit", "miss", "undecided"};
}

bool is_known_verdict(QueryKind kind, std::string_view verdict) {
  for (auto v : known_verdicts(kind))
    if (v == verdict) return true;
  return false;
}

std::optional<std::string> case_error(const CaseFile& c) {
  if (c.version != kCaseFileVersion)
    return "unsupported case-file version " + std::to_string(c.version) + " (this build writes version " +
           std::to_string(kCaseFileVersion) + ")";
  if (!is_registered(c.query))
    return "unregistered query id " + std::to_string(static_cast<long long>(c.query));
  const QueryInfo& q = info(c.query);
  const std::vector<double>* v[2] = {&c.a, &c.b};
  for (int w = 0; w < 2; ++w) {
    const ShapeLayout l = query_shape(c.query, w);
    if (v[w]->size() != l.size)
      return std::string("shape ") + kShapeRole[w] + " of " + q.name + " (" + std::string(l.kind) + ") needs " +
             std::to_string(l.size) + " doubles, the case has " + std::to_string(v[w]->size());
  }
  if (!c.oracle_verdict.empty() && !is_known_verdict(q.kind, c.oracle_verdict))
    return "unknown oracle verdict " + quote_token(c.oracle_verdict) + " for query " + q.name + " (known: " +
           verdict_list(q.kind) + ")";
  return std::nullopt;
}

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
  if (parse_number(token, v) != NumStatus::Ok) return std::nullopt;
  return v;
}

std::string write_case(const CaseFile& c) {
  std::string out;
  const bool registered = is_registered(c.query);
  detail::write_header(out, c.version,
                       registered ? std::string(info(c.query).name)
                                  : "unregistered-query-" + std::to_string(static_cast<long long>(c.query)));
  detail::write_meta(out, c.found_by, c.oracle_verdict, c.note);
  const std::vector<double>* vals[2] = {&c.a, &c.b};
  for (int w = 0; w < 2; ++w) {
    const ShapeLayout l = registered ? query_shape(c.query, w) : ShapeLayout{};
    const std::vector<double>& v = *vals[w];
    out += "shape " + (registered ? std::string(l.kind) : std::string("unknown")) + "\n";
    // One line per field; a case with the wrong number of doubles is written
    // as it is (short or long last line) so that parsing it reports the error.
    std::vector<std::string> lhs, rhs;
    std::size_t pos = 0;
    const std::size_t nf = l.num_fields == 0 ? 1 : l.num_fields;
    for (std::size_t f = 0; f < nf; ++f) {
      const char* name = l.num_fields ? l.fields[f].name : "values";
      std::size_t take = l.num_fields ? static_cast<std::size_t>(l.fields[f].arity) : v.size();
      if (f + 1 == nf) take = v.size() > pos ? v.size() - pos : 0;
      take = std::min(take, v.size() > pos ? v.size() - pos : std::size_t{0});
      std::string h = std::string("  ") + name, d;
      for (std::size_t k = 0; k < take; ++k) {
        h += ' ';
        h += format_double(v[pos + k]);
        if (k) d += ' ';
        d += format_decimal(v[pos + k]);
      }
      pos += take;
      lhs.push_back(std::move(h));
      rhs.push_back(std::move(d));
    }
    detail::write_commented_lines(out, lhs, rhs);
  }
  out += "end\n";
  return out;
}

ParseResult parse_case(std::string_view text) { return Parser(text).run(); }

ParseResult load_case(const std::filesystem::path& path) {
  ParseResult res;
  std::string text;
  if (!detail::read_case_text(path, kMaxCaseFileBytes, text, res.error, res.error_line)) return res;
  res = parse_case(text);
  if (!res.ok()) res.error = path.string() + ": " + res.error;
  return res;
}

bool save_case(const std::filesystem::path& path, const CaseFile& c, std::string& error) {
  if (auto e = case_error(c)) {
    error = "refusing to write '" + path.string() + "': " + *e;
    return false;
  }
  return detail::save_text(path, write_case(c), error);
}

}  // namespace geomcheck
