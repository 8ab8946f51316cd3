// geomcheck — verify() and replay() for any subject (verify.hpp).
#include "geomcheck/verify.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <csignal>
#include <ctime>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <system_error>

#include "geomcheck/casefile.hpp"
#include "geomcheck/properties/shrink.hpp"
#include "geomcheck/properties/spec.hpp"
#include "geomcheck/properties/tolerances.hpp"
#include "geomcheck/reports/draw.hpp"
#include "geomcheck/reports/report.hpp"
#include "guarded.hpp"

namespace geomcheck {

namespace {

using detail::shell_quote;

using detail::replay_command;
using detail::replay_prefix;

/// check_every (each failing property of the case, so that one cannot hide
/// another), with a subject that throws failing the case instead of ending
/// the run.
template <class Case, class Impl>
std::vector<Failure> guarded_every(const Case& c, const Impl& subject, const Evaluation* known = nullptr) {
  try {
    return check_every(c, subject, known);
  } catch (const std::exception& ex) {
    return {Failure{"subject-threw", std::string("the subject threw: ") + ex.what()}};
  } catch (...) {
    return {Failure{"subject-threw", "the subject threw something that is not a std::exception"}};
  }
}

/// The subject's answer, drawn (nothing drawn when it throws).
template <class Case, class Impl>
draw::Answer drawn_answer(const Case& c, const Impl& subject) {
  try {
    if constexpr (QueryTraits<query_of_case<Case>>::kind == QueryKind::Collide)
      return draw::answer_of(subject.collide(c.a, c.b), subject.name);
    else if constexpr (QueryTraits<query_of_case<Case>>::kind == QueryKind::Cast)
      return draw::answer_of(subject.cast(c.a, c.b), subject.name);
    else
      return draw::answer_of(subject.sweep(c.a, c.b), subject.name);
  } catch (...) {
    draw::Answer a;
    a.label = std::string(subject.name) + ": threw";
    return a;
  }
}

/// The subject held to the truth on one case; where the subject throws,
/// the truth alone (evaluated beside production's answer, which is not
/// shown).
/// `answered` (when given) tells which.
/// `how` (when given) evaluates in evaluate()'s place (RunHooks::evaluate).
template <QueryId Q>
Evaluation truth_of(const typename QueryTraits<Q>::Case& c, const ImplOf<Q>& subject, bool* answered = nullptr,
                    const std::function<Evaluation()>& how = {}) {
  if (answered) *answered = true;
  try {
    return how ? how() : evaluate(c, subject);
  } catch (...) {
    if (answered) *answered = false;
    Evaluation e = evaluate(c, production_of<Q>());
    e.prod_text = "threw";
    return e;
  }
}

/// Saves a failing case: its case file (the truth's verdict filed, none on
/// invalid input, as replay expects) and, beside it, a page drawing it
/// (the drawing also into `drawing`, when given).
template <QueryId Q>
bool save_failure(const typename QueryTraits<Q>::Case& c, const ImplOf<Q>& subject, const Failure& f,
                  const VerifyOptions& opt, int index, const std::string& mode, std::filesystem::path& path,
                  bool with_answer, std::string* drawing_out = nullptr) {
  const std::filesystem::path dir = opt.out / info(Q).name;
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  char name[96];
  std::snprintf(name, sizeof name, "%05d-%s.case", index, f.property.c_str());
  path = dir / name;
  const Evaluation e = with_answer ? truth_of<Q>(c, subject) : evaluate(c, production_of<Q>());
  CaseFile file = from_case<Q>(c, opt.found_by + " " + subject.name + " seed=" + std::to_string(opt.seed) +
                                      " case=" + std::to_string(index) + (mode.empty() ? "" : " mode=" + mode),
                               e.valid ? verdict_word(Q, e) : std::string(), f.property + ": " + f.detail);
  std::string err;
  if (!save_case(path, file, err)) {
    std::fprintf(stderr, "verify: cannot save %s: %s\n", path.string().c_str(), err.c_str());
    return false;
  }
  draw::Answer ans;  // a subject that crashed is not asked again
  ans.label = std::string(subject.name) + ": crashed";
  if (with_answer) ans = drawn_answer(c, subject);
  std::string drawing = draw::views(
      c, report::html(std::string(name) + ": " + f.property + ": " + f.detail + "; truth: " + e.truth_text), {},
      &ans);
  // A relation's failure: the case it was compared with, beside it.
  if (const auto* t = std::any_cast<typename QueryTraits<Q>::Case>(&f.related)) {
    draw::Answer other = ans;
    if (with_answer) other = drawn_answer(*t, subject);
    drawing += draw::views(*t, report::html("the case " + f.property + " compared it with"), {}, &other);
  }
  report::write_counterexample_page(std::filesystem::path(path).replace_extension(".html"), name, drawing, subject.name,
                                    replay_command(opt, path));
  if (drawing_out) *drawing_out = std::move(drawing);
  return true;
}

/// What the subject is held to, in one line.
template <QueryId Q>
std::string claims_text(const ImplOf<Q>& subject) {
  const Claims& c = subject.claims ? *subject.claims : spec_of<Q>().claims;
  std::string t = std::string("claims of ") + subject.name + (subject.claims ? "" : " (production's)") +
                  ": verdict " + (c.exact_verdict ? "exact" : "not exact");
  if (QueryTraits<Q>::kind == QueryKind::Collide) t += std::string("; depth: ") + to_string(c.depth);
  t += std::string("; point ") + (c.point_in_both ? "claimed" : "not claimed");
  t += std::string("; touching ") + (c.touching_is_contact ? "is" : "is not") + " contact";
  if (c.margin > 0) {
    char m[32];
    std::snprintf(m, sizeof m, "%.3g", c.margin);
    t += std::string("; margin ") + m + " * scale";
  }
  if (*c.normal) t += std::string("; normal: ") + c.normal;
  t += "; precision: " + report::precision_text(c.precision);
  char b[320];
  const Tolerances tol = bounds_of(Q, subject.claims);
  std::snprintf(b, sizeof b, "\nbounds of %s (* scale): verdict band %.3g, depth %.3g, normal %.3g, point %.3g, t %.3g; |normal| - 1: %.3g",
                subject.name, tol.verdict, tol.depth, tol.normal, tol.point, tol.t, tol.unit);
  t += b;
  if (&subject != &production_of<Q>())
    t += "\n  not checked for this subject: the argument order (production's swapped entry point; a subject has one)";
  return t;
}

/// What verify() gathers: the counts returned to the caller and the report.
struct Tally {
  VerifyResult res;
  report::QueryReport rep;
  std::vector<double> ns;  ///< the subject's time per call, one per case
  std::vector<std::string> modes;  ///< each case's generator mode: a failure's signature is property @ mode
  std::map<std::string, int> saved_of_property, saved_of_signature;  ///< case files saved, for the caps
  /// Case i's line (detail::run_guarded): its evaluation (read from its
  /// figures), its failures and their case files.
  void add(QueryId id, int i, const detail::CaseLine& line, const Evaluation& e) {
    report::add_evaluation(rep, id, e);
    if (std::isfinite(line.ns)) ns.push_back(line.ns);
    rep.shrunk += line.shrunk;
    fail(i, line.properties, line.files);
  }
  /// Case i failing these properties (and the case file of each, where one
  /// was saved): one failing case, counted under each of its properties.
  void fail(int i, const std::vector<std::string>& properties, const std::vector<std::string>& saved) {
    if (properties.empty()) return;
    ++res.failures;
    ++rep.check_failures;
    if (i < static_cast<int>(modes.size()) &&
        (res.failed_cases.empty() || res.failed_cases.back() != modes[i]))
      res.failed_cases.push_back(modes[i]);
    for (std::size_t k = 0; k < properties.size(); ++k) {
      const std::string& property = properties[k];
      ++res.by_property[property];
      ++rep.failures_by_property[property];
      ++rep.failures_by_signature[signature(i, property)];
      if (k < saved.size() && !saved[k].empty()) {
        ++saved_of_property[property];
        ++saved_of_signature[signature(i, property)];
        res.saved.emplace_back(saved[k]);
        rep.counterexamples.push_back(saved[k]);
      }
    }
  }
  /// Whether a failure of `property` on case i is past the caps.
  bool capped(int i, const std::string& property, int max_saved) {
    return saved_of_property[property] >= max_saved ||
           saved_of_signature[signature(i, property)] >= report::kMaxSavedPerSignature;
  }
  /// The signature of case i failing `property`.
  std::string signature(int i, const std::string& property) const {
    return property + " @ " + (i < static_cast<int>(modes.size()) ? modes[i] : std::string("?"));
  }
};

/// report.json and report.html of a verify run (and a JUnit file when asked
/// for) under opt.out, from the tally of subject's cases.
/// The tally's report of subject's run completed: names, claims, bounds,
/// the median call, the time per case.
template <QueryId Q>
void complete_figures(const ImplOf<Q>& subject, const VerifyOptions& opt, Tally& t, double seconds) {
  report::QueryReport& rep = t.rep;
  rep.name = info(Q).name;
  rep.summary = info(Q).summary;
  rep.subject = subject.name;
  rep.replay = replay_prefix(opt);
  rep.claims = subject.claims ? *subject.claims : spec_of<Q>().claims;
  rep.own_claims = subject.claims != nullptr;
  rep.requested = opt.cases;
  rep.tol = bounds_of(Q, subject.claims);
  rep.depth_is_bound = rep.claims.depth == Claims::Depth::UpperBound;
  if (!t.ns.empty()) {  // the median call
    std::nth_element(t.ns.begin(), t.ns.begin() + t.ns.size() / 2, t.ns.end());
    rep.prod_ns = t.ns[t.ns.size() / 2];
  }
  const int threads = opt.isolate ? 1 : std::max(1, opt.threads);  // the time per case on one core
  rep.oracle_us = rep.cases ? seconds * 1e6 * threads / rep.cases : NAN;
}

/// report.json and report.html of a verify run (and a JUnit file when asked
/// for) under opt.out, from its completed figures.
template <QueryId Q>
std::filesystem::path write_report(const ImplOf<Q>& subject, const VerifyOptions& opt, const report::QueryReport& rep) {
  report::RunInfo run;
  run.version = GEOMCHECK_VERSION;
  run.started = opt.started.empty() ? report::utc_now() : opt.started;
  run.command = opt.command.empty() ? opt.program : opt.command;
  run.seed = opt.seed;
  run.per_query = std::to_string(opt.cases) + " targeted cases";
  run.rerun = opt.program + " --seed " + std::to_string(opt.seed) + " --cases " + std::to_string(opt.cases);
  run.under_test = std::string(subject.name) + " (the subject verified)";
  std::vector<report::QueryReport> reps{rep};
  std::error_code ec;
  std::filesystem::create_directories(opt.out, ec);
  report::write_json(opt.out / "report.json", run, reps, {});
  report::write_html(opt.out / "report.html", run, reps, {});
  if (!opt.junit.empty()) report::write_junit(opt.junit, run, reps, {});
  return opt.out / "report.html";
}

template <QueryId Q>
VerifyResult run_cases(const ImplOf<Q>& subject, const std::vector<Tagged<typename QueryTraits<Q>::Case>>& all,
                       const std::vector<int>& index, const VerifyOptions& opt, const RunHooks<Q>& hooks = {});

template <QueryId Q>
VerifyResult verify_cases(const ImplOf<Q>& subject, const VerifyOptions& opt) {
  std::vector<int> index(std::max(0, opt.cases));
  for (int i = 0; i < opt.cases; ++i) index[i] = i;
  return run_cases<Q>(subject, gen::draw<Q>(opt.seed, opt.cases), index, opt);
}

/// verify() on the given cases (each tagged: its mode, or its file's name),
/// case k numbered index[k].
template <QueryId Q>
VerifyResult run_cases(const ImplOf<Q>& subject, const std::vector<Tagged<typename QueryTraits<Q>::Case>>& all,
                       const std::vector<int>& all_index, const VerifyOptions& opt, const RunHooks<Q>& hooks) {
  using Case = typename QueryTraits<Q>::Case;
  const auto start = std::chrono::steady_clock::now();
  // The cases the subject can state (all of them unless it says otherwise).
  std::vector<Tagged<Case>> cases;
  std::vector<int> index;  // case i's number
  int not_expressed = 0;
  for (std::size_t k = 0; k < all.size(); ++k) {
    if (!subject_states(all[k].first, subject)) {
      ++not_expressed;
      continue;
    }
    cases.push_back(all[k]);
    index.push_back(k < all_index.size() ? all_index[k] : static_cast<int>(k));
  }
  if (opt.summary)
    std::fprintf(stderr, "verify %s against %s: %d targeted cases, seed %llu%s\n", subject.name, info(Q).name,
                 static_cast<int>(all.size()), static_cast<unsigned long long>(opt.seed), opt.isolate ? "" : ", in process");
  if (opt.summary) std::printf("%s\n", claims_text<Q>(subject).c_str());
  std::fflush(stdout);

  Tally tally;
  for (const auto& c : cases) tally.modes.push_back(c.second);
  int shrunk = 0;  // counterexamples shrunk while checking the current case
  // A failure saved (the first opt.max_saved of its property, at most
  // kMaxSavedPerSignature of its signature), shrunk while it fails the same
  // property (not a crash or a hang: the subject is not asked again), and
  // announced.
  auto save = [&](int i, const Failure& f, bool ask_subject) -> std::filesystem::path {
    std::filesystem::path path;
    if (tally.capped(i, f.property, opt.max_saved)) return path;
    Case c = cases[i].first;
    Failure shown = f;
    if (ask_subject && opt.shrink_budget > 0) {
      Shrunk how;
      // Failing the same property, wherever it comes among the case's
      // failures (a property that fails after another is shrunk too).
      const auto same = [&](const Case& k) -> CheckResult {
        for (Failure& g : guarded_every(k, subject))
          if (g.property == f.property) return std::move(g);
        return std::nullopt;
      };
      c = shrink(
          c, [&](const Case& k) { return same(k).has_value(); }, opt.shrink_budget, &how);
      if (how.simplified > 0) {
        ++shrunk;
        if (CheckResult g = same(c)) shown = std::move(*g);
        shown.detail += " (shrunk: " + std::to_string(how.simplified) + " numbers simplified)";
      }
    }
    std::string drawing;
    if (!save_failure<Q>(c, subject, shown, opt, index[i], cases[i].second, path, ask_subject, &drawing)) return {};
    if (tally.rep.drawings.size() < report::kInlineDrawings) tally.rep.drawings.push_back(std::move(drawing));
    if (!opt.quiet)
      std::printf("FAIL %s %s (case %d, %s): %s\n  drawn: %s\n  replay: %s\n", subject.name, f.property.c_str(), index[i],
                  cases[i].second.c_str(), shown.detail.c_str(),
                  std::filesystem::path(path).replace_extension(".html").string().c_str(),
                  replay_command(opt, path).c_str());
    std::fflush(stdout);
    return path;
  };
  // Every property, the figures of the report and one call timed; the
  // evaluation and the failures kept in this process (which saves and, in
  // process, counts them next; a child's line carries the figures).
  std::vector<std::vector<Failure>> found(cases.size());
  std::vector<Evaluation> evaluations(opt.isolate ? 0 : cases.size());
  auto check = [&](int i) {
    detail::CaseLine line;
    const Case& c = cases[i].first;
    bool answered = false;
    const Evaluation e =
        hooks.evaluate ? truth_of<Q>(c, subject, &answered, [&] { return hooks.evaluate(index[i], c); })
                       : truth_of<Q>(c, subject, &answered);
    std::vector<Failure>& failures = found[i];
    failures = guarded_every(c, subject, answered ? &e : nullptr);
    try {
      const auto t0 = std::chrono::steady_clock::now();
      const bool hit = Spec<Q>::hit(c, subject);
      line.ns = std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - t0).count();
      if (hit && line.ns < 0) std::puts("");  // keeps the call
    } catch (...) {
    }
    if (opt.isolate) line.figures = report::to_json(e);
    else evaluations[i] = e;
    for (const Failure& f : failures) line.properties.push_back(f.property);
    return line;
  };
  auto save_all = [&](int i, detail::CaseLine& line, bool ask_subject) {
    std::vector<std::string> files;
    shrunk = 0;
    for (std::size_t k = 0; k < line.properties.size(); ++k) {
      const Failure f = k < found[i].size()
                            ? found[i][k]
                            : Failure{line.properties[k], "(the subject ended the process while this failure was being shrunk)"};
      files.push_back(save(i, f, ask_subject).string());
    }
    line.shrunk += shrunk;
    return files;
  };
  auto absorb = [&](int i, const detail::CaseLine& line) {
    Evaluation read;
    if (!line.figures.empty()) report::from_json(line.figures, read);
    const Evaluation& e = line.figures.empty() && i < static_cast<int>(evaluations.size()) ? evaluations[i] : read;
    tally.add(Q, i, line, e);
    if (hooks.counted) hooks.counted(index[i], e, line.properties);
    found[i].clear();
    if (i < static_cast<int>(evaluations.size())) evaluations[i] = Evaluation{};
  };
  auto lost = [&](int i, const Failure& f) {
    ++tally.rep.cases;  // run, and failed without an answer to count
    tally.fail(i, {f.property}, {save(i, f, false).string()});
  };
  const int ran =
      detail::run_guarded(static_cast<int>(cases.size()),
                          {opt.isolate, opt.case_seconds, opt.seconds, opt.isolate ? 1 : opt.threads, opt.progress},
                          {check, save_all, absorb, lost});
  VerifyResult& res = tally.res;
  res.cases = ran;
  tally.rep.stopped_by_time = ran < static_cast<int>(cases.size());
  res.not_expressed = not_expressed;
  tally.rep.not_expressed = not_expressed;
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  complete_figures<Q>(subject, opt, tally, seconds);
  if (opt.report) res.report = write_report<Q>(subject, opt, tally.rep);
  res.figures = tally.rep;
  if (!opt.summary) return res;

