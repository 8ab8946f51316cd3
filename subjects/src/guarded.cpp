// geomcheck — verify()'s case runner (guarded.hpp).
#include "guarded.hpp"

#include <CLI/CLI.hpp>

#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <mutex>
#include <thread>

namespace geomcheck::detail {

namespace {

/// Separates the properties of one case (and their case files) on the
/// child's line: no property name or path holds it.
constexpr char kSep = '\x1f';

std::string joined(const std::vector<std::string>& fields) {
  std::string out;
  for (std::size_t k = 0; k < fields.size(); ++k) out += (k ? std::string(1, kSep) : std::string()) + fields[k];
  return out;
}

/// The fields of `text` separated by kSep (none in an empty text).
std::vector<std::string> split(const std::string& text) {
  std::vector<std::string> out;
  if (text.empty()) return out;
  std::size_t from = 0;
  for (std::size_t at; (at = text.find(kSep, from)) != std::string::npos; from = at + 1) out.push_back(text.substr(from, at - from));
  out.push_back(text.substr(from));
  return out;
}

using Clock = std::chrono::steady_clock;

/// The progress line of a run (GuardOptions::progress): on a terminal
/// redrawn every 0.5 s, into a file a line every 10 s (a log stays
/// readable), and the last one when the run ends.
class Progress {
 public:
  Progress(const std::string& label, int n, Clock::time_point start)
      : label_(label), n_(n), start_(start), tty_(::isatty(::fileno(stderr)) != 0) {}
  /// `done` cases so far; shown when the line is due (always when `last`).
  void show(int done, bool last = false) {
    if (label_.empty()) return;
    const double el = std::chrono::duration<double>(Clock::now() - start_).count();
    if (!last && el - shown_ < (tty_ ? 0.5 : 10)) return;
    shown_ = el;
    std::fprintf(stderr, "%s%s %7d / %d cases  %6.0f cases/s  %5.1fs%s", tty_ ? "\r" : "", label_.c_str(), done, n_,
                 done / std::max(el, 1e-9), el, tty_ && !last ? "" : "\n");
  }

