// Cylinder/cylinder: production against FCL on the same inputs, in one run.
//
//   bench_collide_cylinder_cylinder [--benchmark_* flags]
//   GEOMCHECK_BENCH_SEED=<n> bench_collide_cylinder_cylinder   (other inputs)
//
// Two batches of kBatch cylinder/cylinder pairs from a fixed seed (printed),
// each shuffled so that branches are not predictable:
//   random   random poses, exactly half of them overlapping according to
//            production;
//   contact  pairs in contact: every one overlapping according to
//            production (shallow and deep as the generator gives them), so
//            that every FCL collide runs MPR's penetration phase.
// The FCL benchmarks time fcl::collide on shapes converted once beforehand
// (fcl_convert.hpp: FCL as shipped, libccd's MPR, GST_LIBCCD: FCL has no
// closed form for two cylinders); BM_fcl_collide_adapter_* adds the
// adapter's validation, conversion and guarded support functions
// (fcl_adapter.hpp) for reference. After the run the program prints
// ns/query and the FCL/production ratios per batch. Neither depth is the
// penetration depth: production's is the overlap along its normal (an upper
// bound), FCL's MPR's estimate.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "bench_common.hpp"
#include "bench_random.hpp"
#include "geomcheck/collide_cylinder_cylinder.hpp"
#include "geomcheck/oracles/fcl_adapter.hpp"
#include "geomcheck/oracles/fcl_convert.hpp"

