// geomcheck — an evaluation as one line of JSON and back (report.hpp):
// every field, written once in fields() below.
#include <cmath>
#include <stdexcept>
#include <string>

#include <nlohmann/json.hpp>

#include "geomcheck/reports/report.hpp"

namespace geomcheck::report {
namespace {

using Json = nlohmann::json;

// Every field of Evaluation (and of the Tolerances and PeerScore it holds).
// A field added to Evaluation changes its size and stops the build here
// until it is added below (x86-64, libstdc++: the platform CI builds on).
#if defined(__x86_64__) && defined(__GLIBCXX__)
static_assert(sizeof(Evaluation) == 336, "Evaluation has changed: write its new field in fields() below");
#endif

template <class IO, class E>
void fields(IO& io, E& e) {
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
  io("peer_depth_err", e.peer.depth_err);
  io("peer_normal_err", e.peer.normal_err);
  io("peer_point_err", e.peer.point_err);
  io("peer_unit_err", e.peer.unit_err);
  io("peer_t_err", e.peer.t_err);
  io("depth_ratio", e.depth_ratio);
  io("depth_ratio_lo", e.depth_ratio_lo);
  io("depth_short", e.depth_short);
  io("depth_over", e.depth_over);
  io("tol_verdict", e.tol.verdict);
  io("tol_depth", e.tol.depth);
  io("tol_normal", e.tol.normal);
  io("tol_point", e.tol.point);
  io("tol_t", e.tol.t);
  io("tol_unit", e.tol.unit);
  io("tol_depth_ratio", e.tol.depth_ratio);
  io("tol_input", e.tol.input);
}

/// A double as JSON: a number (written to round-trip exactly), or "nan",
/// "inf", "-inf", which JSON numbers cannot hold.
Json number(double x) {
  if (std::isnan(x)) return "nan";
  if (std::isinf(x)) return x > 0 ? "inf" : "-inf";
  return x;
}

struct Out {
  Json& j;
  void operator()(const char* k, double x) { j[k] = number(x); }
  void operator()(const char* k, bool x) { j[k] = x; }
  void operator()(const char* k, oracle::Verdict x) { j[k] = static_cast<int>(x); }
  void operator()(const char* k, const std::string& x) { j[k] = x; }
};

struct In {
  const Json& j;
  const Json& at(const char* k) const {
    if (!j.contains(k)) throw std::runtime_error(std::string("evaluation line: field '") + k + "' missing");
    return j.at(k);
  }
  void operator()(const char* k, double& x) {
    const Json& v = at(k);
    if (!v.is_string()) {
      x = v.get<double>();
      return;
    }
    const std::string s = v.get<std::string>();
    if (s == "nan") x = NAN;
    else if (s == "inf") x = INFINITY;
    else if (s == "-inf") x = -INFINITY;
    else throw std::runtime_error("evaluation line: field '" + std::string(k) + "' is '" + s + "', not a number");
  }
  void operator()(const char* k, bool& x) { x = at(k).get<bool>(); }
  void operator()(const char* k, oracle::Verdict& x) { x = static_cast<oracle::Verdict>(at(k).get<int>()); }
  void operator()(const char* k, std::string& x) { x = at(k).get<std::string>(); }
};

}  // namespace

std::string evaluation_line(const Evaluation& e) {
  Json j = Json::object();
  Out out{j};
  fields(out, e);
  return j.dump();  // one line: control characters in the texts are escaped
}

Evaluation evaluation_from_line(const std::string& line) {
  const Json j = Json::parse(line);  // throws on a malformed line
  Evaluation e;
  In in{j};
  fields(in, e);
  return e;
}

}  // namespace geomcheck::report
