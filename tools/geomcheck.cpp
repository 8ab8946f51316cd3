// geomcheck — command-line entry point: campaign, replay, converters.
#include <CLI/CLI.hpp>

#include <algorithm>
#include <charconv>
#include <cstdlib>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "campaign.hpp"
#include "shard.hpp"
#include "geomcheck/casefile.hpp"
#include "geomcheck/fuzz_decode.hpp"
#include "geomcheck/delaunay_2d.hpp"
#include "geomcheck/oracles/delaunay_2d.hpp"
#include "geomcheck/mesh_file.hpp"
#include "geomcheck/pointset_file.hpp"
#include "geomcheck/properties/mesh_checks.hpp"
#include "geomcheck/properties/pointset_checks.hpp"
#include "geomcheck/properties/checks.hpp"
#include "geomcheck/properties/spec.hpp"
#include "geomcheck/properties/tolerances.hpp"
#include "geomcheck/shape_traits.hpp"
#include "geomcheck/peers/fcl_peer.hpp"
#include "peers.hpp"

namespace fs = std::filesystem;
using namespace geomcheck;

namespace {

// An error of the caller's (usage, a bad number, an unreadable or malformed
// file, nothing to replay): said on stderr, exit status 2.
struct InputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// A whole number > 0, every character of it (CLI11's own checks would take "10abc").
std::string positive_integer(const std::string& v) {
  int x = 0;
  const auto [end, ec] = std::from_chars(v.data(), v.data() + v.size(), x);
  if (ec != std::errc() || end != v.data() + v.size() || x <= 0) return "'" + v + "' is not a whole number above 0";
  return "";
}
/// A finite number > 0, every character of it.
std::string positive_number(const std::string& v) {
  char* end = nullptr;
  const double x = v.empty() ? 0 : std::strtod(v.c_str(), &end);
  if (v.empty() || end != v.c_str() + v.size() || !std::isfinite(x) || !(x > 0)) return "'" + v + "' is not a number above 0";
  return "";
}
/// A whole number >= 0 of 64 bits, every character of it.
std::string seed_number(const std::string& v) {
  std::uint64_t x = 0;
  const auto [end, ec] = std::from_chars(v.data(), v.data() + v.size(), x);
  if (ec != std::errc() || end != v.data() + v.size()) return "'" + v + "' is not a whole number from 0 to 2^64 - 1";
  return "";
}


/// The largest input the converters read (a fuzz input or a RapidCheck text).
constexpr std::uintmax_t kMaxConvertInputBytes = 1 << 20;

std::string shapes_text(const CaseFile& f) {
  std::ostringstream o;
  const ShapeLayout la = query_shape(f.query, 0), lb = query_shape(f.query, 1);
  o << "  A: " << describe_shape(la, f.a.data()) << "\n  B: " << describe_shape(lb, f.b.data()) << "\n";
  return o.str();
}

/// How a replayed file came out.
enum class Replayed { Passed, Failed, Unreadable };

/// A file that cannot be read or parsed: said on stderr (file, line, field).
Replayed unreadable(const fs::path& path, const std::string& error) {
  std::fflush(stdout);
  const bool named = error.rfind(path.string(), 0) == 0;  // the parser names the file itself
  std::fprintf(stderr, "geomcheck: %s%s%s\n", named ? "" : path.string().c_str(), named ? "" : ": ", error.c_str());
  return Replayed::Unreadable;
}

// Replays one point-set file: it parses, its filed verdict is the kind of
// its points (classify_point_set), and the subject (production unless
// named) holds every check of the family (pointset_checks.hpp: the exact
// validity checker, CGAL's triangles up to cocircular choices, non-finite
// input rejected naming the first bad index).
Replayed replay_point_set(const fs::path& path, bool quiet, const std::string& subject) {
  const PointSetParseResult pr = load_point_set(path);
  if (!pr.ok()) return unreadable(path, pr.error);
  const PointSetFile& f = pr.value;
  const PointSetImpl* impl = point_set_subject(subject);
  if (!impl) return unreadable(path, "no subject '" + subject + "' of query " + kDelaunayQueryName);
  const std::string_view kind = classify_point_set(f.points);
  const bool verdict_ok = f.oracle_verdict.empty() || f.oracle_verdict == kind;
  const PointSetOutcome o = check_point_set(f.points, *impl);
  const bool pass = verdict_ok && !o.failure;
  if (quiet && pass) {
    std::printf("PASS %s\n", path.string().c_str());
    return Replayed::Passed;
  }
  std::printf("%s %s\n  query: %s\n  points: %zu\n", pass ? "PASS" : "FAIL", path.string().c_str(), kDelaunayQueryName,
              f.points.size());
  if (!f.found_by.empty()) std::printf("  found by: %s\n", f.found_by.c_str());
  std::printf("  kind of the point set: %.*s\n", static_cast<int>(kind.size()), kind.data());
  if (!f.oracle_verdict.empty())
    std::printf("  filed oracle verdict: %s%s\n", f.oracle_verdict.c_str(), verdict_ok ? "" : "  <-- the points are of another kind");
  std::printf("  %s: %s\n", impl->name, o.answer.c_str());
  std::printf("  oracles (exact validity, CGAL): %s\n",
              o.failure ? (o.failure->property + ": " + o.failure->detail).c_str() : "agree");
  return pass ? Replayed::Passed : Replayed::Failed;
}

// Replays one mesh file: every check of mesh_checks.hpp on the subject
// (production or a known-wrong variant of the mesh query), and the filed
// verdict (if any) is the truth's, the strongest of the faces'.
Replayed replay_mesh(const fs::path& path, bool quiet, const std::string& subject) {
  const MeshParseResult pr = load_mesh_file(path);
  if (!pr.ok()) return unreadable(path, pr.error);
  const MeshFile& f = pr.value;
  const MeshImpl* impl = mesh_subject(subject.empty() ? "production" : subject);
  if (!impl) return unreadable(path, "no subject '" + subject + "' of query " + f.query);
  const TriangleMesh mesh = mesh_of(f);
  MeshTruth truth;
  const CheckResult failure = check_mesh_all(f.cylinder, mesh, *impl, &truth);
  const std::string truth_word = truth.valid ? oracle::to_string(truth.verdict) : "invalid";
  const bool verdict_ok = f.oracle_verdict.empty() || f.oracle_verdict == truth_word;
  const bool pass = !failure && verdict_ok;
  if (quiet && pass) {
    std::printf("PASS %s\n", path.string().c_str());
    return Replayed::Passed;
  }
  std::uint32_t face = 0xffffffffu;
  const Contact k = impl->collide(f.cylinder, mesh, &face);
  std::printf("%s %s\n  query: %s\n  subject: %s\n  cylinder: p=(%.17g, %.17g, %.17g) q=(%.17g, %.17g, %.17g) r=%.17g\n"
              "  mesh: %zu vertices, %zu faces%s\n",
              pass ? "PASS" : "FAIL", path.string().c_str(), f.query.c_str(), impl->name, f.cylinder.p.x,
              f.cylinder.p.y, f.cylinder.p.z, f.cylinder.q.x, f.cylinder.q.y, f.cylinder.q.z, f.cylinder.r,
              f.vertices.size(), f.faces.size(), mesh.valid() ? "" : " (invalid: a non-finite vertex or an index out of range)");
  if (!f.found_by.empty()) std::printf("  found by: %s\n", f.found_by.c_str());
  if (k.hit)
    std::printf("  %s: hit, face %u, depth %.17g, normal (%.17g, %.17g, %.17g), point (%.17g, %.17g, %.17g)\n", impl->name,
                face, k.depth, k.normal.x, k.normal.y, k.normal.z, k.point.x, k.point.y, k.point.z);
  else
    std::printf("  %s: no hit\n", impl->name);
  std::printf("  truth: %s (faces separated by their boxes %d, decided by the engine %d)\n", truth_word.c_str(),
              truth.faces_by_box, truth.faces_by_engine);
  if (!f.oracle_verdict.empty())
    std::printf("  filed oracle verdict: %s%s\n", f.oracle_verdict.c_str(), verdict_ok ? "" : "  <-- the truth differs");
  std::printf("  checks: %s\n", failure ? (failure->property + ": " + failure->detail).c_str() : "all pass");
  return pass ? Replayed::Passed : Replayed::Failed;
}

// Replays one case: passed when every check passes and the filed verdict
// (if any) is the truth's; a verdict filed on invalid input is wrong (the
// only truth there is "invalid": no hit).
Replayed replay_one(const fs::path& path, bool quiet, const std::string& subject) {
  const auto family = family_of(declared_query(path));
  if (family == QueryFamily::PointSet) return replay_point_set(path, quiet, subject);
  if (family == QueryFamily::Mesh) return replay_mesh(path, quiet, subject);
  const ParseResult pr = load_case(path);
  if (!pr.ok()) return unreadable(path, pr.error);
  const CaseFile& f = pr.value;
  if (auto err = case_error(f)) return unreadable(path, *err);
  return visit_case(f, [&](auto q, const auto& c) {
    constexpr QueryId Q = decltype(q)::value;
    const auto* impl = Spec<Q>::subject(subject);
    if (!impl) impl = peer_subject<Q>(subject);  // another engine (peers/)
    if (!impl) return unreadable(path, "no subject '" + subject + "' of query " + info(Q).name);
    const peers::FclAnswer fcl = peers::fcl_answer(c);
    const Evaluation e = peers::evaluate_with_fcl(c, fcl, *impl);
    const CheckResult failure = check_all(c, *impl);
    const Tolerances tol = bounds_of(Q, impl->claims);
    bool filed_ok = true;
    std::string truth_word = verdict_word(Q, e);
    if (!e.valid) truth_word = "invalid";
    if (!f.oracle_verdict.empty() && f.oracle_verdict != truth_word) filed_ok = false;
    const bool pass = !failure && filed_ok;
    if (quiet && pass) {
      std::printf("PASS %s\n", path.string().c_str());
      return Replayed::Passed;
    }
    std::printf("%s %s\n  query: %s\n%s", pass ? "PASS" : "FAIL", path.string().c_str(), info(Q).name, shapes_text(f).c_str());
    if (!f.found_by.empty()) std::printf("  found by: %s\n", f.found_by.c_str());
    std::printf("  %s: %s\n", impl == &production_of<Q>() ? "production" : impl->name, e.prod_text.c_str());
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
      std::printf("  filed oracle verdict: %s%s\n", f.oracle_verdict.c_str(),
                  filed_ok ? "" : (e.valid ? "  <-- the oracle now says otherwise" : "  <-- filed on invalid input"));
    if (failure) std::printf("  check FAILED: %s: %s\n", failure->property.c_str(), failure->detail.c_str());
    return pass ? Replayed::Passed : Replayed::Failed;
  });
}

/// The case files a replay argument names: the file, or every *.case below a directory.
std::vector<fs::path> case_files(const std::string& arg) {
  const fs::path p(arg);
  std::error_code ec;
  if (fs::is_directory(p, ec)) {
    std::vector<fs::path> found;
    for (const auto& e : fs::recursive_directory_iterator(p))
      if (e.is_regular_file() && e.path().extension() == kCaseFileExtension) found.push_back(e.path());
    std::sort(found.begin(), found.end());
    if (found.empty()) throw InputError("replay: no " + std::string(kCaseFileExtension) + " file under " + arg);
    return found;
  }
  if (!fs::exists(p, ec)) throw InputError("replay: no such file or directory: " + arg);
  return {p};
}

// 0 every case passed, 1 a check failed, 2 a file could not be read or parsed.
int cmd_replay(const std::vector<std::string>& args, bool quiet, const std::string& subject) {
  std::vector<fs::path> files;
  for (const auto& a : args) {
    const auto more = case_files(a);
    files.insert(files.end(), more.begin(), more.end());
  }
  int failed = 0, unreadable = 0;
  for (const auto& f : files) {
    const Replayed r = replay_one(f, quiet, subject);
    failed += r == Replayed::Failed;
    unreadable += r == Replayed::Unreadable;
  }
  std::printf("replay: %zu passed, %d failed, %d unreadable\n", files.size() - failed - unreadable, failed, unreadable);
  return unreadable ? 2 : (failed ? 1 : 0);
}

QueryId need_query(const std::string& s) {
  const auto q = query_from_name(s);
  if (!q && family_of(s))
    throw InputError("query '" + s + "' is of the " + family_name(*family_of(s)) +
                     " family: its fuzz target prints the failing case as a case file itself; replay that file");
  if (!q) {
    std::string known;
    for (const auto& i : kQueries) known += std::string(" ") + i.name;
    throw InputError("unknown query '" + s + "'; known:" + known);
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

int cmd_convert(bool fuzz, const std::string& query, const std::string& input, const std::string& out) {
  const QueryId q = need_query(query);
  std::string data;
  if (input == "-") {
    data = slurp(std::cin);
  } else {
    std::error_code ec;
    const auto bytes = fs::file_size(input, ec);
    if (ec) throw InputError("cannot read " + input + ": " + ec.message());
    if (bytes > kMaxConvertInputBytes)
      throw InputError(input + ": " + std::to_string(bytes) + " bytes, more than the limit of " +
                       std::to_string(kMaxConvertInputBytes));
    std::ifstream in(input, std::ios::binary);
    if (!in) throw InputError("cannot read " + input);
    data = slurp(in);
  }
  if (fuzz) {
    const std::string artifact = fs::path(input).filename().string();
    CaseFile f = fuzz::case_from_input(q, reinterpret_cast<const std::uint8_t*>(data.data()), data.size(),
                                       artifact.rfind("crash-", 0) == 0 || artifact.rfind("timeout-", 0) == 0 ? artifact : "");
    return write_out(f, out);
  }
  const auto f = case_from_rapidcheck_text(q, data);
  if (!f) throw InputError(std::string("no ") + info(q).shape_a + " and " + info(q).shape_b + " description found in " + input);
  return write_out(*f, out);
}

/// I/N with 0 <= I < N: "" when it is, else what is wrong.
std::string shard_spec(const std::string& v) {
  const auto slash = v.find('/');
  auto digits = [](const std::string& x) {
    return !x.empty() && x.size() <= 6 && std::all_of(x.begin(), x.end(), [](char ch) { return ch >= '0' && ch <= '9'; });
  };
  if (slash == std::string::npos || !digits(v.substr(0, slash)) || !digits(v.substr(slash + 1)))
    return "shard '" + v + "': expected I/N, e.g. 0/4 (shard I of N, 0-based)";
  const int i = std::stoi(v.substr(0, slash)), n = std::stoi(v.substr(slash + 1));
  if (n < 1 || i >= n) return "shard '" + v + "': I must be in 0.." + std::to_string(std::max(0, n - 1)) + " and N >= 1";
  return "";
}

int cmd_campaign(CampaignOptions opt, const std::string& shard) {
  if (!shard.empty()) {
    // I/N, checked by the option's validator.
    opt.shard = std::stoi(shard.substr(0, shard.find('/')));
    opt.shards = std::stoi(shard.substr(shard.find('/') + 1));
  } else if (const char* i = std::getenv("GTEST_SHARD_INDEX"), *n = std::getenv("GTEST_TOTAL_SHARDS"); i && n) {
    const std::string env = std::string(i) + "/" + n;
    if (!shard_spec(env).empty()) throw InputError("GTEST_SHARD_INDEX/GTEST_TOTAL_SHARDS: " + shard_spec(env));
    opt.shard = std::stoi(i);
    opt.shards = std::stoi(n);
  }
  const int failures = run_campaign(opt);
  std::printf("campaign: %s\n", failures ? "FAILURES found (see the report)" : "no failure");
  return failures ? 1 : 0;
}

std::string known_variants() {
  std::string names;
  for (const auto& [v, q] : campaign_variants()) names += "\n  " + v + " (" + q + ")";
  return names;
}

void add_campaign(CLI::App& app, CampaignOptions& opt, int& rc) {
  static std::string shard;
  auto* c = app.add_subcommand("campaign", "Differential campaign of every registered query: production against the "
                                           "truth and FCL on the targeted generators; ends in DIR/report.json and "
                                           "DIR/report.html. Exit status 1 when anything failed.");
  c->add_option("--cases", opt.cases, "cases per query, point sets and meshes included (default: each query's own: 100000 pairs, 10000 "
                "point sets, 2000 meshes)")
      ->check(positive_integer);
  c->add_option("--seconds", opt.seconds, "time budget per query, in seconds (default: none)")->check(positive_number);
  c->add_option("--seed", opt.seed, "the generators' seed")->capture_default_str()->check(seed_number);
  c->add_option("--threads", opt.threads, "worker threads (default: every core)")->check(positive_integer);
  c->add_option("--out", opt.out, "the report's folder")->capture_default_str();
  c->add_option("--query", opt.queries, "only this query (repeatable; geomcheck queries lists them)")
      ->check([](const std::string& q) { return family_of(q) ? std::string() : "unknown query '" + q + "'"; });
  c->add_option("--junit", opt.junit, "also write the results as JUnit XML (a test case per query and property family)");
  c->add_option("--peer-cases", opt.peer_cases,
                "cases of each query also put to the other engines (ODE, Bullet, MuJoCo where built; 0: none)")
      ->capture_default_str()
      ->check(CLI::NonNegativeNumber);
  c->add_option("--seeds", opt.seeds, "where the bug-report configurations put to the other engines are "
                                       "(<query>/bugreport-*.case)")
      ->capture_default_str();
  c->add_option("--shard", shard,
                "run shard I of N (0-based: the cases i with i % N == I of every query) and also write DIR/shard.json "
                "for 'geomcheck merge'; default: GTEST_SHARD_INDEX/GTEST_TOTAL_SHARDS when both are set")
      ->check(shard_spec);
  c->add_flag("--no-progress", [&opt](std::int64_t) { opt.progress = false; }, "no progress lines on stderr");
  c->add_option("--subject,--variant", opt.variant,
                "run a built-in subject of one query in production's place: a known-wrong variant ('help' lists them)")
      ->check([](const std::string& v) {
        if (v == "help") return std::string();
        for (const auto& [name, q] : campaign_variants())
          if (name == v) return std::string();
        return "unknown variant '" + v + "'; the known-wrong variants are:" + known_variants();
      });
  c->callback([&opt, &rc] {
    if (opt.variant == "help") {
      std::printf("%s\n", known_variants().c_str() + 1);
      rc = 0;
      return;
    }
    rc = cmd_campaign(opt, shard);
  });
}

void add_merge(CLI::App& app, const std::string& command, int& rc) {
  static std::vector<std::string> dirs;
  static std::string out = "reports/out", junit;
  auto* m = app.add_subcommand("merge", "Joins the output folders of the shards of one campaign ('campaign --shard "
                                        "I/N', N folders) into one report: OUT/report.json and OUT/report.html, the "
                                        "figures of the unsharded run, and every saved case. Exit status 1 when "
                                        "anything failed, 2 when a shard is missing, repeated or of another campaign.");
  m->add_option("dirs", dirs, "the shards' output folders (each holds shard.json)")->required()->check(CLI::ExistingDirectory);
  m->add_option("--out", out, "the merged report's folder")->capture_default_str();
  m->add_option("--junit", junit, "also write the merged results as JUnit XML");
  m->callback([&rc, &command] { rc = merge_shards(dirs, out, junit, command); });
}

void add_replay(CLI::App& app, int& rc) {
  static std::vector<std::string> paths;
  static bool quiet = false;
  static std::string subject;
  auto* r = app.add_subcommand("replay", "Replays case files (or every *.case under a directory): production, the "
                                         "truth and FCL side by side, the verdict margin and every check. A point-set "
                                         "file (query delaunay_2d) is held to the exact checker and CGAL; a mesh file "
                                         "(collide_cylinder_mesh) to the brute force and the engine face by face. Exit status "
                                         "1 when a check fails, 2 when a file cannot be read or parsed.");
  r->add_flag("--quiet", quiet, "one line per passing case");
  r->add_option("--subject,--variant", subject,
                "replay against a built-in subject in production's place: a known-wrong variant, or another engine "
                "(ODE, Bullet, MuJoCo where built); a subject the file's query does not have is a usage error (exit 2), "
                "for every family");
  r->add_option("paths", paths, "case files or directories")->required();
  r->callback([&rc] { rc = cmd_replay(paths, quiet, subject); });
}

void add_converter(CLI::App& app, bool fuzz, int& rc) {
  struct Args {
    std::string query, input, out;
  };
  static Args args[2];
  Args& a = args[fuzz];
  auto* c = app.add_subcommand(fuzz ? "from-fuzz" : "from-rapidcheck",
                               fuzz ? "Turns a libFuzzer input of QUERY's fuzz target into a case file."
                                    : "Turns a RapidCheck counterexample (its printed text) into a case file.");
  c->add_option("query", a.query, "the query id")->required();
  c->add_option("input", a.input, fuzz ? "the input (crash-..., timeout-...)" : "the text, or - for stdin")->required();
  c->add_option("-o,--out", a.out, "the case file to write (default: stdout)");
  c->callback([&a, fuzz, &rc] { rc = cmd_convert(fuzz, a.query, a.input, a.out); });
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"geomcheck: property-based verification of geometric queries against exact arithmetic."};
  app.set_version_flag("--version", std::string("geomcheck ") + GEOMCHECK_VERSION);
  app.require_subcommand(1);
  app.footer("Case files: corpora/seeds/<query>/ and corpora/regressions/<query>/ (format: corpora/README.md).\n"
             "Exit status: 0 all passed, 1 a check failed, 2 a usage or input error.");
  int rc = 0;
  CampaignOptions opt;
  opt.version = GEOMCHECK_VERSION;
  opt.started = report::utc_now();
  for (int i = 0; i < argc; ++i) opt.command += (i ? " " : "") + std::string(argv[i]);
  add_campaign(app, opt, rc);
  add_merge(app, opt.command, rc);
  add_replay(app, rc);
  add_converter(app, true, rc);
  add_converter(app, false, rc);
  app.add_subcommand("queries", "Lists the registered queries: id, family (a pair of shapes, a point set, or a "
                                "cylinder and a mesh), what production answers.")
      ->callback([] {
        int w = 0;  // the longest id sets the column
        for (const auto& q : kAllQueries) w = std::max(w, static_cast<int>(std::strlen(q.name)));
        for (const auto& q : kAllQueries) std::printf("%-*s  %-9s %s\n", w, q.name, family_name(q.family), q.summary);
      });
  std::string names;
  bool known = false;
  for (const CLI::App* c : app.get_subcommands({})) {
    names += (names.empty() ? "" : ", ") + c->get_name();
    known = known || (argc > 1 && c->get_name() == argv[1]);
  }
  if (argc > 1 && argv[1][0] != '-' && !known) {
    std::fprintf(stderr, "geomcheck: unknown command '%s' (commands: %s; --help says more)\n", argv[1], names.c_str());
    return 2;
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& e) {  // --help, --version
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    app.exit(e);
    return 2;
  } catch (const InputError& e) {
    std::fprintf(stderr, "geomcheck: %s\n", e.what());
    return 2;
  }
  return rc;
}