namespace geomcheck::bench {
namespace {

constexpr std::size_t kBatch = 4096;

struct Pair {
  Cylinder a, b;
};

struct Batch {
  std::vector<Pair> pairs;
  std::vector<oracles::FclCylinderCylinder> fcl;  // the same pairs, converted for FCL
};

struct Inputs {
  std::uint64_t seed = 0;
  Batch random, contact;
};

/// A random pose: B's middle within reach + 1.5 of A's middle, B's length
/// 0.5..4 and radius 0.1..1.5 (as Rng::cylinder), any direction.
Pair random_pair(Rng& rng) {
  Pair pr;
  pr.a = rng.cylinder();
  const Vec3 mid = 0.5 * pr.a.p + 0.5 * pr.a.q;
  const double reach = 0.5 * length(pr.a.q - pr.a.p) + pr.a.r;
  const Vec3 c = mid + rng.in_box(reach + 1.5);
  const Vec3 half = (0.5 * rng.uniform(0.5, 4.0)) * rng.direction();
  pr.b = {c - half, c + half, rng.uniform(0.1, 1.5)};
  return pr;
}

void shuffle_and_convert(Batch& b, Rng& rng) {
  for (std::size_t i = b.pairs.size(); i > 1; --i) std::swap(b.pairs[i - 1], b.pairs[rng.next() % i]);
  b.fcl.reserve(b.pairs.size());
  for (const Pair& pr : b.pairs) b.fcl.emplace_back(pr.a, pr.b);
}

Inputs make_inputs(std::uint64_t seed) {
  Inputs in;
  in.seed = seed;
  Rng rng(seed);
  std::size_t n_hit = 0, n_miss = 0;
  while (in.random.pairs.size() < kBatch) {
    const Pair pr = random_pair(rng);
    const bool hit = overlap(pr.a, pr.b);
    if (hit ? n_hit >= kBatch / 2 : n_miss >= kBatch / 2) continue;
    (hit ? n_hit : n_miss)++;
    in.random.pairs.push_back(pr);
  }
  while (in.contact.pairs.size() < kBatch) {
    const Pair pr = random_pair(rng);
    if (overlap(pr.a, pr.b)) in.contact.pairs.push_back(pr);
  }
  shuffle_and_convert(in.random, rng);
  shuffle_and_convert(in.contact, rng);
  return in;
}

const Inputs& inputs() {
  static const Inputs in = make_inputs(seed_from_env());
  return in;
}

void bm_prod_overlap(benchmark::State& state, const Batch* b) {
  for (auto _ : state) {
    for (const Pair& pr : b->pairs) benchmark::DoNotOptimize(overlap(pr.a, pr.b));
  }
  set_per_query(state, b->pairs.size());
}

void bm_prod_collide(benchmark::State& state, const Batch* b) {
  for (auto _ : state) {
    for (const Pair& pr : b->pairs) benchmark::DoNotOptimize(collide(pr.a, pr.b));
  }
  set_per_query(state, b->pairs.size());
}

void bm_fcl_overlap(benchmark::State& state, const Batch* b) {
  for (auto _ : state) {
    for (const auto& pr : b->fcl) benchmark::DoNotOptimize(oracles::fcl_overlap_prepared(pr));
  }
  set_per_query(state, b->fcl.size());
}

void bm_fcl_collide(benchmark::State& state, const Batch* b) {
  for (auto _ : state) {
    for (const auto& pr : b->fcl) benchmark::DoNotOptimize(oracles::fcl_collide_prepared(pr));
  }
  set_per_query(state, b->fcl.size());
}

// Reference only: validation + conversion + guarded fcl::collide, per query.
void bm_fcl_collide_adapter(benchmark::State& state, const Batch* b) {
  for (auto _ : state) {
    for (const Pair& pr : b->pairs) benchmark::DoNotOptimize(oracles::fcl_collide(pr.a, pr.b));
  }
  set_per_query(state, b->pairs.size());
}

void register_batch(const char* set, const Batch& b) {
  const std::string s = set;
  benchmark::RegisterBenchmark(("BM_prod_overlap_" + s).c_str(), bm_prod_overlap, &b);
  benchmark::RegisterBenchmark(("BM_prod_collide_" + s).c_str(), bm_prod_collide, &b);
  benchmark::RegisterBenchmark(("BM_fcl_overlap_" + s).c_str(), bm_fcl_overlap, &b);
  benchmark::RegisterBenchmark(("BM_fcl_collide_" + s).c_str(), bm_fcl_collide, &b);
  benchmark::RegisterBenchmark(("BM_fcl_collide_adapter_" + s).c_str(), bm_fcl_collide_adapter, &b);
}

void print_batch(const char* set, const Batch& b) {
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
    std::printf("%-8s FCL depth - production depth over %zu contacts: min %.3g, median %.3g, max %.3g "
                "(production's is the overlap along its normal, an upper bound of the penetration depth; FCL's "
                "is MPR's estimate)\n",
                set, both, excess.front(), excess[excess.size() / 2], excess.back());
  }
}

void print_inputs(const Inputs& in) {
  std::printf("cylinder/cylinder batches: %zu pairs each, seed = %llu (0x%llx; GEOMCHECK_BENCH_SEED overrides)\n",
              in.random.pairs.size(), static_cast<unsigned long long>(in.seed),
              static_cast<unsigned long long>(in.seed));
  print_batch("random", in.random);
  print_batch("contact", in.contact);
  std::printf("\n");
  std::fflush(stdout);
}

}  // namespace
}  // namespace geomcheck::bench

int main(int argc, char** argv) {
  using namespace geomcheck::bench;
  print_inputs(inputs());
  register_batch("random", inputs().random);
  register_batch("contact", inputs().contact);
  CaptureReporter reporter(kBatch);
  if (int rc = run_benchmarks(argc, argv, reporter)) return rc;
  print_summary(reporter, {
                              {"overlap fcl/prod (random)", {"BM_fcl_overlap_random", "BM_prod_overlap_random"}},
                              {"collide fcl/prod (random)", {"BM_fcl_collide_random", "BM_prod_collide_random"}},
                              {"overlap fcl/prod (contact)", {"BM_fcl_overlap_contact", "BM_prod_overlap_contact"}},
                              {"collide fcl/prod (contact)", {"BM_fcl_collide_contact", "BM_prod_collide_contact"}},
                          });
  return 0;
}
