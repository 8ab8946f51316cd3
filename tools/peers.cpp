// geomcheck — the other engines by name, and their campaign runs (peers.hpp).
#include "peers.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>

#include "geomcheck/verify.hpp"
#include "shard.hpp"
#ifdef GEOMCHECK_PEER_ODE
#include "geomcheck/peers/ode.hpp"
#endif
#ifdef GEOMCHECK_PEER_BULLET
#include "geomcheck/peers/bullet.hpp"
#endif
#ifdef GEOMCHECK_PEER_MUJOCO
#include "geomcheck/peers/mujoco.hpp"
#endif

namespace geomcheck {

namespace {

#if defined(GEOMCHECK_PEER_ODE) || defined(GEOMCHECK_PEER_BULLET) || defined(GEOMCHECK_PEER_MUJOCO)
/// An engine's subject of Q with the engine's `expresses` attached (so that
/// verify() does not ask it cases it cannot state); null where the engine
/// cannot express Q. Made once per engine and query.
template <QueryId Q>
const ImplOf<Q>* with_expresses(const peers::PeerSubject<Q>& p) {
  if (!p.subject) return nullptr;
  auto* s = new ImplOf<Q>(*p.subject);  // lives as long as the program, as the engine's own subject does
  if (p.expresses) {
    using Case = typename QueryTraits<Q>::Case;
    const auto expresses = p.expresses;
    s->expresses = [expresses](const typename QueryTraits<Q>::ShapeA& a, const typename QueryTraits<Q>::ShapeB& b) {
      return expresses(Case{a, b});
    };
  }
  return s;
}
#endif

/// Every engine's subject of Q, null where the engine cannot express it.
template <QueryId Q>
std::vector<const ImplOf<Q>*> subjects_of() {
  static const std::vector<const ImplOf<Q>*> out = [] {
    std::vector<const ImplOf<Q>*> v;
#ifdef GEOMCHECK_PEER_ODE
    v.push_back(with_expresses(peers::peer_ode<Q>()));
#endif
#ifdef GEOMCHECK_PEER_BULLET
    v.push_back(with_expresses(peers::peer_bullet<Q>()));
#endif
#ifdef GEOMCHECK_PEER_MUJOCO
    v.push_back(with_expresses(peers::peer_mujoco<Q>()));
#endif
    return v;
  }();
  return out;
}

}  // namespace

std::vector<std::string> peer_engines() {
  std::vector<std::string> out;
  for_each_query([&](auto q) {
    for (const auto* s : subjects_of<decltype(q)::value>())
      if (s && std::find(out.begin(), out.end(), s->name) == out.end()) out.push_back(s->name);
  });
  return out;
}

template <QueryId Q>
const ImplOf<Q>* peer_subject(const std::string& name) {
  for (const auto* s : subjects_of<Q>())
    if (s && name == s->name) return s;
  return nullptr;
}

template <QueryId Q>
std::vector<report::QueryReport> run_peers(int cases, std::uint64_t seed, const std::filesystem::path& out_dir,
                                           const std::filesystem::path& seeds, int jobs) {
  std::vector<report::QueryReport> out;
  if (cases <= 0) return out;
  std::vector<std::filesystem::path> bugreports;
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(seeds / info(Q).name, ec)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind("bugreport-", 0) == 0 && entry.path().extension() == ".case") bugreports.push_back(entry.path());
  }
  std::sort(bugreports.begin(), bugreports.end());
  std::vector<const ImplOf<Q>*> engines;
  for (const auto* s : subjects_of<Q>())
    if (s) engines.push_back(s);
  // One engine's run: its cases, then the bug-report configurations.
  const auto run_one = [&](const ImplOf<Q>& s) {
    VerifyOptions opt;
    opt.cases = cases;
    opt.seed = seed;
    opt.out = out_dir / "peers" / s.name;
    opt.max_saved = 10;  // of a property (and 5 of a signature): each is shrunk, one engine answering at a time
    opt.shrink_budget = 30;  // shrunk (a short budget: the time goes to the cases)
    opt.quiet = true;
    opt.summary = false;
    opt.report = false;
    opt.replay = std::string("geomcheck replay --subject ") + s.name + " ";
    report::QueryReport rep = verify<Q>(s, opt).figures;
    if (!bugreports.empty()) {
      opt.out = out_dir / "peers" / s.name / "bugreports";
      const VerifyResult b = verify<Q>(s, bugreports, opt);
      rep.bugreports = b.cases;
      rep.bugreports_failed = b.failed_cases;
    }
    return rep;
  };
  out.resize(engines.size());
  // Side by side: engine k's run in a child process that writes its report
  // (shard.json's layout, exact) to `figures(k)`; the parent reads it back.
  // A child that fails is run again here, so a report is never lost.
  const auto figures = [&](std::size_t k) { return out_dir / "peers" / (std::string(".") + engines[k]->name + ".report.json"); };
  std::map<pid_t, std::size_t> running;
  const auto collect = [&](pid_t pid, int status) {
    const std::size_t k = running.at(pid);
    running.erase(pid);
    bool ok = WIFEXITED(status) && WEXITSTATUS(status) == 0;
    if (ok) {
      try {
        std::ifstream f(figures(k));
        std::stringstream text;
        text << f.rdbuf();
        report::from_json(text.str(), out[k]);
      } catch (const std::exception& e) {
        std::fprintf(stderr, "[campaign] %s: %s's report unreadable (%s)\n", info(Q).name, engines[k]->name, e.what());
        ok = false;
      }
    }
    std::filesystem::remove(figures(k), ec);
    if (!ok) {
      std::fprintf(stderr, "[campaign] %-24s %s again, in this process (its process ended with status %d)\n",
                   info(Q).name, engines[k]->name, status);
      out[k] = run_one(*engines[k]);
    }
  };
  std::filesystem::create_directories(out_dir / "peers", ec);
  for (std::size_t k = 0; k < engines.size(); ++k) {
    std::fprintf(stderr, "[campaign] %-24s %s on the first %d cases\n", info(Q).name, engines[k]->name, cases);
    std::fflush(nullptr);
    const pid_t pid = jobs > 1 ? ::fork() : -1;
    if (pid == 0) {  // the child: the run, its report to the file
      int rc = 1;
      try {
        const std::string text = report::to_json(run_one(*engines[k]));
        std::ofstream f(figures(k));
        f << text;
        f.close();
        rc = f ? 0 : 1;
      } catch (...) {
      }
      std::fflush(nullptr);
      std::_Exit(rc);
    }
    if (pid < 0) {
      out[k] = run_one(*engines[k]);
      continue;
    }
    running[pid] = k;
    while (static_cast<int>(running.size()) >= jobs) {
      int status = 0;
      const pid_t done = ::waitpid(-1, &status, 0);
      if (done > 0 && running.count(done)) collect(done, status);
      else if (done < 0) break;
    }
  }
  while (!running.empty()) {
    int status = 0;
    const pid_t done = ::waitpid(-1, &status, 0);
    if (done < 0) {  // lost track of the children: their engines again, here
      for (const auto& entry : std::map<pid_t, std::size_t>(running)) collect(entry.first, -1);
      break;
    }
    if (running.count(done)) collect(done, status);
  }
  return out;
}

#define GEOMCHECK_X(id, kind, A, B, summary)                                                               \
  template const ImplOf<QueryId::id>* peer_subject<QueryId::id>(const std::string&);                      \
  template std::vector<report::QueryReport> run_peers<QueryId::id>(int, std::uint64_t, const std::filesystem::path&, \
                                                                   const std::filesystem::path&, int);
GEOMCHECK_QUERY_LIST(GEOMCHECK_X)
#undef GEOMCHECK_X

}  // namespace geomcheck
