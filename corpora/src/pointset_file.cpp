// geomcheck — point-set case files: writer, parser, classification (format in
// pointset_file.hpp; the text core the formats share in detail/text_format.hpp).
#include "geomcheck/pointset_file.hpp"

#include "geomcheck/detail/text_format.hpp"

#include <cmath>

namespace geomcheck {

namespace {

using detail::next_token;
using detail::quote_token;

bool is_point_set_verdict(std::string_view verdict) {
  for (auto v : point_set_verdicts())
    if (v == verdict) return true;
  return false;
}

std::string unknown_verdict_error(std::string_view verdict) {
  return "unknown oracle verdict " + quote_token(verdict) + " for query " + kDelaunayQueryName + " (known: " +
         detail::join_list(point_set_verdicts()) + ")";
}

/// The body of a point-set file: point lines (the statement loop, header and
/// meta lines are LineParser's).
class Parser : public detail::LineParser<Parser, PointSetFile> {
 public:
  static constexpr const char* kBodyKeyword = "point";

  bool query_id(std::string_view id, int n) {
    if (id == kDelaunayQueryName) return true;
    const std::string holds = std::string(" (a point-set file holds query ") + kDelaunayQueryName + ")";
    if (query_from_name(id))
      return fail(n, "query " + std::string(id) + " is not a point-set query: this is not a point-set file" + holds +
                         "; parse_case reads it");
    if (family_of(id) == QueryFamily::Mesh)
      return fail(n, "query " + std::string(id) + " is not a point-set query: this is not a point-set file" + holds +
                         "; parse_mesh_file reads it");
    return fail(n, "unknown query " + quote_token(id) + ": this is not a point-set file" + holds);
  }

  bool after_meta(std::string_view key, int n) {
    if (key == "oracle-verdict" && !is_point_set_verdict(meta_.oracle_verdict))
      return fail(n, unknown_verdict_error(meta_.oracle_verdict));
    return true;
  }

  bool body(std::string_view key, std::string_view rest, int n) {
    if (key == "point") return point(rest, n);
    if (key == "end") {
      if (!no_trailing(rest, n, "'end'")) return false;
      if (!have_query_) return fail(n, "missing 'query' line");
      stage_ = Stage::Done;
      return true;
    }
    if (stage_ == Stage::Body) return fail(n, "unknown keyword " + quote_token(key) + " (expected point or end)");
    return fail(n, "unknown keyword " + quote_token(key) +
                       " (expected query, found-by, oracle-verdict, note, point or end)");
  }

 private:
  bool point(std::string_view rest, int n) {
    if (!have_query_) return fail(n, "'point' before the 'query' line");
    stage_ = Stage::Body;
    std::string_view tokens[2];
    if (!exactly(tokens, rest, n, "point", "values (x y)")) return false;
    double v[2] = {0, 0};
    if (auto e = detail::parse_values(tokens, 2, v, "in 'point'", "")) return fail(n, *e);
    file_.points.push_back(Vec2{v[0], v[1]});
    return true;
  }
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
  if (auto e = detail::write_version_error(f.version)) return e;
  if (!f.oracle_verdict.empty() && !is_point_set_verdict(f.oracle_verdict))
    return unknown_verdict_error(f.oracle_verdict);
  return std::nullopt;
}

std::string write_point_set(const PointSetFile& f) {
  std::string out;
  detail::write_preamble(out, f, kDelaunayQueryName);
  detail::ValueLines lines;
  for (const Vec2& p : f.points) {
    const double xy[2] = {p.x, p.y};
    lines.add("point", xy, 2);
  }
  lines.write(out);
  out += "end\n";
  return out;
}

PointSetParseResult parse_point_set(std::string_view text) { return Parser().run(text, kMaxPointSetFileBytes); }

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
