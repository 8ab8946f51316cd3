// geomcheck — verify() and replay() for any subject (verify.hpp).
#include "geomcheck/verify.hpp"

#include <CLI/CLI.hpp>

#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <system_error>

#include "geomcheck/casefile.hpp"
#include "geomcheck/properties/spec.hpp"
#include "geomcheck/reports/draw.hpp"
#include "geomcheck/reports/report.hpp"

namespace geomcheck {

namespace {

/// check_all, with a subject that throws failing the case instead of
/// ending the run.
template <class Case, class Impl>
CheckResult guarded_check(const Case& c, const Impl& subject) {
  try {
    return check_all(c, subject);
  } catch (const std::exception& ex) {
    return Failure{"subject-threw", std::string("the subject threw: ") + ex.what()};
  } catch (...) {
    return Failure{"subject-threw", "the subject threw something that is not a std::exception"};
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
template <QueryId Q>
Evaluation truth_of(const typename QueryTraits<Q>::Case& c, const ImplOf<Q>& subject) {
  try {
    return evaluate(c, subject);
  } catch (...) {
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
  const std::string drawing = draw::views(
      c.a, c.b, report::html(std::string(name) + ": " + f.property + ": " + f.detail + "; truth: " + e.truth_text), {},
      &ans);
  report::write_counterexample_page(std::filesystem::path(path).replace_extension(".html"), name, drawing, subject.name,
                                    opt.program + " --replay " + path.string());
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
  return t;
}

/// A failure counted into res (and its case file, when one was saved).
void count(VerifyResult& res, const std::string& property, const std::filesystem::path& saved) {
  ++res.failures;
  ++res.by_property[property];
  if (!saved.empty()) res.saved.push_back(saved);
}

/// Runs check(i) for every i in [0, n) in a child process, so that a
/// subject that crashes (a signal: a segfault, an abort) fails its case
/// instead of ending the run, and one that hangs (no answer within
/// case_seconds) fails it too: the case is counted as "subject-crashed" or
/// "subject-hung" (saved without asking the subject again) and a new
/// child goes on after it. A failure is saved and printed where it is found
/// (save(i, failure, ask_subject) returns the case file, or nothing past
/// the cap), and counted in res by the parent. Without fork, in process.
template <class Check, class Save>
void run_guarded(int n, unsigned case_seconds, VerifyResult& res, Check&& check, Save&& save) {
  int next = 0;
  while (next < n) {
    int fds[2];
    const pid_t pid = ::pipe(fds) == 0 ? ::fork() : -1;
    if (pid < 0) {  // no child: in process
      for (; next < n; ++next)
        if (const CheckResult f = check(next)) count(res, f->property, save(next, *f, true));
      return;
    }
    if (pid == 0) {  // the child: a line per case, "<i>" or "<i>\t<property>\t<saved case file>"
      ::close(fds[0]);
      FILE* out = ::fdopen(fds[1], "w");
      for (int i = next; i < n; ++i) {
        ::alarm(case_seconds);  // a subject that hangs is ended by SIGALRM
        const CheckResult f = check(i);
        ::alarm(0);
        if (!f) {
          std::fprintf(out, "%d\n", i);
        } else {
          const std::filesystem::path saved = save(i, *f, true);
          count(res, f->property, saved);  // the child's copy: the cap per property
          std::fprintf(out, "%d\t%s\t%s\n", i, f->property.c_str(), saved.string().c_str());
        }
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
      const std::size_t t1 = line.find('\t');
      if (t1 != std::string::npos) {
        const std::size_t t2 = line.find('\t', t1 + 1);
        count(res, line.substr(t1 + 1, t2 - t1 - 1), line.substr(t2 + 1));
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
      count(res, f.property, save(next, f, false));
      ++next;
    }
  }
}


template <QueryId Q>
VerifyResult verify_cases(const ImplOf<Q>& subject, const VerifyOptions& opt) {
  using Case = typename QueryTraits<Q>::Case;
  VerifyResult res;
  const auto gen = Spec<Q>::targeted();
  // The campaign's derivation: the same seed draws the same cases there.
  rc::Random random(opt.seed ^ (0x9e3779b97f4a7c15ull * (static_cast<std::uint64_t>(Q) + 1)));
  std::vector<Tagged<Case>> cases;
  cases.reserve(opt.cases);
  for (int i = 0; i < opt.cases; ++i) cases.push_back(gen(random.split(), 50).value());
  std::fprintf(stderr, "verify %s against %s: %d targeted cases, seed %llu\n", subject.name, info(Q).name, opt.cases,
               static_cast<unsigned long long>(opt.seed));
  std::printf("%s\n", claims_text<Q>(subject).c_str());
  std::fflush(stdout);

  // A failure saved (the first opt.max_saved of its property) and announced.
  auto save = [&](int i, const Failure& f, bool ask_subject) -> std::filesystem::path {
    std::filesystem::path path;
    const auto it = res.by_property.find(f.property);
    if (it != res.by_property.end() && it->second >= opt.max_saved) return path;
    if (!save_failure<Q>(cases[i].first, subject, f, opt, i, path, ask_subject)) return {};
    if (!opt.quiet)
      std::printf("FAIL %s (case %d, %s): %s\n  drawn: %s\n  replay: %s --replay %s\n", f.property.c_str(), i,
                  cases[i].second.c_str(), f.detail.c_str(),
                  std::filesystem::path(path).replace_extension(".html").string().c_str(), opt.program.c_str(),
                  path.string().c_str());
    std::fflush(stdout);
    return path;
  };
  run_guarded(static_cast<int>(cases.size()), opt.case_seconds, res, [&](int i) { return guarded_check(cases[i].first, subject); }, save);
  res.cases = static_cast<int>(cases.size());

  std::printf("verify %s (%s): %d cases, seed %llu: %s\n", subject.name, info(Q).name, res.cases,
              static_cast<unsigned long long>(opt.seed), res.failures == 0 ? "every property held" : "FAILED");
  for (const auto& [property, n] : res.by_property) std::printf("  %6d failing cases: %s\n", n, property.c_str());
  if (!res.saved.empty())
    std::printf("  %zu saved (at most %d per property) under %s\n", res.saved.size(), opt.max_saved,
                (opt.out / info(Q).name).string().c_str());
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
    const CheckResult f = guarded_check(c, subject);
    const Evaluation e = truth_of<Q>(c, subject);
    std::printf("%s %s\n  %s: %s\n  truth: %s\n", f ? "FAIL" : "PASS", path.string().c_str(), subject.name,
                e.prod_text.c_str(), e.truth_text.c_str());
    if (f) {
      std::printf("  %s: %s\n", f->property.c_str(), f->detail.c_str());
      ++failed;
    }
  }
  return failed;
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
  app.add_option("--max-saved", opt.max_saved, "case files saved per failing property")->capture_default_str();
  app.add_option("--replay", replays, "replay these case files instead")->check(CLI::ExistingFile);
  app.add_flag("--quiet", opt.quiet, "no line per saved failure");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int rc = app.exit(e);
    return rc == 0 ? 0 : 2;
  }
  if (!replays.empty()) return replay_files<Q>(subject, replays) == 0 ? 0 : 1;
  return verify_cases<Q>(subject, opt).failures == 0 ? 0 : 1;
}

}  // namespace

#define GEOMCHECK_X(id, kind, A, B, summary)                                                          \
  VerifyResult verify(const ImplOf<QueryId::id>& subject, const VerifyOptions& opt) {                 \
    return verify_cases<QueryId::id>(subject, opt);                                                   \
  }                                                                                                   \
  int replay(const ImplOf<QueryId::id>& subject, const std::vector<std::filesystem::path>& files) {   \
    return replay_files<QueryId::id>(subject, files);                                                 \
  }                                                                                                   \
  int verify(const ImplOf<QueryId::id>& subject, int argc, char** argv) {                             \
    return verify_program<QueryId::id>(subject, argc, argv);                                          \
  }
GEOMCHECK_QUERY_LIST(GEOMCHECK_X)
#undef GEOMCHECK_X

}  // namespace geomcheck
