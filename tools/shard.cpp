#include "shard.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <set>
#include <stdexcept>

#include <nlohmann/json.hpp>

namespace geomcheck {

namespace {

namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;
using report::PointSetReport;
using report::MeshReport;
using report::QueryReport;
using report::Series;

/// The layout of shard.json (bumped on any change: merge refuses others).
constexpr int kShardFormat = 2;

/// A string that lives as long as the program (Claims hold const char*).
const char* intern(const std::string& s) {
  static std::set<std::string> pool;
  return pool.insert(s).first->c_str();
}

// One visitor over every field of a report, for both directions: Out
// writes the fields into a JSON object, In reads them back.
struct Out {
  Json& j;
  void operator()(const char* k, const int& v) { j[k] = v; }
  void operator()(const char* k, const bool& v) { j[k] = v; }
  void operator()(const char* k, const std::size_t& v) { j[k] = v; }
  void operator()(const char* k, const unsigned long long& v) { j[k] = v; }
  void operator()(const char* k, const double& v) {
    if (std::isfinite(v)) j[k] = v;
    else j[k] = std::isnan(v) ? Json("nan") : Json(v > 0 ? "inf" : "-inf");
  }
  void operator()(const char* k, const std::string& v) { j[k] = v; }
  void operator()(const char* k, const char* const& v) { j[k] = std::string(v ? v : ""); }
  void operator()(const char* k, const std::map<std::string, int>& v) { j[k] = v; }
  void operator()(const char* k, const std::vector<std::string>& v) { j[k] = v; }
  void operator()(const char* k, const Series& v) { j[k] = v.v; }
  void operator()(const char* k, const Claims::Depth& v) { j[k] = static_cast<int>(v); }
  template <class T>
  void operator()(const char* k, const std::vector<T>& v) {
    Json a = Json::array();
    for (const T& x : v) {
      Json o = Json::object();
      Out w{o};
      fields(w, const_cast<T&>(x));
      a.push_back(std::move(o));
    }
    j[k] = std::move(a);
  }
  template <class T>
  static void fields(Out& w, T& x);
};

struct In {
  const Json& j;
  const Json& at(const char* k) const {
    if (!j.contains(k)) throw std::runtime_error(std::string("shard.json: field '") + k + "' missing");
    return j.at(k);
  }
  void operator()(const char* k, int& v) { v = at(k).get<int>(); }
  void operator()(const char* k, bool& v) { v = at(k).get<bool>(); }
  void operator()(const char* k, std::size_t& v) { v = at(k).get<std::size_t>(); }
  void operator()(const char* k, unsigned long long& v) { v = at(k).get<unsigned long long>(); }
  void operator()(const char* k, double& v) {
    const Json& x = at(k);
    if (x.is_string()) {
      const std::string s = x.get<std::string>();
      v = s == "nan" ? NAN : (s == "inf" ? INFINITY : -INFINITY);
    } else {
      v = x.get<double>();
    }
  }
  void operator()(const char* k, std::string& v) { v = at(k).get<std::string>(); }
  void operator()(const char* k, const char*& v) { v = intern(at(k).get<std::string>()); }
  void operator()(const char* k, std::map<std::string, int>& v) { v = at(k).get<std::map<std::string, int>>(); }
  void operator()(const char* k, std::vector<std::string>& v) { v = at(k).get<std::vector<std::string>>(); }
  void operator()(const char* k, Series& v) { v.v = at(k).get<std::vector<double>>(); }
  void operator()(const char* k, Claims::Depth& v) { v = static_cast<Claims::Depth>(at(k).get<int>()); }
  template <class T>
  void operator()(const char* k, std::vector<T>& v) {
    v.clear();
    for (const Json& o : at(k)) {
      T x{};
      In r{o};
      fields(r, x);
      v.push_back(std::move(x));
    }
  }
};

template <class IO>
void fields(IO& io, Claims& c) {
  io("exact_verdict", c.exact_verdict);
  io("depth", c.depth);
  io("point_in_both", c.point_in_both);
  io("normal", c.normal);
  io("truth", c.truth);
  io("touching_is_contact", c.touching_is_contact);
  io("margin", c.margin);
}

template <class IO>
void fields(IO& io, Tolerances& t) {
  io("verdict", t.verdict);
  io("depth", t.depth);
  io("normal", t.normal);
  io("point", t.point);
  io("t", t.t);
  io("unit", t.unit);
}

/// A nested object (claims, tolerances) through the same visitor.
template <class T>
void nested(Out& w, const char* k, T& x) {
  Json o = Json::object();
  Out inner{o};
  fields(inner, x);
  w.j[k] = std::move(o);
}
template <class T>
void nested(In& r, const char* k, T& x) {
  In inner{r.at(k)};
  fields(inner, x);
}

template <class IO>
void fields(IO& io, QueryReport& r) {
  io("name", r.name);
  io("summary", r.summary);
  io("subject", r.subject);
  io("replay", r.replay);
  nested(io, "claims", r.claims);
  io("own_claims", r.own_claims);
  io("requested", r.requested);
  io("stopped_by_time", r.stopped_by_time);
  io("cases", r.cases);
  io("valid", r.valid);
  io("prod_hits", r.prod_hits);
  io("truth_hits", r.truth_hits);
  io("not_expressed", r.not_expressed);
  io("verdicts", r.verdicts);
  io("disagree", r.disagree);
  io("excused", r.excused);
  io("beyond", r.beyond);
  io("check_failures", r.check_failures);
  io("worst_margin", r.worst_margin);
  io("depth", r.depth);
  io("normal", r.normal);
  io("point", r.point);
  io("t", r.t);
  io("fcl_supported", r.fcl_supported);
  io("fcl_ok", r.fcl_ok);
  io("fcl_disagree", r.fcl_disagree);
  io("fcl_beyond", r.fcl_beyond);
  io("fcl_depth", r.fcl_depth);
  io("fcl_normal", r.fcl_normal);
  io("fcl_point", r.fcl_point);
  io("fcl_t_gap", r.fcl_t_gap);
  io("fcl_t", r.fcl_t);
  io("fcl_distance", r.fcl_distance);
  io("fcl_distance_asked", r.fcl_distance_asked);
  io("fcl_distance_beyond", r.fcl_distance_beyond);
  io("fcl_cases", r.fcl_cases);
  io("fcl_by_signature", r.fcl_by_signature);
  io("fcl_shrunk", r.fcl_shrunk);
  io("prod_ns", r.prod_ns);
  io("oracle_us", r.oracle_us);
  io("truth_stages", r.truth_stages);
  io("counterexamples", r.counterexamples);
  io("drawings", r.drawings);
  io("fcl_drawings", r.fcl_drawings);
  io("failures_by_property", r.failures_by_property);
  io("failures_by_signature", r.failures_by_signature);
  io("shrunk", r.shrunk);
  nested(io, "tol", r.tol);
  io("depth_is_bound", r.depth_is_bound);
  io("depth_ratio", r.depth_ratio);
  io("peers", r.peers);
  io("first", r.first);
  io("bugreports", r.bugreports);
  io("bugreports_failed", r.bugreports_failed);
}

template <class IO>
void fields(IO& io, PointSetReport& r) {
  io("name", r.name);
  io("summary", r.summary);
  io("subject", r.subject);
  io("not_asked", r.not_asked);
  io("requested", r.requested);
  io("stopped_by_time", r.stopped_by_time);
  io("sets", r.sets);
  io("points", r.points);
  io("modes", r.modes);
  io("kinds", r.kinds);
  io("failures", r.failures);
  io("failures_by_property", r.failures_by_property);
  io("cgal_choices_differ", r.cgal_choices_differ);
  io("production_us", r.production_us);
  io("cgal_us", r.cgal_us);
  io("counterexamples", r.counterexamples);
}

template <class IO>
void fields(IO& io, MeshReport& r) {
  io("name", r.name);
  io("summary", r.summary);
  io("under_test", r.under_test);
  io("requested", r.requested);
  io("stopped_by_time", r.stopped_by_time);
  io("meshes", r.meshes);
  io("faces", r.faces);
  io("modes", r.modes);
  io("verdicts", r.verdicts);
  io("failures", r.failures);
  io("failures_by_property", r.failures_by_property);
  io("faces_by_box", r.faces_by_box);
  io("faces_by_engine", r.faces_by_engine);
  io("production_us", r.production_us);
  io("brute_force_us", r.brute_force_us);
  io("seconds", r.seconds);
  io("counterexamples", r.counterexamples);
}

template <class IO>
void fields(IO& io, report::RunInfo& r) {
  io("version", r.version);
  io("started", r.started);
  io("command", r.command);
  io("seed", r.seed);
  io("per_query", r.per_query);
  io("rerun", r.rerun);
  io("under_test", r.under_test);
}

template <class T>
void Out::fields(Out& w, T& x) {
  geomcheck::fields(w, x);
}

// ---- merging -----------------------------------------------------------------

void add(std::map<std::string, int>& a, const std::map<std::string, int>& b) {
  for (const auto& [k, v] : b) a[k] += v;
}
void add(Series& a, const Series& b) { a.v.insert(a.v.end(), b.v.begin(), b.v.end()); }
void add(std::vector<std::string>& a, const std::vector<std::string>& b) { a.insert(a.end(), b.begin(), b.end()); }
/// Mean of two per-case figures weighted by their cases (NaN where neither has any).
double weighted(double x, int nx, double y, int ny) {
  if (!(nx > 0) || !std::isfinite(x)) return ny > 0 ? y : x;
  if (!(ny > 0) || !std::isfinite(y)) return x;
  return (x * nx + y * ny) / (nx + ny);
}

/// b's counts, samples and saved cases into a (the same query, another shard).
void merge_into(QueryReport& a, const QueryReport& b) {
  a.oracle_us = weighted(a.oracle_us, a.cases, b.oracle_us, b.cases);
  a.prod_ns = weighted(a.prod_ns, a.cases, b.prod_ns, b.cases);
  a.requested += b.requested;
  a.stopped_by_time = a.stopped_by_time || b.stopped_by_time;
  a.cases += b.cases;
  a.valid += b.valid;
  a.prod_hits += b.prod_hits;
  a.truth_hits += b.truth_hits;
  a.not_expressed += b.not_expressed;
  add(a.verdicts, b.verdicts);
  a.disagree += b.disagree;
  a.excused += b.excused;
  a.beyond += b.beyond;
  a.check_failures += b.check_failures;
  a.worst_margin = std::max(a.worst_margin, b.worst_margin);
  add(a.depth, b.depth);
  add(a.normal, b.normal);
  add(a.point, b.point);
  add(a.t, b.t);
  a.fcl_supported += b.fcl_supported;
  a.fcl_ok += b.fcl_ok;
  a.fcl_disagree += b.fcl_disagree;
  a.fcl_beyond += b.fcl_beyond;
  add(a.fcl_depth, b.fcl_depth);
  add(a.fcl_normal, b.fcl_normal);
  add(a.fcl_point, b.fcl_point);
  add(a.fcl_t_gap, b.fcl_t_gap);
  add(a.fcl_t, b.fcl_t);
  add(a.fcl_distance, b.fcl_distance);
  a.fcl_distance_asked += b.fcl_distance_asked;
  a.fcl_distance_beyond += b.fcl_distance_beyond;
  add(a.fcl_cases, b.fcl_cases);
  add(a.fcl_by_signature, b.fcl_by_signature);
  a.fcl_shrunk += b.fcl_shrunk;
  add(a.truth_stages, b.truth_stages);
  add(a.counterexamples, b.counterexamples);
  for (const std::string& d : b.drawings)
    if (a.drawings.size() < 12) a.drawings.push_back(d);
  add(a.fcl_drawings, b.fcl_drawings);
  add(a.failures_by_property, b.failures_by_property);
  add(a.failures_by_signature, b.failures_by_signature);
  a.shrunk += b.shrunk;
  add(a.depth_ratio, b.depth_ratio);
  if (a.peers.empty()) a.peers = b.peers;  // the engines ran in shard 0 only
  if (a.first.empty()) a.first = b.first;
  else if (!b.first.empty()) merge_into(a.first.front(), b.first.front());
}

void merge_into(PointSetReport& a, const PointSetReport& b) {
  a.requested += b.requested;
  a.stopped_by_time = a.stopped_by_time || b.stopped_by_time;
  a.sets += b.sets;
  a.points += b.points;
  add(a.modes, b.modes);
  add(a.kinds, b.kinds);
  a.failures += b.failures;
  add(a.failures_by_property, b.failures_by_property);
  a.cgal_choices_differ += b.cgal_choices_differ;
  a.not_asked += b.not_asked;
  a.production_us += b.production_us;
  a.cgal_us += b.cgal_us;
  add(a.counterexamples, b.counterexamples);
}

void merge_into(MeshReport& a, const MeshReport& b) {
  a.requested += b.requested;
  a.stopped_by_time = a.stopped_by_time || b.stopped_by_time;
  a.meshes += b.meshes;
  a.faces += b.faces;
  add(a.modes, b.modes);
  add(a.verdicts, b.verdicts);
  a.failures += b.failures;
  add(a.failures_by_property, b.failures_by_property);
  a.faces_by_box += b.faces_by_box;
  a.faces_by_engine += b.faces_by_engine;
  a.production_us += b.production_us;
  a.brute_force_us += b.brute_force_us;
  a.seconds = std::max(a.seconds, b.seconds);  // the shards run side by side
  add(a.counterexamples, b.counterexamples);
}

/// A path written by a shard whose output was `was`, now under `now`.
std::string moved(const std::string& p, const fs::path& was, const fs::path& now) {
  const fs::path rel = fs::path(p).lexically_normal().lexically_relative(was.lexically_normal());
  if (rel.empty() || *rel.begin() == "..") return p;
  return (now / rel).string();
}
void move_paths(std::vector<std::string>& v, const fs::path& was, const fs::path& now) {
  for (std::string& p : v) p = moved(p, was, now);
}
void move_paths(QueryReport& r, const fs::path& was, const fs::path& now) {
  move_paths(r.counterexamples, was, now);
  move_paths(r.fcl_cases, was, now);
  move_paths(r.bugreports_failed, was, now);
  for (QueryReport& p : r.peers) move_paths(p, was, now);
  for (QueryReport& f : r.first) move_paths(f, was, now);
}

struct Shard {
  fs::path dir;
  Json j;
  report::RunInfo run;
  std::vector<QueryReport> reps;
  std::vector<PointSetReport> point_sets;
  std::vector<MeshReport> meshes;
};

/// Every file of a shard's folder but its own reports, copied into out.
void copy_saved(const fs::path& from, const fs::path& out) {
  for (const auto& e : fs::directory_iterator(from)) {
    const std::string name = e.path().filename().string();
    if (name == "shard.json" || name == "report.json" || name == "report.html") continue;
    fs::copy(e.path(), out / name, fs::copy_options::recursive | fs::copy_options::overwrite_existing);
  }
}

}  // namespace

void write_shard(const fs::path& file, const CampaignOptions& opt, const report::RunInfo& run,
                 const std::vector<QueryReport>& reps, const std::vector<PointSetReport>& point_sets,
                 const std::vector<MeshReport>& meshes) {
  Json j = Json::object();
  j["geomcheck_shard"] = kShardFormat;
  j["shard"] = opt.shard;
  j["shards"] = opt.shards;
  // What must be equal across the shards of one campaign.
  j["campaign"] = {{"version", opt.version}, {"seed", opt.seed},          {"cases", opt.cases},
                   {"seconds", opt.seconds}, {"queries", opt.queries},    {"variant", opt.variant},
                   {"peer_cases", opt.peer_cases}};
  j["out"] = opt.out;
  Out w{j};
  Json r = Json::object();
  Out rw{r};
  fields(rw, const_cast<report::RunInfo&>(run));
  j["run"] = std::move(r);
  w("reports", reps);
  w("point_sets", point_sets);
  w("meshes", meshes);
  std::ofstream f(file);
  f << j.dump(1) << "\n";
  if (!f) std::fprintf(stderr, "[campaign] cannot write %s\n", file.string().c_str());
}

std::string query_report_json(const QueryReport& r) {
  Json j = Json::object();
  Out w{j};
  fields(w, const_cast<QueryReport&>(r));
  return j.dump();
}

QueryReport query_report_from_json(const std::string& text) {
  const Json j = Json::parse(text);
  QueryReport r;
  In in{j};
  fields(in, r);
  return r;
}

int merge_shards(const std::vector<std::string>& dirs, const std::string& out_arg, const std::string& junit,
                 const std::string& command) {
  const fs::path out(out_arg);
  std::vector<Shard> shards;
  try {
    for (const std::string& d : dirs) {
      Shard s;
      s.dir = d;
      const fs::path file = s.dir / "shard.json";
      std::ifstream f(file);
      if (!f) throw std::runtime_error(file.string() + ": cannot read (not a shard's output folder?)");
      try {
        s.j = Json::parse(f);
      } catch (const std::exception& e) {
        throw std::runtime_error(file.string() + ": not JSON: " + e.what());
      }
      if (s.j.value("geomcheck_shard", 0) != kShardFormat)
        throw std::runtime_error(file.string() + ": not a shard file of this geomcheck (format " +
                                 std::to_string(kShardFormat) + ")");
      In r{s.j};
      In rr{s.j.at("run")};
      fields(rr, s.run);
      r("reports", s.reps);
      r("point_sets", s.point_sets);
      r("meshes", s.meshes);
      if (fs::exists(out) && fs::equivalent(out, s.dir))
        throw std::runtime_error("the output folder " + out.string() + " is one of the shards' folders");
      shards.push_back(std::move(s));
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "geomcheck merge: %s\n", e.what());
    return 2;
  }
  if (shards.empty()) {
    std::fprintf(stderr, "geomcheck merge: no shard folders given\n");
    return 2;
  }
  // The N shards of one campaign, each once.
  const int n = shards.front().j.at("shards").get<int>();
  std::vector<int> seen(n, -1);
  for (std::size_t k = 0; k < shards.size(); ++k) {
    const Shard& s = shards[k];
    if (s.j.at("shards").get<int>() != n || s.j.at("campaign") != shards.front().j.at("campaign")) {
      std::fprintf(stderr,
                   "geomcheck merge: %s and %s are not shards of one campaign (the shard count, seed, cases, "
                   "queries, variant, engines' cases or version differ)\n",
                   shards.front().dir.string().c_str(), s.dir.string().c_str());
      return 2;
    }
    const int i = s.j.at("shard").get<int>();
    if (i < 0 || i >= n || seen[i] >= 0) {
      std::fprintf(stderr, "geomcheck merge: shard %d of %d given twice (%s)\n", i, n, s.dir.string().c_str());
      return 2;
    }
    seen[i] = static_cast<int>(k);
  }
  for (int i = 0; i < n; ++i)
    if (seen[i] < 0) {
      std::fprintf(stderr, "geomcheck merge: shard %d of %d is missing (%zu of %d given)\n", i, n, shards.size(), n);
      return 2;
    }
  fs::create_directories(out);
  std::vector<QueryReport> reps;
  std::vector<PointSetReport> point_sets;
  std::vector<MeshReport> meshes;
  report::RunInfo run = shards[seen[0]].run;
  for (int i = 0; i < n; ++i) {  // in shard order
    Shard& s = shards[seen[i]];
    const fs::path was = s.j.at("out").get<std::string>();
    copy_saved(s.dir, out);
    for (QueryReport& r : s.reps) move_paths(r, was, out);
    for (PointSetReport& p : s.point_sets) move_paths(p.counterexamples, was, out);
    for (MeshReport& m : s.meshes) move_paths(m.counterexamples, was, out);
    if (i == 0) {
      reps = std::move(s.reps);
      point_sets = std::move(s.point_sets);
      meshes = std::move(s.meshes);
      continue;
    }
    if (s.reps.size() != reps.size() || s.point_sets.size() != point_sets.size() || s.meshes.size() != meshes.size()) {
      std::fprintf(stderr, "geomcheck merge: %s ran other queries than shard 0\n", s.dir.string().c_str());
      return 2;
    }
    for (std::size_t q = 0; q < reps.size(); ++q) merge_into(reps[q], s.reps[q]);
    for (std::size_t q = 0; q < point_sets.size(); ++q) merge_into(point_sets[q], s.point_sets[q]);
    for (std::size_t q = 0; q < meshes.size(); ++q) merge_into(meshes[q], s.meshes[q]);
    run.started = std::min(run.started, s.run.started);
  }
  for (QueryReport& r : reps)
    if (r.peers.empty()) r.first.clear();  // no engine built: nothing to set beside (as unsharded)
  run.command = command;
  report::write_json(out / "report.json", run, reps, point_sets, meshes);
  report::write_html(out / "report.html", run, reps, point_sets, meshes);
  if (!junit.empty()) report::write_junit(junit, run, reps, point_sets, meshes);
  int failures = 0;
  for (const QueryReport& r : reps) failures += r.beyond + r.check_failures;
  for (const PointSetReport& p : point_sets) failures += p.failures;
  for (const MeshReport& m : meshes) failures += m.failures;
  std::fprintf(stderr, "[merge] %d shards merged into %s and %s\n", n, (out / "report.json").string().c_str(),
               (out / "report.html").string().c_str());
  std::printf("merge: %s\n", failures ? "FAILURES found (see the report)" : "no failure");
  return failures ? 1 : 0;
}

}  // namespace geomcheck
