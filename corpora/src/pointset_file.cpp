// geomcheck — point-set case files: writer, parser, classification (format in
// pointset_file.hpp; the shared conventions in case_text.hpp).
#include "geomcheck/pointset_file.hpp"

#include "bits.hpp"
#include "case_text.hpp"

#include <cmath>

namespace geomcheck {

namespace {

using detail::next_token;
using detail::NumStatus;
using detail::quote_token;

std::string verdict_list() {
  std::string s;
  for (auto v : point_set_verdicts()) {
    if (!s.empty()) s += ", ";
    s += v;
  }
  return s;
}

bool is_point_set_verdict(std::string_view verdict) {
  for (auto v : point_set_verdicts())
    if (v == verdict) return true;
  return false;
}

std::string unknown_verdict_error(std::string_view verdict) {
  return "unknown oracle verdict " + quote_token(verdict) + " for query " + kDelaunayQueryName + " (known: " +
         verdict_list() + ")";
}

class Parser {
 public:
  explicit Parser(std::string_view text) : text_(text) {}

  PointSetParseResult run() {
    PointSetParseResult res;
    if (text_.size() > kMaxPointSetFileBytes) {
      fail(1, detail::too_large_error(text_.size(), kMaxPointSetFileBytes));
    } else {
      const int lines =
          detail::for_each_line(text_, [this](std::string_view line, int n) { return statement(line, n); });
      if (error_.empty() && stage_ != Stage::Done)
        fail(lines == 0 ? 1 : lines, detail::unterminated_error(lines, stage_ != Stage::Header));
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

 private:
  enum class Stage { Header, Meta, Points, Done };

  bool fail(int line, std::string what) {
    if (error_.empty()) {
      error_ = "line " + std::to_string(line) + ": " + what;
      error_line_ = line;
    }
    return false;
  }

  bool statement(std::string_view line, int n) {
    if (auto e = detail::control_byte_error(line)) return fail(n, *e);
    std::string_view rest = line;
    const std::string_view key = next_token(rest);
    if (key.empty() || key[0] == '#') return true;  // blank or comment line

    if (stage_ == Stage::Done) return fail(n, "unexpected " + quote_token(key) + " after 'end'");

    if (stage_ == Stage::Header) {
      if (auto e = detail::header_error(key, rest, file_.version)) return fail(n, *e);
      stage_ = Stage::Meta;
      return true;
    }

    if (key == "geomcheck-case") return fail(n, "duplicate 'geomcheck-case' line");
    if (key == "query" || detail::MetaLines::is_text_meta(key)) {
      if (stage_ == Stage::Points) return fail(n, quote_token(key) + " must come before the first 'point'");
      if (key == "query") return query(rest, n);
      if (auto e = meta_.read(key, rest, n)) return fail(n, *e);
      if (key == "oracle-verdict" && !is_point_set_verdict(meta_.oracle_verdict))
        return fail(n, unknown_verdict_error(meta_.oracle_verdict));
      return true;
    }
    if (key == "point") return point(rest, n);
    if (key == "end") {
      if (auto e = detail::trailing_text_error(rest, "'end'")) return fail(n, *e);
      if (!have_query_) return fail(n, "missing 'query' line");
      stage_ = Stage::Done;
      return true;
    }
    if (stage_ == Stage::Points) return fail(n, "unknown keyword " + quote_token(key) + " (expected point or end)");
    return fail(n, "unknown keyword " + quote_token(key) +
                       " (expected query, found-by, oracle-verdict, note, point or end)");
  }

  bool query(std::string_view rest, int n) {
    if (have_query_) return fail(n, "duplicate 'query' line");
    const std::string_view id = next_token(rest);
    if (id.empty() || id[0] == '#') return fail(n, "missing query id after 'query'");
    if (id != kDelaunayQueryName) {
      const std::string holds = std::string(" (a point-set file holds query ") + kDelaunayQueryName + ")";
      if (query_from_name(id))
        return fail(n, "query " + std::string(id) + " is not a point-set query: this is not a point-set file" + holds +
                           "; parse_case reads it");
      return fail(n, "unknown query " + quote_token(id) + ": this is not a point-set file" + holds);
    }
    if (auto e = detail::trailing_text_error(rest, "the query id")) return fail(n, *e);
    have_query_ = true;
    return true;
  }

  bool point(std::string_view rest, int n) {
    if (!have_query_) return fail(n, "'point' before the 'query' line");
    stage_ = Stage::Points;
    std::string_view tokens[2];
    std::size_t count = 0;
    for (std::string_view r = rest;;) {
      const std::string_view t = next_token(r);
      if (t.empty() || t[0] == '#') break;
      if (count < 2) tokens[count] = t;
      ++count;
    }
    if (count != 2) return fail(n, "'point' takes 2 values (x y), got " + std::to_string(count));
    double v[2] = {0, 0};
    for (std::size_t k = 0; k < 2; ++k) {
      switch (detail::parse_number(tokens[k], v[k])) {
        case NumStatus::Ok: break;
        case NumStatus::Malformed: return fail(n, "malformed number " + quote_token(tokens[k]) + " in 'point'");
        case NumStatus::OutOfRange:
          return fail(n, "number " + quote_token(tokens[k]) +
                             " in 'point' is outside the double range (write inf, or a representable value)");
        case NumStatus::BadNanPayload:
          return fail(n, "bad NaN payload " + quote_token(tokens[k]) +
                             " in 'point' (nan(0xHHH) takes 1 to 13 hex digits, a non-zero 52-bit fraction)");
      }
    }
    file_.points.push_back(Vec2{v[0], v[1]});
    return true;
  }

  std::string_view text_;
  std::string error_;
  int error_line_ = 0;
  PointSetFile file_;
  detail::MetaLines meta_;
  Stage stage_ = Stage::Header;
  bool have_query_ = false;
};

}  // namespace

bool operator==(const PointSetFile& x, const PointSetFile& y) {
  if (x.points.size() != y.points.size()) return false;
  for (std::size_t i = 0; i < x.points.size(); ++i)
    if (detail::bits_of(x.points[i].x) != detail::bits_of(y.points[i].x) ||
        detail::bits_of(x.points[i].y) != detail::bits_of(y.points[i].y))
      return false;
  return x.version == y.version && x.oracle_verdict == y.oracle_verdict && x.found_by == y.found_by &&
         x.note == y.note;
}

std::vector<std::string_view> point_set_verdicts() {
  return {"triangulated", "collinear", "coincident", "empty", "rejected"};
}

std::optional<std::string> point_set_error(const PointSetFile& f) {
  if (f.version != kCaseFileVersion)
    return "unsupported case-file version " + std::to_string(f.version) + " (this build writes version " +
           std::to_string(kCaseFileVersion) + ")";
  if (!f.oracle_verdict.empty() && !is_point_set_verdict(f.oracle_verdict))
    return unknown_verdict_error(f.oracle_verdict);
  return std::nullopt;
}

std::string write_point_set(const PointSetFile& f) {
  std::string out;
  detail::write_header(out, f.version, kDelaunayQueryName);
  detail::write_meta(out, f.found_by, f.oracle_verdict, f.note);
  std::vector<std::string> lhs, rhs;
  lhs.reserve(f.points.size());
  rhs.reserve(f.points.size());
  for (const Vec2& p : f.points) {
    lhs.push_back("point " + format_double(p.x) + " " + format_double(p.y));
    rhs.push_back(format_decimal(p.x) + " " + format_decimal(p.y));
  }
  detail::write_commented_lines(out, lhs, rhs);
  out += "end\n";
  return out;
}

PointSetParseResult parse_point_set(std::string_view text) { return Parser(text).run(); }

PointSetParseResult load_point_set(const std::filesystem::path& path) {
  PointSetParseResult res;
  std::string text;
  if (!detail::read_case_text(path, kMaxPointSetFileBytes, text, res.error, res.error_line)) return res;
  res = parse_point_set(text);
  if (!res.ok()) res.error = path.string() + ": " + res.error;
  return res;
}

bool save_point_set(const std::filesystem::path& path, const PointSetFile& f, std::string& error) {
  if (auto e = point_set_error(f)) {
    error = "refusing to write '" + path.string() + "': " + *e;
    return false;
  }
  return detail::save_text(path, write_point_set(f), error);
}

bool is_point_set_text(std::string_view text) {
  bool found = false;
  detail::for_each_line(text, [&found](std::string_view line, int) {
    std::string_view rest = line;
    if (next_token(rest) != "query") return true;
    found = next_token(rest) == kDelaunayQueryName;
    return false;
  });
  return found;
}

std::string_view classify_point_set(const std::vector<Vec2>& points) {
  for (const Vec2& p : points)
    if (!std::isfinite(p.x) || !std::isfinite(p.y)) return "rejected";
  if (points.empty()) return "empty";
  const Vec2 a = points[0];
  std::size_t i = 1;
  while (i < points.size() && points[i] == a) ++i;
  if (i == points.size()) return "coincident";
  const Vec2 b = points[i];
  for (const Vec2& p : points)
    if (orient2d(a, b, p) != 0) return "triangulated";
  return "collinear";
}

std::string fuzz_input_from_point_set(const std::vector<Vec2>& points) {
  std::vector<double> values;
  values.reserve(2 * points.size());
  for (const Vec2& p : points) {
    values.push_back(p.x);
    values.push_back(p.y);
  }
  const std::vector<std::uint8_t> bytes = encode_raw_doubles(values);
  std::string out(1, '\0');
  out.append(bytes.begin(), bytes.end());
  return out;
}

}  // namespace geomcheck
