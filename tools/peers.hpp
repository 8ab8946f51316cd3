// geomcheck — the other engines (peers/: ODE, Bullet, MuJoCo) as the
// geomcheck command sees them: by name, for replay --subject, and run on a
// campaign's cases for the cross-engine precision table. An engine whose
// package was not found at configure time is simply absent.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "geomcheck/properties/spec.hpp"
#include "geomcheck/reports/report.hpp"

namespace geomcheck {

/// The engines built in (their subjects' names: "ODE", "Bullet", "MuJoCo").
std::vector<std::string> peer_engines();

/// Engine `name`'s subject of query Q (nullptr: no such engine, or it
/// cannot express Q).
template <QueryId Q>
const ImplOf<Q>* peer_subject(const std::string& name);

/// Every engine's subject of Q held to every property (verify(): a child
/// process, a hang or a crash that case's failure) on the first `cases`
/// cases the campaign draws from `seed`; failures saved under
/// out_dir/peers/<engine>/ (at most 10 per property, 5 per signature, each
/// shrunk); then the bug-report configurations of Q
/// (`seeds`/<query>/bugreport-*.case, where the folder exists), each failing
/// one named. One report per engine, in the engines' order. The engines run
/// side by side, each in a process of its own, at most `jobs` at a time
/// (each engine's run is the same as alone: its own cases, caps and files;
/// the process only carries its report back); 1, or no fork: one after the
/// other in this process.
template <QueryId Q>
std::vector<report::QueryReport> run_peers(int cases, std::uint64_t seed, const std::filesystem::path& out_dir,
                                           const std::filesystem::path& seeds, int jobs = 1);

}  // namespace geomcheck
