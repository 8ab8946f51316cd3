// geomcheck — one evaluated case into a query's report, and a report's start time (report.hpp).
#include <algorithm>
#include <cmath>
#include <ctime>

#include "geomcheck/reports/report.hpp"

namespace geomcheck::report {

void add_evaluation(QueryReport& rep, QueryId id, const Evaluation& e) {
  ++rep.cases;
  if (!e.valid) return;
  ++rep.valid;
  rep.prod_hits += e.prod_hit;
  rep.truth_hits += e.truth_hit;
  rep.verdicts[verdict_word(id, e)]++;
  if (e.disagree) {
    ++rep.disagree;
    if (e.excused) ++rep.excused;
    else ++rep.beyond;
    if (std::isfinite(e.margin)) rep.worst_margin = std::max(rep.worst_margin, e.margin);
  }
  rep.depth.add(e.depth_err);
  rep.depth_ratio.add(e.depth_ratio);
  rep.normal.add(e.normal_err);
  rep.point.add(e.point_err);
  rep.t.add(e.t_err);
}

std::string utc_now() {
  const std::time_t t = std::time(nullptr);
  std::tm tm{};
  gmtime_r(&t, &tm);
  char b[32];
  std::strftime(b, sizeof b, "%Y-%m-%dT%H:%M:%SZ", &tm);
  return b;
}

}  // namespace geomcheck::report
