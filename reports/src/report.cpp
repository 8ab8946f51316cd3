#include "geomcheck/reports/report.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

namespace geomcheck::report {

std::string precision_text(const Precision& p) {
  if (p.unit_roundoff == 0x1p-53 && p.ulps == 0 && p.min_scale == 0 && p.max_scale == INFINITY)
    return "production's (double, its own bounds, every scale)";
  char b[320];
  std::snprintf(b, sizeof b, "%s (u = 2^%d), %s, scales [%.3g, %.3g]%s",
                p.unit_roundoff == 0x1p-24 ? "float" : (p.unit_roundoff == 0x1p-53 ? "double" : "custom"),
                static_cast<int>(std::lround(std::log2(p.unit_roundoff))),
                p.ulps > 0 ? (std::to_string(static_cast<long long>(p.ulps)) + " ulps of the scene").c_str()
                           : "production's bounds at this u",
                p.min_scale, p.max_scale, p.exact_moves ? "" : ", moves not bit-exact");
  return b;
}

namespace {

/// The page drawn beside a saved case file, as a link from a report written
/// in `report_dir` (both paths as the run gave them).
std::string page_link(const std::string& case_path, const std::filesystem::path& report_dir) {
  const std::filesystem::path page = std::filesystem::path(case_path).replace_extension(".html");
  const std::filesystem::path rel = page.lexically_relative(report_dir.empty() ? "." : report_dir);
  return (rel.empty() ? page : rel).generic_string();
}

/// "N (hung H / crashed C / threw T)": a subject's property failures.
std::string failures_cell(const QueryReport& r) {
  auto n = [&](const char* property) {
    const auto it = r.failures_by_property.find(property);
    return std::to_string(it == r.failures_by_property.end() ? 0 : it->second);
  };
  return std::string("<span class='") + (r.check_failures ? "bad" : "ok") + "'>" + std::to_string(r.check_failures) +
         "</span> (" + n("subject-hung") + " / " + n("subject-crashed") + " / " + n("subject-threw") + ")";
}

/// "; bug reports: k of n failed (names)": an engine's outcome on the
/// bug-report configurations (empty where none were put to it).
std::string bugreports_cell(const QueryReport& p) {
  if (p.bugreports == 0) return "";
  std::string names;
  for (const std::string& n : p.bugreports_failed) names += (names.empty() ? "" : ", ") + n;
  return "<br>bug reports: " + std::to_string(p.bugreports_failed.size()) + " of " + std::to_string(p.bugreports) +
         " failed" + (names.empty() ? "" : "<span title='" + html(names) + "'> (hover)</span>");
}

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
std::string hnum(double x) { return readable(x, 3); }  // for the page: three digits, a dash for none

using Json = nlohmann::ordered_json;  // report.json keeps its keys in the order written

/// x as report.json gives it: jnum's six significant digits read back (an
/// integer where the text has no fraction), null where x is not finite.
Json json_num(double x) { return Json::parse(jnum(x)); }

/// n and the percentiles of s (its minimum too where asked), as JSON.
Json percentiles_json(Series& s, bool with_min) {
  Json o = {{"n", s.v.size()}};
  if (with_min) o["min"] = json_num(s.pct(0.0));
  for (const auto& [key, p] : {std::pair<const char*, double>{"p50", 0.5}, {"p90", 0.9}, {"p99", 0.99}, {"max", 1.0}})
    o[key] = json_num(s.pct(p));
  return o;
}

/// An error series as JSON: n, percentiles and the log10 histogram.
Json series_json(Series& s) {
  Json o = percentiles_json(s, false);
  o["log10_histogram"] = s.hist();
  return o;
}

// The range of histogram bin i (Series::hist): exactly 0, below 1e-17, a
// decade, or 1e-4 and above.
std::string ten_to(int e) {  // "10⁻¹⁷"
  const std::string t = readable(std::pow(10.0, e), 1);
  const std::size_t at = t.find("\u00d7");
  return at == std::string::npos ? t : t.substr(at + std::string("\u00d7").size());
}
std::string bin_range(std::size_t i) {
  if (i == 0) return "0";
  if (i == 1) return "(0, " + ten_to(-17) + ")";
  if (i == 15) return "[" + ten_to(-4) + ", \u221e)";
  return "[" + ten_to(int(i) - 19) + ", " + ten_to(int(i) - 18) + ")";
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
  const std::pair<std::size_t, std::string> labels[] = {{0, "0"},           {1, "<" + ten_to(-17)}, {3, ten_to(-16)},
                                                        {7, ten_to(-12)}, {11, ten_to(-8)},       {15, "\u2265" + ten_to(-4)}};
  for (const auto& [i, text] : labels)
    o << "<text x='" << kLeft + i * kBin << "' y='" << kBase + 12 << "' font-size='9'>" << text << "</text>";
  if (bound > 0 && std::isfinite(bound)) {
    const double e = std::log10(bound);
    const double x = kLeft + std::clamp(e + 19, 1.0, 15.0) * kBin;
    o << "<line x1='" << x << "' y1='" << kBase - kTall - 4 << "' x2='" << x << "' y2='" << kBase + 2
      << "' stroke='#c00' stroke-dasharray='3,2'><title>bound " << hnum(bound) << "</title></line><text x='" << x + 2
      << "' y='" << kBase + 23 << "' font-size='9' fill='#c00'>bound " << hnum(bound) << "</text>";
  }
  o << "</svg>";
  return o.str();
}


/// The id of an engine's row of a query in the precision table ("q--ODE").
std::string engine_anchor(const std::string& query, const std::string& engine) {
  std::string id = query + "--";
  for (char c : engine) id += std::isalnum(static_cast<unsigned char>(c)) ? c : '-';
  return id;
}

// The precision table: production and FCL, a row each, per query.
std::string claims_text(const QueryReport& r);

/// Whether FCL answered this query's cases (a campaign asks it; verify() does not).
bool fcl_asked(QueryReport& r) {
  return r.fcl_ok > 0 || r.fcl_disagree > 0 || !r.fcl_depth.v.empty() || !r.fcl_t_gap.v.empty() || !r.fcl_t.v.empty();
}

void write_precision_table(std::ostream& h, std::vector<QueryReport>& reps) {
  bool any_fcl = false;
  for (QueryReport& r : reps) any_fcl |= fcl_asked(r);
  bool one_subject = true;
  for (QueryReport& r : reps) one_subject &= r.subject == reps.front().subject;
  const std::string whom = one_subject && !reps.empty() ? html(reps.front().subject) : std::string("each subject");
  h << "<h2 id='precision'>Precision table: " << whom << (any_fcl ? " and FCL" : "") << " against the exact oracle</h2>"
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
       "<th>t</th><th>|&Delta;t|</th><th>property failures (hung / crashed / threw)</th><th>time per call</th></tr>";
  auto tri = [](Series& s) {
    if (s.v.empty()) return std::string("&ndash;");
    return hnum(s.pct(0.5)) + " /<br>" + hnum(s.pct(0.99)) + " /<br>" + hnum(s.pct(1.0));
  };
  auto rate = [&](int n, int of) { return std::to_string(n) + (of ? " (" + hnum(100.0 * n / of) + "%)" : ""); };
  auto production_row = [&](QueryReport& r, const std::string& label) {
    h << "<td class='l'>" << label << "</td><td>" << r.valid << "</td><td class='" << (r.beyond ? "bad" : "ok")
      << "'>" << rate(r.beyond, r.valid) << "</td><td>" << tri(r.depth) << "</td><td>" << tri(r.normal) << "</td><td>"
      << tri(r.point) << "</td><td>&ndash;</td><td>" << tri(r.t) << "</td><td>&ndash;</td><td>" << failures_cell(r)
      << "</td><td>" << hnum(r.prod_ns) << "&nbsp;ns</td></tr>";
  };
  auto fcl_row = [&](QueryReport& r, const std::string& label) {
    h << "<tr><td class='l'>" << label << "</td><td>" << r.fcl_ok << "</td><td class='"
      << (r.fcl_beyond || r.fcl_distance_beyond ? "bad" : "ok") << "'>" << rate(r.fcl_beyond, r.fcl_ok);
    if (r.fcl_distance_asked) h << "<br>distance: " << rate(r.fcl_distance_beyond, r.fcl_distance_asked);
    h << "</td><td>" << tri(r.fcl_depth) << "</td><td>" << tri(r.fcl_normal) << "</td><td>" << tri(r.fcl_point)
      << "</td><td>" << tri(r.fcl_distance) << "</td><td>" << tri(r.fcl_t_gap) << "</td><td>" << tri(r.fcl_t)
      << "</td><td>&ndash;</td><td>&ndash;</td></tr>";
  };
  for (QueryReport& r : reps) {
    // FCL's rows only where FCL was asked (a campaign); the subject's under its name.
    const bool fcl = fcl_asked(r);
    h << "<tr><td class='l' rowspan='" << (fcl ? 2 : 1) * (1 + r.first.size()) + r.peers.size() << "'><a href='#"
      << r.name << "'>" << r.name << "</a></td>";
    production_row(r, html(r.subject));
    if (fcl) fcl_row(r, "FCL");
    for (QueryReport& f : r.first) {
      const std::string first = " (the first " + std::to_string(f.cases) + ", as the engines)";
      h << "<tr class='same'>";
      production_row(f, html(r.subject) + first);
      if (fcl) fcl_row(f, "FCL" + first);
    }
    for (QueryReport& p : r.peers)
      h << "<tr id='" << engine_anchor(r.name, p.subject) << "'><td class='l' title=\"" << html(claims_text(p)) << "\">" << html(p.subject) << "</td><td>" << p.valid
        << " of the first " << p.cases + p.not_expressed
        << (p.not_expressed ? " (" + std::to_string(p.not_expressed) + " it cannot state)" : std::string())
        << "</td><td class='" << (p.beyond ? "bad" : "ok") << "'>"
        << rate(p.beyond, p.valid) << "</td><td>" << tri(p.depth) << "</td><td>" << tri(p.normal) << "</td><td>"
        << tri(p.point) << "</td><td>&ndash;</td><td>" << tri(p.t) << "</td><td>&ndash;</td><td>" << failures_cell(p)
        << bugreports_cell(p) << "</td><td>" << hnum(p.prod_ns) << "&nbsp;ns</td></tr>";
  }
  h << "</table>";
  if (!any_fcl) return;  // the engines' paragraph: a campaign's
  h << "<p>Production's and FCL's first rows are over every case of the run; the rows marked &ldquo;the "
       "first N&rdquo; are over the same cases as the engines below them, for a like-for-like comparison. The "
       "engines' <b>distance</b> is &ndash;: their subjects answer collide, not a distance query. "
       "Other engines (ODE, Bullet, MuJoCo, where built) answer the first cases of each query through "
       "the same door as a user's subject, in a child process (a hang or a crash is that case's failure), and are "
       "held to every property under their own claims (hover an engine's name; its header in <code>peers/</code> "
       "states them). Their failing cases are saved under <code>peers/&lt;engine&gt;/&lt;query&gt;/</code>; "
       "<code>geomcheck replay --subject ENGINE FILE</code> replays one.</p>";
}

// A row of the error table: n, percentiles, histogram, the bound.
void error_row(std::ostream& h, const char* n, Series& s, double bound) {
  if (s.v.empty()) return;
  const double mx = s.pct(1.0);
  h << "<tr><td class='l'>" << n << "</td><td>" << (bound > 0 ? hnum(bound) : std::string("&ndash;")) << "</td><td>" << s.v.size() << "</td><td>" << hnum(s.pct(0.5))
    << "</td><td>" << hnum(s.pct(0.9)) << "</td><td>" << hnum(s.pct(0.99)) << "</td><td class='"
    << (bound > 0 && mx > bound ? "bad" : "") << "'>" << hnum(mx) << "</td><td>" << hist_svg(s, bound) << "</td></tr>";
}

// What the subject is held to, in words.
std::string claims_text(const QueryReport& r) {
  const Claims& c = r.claims;
  const std::string whose = r.own_claims ? "claims of " + r.subject
                            : (r.subject == "production" ? std::string("claims") : "claims of " + r.subject + " (production's)");
  std::string t = whose + ": verdict " + (c.exact_verdict ? "exact" : "not exact") + "; depth: " + to_string(c.depth) +
                  "; point " + (c.point_in_both ? "claimed" : "not claimed") + "; touching " +
                  (c.touching_is_contact ? "is" : "is not") + " contact";
  if (c.margin > 0) t += "; margin " + hnum(c.margin) + " * scale";
  if (*c.normal) t += std::string("; normal: ") + c.normal;
  if (*c.truth) t += std::string("; truth: ") + c.truth;
  t += "; precision: " + report::precision_text(c.precision) + " (the bounds below derive from it)";
  return t;
}


/// The claims as JSON.
Json claims_json(const QueryReport& r) {
  const Claims& c = r.claims;
  return {{"subject", r.subject}, {"own", r.own_claims}, {"exact_verdict", c.exact_verdict},
          {"depth", to_string(c.depth)}, {"point_in_both", c.point_in_both},
          {"touching_is_contact", c.touching_is_contact}, {"margin", json_num(c.margin)}, {"normal", c.normal},
          {"truth", c.truth}};
}

// A query's section: its verdicts, errors, depth ratio, failures, drawings.
void write_query_section(std::ostream& h, QueryReport& r, const std::filesystem::path& report_dir) {
  const bool clean = r.beyond == 0 && r.check_failures == 0;
  // FCL's column only where FCL was asked (a campaign's first cases); the
  // subject's column under its own name.
  const bool fcl = fcl_asked(r);
  auto row = [&](const std::string& label, const std::string& mine, const std::string& theirs = "") {
    h << "<tr><td class='l'>" << label << "</td>" << mine;
    if (fcl) h << "<td>" << theirs << "</td>";
    h << "</tr>";
  };
  auto cell = [](const std::string& text, const char* cls = nullptr) {
    return std::string("<td") + (cls ? std::string(" class='") + cls + "'" : std::string()) + ">" + text + "</td>";
  };
  auto num = [](double x) {
    std::ostringstream o;
    o << hnum(x);
    return o.str();
  };
  h << "<h2 id='" << r.name << "'>" << r.name << "</h2><p>" << html(r.summary) << "</p><p class='claims'>"
    << html(claims_text(r)) << "</p><p class='"
    << (clean ? "ok'>verified: no disagreement beyond the band, every property holds" : "bad'>FAILURES found")
    << "</p><table><tr><th class='l'>measure</th><th>" << html(r.subject) << "</th>" << (fcl ? "<th>FCL</th>" : "")
    << "</tr>";
  row("cases run of requested (valid)",
      cell(std::to_string(r.cases) + " of " + std::to_string(r.requested) + " (" + std::to_string(r.valid) + ")" +
           (r.stopped_by_time ? "; stopped by --seconds" : "") +
           (r.not_expressed ? "; " + std::to_string(r.not_expressed) + " not stated by the subject" : "")),
      std::to_string(r.fcl_ok) + " answered");
  row("hit rate (oracle " + num(r.valid ? double(r.truth_hits) / r.valid : NAN) + ")",
      cell(num(r.valid ? double(r.prod_hits) / r.valid : NAN)));
  row("verdict disagreements", cell(std::to_string(r.disagree)), std::to_string(r.fcl_disagree));
  h << "<tr><td class='l'>beyond the band (" << hnum(r.tol.verdict) << " &times; scale)</td><td class='"
    << (r.beyond ? "bad" : "ok") << "'>" << r.beyond << "</td>";
  if (fcl) h << "<td class='" << (r.fcl_beyond ? "bad" : "ok") << "'>" << r.fcl_beyond << "</td>";
  h << "</tr>";
  row("worst disagreement margin", cell(num(r.worst_margin)));
  row("cases failing a property", cell(std::to_string(r.check_failures), r.check_failures ? "bad" : "ok"));
  row(html(r.subject) + " time per query", cell(num(r.prod_ns) + " ns"));
  row("oracle+checks time per case",
      cell(num(r.oracle_us) + " &micro;s (" + num(r.oracle_us > 0 ? 1e6 / r.oracle_us : NAN) + " cases/s per core)"));
  h << "</table><table><tr><th class='l'>verdict</th><th>cases</th></tr>";
  for (const auto& [k, v] : r.verdicts) h << "<tr><td class='l'>" << k << "</td><td>" << v << "</td></tr>";
  if (!r.truth_stages.empty()) {
    h << "</table><table><tr><th class='l'>truth decided by</th><th>cases</th><th>share</th></tr>";
    int n = 0;
    for (const auto& kv : r.truth_stages) n += kv.second;
    for (const auto& [k, v] : r.truth_stages)
      h << "<tr><td class='l'>" << k << "</td><td>" << v << "</td><td>" << hnum(n ? double(v) / n : NAN) << "</td></tr>";
  }
  h << "</table><table><tr><th class='l'>error / scale</th><th>bound</th><th>n</th><th>p50</th><th>p90</th><th>p99</th><th>max</th><th>log10 histogram</th></tr>";
  error_row(h, "depth", r.depth, r.tol.depth);
  error_row(h, "normal", r.normal, r.tol.normal);
  error_row(h, "point", r.point, r.tol.point);
  error_row(h, "t", r.t, r.tol.t);
  if (fcl) {
    error_row(h, "FCL depth", r.fcl_depth, 0);
    error_row(h, "FCL normal", r.fcl_normal, 0);
    error_row(h, "FCL point", r.fcl_point, 0);
    error_row(h, "FCL distance", r.fcl_distance, 0);
    error_row(h, "FCL t", r.fcl_t_gap, 0);
    error_row(h, "FCL |t - t_exact| (absolute; sweeps: the first 10,000 cases)", r.fcl_t, 0);
  }
  h << "</table>";
  if (r.depth_is_bound) {
    // The depth is the overlap along the returned normal, not the minimal
    // translation: how much larger than the penetration depth it is.
    Series& q = r.depth_ratio;
    h << "<table><tr><th class='l'>depth / penetration depth</th><th>n</th><th>min</th><th>p50</th><th>p90</th>"
         "<th>p99</th><th>max</th></tr><tr><td class='l'>"
      << html(r.subject) << " (overlapping cases, penetration depth certified to 1%)</td><td>"
      << q.v.size() << "</td><td>" << hnum(q.pct(0.0)) << "</td><td>" << hnum(q.pct(0.5)) << "</td><td>"
      << hnum(q.pct(0.9)) << "</td><td>" << hnum(q.pct(0.99)) << "</td><td>" << hnum(q.pct(1.0))
      << "</td></tr></table><p>The contact's depth is the overlap of the shapes along its normal, an upper bound "
         "of the penetration depth (1 where the normal is a minimal direction); only a depth below the "
         "penetration depth is an error (the <b>depth</b> row above).</p>";
  }
  if (!r.failures_by_property.empty()) {
    h << "<h3>failures</h3><ul>";
    for (const auto& [k, v] : r.failures_by_property) h << "<li>" << html(k) << ": " << v << "</li>";
    h << "</ul><table><tr><th class='l'>kind of failure (property @ generator mode)</th><th>cases</th></tr>";
    for (const auto& [k, v] : r.failures_by_signature)
      h << "<tr><td class='l'>" << html(k) << "</td><td>" << v << "</td></tr>";
    h << "</table><p>counterexamples (at most " << kMaxSavedPerSignature << " of a kind and " << kMaxSavedPerKind
      << " of a property saved, " << r.shrunk << " of them shrunk while they fail the same property; replay with <code>"
      << html(replay_prefix(r)) << "FILE</code>; each links to its drawing):</p><ul>";
    for (std::size_t k = 0; k < r.counterexamples.size() && k < 50; ++k)
      h << "<li><a href='" << html(page_link(r.counterexamples[k], report_dir)) << "'><code>"
        << html(r.counterexamples[k]) << "</code></a></li>";
    if (r.counterexamples.size() > 50)
      h << "<li>and " << r.counterexamples.size() - 50 << " more under <code>counterexamples/" << r.name << "/</code></li>";
    h << "</ul><h3>counterexamples drawn (first " << r.drawings.size() << " of " << r.counterexamples.size() << ")</h3>";
    for (const auto& d : r.drawings) h << d;
  }
  if (!r.fcl_by_signature.empty()) {
    int all = 0;
    for (const auto& [k, v] : r.fcl_by_signature) all += v;
    h << "<h3>FCL's disagreements beyond the band</h3><table><tr><th class='l'>kind of disagreement (kind @ generator "
         "mode)</th><th>cases</th></tr>";
    for (const auto& [k, v] : r.fcl_by_signature)
      h << "<tr><td class='l'>" << html(k) << "</td><td>" << v << "</td></tr>";
    h << "</table><p>" << r.fcl_cases.size() << " of " << all << " saved under <code>fcl-disagreements/" << r.name
      << "/</code> (at most " << kMaxSavedPerSignature << " of a kind and generator mode, " << kMaxSavedPerKind
      << " of a kind), " << r.fcl_shrunk
      << " of them shrunk while FCL disagrees the same way; replay with <code>geomcheck replay DIR</code>, "
         "which shows production's answer and the truth; the drawings show FCL's.</p>";
    h << "<h3>FCL's disagreements drawn (" << r.fcl_drawings.size() << " of " << r.fcl_cases.size() << ")</h3>";
    for (const auto& d : r.fcl_drawings) h << d;
  }
}

/// An engine's row of a query in report.json (QueryReport::peers).
Json peer_json(QueryReport& p) {
  auto count = [&](const char* property) {
    const auto it = p.failures_by_property.find(property);
    return it == p.failures_by_property.end() ? 0 : it->second;
  };
  return {{"engine", p.subject}, {"claims", claims_json(p)}, {"cases", p.cases},
          {"not_expressed", p.not_expressed}, {"valid", p.valid},
          {"disagreements", p.disagree}, {"beyond_band", p.beyond}, {"check_failures", p.check_failures},
          {"failures_by_property", p.failures_by_property},
          {"failures_by_signature", p.failures_by_signature}, {"shrunk", p.shrunk}, {"hung", count("subject-hung")},
          {"crashed", count("subject-crashed")}, {"threw", count("subject-threw")},
          {"errors", {{"depth", series_json(p.depth)}, {"normal", series_json(p.normal)},
                      {"point", series_json(p.point)}, {"t", series_json(p.t)}}},
          {"ns_per_call", json_num(p.prod_ns)}, {"counterexamples", p.counterexamples},
          {"bugreports", {{"cases", p.bugreports}, {"failed", p.bugreports_failed}}}};
}

/// A query's entry in report.json.
Json query_json(QueryReport& r) {
  Json q = {{"id", r.name}, {"summary", r.summary}, {"claims", claims_json(r)}, {"requested", r.requested},
            {"stopped_by_time", r.stopped_by_time}, {"cases", r.cases}, {"valid", r.valid},
            {"subject_hits", r.prod_hits}, {"oracle_hits", r.truth_hits},
            {"hit_rate", json_num(r.valid ? double(r.prod_hits) / r.valid : NAN)}, {"verdicts", r.verdicts},
            {"disagreements", r.disagree}, {"inside_band", r.excused}, {"beyond_band", r.beyond},
            {"worst_margin", json_num(r.worst_margin)}, {"verdict_band", json_num(r.tol.verdict)},
            {"check_failures", r.check_failures}, {"failures_by_property", r.failures_by_property},
            {"failures_by_signature", r.failures_by_signature}, {"shrunk", r.shrunk},
            {"errors", {{"depth", series_json(r.depth)}, {"normal", series_json(r.normal)},
                        {"point", series_json(r.point)}, {"t", series_json(r.t)}}}};
  if (r.depth_is_bound) q["depth_over_penetration_depth"] = percentiles_json(r.depth_ratio, true);
  q["fcl"] = {{"supported", r.fcl_supported}, {"answered", r.fcl_ok}, {"disagreements", r.fcl_disagree},
              {"beyond_band", r.fcl_beyond}, {"depth", series_json(r.fcl_depth)},
              {"normal", series_json(r.fcl_normal)}, {"point", series_json(r.fcl_point)},
              {"t", series_json(r.fcl_t_gap)}, {"t_abs", series_json(r.fcl_t)},
              {"distance_asked", r.fcl_distance_asked}, {"distance_verdicts_beyond_band", r.fcl_distance_beyond},
              {"distance", series_json(r.fcl_distance)}, {"by_signature", r.fcl_by_signature},
              {"shrunk", r.fcl_shrunk}, {"cases", r.fcl_cases}};
  q["subject_ns_per_query"] = json_num(r.prod_ns);
  q["oracle_us_per_case"] = json_num(r.oracle_us);
  q["cases_per_second_per_core"] = json_num(r.oracle_us > 0 ? 1e6 / r.oracle_us : NAN);
  q["truth_stages"] = r.truth_stages;
  q["counterexamples"] = r.counterexamples;
  q["peers"] = Json::array();
  for (QueryReport& p : r.peers) q["peers"].push_back(peer_json(p));
  for (QueryReport& f : r.first)
    q["same_cases"] = {
        {"cases", f.cases},
        {"production", {{"valid", f.valid}, {"beyond_band", f.beyond}, {"check_failures", f.check_failures},
                        {"failures_by_property", f.failures_by_property},
                        {"errors", {{"depth", series_json(f.depth)}, {"normal", series_json(f.normal)},
                                    {"point", series_json(f.point)}, {"t", series_json(f.t)}}}}},
        {"fcl", {{"answered", f.fcl_ok}, {"beyond_band", f.fcl_beyond},
                 {"distance_asked", f.fcl_distance_asked}, {"distance_verdicts_beyond_band", f.fcl_distance_beyond},
                 {"errors", {{"depth", series_json(f.fcl_depth)}, {"normal", series_json(f.fcl_normal)},
                             {"point", series_json(f.fcl_point)}, {"distance", series_json(f.fcl_distance)},
                             {"t", series_json(f.fcl_t_gap)}}}}}};
  return q;
}

/// A point-set query's entry in report.json.
Json point_set_json(const PointSetReport& r) {
  return {{"id", r.name}, {"summary", r.summary}, {"subject", r.subject}, {"requested", r.requested},
          {"stopped_by_time", r.stopped_by_time}, {"not_asked", r.not_asked}, {"sets", r.sets}, {"points", r.points}, {"failures", r.failures}, {"modes", r.modes}, {"kinds", r.kinds},
          {"failures_by_property", r.failures_by_property}, {"cgal_choices_differ", r.cgal_choices_differ},
          {"production_us_total", json_num(r.production_us)}, {"cgal_us_total", json_num(r.cgal_us)},
          {"production_over_cgal", json_num(r.cgal_us > 0 ? r.production_us / r.cgal_us : NAN)},
          {"counterexamples", r.counterexamples}};
}

// A point-set query's section: the sets by mode and kind, failures, time against CGAL.
void write_point_set_section(std::ostream& h, const PointSetReport& r) {
  const bool clean = r.failures == 0;
  h << "<h2 id='" << r.name << "'>" << r.name << "</h2><p>" << html(r.summary) << "</p><p class='"
    << (clean ? "ok'>verified: every triangulation valid (exact checker) and CGAL's up to cocircular choices"
              : "bad'>FAILURES found")
    << "</p><p>subject: " << html(r.subject)
    << "</p><table><tr><th class='l'>measure</th><th>value</th></tr><tr><td class='l'>point sets run of requested (points)</td><td>"
    << r.sets << " of " << r.requested << " (" << r.points << ")" << (r.stopped_by_time ? "; stopped by --seconds" : "")
    << (r.not_asked ? "; " + std::to_string(r.not_asked) + " not asked (non-finite; the subject claims finite input)" : std::string())
    << "</td></tr><tr><td class='l'>failures</td><td class='" << (clean ? "ok" : "bad") << "'>"
    << r.failures << "</td></tr><tr><td class='l'>cocircular choices other than CGAL's (legitimate)</td><td>"
    << r.cgal_choices_differ << "</td></tr><tr><td class='l'>time, " << html(r.subject) << " / CGAL (all sets)</td><td>"
    << hnum(r.production_us / 1e3) << " ms / " << hnum(r.cgal_us / 1e3) << " ms = "
    << hnum(r.cgal_us > 0 ? r.production_us / r.cgal_us : NAN) << "</td></tr></table>";
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

/// The command that replays a mesh query's saved case, but for its path:
/// a known-wrong variant's cases replay against it.
std::string mesh_replay_prefix(const MeshReport& r) {
  return "geomcheck replay " + (r.under_test == "production" ? std::string() : "--subject " + r.under_test + " ");
}

/// A mesh query's entry in report.json.
Json mesh_json(const MeshReport& r) {
  return {{"id", r.name}, {"summary", r.summary}, {"implementation", r.under_test}, {"requested", r.requested},
          {"stopped_by_time", r.stopped_by_time}, {"meshes", r.meshes}, {"faces", r.faces}, {"failures", r.failures},
          {"modes", r.modes}, {"verdicts", r.verdicts}, {"failures_by_property", r.failures_by_property},
          {"faces_by_box", r.faces_by_box}, {"faces_by_engine", r.faces_by_engine},
          {"seconds", json_num(r.seconds)},
          {"meshes_per_second", json_num(r.seconds > 0 ? r.meshes / r.seconds : NAN)},
          {"production_us_total", json_num(r.production_us)}, {"brute_force_us_total", json_num(r.brute_force_us)},
          {"brute_force_over_production", json_num(r.production_us > 0 ? r.brute_force_us / r.production_us : NAN)},
          {"counterexamples", r.counterexamples}};
}

// A mesh query's section: meshes by mode and verdict, failures with their
// drawings, how the truth was decided, time against the brute force.
void write_mesh_section(std::ostream& h, const MeshReport& r) {
  const bool clean = r.failures == 0;
  h << "<h2 id='" << r.name << "'>" << r.name << "</h2><p>" << html(r.summary) << "</p><p class='"
    << (clean ? "ok'>verified: every mesh's answer held to the certified engine face by face and to the deepest "
                "face (production: its brute force's and its triangle query's answers, bit for bit; a subject of its own: "
                "its claims)"
              : "bad'>FAILURES found")
    << " (" << html(r.under_test) << ")</p><table><tr><th class='l'>measure</th><th>value</th></tr>"
    << "<tr><td class='l'>meshes run of requested (faces)</td><td>" << r.meshes << " of " << r.requested << " ("
    << r.faces << ")" << (r.stopped_by_time ? "; stopped by --seconds" : "") << "</td></tr><tr><td class='l'>failures</td><td class='"
    << (clean ? "ok" : "bad") << "'>" << r.failures << "</td></tr><tr><td class='l'>meshes per second (checks, all threads)</td><td>"
    << hnum(r.seconds > 0 ? r.meshes / r.seconds : NAN)
    << "</td></tr><tr><td class='l'>faces separated by their boxes / decided by the engine</td><td>" << r.faces_by_box
    << " / " << r.faces_by_engine << "</td></tr><tr><td class='l'>time, production (hierarchy) / brute force</td><td>"
    << hnum(r.production_us / 1e3) << " ms / " << hnum(r.brute_force_us / 1e3) << " ms</td></tr></table>";
  auto table = [&](const char* what, const std::map<std::string, int>& m) {
    h << "<table><tr><th class='l'>" << what << "</th><th>meshes</th></tr>";
    for (const auto& [k, v] : m) h << "<tr><td class='l'>" << html(k) << "</td><td>" << v << "</td></tr>";
    h << "</table>";
  };
  table("generator mode", r.modes);
  table("exact verdict", r.verdicts);
  if (!r.failures_by_property.empty()) {
    table("failed property", r.failures_by_property);
    h << "<p>counterexamples (replay with <code>" << html(mesh_replay_prefix(r))
      << "FILE</code>; each drawn in a page beside it, FILE with .html for .case):</p><ul>";
    for (std::size_t k = 0; k < r.counterexamples.size() && k < 50; ++k)
      h << "<li><code>" << html(r.counterexamples[k]) << "</code></li>";
    h << "</ul>";
  }
}


/// A cell of the glance matrix: its state (ok, near: within its bounds but
/// past half of one, bad, none: not asked), its text and its link.
struct GlanceCell {
  std::string state = "none", text = "not asked", href;
};

/// The largest error of r's over its bound, across depth, normal, point and
/// t (NaN where no bounded error was measured).
double worst_over_bound(QueryReport& r) {
  double worst = NAN;
  const std::pair<Series*, double> errs[] = {{&r.depth, r.tol.depth}, {&r.normal, r.tol.normal},
                                             {&r.point, r.tol.point}, {&r.t, r.tol.t}};
  for (const auto& [s, bound] : errs)
    if (!s->v.empty() && bound > 0 && std::isfinite(bound))
      worst = std::isnan(worst) ? s->pct(1.0) / bound : std::max(worst, s->pct(1.0) / bound);
  return worst;
}

/// A subject's (or an engine's) cell: its verdicts beyond the band, its
/// property failures and its worst error against its bound.
GlanceCell subject_cell(QueryReport& r, const std::string& href) {
  if (r.cases == 0) return {"none", r.not_expressed ? "cannot state it" : "not asked", href};
  const double worst = worst_over_bound(r);
  const bool bad = r.beyond > 0 || r.check_failures > 0 || worst > 1;
  GlanceCell c;
  c.href = href;
  c.state = bad ? "bad" : (worst > 0.5 ? "near" : "ok");
  c.text = std::string(bad ? "\u2717 " : "\u2713 ") + std::to_string(r.beyond) + " beyond the band, " +
           std::to_string(r.check_failures) + " failing<br>worst error / bound: " +
           (std::isnan(worst) ? std::string("\u2013") : hnum(worst)) + "<br>" +
           std::to_string(r.valid) + " cases";
  return c;
}

/// The matrix at the top of the page: a row per query, a column per engine
/// (the subject, FCL where a campaign asked it, each engine of peers/), each
/// cell coloured by its verdicts beyond the band and its worst error against
/// its bound, and linked to the rows that detail it.
void write_glance(std::ostream& h, std::vector<QueryReport>& reps, const std::vector<PointSetReport>& point_sets,
                  const std::vector<MeshReport>& meshes) {
  bool any_fcl = false;
  std::vector<std::string> engines;
  for (QueryReport& r : reps) {
    any_fcl |= fcl_asked(r);
    for (const QueryReport& p : r.peers)
      if (std::find(engines.begin(), engines.end(), p.subject) == engines.end()) engines.push_back(p.subject);
  }
  std::string subject = "subject";
  if (!reps.empty()) subject = reps.front().subject;
  for (const QueryReport& r : reps)
    if (r.subject != subject) subject = "subject";
  h << "<h2 id='glance'>At a glance</h2><table class='glance'><tr><th class='l'>query</th><th>" << html(subject)
    << "</th>" << (any_fcl ? "<th>FCL</th>" : "");
  for (const std::string& e : engines) h << "<th>" << html(e) << "</th>";
  h << "</tr>";
  const std::size_t columns = 1 + (any_fcl ? 1 : 0) + engines.size();
  auto cell = [&](const GlanceCell& c) {
    h << "<td class='g " << c.state << "' data-state='" << c.state << "'>"
      << (c.href.empty() ? c.text : "<a href='#" + c.href + "'>" + c.text + "</a>") << "</td>";
  };
  for (QueryReport& r : reps) {
    h << "<tr><td class='l'><a href='#" << r.name << "'>" << r.name << "</a></td>";
    cell(subject_cell(r, r.name));
    if (any_fcl) {
      GlanceCell c{"none", "not asked", r.name};
      if (fcl_asked(r)) {
        const int beyond = r.fcl_beyond + r.fcl_distance_beyond;
        c.state = beyond ? "bad" : "ok";
        c.text = std::string(beyond ? "\u2717 " : "\u2713 ") + std::to_string(beyond) +
                 " beyond the band<br>(FCL states no bounds)<br>" + std::to_string(r.fcl_ok) + " answered";
      }
      cell(c);
    }
    for (const std::string& e : engines) {
      auto p = std::find_if(r.peers.begin(), r.peers.end(), [&](const QueryReport& q) { return q.subject == e; });
      cell(p == r.peers.end() ? GlanceCell{} : subject_cell(*p, engine_anchor(r.name, e)));
    }
    h << "</tr>";
  }
  auto family_row = [&](const std::string& name, int failures, const std::string& what) {
    h << "<tr><td class='l'><a href='#" << name << "'>" << name << "</a></td>";
    cell({failures ? "bad" : "ok", std::string(failures ? "\u2717 " : "\u2713 ") + std::to_string(failures) +
                                       " failing<br>" + what, name});
    for (std::size_t k = 1; k < columns; ++k) cell({});
    h << "</tr>";
  };
  for (const PointSetReport& r : point_sets) family_row(r.name, r.failures, std::to_string(r.sets) + " point sets");
  for (const MeshReport& r : meshes) family_row(r.name, r.failures, std::to_string(r.meshes) + " meshes");
  h << "</table><p class='legend'><span class='g ok'>&nbsp;\u2713&nbsp;</span> no verdict beyond the band, every "
       "property holds, every error within half its bound; <span class='g near'>&nbsp;\u2713&nbsp;</span> the same "
       "but an error past half its bound; <span class='g bad'>&nbsp;\u2717&nbsp;</span> a verdict beyond the band, "
       "a failing property or an error over its bound; <span class='g none'>&nbsp;&nbsp;&nbsp;</span> not asked. "
       "Each cell links to its rows below.</p>";
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

std::string readable_numbers(const std::string& text) {
  auto word = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.'; };
  std::string out;
  std::size_t i = 0;
  while (i < text.size()) {
    const bool sign = text[i] == '-' && i + 1 < text.size() && std::isdigit(static_cast<unsigned char>(text[i + 1]));
    if ((sign || std::isdigit(static_cast<unsigned char>(text[i]))) && (i == 0 || !word(text[i - 1]))) {
      char* end = nullptr;
      const double x = std::strtod(text.c_str() + i, &end);
      const std::size_t n = static_cast<std::size_t>(end - (text.c_str() + i));
      const std::string token = text.substr(i, n);
      const std::size_t e = token.find_first_of("eE");
      const bool alone = i + n == text.size() || !word(text[i + n]) || text[i + n] == '.';
      if (n > 0 && e != std::string::npos && alone && token.find_first_of("xX") == std::string::npos) {
        int digits = 0;
        for (std::size_t k = 0; k < e; ++k) digits += std::isdigit(static_cast<unsigned char>(token[k])) ? 1 : 0;
        out += readable(x, std::max(1, digits));
        i += n;
        continue;
      }
      out += text.substr(i, std::max<std::size_t>(n, 1));
      i += std::max<std::size_t>(n, 1);
      continue;
    }
    out += text[i++];
  }
  return out;
}

std::string readable(double x, int digits) {
  if (std::isnan(x)) return "\u2013";
  if (std::isinf(x)) return x > 0 ? "\u221e" : "-\u221e";
  if (x == 0) return "0";
  digits = std::clamp(digits, 1, 17);
  auto trim = [](std::string t) {  // "2.500" -> "2.5", "3.0" -> "3"
    if (t.find('.') == std::string::npos) return t;
    while (t.back() == '0') t.pop_back();
    if (t.back() == '.') t.pop_back();
    return t;
  };
  char b[64];
  const double a = std::fabs(x);
  if (a >= 1e-3 && a < 1e6) {
    const int e = static_cast<int>(std::floor(std::log10(a)));
    std::snprintf(b, sizeof b, "%.*f", std::max(0, digits - 1 - e), x);
    std::string t = trim(b);
    if (std::fabs(std::strtod(b, nullptr)) < 1e6) return t;  // else it rounded up to a million: below
  }
  std::snprintf(b, sizeof b, "%.*e", digits - 1, x);  // "-2.50e-09"
  const double rounded = std::fabs(std::strtod(b, nullptr));
  if (rounded >= 1e-3 && rounded < 1e6) return readable(std::strtod(b, nullptr), digits);  // 0.00099999 -> 0.001
  const std::string t = b;
  const std::size_t at = t.find('e');
  const int exponent = std::atoi(t.c_str() + at + 1);
  static const char* const kSup[] = {"\u2070", "\u00b9", "\u00b2", "\u00b3", "\u2074",
                                     "\u2075", "\u2076", "\u2077", "\u2078", "\u2079"};
  std::string sup = exponent < 0 ? "\u207b" : "";
  for (char c : std::to_string(std::abs(exponent))) sup += kSup[c - '0'];
  const std::string mantissa = trim(t.substr(0, at));
  return mantissa + "\u00d710" + sup;
}


void write_json(const std::filesystem::path& file, const RunInfo& run, std::vector<QueryReport>& reps,
                const std::vector<PointSetReport>& point_sets, const std::vector<MeshReport>& meshes) {
  bool passed = true;
  for (const QueryReport& r : reps) passed = passed && r.beyond == 0 && r.check_failures == 0;
  for (const PointSetReport& r : point_sets) passed = passed && r.failures == 0;
  for (const MeshReport& r : meshes) passed = passed && r.failures == 0;
  Json report = {{"tool", "geomcheck"}, {"schema_version", kReportSchemaVersion}, {"version", run.version},
                 {"started", run.started}, {"command_line", run.command}, {"verdict", passed ? "passed" : "failed"},
                 {"seed", run.seed}, {"cases_per_query", run.per_query}, {"saved_cases_per_kind", kMaxSavedPerKind},
                 {"saved_cases_per_signature", kMaxSavedPerSignature},
                 {"replay", run.rerun}, {"implementation", run.under_test}, {"queries", Json::array()}};
  for (QueryReport& r : reps) report["queries"].push_back(query_json(r));
  // The point-set queries follow the pair queries (absent when none ran).
  if (!point_sets.empty()) {
    Json& sets = report["point_set_queries"] = Json::array();
    for (const PointSetReport& r : point_sets) sets.push_back(point_set_json(r));
  }
  if (!meshes.empty()) {
    Json& m = report["mesh_queries"] = Json::array();
    for (const MeshReport& r : meshes) m.push_back(mesh_json(r));
  }
  // Text that is not UTF-8 (a path, say) is written with U+FFFD in its place, not thrown on.
  std::ofstream js(file);
  js << report.dump(2, ' ', false, Json::error_handler_t::replace) << '\n';
}

void write_html(const std::filesystem::path& file, const RunInfo& run, std::vector<QueryReport>& reps,
                const std::vector<PointSetReport>& point_sets, const std::vector<MeshReport>& meshes) {
  std::ofstream h(file);
  h << "<!doctype html><html lang='en'><head><meta charset='utf-8'><title>geomcheck campaign report</title>"
       "<style>body{font-family:sans-serif;margin:2em;max-width:1100px}table{border-collapse:collapse;margin:1em 0}"
       "td,th{border:1px solid #bbb;padding:4px 8px;text-align:right}th{background:#eee}td.l,th.l{text-align:left}"
       ".bad{color:#b00;font-weight:bold}.ok{color:#070}.claims{font-size:13px;color:#444}figure.cx{margin:1em 0;border-top:1px solid #ddd}"
       "figure.cx svg{margin-right:6px}figcaption{font-size:12px;margin:4px 0;word-break:break-all}"
       ".legend{font-size:12px;margin:2px 0}td.g{text-align:left;font-size:12px}td.g a{color:inherit;text-decoration:none}"
       ".g.ok{background:#dff0d8}.g.near{background:#fcf3cf}.g.bad{background:#f5c6c6;color:#800}.g.none{background:#eee;color:#777}</style></head><body>"
       "<h1>geomcheck campaign report</h1><p>seed <code>"
    << run.seed << "</code>, " << html(run.per_query) << ", implementation under test: <b>" << html(run.under_test)
    << "</b>. Errors are multiples of the case scale "
       "(largest coordinate magnitude or extent). Rerun: <code>" << html(run.rerun) << "</code></p>";
  write_glance(h, reps, point_sets, meshes);
  write_precision_table(h, reps);
  for (QueryReport& r : reps) write_query_section(h, r, file.parent_path());
  for (const PointSetReport& r : point_sets) write_point_set_section(h, r);
  for (const MeshReport& r : meshes) write_mesh_section(h, r);
  h << "</body></html>\n";
}

namespace {

/// s for XML text or an attribute: html()'s escapes, quotes too, and control
/// characters other than a newline as spaces.
std::string xml(const std::string& s) {
  std::string o;
  for (char c : html(s)) {
    if (c == '"') o += "&quot;";
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
                 const std::vector<PointSetReport>& point_sets, const std::vector<MeshReport>& meshes) {
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
  for (const MeshReport& r : meshes)
    for (const char* family : {"robust", "consistency", "bvh-equals-brute-force", "symmetry", "deepest-face", "oracle"}) {
      JunitCase c{r.name + "." + family, 0, ""};
      for (const auto& [prop, n] : r.failures_by_property)
        if (prop.rfind(family, 0) == 0) c.failures += n, c.message += prop + ": " + std::to_string(n) + "\n";
      if (c.failures) {
        for (const std::string& cx : r.counterexamples)
          if (std::filesystem::path(cx).filename().string().find("-" + std::string(family)) != std::string::npos) {
            c.message += "replay: " + mesh_replay_prefix(r) + cx + "\n";
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