  std::printf("verify %s (%s): %d cases, seed %llu: %s\n", subject.name, info(Q).name, res.cases,
              static_cast<unsigned long long>(opt.seed), res.failures == 0 ? "every property held" : "FAILED");
  if (res.not_expressed)
    std::printf("  %d cases not asked: the subject cannot state them (its expresses(), or a scale outside its precision's range)\n",
                res.not_expressed);
  if (res.failures) std::printf("  %d failing cases; by property (a case may fail several):\n", res.failures);
  for (const auto& [property, n] : res.by_property) std::printf("  %6d %s\n", n, property.c_str());
  if (!res.saved.empty())
    std::printf("  %zu saved (at most %d per property and %d per property and generator mode) under %s\n",
                res.saved.size(), opt.max_saved, report::kMaxSavedPerSignature, (opt.out / info(Q).name).string().c_str());
  if (!res.report.empty()) std::printf("  report: %s (and report.json)\n", res.report.string().c_str());
  return res;
}

template <QueryId Q>
int replay_files(const ImplOf<Q>& subject, const std::vector<std::filesystem::path>& files) {
  int failed = 0;
  for (const auto& path : files) {
    const ParseResult pr = load_case(path);
    std::optional<std::string> err = pr.ok() ? case_error(pr.value) : std::optional<std::string>(pr.error);
    if (!err && pr.value.query != Q) err = std::string("a case of ") + info(pr.value.query).name + ", not of " + info(Q).name;
    if (err) {
      std::fprintf(stderr, "replay: %s: %s\n", path.string().c_str(), err->c_str());
      ++failed;
      continue;
    }
    const auto c = to_case<Q>(pr.value);
    bool answered = false;
    const Evaluation e = truth_of<Q>(c, subject, &answered);
    const std::vector<Failure> fs = guarded_every(c, subject, answered ? &e : nullptr);
    std::printf("%s %s\n  %s: %s\n  truth: %s\n", fs.empty() ? "PASS" : "FAIL", path.string().c_str(), subject.name,
                e.prod_text.c_str(), e.truth_text.c_str());
    for (const Failure& f : fs) std::printf("  %s: %s\n", f.property.c_str(), f.detail.c_str());
    if (!fs.empty()) ++failed;
  }
  return failed;
}

/// verify() on case files of Q (each tagged by its file name); a file that
/// cannot be read, or is of another query, is said on stderr and left out.
template <QueryId Q>
VerifyResult verify_file_cases(const ImplOf<Q>& subject, const std::vector<std::filesystem::path>& files,
                               const VerifyOptions& opt) {
  std::vector<Tagged<typename QueryTraits<Q>::Case>> cases;
  for (const auto& path : files) {
    const ParseResult pr = load_case(path);
    std::optional<std::string> err = pr.ok() ? case_error(pr.value) : std::optional<std::string>(pr.error);
    if (!err && pr.value.query != Q) err = std::string("a case of ") + info(pr.value.query).name;
    if (err) {
      std::fprintf(stderr, "verify: %s: %s\n", path.string().c_str(), err->c_str());
      continue;
    }
    cases.emplace_back(to_case<Q>(pr.value), path.stem().string());
  }
  VerifyOptions o = opt;
  o.cases = static_cast<int>(cases.size());
  std::vector<int> index(cases.size());
  for (std::size_t k = 0; k < cases.size(); ++k) index[k] = static_cast<int>(k);
  return run_cases<Q>(subject, cases, index, o);
}

template <QueryId Q>
int verify_program(const ImplOf<Q>& subject, int argc, char** argv) {
  VerifyOptions opt;
  std::vector<std::filesystem::path> replays;
  const int rc = detail::parse_verify_command(
      argc, argv,
      std::string("Holds subject '") + subject.name + "' to every property of " + info(Q).name +
          " on generated cases; saves and draws each failing case.",
      "cases",
      "case files saved per failing property (and at most " + std::to_string(report::kMaxSavedPerSignature) +
          " per property and generator mode)",
      opt, replays);
  if (rc >= 0) return rc;
  if (!replays.empty()) {
    for (const auto& path : replays) {  // a file of another query (of any family) is a usage error
      const std::string q = declared_query(path);
      if (!q.empty() && q != info(Q).name) {
        std::fprintf(stderr, "%s: %s is a case of %s; %s verifies %s\n", opt.program.c_str(), path.string().c_str(),
                     q.c_str(), subject.name, info(Q).name);
        return 2;
      }
    }
    return replay_files<Q>(subject, replays) == 0 ? 0 : 1;
  }
  return verify_cases<Q>(subject, opt).failures == 0 ? 0 : 1;
}

}  // namespace

