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

report::PointSetReport run_delaunay_2d(const CampaignOptions& opt, const std::filesystem::path& out_dir) {
  // Every set of the seed is drawn (the same sets in every shard); this
  // shard's are run, on one thread (a set takes microseconds).
  auto sets = gen::draw_point_sets(opt.seed, opt.cases > 0 ? opt.cases : kDelaunayDefaultSets);
  std::vector<int> index;
  keep_this_shard(sets, opt, index);
  const VerifyOptions v = family_run_options(opt, out_dir, static_cast<int>(sets.size()), "geomcheck replay ");
  report::PointSetReport rep = verify(production_point_set(), sets, index, v).point_set_figures;
  rep.requested = static_cast<int>(sets.size());
  if (opt.progress)
    std::fprintf(stderr, "[campaign] %-24s %7d sets, %d failing\n", rep.name.c_str(), rep.sets, rep.failures);
  return rep;
}

}  // namespace geomcheck
