#include "campaign.hpp"
#include "geomcheck/properties/mesh_checks.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <mutex>
#include <sstream>
#include <thread>
#include <type_traits>

#include <unistd.h>

#include "geomcheck/oracles/engine.hpp"
#include "geomcheck/reports/draw.hpp"
#include "geomcheck/reports/report.hpp"
#include "geomcheck/casefile.hpp"
#include "geomcheck/properties/tolerances.hpp"
#include "geomcheck/peers/fcl_peer.hpp"
#include "peers.hpp"
#include "shard.hpp"
#include "geomcheck/properties/shrink.hpp"
#include "geomcheck/properties/spec.hpp"

namespace geomcheck {

namespace {

using report::html;
using report::QueryReport;
using report::Series;
using Clock = std::chrono::steady_clock;

// The caps on saved cases: at most kMaxSavedPerKind of a kind (a property,
// or a kind of FCL's disagreement) and kMaxSavedPerSignature of a
// signature (kind @ generator mode).
struct SaveCaps {
  std::map<std::string, int> of_kind, of_signature;
  /// Whether one more case of `kind` and `signature` is saved (then counted).
  bool take(const std::string& kind, const std::string& signature) {
    if (of_kind[kind] >= report::kMaxSavedPerKind || of_signature[signature] >= report::kMaxSavedPerSignature)
      return false;
    ++of_kind[kind];
    ++of_signature[signature];
    return true;
  }
};

// What the campaign keeps of each case beside the subject's checks (which
// verify()'s runner keeps): FCL's answer, the deepest stage the truth
// needed, a sweep's exact first touch, the evaluation FCL is scored on.
template <class Case>
struct Row {
  Case c{};
  Evaluation e;
  peers::FclAnswer fcl;
  std::string tag;
  oracle::Stage stage = oracle::Stage::None;
  double t_true = NAN;
  int index = 0;
};

// An implementation's answer, drawn in red.
template <class Case, class Impl>
draw::Answer answer_of(const Case& c, const Impl& impl) {
  if constexpr (std::is_same_v<Case, SegmentCylinderCase>) return draw::answer_of(impl.cast(c.a, c.b), impl.name);
  else if constexpr (std::is_same_v<Case, SweepCylinderCase>) return draw::answer_of(impl.sweep(c.a, c.b), impl.name);
  else return draw::answer_of(impl.collide(c.a, c.b), impl.name);
}

// FCL's answer, drawn beside production's (purple).
template <class Case>
draw::Mark fcl_mark(const Case& c, const peers::FclAnswer& p) {
  constexpr const char* kColour = "#83c";
  const Vec3 nowhere{NAN, NAN, NAN};
  char b[96];
  if (!p.hit) return {draw::Mark::Kind::PointNormal, nowhere, Vec3{}, 0, kColour, "FCL: " + html(p.text)};
  if constexpr (std::is_same_v<Case, SegmentCylinderCase>) {
    std::snprintf(b, sizeof b, "FCL: hit at t = %.6g (S(t); FCL gives no point)", p.t);
    return {draw::Mark::Kind::PointNormal, c.a.a + p.t * (c.a.b - c.a.a), Vec3{}, 0, kColour, b};
  } else if constexpr (std::is_same_v<Case, SweepCylinderCase>) {
    std::snprintf(b, sizeof b, "FCL: hit at t = %.6g (the ball then)", p.t);
    return {draw::Mark::Kind::Ball, c.a.c + p.t * c.a.delta, Vec3{}, c.a.r, kColour, b};
  } else {
    std::snprintf(b, sizeof b, "FCL: contact, depth %.6g (point and normal)", p.contact.depth);
    return {draw::Mark::Kind::PointNormal, p.contact.point, p.contact.normal, 0, kColour, b};
  }
}

// One query's part of a campaign: cases drawn in order from the seed
// (deterministic), production timed on them, then verify()'s run of the
// subject on this shard's cases (in process, on `threads` threads: every
// check, the failures shrunk, saved and drawn, the figures), with FCL asked
// on every case beside it (RunHooks) and its disagreements kept, shrunk and
// saved here.
// Sweeps: FCL's |t - t_exact| needs the exact first touch, the engine's
// time of impact (milliseconds a case, most of a sweep campaign's time when
// asked on every case): asked on the first cases only, by index, so that
// shards merge to the unsharded figures. The report says so.
constexpr int kExactTouchCases = 10000;

template <QueryId Q>
class QueryRun {
 public:
  using Case = typename Spec<Q>::Case;
  using Impl = typename Spec<Q>::Impl;

