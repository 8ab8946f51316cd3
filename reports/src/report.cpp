#include "geomcheck/reports/report.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

namespace geomcheck::report {

namespace {

/// The command that replays one of r's counterexamples, less its path.
std::string replay_prefix(const QueryReport& r) {
  if (!r.replay.empty()) return r.replay;
  return "geomcheck replay " + (r.subject == "production" ? std::string() : "--subject " + r.subject + " ");
}

std::string jnum(double x) {
  if (!std::isfinite(x)) return "null";
  char b[40];
  std::snprintf(b, sizeof b, "%.6g", x);
  return b;
}
std::string jstr(const std::string& s) {
  std::string o = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') o += '\\', o += c;
    else if (c == '\n') o += "\\n";
    else if (static_cast<unsigned char>(c) < 0x20) o += ' ';
    else o += c;
  }
  return o + "\"";
}
std::string hnum(double x) {  // for a table cell: three digits, a dash for none
  if (!std::isfinite(x)) return "&ndash;";
  char b[32];
  std::snprintf(b, sizeof b, "%.3g", x);
  return b;
}

void write_series_json(std::ostream& o, const char* name, Series& s) {
  o << "      " << jstr(name) << ": {\"n\": " << s.v.size() << ", \"p50\": " << jnum(s.pct(0.5))
    << ", \"p90\": " << jnum(s.pct(0.9)) << ", \"p99\": " << jnum(s.pct(0.99)) << ", \"max\": " << jnum(s.pct(1.0))
    << ", \"log10_histogram\": [";
  const auto h = s.hist();
  for (std::size_t i = 0; i < h.size(); ++i) o << (i ? ", " : "") << h[i];
  o << "]}";
}

// The range of histogram bin i (Series::hist): exactly 0, below 1e-17, a
// decade, or 1e-4 and above.
std::string bin_range(std::size_t i) {
  if (i == 0) return "0";
  if (i == 1) return "(0, 1e-17)";
  if (i == 15) return "[1e-4, inf)";
  return "[1e" + std::to_string(int(i) - 19) + ", 1e" + std::to_string(int(i) - 18) + ")";
}

// A histogram of log10(error / scale) drawn so that its tails show: bar
// heights on a log count scale (one case is a visible bar), the count scale
// labelled, the under- and overflow bins labelled with their real ranges,
// and the bound drawn as a red line.
std::string hist_svg(const Series& s, double bound) {
  const auto h = s.hist();
  const int mx = std::max(1, *std::max_element(h.begin(), h.end()));
  constexpr int kLeft = 34, kBin = 24, kBase = 70, kTall = 56;
  auto height = [&](int n) { return n <= 0 ? 0 : 4 + static_cast<int>(std::lround((kTall - 4) * std::log10(n) / std::log10(std::max(mx, 2)))); };
  std::ostringstream o;
  o << "<svg width='" << kLeft + 16 * kBin + 6 << "' height='" << kBase + 26 << "' role='img' class='hist'>"
    << "<title>log10 histogram of error / scale, count on a log scale</title>"
    << "<line x1='" << kLeft - 2 << "' y1='" << kBase - kTall << "' x2='" << kLeft - 2 << "' y2='" << kBase
    << "' stroke='#888'/><text x='" << kLeft - 4 << "' y='" << kBase - kTall + 8
    << "' font-size='9' text-anchor='end'>" << mx << "</text><text x='" << kLeft - 4 << "' y='" << kBase
    << "' font-size='9' text-anchor='end'>1</text>";
  for (std::size_t i = 0; i < h.size(); ++i) {
    const int bh = height(h[i]);
    o << "<rect x='" << kLeft + i * kBin << "' y='" << kBase - bh << "' width='" << kBin - 4 << "' height='" << bh
      << "' fill='#4a78c2' data-count='" << h[i] << "'><title>" << bin_range(i) << ": " << h[i] << "</title></rect>";
  }
  const std::pair<std::size_t, const char*> labels[] = {{0, "0"}, {1, "<1e-17"}, {3, "1e-16"}, {7, "1e-12"}, {11, "1e-8"}, {15, "≥1e-4"}};
  for (const auto& [i, text] : labels)
    o << "<text x='" << kLeft + i * kBin << "' y='" << kBase + 12 << "' font-size='9'>" << text << "</text>";
  if (bound > 0 && std::isfinite(bound)) {
    const double e = std::log10(bound);
    const double x = kLeft + std::clamp(e + 19, 1.0, 15.0) * kBin;
    o << "<line x1='" << x << "' y1='" << kBase - kTall - 4 << "' x2='" << x << "' y2='" << kBase + 2
      << "' stroke='#c00' stroke-dasharray='3,2'><title>bound " << jnum(bound) << "</title></line><text x='" << x + 2
      << "' y='" << kBase + 23 << "' font-size='9' fill='#c00'>bound " << jnum(bound) << "</text>";
  }
  o << "</svg>";
  return o.str();
}


// The precision table: production and FCL, a row each, per query.
void write_precision_table(std::ostream& h, std::vector<QueryReport>& reps) {
  h << "<h2 id='precision'>Precision table: production and FCL against the exact oracle</h2>"
       "<p>Every error is measured with the same exact yardstick for both engines, as a multiple of the case scale "
       "(p50 / p99 / max over the cases where it applies). <b>verdicts</b>: disagreements with the certified "
       "verdict where the exact answer is farther than the band from touching (collide: overlap or FCL's collide; "
       "FCL's distance is counted apart: &lt; 0 meaning &lsquo;they meet&rsquo;). <b>depth</b>: distance of the "
       "reported depth from the certified penetration depth. <b>normal</b>: how much farther the shapes overlap "
       "along the reported normal than the true depth (0 for a minimal direction). <b>point</b>: how far the "
       "reported point lies outside either shape. <b>distance</b>: |reported &minus; certified distance| on "
       "separated pairs. <b>t</b>: the gap (or depth) of the segment point or ball at the reported t; "
       "|&Delta;t| is FCL's t against the exact first touch, absolute.</p>"
       "<table style='font-size:12px'><tr><th class='l'>query</th><th class='l'>engine</th><th>answered</th>"
       "<th>verdicts beyond the band</th><th>depth</th><th>normal</th><th>point</th><th>distance</th>"
       "<th>t</th><th>|&Delta;t|</th></tr>";
  auto tri = [](Series& s) {
    if (s.v.empty()) return std::string("&ndash;");
    return hnum(s.pct(0.5)) + " / " + hnum(s.pct(0.99)) + " / " + hnum(s.pct(1.0));
  };
  for (QueryReport& r : reps) {
    auto rate = [&](int n, int of) { return std::to_string(n) + (of ? " (" + hnum(100.0 * n / of) + "%)" : ""); };
    Series none;
    h << "<tr><td class='l' rowspan='2'><a href='#" << r.name << "'>" << r.name << "</a></td><td class='l'>production</td><td>"
      << r.valid << "</td><td class='" << (r.beyond ? "bad" : "ok") << "'>" << rate(r.beyond, r.valid) << "</td><td>"
      << tri(r.depth) << "</td><td>" << tri(r.normal) << "</td><td>" << tri(r.point) << "</td><td>&ndash;</td><td>"
      << tri(r.t) << "</td><td>&ndash;</td></tr>";
    h << "<tr><td class='l'>FCL</td><td>" << r.fcl_ok << "</td><td class='" << (r.fcl_beyond || r.fcl_distance_beyond ? "bad" : "ok")
      << "'>" << rate(r.fcl_beyond, r.fcl_ok);
    if (r.fcl_distance_asked) h << "<br>distance: " << rate(r.fcl_distance_beyond, r.fcl_distance_asked);
    h << "</td><td>" << tri(r.fcl_depth) << "</td><td>" << tri(r.fcl_normal) << "</td><td>" << tri(r.fcl_point)
      << "</td><td>" << tri(r.fcl_distance) << "</td><td>" << tri(r.fcl_t_gap) << "</td><td>" << tri(r.fcl_t)
      << "</td></tr>";
  }
  h << "</table>";
}

// A row of the error table: n, percentiles, histogram, the bound.
void error_row(std::ostream& h, const char* n, Series& s, double bound) {
  if (s.v.empty()) return;
  const double mx = s.pct(1.0);
  h << "<tr><td class='l'>" << n << "</td><td>" << (bound > 0 ? jnum(bound) : std::string("&ndash;")) << "</td><td>" << s.v.size() << "</td><td>" << jnum(s.pct(0.5))
    << "</td><td>" << jnum(s.pct(0.9)) << "</td><td>" << jnum(s.pct(0.99)) << "</td><td class='"
    << (bound > 0 && mx > bound ? "bad" : "") << "'>" << jnum(mx) << "</td><td>" << hist_svg(s, bound) << "</td></tr>";
}

// What the subject is held to, in words.
std::string claims_text(const QueryReport& r) {
  const Claims& c = r.claims;
  const std::string whose = r.own_claims ? "claims of " + r.subject
                            : (r.subject == "production" ? std::string("claims") : "claims of " + r.subject + " (production's)");
  std::string t = whose + ": verdict " + (c.exact_verdict ? "exact" : "not exact") + "; depth: " + to_string(c.depth) +
                  "; point " + (c.point_in_both ? "claimed" : "not claimed") + "; touching " +
                  (c.touching_is_contact ? "is" : "is not") + " contact";
  if (c.margin > 0) t += "; margin " + jnum(c.margin) + " * scale";
  if (*c.normal) t += std::string("; normal: ") + c.normal;
  if (*c.truth) t += std::string("; truth: ") + c.truth;
  return t;
}

// The claims as JSON.
std::string claims_json(const QueryReport& r) {
  const Claims& c = r.claims;
  auto b = [](bool v) { return v ? "true" : "false"; };
  return std::string("{\"subject\": ") + jstr(r.subject) + ", \"own\": " + b(r.own_claims) +
         ", \"exact_verdict\": " + b(c.exact_verdict) + ", \"depth\": " + jstr(to_string(c.depth)) +
         ", \"point_in_both\": " + b(c.point_in_both) + ", \"touching_is_contact\": " + b(c.touching_is_contact) +
         ", \"margin\": " + jnum(c.margin) + ", \"normal\": " + jstr(c.normal) + ", \"truth\": " + jstr(c.truth) + "}";
}

// A query's section: its verdicts, errors, depth ratio, failures, drawings.
void write_query_section(std::ostream& h, QueryReport& r) {
  const bool clean = r.beyond == 0 && r.check_failures == 0;
  h << "<h2 id='" << r.name << "'>" << r.name << "</h2><p>" << html(r.summary) << "</p><p class='claims'>"
    << html(claims_text(r)) << "</p><p class='"
    << (clean ? "ok'>verified: no disagreement beyond the band, every property holds" : "bad'>FAILURES found")
    << "</p><table><tr><th class='l'>measure</th><th>production</th><th>FCL</th></tr>"
    << "<tr><td class='l'>cases run of requested (valid)</td><td>" << r.cases << " of " << r.requested << " ("
    << r.valid << ")" << (r.stopped_by_time ? "; stopped by --seconds" : "") << "</td><td>" << r.fcl_ok
    << " answered</td></tr>"
    << "<tr><td class='l'>hit rate (oracle " << jnum(r.valid ? double(r.truth_hits) / r.valid : NAN) << ")</td><td>"
    << jnum(r.valid ? double(r.prod_hits) / r.valid : NAN) << "</td><td></td></tr>"
    << "<tr><td class='l'>verdict disagreements</td><td>" << r.disagree << "</td><td>" << r.fcl_disagree << "</td></tr>"
    << "<tr><td class='l'>beyond the band (" << jnum(r.tol.verdict) << " &times; scale)</td><td class='"
    << (r.beyond ? "bad" : "ok") << "'>" << r.beyond << "</td><td class='" << (r.fcl_beyond ? "bad" : "ok") << "'>"
    << r.fcl_beyond << "</td></tr>"
    << "<tr><td class='l'>worst disagreement margin</td><td>" << jnum(r.worst_margin) << "</td><td></td></tr>"
    << "<tr><td class='l'>property failures</td><td class='" << (r.check_failures ? "bad" : "ok") << "'>"
    << r.check_failures << "</td><td></td></tr>"
    << "<tr><td class='l'>production time per query</td><td>" << jnum(r.prod_ns) << " ns</td><td></td></tr>"
    << "<tr><td class='l'>oracle+checks time per case</td><td>" << jnum(r.oracle_us) << " &micro;s</td><td></td></tr>"
    << "</table><table><tr><th class='l'>verdict</th><th>cases</th></tr>";
  for (const auto& [k, v] : r.verdicts) h << "<tr><td class='l'>" << k << "</td><td>" << v << "</td></tr>";
  h << "</table><table><tr><th class='l'>error / scale</th><th>bound</th><th>n</th><th>p50</th><th>p90</th><th>p99</th><th>max</th><th>log10 histogram</th></tr>";
  error_row(h, "depth", r.depth, r.tol.depth);
  error_row(h, "normal", r.normal, r.tol.normal);
  error_row(h, "point", r.point, r.tol.point);
  error_row(h, "t", r.t, r.tol.t);
  error_row(h, "FCL depth", r.fcl_depth, 0);
  error_row(h, "FCL normal", r.fcl_normal, 0);
  error_row(h, "FCL point", r.fcl_point, 0);
  error_row(h, "FCL distance", r.fcl_distance, 0);
  error_row(h, "FCL t", r.fcl_t_gap, 0);
  error_row(h, "FCL |t - t_exact| (absolute)", r.fcl_t, 0);
  h << "</table>";
  if (r.depth_is_bound) {
    // The depth is the overlap along the returned normal, not the minimal
    // translation: how much larger than the penetration depth it is.
    Series& q = r.depth_ratio;
    h << "<table><tr><th class='l'>depth / penetration depth</th><th>n</th><th>min</th><th>p50</th><th>p90</th>"
         "<th>p99</th><th>max</th></tr><tr><td class='l'>production (overlapping cases, penetration depth "
         "certified to 1%)</td><td>"
      << q.v.size() << "</td><td>" << jnum(q.pct(0.0)) << "</td><td>" << jnum(q.pct(0.5)) << "</td><td>"
      << jnum(q.pct(0.9)) << "</td><td>" << jnum(q.pct(0.99)) << "</td><td>" << jnum(q.pct(1.0))
      << "</td></tr></table><p>The contact's depth is the overlap of the shapes along its normal, an upper bound "
         "of the penetration depth (1 where the normal is a minimal direction); only a depth below the "
         "penetration depth is an error (the <b>depth</b> row above).</p>";
  }
  if (!r.failures_by_property.empty()) {
    h << "<h3>failures</h3><ul>";
    for (const auto& [k, v] : r.failures_by_property) h << "<li>" << html(k) << ": " << v << "</li>";
    h << "</ul><p>counterexamples (replay with <code>" << html(replay_prefix(r))
      << "FILE</code>; each drawn in the "
         ".html beside it):</p><ul>";
    for (std::size_t k = 0; k < r.counterexamples.size() && k < 50; ++k)
      h << "<li><code>" << html(r.counterexamples[k]) << "</code></li>";
    if (r.counterexamples.size() > 50)
      h << "<li>and " << r.counterexamples.size() - 50 << " more under <code>counterexamples/" << r.name << "/</code></li>";
    h << "</ul><h3>counterexamples drawn (first " << r.drawings.size() << " of " << r.counterexamples.size() << ")</h3>";
    for (const auto& d : r.drawings) h << d;
  }
  if (!r.fcl_drawings.empty()) {
    h << "<h3>FCL's disagreements beyond the band, drawn (" << r.fcl_drawings.size() << " of " << r.fcl_cases.size()
      << "; every one saved under <code>fcl-disagreements/" << r.name
      << "/</code>, replay with <code>geomcheck replay DIR</code>)</h3>";
    for (const auto& d : r.fcl_drawings) h << d;
  }
}

std::string json_counts(const std::map<std::string, int>& m) {
  std::string o = "{";
  for (const auto& [k, v] : m) o += (o.size() > 1 ? ", " : "") + jstr(k) + ": " + std::to_string(v);
  return o + "}";
}

// The point-set queries, after the pair queries (absent when none ran).
void write_point_sets_json(std::ostream& js, const std::vector<PointSetReport>& point_sets) {
  if (point_sets.empty()) return;
  js << ",\n  \"point_set_queries\": [\n";
  for (std::size_t i = 0; i < point_sets.size(); ++i) {
    const PointSetReport& r = point_sets[i];
    js << "    {\n      \"id\": " << jstr(r.name) << ",\n      \"summary\": " << jstr(r.summary)
       << ",\n      \"requested\": " << r.requested << ", \"stopped_by_time\": " << (r.stopped_by_time ? "true" : "false")
       << ",\n      \"sets\": " << r.sets << ", \"points\": " << r.points << ", \"failures\": " << r.failures
       << ",\n      \"modes\": " << json_counts(r.modes) << ",\n      \"kinds\": " << json_counts(r.kinds)
       << ",\n      \"failures_by_property\": " << json_counts(r.failures_by_property)
       << ",\n      \"cgal_choices_differ\": " << r.cgal_choices_differ
       << ",\n      \"production_us_total\": " << jnum(r.production_us) << ", \"cgal_us_total\": " << jnum(r.cgal_us)
       << ", \"production_over_cgal\": " << jnum(r.cgal_us > 0 ? r.production_us / r.cgal_us : NAN)
       << ",\n      \"counterexamples\": [";
    for (std::size_t k = 0; k < r.counterexamples.size(); ++k) js << (k ? ", " : "") << jstr(r.counterexamples[k]);
    js << "]\n    }" << (i + 1 < point_sets.size() ? "," : "") << "\n";
  }
  js << "  ]";
}

// A point-set query's section: the sets by mode and kind, failures, time against CGAL.
void write_point_set_section(std::ostream& h, const PointSetReport& r) {
  const bool clean = r.failures == 0;
  h << "<h2 id='" << r.name << "'>" << r.name << "</h2><p>" << html(r.summary) << "</p><p class='"
    << (clean ? "ok'>verified: every triangulation valid (exact checker) and CGAL's up to cocircular choices"
              : "bad'>FAILURES found")
    << "</p><table><tr><th class='l'>measure</th><th>value</th></tr><tr><td class='l'>point sets run of requested (points)</td><td>"
    << r.sets << " of " << r.requested << " (" << r.points << ")" << (r.stopped_by_time ? "; stopped by --seconds" : "")
    << "</td></tr><tr><td class='l'>failures</td><td class='" << (clean ? "ok" : "bad") << "'>"
    << r.failures << "</td></tr><tr><td class='l'>cocircular choices other than CGAL's (legitimate)</td><td>"
    << r.cgal_choices_differ << "</td></tr><tr><td class='l'>time, production / CGAL (all sets)</td><td>"
    << jnum(r.production_us / 1e3) << " ms / " << jnum(r.cgal_us / 1e3) << " ms = "
    << jnum(r.cgal_us > 0 ? r.production_us / r.cgal_us : NAN) << "</td></tr></table>";
  auto table = [&](const char* what, const std::map<std::string, int>& m) {
    h << "<table><tr><th class='l'>" << what << "</th><th>sets</th></tr>";
    for (const auto& [k, v] : m) h << "<tr><td class='l'>" << html(k) << "</td><td>" << v << "</td></tr>";
    h << "</table>";
  };
  table("generator mode", r.modes);
  table("kind of point set (dimension)", r.kinds);
  if (!r.failures_by_property.empty()) {
    table("failed property", r.failures_by_property);
    h << "<p>counterexamples (replay with <code>geomcheck replay FILE</code>):</p><ul>";
    for (std::size_t k = 0; k < r.counterexamples.size() && k < 50; ++k)
      h << "<li><code>" << html(r.counterexamples[k]) << "</code></li>";
    h << "</ul>";
  }
}

}  // namespace