 private:
  std::string label_;
  int n_;
  Clock::time_point start_;
  bool tty_;
  double shown_ = 0;
};

/// run_guarded in this process on opt.threads threads, from case `from`:
/// every check first, then save and absorb in case order (a harness error
/// in a check: the case lost). Returns the number of cases run.
int run_in_threads(int from, int n, const GuardOptions& opt, const CaseSteps& steps, Progress& progress,
                   const std::function<bool()>& expired) {
  const int m = n - from;
  std::vector<CaseLine> lines(m);
  std::vector<std::string> errors(m);
  std::vector<char> ran(m, 0);
  std::atomic<int> next{from}, done{0};
  std::mutex mu;
  std::condition_variable all_done;
  int finished = 0;
  auto worker = [&] {
    for (;;) {
      const int i = next++;
      if (i >= n || expired()) break;
      try {
        lines[i - from] = steps.check(i);
      } catch (const std::exception& e) {
        errors[i - from] = e.what();
      } catch (...) {
        errors[i - from] = "an exception that is not a std::exception";
      }
      ran[i - from] = 1;
      ++done;
    }
    std::lock_guard<std::mutex> lock(mu);
    ++finished;
    all_done.notify_one();
  };
  const int threads = std::max(1, std::min(opt.threads, m));
  std::vector<std::thread> pool;
  for (int k = 0; k < threads; ++k) pool.emplace_back(worker);
  {
    std::unique_lock<std::mutex> lock(mu);
    while (!all_done.wait_for(lock, std::chrono::milliseconds(500), [&] { return finished == threads; }))
      progress.show(done);
  }
  for (auto& t : pool) t.join();
  int count = 0;
  for (int i = from; i < n; ++i) {
    if (!ran[i - from]) continue;  // not started: the time ran out
    ++count;
    if (!errors[i - from].empty()) {
      std::fprintf(stderr, "verify: case %d: internal error: %s\n", i, errors[i - from].c_str());
      steps.lost(i, Failure{"harness-error", "the harness failed on this case (" + errors[i - from] + ")"});
      continue;
    }
    CaseLine& line = lines[i - from];
    if (!line.properties.empty()) line.files = steps.save(i, line, true);
    steps.absorb(i, line);
  }
  return count;
}

/// run_guarded's cases, without its last progress line.
int run_cases_guarded(int n, const GuardOptions& opt, const CaseSteps& steps, Progress& progress,
                      const std::function<bool()>& expired);

}  // namespace

int parse_verify_command(int argc, char** argv, const std::string& about, const std::string& unit,
                         const std::string& max_saved_help, VerifyOptions& opt,
                         std::vector<std::filesystem::path>& replays) {
  if (argc > 0 && argv[0]) opt.program = argv[0];
  CLI::App app{about};
  app.add_option("--cases", opt.cases, unit + " to draw")->capture_default_str()->check(CLI::PositiveNumber);
  app.add_option("--seconds", opt.seconds, "start no case after this many seconds (0: no limit)")
      ->capture_default_str()
      ->check(CLI::NonNegativeNumber);
  app.add_option("--seed", opt.seed, "the seed (the same seed draws the same " + unit + ")")->capture_default_str();
  app.add_option("--out", opt.out, "where the failing " + unit + " go (one folder per query)")->capture_default_str();
  app.add_option("--max-saved", opt.max_saved, max_saved_help)->capture_default_str()->check(CLI::NonNegativeNumber);
  bool no_shrink = false;
  app.add_flag("--no-shrink", no_shrink, "save failing " + unit + " as found, not shrunk");
  app.add_option("--replay", replays, "replay these case files instead")->check(CLI::ExistingFile);
  app.add_flag("--quiet", opt.quiet, "no line per saved failure, no progress line (stderr)");
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
  if (!opt.quiet && opt.progress.empty()) opt.progress = "[verify]";
  for (int i = 0; i < argc; ++i) opt.command += (i ? " " : "") + std::string(argv[i]);
  return -1;
}

std::string replay_prefix(const VerifyOptions& opt) {
  return opt.replay.empty() ? shell_quote(opt.program) + " --replay " : opt.replay;
}

std::string replay_command(const VerifyOptions& opt, const std::filesystem::path& path) {
  return replay_prefix(opt) + shell_quote(path.string());
}

std::string shell_quote(const std::string& word) {
  const bool plain = !word.empty() && word.find_first_not_of("ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz"
                                                            "0123456789_-+./:=@%,") == std::string::npos;
  if (plain) return word;
  std::string q = "'";
  for (char ch : word) q += ch == '\'' ? std::string("'\\''") : std::string(1, ch);
  return q + "'";
}

// "<i>\t<properties>\t<saved case files>\t<shrunk>\t<ns per call, a hex
// float>\t<figures>", the properties ("-": none) and their case files each
// separated by kSep.
std::string case_line_text(int i, const CaseLine& line) {
  char head[96];
  std::snprintf(head, sizeof head, "%d\t", i);
  char tail[64];
  std::snprintf(tail, sizeof tail, "\t%d\t%a\t", line.shrunk, line.ns);
  return head + (line.properties.empty() ? std::string("-") : joined(line.properties)) + "\t" + joined(line.files) +
         tail + line.figures;
}

bool case_line_from_text(const std::string& text, int& i, CaseLine& line) {
  std::size_t at[5];
  std::size_t from = 0;
  for (std::size_t& a : at) {
    a = text.find('\t', from);
    if (a == std::string::npos) return false;
    from = a + 1;
  }
  i = std::atoi(text.c_str());
  line = CaseLine{};
  const std::string properties = text.substr(at[0] + 1, at[1] - at[0] - 1);
  if (properties != "-") {
    line.properties = split(properties);
    line.files = split(text.substr(at[1] + 1, at[2] - at[1] - 1));
    line.files.resize(line.properties.size());
  }
  line.shrunk = std::atoi(text.c_str() + at[2] + 1);
  line.ns = std::strtod(text.c_str() + at[3] + 1, nullptr);
  line.figures = text.substr(at[4] + 1);
  return true;
}

int run_guarded(int n, const GuardOptions& opt, const CaseSteps& steps) {
  const auto start = Clock::now();
  const std::function<bool()> expired = [&] {
    return opt.seconds > 0 && std::chrono::duration<double>(Clock::now() - start).count() > opt.seconds;
  };
  Progress progress(opt.progress, n, start);
  const int ran = run_cases_guarded(n, opt, steps, progress, expired);
  progress.show(ran, true);
  return ran;
}

namespace {

int run_cases_guarded(int n, const GuardOptions& opt, const CaseSteps& steps, Progress& progress,
                      const std::function<bool()>& expired) {
  const auto whole = [&](int i) {  // check, save, count
    CaseLine line = steps.check(i);
    line.files = steps.save(i, line, true);
    return line;
  };
  int next = 0;
  while (next < n && !expired()) {
    std::fflush(nullptr);  // nothing buffered is written twice, by the child too
    int fds[2] = {-1, -1};
    pid_t pid = -1;
    if (opt.isolate && ::pipe(fds) == 0) {
      pid = ::fork();
      if (pid < 0) ::close(fds[0]), ::close(fds[1]);
    }
    if (pid < 0) {  // no child: in process
      if (opt.threads > 1) return next + run_in_threads(next, n, opt, steps, progress, expired);
      for (; next < n && !expired(); ++next) {
        steps.absorb(next, whole(next));
        progress.show(next + 1);
      }
      return next;
    }
    // The child: "C\t<line>" when a case's checks are done, "F\t<line>" when
    // its failures are saved, "D" when every case is.
    if (pid == 0) {
      ::close(fds[0]);
      FILE* out = ::fdopen(fds[1], "w");
      int status = 0;
      try {
        for (int i = next; i < n && !expired(); ++i) {
          ::alarm(opt.case_seconds);  // a subject that hangs (checks, shrink, drawing) is ended by SIGALRM
          CaseLine line = steps.check(i);
          if (!line.properties.empty()) {
            std::fprintf(out, "C\t%s\n", case_line_text(i, line).c_str());
            std::fflush(out);
            line.files = steps.save(i, line, true);
          }
          ::alarm(0);
          steps.absorb(i, line);  // the child's copy: the caps of what it saves next
          std::fprintf(out, "F\t%s\n", case_line_text(i, line).c_str());
          std::fflush(out);
        }
        std::fprintf(out, "D\n");
      } catch (const std::exception& e) {
        std::fprintf(stderr, "verify: internal error: %s\n", e.what());
        status = 3;
      } catch (...) {
        std::fprintf(stderr, "verify: internal error\n");
        status = 3;
      }
      std::fflush(nullptr);
      std::_Exit(status);
    }
    ::close(fds[1]);
    FILE* in = ::fdopen(fds[0], "r");
    std::string text;
    bool done = false, pending = false;
    int pending_i = -1;
    CaseLine checked;
    for (int ch; (ch = std::fgetc(in)) != EOF;) {
      if (ch != '\n') {
        text += static_cast<char>(ch);
        continue;
      }
      int i = 0;
      CaseLine line;
      if (text == "D") {
        done = true;
      } else if (text.size() > 2 && text[1] == '\t' && case_line_from_text(text.substr(2), i, line) && i == next) {
        if (text[0] == 'C') {
          pending = true, pending_i = i, checked = std::move(line);
        } else if (text[0] == 'F') {
          steps.absorb(i, line);
          pending = false;
          next = i + 1;
          progress.show(next);
        }
      }
      text.clear();
    }
    std::fclose(in);
    int status = 0;
    const bool waited = ::waitpid(pid, &status, 0) == pid;
    if (done || next >= n) continue;
    if (waited && WIFEXITED(status) && WEXITSTATUS(status) == 0) {
      if (expired()) break;  // the child stopped by the clock
    }
    const bool hung = waited && WIFSIGNALED(status) && WTERMSIG(status) == SIGALRM;
    const bool harness = waited && WIFEXITED(status) && WEXITSTATUS(status) == 3;
    const std::string how = !waited                ? std::string("its status is unknown")
                            : WIFSIGNALED(status) ? "signal " + std::to_string(WTERMSIG(status))
                                                  : "exit status " + std::to_string(WEXITSTATUS(status));
    if (pending && pending_i == next && !harness) {
      // The checks were done: the subject ended the child while its
      // failures were being saved (asked again to shrink or draw them).
      std::fprintf(stderr, "verify: case %d: the subject %s while its failure was being shrunk or drawn; saved as found\n",
                   next, hung ? "hung" : ("ended the process (" + how + ")").c_str());
      checked.files = steps.save(next, checked, false);
      steps.absorb(next, checked);
    } else {
      steps.lost(next, harness  ? Failure{"harness-error", "the harness failed on this case (" + how + "; its message is on stderr)"}
                       : hung   ? Failure{"subject-hung", "no answer within " + std::to_string(opt.case_seconds) + " s"}
                                : Failure{"subject-crashed", "the subject ended the process (" + how + ")"});
    }
    ++next;
  }
  return next;
}

}  // namespace

}  // namespace geomcheck::detail
