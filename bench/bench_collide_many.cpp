// The list queries (collide_many.hpp) against FCL per pair, in one run: one
// random cylinder and kPairBatch spheres, capsules or boxes around it
// (exactly half overlapping according to production, shuffled; seed
// printed). Per element:
//   BM_many_overlap_<B>   overlap_many over the batch;
//   BM_many_collide_<B>   collide_many over the batch;
//   BM_prod_overlap_<B>, BM_prod_collide_<B>   the scalar query per element;
//   BM_fcl_overlap_<B>, BM_fcl_collide_<B>     FCL per pair (the pairs
//                          converted once beforehand, fcl_convert.hpp).
// The shapes are drawn as in the query programs (bench_random.hpp).
// After the run: ns per element and FCL / list-query ratios (the issue's
// target: 20x for spheres and capsules).
//
//   build/release/bench/bench_collide_many [--benchmark_* flags]
#include <benchmark/benchmark.h>

#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "bench_common.hpp"
#include "bench_random.hpp"
#include "geomcheck/collide_cylinder_capsule.hpp"
#include "geomcheck/collide_cylinder_obb.hpp"
#include "geomcheck/collide_cylinder_sphere.hpp"
#include "geomcheck/collide_many.hpp"
#include "geomcheck/peers/fcl_convert.hpp"

namespace geomcheck::bench {
namespace {

constexpr std::size_t kPairBatch = 4096;

template <class B, class Prepared>
struct ManyBatch {
  Cylinder cyl;
  std::vector<B> b;
  std::vector<Prepared> fcl;
};

template <class B, class Prepared>
ManyBatch<B, Prepared> make_batch(Rng& rng, B (*draw)(Rng&, const Cylinder&)) {
  ManyBatch<B, Prepared> m;
  m.cyl = rng.cylinder();
  m.b = half_hitting(kPairBatch, [&] { return draw(rng, m.cyl); }, [&](const B& x) { return int(overlap(m.cyl, x)); });
  shuffle(m.b, rng);
  for (const B& x : m.b) m.fcl.emplace_back(m.cyl, x);
  return m;
}

template <class B, class Prepared>
void register_batch(const std::string& name, const ManyBatch<B, Prepared>& m) {
  benchmark::RegisterBenchmark(("BM_many_overlap_" + name).c_str(), [&m](benchmark::State& state) {
    const std::unique_ptr<bool[]> out(new bool[m.b.size()]);
    for (auto _ : state) {
      overlap_many(m.cyl, m.b.data(), m.b.size(), out.get());
      benchmark::DoNotOptimize(out.get());
      benchmark::ClobberMemory();
    }
    set_per_query(state, m.b.size());
  });
  benchmark::RegisterBenchmark(("BM_many_collide_" + name).c_str(), [&m](benchmark::State& state) {
    std::vector<Contact> out(m.b.size());
    for (auto _ : state) {
      collide_many(m.cyl, m.b.data(), m.b.size(), out.data());
      benchmark::DoNotOptimize(out.data());
      benchmark::ClobberMemory();
    }
    set_per_query(state, m.b.size());
  });
  register_each("BM_prod_overlap_" + name, m.b, [&m](const B& x) { return overlap(m.cyl, x); });
  register_each("BM_prod_collide_" + name, m.b, [&m](const B& x) { return collide(m.cyl, x); });
  register_each("BM_fcl_overlap_" + name, m.fcl, [](const Prepared& p) { return peers::fcl_overlap_prepared(p); });
  register_each("BM_fcl_collide_" + name, m.fcl, [](const Prepared& p) { return peers::fcl_collide_prepared(p); });
}

Ratio fcl_over_many(const std::string& query, const std::string& b) {
  return {query + " fcl/list (" + b + ")", {"BM_fcl_" + query + "_" + b, "BM_many_" + query + "_" + b}};
}
Ratio scalar_over_many(const std::string& query, const std::string& b) {
  return {query + " scalar/list (" + b + ")", {"BM_prod_" + query + "_" + b, "BM_many_" + query + "_" + b}};
}

}  // namespace
}  // namespace geomcheck::bench

int main(int argc, char** argv) {
  using namespace geomcheck;
  using namespace geomcheck::bench;
  const std::uint64_t seed = seed_from_env();
  Rng rng(seed);
  const auto spheres = make_batch<Sphere, peers::FclCylinderSphere>(rng, random_sphere);
  const auto capsules = make_batch<Capsule, peers::FclCylinderCapsule>(rng, random_capsule);
  const auto boxes = make_batch<Obb, peers::FclCylinderBox>(rng, random_box);
  std::printf("list queries: one cylinder and %zu shapes per batch (half overlapping according to production), %s\n\n",
              kPairBatch, seed_text(seed).c_str());
  std::fflush(stdout);
  register_batch("sphere", spheres);
  register_batch("capsule", capsules);
  register_batch("box", boxes);
  CaptureReporter reporter(kPairBatch);
  std::vector<Ratio> ratios;
  for (const char* b : {"sphere", "capsule", "box"})
    for (const char* q : {"overlap", "collide"}) {
      ratios.push_back(fcl_over_many(q, b));
      ratios.push_back(scalar_over_many(q, b));
    }
  return run_and_summarise(argc, argv, reporter, ratios);
}
