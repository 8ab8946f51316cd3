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
#include "family_door.hpp"
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

/// The point-set family's part of the door (family_door.hpp).
struct PointSetFamily {
  using Case = Points;
  using Report = report::PointSetReport;
  const PointSetImpl& subject;
  const VerifyOptions& opt;

  static std::vector<std::pair<Case, std::string>> draw(std::uint64_t seed, int n) { return gen::draw_point_sets(seed, n); }
  static constexpr detail::FamilyWords words{kDelaunayQueryName, "point sets", "set", "point-set files"};
  const char* subject_name() const { return subject.name; }
  std::string in_all(const Report& r) const { return " (" + std::to_string(r.points) + " points)"; }
  bool asked(const Points& p) const { return subject.any_input || all_finite(p); }
  const char* not_asked_why() const { return "a non-finite coordinate, and the subject claims finite input only"; }
  void print_claims() const {
    std::printf("claims of %s: a Delaunay triangulation of the distinct points (held to the exact checker and CGAL); %s\n",
                subject.name,
                subject.any_input ? "any input (a non-finite coordinate rejected with DelaunayInputError naming the first)"
                                  : "finite input only (sets with a NaN or an infinity are not asked)");
  }
  void start_report(Report& r) const {
    r.name = kDelaunayQueryName;
    r.summary = info(PointSetQueryId::delaunay_2d).summary;
    r.subject = subject.name;
  }
  void keep(VerifyResult& res, const Report& r) const { res.point_set_figures = r; }
  void print_figures(const Report& r) const {
    if (r.production_us > 0)
      std::printf("  time: %s %.3g s, CGAL %.3g s on the same sets (%.2fx CGAL's)\n", subject.name, r.production_us * 1e-6,
                  r.cgal_us * 1e-6, r.production_us / r.cgal_us);
  }

  detail::Checked check(const Points& p, const std::string& tag) const {
    const PointSetOutcome o = check_point_set(p, subject);
    return {o.failure, figures_text(tag, classify_point_set(p), p.size(), o),
            std::isfinite(o.subject_us) ? o.subject_us * 1e3 : NAN};
  }
  std::string lost_figures(const Points& p, const std::string& tag) const {
    report::PointSetReport one;
    one.sets = 1;
    one.points = p.size();
    one.modes[tag] = 1;
    one.kinds[std::string(classify_point_set(p))] = 1;
    return report::to_json(one);
  }

  /// Saves a failing set (shrunk unless the subject crashed) with its page.
  std::string save(const Points& set, const std::string& tag, int number, const Failure& f, bool ask_subject,
                   int& shrunk) const {
    Points p = set;
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
    std::string name;
    const std::filesystem::path path = detail::failure_path(opt, kDelaunayQueryName, number, f.property, name);
    PointSetFile file;
    file.points = p;
    file.oracle_verdict = std::string(classify_point_set(p));
    file.found_by = opt.found_by + " " + subject.name + " seed=" + std::to_string(opt.seed) + " case=" + std::to_string(number);
    file.note = shown.property + ": " + shown.detail;
    std::string err;
    if (!save_point_set(path, file, err)) {
      std::fprintf(stderr, "verify: cannot save %s: %s\n", path.string().c_str(), err.c_str());
      return "";
    }
    const std::string title = report::html(name + ": " + shown.property + ": " + shown.detail);
    report::write_counterexample_page(std::filesystem::path(path).replace_extension(".html"), name,
                                      draw::point_set_view(p, drawn, title), subject.name,
                                      detail::replay_command(opt, path));
    detail::announce_failure(opt, subject.name, "set", f.property, number, tag, shown.detail, path);
    return path.string();
  }

  std::optional<std::string> load(const std::filesystem::path& path, Points& points) const {
    PointSetFile f;
    if (auto err = load_set(path, f)) return err;
    points = f.points;
    return std::nullopt;
  }

  bool replay_one(const std::filesystem::path& path, const Points& points) const {
    const PointSetOutcome o = check_point_set(points, subject);
    const bool pass = !o.failure;
    std::printf("%s %s\n  points: %zu (%s)\n", !o.asked ? "NOT ASKED" : pass ? "PASS" : "FAIL", path.string().c_str(),
                points.size(), std::string(classify_point_set(points)).c_str());
    if (!o.asked) {
      std::printf("  a non-finite coordinate: %s claims finite input only\n", subject.name);
      return true;
    }
    std::printf("  %s: %s\n", subject.name, o.answer.c_str());
    std::printf("  oracles (exact validity, CGAL): %s\n",
                pass ? "agree" : (o.failure->property + ": " + o.failure->detail).c_str());
    return pass;
  }

  static std::optional<std::string> load_set(const std::filesystem::path& path, PointSetFile& f);
};

/// The point-set file at `path`, or why not (also for a case file of another query).
std::optional<std::string> PointSetFamily::load_set(const std::filesystem::path& path, PointSetFile& f) {
  const std::string q = declared_query(path);
  if (!q.empty() && q != kDelaunayQueryName) return "a case of " + q + ", not of " + kDelaunayQueryName;
  const PointSetParseResult pr = load_point_set(path);
  if (!pr.ok()) return pr.error;
  f = pr.value;
  return std::nullopt;
}

}  // namespace

GEOMCHECK_FAMILY_DOOR(PointSetImpl, PointSetFamily)

}  // namespace geomcheck
