// geomcheck benchmarks — a convex shape against another, production against
// FCL on the same inputs, in one run (the cylinder's capsule, box, triangle
// and cylinder pairs, the sphere and capsule pairs; the cylinder/sphere
// program takes its batch and benchmarks from here).
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
#include "bench_engines.hpp"
#include "bench_random.hpp"
#include "geomcheck/peers/fcl_adapter.hpp"
#include "geomcheck/results.hpp"
#include "geomcheck/shapes.hpp"
#include "geomcheck/peers/fcl_convert.hpp"

namespace geomcheck::bench {

inline constexpr std::size_t kPairBatch = 4096;

/// The benchmark of collide(A, B) against FCL (A a cylinder unless given);
/// `Prepared` is the pair converted once for FCL (fcl_convert.hpp).
template <class B, class Prepared, class A = Cylinder>
struct PairBench {
  struct Pair {
    A a;
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

  const char* name;                         ///< e.g. "cylinder/capsule"
  B (*random_b)(Rng&, const A& a);  ///< B in a random pose near `a` (a random A, Rng::first, drawn first)
  const char* depth_note;                   ///< what the two depths are, printed with their differences
  /// The selecting verdict: 1 overlapping (or touching), 0 apart, -1
  /// undecided (the pose is skipped); null: production's overlap.
  int (*verdict)(const Pair&) = nullptr;
  const char* selected_by = "production";  ///< whose verdict `verdict` is
  /// An earlier version of production's collide, timed in the same run
  /// (BM_prod_collide_before_<set>, and its ratio to FCL); null: none.
  Contact (*collide_before)(const A& a, const B& b) = nullptr;
  /// The pair's second query, production's exact penetration depth
  /// (penetration_cylinder_<B>), timed in the same run
  /// (BM_prod_penetration_<set>, and its ratio to FCL's collide); null: none.
  Contact (*penetration)(const A& a, const B& b) = nullptr;
  /// The other engines timed in the same run (bench_engines.hpp's
  /// other_engines<Q>(): BM_<engine>_overlap_<set>, BM_<engine>_collide_<set>
  /// and their ratios to production); empty: FCL alone.
  std::vector<OtherEngine<A, B>> others{};

  /// One random pose: a random A, then B near it.
  Pair random_pair(Rng& rng) const {
    Pair pr;
    pr.a = rng.first<A>();
    pr.b = random_b(rng, pr.a);
    return pr;
  }

  /// The selecting verdict of a pose (production's overlap unless `verdict` is given).
  int hit_of(const Pair& pr) const { return verdict ? verdict(pr) : int(overlap(pr.a, pr.b)); }

  /// kPairBatch random poses, exactly half of them overlapping according to
  /// the selecting verdict (undecided ones counted in `undecided`).
  std::vector<Pair> half_overlapping(Rng& rng, std::size_t& undecided) const {
    return half_hitting(kPairBatch, [&] { return random_pair(rng); }, [&](const Pair& pr) { return hit_of(pr); },
                        &undecided);
  }

  static void shuffle_and_convert(Batch& b, Rng& rng) {
    shuffle(b.pairs, rng);
    b.fcl.reserve(b.pairs.size());
    for (const Pair& pr : b.pairs) b.fcl.emplace_back(pr.a, pr.b);
  }

  Inputs make_inputs(std::uint64_t seed) const {
    Inputs in;
    in.seed = seed;
    Rng rng(seed);
    in.random.pairs = half_overlapping(rng, in.undecided);
    in.contact.pairs = all_hitting(kPairBatch, [&] { return random_pair(rng); },
                                   [&](const Pair& pr) { return hit_of(pr); }, in.contact_draws, &in.undecided);
    shuffle_and_convert(in.random, rng);
    shuffle_and_convert(in.contact, rng);
    return in;
  }

