// geomcheck — verification campaigns: every registered query's generators,
// production held against the exact oracle and FCL, written as report.json
// and report.html.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace geomcheck {

struct CampaignOptions {
  std::uint64_t seed = 20261121;
  int cases = 100000;         ///< per query
  double seconds = 0;         ///< per query time budget; 0 = no limit
  int threads = 0;            ///< 0 = all cores
  std::string out = "reports/out";
  std::vector<std::string> queries;  ///< empty = all
  bool progress = true;
};

/// Runs the campaign; returns the number of disagreements beyond the band
/// (0 = production verified on every case run).
int run_campaign(const CampaignOptions& opt);

}  // namespace geomcheck
