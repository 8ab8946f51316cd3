// geomcheck — command-line entry point: campaign, replay, converters.
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "campaign.hpp"
#include "geomcheck/casefile.hpp"
#include "geomcheck/fuzz_decode.hpp"
#include "geomcheck/delaunay_2d.hpp"
#include "geomcheck/oracles/delaunay_2d.hpp"
#include "geomcheck/pointset_file.hpp"
#include "geomcheck/properties/checks.hpp"
#include "geomcheck/properties/tolerances.hpp"
#include "geomcheck/shape_traits.hpp"
#include "peer.hpp"

namespace fs = std::filesystem;
using namespace geomcheck;

namespace {

const char* kUsage =
    "usage: geomcheck <command> [options]\n"
    "\n"
    "commands:\n"
    "  campaign [--cases N] [--seconds S] [--seed N] [--threads N] [--out DIR] [--query ID]...\n"
    "           [--variant NAME] [--no-progress]\n"
    "        Differential campaign of every registered query: production vs the exact\n"
    "        oracle vs FCL on the targeted generators. Writes DIR/report.json and\n"
    "        DIR/report.html (default DIR: reports/out), every failing case and its\n"
    "        drawing under DIR/counterexamples/, every FCL disagreement beyond the\n"
    "        band under DIR/fcl-disagreements/. Exit status 1 when anything failed.\n"
    "        Defaults: --cases 100000 per query (10000 for the queries whose oracle is\n"
    "        the certified engine), --seed 20261121, all cores.\n"
    "        --variant NAME runs a known-wrong variant of one query in production's\n"
    "        place (what a failing campaign looks like; --variant help lists them).\n"
    "  replay [--quiet] PATH...\n"
    "        Replays case files (or every *.case under a directory): production, the\n"
    "        exact oracle and FCL side by side, the verdict margin and every property\n"
    "        check. A point-set file (query delaunay_2d) is parsed and its filed verdict\n"
    "        checked against the kind of its points. Exit status 1 when any case fails\n"
    "        a check.\n"
    "  from-fuzz QUERY CRASH_FILE [-o OUT.case]\n"
    "        Turns a libFuzzer input of QUERY's fuzz target into a case file.\n"
    "  from-rapidcheck QUERY TEXT_FILE|- [-o OUT.case]\n"
    "        Turns a RapidCheck counterexample (its printed text) into a case file.\n"
    "  queries\n"
    "        Lists the registered queries: id, family (a pair of shapes, or a point\n"
    "        set), what production answers.\n"
    "\n"
    "Case files: corpora/seeds/<query>/ and corpora/regressions/<query>/ (format: corpora/README.md).\n";

[[noreturn]] void usage_error(const std::string& msg) {
  std::fprintf(stderr, "geomcheck: %s\n\n%s", msg.c_str(), kUsage);
  std::exit(2);
}

std::string shapes_text(const CaseFile& f) {
  std::ostringstream o;
  const ShapeLayout la = query_shape(f.query, 0), lb = query_shape(f.query, 1);
  o << "  A: " << describe_shape(la, f.a.data()) << "\n  B: " << describe_shape(lb, f.b.data()) << "\n";
  return o.str();
}

// The query a case file declares in its header (`query NAME`, among the
// first lines), without reading further: it decides the file's family and
// so its parser. Empty when the header names none (the parser then says why).
std::string declared_query(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::string line;
  for (int n = 0; n < 16 && std::getline(in, line); ++n) {
    std::istringstream words(line);
    std::string key, name;
    if (words >> key && key == "query") return words >> name ? name : "";  // the first query line decides
  }
  return "";
}

// Replays one point-set file: it parses, its filed verdict is the kind of
// its points (classify_point_set), and production's triangulation passes
// the exact validity checker and agrees with CGAL's (up to cocircular
// choices); non-finite input must be rejected naming the first bad index.
// Returns true when all of that holds.
bool replay_point_set(const fs::path& path, bool quiet) {
  const PointSetParseResult pr = load_point_set(path);
  if (!pr.ok()) {
    std::printf("%s\n  ERROR %s\n", path.string().c_str(), pr.error.c_str());
    return false;
  }
  const PointSetFile& f = pr.value;
  const std::string_view kind = classify_point_set(f.points);
  const bool verdict_ok = f.oracle_verdict.empty() || f.oracle_verdict == kind;
  std::string production, problem;
  try {
    const DelaunayTriangulation t = delaunay_2d(f.points);
    production = t.summary();
    if (kind == "rejected") problem = "non-finite input accepted";
    if (problem.empty()) problem = oracle::check_delaunay(f.points, t);
    if (problem.empty()) problem = oracle::compare_with_cgal(f.points, t);
  } catch (const DelaunayInputError& e) {
    production = std::string("rejected: ") + e.what();
    if (kind != "rejected") problem = "finite input rejected";
  } catch (const std::exception& e) {
    production = std::string("threw: ") + e.what();
    problem = production;
  }
  const bool pass = verdict_ok && problem.empty();
  if (quiet && pass) {
    std::printf("PASS %s\n", path.string().c_str());
    return true;
  }
  std::printf("%s %s\n  query: %s\n  points: %zu\n", pass ? "PASS" : "FAIL", path.string().c_str(), kDelaunayQueryName,
              f.points.size());
  if (!f.found_by.empty()) std::printf("  found by: %s\n", f.found_by.c_str());
  std::printf("  kind of the point set: %.*s\n", static_cast<int>(kind.size()), kind.data());
  if (!f.oracle_verdict.empty())
    std::printf("  filed oracle verdict: %s%s\n", f.oracle_verdict.c_str(), verdict_ok ? "" : "  <-- the points are of another kind");
  std::printf("  production: %s\n", production.c_str());
  std::printf("  oracles (exact validity, CGAL): %s\n", problem.empty() ? "agree" : problem.c_str());
  return pass;
}

// Replays one case; returns true when every check passes.
bool replay_one(const fs::path& path, bool quiet) {
  if (family_of(declared_query(path)) == QueryFamily::PointSet) return replay_point_set(path, quiet);
  const ParseResult pr = load_case(path);
  if (!pr.ok()) {
    std::printf("%s\n  ERROR %s\n", path.string().c_str(), pr.error.c_str());
    return false;
  }
  const CaseFile& f = pr.value;
  if (auto err = case_error(f)) {
    std::printf("%s\n  ERROR %s\n", path.string().c_str(), err->c_str());
    return false;
  }
  return visit_case(f, [&](auto q, const auto& c) {
    constexpr QueryId Q = decltype(q)::value;
    const PeerAnswer fcl = peer(c);
    const Evaluation e = evaluate_with_peer(c, fcl);
    const CheckResult failure = check_all(c);
    const Tolerances tol = tolerances(Q);
    bool filed_ok = true;
    std::string truth_word = verdict_word(Q, e);
    if (!e.valid) truth_word = "invalid";
    if (!f.oracle_verdict.empty() && e.valid && f.oracle_verdict != truth_word) filed_ok = false;
    const bool pass = !failure && filed_ok;
    if (quiet && pass) {
      std::printf("PASS %s\n", path.string().c_str());
      return true;
    }
    std::printf("%s %s\n  query: %s\n%s", pass ? "PASS" : "FAIL", path.string().c_str(), info(Q).name, shapes_text(f).c_str());
    if (!f.found_by.empty()) std::printf("  found by: %s\n", f.found_by.c_str());
    std::printf("  production: %s\n", e.prod_text.c_str());
    std::printf("  oracle:     %s\n", e.truth_text.c_str());
    std::printf("  FCL:        %s\n", fcl.supported ? fcl.text.c_str() : "(FCL cannot express this query)");
    if (e.valid) {
      std::printf("  scale %.3g; verdict band %.1e * scale", e.scale, tol.verdict);
      if (std::isfinite(e.signed_distance)) std::printf("; |signed distance| = %.3g * scale", std::fabs(e.signed_distance) / e.scale);
      else if (std::isfinite(e.margin)) std::printf("; disagreement margin %.3g * scale", e.margin);
      std::printf("\n  production vs oracle: %s\n",
                  !e.disagree ? "agree" : (e.excused ? "disagree, inside the band (either answer passes)" : "DISAGREE beyond the band"));
      auto err = [](const char* n, double v, double b) {
        if (std::isfinite(v)) std::printf("  %s error %.3g * scale (bound %.1e)%s\n", n, v, b, v > b ? "  <-- exceeds" : "");
      };
      err("depth", e.depth_err, tol.depth);
      err("normal", e.normal_err, tol.normal);
      err("point", e.point_err, tol.point);
      err("t", e.t_err, tol.t);
      // FCL by the same yardsticks (no bound: FCL is measured, not judged).
      auto ferr = [&](const char* n, double v) {
        if (std::isfinite(v)) std::printf("  FCL %s error %.3g * scale\n", n, v);
      };
      if (fcl.supported && fcl.ok) {
        ferr("depth", e.peer.depth_err);
        ferr("normal", e.peer.normal_err);
        ferr("point", e.peer.point_err);
        ferr("t", e.peer.t_err);
        if (std::isfinite(fcl.distance) && std::isfinite(e.distance))
          ferr("distance", fcl.distance >= 0 ? std::fabs(fcl.distance - e.distance) / e.scale : NAN);
        if (std::isfinite(fcl.distance) && (fcl.distance < 0) != e.truth_hit)
          std::printf("  FCL's distance %s the oracle's verdict%s\n", fcl.distance < 0 ? "says they meet, against" : "says separated, against",
                      e.near_boundary ? " (inside the band)" : " (beyond the band)");
      }
    }
    if (!f.oracle_verdict.empty())
      std::printf("  filed oracle verdict: %s%s\n", f.oracle_verdict.c_str(), filed_ok ? "" : "  <-- the oracle now says otherwise");
    if (failure) std::printf("  check FAILED: %s: %s\n", failure->property.c_str(), failure->detail.c_str());
    return pass;
  });
}

int cmd_replay(const std::vector<std::string>& args) {
  bool quiet = false;
  std::vector<fs::path> files;
  for (const auto& a : args) {
    if (a == "--quiet") { quiet = true; continue; }
    if (a.rfind("-", 0) == 0) usage_error("replay: unknown option " + a);
    const fs::path p(a);
    std::error_code ec;
    if (fs::is_directory(p, ec)) {
      std::vector<fs::path> found;
      for (const auto& e : fs::recursive_directory_iterator(p))
        if (e.is_regular_file() && e.path().extension() == kCaseFileExtension) found.push_back(e.path());
      std::sort(found.begin(), found.end());
      files.insert(files.end(), found.begin(), found.end());
    } else if (fs::exists(p, ec)) {
      files.push_back(p);
    } else {
      usage_error("replay: no such file or directory: " + a);
    }
  }
  if (files.empty() && args.empty()) usage_error("replay: give case files or directories");
  int failed = 0;
  for (const auto& f : files) failed += !replay_one(f, quiet);
  std::printf("replay: %zu passed, %d failed\n", files.size() - failed, failed);
  return failed ? 1 : 0;
}

QueryId need_query(const std::string& s) {
  const auto q = query_from_name(s);
  if (!q) {
    std::string known;
    for (const auto& i : kQueries) known += std::string(" ") + i.name;
    usage_error("unknown query '" + s + "'; known:" + known);
  }
  return *q;
}

int write_out(const CaseFile& f, const std::string& out) {
  if (out.empty()) {
    std::fputs(write_case(f).c_str(), stdout);
    return 0;
  }
  std::string err;
  if (!save_case(out, f, err)) {
    std::fprintf(stderr, "geomcheck: %s\n", err.c_str());
    return 1;
  }
  std::fprintf(stderr, "wrote %s\n", out.c_str());
  return 0;
}

std::string slurp(std::istream& in) {
  std::ostringstream o;
  o << in.rdbuf();
  return o.str();
}

int cmd_convert(bool fuzz, const std::vector<std::string>& args) {
  std::string out;
  std::vector<std::string> pos;
  for (std::size_t i = 0; i < args.size(); ++i) {
    if (args[i] == "-o") {
      if (i + 1 >= args.size()) usage_error("-o needs a file name");
      out = args[++i];
    } else {
      pos.push_back(args[i]);
    }
  }
  if (pos.size() != 2) usage_error(fuzz ? "from-fuzz QUERY CRASH_FILE [-o OUT]" : "from-rapidcheck QUERY TEXT_FILE|- [-o OUT]");
  const QueryId q = need_query(pos[0]);
  std::string data;
  if (pos[1] == "-") {
    data = slurp(std::cin);
  } else {
    std::ifstream in(pos[1], std::ios::binary);
    if (!in) usage_error("cannot read " + pos[1]);
    data = slurp(in);
  }
  if (fuzz) {
    const std::string artifact = fs::path(pos[1]).filename().string();
    CaseFile f = fuzz::case_from_input(q, reinterpret_cast<const std::uint8_t*>(data.data()), data.size(),
                                       artifact.rfind("crash-", 0) == 0 || artifact.rfind("timeout-", 0) == 0 ? artifact : "");
    return write_out(f, out);
  }
  const auto f = case_from_rapidcheck_text(q, data);
  if (!f) {
    std::fprintf(stderr, "geomcheck: no %s and %s description found in the text\n", info(q).shape_a, info(q).shape_b);
    return 1;
  }
  return write_out(*f, out);
}

int cmd_campaign(const std::vector<std::string>& args) {
  CampaignOptions opt;
  auto num = [&](std::size_t& i) -> std::string {
    if (i + 1 >= args.size()) usage_error(args[i] + " needs a value");
    return args[++i];
  };
  try {
    for (std::size_t i = 0; i < args.size(); ++i) {
      const std::string& a = args[i];
      if (a == "--cases") opt.cases = std::stoi(num(i));
      else if (a == "--seconds") opt.seconds = std::stod(num(i));
      else if (a == "--seed") opt.seed = std::stoull(num(i));
      else if (a == "--threads") opt.threads = std::stoi(num(i));
      else if (a == "--out") opt.out = num(i);
      else if (a == "--query") {
        const std::string q = num(i);
        if (!family_of(q)) {
          std::string known;
          for (const auto& k : kAllQueries) known += std::string(" ") + k.name;
          usage_error("campaign: unknown query '" + q + "'; known:" + known);
        }
        opt.queries.push_back(q);
      }
      else if (a == "--no-progress") opt.progress = false;
      else if (a == "--variant") {
        opt.variant = num(i);
        if (opt.variant == "help") {
          for (const auto& [v, q] : campaign_variants()) std::printf("%s (%s)\n", v.c_str(), q.c_str());
          std::exit(0);
        }
        bool known = false;
        std::string names;
        for (const auto& [v, q] : campaign_variants()) known = known || v == opt.variant, names += "\n  " + v + " (" + q + ")";
        if (!known) usage_error("campaign: unknown variant " + opt.variant + "; the known-wrong variants are:" + names);
      }
      else usage_error("campaign: unknown option " + a);
    }
  } catch (const std::exception&) {
    usage_error("campaign: a number was expected");
  }
  for (std::size_t i = 0; i < args.size(); ++i)
    if (args[i] == "--cases" && opt.cases <= 0) usage_error("campaign: --cases must be positive");
  const int failures = run_campaign(opt);
  std::printf("campaign: %s\n", failures ? "FAILURES found (see the report)" : "no failure");
  return failures ? 1 : 0;
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> args(argv + 1, argv + argc);
  if (args.empty() || args[0] == "--help" || args[0] == "-h" || args[0] == "help") {
    std::fputs(kUsage, stdout);
    return args.empty() ? 2 : 0;
  }
  const std::string cmd = args[0];
  args.erase(args.begin());
  for (const auto& a : args)
    if (a == "--help" || a == "-h") {
      std::fputs(kUsage, stdout);
      return 0;
    }
  if (cmd == "campaign") return cmd_campaign(args);
  if (cmd == "replay") return cmd_replay(args);
  if (cmd == "from-fuzz") return cmd_convert(true, args);
  if (cmd == "from-rapidcheck") return cmd_convert(false, args);
  if (cmd == "queries") {
    for (const auto& q : kAllQueries)
      std::printf("%-26s %-9s %s\n", q.name, q.family == QueryFamily::Pair ? "pair" : "point-set", q.summary);
    return 0;
  }
  usage_error("unknown command '" + cmd + "'");
}