  QueryRun(const CampaignOptions& opt, const std::filesystem::path& out_dir) : opt_(opt), out_dir_(out_dir) {
    impl_ = Spec<Q>::subject(opt.variant);
    if (!impl_) impl_ = &production_of<Q>();
    extra_.name = info(Q).name;
    extra_.subject = impl_->name;
  }

  /// Runs every case; production and FCL are also reported apart on the
  /// first `first_cases` (the cases the other engines answer; 0: none).
  QueryReport run(int threads, int first_cases = 0) {
    auto cases = gen::draw<Q>(opt_.seed, campaign_cases(opt_, Q));
    const double prod_ns = time_production(cases);
    rows_.assign(cases.size(), Row<Case>{});
    for (std::size_t i = 0; i < cases.size(); ++i) rows_[i].tag = cases[i].second, rows_[i].index = static_cast<int>(i);
    first_cases_ = std::min(first_cases, static_cast<int>(cases.size()));
    std::vector<int> index;
    keep_this_shard(cases, opt_, index);
    if (first_cases_ > 0) {
      QueryReport f;
      f.name = extra_.name;
      f.subject = extra_.subject;
      f.claims = impl_->claims ? *impl_->claims : Spec<Q>::claims();
      f.tol = bounds_of(Q, impl_->claims);
      for (int k : index) f.requested += k < first_cases_;
      f.prod_ns = prod_ns;
      extra_.first.push_back(std::move(f));
    }
    const std::string replay = impl_ == &production_of<Q>()
                                   ? "geomcheck replay "
                                   : std::string("geomcheck replay --subject ") + impl_->name + " ";
    VerifyOptions v = family_run_options(opt_, out_dir_, static_cast<int>(cases.size()), replay);
    v.threads = threads;
    if (opt_.progress) {
      char label[64];
      std::snprintf(label, sizeof label, "[campaign] %-24s", info(Q).name);
      v.progress = label;
    }
    RunHooks<Q> hooks;
    hooks.evaluate = [this](int k, const Case& c) {
      Row<Case>& r = rows_[k];
      r.c = c;
      r.fcl = peers::fcl_answer(c);
      oracle::reset_deepest_stage();
      Evaluation e = peers::evaluate_with_fcl(c, r.fcl, *impl_);
      r.stage = oracle::deepest_stage();
      if constexpr (std::is_same_v<Case, SweepCylinderCase>)
        if (k < kExactTouchCases && r.fcl.supported && r.fcl.ok && r.fcl.hit && e.truth_hit && r.fcl.t >= 0 &&
            r.fcl.t <= 1)
          r.t_true = exact_first_touch(c);
      return e;
    };
    hooks.counted = [this](int k, const Evaluation& e, const std::vector<std::string>& failed) { gather(k, e, failed); };
    QueryReport rep = verify<Q>(*impl_, cases, index, v, hooks).figures;
    save_fcl_cases(threads);
    report::merge_into(rep, extra_);  // FCL's part, the truth's stages, the first cases
    rep.prod_ns = prod_ns;
    return rep;
  }

 private:
  std::string origin(const Row<Case>& r) const {
    return "campaign seed=" + std::to_string(opt_.seed) + " case=" + std::to_string(r.index);
  }

  // Production's time per query on these cases.
  double time_production(const std::vector<std::pair<Case, std::string>>& cases) const {
    const auto t0 = Clock::now();
    int sink = 0;
    const int reps = 5;
    for (int r = 0; r < reps; ++r)
      for (const auto& c : cases) sink += Spec<Q>::hit(c.first, *impl_);
    const double ns = std::chrono::duration<double, std::nano>(Clock::now() - t0).count();
    if (sink == -1) std::puts("");
    return ns / (reps * std::max<std::size_t>(1, cases.size()));
  }

  // Case k counted (in case order): the truth's stage, FCL's answer held
  // to the same truth, the first cases' row.
  void gather(int k, const Evaluation& e, const std::vector<std::string>& failed) {
    Row<Case>& r = rows_[k];
    r.e = e;
    if (std::isfinite(r.t_true)) r.e.t_true = r.t_true;  // a sweep's exact first touch (a cast's is the truth's)
    if (k < first_cases_) gather_first(r, failed);
    if (!e.valid) return;
    ++extra_.truth_stages[oracle::to_string(r.stage)];
    if (r.fcl.supported) {
      ++extra_.fcl_supported;
      if (r.fcl.ok) gather_fcl(r);
    }
  }