std::string html(const std::string& s) {
  std::string o;
  for (char c : s) {
    if (c == '<') o += "&lt;";
    else if (c == '>') o += "&gt;";
    else if (c == '&') o += "&amp;";
    else o += c;
  }
  return o;
}


void write_json(const std::filesystem::path& file, const RunInfo& run, std::vector<QueryReport>& reps,
                const std::vector<PointSetReport>& point_sets) {
  std::ofstream js(file);
  bool passed = true;
  for (const QueryReport& r : reps) passed = passed && r.beyond == 0 && r.check_failures == 0;
  for (const PointSetReport& r : point_sets) passed = passed && r.failures == 0;
  js << "{\n  \"tool\": \"geomcheck\",\n  \"schema_version\": " << kReportSchemaVersion
     << ",\n  \"version\": " << jstr(run.version) << ",\n  \"started\": " << jstr(run.started)
     << ",\n  \"command_line\": " << jstr(run.command) << ",\n  \"verdict\": " << jstr(passed ? "passed" : "failed")
     << ",\n  \"seed\": " << run.seed << ",\n  \"cases_per_query\": " << jstr(run.per_query)
     << ",\n  \"saved_cases_per_kind\": " << kMaxSavedPerKind
     << ",\n  \"replay\": " << jstr(run.rerun) << ",\n  \"implementation\": " << jstr(run.under_test)
     << ",\n  \"queries\": [\n";
  for (std::size_t i = 0; i < reps.size(); ++i) {
    QueryReport& r = reps[i];
    js << "    {\n      \"id\": " << jstr(r.name) << ",\n      \"summary\": " << jstr(r.summary)
       << ",\n      \"claims\": " << claims_json(r)
       << ",\n      \"requested\": " << r.requested << ", \"stopped_by_time\": " << (r.stopped_by_time ? "true" : "false")
       << ",\n      \"cases\": " << r.cases << ", \"valid\": " << r.valid << ", \"production_hits\": " << r.prod_hits
       << ", \"oracle_hits\": " << r.truth_hits << ",\n      \"hit_rate\": " << jnum(r.valid ? double(r.prod_hits) / r.valid : NAN)
       << ",\n      \"verdicts\": {";
    bool first = true;
    for (const auto& [k, v] : r.verdicts) js << (first ? "" : ", ") << jstr(k) << ": " << v, first = false;
    js << "},\n      \"disagreements\": " << r.disagree << ", \"inside_band\": " << r.excused
       << ", \"beyond_band\": " << r.beyond << ", \"worst_margin\": " << jnum(r.worst_margin)
       << ", \"verdict_band\": " << jnum(r.tol.verdict) << ",\n      \"check_failures\": " << r.check_failures
       << ", \"failures_by_property\": {";
    first = true;
    for (const auto& [k, v] : r.failures_by_property) js << (first ? "" : ", ") << jstr(k) << ": " << v, first = false;
    js << "},\n      \"errors\": {\n";
    write_series_json(js, "depth", r.depth);
    js << ",\n";
    write_series_json(js, "normal", r.normal);
    js << ",\n";
    write_series_json(js, "point", r.point);
    js << ",\n";
    write_series_json(js, "t", r.t);
    js << "\n      },\n";
    if (r.depth_is_bound) {
      Series& q = r.depth_ratio;
      js << "      \"depth_over_penetration_depth\": {\"n\": " << q.v.size() << ", \"min\": " << jnum(q.pct(0.0))
         << ", \"p50\": " << jnum(q.pct(0.5)) << ", \"p90\": " << jnum(q.pct(0.9)) << ", \"p99\": " << jnum(q.pct(0.99))
         << ", \"max\": " << jnum(q.pct(1.0)) << "},\n";
    }
    js << "      \"fcl\": {\"supported\": " << r.fcl_supported << ", \"answered\": " << r.fcl_ok
       << ", \"disagreements\": " << r.fcl_disagree << ", \"beyond_band\": " << r.fcl_beyond << ",\n";
    write_series_json(js, "depth", r.fcl_depth);
    js << ",\n";
    write_series_json(js, "normal", r.fcl_normal);
    js << ",\n";
    write_series_json(js, "point", r.fcl_point);
    js << ",\n";
    write_series_json(js, "t", r.fcl_t_gap);
    js << ",\n";
    write_series_json(js, "t_abs", r.fcl_t);
    js << ",\n      \"distance_asked\": " << r.fcl_distance_asked
       << ", \"distance_verdicts_beyond_band\": " << r.fcl_distance_beyond << ",\n";
    write_series_json(js, "distance", r.fcl_distance);
    js << ", \"cases\": [";
    for (std::size_t k = 0; k < r.fcl_cases.size(); ++k) js << (k ? ", " : "") << jstr(r.fcl_cases[k]);
    js << "]},\n      \"production_ns_per_query\": " << jnum(r.prod_ns) << ", \"oracle_us_per_case\": " << jnum(r.oracle_us)
       << ",\n      \"counterexamples\": [";
    for (std::size_t k = 0; k < r.counterexamples.size(); ++k) js << (k ? ", " : "") << jstr(r.counterexamples[k]);
    js << "]\n    }" << (i + 1 < reps.size() ? "," : "") << "\n";
  }
  js << "  ]";
  write_point_sets_json(js, point_sets);
  js << "\n}\n";

}