template <QueryId Q>
VerifyResult verify(const ImplOf<Q>& subject, const std::vector<std::pair<typename QueryTraits<Q>::Case, std::string>>& cases,
                    const std::vector<int>& index, const VerifyOptions& opt, const RunHooks<Q>& hooks) {
  return run_cases<Q>(subject, cases, index, opt, hooks);
}
template <QueryId Q>
VerifyResult verify(const ImplOf<Q>& subject, const VerifyOptions& opt) {
  return verify_cases<Q>(subject, opt);
}
template <QueryId Q>
VerifyResult verify(const ImplOf<Q>& subject, const std::vector<std::filesystem::path>& files, const VerifyOptions& opt) {
  return verify_file_cases<Q>(subject, files, opt);
}
template <QueryId Q>
int replay(const ImplOf<Q>& subject, const std::vector<std::filesystem::path>& files) {
  return replay_files<Q>(subject, files);
}
template <QueryId Q>
int verify(const ImplOf<Q>& subject, int argc, char** argv) {
  return verify_program<Q>(subject, argc, argv);
}

// The subject inside a plain overload's argument.
template <class Impl>
const Impl& unwrap(const Impl& s) {
  return s;
}
template <QueryId Q>
const ImplOf<Q>& unwrap(const NamedOnly<Q>& s) {
  return s.subject;
}