  // The kinds of FCL's disagreement beyond the band on one case: its
  // verdict (false-hit, missed-hit), its distance's verdict
  // (distance-says-meet, distance-says-apart); none where it agrees.
  static std::vector<const char*> fcl_kinds(const peers::FclAnswer& p, const Evaluation& e) {
    std::vector<const char*> out;
    if (!e.valid || !p.supported || !p.ok || e.near_boundary) return out;  // the same band as production's
    if (p.hit != e.truth_hit) out.push_back(p.hit ? "false-hit" : "missed-hit");
    if (std::isfinite(p.distance) && (p.distance < 0) != e.truth_hit)
      out.push_back(p.distance < 0 ? "distance-says-meet" : "distance-says-apart");
    return out;
  }

  // FCL's answer to one case, held to the same truth; its disagreements
  // kept to be saved.
  void gather_fcl(const Row<Case>& r) {
    score_fcl(extra_, r);
    for (const char* kind : fcl_kinds(r.fcl, r.e)) note_fcl(r, kind);
  }

  // FCL's answer to one case counted into `into`.
  static void score_fcl(QueryReport& into, const Row<Case>& r) {
    const Evaluation& e = r.e;
    ++into.fcl_ok;
    if (r.fcl.hit != e.truth_hit) {
      ++into.fcl_disagree;
      if (!e.near_boundary) ++into.fcl_beyond;
    }
    if (std::isfinite(r.fcl.distance)) {
      ++into.fcl_distance_asked;
      if ((r.fcl.distance < 0) != e.truth_hit && !e.near_boundary) ++into.fcl_distance_beyond;
      if (r.fcl.distance >= 0 && std::isfinite(e.distance))
        into.fcl_distance.add(std::fabs(r.fcl.distance - e.distance) / e.scale);
    }
    into.fcl_depth.add(e.peer.depth_err);
    into.fcl_normal.add(e.peer.normal_err);
    into.fcl_point.add(e.peer.point_err);
    into.fcl_t_gap.add(e.peer.t_err);
    if (r.fcl.hit && e.truth_hit && std::isfinite(r.fcl.t) && std::isfinite(e.t_true))
      into.fcl_t.add(std::fabs(r.fcl.t - e.t_true));
  }

  // Production and FCL on the first `first_cases` cases, the ones the other
  // engines answer: the precision table's rows on the same cases.
  void gather_first(const Row<Case>& r, const std::vector<std::string>& failed) {
    QueryReport& f = extra_.first.front();
    report::add_evaluation(f, Q, r.e);
    if (!r.e.valid) return;
    if (!failed.empty()) ++f.check_failures;
    for (const std::string& property : failed) ++f.failures_by_property[property];
    if (r.fcl.supported) {
      ++f.fcl_supported;
      if (r.fcl.ok) score_fcl(f, r);
    }
  }

  // FCL's disagreements beyond the band, as for production's
  // counterexamples: every one counted by signature (kind @ generator mode);
  // the first kMaxSavedPerSignature of a signature, at most kMaxSavedPerKind
  // of a kind, kept to be shrunk and saved (save_fcl_cases).
  struct FclSave {
    int row = 0;
    const char* kind = "";
    Case small{};
    peers::FclAnswer fcl;
    Evaluation e;
    Shrunk how;
  };
  void note_fcl(const Row<Case>& r, const char* kind) {
    const std::string signature = std::string(kind) + " @ " + r.tag;
    ++extra_.fcl_by_signature[signature];
    if (!fcl_caps_.take(kind, signature)) return;
    FclSave s;
    s.row = r.index;
    s.kind = kind;
    fcl_saves_.push_back(std::move(s));
  }