void write_html(const std::filesystem::path& file, const RunInfo& run, std::vector<QueryReport>& reps,
                const std::vector<PointSetReport>& point_sets) {
  std::ofstream h(file);
  h << "<!doctype html><html lang='en'><head><meta charset='utf-8'><title>geomcheck campaign report</title>"
       "<style>body{font-family:sans-serif;margin:2em;max-width:1100px}table{border-collapse:collapse;margin:1em 0}"
       "td,th{border:1px solid #bbb;padding:4px 8px;text-align:right}th{background:#eee}td.l,th.l{text-align:left}"
       ".bad{color:#b00;font-weight:bold}.ok{color:#070}.claims{font-size:13px;color:#444}figure.cx{margin:1em 0;border-top:1px solid #ddd}"
       "figure.cx svg{margin-right:6px}figcaption{font-size:12px;margin:4px 0;word-break:break-all}"
       ".legend{font-size:12px;margin:2px 0}</style></head><body>"
       "<h1>geomcheck campaign report</h1><p>seed <code>"
    << run.seed << "</code>, " << html(run.per_query) << ", implementation under test: <b>" << html(run.under_test)
    << "</b>. Errors are multiples of the case scale "
       "(largest coordinate magnitude or extent). Rerun: <code>" << html(run.rerun) << "</code></p>";
  write_precision_table(h, reps);
  for (QueryReport& r : reps) write_query_section(h, r);
  for (const PointSetReport& r : point_sets) write_point_set_section(h, r);
  h << "</body></html>\n";
}

