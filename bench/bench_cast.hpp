// geomcheck benchmarks — the queries that answer a time of impact against a
// cylinder (the segment cast and the sphere sweep): production's CastHit
// against FCL's answer through the adapter (fcl::continuousCollide,
// fcl_adapter.hpp), asked as the adapter does by default (after a miss it
// asks again in up to three equivalent frames) and once.
#pragma once

#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "bench_common.hpp"
#include "bench_random.hpp"
#include "geomcheck/peers/fcl_adapter.hpp"
#include "geomcheck/results.hpp"

namespace geomcheck::bench {

/// A cast-like query on a Case: `prod(k)` is production's CastHit, `fcl(k,
/// method)` FCL's peers::PeerCast. The benchmarks are BM_prod_<query>,
/// BM_fcl_<query> (the adapter's default) and BM_fcl_<query>_once (a single
/// FCL call), each followed by _<set> when the batch has a name.
template <class Prod, class Fcl>
struct CastBench {
  const char* query;  ///< "cast" or "sweep"
  Prod prod;
  Fcl fcl;

  /// The FCL methods compared: the adapter's default, then a single call.
  static constexpr peers::FclCastMethod kMethods[2] = {peers::FclCastMethod::kConservativeAdvancement,
                                                         peers::FclCastMethod::kConservativeAdvancementOnce};

  /// `n` cases drawn by `draw`, exactly half of them hitting according to production.
  template <class Draw>
  auto half_hitting(std::size_t n, Draw&& draw) const {
    return bench::half_hitting(n, draw, [&](const auto& k) { return int(prod(k).hit); });
  }

  /// The three benchmarks over `cases` (which must outlive the run).
  template <class Case>
  void register_batch(const std::string& set, const std::vector<Case>& cases) const {
    const std::string q = query, s = set_suffix(set);
    register_each("BM_prod_" + q + s, cases, prod);
    register_each("BM_fcl_" + q + s, cases, [f = fcl](const Case& k) { return f(k, kMethods[0]); });
    register_each("BM_fcl_" + q + "_once" + s, cases, [f = fcl](const Case& k) { return f(k, kMethods[1]); });
  }

  /// The ratios of BM_fcl_<query> and BM_fcl_<query>_once to BM_prod_<query>.
  std::vector<Ratio> ratios(const std::string& set = "") const {
    return {fcl_over_prod(query, set), fcl_over_prod(query, set, "once")};
  }

  /// "hits: production ...; FCL ... (verdicts agree ..., max |dt| ...); FCL
  /// once ...", after "<set> " (padded to 6) when `set` is not empty.
  template <class Case>
  void print_agreement(const char* set, const std::vector<Case>& cases) const {
    std::size_t prod_hits = 0;
    std::size_t hits[2] = {0, 0}, agree[2] = {0, 0};
    double max_dt[2] = {0, 0};
    for (const Case& k : cases) {
      const CastHit p = prod(k);
      prod_hits += p.hit;
      for (int m = 0; m < 2; ++m) {
        const peers::PeerCast f = fcl(k, kMethods[m]);
        hits[m] += f.hit;
        agree[m] += (f.ok && f.hit == p.hit);
        if (p.hit && f.ok && f.hit) max_dt[m] = std::fmax(max_dt[m], std::fabs(f.t - p.t));
      }
    }
    if (*set) std::printf("%-6s ", set);
    std::printf("hits: production %zu; FCL %zu (verdicts agree %zu/%zu, max |dt| %.3g); FCL once %zu (agree %zu/%zu, "
                "max |dt| %.3g)\n",
                prod_hits, hits[0], agree[0], cases.size(), max_dt[0], hits[1], agree[1], cases.size(), max_dt[1]);
  }
};

template <class Prod, class Fcl>
CastBench(const char*, Prod, Fcl) -> CastBench<Prod, Fcl>;

}  // namespace geomcheck::bench