  // Each kept disagreement shrunk while FCL still disagrees the same way
  // (on `threads` threads: every step asks the truth), then saved in case
  // order, the first 3 of each kind drawn.
  void save_fcl_cases(int threads) {
    std::atomic<std::size_t> next{0};
    auto worker = [&] {
      for (;;) {
        const std::size_t k = next++;
        if (k >= fcl_saves_.size()) return;
        FclSave& s = fcl_saves_[k];
        const std::string kind = s.kind;
        s.small = shrink(
            rows_[s.row].c,
            [&](const Case& c) {
              const peers::FclAnswer p = peers::fcl_answer(c);
              for (const char* k2 : fcl_kinds(p, peers::evaluate_with_fcl(c, p, *impl_)))
                if (kind == k2) return true;
              return false;
            },
            report::kShrinkBudget, &s.how);
        s.fcl = s.how.simplified ? peers::fcl_answer(s.small) : rows_[s.row].fcl;
        s.e = s.how.simplified ? peers::evaluate_with_fcl(s.small, s.fcl, *impl_) : rows_[s.row].e;
      }
    };
    std::vector<std::thread> pool;
    for (int k = 0; k < std::max(1, threads) && k < static_cast<int>(fcl_saves_.size()); ++k) pool.emplace_back(worker);
    for (auto& th : pool) th.join();
    std::map<std::string, int> drawn;
    for (const FclSave& s : fcl_saves_) {
      extra_.fcl_shrunk += s.how.simplified > 0;
      const std::filesystem::path dir = out_dir_ / "fcl-disagreements" / extra_.name;
      std::filesystem::create_directories(dir);
      char name[80];
      std::snprintf(name, sizeof name, "%05d-fcl-%s.case", s.row, s.kind);
      const std::string found_by =
          origin(rows_[s.row]) + " mode=" + rows_[s.row].tag +
          (s.how.simplified ? " (shrunk: " + std::to_string(s.how.simplified) + " numbers simplified)" : std::string());
      CaseFile f = from_case<Q>(s.small, found_by, verdict_word(Q, s.e), "FCL: " + s.fcl.text + "; oracle: " + s.e.truth_text);
      std::string err;
      if (save_case(dir / name, f, err)) extra_.fcl_cases.push_back((dir / name).string());
      else std::fprintf(stderr, "[campaign] cannot save %s: %s\n", (dir / name).string().c_str(), err.c_str());
      if (drawn[s.kind]++ < 3) {
        const draw::Answer ans = answer_of(s.small, *impl_);
        extra_.fcl_drawings.push_back(draw::views(
            s.small,
            html(std::string("case ") + name + ": FCL's " + s.kind + " (" + s.fcl.text + "); oracle: " + s.e.truth_text),
            {fcl_mark(s.small, s.fcl)}, &ans));
      }
    }
  }