#define GEOMCHECK_X(id, kind, A, B, summary)                                                                   \
  template VerifyResult verify<QueryId::id>(const ImplOf<QueryId::id>&, const VerifyOptions&);                \
  template VerifyResult verify<QueryId::id>(const ImplOf<QueryId::id>&, const std::vector<std::filesystem::path>&, \
                                            const VerifyOptions&);                                             \
  template int replay<QueryId::id>(const ImplOf<QueryId::id>&, const std::vector<std::filesystem::path>&);    \
  template int verify<QueryId::id>(const ImplOf<QueryId::id>&, int, char**);                                 \
  template VerifyResult verify<QueryId::id>(const ImplOf<QueryId::id>&,                                       \
                                            const std::vector<std::pair<QueryTraits<QueryId::id>::Case, std::string>>&, \
                                            const std::vector<int>&, const VerifyOptions&, const RunHooks<QueryId::id>&); \
  VerifyResult verify(const PlainSubject<QueryId::id>& subject, const VerifyOptions& opt) {                   \
    return verify_cases<QueryId::id>(unwrap(subject), opt);                                                           \
  }                                                                                                           \
  VerifyResult verify(const PlainSubject<QueryId::id>& subject, const std::vector<std::filesystem::path>& files, \
                      const VerifyOptions& opt) {                                                              \
    return verify_file_cases<QueryId::id>(unwrap(subject), files, opt);                                               \
  }                                                                                                           \
  int replay(const PlainSubject<QueryId::id>& subject, const std::vector<std::filesystem::path>& files) {     \
    return replay_files<QueryId::id>(unwrap(subject), files);                                                         \
  }                                                                                                           \
  int verify(const PlainSubject<QueryId::id>& subject, int argc, char** argv) {                               \
    return verify_program<QueryId::id>(unwrap(subject), argc, argv);                                                  \
  }
GEOMCHECK_QUERY_LIST(GEOMCHECK_X)
#undef GEOMCHECK_X

}  // namespace geomcheck
