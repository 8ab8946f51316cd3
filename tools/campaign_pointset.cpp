// geomcheck — the point-set family's part of a campaign (delaunay_2d): point
// sets drawn from its generators (every mode of gen::point_sets), production
// held to the family's checks (the exact validity checker and CGAL's
// triangulation, pointset_checks.hpp) and timed against CGAL on the same
// sets. The run is verify()'s for a point-set subject (verify.hpp), in this
// process: the same runner, the same saved, shrunk and drawn failures.
#include <cstdio>
#include <filesystem>

#include "campaign.hpp"
#include "geomcheck/pointset_file.hpp"
#include "geomcheck/properties/generators.hpp"
#include "geomcheck/properties/pointset_checks.hpp"
#include "geomcheck/reports/report.hpp"
#include "geomcheck/verify.hpp"

namespace geomcheck {

report::PointSetReport run_delaunay_2d(const CampaignOptions& opt, const std::filesystem::path& out_dir, int threads) {
  (void)threads;  // one thread: a set takes microseconds, the family a few seconds
  const int n = opt.cases > 0 ? opt.cases : kDelaunayDefaultSets;
  // Every set of the seed is drawn (the same sets in every shard); this
  // shard's are run.
  auto all = gen::draw_point_sets(opt.seed, n);
  std::vector<std::pair<std::vector<Vec2>, std::string>> sets;
  std::vector<int> index;
  for (int i = 0; i < n; ++i) {
    if (i % opt.shards != opt.shard) continue;
    sets.push_back(std::move(all[i]));
    index.push_back(i);
  }
  VerifyOptions v;
  v.cases = static_cast<int>(sets.size());
  v.seed = opt.seed;
  v.out = out_dir / "counterexamples";
  v.max_saved = report::kMaxSavedPerKind;
  v.quiet = true;
  v.summary = false;
  v.report = false;  // the campaign's report has the section
  v.isolate = false;
  v.program = "geomcheck";
  v.replay = "geomcheck replay ";
  v.found_by = "campaign";
  v.seconds = opt.seconds;
  const VerifyResult res = verify(production_point_set(), sets, index, v);
  report::PointSetReport rep = res.point_set_figures;
  rep.requested = static_cast<int>(sets.size());
  if (opt.progress)
    std::fprintf(stderr, "[campaign] %-24s %7d sets, %d failing\n", rep.name.c_str(), rep.sets, rep.failures);
  return rep;
}

}  // namespace geomcheck
