// geomcheck — verify(), replay() and the program of a family's door, written
// once for the families whose cases are not pairs (the point-set and mesh
// families): the runner (guarded.hpp) over the family's cases, the tally
// of failures with the caps on what is saved, the report, the summary and
// the command line. A family says what is its own (a Family, below): how a
// case is asked, checked, shrunk, saved and drawn, replayed and counted.
//
// A Family has:
//   using Case, Report (report::PointSetReport, report::MeshReport);
//   static std::vector<std::pair<Case, std::string>> draw(seed, n): the
//     seed's first n cases, tagged (the campaign's);
//   FamilyWords words: its query and what its cases are called;
//   const char* subject_name() const;
//   std::string in_all(const Report&) const: what the cases held, for the
//     summary (" (N points)");
//   bool asked(const Case&) const: the subject states the case (else not
//     asked, counted);
//   void print_claims() const: what the subject is held to, on stdout;
//   Checked check(const Case&, const std::string& tag) const: its failure,
//     its figures (report::to_json of a one-case Report) and the subject's
//     time;
//   std::string lost_figures(const Case&, const std::string& tag) const: the
//     figures of a case that ended its child before its checks were done;
//   std::string save(const Case&, const std::string& tag, int number,
//     const Failure&, bool ask_subject, int& shrunk) const: the case file
//     (shrunk unless the subject is not to be asked again) and its page; its
//     path ("" when not saved);
//   void start_report(Report&) const: the report's names;
//   void print_figures(const Report&) const: the family's lines of the
//     summary (times);
//   void keep(VerifyResult&, const Report&) const: the report in the result;
//   std::optional<std::string> load(const path&, Case&) const: a file of
//     the family's query, or why not;
//   bool replay_one(const path&, const Case&) const: prints the case's
//     replay, true when it passes.
#pragma once

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

#include "geomcheck/casefile.hpp"
#include "geomcheck/reports/report.hpp"
#include "geomcheck/verify.hpp"
#include "guarded.hpp"

namespace geomcheck::detail {

/// A family's query and what its cases are called in messages.
struct FamilyWords {
  const char* query;  ///< "delaunay_2d"
  const char* unit;   ///< "point sets"
  const char* one;    ///< "set"
  const char* files;  ///< "point-set files"
};

/// What a family's check of one case gives.
struct Checked {
  CheckResult failure;  ///< the first failing property, none when it passes
  std::string figures;  ///< report::to_json of the case's one-case report
  double ns = NAN;      ///< the subject's time on the case
};

/// The report files of a door's run: one family's report, no pairs.
inline void write_family_report(const std::filesystem::path& dir, const std::filesystem::path& junit,
                                const report::RunInfo& run, const report::PointSetReport& rep) {
  std::vector<report::QueryReport> none;
  report::write_json(dir / "report.json", run, none, {rep});
  report::write_html(dir / "report.html", run, none, {rep});
  if (!junit.empty()) report::write_junit(junit, run, none, {rep});
}
inline void write_family_report(const std::filesystem::path& dir, const std::filesystem::path& junit,
                                const report::RunInfo& run, const report::MeshReport& rep) {
  std::vector<report::QueryReport> none;
  report::write_json(dir / "report.json", run, none, {}, {rep});
  report::write_html(dir / "report.html", run, none, {}, {rep});
  if (!junit.empty()) report::write_junit(junit, run, none, {}, {rep});
}

/// One run of a family's door over its cases: the steps run_guarded takes,
/// and the tally.
template <class Family>
class FamilyRun {
 public:
  using Case = typename Family::Case;
  using Report = typename Family::Report;

  FamilyRun(const Family& family, const VerifyOptions& opt) : fam_(family), opt_(opt) {}