  /// BM_prod_overlap, BM_prod_collide, BM_fcl_overlap, BM_fcl_collide and
  /// BM_fcl_collide_adapter (each followed by _<set> unless `set` is empty)
  /// over the batch.
  void register_batch(const std::string& set, const Batch& b) const {
    const std::string s = set_suffix(set);
    register_each("BM_prod_overlap" + s, b.pairs, [](const Pair& pr) { return overlap(pr.a, pr.b); });
    register_each("BM_prod_collide" + s, b.pairs, [](const Pair& pr) { return collide(pr.a, pr.b); });
    if (collide_before) {
      const auto before = collide_before;
      register_each("BM_prod_collide_before" + s, b.pairs, [before](const Pair& pr) { return before(pr.a, pr.b); });
    }
    if (penetration) {
      const auto pen = penetration;
      register_each("BM_prod_penetration" + s, b.pairs, [pen](const Pair& pr) { return pen(pr.a, pr.b); });
    }
    register_each("BM_fcl_overlap" + s, b.fcl, [](const Prepared& pr) { return peers::fcl_overlap_prepared(pr); });
    register_each("BM_fcl_collide" + s, b.fcl, [](const Prepared& pr) { return peers::fcl_collide_prepared(pr); });
    for (const OtherEngine<A, B>& e : others) {
      register_each("BM_" + e.key + "_overlap" + s, b.pairs, [e](const Pair& pr) { return e.overlap(pr.a, pr.b); });
      register_each("BM_" + e.key + "_collide" + s, b.pairs, [e](const Pair& pr) { return e.collide(pr.a, pr.b); });
    }
    // Reference only: validation + conversion + guarded fcl::collide, per query.
    register_each("BM_fcl_collide_adapter" + s, b.pairs,
                  [](const Pair& pr) { return peers::fcl_collide(pr.a, pr.b); });
  }

  void print_batch(const char* set, const Batch& b) const {
    std::size_t prod_hits = 0, fcl_hits = 0, agree = 0, both = 0, fcl_not_ok = 0;
    std::vector<double> excess;  // FCL depth - production depth, where both hit
    for (std::size_t i = 0; i < b.pairs.size(); ++i) {
      const Contact p = collide(b.pairs[i].a, b.pairs[i].b);
      const peers::PeerContact f = peers::fcl_collide(b.pairs[i].a, b.pairs[i].b);
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
    std::printf("%s batches: %zu pairs each, %s; selected by %s's verdicts (%zu undecided poses skipped)\n", name,
                in.random.pairs.size(), seed_text(in.seed).c_str(), selected_by, in.undecided);
    std::printf("random poses overlapping (or touching): %zu of %zu drawn for the contact batch (%.0f%%)\n",
                in.contact.pairs.size(), in.contact_draws, 100.0 * in.contact.pairs.size() / in.contact_draws);
    print_batch("random", in.random);
    print_batch("contact", in.contact);
    std::printf("\n");
    std::fflush(stdout);
    register_batch("random", in.random);
    register_batch("contact", in.contact);
    CaptureReporter reporter(kPairBatch);
    std::vector<Ratio> ratios{fcl_over_prod("overlap", "random"), fcl_over_prod("collide", "random"),
                              fcl_over_prod("overlap", "contact"), fcl_over_prod("collide", "contact")};
    for (const OtherEngine<A, B>& e : others)
      for (const char* set : {"random", "contact"})
        for (const char* q : {"overlap", "collide"})
          ratios.push_back({std::string(q) + " " + e.key + "/prod (" + set + ")",
                            {"BM_" + e.key + "_" + q + "_" + set, std::string("BM_prod_") + q + "_" + set}});
    if (collide_before)
      for (const char* set : {"random", "contact"})
        ratios.push_back({std::string("collide fcl/prod-before (") + set + ")",
                          {std::string("BM_fcl_collide_") + set, std::string("BM_prod_collide_before_") + set}});
    if (penetration)
      for (const char* set : {"random", "contact"})
        ratios.push_back({std::string("penetration fcl-collide/prod (") + set + ")",
                          {std::string("BM_fcl_collide_") + set, std::string("BM_prod_penetration_") + set}});
    return run_and_summarise(argc, argv, reporter, ratios);
  }
};

/// The main() of a pair program whose query Q the other engines answer
/// too: `bench` with other_engines<Q>() in the same run.
template <QueryId Q, class B, class Prepared, class A>
int run_with_other_engines(PairBench<B, Prepared, A> bench, int argc, char** argv) {
  bench.others = other_engines<Q>();
  return bench.run(argc, argv);
}

}  // namespace geomcheck::bench
