// geomcheck — verify()'s case runner for every family: each case checked in a
// child process, so that a subject that crashes or hangs fails its case
// instead of ending the run.
#pragma once

#include <cmath>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "geomcheck/properties/checks.hpp"
#include "geomcheck/verify.hpp"

namespace geomcheck::detail {

/// What one case gave, as the child tells the parent: the properties it
/// failed, the case file saved for each (empty: not saved), the counterexamples
/// shrunk on the way, the subject's time per call, and the family's own
/// figures (one line of text, no newline: report::to_json of the case's
/// evaluation for a pair, of a one-set report for a point set).
struct CaseLine {
  std::vector<std::string> properties;
  std::vector<std::string> files;
  int shrunk = 0;
  double ns = NAN;
  std::string figures;
};

/// The line the child writes for case i (no newline), and its reading
/// (false: not a case line).
std::string case_line_text(int i, const CaseLine& line);
bool case_line_from_text(const std::string& text, int& i, CaseLine& line);

/// How run_guarded runs.
struct GuardOptions {
  bool isolate = true;          ///< a child process (false, or no fork: in process)
  unsigned case_seconds = 60;   ///< a case taking longer: the subject hung
  double seconds = 0;           ///< no case started after this many seconds (0: no limit)
  /// In process: the checks of the cases on this many threads (check() must
  /// be safe to call at once on different cases), then each case saved and
  /// counted in case order. With a child process: one case at a time.
  int threads = 1;
  /// Heads a progress line on stderr ("<progress> <done> / <n> cases ..."),
  /// redrawn every 0.5 s on a terminal, a line every 10 s into a file, and
  /// a last one when the run ends; empty: none.
  std::string progress;
};

/// The steps of one case, as the family runs them.
struct CaseSteps {
  /// The checks of case i: its failing properties, its figures and the
  /// subject's time (no case file saved yet).
  std::function<CaseLine(int)> check;
  /// Saves the failures of case i (line.properties, capped): the case file
  /// of each (empty: not saved), shrunk on the way unless `ask_subject` is
  /// false (the subject is not asked again: it crashed or hung while they
  /// were being saved); counts the shrunk ones into line.shrunk.
  std::function<std::vector<std::string>(int, CaseLine&, bool ask_subject)> save;
  /// Counts what case i gave (its figures, failures and case files).
  std::function<void(int, const CaseLine&)> absorb;
  /// Case i ended its child before its checks were done ("subject-crashed",
  /// "subject-hung", or "harness-error" when the harness itself failed
  /// there): saves it without asking the subject, and counts it.
  std::function<void(int, const Failure&)> lost;
};

/// Runs every case i in [0, n): check, save, absorb. With opt.isolate, in a
/// child process, so that a subject that crashes (a signal: a segfault, an
/// abort) or gives no answer within case_seconds fails its case instead of
/// ending the run; the child sends the parent a line when a case's checks
/// are done and another when its failures are saved, so that a subject
/// that dies while its failure is being shrunk or drawn loses nothing:
/// the case's checks are counted and its failures saved as found. A new
/// child goes on after a lost case. absorb() runs in the child too (its
/// caps of what it saves next) and in the parent from the child's lines.
/// Without isolate (or without fork), in this process: the subject's state
/// changes stay, and a crash ends the run; with opt.threads, the checks on
/// that many threads first, then save() and absorb() in case order. With
/// opt.seconds, no case is started once that many seconds have passed.
/// Returns the number of cases run (n unless stopped by time).
int run_guarded(int n, const GuardOptions& opt, const CaseSteps& steps);

/// Parses verify()'s command line (verify.hpp's options) into `opt` and
/// `replays`; `about` heads --help, `unit` names what is drawn ("cases",
/// "point sets"), `max_saved_help` says the caps. -1: go on; else the exit
/// status (0 after --help, 2 on a usage error, said on stderr).
int parse_verify_command(int argc, char** argv, const std::string& about, const std::string& unit,
                         const std::string& max_saved_help, VerifyOptions& opt,
                         std::vector<std::filesystem::path>& replays);

/// The command that replays a saved case, less its path (opt.replay, or the
/// program with --replay), and with it.
std::string replay_prefix(const VerifyOptions& opt);
std::string replay_command(const VerifyOptions& opt, const std::filesystem::path& path);

/// `word` quoted for a POSIX shell where it needs it.
std::string shell_quote(const std::string& word);

}  // namespace geomcheck::detail
