// geomcheck — verification campaigns: every registered query's generators,
// production held against the exact oracle and FCL, written as report.json
// and report.html.
#pragma once

#include <chrono>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include <filesystem>

#include "geomcheck/registry.hpp"
#include "geomcheck/reports/report.hpp"
#include "geomcheck/verify.hpp"

namespace geomcheck {

struct CampaignOptions {
  std::uint64_t seed = 20261121;
  int cases = 0;              ///< per query; 0 = each query's default (campaign_cases)
  double seconds = 0;         ///< per query time budget; 0 = no limit
  int threads = 0;            ///< 0 = all cores
  std::string out = "reports/out";
  std::vector<std::string> queries;  ///< empty = all
  bool progress = true;
  /// A known-wrong variant (its spec's variants()) run in
  /// production's place: only its query runs. Empty = production.
  std::string variant;
  /// Cases of each query put to every other engine (peers/: ODE, Bullet,
  /// MuJoCo), the first ones of the campaign's; 0: none. Not with a variant.
  int peer_cases = 300;
  /// Where the bug-report configurations are (<query>/bugreport-*.case),
  /// put to every other engine too.
  std::string seeds = "corpora/seeds";
  /// This run is shard `shard` (0-based) of `shards`: it evaluates the cases
  /// whose index i has i % shards == shard, of every query, from the same
  /// generated sequence, and also writes DIR/shard.json for `geomcheck merge`.
  /// The other engines run in shard 0 only (on the campaign's first cases).
  int shard = 0, shards = 1;
  std::string junit;    ///< also write a JUnit XML file here (empty: none)
  std::string version;  ///< for the report: the build's version
  std::string started;  ///< for the report: UTC start time
  std::string command;  ///< for the report: the command line
};

/// The known-wrong variants' names, each with its query id.
std::vector<std::pair<std::string, std::string>> campaign_variants();

/// Cases run for query `id`: opt.cases when given, else its spec's
/// default_cases.
int campaign_cases(const CampaignOptions& opt, QueryId id);

/// Point sets of a default campaign of delaunay_2d.
inline constexpr int kDelaunayDefaultSets = 10000;
/// delaunay_2d's part of a campaign (tools/campaign_pointset.cpp).
report::PointSetReport run_delaunay_2d(const CampaignOptions& opt, const std::filesystem::path& out_dir);

/// Meshes of a default campaign of collide_cylinder_mesh.
inline constexpr int kMeshDefaultCases = 2000;
/// collide_cylinder_mesh's part of a campaign (tools/campaign_mesh.cpp): the
/// production subject, or the known-wrong variant opt.variant when it is one
/// of the mesh query's (mesh_variants()).
report::MeshReport run_collide_cylinder_mesh(const CampaignOptions& opt, const std::filesystem::path& out_dir);

/// The seed's cases of a family (all of them, tagged), cut to this shard's,
/// each numbered in `index` by its place in the seed's sequence.
template <class Case>
void keep_this_shard(std::vector<std::pair<Case, std::string>>& all, const CampaignOptions& opt, std::vector<int>& index) {
  std::vector<std::pair<Case, std::string>> mine;
  for (std::size_t i = 0; i < all.size(); ++i) {
    if (static_cast<int>(i) % opt.shards != opt.shard) continue;
    mine.push_back(std::move(all[i]));
    index.push_back(static_cast<int>(i));
  }
  all = std::move(mine);
}

/// verify()'s options for a family's part of a campaign: `cases` cases, in
/// this process, quiet, no report of its own (the campaign's has the
/// section), failures under OUT/counterexamples with the campaign's caps,
/// `replay` the command that replays one, less its path.
inline VerifyOptions family_run_options(const CampaignOptions& opt, const std::filesystem::path& out_dir, int cases,
                                        const std::string& replay) {
  VerifyOptions v;
  v.cases = cases;
  v.seed = opt.seed;
  v.out = out_dir / "counterexamples";
  v.max_saved = report::kMaxSavedPerKind;
  v.quiet = true;
  v.summary = false;
  v.report = false;
  v.isolate = false;
  v.program = "geomcheck";
  v.replay = replay;
  v.found_by = "campaign";
  v.seconds = opt.seconds;
  return v;
}

/// Runs the campaign; returns the number of disagreements beyond the band
/// (0 = production verified on every case run).
int run_campaign(const CampaignOptions& opt);

}  // namespace geomcheck
