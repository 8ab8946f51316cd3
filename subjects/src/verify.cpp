// geomcheck — verify() and replay() for any subject (verify.hpp).
#include "geomcheck/verify.hpp"

#include <CLI/CLI.hpp>

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

namespace geomcheck {

namespace {

/// `word` as one word of a POSIX shell command line: as it is when it has
/// only characters no shell reads specially, else in single quotes.
std::string shell_quote(const std::string& word) {
  const bool plain = !word.empty() && word.find_first_not_of("ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz"
                                                            "0123456789_-+./:=@%,") == std::string::npos;
  if (plain) return word;
  std::string q = "'";
  for (char ch : word) q += ch == '\'' ? std::string("'\\''") : std::string(1, ch);
  return q + "'";
}

/// The replay command of a saved case, less its path.
std::string replay_prefix(const VerifyOptions& opt) {
  return opt.replay.empty() ? shell_quote(opt.program) + " --replay " : opt.replay;
}
/// The replay command of a saved case.
std::string replay_command(const VerifyOptions& opt, const std::filesystem::path& path) {
  return replay_prefix(opt) + shell_quote(path.string());
}

/// check_all, with a subject that throws failing the case instead of
/// ending the run.
/// `known`: the subject's evaluation of c, when it answered (judged instead
/// of asking the truth again).
template <class Case, class Impl>
CheckResult guarded_check(const Case& c, const Impl& subject, const Evaluation* known = nullptr) {
  try {
    return known ? check_all(c, *known, subject) : check_all(c, subject);
  } catch (const std::exception& ex) {
    return Failure{"subject-threw", std::string("the subject threw: ") + ex.what()};
  } catch (...) {
    return Failure{"subject-threw", "the subject threw something that is not a std::exception"};
  }
}

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
template <QueryId Q>
Evaluation truth_of(const typename QueryTraits<Q>::Case& c, const ImplOf<Q>& subject, bool* answered = nullptr) {
  if (answered) *answered = true;
  try {
    return evaluate(c, subject);
  } catch (...) {
    if (answered) *answered = false;
    Evaluation e = evaluate(c, production_of<Q>());
    e.prod_text = "threw";
    return e;
  }
}

/// Saves a failing case: its case file (the truth's verdict filed, none on
/// invalid input, as replay expects) and, beside it, a page drawing it.
template <QueryId Q>
bool save_failure(const typename QueryTraits<Q>::Case& c, const ImplOf<Q>& subject, const Failure& f,
                  const VerifyOptions& opt, int index, std::filesystem::path& path, bool with_answer) {
  const std::filesystem::path dir = opt.out / info(Q).name;
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  char name[96];
  std::snprintf(name, sizeof name, "%05d-%s.case", index, f.property.c_str());
  path = dir / name;
  const Evaluation e = with_answer ? truth_of<Q>(c, subject) : evaluate(c, production_of<Q>());
  CaseFile file = from_case<Q>(c, "verify " + std::string(subject.name) + " seed=" + std::to_string(opt.seed) +
                                      " case=" + std::to_string(index),
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

/// What one case gave: its failing properties (none when every property
/// held), the evaluation's figures (the report's counts and error measures)
/// and the time of one call of the subject.
struct Outcome {
  std::vector<Failure> failures;
  Evaluation e;
  double ns = NAN;
};

/// What verify() gathers: the counts returned to the caller and the report.
struct Tally {
  VerifyResult res;
  report::QueryReport rep;
  std::vector<double> ns;  ///< the subject's time per call, one per case
  std::vector<std::string> modes;  ///< each case's generator mode: a failure's signature is property @ mode
  std::map<std::string, int> saved_of_property, saved_of_signature;  ///< case files saved, for the caps
  /// Case i's outcome (`saved`: the case file of each failing property,
  /// empty where none was saved).
  void add(QueryId id, int i, const Outcome& o, const std::vector<std::filesystem::path>& saved) {
    report::add_evaluation(rep, id, o.e);
    if (std::isfinite(o.ns)) ns.push_back(o.ns);
    fail(i, o.failures, saved);
  }
  /// Case i failing these properties (and the case file of each, when one
  /// was saved): one failing case, counted under each of its properties.
  void fail(int i, const std::vector<Failure>& failures, const std::vector<std::filesystem::path>& saved) {
    if (failures.empty()) return;
    ++res.failures;
    ++rep.check_failures;
    if (i < static_cast<int>(modes.size()) &&
        (res.failed_cases.empty() || res.failed_cases.back() != modes[i]))
      res.failed_cases.push_back(modes[i]);
    for (std::size_t k = 0; k < failures.size(); ++k) {
      const std::string& property = failures[k].property;
      ++res.by_property[property];
      ++rep.failures_by_property[property];
      ++rep.failures_by_signature[signature(i, property)];
      if (k < saved.size() && !saved[k].empty()) {
        ++saved_of_property[property];
        ++saved_of_signature[signature(i, property)];
        res.saved.push_back(saved[k]);
        rep.counterexamples.push_back(saved[k].string());
      }
    }
  }
  /// The signature of case i failing `property`.
  std::string signature(int i, const std::string& property) const {
    return property + " @ " + (i < static_cast<int>(modes.size()) ? modes[i] : std::string("?"));
  }
};

/// Separates the properties of one case (and their case files) on the
/// child's line: no property name or path holds it.
constexpr char kSep = '\x1f';
/// The fields of `text` separated by kSep (none in an empty text).
std::vector<std::string> split(const std::string& text) {
  std::vector<std::string> out;
  if (text.empty()) return out;
  std::size_t from = 0;
  for (std::size_t at; (at = text.find(kSep, from)) != std::string::npos; from = at + 1) out.push_back(text.substr(from, at - from));
  out.push_back(text.substr(from));
  return out;
}

/// Runs check(i) for every i in [0, n) in a child process, so that a
/// subject that crashes (a signal: a segfault, an abort) fails its case
/// instead of ending the run, and one that hangs (no answer within
/// case_seconds) fails it too: the case is counted as "subject-crashed" or
/// "subject-hung" (saved without asking the subject again) and a new
/// child goes on after it. A failure is saved and printed where it is found
/// (save(i, failure, ask_subject) returns the case file, or nothing past
/// the cap), and counted in `tally` by the parent from the child's line.
/// Without `isolate` (or without fork), in process: the subject's state
/// changes stay, and a crash ends the run.
template <class Check, class Save>
void run_guarded(QueryId id, int n, bool isolate, unsigned case_seconds, Tally& tally, Check&& check, Save&& save) {
  int next = 0;
  while (next < n) {
    int fds[2];
    const pid_t pid = isolate && ::pipe(fds) == 0 ? ::fork() : -1;
    if (pid < 0) {  // no child: in process
      for (; next < n; ++next) {
        const Outcome o = check(next);
        std::vector<std::filesystem::path> saved;
        for (const Failure& f : o.failures) saved.push_back(save(next, f, true));
        tally.add(id, next, o, saved);
      }
      return;
    }
    // The child: a line per case, "<i>\t<properties>\t<saved case files>\t<shrunk>\t<ns per call, a hex
    // float>\t<the evaluation, report::evaluation_line: every field>", the properties ("-": none) and
    // their case files (empty: not saved) each separated by kSep.
    if (pid == 0) {
      ::close(fds[0]);
      FILE* out = ::fdopen(fds[1], "w");
      for (int i = next; i < n; ++i) {
        ::alarm(case_seconds);  // a subject that hangs (checks or shrink) is ended by SIGALRM
        const Outcome o = check(i);
        std::vector<std::filesystem::path> saved;
        const int shrunk_before = tally.rep.shrunk;
        for (const Failure& f : o.failures) saved.push_back(save(i, f, true));
        tally.fail(i, o.failures, saved);  // the child's copy: the caps
        ::alarm(0);
        std::string properties, files;
        for (std::size_t k = 0; k < o.failures.size(); ++k) {
          properties += (k ? std::string(1, kSep) : std::string()) + o.failures[k].property;
          files += (k ? std::string(1, kSep) : std::string()) + saved[k].string();
        }
        std::fprintf(out, "%d\t%s\t%s\t%d\t%a\t%s\n", i, properties.empty() ? "-" : properties.c_str(), files.c_str(),
                     tally.rep.shrunk - shrunk_before, o.ns, report::evaluation_line(o.e).c_str());
        std::fflush(out);
      }
      std::fflush(stdout);
      std::_Exit(0);
    }
    ::close(fds[1]);
    FILE* in = ::fdopen(fds[0], "r");
    std::string line;
    for (int ch; (ch = std::fgetc(in)) != EOF;) {
      if (ch != '\n') {
        line += static_cast<char>(ch);
        continue;
      }
      const std::size_t t1 = line.find('\t'), t2 = line.find('\t', t1 + 1), t3 = line.find('\t', t2 + 1);
      const std::size_t t4 = t3 == std::string::npos ? t3 : line.find('\t', t3 + 1);
      const std::size_t t5 = t4 == std::string::npos ? t4 : line.find('\t', t4 + 1);
      if (t5 != std::string::npos) {
        Outcome o;
        o.ns = std::strtod(line.c_str() + t4 + 1, nullptr);
        o.e = report::evaluation_from_line(line.substr(t5 + 1));
        const std::string properties = line.substr(t1 + 1, t2 - t1 - 1);
        std::vector<std::filesystem::path> saved;
        if (properties != "-") {
          for (const std::string& p : split(properties)) o.failures.push_back(Failure{p, ""});
          for (const std::string& f : split(line.substr(t2 + 1, t3 - t2 - 1))) saved.emplace_back(f);
        }
        tally.add(id, std::atoi(line.c_str()), o, saved);
        tally.rep.shrunk += std::atoi(line.c_str() + t3 + 1);  // shrunk in the child
      }
      next = std::atoi(line.c_str()) + 1;
      line.clear();
    }
    std::fclose(in);
    int status = 0;
    ::waitpid(pid, &status, 0);
    if (next < n && !(WIFEXITED(status) && WEXITSTATUS(status) == 0)) {
      const bool hung = WIFSIGNALED(status) && WTERMSIG(status) == SIGALRM;
      const std::string how = WIFSIGNALED(status) ? std::string("signal ") + std::to_string(WTERMSIG(status))
                                                  : "exit status " + std::to_string(WEXITSTATUS(status));
      const Failure f = hung ? Failure{"subject-hung", "no answer within " + std::to_string(case_seconds) + " s"}
                             : Failure{"subject-crashed", "the subject ended the process (" + how + ")"};
      ++tally.rep.cases;  // run, and failed without an answer to count
      tally.fail(next, {f}, {save(next, f, false)});
      ++next;
    }
  }
}


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
  rep.oracle_us = rep.cases ? seconds * 1e6 / rep.cases : NAN;
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
VerifyResult run_cases(const ImplOf<Q>& subject, const std::vector<Tagged<typename QueryTraits<Q>::Case>>& cases,
                       const VerifyOptions& opt);

template <QueryId Q>
VerifyResult verify_cases(const ImplOf<Q>& subject, const VerifyOptions& opt) {
  using Case = typename QueryTraits<Q>::Case;
  const auto gen = Spec<Q>::targeted();
  // The campaign's derivation: the same seed draws the same cases there.
  rc::Random random(opt.seed ^ (0x9e3779b97f4a7c15ull * (static_cast<std::uint64_t>(Q) + 1)));
  std::vector<Tagged<Case>> cases;
  cases.reserve(opt.cases);
  for (int i = 0; i < opt.cases; ++i) cases.push_back(gen(random.split(), 50).value());
  return run_cases<Q>(subject, cases, opt);
}

/// verify() on the given cases (each tagged: its mode, or its file's name).
template <QueryId Q>
VerifyResult run_cases(const ImplOf<Q>& subject, const std::vector<Tagged<typename QueryTraits<Q>::Case>>& all,
                       const VerifyOptions& opt) {
  using Case = typename QueryTraits<Q>::Case;
  const auto start = std::chrono::steady_clock::now();
  // The cases the subject can state (all of them unless it says otherwise).
  std::vector<Tagged<Case>> cases;
  int not_expressed = 0;
  for (const auto& c : all) {
    if (subject_states(c.first, subject)) cases.push_back(c);
    else ++not_expressed;
  }
  if (opt.summary)
    std::fprintf(stderr, "verify %s against %s: %d targeted cases, seed %llu%s\n", subject.name, info(Q).name,
                 opt.cases, static_cast<unsigned long long>(opt.seed), opt.isolate ? "" : ", in process");
  if (opt.summary) std::printf("%s\n", claims_text<Q>(subject).c_str());
  std::fflush(stdout);

  Tally tally;
  for (const auto& c : cases) tally.modes.push_back(c.second);
  // A failure saved (the first opt.max_saved of its property, at most
  // kMaxSavedPerSignature of its signature), shrunk while it fails the same
  // property (not a crash or a hang: the subject is not asked again), and
  // announced.
  auto save = [&](int i, const Failure& f, bool ask_subject) -> std::filesystem::path {
    std::filesystem::path path;
    if (tally.saved_of_property[f.property] >= opt.max_saved ||
        tally.saved_of_signature[tally.signature(i, f.property)] >= report::kMaxSavedPerSignature)
      return path;
    Case c = cases[i].first;
    Failure shown = f;
    if (ask_subject && opt.shrink_budget > 0) {
      Shrunk how;
      c = shrink(
          c,
          [&](const Case& k) {
            const CheckResult g = guarded_check(k, subject);
            return g && g->property == f.property;
          },
          opt.shrink_budget, &how);
      if (how.simplified > 0) {
        ++tally.rep.shrunk;
        if (const CheckResult g = guarded_check(c, subject)) shown = *g;
        shown.detail += " (shrunk: " + std::to_string(how.simplified) + " numbers simplified)";
      }
    }
    if (!save_failure<Q>(c, subject, shown, opt, i, path, ask_subject)) return {};
    if (!opt.quiet)
      std::printf("FAIL %s %s (case %d, %s): %s\n  drawn: %s\n  replay: %s\n", subject.name, f.property.c_str(), i,
                  cases[i].second.c_str(), shown.detail.c_str(),
                  std::filesystem::path(path).replace_extension(".html").string().c_str(),
                  replay_command(opt, path).c_str());
    std::fflush(stdout);
    return path;
  };
  // Every property, the figures of the report, and one call timed.
  auto check = [&](int i) {
    Outcome o;
    const Case& c = cases[i].first;
    bool answered = false;
    o.e = truth_of<Q>(c, subject, &answered);
    o.failures = guarded_every(c, subject, answered ? &o.e : nullptr);
    try {
      const auto t0 = std::chrono::steady_clock::now();
      const bool hit = Spec<Q>::hit(c, subject);
      o.ns = std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - t0).count();
      if (hit && o.ns < 0) std::puts("");  // keeps the call
    } catch (...) {
    }
    return o;
  };
  run_guarded(Q, static_cast<int>(cases.size()), opt.isolate, opt.case_seconds, tally, check, save);
  VerifyResult& res = tally.res;
  res.cases = static_cast<int>(cases.size());
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
  return run_cases<Q>(subject, cases, o);
}

template <QueryId Q>
int verify_program(const ImplOf<Q>& subject, int argc, char** argv) {
  VerifyOptions opt;
  if (argc > 0 && argv[0]) opt.program = argv[0];
  std::vector<std::filesystem::path> replays;
  CLI::App app{std::string("Holds subject '") + subject.name + "' to every property of " + info(Q).name +
               " on generated cases; saves and draws each failing case."};
  app.add_option("--cases", opt.cases, "targeted cases to draw")->capture_default_str()->check(CLI::PositiveNumber);
  app.add_option("--seed", opt.seed, "the seed (the same seed draws the same cases)")->capture_default_str();
  app.add_option("--out", opt.out, "where the failing cases go (one folder per query)")->capture_default_str();
  app.add_option("--max-saved", opt.max_saved,
                 "case files saved per failing property (and at most " + std::to_string(report::kMaxSavedPerSignature) +
                     " per property and generator mode)")
      ->capture_default_str()
      ->check(CLI::NonNegativeNumber);
  bool no_shrink = false;
  app.add_flag("--no-shrink", no_shrink, "save failing cases as found, not shrunk");
  app.add_option("--replay", replays, "replay these case files instead")->check(CLI::ExistingFile);
  app.add_flag("--quiet", opt.quiet, "no line per saved failure");
  app.add_flag("!--in-process", opt.isolate,
               "run the subject in this process (its state changes stay; a crash ends the run)");
  app.add_flag("!--no-report", opt.report, "write no report.json and report.html");
  app.add_option("--junit", opt.junit, "also write a JUnit XML file here");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int rc = app.exit(e);
    return rc == 0 ? 0 : 2;
  }
  if (no_shrink) opt.shrink_budget = 0;
  if (!replays.empty()) {
    for (const auto& path : replays) {  // a file of another query is a usage error
      const ParseResult pr = load_case(path);
      if (pr.ok() && pr.value.query != Q) {
        std::fprintf(stderr, "%s: %s is a case of %s; %s verifies %s\n", opt.program.c_str(), path.string().c_str(),
                     info(pr.value.query).name, subject.name, info(Q).name);
        return 2;
      }
    }
    return replay_files<Q>(subject, replays) == 0 ? 0 : 1;
  }
  for (int i = 0; i < argc; ++i) opt.command += (i ? " " : "") + std::string(argv[i]);
  return verify_cases<Q>(subject, opt).failures == 0 ? 0 : 1;
}

}  // namespace

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
