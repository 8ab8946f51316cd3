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

/// The layout of shard.json (bumped on any change: merge refuses others).
constexpr int kShardFormat = 3;

/// A list of reports as a JSON array, through the one serialiser (report.hpp).
template <class R>
Json array_of(const std::vector<R>& reps) {
  Json a = Json::array();
  for (const R& r : reps) a.push_back(Json::parse(report::to_json(r)));
  return a;
}
/// The reports of a JSON array.
template <class R>
std::vector<R> reports_of(const Json& a) {
  std::vector<R> out;
  for (const Json& o : a) {
    R r;
    report::from_json(o.dump(), r);
    out.push_back(std::move(r));
  }
  return out;
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
  j["run"] = Json::parse(report::to_json(run));
  j["reports"] = array_of(reps);
  j["point_sets"] = array_of(point_sets);
  j["meshes"] = array_of(meshes);
  std::ofstream f(file);
  f << j.dump(1) << "\n";
  if (!f) std::fprintf(stderr, "[campaign] cannot write %s\n", file.string().c_str());
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
      try {
        report::from_json(s.j.at("run").dump(), s.run);
        s.reps = reports_of<QueryReport>(s.j.at("reports"));
        s.point_sets = reports_of<PointSetReport>(s.j.at("point_sets"));
        s.meshes = reports_of<MeshReport>(s.j.at("meshes"));
      } catch (const std::exception& e) {
        throw std::runtime_error(file.string() + ": " + e.what());
      }
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
    for (std::size_t q = 0; q < reps.size(); ++q) report::merge_into(reps[q], s.reps[q]);
    for (std::size_t q = 0; q < point_sets.size(); ++q) report::merge_into(point_sets[q], s.point_sets[q]);
    for (std::size_t q = 0; q < meshes.size(); ++q) report::merge_into(meshes[q], s.meshes[q]);
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
