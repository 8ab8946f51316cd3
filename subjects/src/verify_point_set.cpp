// geomcheck — verify() and replay() for a point-set subject (verify.hpp, "The
// point-set family"): the same runner as a pair's (guarded.hpp), the checks
// of pointset_checks.hpp, point-set files for the failures.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <sstream>
#include <stdexcept>
#include <system_error>

#include "geomcheck/pointset_file.hpp"
#include "geomcheck/properties/generators.hpp"
#include "geomcheck/reports/draw.hpp"
#include "geomcheck/reports/report.hpp"
#include "geomcheck/verify.hpp"
#include "guarded.hpp"

namespace geomcheck {

namespace {

using Points = std::vector<Vec2>;

/// One set's figures on the child's line: a report of that set alone
/// (report::to_json), merged by the parent (report::merge_into).
std::string figures_text(const std::string& mode, std::string_view kind, std::size_t points, const PointSetOutcome& o) {
  report::PointSetReport one;
  one.sets = 1;
  one.points = points;
  one.modes[mode] = 1;
  one.kinds[std::string(kind)] = 1;
  one.cgal_choices_differ = o.cgal_differs;
  if (std::isfinite(o.subject_us) && std::isfinite(o.cgal_us)) one.production_us = o.subject_us, one.cgal_us = o.cgal_us;
  return report::to_json(one);
}

/// A set's points without the points at `drop` (sorted indices).
Points without(const Points& p, std::size_t from, std::size_t count) {
  Points q(p.begin(), p.begin() + from);
  q.insert(q.end(), p.begin() + std::min(p.size(), from + count), p.end());
  return q;
}

/// Shrinks a failing set while it fails `property`: drops runs of points,
/// halving the run, within `budget` checks. The number of points dropped.
std::size_t shrink_set(Points& p, const PointSetImpl& subject, const std::string& property, int budget) {
  const std::size_t before = p.size();
  auto fails = [&](const Points& q) {
    const PointSetOutcome o = check_point_set(q, subject, static_cast<std::size_t>(-1), false);
    return o.asked && o.failure && o.failure->property == property;
  };
  for (std::size_t run = std::max<std::size_t>(1, p.size() / 2); budget > 0 && !p.empty();) {
    bool dropped = false;
    for (std::size_t from = 0; from < p.size() && budget > 0;) {
      const Points q = without(p, from, run);
      --budget;
      if (q.size() < p.size() && fails(q)) {
        p = q;
        dropped = true;
      } else {
        from += run;
      }
    }
    if (!dropped) {
      if (run == 1) break;
      run = std::max<std::size_t>(1, run / 2);
    }
  }
  return before - p.size();
}

struct PointSetRun {
  const PointSetImpl& subject;
  const VerifyOptions& opt;
  std::vector<std::pair<Points, std::string>> sets;  // asked sets and their tags
  std::vector<int> index;                            // the number each asked set is saved under
  int checked_case = -1;                             // the set check() last ran, and its failure
  CheckResult checked_failure;
  report::PointSetReport rep;
  VerifyResult res;
  std::map<std::string, int> saved_of_property;

  std::string replay_command(const std::filesystem::path& path) const { return detail::replay_command(opt, path); }

