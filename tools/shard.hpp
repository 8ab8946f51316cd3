// geomcheck — sharded campaigns: what a shard keeps (DIR/shard.json: every
// report of the shard, raw error samples included) and `geomcheck merge`,
// which joins the shards of one campaign into the report the unsharded run
// writes.
//
// The promise: shards 0..N-1 of one campaign (same seed, cases, queries,
// variant and build), merged, give the figures of the unsharded run: the
// counts, verdict mixes, failures by property and signature, worst margins
// and every error percentile and histogram (the samples are joined, not
// their summaries). What differs: timings (measured per shard), and the
// saved case files, which are capped per shard (at most N times the caps of
// one run), all kept.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "campaign.hpp"
#include "geomcheck/reports/report.hpp"

namespace geomcheck {

/// Writes a shard's reports to `file` (JSON, exact: doubles round-trip).
void write_shard(const std::filesystem::path& file, const CampaignOptions& opt, const report::RunInfo& run,
                 const std::vector<report::QueryReport>& reps, const std::vector<report::PointSetReport>& point_sets,
                 const std::vector<report::MeshReport>& meshes);

/// `geomcheck merge`: reads DIR/shard.json of every directory, checks they
/// are the N distinct shards of one campaign, copies their saved cases into
/// `out` and writes out/report.json, out/report.html (and `junit` when
/// given). Returns the exit status: 0 passed, 1 a failure in any shard, 2 an
/// input error (printed on stderr).
int merge_shards(const std::vector<std::string>& dirs, const std::string& out, const std::string& junit,
                 const std::string& command);

}  // namespace geomcheck
