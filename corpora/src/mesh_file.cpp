// geomcheck — mesh case files: writer and parser (format in mesh_file.hpp;
// the text core the case-file formats share in detail/text_format.hpp).
#include "geomcheck/mesh_file.hpp"

#include "geomcheck/detail/text_format.hpp"

namespace geomcheck {

namespace {

using detail::quote_token;

bool is_mesh_verdict(std::string_view verdict) {
  for (auto v : mesh_verdicts())
    if (v == verdict) return true;
  return false;
}

std::string unknown_verdict_error(std::string_view verdict, std::string_view query) {
  return "unknown oracle verdict " + quote_token(verdict) + " for query " + std::string(query) + " (known: " +
         detail::join_list(mesh_verdicts()) + ")";
}

std::string mesh_query_list() {
  std::vector<std::string_view> names;
  for (const auto& q : kAllQueries)
    if (q.family == QueryFamily::Mesh) names.push_back(q.name);
  return detail::join_list(names);
}

std::string too_many(const char* what, std::size_t limit) {
  return "more than " + std::to_string(limit) + " " + what + " (the limit of a mesh file)";
}

/// INDEX: a decimal from 0 to 4294967295, digits only.
bool parse_index(std::string_view t, std::uint32_t& out) {
  if (t.empty()) return false;
  std::uint64_t v = 0;
  for (char ch : t) {
    if (ch < '0' || ch > '9') return false;
    v = 10 * v + static_cast<std::uint64_t>(ch - '0');
    if (v > 0xffffffffull) return false;  // leading zeros are fine, a value beyond is not
  }
  out = static_cast<std::uint32_t>(v);
  return true;
}

/// The body of a mesh file: the cylinder, vertex and face lines (the
/// statement loop, header and meta lines are LineParser's).
class Parser : public detail::LineParser<Parser, MeshFile> {
 public:
  static constexpr const char* kBodyKeyword = "cylinder";

  bool query_id(std::string_view id, int n) {
    const auto family = family_of(id);
    if (family == QueryFamily::Mesh) {
      file_.query = std::string(id);
      return true;
    }
    const std::string holds = " (a mesh file holds query " + mesh_query_list() + ")";
    if (family == QueryFamily::Pair)
      return fail(n, "query " + std::string(id) + " is not a mesh query: this is not a mesh file" + holds +
                         "; parse_case reads it");
    if (family == QueryFamily::PointSet)
      return fail(n, "query " + std::string(id) + " is not a mesh query: this is not a mesh file" + holds +
                         "; parse_point_set reads it");
    return fail(n, "unknown query " + quote_token(id) + ": this is not a mesh file" + holds);
  }

  bool after_meta(std::string_view key, int n) {
    if (key == "oracle-verdict" && !is_mesh_verdict(meta_.oracle_verdict))
      return fail(n, unknown_verdict_error(meta_.oracle_verdict, have_query_ ? file_.query : mesh_query_list()));
    return true;
  }

  bool body(std::string_view key, std::string_view rest, int n) {
    if (key == "cylinder") return cylinder(rest, n);
    if (key == "vertex") return vertex(rest, n);
    if (key == "face") return face(rest, n);
    if (key == "end") {
      if (!no_trailing(rest, n, "'end'")) return false;
      if (!have_query_) return fail(n, "missing 'query' line");
      if (!have_cylinder_) return fail(n, "missing 'cylinder' line before 'end'");
      stage_ = Stage::Done;
      return true;
    }
    if (stage_ == Stage::Body)
      return fail(n, "unknown keyword " + quote_token(key) + " (expected vertex, face or end)");
    return fail(n, "unknown keyword " + quote_token(key) +
                       " (expected query, found-by, oracle-verdict, note, cylinder or end)");
  }

 private:
  bool cylinder(std::string_view rest, int n) {
    if (!have_query_) return fail(n, "'cylinder' before the 'query' line");
    if (have_cylinder_) return fail(n, "duplicate 'cylinder' line");
    stage_ = Stage::Body;
    std::string_view tokens[7];
    if (!exactly(tokens, rest, n, "cylinder", "values (p, q, r)")) return false;
    double v[7];
    if (auto e = detail::parse_values(tokens, 7, v, "in 'cylinder'", "")) return fail(n, *e);
    file_.cylinder = {{v[0], v[1], v[2]}, {v[3], v[4], v[5]}, v[6]};
    have_cylinder_ = true;
    return true;
  }

  /// Whether a `word` line may come: after the cylinder line, and fewer
  /// than `limit` such lines (`held` so far, called `plural`) before it.
  bool room_for(const char* word, std::size_t held, std::size_t limit, const char* plural, int n) {
    if (!have_cylinder_) return fail(n, "'" + std::string(word) + "' before the 'cylinder' line");
    if (held >= limit) return fail(n, too_many(plural, limit));
    return true;
  }

  bool vertex(std::string_view rest, int n) {
    if (!room_for("vertex", file_.vertices.size(), kMaxMeshVertices, "vertices", n)) return false;
    std::string_view tokens[3];
    if (!exactly(tokens, rest, n, "vertex", "values (x y z)")) return false;
    double v[3];
    if (auto e = detail::parse_values(tokens, 3, v, "in 'vertex'", "")) return fail(n, *e);
    file_.vertices.push_back({v[0], v[1], v[2]});
    return true;
  }

