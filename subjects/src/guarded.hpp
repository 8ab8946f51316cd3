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
};

/// Runs case i for every i in [0, n): `run(i)` checks the case (and saves
/// its failures, within the caps its process has counted), and `absorb(i,
/// line)` counts what it gave. With `isolate`, run() is called in a child
/// process and absorb() both there (so that the child's caps grow) and in
/// the parent, from the child's line; when the child dies (a signal: a
/// segfault, an abort) or gives no answer within case_seconds, the case is
/// handed to `lost(i, failure)` ("subject-crashed" or "subject-hung") in the
/// parent, and a new child goes on after it. Without `isolate`, run() and
/// absorb() in this process: the subject's state changes stay, and a crash
/// ends the run. With opt.seconds, no case is started once that many seconds
/// have passed. Returns the number of cases run (n unless stopped by time).
int run_guarded(int n, const GuardOptions& opt, const std::function<CaseLine(int)>& run,
                 const std::function<void(int, const CaseLine&)>& absorb,
                 const std::function<void(int, const Failure&)>& lost);

/// Parses verify()'s command line (verify.hpp's options) into `opt` and
/// `replays`; `about` heads --help, `unit` names what is drawn ("cases",
/// "point sets"), `max_saved_help` says the caps. -1: go on; else the exit
/// status (0 after --help, 2 on a usage error, said on stderr).
int parse_verify_command(int argc, char** argv, const std::string& about, const std::string& unit,
                         const std::string& max_saved_help, VerifyOptions& opt,
                         std::vector<std::filesystem::path>& replays);

/// `word` quoted for a POSIX shell where it needs it.
std::string shell_quote(const std::string& word);

}  // namespace geomcheck::detail