  /// Saves failing set i (shrunk unless the subject crashed) with its page.
  std::string save(int i, const Failure& f, bool ask_subject, int& shrunk) {
    if (saved_of_property[f.property] >= opt.max_saved) return "";
    Points p = sets[i].first;
    Failure shown = f;
    IndexTriangles drawn;
    if (ask_subject) {
      if (opt.shrink_budget > 0) {
        const std::size_t dropped = shrink_set(p, subject, f.property, 4 * opt.shrink_budget);
        if (dropped > 0) ++shrunk;
        const PointSetOutcome o = check_point_set(p, subject, static_cast<std::size_t>(-1), false);
        if (o.failure) shown = *o.failure;
        if (dropped > 0) shown.detail += " (shrunk: " + std::to_string(dropped) + " points dropped)";
        drawn = o.triangles;
      } else {
        drawn = check_point_set(p, subject, static_cast<std::size_t>(-1), false).triangles;
      }
    }
    const std::filesystem::path dir = opt.out / kDelaunayQueryName;
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    char name[96];
    std::snprintf(name, sizeof name, "%05d-%s.case", index[i], f.property.c_str());
    const std::filesystem::path path = dir / name;
    PointSetFile file;
    file.points = p;
    file.oracle_verdict = std::string(classify_point_set(p));
    file.found_by = opt.found_by + " " + subject.name + " seed=" + std::to_string(opt.seed) + " case=" + std::to_string(index[i]);
    file.note = shown.property + ": " + shown.detail;
    std::string err;
    if (!save_point_set(path, file, err)) {
      std::fprintf(stderr, "verify: cannot save %s: %s\n", path.string().c_str(), err.c_str());
      return "";
    }
    const std::string title = report::html(std::string(name) + ": " + shown.property + ": " + shown.detail);
    report::write_counterexample_page(std::filesystem::path(path).replace_extension(".html"), name,
                                      draw::point_set_view(p, drawn, title), subject.name, replay_command(path));
    if (!opt.quiet)
      std::printf("FAIL %s %s (set %d, %s): %s\n  drawn: %s\n  replay: %s\n", subject.name, f.property.c_str(), index[i],
                  sets[i].second.c_str(), shown.detail.c_str(),
                  std::filesystem::path(path).replace_extension(".html").string().c_str(), replay_command(path).c_str());
    std::fflush(stdout);
    return path.string();
  }

  /// The checks of set i (its failure kept for the page: the same process
  /// saves it next).
  detail::CaseLine check(int i) {
    detail::CaseLine line;
    const Points& p = sets[i].first;
    const PointSetOutcome o = check_point_set(p, subject);
    line.ns = std::isfinite(o.subject_us) ? o.subject_us * 1e3 : NAN;
    line.figures = figures_text(sets[i].second, classify_point_set(p), p.size(), o);
    checked_case = i;
    checked_failure = o.failure;
    if (o.failure) line.properties.push_back(o.failure->property);
    return line;
  }

  /// Saves set i's failures (shrunk when the subject may be asked again).
  std::vector<std::string> save_all(int i, detail::CaseLine& line, bool ask_subject) {
    std::vector<std::string> files;
    for (const std::string& property : line.properties) {
      const Failure f = checked_case == i && checked_failure && checked_failure->property == property
                            ? *checked_failure
                            : Failure{property, "(the subject ended the process while this failure was being shrunk)"};
      files.push_back(save(i, f, ask_subject, line.shrunk));
    }
    return files;
  }

  void absorb(int i, const detail::CaseLine& line) {
    report::PointSetReport one;
    report::from_json(line.figures, one);
    report::merge_into(rep, one);
    fail(i, line.properties, line.files);
  }

  void fail(int i, const std::vector<std::string>& properties, const std::vector<std::string>& files) {
    if (properties.empty()) return;
    ++rep.failures;
    ++res.failures;
    res.failed_cases.push_back(sets[i].second);
    for (std::size_t k = 0; k < properties.size(); ++k) {
      ++rep.failures_by_property[properties[k]];
      ++res.by_property[properties[k]];
      if (k < files.size() && !files[k].empty()) {
        ++saved_of_property[properties[k]];
        rep.counterexamples.push_back(files[k]);
        res.saved.emplace_back(files[k]);
      }
    }
  }

