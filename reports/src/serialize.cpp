// geomcheck — the one serialiser of the harness's figures (report.hpp,
// "Serialising"): every field of an evaluation, a query's report, a point-set
// or mesh query's report and a run's facts, written once in fields() below,
// read and written by one visitor; and the merge of two reports of one query.
#include <algorithm>
#include <cmath>
#include <set>
#include <stdexcept>
#include <string>

#include <nlohmann/json.hpp>

#include "geomcheck/reports/report.hpp"

namespace geomcheck::report {
namespace {

using Json = nlohmann::ordered_json;

// A field added to one of these structures changes its size and stops the
// build here until it is written in its fields() below (x86-64, libstdc++:
// the platform CI builds on).
#if defined(__x86_64__) && defined(__GLIBCXX__)
static_assert(sizeof(Evaluation) == 336, "Evaluation has changed: write its new field in fields() below");
static_assert(sizeof(Evaluation::PeerScore) == 40, "PeerScore has changed: write its new field in fields() below");
static_assert(sizeof(Precision) == 40, "Precision has changed: write its new field in fields() below");
static_assert(sizeof(Claims) == 96, "Claims has changed: write its new field in fields() below");
static_assert(sizeof(Tolerances) == 64, "Tolerances has changed: write its new field in fields() below");
static_assert(sizeof(QueryReport) == 1088, "QueryReport has changed: write its new field in fields() below");
static_assert(sizeof(PointSetReport) == 320, "PointSetReport has changed: write its new field in fields() below");
static_assert(sizeof(MeshReport) == 336, "MeshReport has changed: write its new field in fields() below");
static_assert(sizeof(RunInfo) == 200, "RunInfo has changed: write its new field in fields() below");
#endif

/// A string that lives as long as the program (Claims hold const char*).
const char* intern(const std::string& s) {
  static std::set<std::string> pool;
  return pool.insert(s).first->c_str();
}

struct Out;
struct In;

template <class IO>
void fields(IO& io, Precision& p) {
  io("unit_roundoff", p.unit_roundoff);
  io("ulps", p.ulps);
  io("min_scale", p.min_scale);
  io("max_scale", p.max_scale);
  io("exact_moves", p.exact_moves);
}

template <class IO>
void fields(IO& io, Claims& c) {
  io("exact_verdict", c.exact_verdict);
  io("depth", c.depth);
  io("point_in_both", c.point_in_both);
  io("normal", c.normal);
  io("truth", c.truth);
  io("touching_is_contact", c.touching_is_contact);
  io("margin", c.margin);
  io("any_input", c.any_input);
  io.nested("precision", c.precision);
}

template <class IO>
void fields(IO& io, Tolerances& t) {
  io("verdict", t.verdict);
  io("depth", t.depth);
  io("normal", t.normal);
  io("point", t.point);
  io("t", t.t);
  io("unit", t.unit);
  io("depth_ratio", t.depth_ratio);
  io("input", t.input);
}

template <class IO>
void fields(IO& io, Evaluation::PeerScore& s) {
  io("depth_err", s.depth_err);
  io("normal_err", s.normal_err);
  io("point_err", s.point_err);
  io("unit_err", s.unit_err);
  io("t_err", s.t_err);
}

template <class IO>
void fields(IO& io, Evaluation& e) {
  io("valid", e.valid);
  io("scale", e.scale);
  io("prod_hit", e.prod_hit);
  io("truth_hit", e.truth_hit);
  io("verdict", e.verdict);
  io("signed_distance", e.signed_distance);
  io("disagree", e.disagree);
  io("excused", e.excused);
  io("near_boundary", e.near_boundary);
  io("margin", e.margin);
  io("depth_err", e.depth_err);
  io("normal_err", e.normal_err);
  io("point_err", e.point_err);
  io("t_err", e.t_err);
  io("t_true", e.t_true);
  io("unit_err", e.unit_err);
  io("extra_failure", e.extra_failure);
  io("truth_text", e.truth_text);
  io("prod_text", e.prod_text);
  io("distance", e.distance);
  io.nested("peer", e.peer);
  io("depth_ratio", e.depth_ratio);
  io("depth_ratio_lo", e.depth_ratio_lo);
  io("depth_short", e.depth_short);
  io("depth_over", e.depth_over);
  io.nested("tol", e.tol);
}

template <class IO>
void fields(IO& io, QueryReport& r) {
  io("name", r.name);
  io("summary", r.summary);
  io("subject", r.subject);
  io("replay", r.replay);
  io.nested("claims", r.claims);
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
  io.nested("tol", r.tol);
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
void fields(IO& io, RunInfo& r) {
  io("version", r.version);
  io("started", r.started);
  io("command", r.command);
  io("seed", r.seed);
  io("per_query", r.per_query);
  io("rerun", r.rerun);
  io("under_test", r.under_test);
}

/// Writes every field into a JSON object.
struct Out {
  Json& j;
  void operator()(const char* k, int v) { j[k] = v; }
  void operator()(const char* k, bool v) { j[k] = v; }
  void operator()(const char* k, std::size_t v) { j[k] = v; }
  void operator()(const char* k, unsigned long long v) { j[k] = v; }
  void operator()(const char* k, double v) {  // exact; NaN and infinities as strings (JSON numbers cannot hold them)
    if (std::isfinite(v)) j[k] = v;
    else j[k] = std::isnan(v) ? Json("nan") : Json(v > 0 ? "inf" : "-inf");
  }
  void operator()(const char* k, const std::string& v) { j[k] = v; }
  void operator()(const char* k, const char* v) { j[k] = std::string(v ? v : ""); }
  void operator()(const char* k, const std::map<std::string, int>& v) { j[k] = v; }
  void operator()(const char* k, const std::vector<std::string>& v) { j[k] = v; }
  void operator()(const char* k, const Series& v) {
    Json a = Json::array();
    for (double x : v.v) {
      Json one = Json::object();
      Out w{one};
      w("v", x);
      a.push_back(one["v"]);
    }
    j[k] = std::move(a);
  }
  void operator()(const char* k, Claims::Depth v) { j[k] = static_cast<int>(v); }
  void operator()(const char* k, oracle::Verdict v) { j[k] = static_cast<int>(v); }
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
  void nested(const char* k, T& x) {
    Json o = Json::object();
    Out w{o};
    fields(w, x);
    j[k] = std::move(o);
  }
};

/// Reads every field back from a JSON object; a missing field is an error.
struct In {
  const Json& j;
  const Json& at(const char* k) const {
    if (!j.is_object() || !j.contains(k)) throw std::runtime_error(std::string("field '") + k + "' missing");
    return j.at(k);
  }
  static double number(const Json& x, const char* k) {
    if (!x.is_string()) return x.get<double>();
    const std::string s = x.get<std::string>();
    if (s == "nan") return NAN;
    if (s == "inf") return INFINITY;
    if (s == "-inf") return -INFINITY;
    throw std::runtime_error("field '" + std::string(k) + "' is '" + s + "', not a number");
  }
  void operator()(const char* k, int& v) { v = at(k).get<int>(); }
  void operator()(const char* k, bool& v) { v = at(k).get<bool>(); }
  void operator()(const char* k, std::size_t& v) { v = at(k).get<std::size_t>(); }
  void operator()(const char* k, unsigned long long& v) { v = at(k).get<unsigned long long>(); }
  void operator()(const char* k, double& v) { v = number(at(k), k); }
  void operator()(const char* k, std::string& v) { v = at(k).get<std::string>(); }
  void operator()(const char* k, const char*& v) { v = intern(at(k).get<std::string>()); }
  void operator()(const char* k, std::map<std::string, int>& v) { v = at(k).get<std::map<std::string, int>>(); }
  void operator()(const char* k, std::vector<std::string>& v) { v = at(k).get<std::vector<std::string>>(); }
  void operator()(const char* k, Series& v) {
    v.v.clear();
    for (const Json& x : at(k)) v.v.push_back(number(x, k));
  }
  void operator()(const char* k, Claims::Depth& v) { v = static_cast<Claims::Depth>(at(k).get<int>()); }
  void operator()(const char* k, oracle::Verdict& v) { v = static_cast<oracle::Verdict>(at(k).get<int>()); }
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
  template <class T>
  void nested(const char* k, T& x) {
    In r{at(k)};
    fields(r, x);
  }
};

template <class T>
std::string write(const T& x) {
  Json j = Json::object();
  Out w{j};
  fields(w, const_cast<T&>(x));
  return j.dump();  // one line: control characters in the texts are escaped
}

template <class T>
void read(const std::string& text, T& x, const char* what) {
  try {
    const Json j = Json::parse(text);
    In r{j};
    fields(r, x);
  } catch (const std::exception& e) {
    throw std::runtime_error(std::string(what) + ": " + e.what());
  }
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

}  // namespace

std::string to_json(const Evaluation& e) { return write(e); }
std::string to_json(const QueryReport& r) { return write(r); }
std::string to_json(const PointSetReport& r) { return write(r); }
std::string to_json(const MeshReport& r) { return write(r); }
std::string to_json(const RunInfo& r) { return write(r); }
void from_json(const std::string& text, Evaluation& e) { read(text, e, "an evaluation"); }
void from_json(const std::string& text, QueryReport& r) { read(text, r, "a query's report"); }
void from_json(const std::string& text, PointSetReport& r) { read(text, r, "a point-set query's report"); }
void from_json(const std::string& text, MeshReport& r) { read(text, r, "a mesh query's report"); }
void from_json(const std::string& text, RunInfo& r) { read(text, r, "a run's facts"); }

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
  a.bugreports += b.bugreports;
  add(a.bugreports_failed, b.bugreports_failed);
}

void merge_into(PointSetReport& a, const PointSetReport& b) {
  a.requested += b.requested;
  a.stopped_by_time = a.stopped_by_time || b.stopped_by_time;
  a.not_asked += b.not_asked;
  a.sets += b.sets;
  a.points += b.points;
  add(a.modes, b.modes);
  add(a.kinds, b.kinds);
  a.failures += b.failures;
  add(a.failures_by_property, b.failures_by_property);
  a.cgal_choices_differ += b.cgal_choices_differ;
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

}  // namespace geomcheck::report