  /// verify() on these cases (each tagged by its generator mode or file
  /// name), case k saved under the number index[k] (empty: k); `what` says
  /// the cases in words.
  VerifyResult run(const std::vector<std::pair<Case, std::string>>& all, const std::vector<int>& index,
                   const std::string& what) {
    if (!index.empty() && index.size() != all.size())
      throw std::invalid_argument("verify: " + std::to_string(index.size()) + " numbers for " +
                                  std::to_string(all.size()) + " " + fam_.words.unit);
    const auto start = std::chrono::steady_clock::now();
    int not_asked = 0;
    for (std::size_t k = 0; k < all.size(); ++k) {
      if (fam_.asked(all[k].first)) {
        cases_.push_back(all[k]);
        index_.push_back(index.empty() ? static_cast<int>(k) : index[k]);
      } else {
        ++not_asked;
      }
    }
    if (opt_.summary) {
      std::fprintf(stderr, "verify %s against %s: %s, seed %llu%s\n", fam_.subject_name(), fam_.words.query, what.c_str(),
                   static_cast<unsigned long long>(opt_.seed), opt_.isolate ? "" : ", in process");
      fam_.print_claims();
      std::fflush(stdout);
    }
    fam_.start_report(rep_);
    rep_.requested = static_cast<int>(all.size());
    int shrunk = 0;
    CaseSteps steps;
    steps.check = [&](int i) { return check(i); };
    steps.save = [&](int i, CaseLine& line, bool ask) { return save_all(i, line, ask); };
    steps.absorb = [&](int i, const CaseLine& line) {
      absorb(i, line);
      shrunk += line.shrunk;
    };
    steps.lost = [&](int i, const Failure& f) { lost(i, f); };
    const int ran = run_guarded(static_cast<int>(cases_.size()), {opt_.isolate, opt_.case_seconds, opt_.seconds, 1, opt_.progress}, steps);
    res_.cases = ran;
    stopped_by_time(rep_, ran < static_cast<int>(cases_.size()));
    res_.not_expressed = not_asked;
    note_not_asked(rep_, not_asked);
    if (opt_.report) {
      report::RunInfo run;
      run.version = GEOMCHECK_VERSION;
      run.started = opt_.started.empty() ? report::utc_now() : opt_.started;
      run.command = opt_.command.empty() ? opt_.program : opt_.command;
      run.seed = opt_.seed;
      run.per_query = what;
      run.rerun = opt_.program + " --seed " + std::to_string(opt_.seed) + " --cases " + std::to_string(opt_.cases);
      run.under_test = std::string(fam_.subject_name()) + " (the subject verified)";
      std::error_code ec;
      std::filesystem::create_directories(opt_.out, ec);
      write_family_report(opt_.out, opt_.junit, run, rep_);
      res_.report = opt_.out / "report.html";
    }
    fam_.keep(res_, rep_);
    if (opt_.summary) {
      const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      std::printf("verify %s (%s): %d %s%s, seed %llu, %.1f s: %s\n", fam_.subject_name(), fam_.words.query, res_.cases,
                  fam_.words.unit, fam_.in_all(rep_).c_str(), static_cast<unsigned long long>(opt_.seed), seconds,
                  res_.failures == 0 ? "every property held" : "FAILED");
      if (res_.not_expressed) std::printf("  %d %s not asked: %s\n", res_.not_expressed, fam_.words.unit, fam_.not_asked_why());
      if (res_.failures) std::printf("  %d failing %s; by property:\n", res_.failures, fam_.words.unit);
      for (const auto& [property, n] : res_.by_property) std::printf("  %6d %s\n", n, property.c_str());
      if (shrunk) std::printf("  %d saved %s shrunk\n", shrunk, fam_.words.unit);
      if (!res_.saved.empty())
        std::printf("  %zu saved (at most %d per property) under %s\n", res_.saved.size(), opt_.max_saved,
                    (opt_.out / fam_.words.query).string().c_str());
      fam_.print_figures(rep_);
      if (!res_.report.empty()) std::printf("  report: %s (and report.json)\n", res_.report.string().c_str());
    }
    return res_;
  }

  const Report& report() const { return rep_; }

 private:
  static void stopped_by_time(Report& r, bool stopped) { r.stopped_by_time = stopped; }
  static void note_not_asked(report::PointSetReport& r, int n) { r.not_asked = n; }
  static void note_not_asked(report::MeshReport&, int) {}  // said in the summary and VerifyResult

  /// The checks of case i (its failure kept for the page: the same process
  /// saves it next).
  CaseLine check(int i) {
    const Checked c = fam_.check(cases_[i].first, cases_[i].second);
    CaseLine line;
    line.ns = c.ns;
    line.figures = c.figures;
    checked_case_ = i;
    checked_failure_ = c.failure;
    if (c.failure) line.properties.push_back(c.failure->property);
    return line;
  }

