// geomcheck — case files: writer, parser and validation (format in
// casefile.hpp; the text core the formats share in detail/text_format.hpp).
#include "geomcheck/casefile.hpp"

#include "geomcheck/detail/text_format.hpp"
#include "geomcheck/pointset_file.hpp"

#include <sstream>
#include <fstream>
#include <algorithm>

namespace geomcheck {

namespace {

using detail::bits_of;
using detail::join_list;
using detail::next_token;
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
  std::vector<std::string_view> names;
  for (std::size_t i = 0; i < l.num_fields; ++i) names.push_back(l.fields[i].name);
  return join_list(names);
}

std::string known_query_list() {
  std::vector<std::string_view> names;
  for (const auto& q : kQueries) names.push_back(q.name);
  return join_list(names);
}

std::string verdict_list(QueryKind kind) { return join_list(known_verdicts(kind)); }

const char* const kShapeRole[2] = {"A", "B"};

// --- parser -----------------------------------------------------------------

/// The body of a case file: two shape blocks (the statement loop, header and
/// meta lines are LineParser's).
class Parser : public detail::LineParser<Parser, CaseFile> {
 public:
  static constexpr const char* kBodyKeyword = "shape";

  bool query_id(std::string_view id, int n) {
    if (id == kDelaunayQueryName)
      return fail(n, "query " + std::string(kDelaunayQueryName) +
                         " is a point-set case (see pointset_file.hpp: parse it with parse_point_set)");
    if (family_of(id) == QueryFamily::Mesh)
      return fail(n, "query " + std::string(id) + " is a mesh case (see mesh_file.hpp: parse it with parse_mesh_file)");
    const auto q = query_from_name(id);
    if (!q) return fail(n, "unknown query " + quote_token(id) + " (known: " + known_query_list() + ")");
    file_.query = *q;
    return true;
  }

  bool after_meta(std::string_view, int) { return true; }

  bool body(std::string_view key, std::string_view rest, int n) {
    if (key == "shape") return shape(rest, n);
    if (key == "end") {
      if (!no_trailing(rest, n, "'end'")) return false;
      if (stage_ == Stage::Meta) {
        if (!have_query_) return fail(n, "missing 'query' line");
        return fail(n, "missing shape A (" + std::string(query_shape(file_.query, 0).kind) + ") before 'end'");
      }
      if (!close_shape()) return false;
      if (shape_index_ == 0)
        return fail(n, "missing shape B (" + std::string(query_shape(file_.query, 1).kind) + ") before 'end'");
      stage_ = Stage::Done;
      return true;
    }
    if (stage_ == Stage::Body) return field(key, rest, n);
    return fail(n, "unknown keyword " + quote_token(key) +
                       " (expected query, found-by, oracle-verdict, note or shape)");
  }

 private:
  bool shape(std::string_view rest, int n) {
    const std::string_view kind = next_token(rest);
    if (kind.empty() || kind[0] == '#') return fail(n, "missing shape kind after 'shape'");
    if (!no_trailing(rest, n, "the shape kind")) return false;
    if (stage_ == Stage::Meta) {
      if (!have_query_) return fail(n, "'shape' before the 'query' line");
      const QueryKind qk = info(file_.query).kind;
      if (meta_.have_verdict && !is_known_verdict(qk, meta_.oracle_verdict))
        return fail(meta_.verdict_line, "unknown oracle verdict " + quote_token(meta_.oracle_verdict) + " for query " +
                                       info(file_.query).name + " (known: " + verdict_list(qk) + ")");
      stage_ = Stage::Body;
    } else {
      if (!close_shape()) return false;
      if (shape_index_ == 1)
        return fail(n, std::string("too many shapes: query ") + info(file_.query).name + " takes two (" +
                           std::string(query_shape(file_.query, 0).kind) + ", " +
                           std::string(query_shape(file_.query, 1).kind) + ")");
    }
    ++shape_index_;
    layout_ = query_shape(file_.query, shape_index_);
    if (kind != layout_.kind) {
      const std::string expect = std::string("query ") + info(file_.query).name + " takes a " +
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
    const std::size_t count = detail::value_tokens(rest, tokens, arity);
    if (count != arity)
      return fail(n, "field " + quote_token(name) + " of " + shape_name + " takes " + std::to_string(arity) +
                         (arity == 1 ? " value" : " values") + ", got " + std::to_string(count));
    if (auto e = detail::parse_values(tokens, arity, values_.data() + layout_.offset(index),
                                      "in field " + quote_token(name), " of " + shape_name))
      return fail(n, *e);
    seen_[index] = true;
    return true;
  }

  /// Ends the current shape block, storing its values.
  bool close_shape() {
    for (std::size_t i = 0; i < layout_.num_fields; ++i)
      if (!seen_[i])
        return fail(shape_line_, "shape " + std::string(layout_.kind) + " is missing field " +
                                     quote_token(layout_.fields[i].name));
    (shape_index_ == 0 ? file_.a : file_.b) = values_;
    return true;
  }

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
  if (auto e = detail::write_version_error(c.version)) return e;
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

std::string write_case(const CaseFile& c) {
  std::string out;
  const bool registered = is_registered(c.query);
  detail::write_preamble(out, c,
                         registered ? std::string(info(c.query).name)
                                    : "unregistered-query-" + std::to_string(static_cast<long long>(c.query)));
  const std::vector<double>* vals[2] = {&c.a, &c.b};
  detail::ValueLines lines;
  for (int w = 0; w < 2; ++w) {
    const ShapeLayout l = registered ? query_shape(c.query, w) : ShapeLayout{};
    const std::vector<double>& v = *vals[w];
    out += "shape " + (registered ? std::string(l.kind) : std::string("unknown")) + "\n";
    // One line per field; a case with the wrong number of doubles is written
    // as it is (short or long last line) so that parsing it reports the error.
    std::size_t pos = 0;
    const std::size_t nf = l.num_fields == 0 ? 1 : l.num_fields;
    for (std::size_t f = 0; f < nf; ++f) {
      const char* name = l.num_fields ? l.fields[f].name : "values";
      std::size_t take = l.num_fields ? static_cast<std::size_t>(l.fields[f].arity) : v.size();
      if (f + 1 == nf) take = v.size() > pos ? v.size() - pos : 0;
      take = std::min(take, v.size() > pos ? v.size() - pos : std::size_t{0});
      lines.add(std::string("  ") + name, v.data() + pos, take);
      pos += take;
    }
    lines.write(out);
  }
  out += "end\n";
  return out;
}

ParseResult parse_case(std::string_view text) { return Parser().run(text, kMaxCaseFileBytes); }

std::string declared_query(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  char head[4096];
  in.read(head, sizeof head);  // the header is short; a file is never read whole here
  std::istringstream lines(std::string(head, static_cast<std::size_t>(in.gcount())));
  std::string line;
  while (std::getline(lines, line)) {
    std::istringstream words(line);
    std::string key, name;
    if (words >> key && key == "query") return words >> name ? name : "";  // the first query line decides
  }
  return "";
}

}  // namespace geomcheck