namespace {

std::string xml(const std::string& s) {
  std::string o;
  for (char c : s) {
    if (c == '<') o += "&lt;";
    else if (c == '>') o += "&gt;";
    else if (c == '&') o += "&amp;";
    else if (c == '"') o += "&quot;";
    else if (static_cast<unsigned char>(c) < 0x20 && c != '\n') o += ' ';
    else o += c;
  }
  return o;
}

struct JunitCase {
  std::string name;
  int failures = 0;
  std::string message;  // counts by property, the replay command
};

// One query's test cases: a family of properties is the part of a
// property's name before its first '-' (oracle-depth: oracle).
std::vector<JunitCase> junit_cases(const QueryReport& r, const std::string& replay_prefix) {
  const char* families[] = {"robust", "oracle", "consistency", "symmetry", "metamorphic", "monotone"};
  std::vector<JunitCase> out;
  JunitCase verdict{r.name + ".verdict", r.beyond, ""};
  if (r.beyond) verdict.message = std::to_string(r.beyond) + " verdicts beyond the band of " + std::to_string(r.valid) + " valid cases\n";
  out.push_back(verdict);
  for (const char* f : families) {
    JunitCase c{r.name + "." + f, 0, ""};
    for (const auto& [prop, n] : r.failures_by_property)
      if (prop.compare(0, prop.find('-'), f) == 0) c.failures += n, c.message += prop + ": " + std::to_string(n) + "\n";
    if (c.failures) {
      for (const std::string& cx : r.counterexamples)
        if (cx.find("-" + std::string(f)) != std::string::npos) {
          c.message += "replay: " + replay_prefix + cx + "\n";
          break;
        }
    }
    out.push_back(c);
  }
  return out;
}

}  // namespace

