#include "campaign.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <mutex>
#include <sstream>
#include <thread>
#include <type_traits>

#include <unistd.h>

#include "draw.hpp"
#include "generators.hpp"
#include "geomcheck/casefile.hpp"
#include "geomcheck/properties/tolerances.hpp"
#include "peer.hpp"
#include "suites.hpp"
#include "teeth_variants.hpp"

namespace geomcheck {

namespace {

using Clock = std::chrono::steady_clock;

// Everything kept per case.
struct Row {
  Evaluation e;
  PeerAnswer fcl;
  std::string tag;
  CheckResult failure;
  int index = 0;
  bool run = false;
};

struct Series {
  std::vector<double> v;
  void add(double x) {
    if (std::isfinite(x)) v.push_back(x);
  }
  double pct(double p) {
    if (v.empty()) return NAN;
    std::sort(v.begin(), v.end());
    return v[std::min(v.size() - 1, static_cast<std::size_t>(p * (v.size() - 1) + 0.5))];
  }
  // Histogram of log10(error / scale), buckets -18..-4 plus "0".
  std::vector<int> hist() const {
    std::vector<int> h(16, 0);
    for (double x : v) {
      if (x <= 0) { ++h[0]; continue; }
      int b = static_cast<int>(std::floor(std::log10(x))) + 19;  // 1e-18 -> bucket 1
      h[std::clamp(b, 1, 15)]++;
    }
    return h;
  }
};

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

struct QueryReport {
  std::string name, summary;
  int cases = 0, valid = 0, prod_hits = 0, truth_hits = 0;
  std::map<std::string, int> verdicts;
  int disagree = 0, excused = 0, beyond = 0, check_failures = 0;
  double worst_margin = 0;
  Series depth, normal, point, t;
  int fcl_supported = 0, fcl_ok = 0, fcl_disagree = 0, fcl_beyond = 0;
  Series fcl_depth, fcl_normal, fcl_point;  // the yardsticks of production's depth, normal, point
  Series fcl_t_gap;  // production's t yardstick (the gap at FCL's t)
  Series fcl_t;  // |t_FCL - t_exact| (absolute, t in [0, 1])
  Series fcl_distance;  // |FCL distance - certified distance| on separated pairs FCL calls separated
  int fcl_distance_asked = 0, fcl_distance_beyond = 0;  // distance's verdict (< 0: meet) beyond the band
  std::vector<std::string> fcl_cases;  // FCL disagreements beyond the band, saved (all of them)
  std::map<std::string, int> fcl_drawn;  // per kind of disagreement (the first 3 of each are drawn)
  double prod_ns = NAN, oracle_us = NAN;
  std::vector<std::string> counterexamples;
  std::vector<std::string> drawings;      // production's counterexamples, drawn (first 12)
  std::vector<std::string> fcl_drawings;  // FCL's disagreements beyond the band, drawn (the first 3 of each kind)
  std::map<std::string, int> failures_by_property;
  Tolerances tol{};
  // Queries whose depth is an upper bound, not the penetration depth
  // (collide_cylinder_cylinder): depth / certified penetration depth over
  // the overlapping cases where the engine encloses it within 1%.
  bool depth_is_bound = false;
  Series depth_ratio;
};

// The known-wrong variants per implementation type.
std::vector<const CylinderSphereImpl*> variants_of(const CylinderSphereImpl*) { return {&teeth::kCapsuleForCylinder}; }
std::vector<const CastSegmentCylinderImpl*> variants_of(const CastSegmentCylinderImpl*) {
  return {&teeth::kInfiniteCylinder, &teeth::kEricsonPrinted};
}
std::vector<const CylinderCapsuleImpl*> variants_of(const CylinderCapsuleImpl*) { return {&teeth::kCapsuleCapsule}; }
std::vector<const SweepSphereCylinderImpl*> variants_of(const SweepSphereCylinderImpl*) {
  return {&teeth::kSweepNoCornerStage, &teeth::kSweepTalkRimPoint};
}
std::vector<const CylinderObbImpl*> variants_of(const CylinderObbImpl*) { return {&teeth::kBoxAsCapsule, &teeth::kBoxTalkRays}; }
std::vector<const CylinderTriangleImpl*> variants_of(const CylinderTriangleImpl*) { return {&teeth::kTriangleNoCapStage}; }
std::vector<const CylinderCylinderImpl*> variants_of(const CylinderCylinderImpl*) { return {}; }

// An implementation's answer, drawn in red.
template <class Case, class Impl>
draw::Answer answer_of(const Case& c, const Impl& impl) {
  if constexpr (std::is_same_v<Case, SegmentCylinderCase>) return draw::answer_of(impl.cast(c.a, c.b), impl.name);
  else if constexpr (std::is_same_v<Case, SweepCylinderCase>) return draw::answer_of(impl.sweep(c.a, c.b), impl.name);
  else return draw::answer_of(impl.collide(c.a, c.b), impl.name);
}

// FCL's answer, drawn beside production's (purple).
template <class Case>
draw::Mark fcl_mark(const Case& c, const PeerAnswer& p) {
  constexpr const char* kColour = "#83c";
  const Vec3 nowhere{NAN, NAN, NAN};
  char b[96];
  if (!p.hit) return {draw::Mark::Kind::PointNormal, nowhere, Vec3{}, 0, kColour, "FCL: " + html(p.text)};
  if constexpr (std::is_same_v<Case, SegmentCylinderCase>) {
    std::snprintf(b, sizeof b, "FCL: hit at t = %.6g (S(t); FCL gives no point)", p.t);
    return {draw::Mark::Kind::PointNormal, c.a.a + p.t * (c.a.b - c.a.a), Vec3{}, 0, kColour, b};
  } else if constexpr (std::is_same_v<Case, SweepCylinderCase>) {
    std::snprintf(b, sizeof b, "FCL: hit at t = %.6g (the ball then)", p.t);
    return {draw::Mark::Kind::Ball, c.a.c + p.t * c.a.delta, Vec3{}, c.a.r, kColour, b};
  } else {
    std::snprintf(b, sizeof b, "FCL: contact, depth %.6g (point and normal)", p.contact.depth);
    return {draw::Mark::Kind::PointNormal, p.contact.point, p.contact.normal, 0, kColour, b};
  }
}

template <QueryId Q>
QueryReport run_query(const CampaignOptions& opt, const std::filesystem::path& out_dir, int threads) {
  using Case = typename Suite<Q>::Case;
  using Impl = typename Suite<Q>::Impl;
  const Impl* impl = &production(Case{});
  for (const Impl* v : variants_of(impl))
    if (opt.variant == v->name) impl = v;
  QueryReport rep;
  rep.name = info(Q).name;
  rep.summary = info(Q).summary;
  rep.tol = tolerances(Q);
  rep.depth_is_bound = Q == QueryId::collide_cylinder_cylinder;
  // Cases are generated in order from the seed (deterministic), then
  // evaluated in parallel.
  std::vector<std::pair<Case, std::string>> cases;
  const auto gen = Suite<Q>::targeted();
  rc::Random random(opt.seed ^ (0x9e3779b97f4a7c15ull * (static_cast<std::uint64_t>(Q) + 1)));
  for (int i = 0, n = campaign_cases(opt, info(Q).name); i < n; ++i) cases.push_back(gen(random.split(), 50).value());

  // Production throughput on these cases.
  {
    const auto t0 = Clock::now();
    int sink = 0;
    const int reps = 5;
    for (int r = 0; r < reps; ++r)
      for (const auto& c : cases) sink += Suite<Q>::hit(c.first, *impl);
    const double ns = std::chrono::duration<double, std::nano>(Clock::now() - t0).count();
    rep.prod_ns = ns / (reps * std::max<std::size_t>(1, cases.size()));
    if (sink == -1) std::puts("");
  }

  std::vector<Row> rows(cases.size());
  std::atomic<int> next{0}, done{0};
  const auto start = Clock::now();
  std::atomic<bool> out_of_time{false};
  auto worker = [&] {
    for (;;) {
      const int i = next++;
      if (i >= static_cast<int>(cases.size())) return;
      if (opt.seconds > 0 && std::chrono::duration<double>(Clock::now() - start).count() > opt.seconds) {
        out_of_time = true;
        return;
      }
      Row& r = rows[i];
      r.index = i;
      r.tag = cases[i].second;
      r.fcl = peer(cases[i].first);
      r.e = evaluate_with_peer(cases[i].first, r.fcl, *impl);
      r.failure = check_all(cases[i].first, *impl);
      r.run = true;
      ++done;
    }
  };
  std::vector<std::thread> pool;
  for (int k = 0; k < threads; ++k) pool.emplace_back(worker);
  // On a terminal the progress line is redrawn every 0.5 s; into a log file
  // (CI) a plain line every 10 s, so that the log stays readable.
  const bool tty = isatty(fileno(stderr));
  const int every = tty ? 1 : 20;
  for (int tick = 1; opt.progress; ++tick) {
    std::this_thread::sleep_for(std::chrono::milliseconds(500));
    const int d = done;
    const bool last = d >= static_cast<int>(cases.size()) || out_of_time;
    if (tick % every == 0 || last) {
      const double el = std::chrono::duration<double>(Clock::now() - start).count();
      std::fprintf(stderr, "%s[campaign] %-24s %7d / %zu cases  %6.0f cases/s  %5.1fs%s", tty ? "\r" : "",
                   rep.name.c_str(), d, cases.size(), d / std::max(el, 1e-9), el, tty ? "" : "\n");
    }
    if (last) break;
  }
  for (auto& th : pool) th.join();
  const double elapsed = std::chrono::duration<double>(Clock::now() - start).count();
  if (opt.progress && tty) std::fprintf(stderr, "\n");

  const std::filesystem::path cx_dir = out_dir / "counterexamples" / rep.name;
  for (const Row& r : rows) {
    if (!r.run) continue;  // time budget ran out first
    const Evaluation& e = r.e;
    ++rep.cases;
    if (!e.valid) continue;
    ++rep.valid;
    rep.prod_hits += e.prod_hit;
    rep.truth_hits += e.truth_hit;
    rep.verdicts[verdict_word(Q, e)]++;
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
    if (r.fcl.supported) {
      ++rep.fcl_supported;
      if (r.fcl.ok) {
        ++rep.fcl_ok;
        // Every FCL disagreement beyond the band is saved as a case file;
        // the first few of each kind are drawn.
        auto save_fcl = [&](const char* kind, const std::string& answer) {
          const std::filesystem::path dir = out_dir / "fcl-disagreements" / rep.name;
          std::filesystem::create_directories(dir);
          char name[80];
          std::snprintf(name, sizeof name, "%05d-fcl-%s.case", r.index, kind);
          CaseFile f = from_case<Q>(cases[r.index].first,
                                    "campaign seed=" + std::to_string(opt.seed) + " case=" + std::to_string(r.index),
                                    verdict_word(Q, e),
                                    "FCL: " + r.fcl.text + "; oracle: " + e.truth_text);
          std::string err;
          if (save_case(dir / name, f, err)) rep.fcl_cases.push_back((dir / name).string());
          else std::fprintf(stderr, "[campaign] cannot save %s: %s\n", (dir / name).string().c_str(), err.c_str());
          if (rep.fcl_drawn[kind]++ < 3) {
            const draw::Answer ans = answer_of(cases[r.index].first, *impl);
            rep.fcl_drawings.push_back(draw::views(
                cases[r.index].first.a, cases[r.index].first.b,
                html(std::string("case ") + name + ": " + answer + " (" + r.fcl.text + "); oracle: " + e.truth_text),
                {fcl_mark(cases[r.index].first, r.fcl)}, &ans));
          }
        };
        if (r.fcl.hit != e.truth_hit) {
          ++rep.fcl_disagree;
          if (!e.near_boundary) {  // the same band as production's
            ++rep.fcl_beyond;
            save_fcl(r.fcl.hit ? "false-hit" : "missed-hit", r.fcl.hit ? "FCL hit" : "FCL no hit");
          }
        }
        rep.fcl_depth.add(e.peer.depth_err);
        rep.fcl_normal.add(e.peer.normal_err);
        rep.fcl_point.add(e.peer.point_err);
        rep.fcl_t_gap.add(e.peer.t_err);
        if (r.fcl.hit && e.truth_hit && std::isfinite(r.fcl.t) && std::isfinite(e.t_true))
          rep.fcl_t.add(std::fabs(r.fcl.t - e.t_true));
        if (std::isfinite(r.fcl.distance)) {
          ++rep.fcl_distance_asked;
          if ((r.fcl.distance < 0) != e.truth_hit && !e.near_boundary) {
            ++rep.fcl_distance_beyond;
            save_fcl(r.fcl.distance < 0 ? "distance-says-meet" : "distance-says-apart",
                     r.fcl.distance < 0 ? "FCL's distance: they meet" : "FCL's distance: separated");
          }
          if (r.fcl.distance >= 0 && std::isfinite(e.distance))
            rep.fcl_distance.add(std::fabs(r.fcl.distance - e.distance) / e.scale);
        }
      }
    }
    if (r.failure) {
      ++rep.check_failures;
      rep.failures_by_property[r.failure->property]++;
      // Every counterexample is saved and drawn (a page beside its case
      // file); the report shows the first 12 drawings inline.
      std::filesystem::create_directories(cx_dir);
      char name[64];
      std::snprintf(name, sizeof name, "%05d-%s.case", r.index, r.failure->property.c_str());
      const auto path = cx_dir / name;
      CaseFile f = from_case<Q>(cases[r.index].first,
                                "campaign seed=" + std::to_string(opt.seed) + " case=" + std::to_string(r.index),
                                "", r.failure->property + ": " + r.failure->detail);
      f.oracle_verdict = verdict_word(Q, e);
      std::string err;
      if (save_case(path, f, err)) rep.counterexamples.push_back(path.string());
      else std::fprintf(stderr, "[campaign] cannot save %s: %s\n", path.string().c_str(), err.c_str());
      const draw::Answer ans = answer_of(cases[r.index].first, *impl);
      const std::string drawing = draw::views(cases[r.index].first.a, cases[r.index].first.b,
                                              html(std::string("case ") + name + ": " + r.failure->property + ": " +
                                                   r.failure->detail + "; oracle: " + e.truth_text),
                                              {}, &ans);
      std::ofstream page(std::filesystem::path(path).replace_extension(".html"));
      page << "<!doctype html><html lang='en'><head><meta charset='utf-8'><title>" << html(name)
           << "</title><style>body{font-family:sans-serif;margin:2em}figcaption{font-size:12px;margin:4px 0}"
              ".legend{font-size:12px}</style></head><body>"
           << drawing << "<p>" << html(impl->name) << " fails this case; <code>geomcheck replay " << html(path.string())
           << "</code> replays it against production.</p></body></html>\n";
      if (rep.drawings.size() < 12) rep.drawings.push_back(drawing);
    }
  }
  rep.oracle_us = rep.cases ? elapsed * 1e6 * threads / rep.cases : NAN;
  return rep;
}

void write_series_json(std::ostream& o, const char* name, Series& s) {
  o << "      " << jstr(name) << ": {\"n\": " << s.v.size() << ", \"p50\": " << jnum(s.pct(0.5))
    << ", \"p90\": " << jnum(s.pct(0.9)) << ", \"p99\": " << jnum(s.pct(0.99)) << ", \"max\": " << jnum(s.pct(1.0))
    << ", \"log10_histogram\": [";
  const auto h = s.hist();
  for (std::size_t i = 0; i < h.size(); ++i) o << (i ? ", " : "") << h[i];
  o << "]}";
}

std::string hist_svg(const Series& s) {
  const auto h = s.hist();
  const int mx = std::max(1, *std::max_element(h.begin(), h.end()));
  std::ostringstream o;
  o << "<svg width='330' height='70' role='img'><title>log10 histogram</title>";
  for (std::size_t i = 0; i < h.size(); ++i) {
    const int bh = h[i] * 50 / mx;
    o << "<rect x='" << 4 + i * 20 << "' y='" << 55 - bh << "' width='16' height='" << bh
      << "' fill='#4a78c2'><title>" << (i == 0 ? std::string("0") : "1e" + std::to_string(int(i) - 19)) << ": "
      << h[i] << "</title></rect>";
  }
  o << "<text x='2' y='68' font-size='9'>0</text><text x='60' y='68' font-size='9'>1e-16</text>"
       "<text x='140' y='68' font-size='9'>1e-12</text><text x='220' y='68' font-size='9'>1e-8</text></svg>";
  return o.str();
}

}  // namespace

int campaign_cases(const CampaignOptions& opt, const char* id) {
  if (opt.cases > 0) return opt.cases;
  const std::string q(id);
  return q == "collide_cylinder_capsule" || q == "sweep_sphere_cylinder" || q == "collide_cylinder_obb" ||
                 q == "collide_cylinder_triangle" || q == "collide_cylinder_cylinder"
             ? 10000
             : 100000;
}

std::vector<std::pair<std::string, std::string>> campaign_variants() {
  std::vector<std::pair<std::string, std::string>> out;
  for_each_query([&](auto q) {
    constexpr QueryId Q = decltype(q)::value;
    for (const auto* v : variants_of(&production(typename Suite<Q>::Case{}))) out.emplace_back(v->name, info(Q).name);
  });
  return out;
}

int run_campaign(const CampaignOptions& opt) {
  namespace fs = std::filesystem;
  const fs::path out_dir(opt.out);
  fs::create_directories(out_dir);
  const int threads = opt.threads > 0 ? opt.threads : std::max(1u, std::thread::hardware_concurrency());
  const std::string per_query = opt.cases > 0 ? std::to_string(opt.cases) + " cases per query"
                                              : std::string("100000 cases per query (10000 where the oracle is the certified engine)");
  std::fprintf(stderr, "[campaign] seed %llu, %s, %d threads, output %s\n", static_cast<unsigned long long>(opt.seed),
               per_query.c_str(), threads, out_dir.string().c_str());
  std::vector<QueryReport> reps;
  for_each_query([&](auto q) {
    constexpr QueryId Q = decltype(q)::value;
    if (!opt.queries.empty() && std::find(opt.queries.begin(), opt.queries.end(), info(Q).name) == opt.queries.end()) return;
    if (!opt.variant.empty()) {
      bool mine = false;
      for (const auto* v : variants_of(&production(typename Suite<Q>::Case{}))) mine = mine || opt.variant == v->name;
      if (!mine) return;
    }
    reps.push_back(run_query<Q>(opt, out_dir, threads));
  });

  int beyond = 0;
  std::ofstream js(out_dir / "report.json");
  std::string rerun = "geomcheck campaign --seed " + std::to_string(opt.seed) +
                      (opt.cases > 0 ? " --cases " + std::to_string(opt.cases) : std::string());
  for (const auto& q : opt.queries) rerun += " --query " + q;
  if (!opt.variant.empty()) rerun += " --variant " + opt.variant;
  const std::string under_test = opt.variant.empty() ? "production" : opt.variant + " (a known-wrong variant)";
  js << "{\n  \"tool\": \"geomcheck\",\n  \"seed\": " << opt.seed << ",\n  \"cases_per_query\": " << jstr(per_query)
     << ",\n  \"replay\": " << jstr(rerun) << ",\n  \"implementation\": " << jstr(under_test)
     << ",\n  \"queries\": [\n";
  for (std::size_t i = 0; i < reps.size(); ++i) {
    QueryReport& r = reps[i];
    beyond += r.beyond + r.check_failures;
    js << "    {\n      \"id\": " << jstr(r.name) << ",\n      \"summary\": " << jstr(r.summary)
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
  js << "  ]\n}\n";

  std::ofstream h(out_dir / "report.html");
  h << "<!doctype html><html lang='en'><head><meta charset='utf-8'><title>geomcheck campaign report</title>"
       "<style>body{font-family:sans-serif;margin:2em;max-width:1100px}table{border-collapse:collapse;margin:1em 0}"
       "td,th{border:1px solid #bbb;padding:4px 8px;text-align:right}th{background:#eee}td.l,th.l{text-align:left}"
       ".bad{color:#b00;font-weight:bold}.ok{color:#070}figure.cx{margin:1em 0;border-top:1px solid #ddd}"
       "figure.cx svg{margin-right:6px}figcaption{font-size:12px;margin:4px 0;word-break:break-all}"
       ".legend{font-size:12px;margin:2px 0}</style></head><body>"
       "<h1>geomcheck campaign report</h1><p>seed <code>"
    << opt.seed << "</code>, " << html(per_query) << ", implementation under test: <b>" << html(under_test)
    << "</b>. Errors are multiples of the case scale "
       "(largest coordinate magnitude or extent). Rerun: <code>" << html(rerun) << "</code></p>";
  // FCL as a subject: production and FCL, a row each, per query.
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
  for (QueryReport& r : reps) {
    const bool clean = r.beyond == 0 && r.check_failures == 0;
    h << "<h2 id='" << r.name << "'>" << r.name << "</h2><p>" << html(r.summary) << "</p><p class='"
      << (clean ? "ok'>verified: no disagreement beyond the band, every property holds" : "bad'>FAILURES found")
      << "</p><table><tr><th class='l'>measure</th><th>production</th><th>FCL</th></tr>"
      << "<tr><td class='l'>cases (valid)</td><td>" << r.cases << " (" << r.valid << ")</td><td>" << r.fcl_ok << " answered</td></tr>"
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
    auto row = [&](const char* n, Series& s, double bound) {
      if (s.v.empty()) return;
      const double mx = s.pct(1.0);
      h << "<tr><td class='l'>" << n << "</td><td>" << (bound > 0 ? jnum(bound) : std::string("&ndash;")) << "</td><td>" << s.v.size() << "</td><td>" << jnum(s.pct(0.5))
        << "</td><td>" << jnum(s.pct(0.9)) << "</td><td>" << jnum(s.pct(0.99)) << "</td><td class='"
        << (bound > 0 && mx > bound ? "bad" : "") << "'>" << jnum(mx) << "</td><td>" << hist_svg(s) << "</td></tr>";
    };
    row("depth", r.depth, r.tol.depth);
    row("normal", r.normal, r.tol.normal);
    row("point", r.point, r.tol.point);
    row("t", r.t, r.tol.t);
    row("FCL depth", r.fcl_depth, 0);
    row("FCL normal", r.fcl_normal, 0);
    row("FCL point", r.fcl_point, 0);
    row("FCL distance", r.fcl_distance, 0);
    row("FCL t", r.fcl_t_gap, 0);
    row("FCL |t - t_exact| (absolute)", r.fcl_t, 0);
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
      h << "</ul><p>counterexamples (replay with <code>geomcheck replay FILE</code>; each drawn in the "
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
  h << "</body></html>\n";
  std::fprintf(stderr, "[campaign] wrote %s and %s\n", (out_dir / "report.json").string().c_str(),
               (out_dir / "report.html").string().c_str());
  return beyond;
}

}  // namespace geomcheck