  /// Saves failing case i's failures (shrunk when the subject may be asked
  /// again), at most opt.max_saved of a property.
  std::vector<std::string> save_all(int i, CaseLine& line, bool ask_subject) {
    std::vector<std::string> files;
    for (const std::string& property : line.properties) {
      const Failure f = checked_case_ == i && checked_failure_ && checked_failure_->property == property
                            ? *checked_failure_
                            : Failure{property, "(the subject ended the process while this failure was being shrunk)"};
      files.push_back(save(i, f, ask_subject, line.shrunk));
    }
    return files;
  }

  std::string save(int i, const Failure& f, bool ask_subject, int& shrunk) {
    if (saved_of_property_[f.property] >= opt_.max_saved) return "";
    return fam_.save(cases_[i].first, cases_[i].second, index_[i], f, ask_subject, shrunk);
  }

  /// Counts what case i gave.
  void absorb(int i, const CaseLine& line) {
    Report one;
    report::from_json(line.figures, one);
    report::merge_into(rep_, one);
    fail(i, line.properties, line.files);
  }

  /// Case i failing these properties (and the file saved for each).
  void fail(int i, const std::vector<std::string>& properties, const std::vector<std::string>& files) {
    if (properties.empty()) return;
    ++rep_.failures;
    ++res_.failures;
    res_.failed_cases.push_back(cases_[i].second);
    for (std::size_t k = 0; k < properties.size(); ++k) {
      ++rep_.failures_by_property[properties[k]];
      ++res_.by_property[properties[k]];
      if (k < files.size() && !files[k].empty()) {
        ++saved_of_property_[properties[k]];
        rep_.counterexamples.push_back(files[k]);
        res_.saved.emplace_back(files[k]);
      }
    }
  }

  /// Case i ended its child before its checks were done: saved as found,
  /// counted with the figures the family gives it without an answer.
  void lost(int i, const Failure& f) {
    int shrunk = 0;
    const std::string file = save(i, f, false, shrunk);
    Report one;
    report::from_json(fam_.lost_figures(cases_[i].first, cases_[i].second), one);
    report::merge_into(rep_, one);
    fail(i, {f.property}, {file});
  }