void write_junit(const std::filesystem::path& file, const RunInfo& run, const std::vector<QueryReport>& reps,
                 const std::vector<PointSetReport>& point_sets) {
  std::vector<JunitCase> cases;
  for (const QueryReport& r : reps) {
    for (JunitCase& c : junit_cases(r, replay_prefix(r))) cases.push_back(std::move(c));
  }
  for (const PointSetReport& r : point_sets)
    for (const char* prop : {"valid", "agrees-with-cgal"}) {
      JunitCase c{r.name + "." + prop, 0, ""};
      if (auto it = r.failures_by_property.find(prop); it != r.failures_by_property.end()) c.failures = it->second;
      if (c.failures) {
        c.message = std::to_string(c.failures) + " of " + std::to_string(r.sets) + " point sets\n";
        for (const std::string& cx : r.counterexamples)
          if (cx.find(prop) != std::string::npos) {
            c.message += "replay: geomcheck replay " + cx + "\n";
            break;
          }
      }
      cases.push_back(c);
    }
  int failed = 0;
  for (const JunitCase& c : cases) failed += c.failures > 0;
  std::ofstream o(file);
  o << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites name=\"geomcheck campaign\" tests=\"" << cases.size()
    << "\" failures=\"" << failed << "\">\n  <testsuite name=\"campaign seed " << run.seed << "\" tests=\""
    << cases.size() << "\" failures=\"" << failed << "\" timestamp=\"" << xml(run.started) << "\">\n";
  for (const JunitCase& c : cases) {
    o << "    <testcase classname=\"geomcheck\" name=\"" << xml(c.name) << "\"";
    if (!c.failures) {
      o << "/>\n";
      continue;
    }
    o << ">\n      <failure message=\"" << c.failures << " failing cases\">" << xml(c.message)
      << "rerun: " << xml(run.rerun) << "</failure>\n    </testcase>\n";
  }
  o << "  </testsuite>\n</testsuites>\n";
}

void write_counterexample_page(const std::filesystem::path& file, const std::string& name, const std::string& drawing,
                               const std::string& subject, const std::string& replay_command) {
  std::ofstream page(file);
  page << "<!doctype html><html lang='en'><head><meta charset='utf-8'><title>" << html(name)
       << "</title><style>body{font-family:sans-serif;margin:2em}figcaption{font-size:12px;margin:4px 0}"
          ".legend{font-size:12px}</style></head><body>"
       << drawing << "<p>" << html(subject) << " fails this case; <code>" << html(replay_command)
       << "</code> replays it.</p></body></html>\n";
}

}  // namespace geomcheck::report