  void lost(int i, const Failure& f) {
    int shrunk = 0;
    const std::string file = save(i, f, false, shrunk);
    ++rep.sets;
    rep.points += sets[i].first.size();
    rep.modes[sets[i].second]++;
    rep.kinds[std::string(classify_point_set(sets[i].first))]++;
    fail(i, {f.property}, {file});
  }
};

VerifyResult run_sets(const PointSetImpl& subject, const std::vector<std::pair<Points, std::string>>& all,
                      const std::vector<int>& index, const VerifyOptions& opt, const std::string& what) {
  if (!index.empty() && index.size() != all.size())
    throw std::invalid_argument("verify: " + std::to_string(index.size()) + " numbers for " + std::to_string(all.size()) +
                                " point sets");
  const auto start = std::chrono::steady_clock::now();
  PointSetRun r{subject, opt, {}, {}, -1, {}, {}, {}, {}};
  int not_expressed = 0;
  for (std::size_t k = 0; k < all.size(); ++k) {
    if (subject.any_input || all_finite(all[k].first)) {
      r.sets.push_back(all[k]);
      r.index.push_back(index.empty() ? static_cast<int>(k) : index[k]);
    } else {
      ++not_expressed;
    }
  }
  if (opt.summary) {
    std::fprintf(stderr, "verify %s against %s: %s, seed %llu%s\n", subject.name, kDelaunayQueryName, what.c_str(),
                 static_cast<unsigned long long>(opt.seed), opt.isolate ? "" : ", in process");
    std::printf("claims of %s: a Delaunay triangulation of the distinct points (held to the exact checker and CGAL); %s\n",
                subject.name,
                subject.any_input ? "any input (a non-finite coordinate rejected with DelaunayInputError naming the first)"
                                  : "finite input only (sets with a NaN or an infinity are not asked)");
    std::fflush(stdout);
  }
  r.rep.name = kDelaunayQueryName;
  r.rep.summary = info(PointSetQueryId::delaunay_2d).summary;
  r.rep.subject = subject.name;
  r.rep.requested = static_cast<int>(all.size());
  int shrunk = 0;
  detail::CaseSteps steps;
  steps.check = [&](int i) { return r.check(i); };
  steps.save = [&](int i, detail::CaseLine& line, bool ask) { return r.save_all(i, line, ask); };
  steps.absorb = [&](int i, const detail::CaseLine& line) {
    r.absorb(i, line);
    shrunk += line.shrunk;
  };
  steps.lost = [&](int i, const Failure& f) { r.lost(i, f); };
  const int ran = detail::run_guarded(static_cast<int>(r.sets.size()), {opt.isolate, opt.case_seconds, opt.seconds}, steps);
  r.rep.not_asked = not_expressed;
  VerifyResult& res = r.res;
  res.cases = ran;
  r.rep.stopped_by_time = ran < static_cast<int>(r.sets.size());
  res.not_expressed = not_expressed;
  if (opt.report) {
    report::RunInfo run;
    run.version = GEOMCHECK_VERSION;
    run.started = opt.started.empty() ? report::utc_now() : opt.started;
    run.command = opt.command.empty() ? opt.program : opt.command;
    run.seed = opt.seed;
    run.per_query = what;
    run.rerun = opt.program + " --seed " + std::to_string(opt.seed) + " --cases " + std::to_string(opt.cases);
    run.under_test = std::string(subject.name) + " (the subject verified)";
    std::vector<report::QueryReport> none;
    std::error_code ec;
    std::filesystem::create_directories(opt.out, ec);
    report::write_json(opt.out / "report.json", run, none, {r.rep});
    report::write_html(opt.out / "report.html", run, none, {r.rep});
    if (!opt.junit.empty()) report::write_junit(opt.junit, run, none, {r.rep});
    res.report = opt.out / "report.html";
  }
  res.point_set_figures = r.rep;
  if (!opt.summary) return res;
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("verify %s (%s): %d point sets (%zu points), seed %llu, %.1f s: %s\n", subject.name, kDelaunayQueryName,
              res.cases, r.rep.points, static_cast<unsigned long long>(opt.seed), seconds,
              res.failures == 0 ? "every property held" : "FAILED");
  if (res.not_expressed)
    std::printf("  %d sets not asked: a non-finite coordinate, and the subject claims finite input only\n", res.not_expressed);
  if (res.failures) std::printf("  %d failing sets; by property:\n", res.failures);
  for (const auto& [property, n] : res.by_property) std::printf("  %6d %s\n", n, property.c_str());
  if (shrunk) std::printf("  %d saved sets shrunk\n", shrunk);
  if (!res.saved.empty())
    std::printf("  %zu saved (at most %d per property) under %s\n", res.saved.size(), opt.max_saved,
                (opt.out / kDelaunayQueryName).string().c_str());
  if (r.rep.production_us > 0)
    std::printf("  time: %s %.3g s, CGAL %.3g s on the same sets (%.2fx CGAL's)\n", subject.name,
                r.rep.production_us * 1e-6, r.rep.cgal_us * 1e-6, r.rep.production_us / r.rep.cgal_us);
  if (!res.report.empty()) std::printf("  report: %s (and report.json)\n", res.report.string().c_str());
  return res;
}

/// The point-set file at `path`, or why not (also for a case file of another query).
std::optional<std::string> load_set(const std::filesystem::path& path, PointSetFile& f) {
  const std::string q = declared_query(path);
  if (!q.empty() && q != kDelaunayQueryName) return "a case of " + q + ", not of " + kDelaunayQueryName;
  const PointSetParseResult pr = load_point_set(path);
  if (!pr.ok()) return pr.error;
  f = pr.value;
  return std::nullopt;
}

}  // namespace

VerifyResult verify(const PointSetImpl& subject, const VerifyOptions& opt) {
  // The campaign's derivation: the same seed draws the same sets there.
  const auto sets = gen::draw_point_sets(opt.seed, opt.cases);
  return run_sets(subject, sets, {}, opt, std::to_string(opt.cases) + " point sets");
}

VerifyResult verify(const PointSetImpl& subject, const std::vector<std::pair<Points, std::string>>& sets,
                    const std::vector<int>& index, const VerifyOptions& opt) {
  return run_sets(subject, sets, index, opt, std::to_string(sets.size()) + " point sets");
}

VerifyResult verify(const PointSetImpl& subject, const std::vector<std::filesystem::path>& files,
                    const VerifyOptions& opt) {
  std::vector<std::pair<Points, std::string>> sets;
  for (const auto& path : files) {
    PointSetFile f;
    if (const auto err = load_set(path, f)) {
      std::fprintf(stderr, "verify: %s: %s\n", path.string().c_str(), err->c_str());
      continue;
    }
    sets.emplace_back(f.points, path.stem().string());
  }
  VerifyOptions o = opt;
  o.cases = static_cast<int>(sets.size());
  return run_sets(subject, sets, {}, o, std::to_string(sets.size()) + " point-set files");
}

int replay(const PointSetImpl& subject, const std::vector<std::filesystem::path>& files) {
  int failed = 0;
  for (const auto& path : files) {
    PointSetFile f;
    if (const auto err = load_set(path, f)) {
      std::fprintf(stderr, "replay: %s: %s\n", path.string().c_str(), err->c_str());
      ++failed;
      continue;
    }
    const PointSetOutcome o = check_point_set(f.points, subject);
    const bool pass = !o.failure;
    std::printf("%s %s\n  points: %zu (%s)\n", !o.asked ? "NOT ASKED" : pass ? "PASS" : "FAIL", path.string().c_str(),
                f.points.size(), std::string(classify_point_set(f.points)).c_str());
    if (!o.asked) {
      std::printf("  a non-finite coordinate: %s claims finite input only\n", subject.name);
      continue;
    }
    std::printf("  %s: %s\n", subject.name, o.answer.c_str());
    std::printf("  oracles (exact validity, CGAL): %s\n",
                pass ? "agree" : (o.failure->property + ": " + o.failure->detail).c_str());
    failed += !pass;
  }
  return failed;
}

int verify(const PointSetImpl& subject, int argc, char** argv) {
  VerifyOptions opt;
  std::vector<std::filesystem::path> replays;
  const int rc = detail::parse_verify_command(
      argc, argv,
      std::string("Holds subject '") + subject.name + "' to every property of " + kDelaunayQueryName +
          " on generated point sets; saves and draws each failing set.",
      "point sets", "point-set files saved per failing property", opt, replays);
  if (rc >= 0) return rc;
  if (!replays.empty()) {
    for (const auto& path : replays) {  // a file of another query is a usage error
      const std::string q = declared_query(path);
      if (!q.empty() && q != kDelaunayQueryName) {
        std::fprintf(stderr, "%s: %s is a case of %s; %s verifies %s\n", opt.program.c_str(), path.string().c_str(),
                     q.c_str(), subject.name, kDelaunayQueryName);
        return 2;
      }
    }
    return replay(subject, replays) == 0 ? 0 : 1;
  }
  return verify(subject, opt).failures == 0 ? 0 : 1;
}

}  // namespace geomcheck
