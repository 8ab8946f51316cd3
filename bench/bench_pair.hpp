// geomcheck benchmarks — a cylinder against another convex shape,
// production against FCL on the same inputs, in one run (the capsule, box,
// triangle and cylinder pairs).
//
// Two batches of kPairBatch pairs from a fixed seed (printed), each
// shuffled so that branches are not predictable:
//   random   random poses, exactly half of them overlapping according to
//            the selecting verdict;
//   contact  pairs in contact: every one overlapping according to it
//            (shallow and deep as the generator gives them), so that every
//            FCL collide runs MPR's penetration phase.
// The selecting verdict is production's overlap unless the program gives
// its own (the triangle: the certified engine's, so that the inputs do not
// depend on the implementation under measurement).
// The FCL benchmarks time fcl::collide on shapes converted once beforehand
// (fcl_convert.hpp: FCL as shipped, libccd's MPR, GST_LIBCCD);
// BM_fcl_collide_adapter_* adds the adapter's validation, conversion and
// guarded support functions (fcl_adapter.hpp) for reference. After the run
// the program prints ns/query and the FCL/production ratios per batch.
#pragma once

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "bench_common.hpp"
#include "bench_random.hpp"
#include "geomcheck/oracles/fcl_adapter.hpp"
#include "geomcheck/results.hpp"
#include "geomcheck/shapes.hpp"
#include "geomcheck/oracles/fcl_convert.hpp"

namespace geomcheck::bench {

inline constexpr std::size_t kPairBatch = 4096;

/// The benchmark of collide(Cylinder, B) against FCL; `Prepared` is the
/// pair converted once for FCL (fcl_convert.hpp).
template <class B, class Prepared>
struct PairBench {
  struct Pair {
    Cylinder a;
    B b;
  };
  struct Batch {
    std::vector<Pair> pairs;
    std::vector<Prepared> fcl;  // the same pairs, converted for FCL
  };
  struct Inputs {
    std::uint64_t seed = 0;
    Batch random, contact;
    std::size_t undecided = 0;      ///< poses the selecting verdict left undecided (skipped)
    std::size_t contact_draws = 0;  ///< poses drawn for the contact batch
  };

  const char* name;            ///< e.g. "cylinder/capsule"
  Pair (*random_pair)(Rng&);   ///< one random pose
  const char* depth_note;      ///< what the two depths are, printed with their differences
  /// The selecting verdict: 1 overlapping (or touching), 0 apart, -1
  /// undecided (the pose is skipped); null: production's overlap.
  int (*verdict)(const Pair&) = nullptr;
  const char* selected_by = "production";  ///< whose verdict `verdict` is

  static void shuffle_and_convert(Batch& b, Rng& rng) {
    for (std::size_t i = b.pairs.size(); i > 1; --i) std::swap(b.pairs[i - 1], b.pairs[rng.next() % i]);
    b.fcl.reserve(b.pairs.size());
    for (const Pair& pr : b.pairs) b.fcl.emplace_back(pr.a, pr.b);
  }

  Inputs make_inputs(std::uint64_t seed) const {
    Inputs in;
    in.seed = seed;
    Rng rng(seed);
    auto hit_of = [&](const Pair& pr) { return verdict ? verdict(pr) : int(overlap(pr.a, pr.b)); };
    std::size_t n_hit = 0, n_miss = 0;
    while (in.random.pairs.size() < kPairBatch) {
      const Pair pr = random_pair(rng);
      const int hit = hit_of(pr);
      if (hit < 0) {
        ++in.undecided;
        continue;
      }
      if (hit ? n_hit >= kPairBatch / 2 : n_miss >= kPairBatch / 2) continue;
      (hit ? n_hit : n_miss)++;
      in.random.pairs.push_back(pr);
    }
    while (in.contact.pairs.size() < kPairBatch) {
      const Pair pr = random_pair(rng);
      const int hit = hit_of(pr);
      ++in.contact_draws;
      in.undecided += hit < 0;
      if (hit > 0) in.contact.pairs.push_back(pr);
    }
    shuffle_and_convert(in.random, rng);
    shuffle_and_convert(in.contact, rng);
    return in;
  }