  const CampaignOptions& opt_;
  std::filesystem::path out_dir_;
  SaveCaps fcl_caps_;  // FCL's disagreements kept
  std::vector<FclSave> fcl_saves_;
  const Impl* impl_ = nullptr;
  int first_cases_ = 0;
  std::vector<Row<Case>> rows_;  // by the case's number in the seed's sequence
  QueryReport extra_;      // what the campaign adds to the subject's figures
};

}  // namespace

int campaign_cases(const CampaignOptions& opt, QueryId id) {
  if (opt.cases > 0) return opt.cases;
  return visit_query(id, [](auto q) { return Spec<decltype(q)::value>::default_cases(); });
}

std::vector<std::pair<std::string, std::string>> campaign_variants() {
  std::vector<std::pair<std::string, std::string>> out;
  for_each_query([&](auto q) {
    constexpr QueryId Q = decltype(q)::value;
    for (const auto* v : Spec<Q>::variants()) out.emplace_back(v->name, info(Q).name);
  });
#define GEOMCHECK_X(id, summary) \
  for (const MeshImpl* v : mesh_variants()) out.emplace_back(v->name, #id);
  GEOMCHECK_MESH_QUERY_LIST(GEOMCHECK_X)
#undef GEOMCHECK_X
  return out;
}

int run_campaign(const CampaignOptions& opt) {
  namespace fs = std::filesystem;
  const fs::path out_dir(opt.out);
  fs::create_directories(out_dir);
  const int threads = opt.threads > 0 ? opt.threads : std::max(1u, std::thread::hardware_concurrency());
  const std::string per_query = opt.cases > 0 ? std::to_string(opt.cases) + " cases per query"
                                              : "100000 cases per query (" + std::to_string(kDelaunayDefaultSets) + " point sets, " +
                                                    std::to_string(kMeshDefaultCases) + " meshes)";
  std::fprintf(stderr, "[campaign] seed %llu, %s, %d threads, output %s\n", static_cast<unsigned long long>(opt.seed),
               per_query.c_str(), threads, out_dir.string().c_str());
  if (opt.shards > 1)
    std::fprintf(stderr, "[campaign] shard %d of %d (0-based): the cases i with i %% %d == %d\n", opt.shard, opt.shards,
                 opt.shards, opt.shard);
  std::vector<QueryReport> reps;
  for_each_query([&](auto q) {
    constexpr QueryId Q = decltype(q)::value;
    if (!opt.queries.empty() && std::find(opt.queries.begin(), opt.queries.end(), info(Q).name) == opt.queries.end()) return;
    if (!opt.variant.empty()) {
      const auto* subject = Spec<Q>::subject(opt.variant);
      if (!subject || subject == &production_of<Q>()) return;  // not one of Q's variants
    }
    reps.push_back(QueryRun<Q>(opt, out_dir).run(threads, opt.variant.empty() ? opt.peer_cases : 0));
    if (opt.variant.empty() && opt.shard == 0) {
      // Sharded: the engines on the campaign's first cases (in shard 0), not this shard's.
      const int first = opt.shards > 1 ? campaign_cases(opt, Q) : reps.back().cases;
      reps.back().peers = run_peers<Q>(std::min(opt.peer_cases, first), opt.seed, out_dir, opt.seeds, threads);
    }
    // No engine built: nothing to set beside (sharded: decided by merge).
    if (opt.shards == 1 && reps.back().peers.empty()) reps.back().first.clear();
  });
  // The point-set family (not with a variant: those are pair subjects).
  std::vector<report::PointSetReport> point_sets;
  const auto wanted = [&](const char* name) {
    return opt.queries.empty() || std::find(opt.queries.begin(), opt.queries.end(), name) != opt.queries.end();
  };
#define GEOMCHECK_X(id, summary) \
  if (opt.variant.empty() && wanted(#id)) point_sets.push_back(run_##id(opt, out_dir));
  GEOMCHECK_POINTSET_QUERY_LIST(GEOMCHECK_X)
#undef GEOMCHECK_X
  // The mesh family: production, or its own known-wrong variants.
  std::vector<report::MeshReport> meshes;
#define GEOMCHECK_X(id, summary)                                                \
  if (wanted(#id) && (opt.variant.empty() || mesh_subject(opt.variant)))        \
    meshes.push_back(run_##id(opt, out_dir));
  GEOMCHECK_MESH_QUERY_LIST(GEOMCHECK_X)
#undef GEOMCHECK_X

  report::RunInfo run;
  run.seed = opt.seed;
  run.per_query = per_query;
  run.version = opt.version;
  run.started = opt.started;
  run.command = opt.command;
  run.rerun = "geomcheck campaign --seed " + std::to_string(opt.seed) +
              (opt.cases > 0 ? " --cases " + std::to_string(opt.cases) : std::string());
  if (opt.seconds > 0) {
    char b[40];
    std::snprintf(b, sizeof b, " --seconds %g", opt.seconds);
    run.rerun += b;
  }
  if (opt.peer_cases != CampaignOptions{}.peer_cases) run.rerun += " --peer-cases " + std::to_string(opt.peer_cases);
  for (const auto& q : opt.queries) run.rerun += " --query " + q;
  if (!opt.variant.empty()) run.rerun += " --variant " + opt.variant;
  run.under_test = opt.variant.empty() ? "production" : opt.variant + " (a known-wrong variant)";
  if (opt.shards > 1) {
    write_shard(out_dir / "shard.json", opt, run, reps, point_sets, meshes);  // the run's rerun: all shards
    run.rerun += " --shard " + std::to_string(opt.shard) + "/" + std::to_string(opt.shards);
  }
  report::write_json(out_dir / "report.json", run, reps, point_sets, meshes);
  report::write_html(out_dir / "report.html", run, reps, point_sets, meshes);
  if (!opt.junit.empty()) report::write_junit(opt.junit, run, reps, point_sets, meshes);
  int beyond = 0;
  for (const QueryReport& r : reps) beyond += r.beyond + r.check_failures;
  for (const report::PointSetReport& r : point_sets) beyond += r.failures;
  for (const report::MeshReport& r : meshes) beyond += r.failures;
  std::fprintf(stderr, "[campaign] wrote %s and %s\n", (out_dir / "report.json").string().c_str(),
               (out_dir / "report.html").string().c_str());
  return beyond;
}

}  // namespace geomcheck
