// geomcheck — the point-set family's part of a campaign (delaunay_2d): point
// sets drawn from its generators (every mode of gen::point_sets), production
// held to the exact validity checker and to CGAL's triangulation, and timed
// against CGAL on the same sets.
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <thread>

#include "campaign.hpp"
#include "geomcheck/delaunay_2d.hpp"
#include "geomcheck/pointset_file.hpp"
#include "geomcheck/properties/generators.hpp"
#include "geomcheck/properties/pointset_checks.hpp"
#include "geomcheck/reports/report.hpp"

namespace geomcheck {

namespace {

using Clock = std::chrono::steady_clock;
using Points = std::vector<Vec2>;

// One set's outcome.
struct SetRow {
  std::string mode, kind;  // generator mode; classify_point_set
  std::string property, problem;  // the first failure, empty when none
  bool cgal_differs = false;      // cocircular choices other than CGAL's (legitimate)
  double prod_us = 0, cgal_us = 0;
  bool run = false;
};

// Production on one set, held to the checks of the family
// (pointset_checks.hpp); times it and CGAL.
SetRow check_set(const Points& p, const std::string& mode) {
  SetRow r;
  r.mode = mode;
  r.kind = std::string(classify_point_set(p));
  const PointSetOutcome o = check_point_set(p, production_point_set());
  if (o.failure) r.property = o.failure->property, r.problem = o.failure->detail;
  r.cgal_differs = o.cgal_differs;
  if (std::isfinite(o.subject_us)) r.prod_us = o.subject_us, r.cgal_us = o.cgal_us;
  return r;
}

// A failing set saved as a point-set file, its replay command in the report.
std::string save_set(const std::filesystem::path& dir, int index, const Points& p, const SetRow& r,
                     std::uint64_t seed) {
  std::filesystem::create_directories(dir);
  char name[96];
  std::snprintf(name, sizeof name, "%05d-%s.case", index, r.property.c_str());
  PointSetFile f;
  f.points = p;
  f.found_by = "campaign seed=" + std::to_string(seed) + " case=" + std::to_string(index);
  f.note = r.property + ": " + r.problem;
  std::string err;
  if (!save_point_set(dir / name, f, err)) {
    std::fprintf(stderr, "[campaign] cannot save %s: %s\n", (dir / name).string().c_str(), err.c_str());
    return "";
  }
  return (dir / name).string();
}

}  // namespace

report::PointSetReport run_delaunay_2d(const CampaignOptions& opt, const std::filesystem::path& out_dir, int threads) {
  report::PointSetReport rep;
  rep.name = kDelaunayQueryName;
  for (const auto& q : kAllQueries)
    if (rep.name == q.name) rep.summary = q.summary;
  const int n = opt.cases > 0 ? opt.cases : kDelaunayDefaultSets;
  std::vector<std::pair<Points, std::string>> sets;
  const auto gen = gen::point_sets();
  rc::Random random(opt.seed ^ 0xd1b54a32d192ed03ull);
  for (int i = 0; i < n; ++i) sets.push_back(gen(random.split(), rc::kNominalSize).value());
  const auto mine = [&](int i) { return i % opt.shards == opt.shard; };
  for (int i = 0; i < n; ++i) rep.requested += mine(i);
  std::vector<SetRow> rows(sets.size());
  std::atomic<int> next{0};
  const auto start = Clock::now();
  auto worker = [&] {
    for (int i; (i = next++) < static_cast<int>(sets.size());) {
      if (!mine(i)) continue;
      if (opt.seconds > 0 && std::chrono::duration<double>(Clock::now() - start).count() > opt.seconds) return;
      rows[i] = check_set(sets[i].first, sets[i].second);
      rows[i].run = true;
    }
  };
  std::vector<std::thread> pool;
  for (int k = 0; k < threads; ++k) pool.emplace_back(worker);
  for (auto& th : pool) th.join();
  const double elapsed = std::chrono::duration<double>(Clock::now() - start).count();
  if (opt.progress)
    std::fprintf(stderr, "[campaign] %-24s %7d sets in %.1fs\n", rep.name.c_str(), rep.requested, elapsed);
  std::vector<double> prod, cgal;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const SetRow& r = rows[i];
    if (!r.run) continue;
    ++rep.sets;
    rep.points += sets[i].first.size();
    rep.modes[r.mode]++;
    rep.kinds[r.kind]++;
    rep.cgal_choices_differ += r.cgal_differs;
    if (r.prod_us > 0) prod.push_back(r.prod_us), cgal.push_back(r.cgal_us);
    if (r.property.empty()) continue;
    ++rep.failures;
    rep.failures_by_property[r.property]++;
    const std::string path = save_set(out_dir / "counterexamples" / rep.name, static_cast<int>(i), sets[i].first, r, opt.seed);
    if (!path.empty()) rep.counterexamples.push_back(path);
  }
  for (std::size_t k = 0; k < prod.size(); ++k) rep.production_us += prod[k], rep.cgal_us += cgal[k];
  rep.stopped_by_time = rep.sets < rep.requested;
  return rep;
}

}  // namespace geomcheck