  const Family& fam_;
  const VerifyOptions& opt_;
  std::vector<std::pair<Case, std::string>> cases_;  // the asked cases and their tags
  std::vector<int> index_;                            // the number each asked case is saved under
  int checked_case_ = -1;                             // the case check() last ran, and its failure
  CheckResult checked_failure_;
  Report rep_;
  VerifyResult res_;
  std::map<std::string, int> saved_of_property_;
};

/// verify() of a family's subject on its case files (each tagged by its
/// file name); a file that cannot be read, or is of another query, is said
/// on stderr and left out.
template <class Family>
VerifyResult verify_family_files(const Family& fam, const std::vector<std::filesystem::path>& files,
                                 const VerifyOptions& opt) {
  std::vector<std::pair<typename Family::Case, std::string>> cases;
  for (const auto& path : files) {
    typename Family::Case c;
    if (const auto err = fam.load(path, c)) {
      std::fprintf(stderr, "verify: %s: %s\n", path.string().c_str(), err->c_str());
      continue;
    }
    cases.emplace_back(std::move(c), path.stem().string());
  }
  VerifyOptions o = opt;
  o.cases = static_cast<int>(cases.size());
  return FamilyRun<Family>(fam, o).run(cases, {}, std::to_string(cases.size()) + " " + fam.words.files);
}

/// replay() of a family's subject: each file's checks printed; the number
/// that failed or could not be read.
template <class Family>
int replay_family(const Family& fam, const std::vector<std::filesystem::path>& files) {
  int failed = 0;
  for (const auto& path : files) {
    typename Family::Case c;
    if (const auto err = fam.load(path, c)) {
      std::fprintf(stderr, "replay: %s: %s\n", path.string().c_str(), err->c_str());
      ++failed;
      continue;
    }
    failed += !fam.replay_one(path, c);
  }
  return failed;
}

/// The program of a family's door (verify.hpp's command line): --replay of
/// a file of another query is a usage error (exit 2).
template <class Family, class Verify>
int family_program(const Family& fam, int argc, char** argv, Verify&& verify_generated) {
  VerifyOptions opt;
  std::vector<std::filesystem::path> replays;
  const int rc = parse_verify_command(argc, argv,
                                      std::string("Holds subject '") + fam.subject_name() + "' to every property of " +
                                          fam.words.query + " on generated " + fam.words.unit + "; saves and draws each failing " +
                                          fam.words.one + ".",
                                      fam.words.unit, std::string(fam.words.files) + " saved per failing property", opt,
                                      replays);
  if (rc >= 0) return rc;
  if (!replays.empty()) {
    for (const auto& path : replays) {
      const std::string q = declared_query(path);
      if (!q.empty() && q != fam.words.query) {
        std::fprintf(stderr, "%s: %s is a case of %s; %s verifies %s\n", opt.program.c_str(), path.string().c_str(),
                     q.c_str(), fam.subject_name(), fam.words.query);
        return 2;
      }
    }
    return replay_family(fam, replays) == 0 ? 0 : 1;
  }
  return verify_generated(opt).failures == 0 ? 0 : 1;
}

/// Where a family's failing case `number` of `property` is saved:
/// OUT/QUERY/NNNNN-PROPERTY.case (the folder made), its file name in `name`.
inline std::filesystem::path failure_path(const VerifyOptions& opt, const char* query, int number,
                                          const std::string& property, std::string& name) {
  const std::filesystem::path dir = opt.out / query;
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  char buf[96];
  std::snprintf(buf, sizeof buf, "%05d-%s.case", number, property.c_str());
  name = buf;
  return dir / name;
}

/// Says a saved failure on stdout (not with opt.quiet): what failed, where
/// it is drawn, the command that replays it.
inline void announce_failure(const VerifyOptions& opt, const char* subject, const char* one, const std::string& property,
                             int number, const std::string& tag, const std::string& detail,
                             const std::filesystem::path& path) {
  if (!opt.quiet)
    std::printf("FAIL %s %s (%s %d, %s): %s\n  drawn: %s\n  replay: %s\n", subject, property.c_str(), one, number,
                tag.c_str(), detail.c_str(), std::filesystem::path(path).replace_extension(".html").string().c_str(),
                replay_command(opt, path).c_str());
  std::fflush(stdout);
}

}  // namespace geomcheck::detail

/// The public entry points of a family's door (verify.hpp) for subjects of
/// type SUBJECT, run by FAMILY (whose static draw(seed, n) gives the seed's
/// cases, as the campaign draws them): verify() on generated cases, on given
/// cases, on files; replay(); the program.
#define GEOMCHECK_FAMILY_DOOR(SUBJECT, FAMILY)                                                                  \
  VerifyResult verify(const SUBJECT& subject, const VerifyOptions& opt) {                                      \
    const FAMILY family{subject, opt};                                                                          \
    return detail::FamilyRun<FAMILY>(family, opt).run(FAMILY::draw(opt.seed, opt.cases), {},                    \
                                                      std::to_string(opt.cases) + " " + family.words.unit);         \
  }                                                                                                            \
  VerifyResult verify(const SUBJECT& subject, const std::vector<std::pair<FAMILY::Case, std::string>>& cases,  \
                      const std::vector<int>& index, const VerifyOptions& opt) {                               \
    const FAMILY family{subject, opt};                                                                          \
    return detail::FamilyRun<FAMILY>(family, opt).run(cases, index,                                             \
                                                      std::to_string(cases.size()) + " " + family.words.unit);      \
  }                                                                                                            \
  VerifyResult verify(const SUBJECT& subject, const std::vector<std::filesystem::path>& files,                 \
                      const VerifyOptions& opt) {                                                               \
    return detail::verify_family_files(FAMILY{subject, opt}, files, opt);                                      \
  }                                                                                                            \
  int replay(const SUBJECT& subject, const std::vector<std::filesystem::path>& files) {                       \
    const VerifyOptions opt;                                                                                    \
    return detail::replay_family(FAMILY{subject, opt}, files);                                                  \
  }                                                                                                            \
  int verify(const SUBJECT& subject, int argc, char** argv) {                                                  \
    const VerifyOptions unused;                                                                                 \
    return detail::family_program(FAMILY{subject, unused}, argc, argv,                                         \
                                  [&](const VerifyOptions& opt) { return verify(subject, opt); });            \
  }