  bool face(std::string_view rest, int n) {
    if (!room_for("face", file_.faces.size(), kMaxMeshFaces, "faces", n)) return false;
    std::string_view tokens[3];
    if (!exactly(tokens, rest, n, "face", "vertex indices")) return false;
    MeshFace f{};
    for (int k = 0; k < 3; ++k)
      if (!parse_index(tokens[k], f[k]))
        return fail(n, "malformed index " + quote_token(tokens[k]) + " in 'face' (a decimal from 0 to 4294967295)");
    file_.faces.push_back(f);
    return true;
  }

  bool have_cylinder_ = false;
};

bool same_bits(Vec3 a, Vec3 b) {
  return detail::bits_of(a.x) == detail::bits_of(b.x) && detail::bits_of(a.y) == detail::bits_of(b.y) &&
         detail::bits_of(a.z) == detail::bits_of(b.z);
}

}  // namespace

bool operator==(const MeshFile& x, const MeshFile& y) {
  if (x.vertices.size() != y.vertices.size() || x.faces != y.faces) return false;
  for (std::size_t i = 0; i < x.vertices.size(); ++i)
    if (!same_bits(x.vertices[i], y.vertices[i])) return false;
  return x.version == y.version && x.query == y.query && same_bits(x.cylinder.p, y.cylinder.p) &&
         same_bits(x.cylinder.q, y.cylinder.q) && detail::bits_of(x.cylinder.r) == detail::bits_of(y.cylinder.r) &&
         x.oracle_verdict == y.oracle_verdict && x.found_by == y.found_by && x.note == y.note;
}

std::vector<std::string_view> mesh_verdicts() { return {"overlapping", "touching", "separated", "undecided"}; }

std::optional<std::string> mesh_file_error(const MeshFile& f) {
  if (auto e = detail::write_version_error(f.version)) return e;
  if (family_of(f.query) != QueryFamily::Mesh)
    return "query " + quote_token(f.query) + " is not a mesh query (known: " + mesh_query_list() + ")";
  if (!f.oracle_verdict.empty() && !is_mesh_verdict(f.oracle_verdict))
    return unknown_verdict_error(f.oracle_verdict, f.query);
  if (f.vertices.size() > kMaxMeshVertices) return too_many("vertices", kMaxMeshVertices);
  if (f.faces.size() > kMaxMeshFaces) return too_many("faces", kMaxMeshFaces);
  // The text's size: written only when the longest lines could reach the
  // limit (a vertex line is at most about 170 bytes, a face line 38).
  const std::size_t bound = 170 * f.vertices.size() + 38 * f.faces.size() + 8 * (f.note.size() + f.found_by.size()) + 4096;
  if (bound > kMaxMeshFileBytes) {
    const std::size_t bytes = write_mesh_file(f).size();
    if (bytes > kMaxMeshFileBytes)
      return "the file would be " + std::to_string(bytes) + " bytes, beyond the limit of a mesh file (" +
             std::to_string(kMaxMeshFileBytes) + ")";
  }
  return std::nullopt;
}

std::string write_mesh_file(const MeshFile& f) {
  std::string out;
  detail::write_preamble(out, f, f.query);
  detail::ValueLines lines;
  const Cylinder& c = f.cylinder;
  const double cyl[7] = {c.p.x, c.p.y, c.p.z, c.q.x, c.q.y, c.q.z, c.r};
  lines.add("cylinder", cyl, 7);
  lines.write(out);  // the vertices' comments aligned among themselves, not with the longer cylinder line
  for (const Vec3& v : f.vertices) {
    const double xyz[3] = {v.x, v.y, v.z};
    lines.add("vertex", xyz, 3);
  }
  lines.write(out);
  for (const MeshFace& t : f.faces)
    out += "face " + std::to_string(t[0]) + ' ' + std::to_string(t[1]) + ' ' + std::to_string(t[2]) + '\n';
  out += "end\n";
  return out;
}

MeshParseResult parse_mesh_file(std::string_view text) { return Parser().run(text, kMaxMeshFileBytes); }

std::optional<std::string> fuzz_input_from_mesh(const MeshFile& f) {
  const std::size_t nv = f.vertices.size(), nf = f.faces.size();
  if (nv > 31 || nf > 63) return std::nullopt;
  const Cylinder& c = f.cylinder;
  std::vector<double> values{c.p.x, c.p.y, c.p.z, c.q.x, c.q.y, c.q.z, c.r};
  for (const Vec3& v : f.vertices) values.insert(values.end(), {v.x, v.y, v.z});
  const std::vector<std::uint8_t> bytes = encode_raw_doubles(values);
  std::string out{'\0', static_cast<char>(nv), static_cast<char>(nf)};
  out.append(bytes.begin(), bytes.end());
  for (const MeshFace& t : f.faces)
    for (std::uint32_t k : t) out += static_cast<char>(k < nv ? k : nv);
  return out;
}

}  // namespace geomcheck