  static void bm_prod_overlap(benchmark::State& state, const Batch* b) {
    for (auto _ : state) {
      for (const Pair& pr : b->pairs) benchmark::DoNotOptimize(overlap(pr.a, pr.b));
    }
    set_per_query(state, b->pairs.size());
  }
  static void bm_prod_collide(benchmark::State& state, const Batch* b) {
    for (auto _ : state) {
      for (const Pair& pr : b->pairs) benchmark::DoNotOptimize(collide(pr.a, pr.b));
    }
    set_per_query(state, b->pairs.size());
  }
  static void bm_fcl_overlap(benchmark::State& state, const Batch* b) {
    for (auto _ : state) {
      for (const auto& pr : b->fcl) benchmark::DoNotOptimize(oracles::fcl_overlap_prepared(pr));
    }
    set_per_query(state, b->fcl.size());
  }
  static void bm_fcl_collide(benchmark::State& state, const Batch* b) {
    for (auto _ : state) {
      for (const auto& pr : b->fcl) benchmark::DoNotOptimize(oracles::fcl_collide_prepared(pr));
    }
    set_per_query(state, b->fcl.size());
  }
  // Reference only: validation + conversion + guarded fcl::collide, per query.
  static void bm_fcl_collide_adapter(benchmark::State& state, const Batch* b) {
    for (auto _ : state) {
      for (const Pair& pr : b->pairs) benchmark::DoNotOptimize(oracles::fcl_collide(pr.a, pr.b));
    }
    set_per_query(state, b->pairs.size());
  }

  static void register_batch(const char* set, const Batch& b) {
    const std::string s = set;
    benchmark::RegisterBenchmark(("BM_prod_overlap_" + s).c_str(), bm_prod_overlap, &b);
    benchmark::RegisterBenchmark(("BM_prod_collide_" + s).c_str(), bm_prod_collide, &b);
    benchmark::RegisterBenchmark(("BM_fcl_overlap_" + s).c_str(), bm_fcl_overlap, &b);
    benchmark::RegisterBenchmark(("BM_fcl_collide_" + s).c_str(), bm_fcl_collide, &b);
    benchmark::RegisterBenchmark(("BM_fcl_collide_adapter_" + s).c_str(), bm_fcl_collide_adapter, &b);
  }

  void print_batch(const char* set, const Batch& b) const {
    std::size_t prod_hits = 0, fcl_hits = 0, agree = 0, both = 0, fcl_not_ok = 0;
    std::vector<double> excess;  // FCL depth - production depth, where both hit
    for (std::size_t i = 0; i < b.pairs.size(); ++i) {
      const Contact p = collide(b.pairs[i].a, b.pairs[i].b);
      const oracles::PeerContact f = oracles::fcl_collide(b.pairs[i].a, b.pairs[i].b);
      if (!f.ok) {
        ++fcl_not_ok;
        continue;
      }
      prod_hits += p.hit;
      fcl_hits += f.hit;
      agree += (p.hit == f.hit);
      if (p.hit && f.hit) {
        ++both;
        excess.push_back(f.depth - p.depth);
      }
    }
    std::printf("%-8s overlapping: production %zu, FCL %zu; verdicts agree on %zu/%zu (FCL not ok: %zu)\n", set,
                prod_hits, fcl_hits, agree, b.pairs.size(), fcl_not_ok);
    if (!excess.empty()) {
      std::sort(excess.begin(), excess.end());
      std::printf("%-8s FCL depth - production depth over %zu contacts: min %.3g, median %.3g, max %.3g (%s)\n", set,
                  both, excess.front(), excess[excess.size() / 2], excess.back(), depth_note);
    }
  }

  /// The whole program: inputs, benchmarks, the ns/query table and ratios.
  int run(int argc, char** argv) const {
    const Inputs in = make_inputs(seed_from_env());
    std::printf("%s batches: %zu pairs each, seed = %llu (0x%llx; GEOMCHECK_BENCH_SEED overrides); selected by %s's "
                "verdicts (%zu undecided poses skipped)\n",
                name, in.random.pairs.size(), static_cast<unsigned long long>(in.seed),
                static_cast<unsigned long long>(in.seed), selected_by, in.undecided);
    std::printf("random poses overlapping (or touching): %zu of %zu drawn for the contact batch (%.0f%%)\n",
                in.contact.pairs.size(), in.contact_draws, 100.0 * in.contact.pairs.size() / in.contact_draws);
    print_batch("random", in.random);
    print_batch("contact", in.contact);
    std::printf("\n");
    std::fflush(stdout);
    register_batch("random", in.random);
    register_batch("contact", in.contact);
    CaptureReporter reporter(kPairBatch);
    if (int rc = run_benchmarks(argc, argv, reporter)) return rc;
    print_summary(reporter, {
                                {"overlap fcl/prod (random)", {"BM_fcl_overlap_random", "BM_prod_overlap_random"}},
                                {"collide fcl/prod (random)", {"BM_fcl_collide_random", "BM_prod_collide_random"}},
                                {"overlap fcl/prod (contact)", {"BM_fcl_overlap_contact", "BM_prod_overlap_contact"}},
                                {"collide fcl/prod (contact)", {"BM_fcl_collide_contact", "BM_prod_collide_contact"}},
                            });
    return 0;
  }
};

}  // namespace geomcheck::bench
