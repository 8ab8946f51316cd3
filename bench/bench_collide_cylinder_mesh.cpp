// Cylinder/mesh: production against FCL on the same inputs, in one run.
//
//   bench_collide_cylinder_mesh [--benchmark_* flags]
//   GEOMCHECK_BENCH_SEED=<n> bench_collide_cylinder_mesh     (other queries)
//   GEOMCHECK_BENCH_VERIFY=<n|all> bench_collide_cylinder_mesh
//       (how many queries of each batch are checked against the brute force
//        before the run; 256 unless told)
//
// The mesh (fixed, independent of the seed): a heightfield of kCells x
// kCells square cells over [-10, 10]^2, two triangles per cell, vertices
// shared between faces (225^2 = 50,625 vertices, 100,352 faces), its height
// a sum of four sines of amplitude at most 0.5 in total (height()).
//
// Two batches of kBatch cylinders from a fixed seed (printed), each
// shuffled: radius in [0.05, 1], length in [0.1, 3], the axis a unit
// quaternion's image of +z, the middle uniform over the mesh's x/y range
// and height() + s * (e + 0.5) in z, s uniform in [-1, 1] and e the
// cylinder's vertical half extent. The verdicts that select them are
// production's (overlap(Cylinder, TriangleMesh)):
//   random   exactly half of them overlapping the mesh;
//   contact  every one overlapping the mesh.
//
// Before the run, on the first GEOMCHECK_BENCH_VERIFY queries of each batch,
// the program checks that production's answers through the hierarchy are
// the brute force's over all faces bit for bit (overlap; collide's hit,
// point, normal, depth and face index) and stops with a message otherwise.
//
// FCL: the mesh as fcl::BVHModel<OBBRSSd> (FclMesh, fcl_convert.hpp) and
// the cylinders converted once, outside the timed loops; fcl::collide as
// shipped (GST_LIBCCD: its mesh/shape traversal and per triangle libccd's
// MPR). FCL's traversal stops as soon as it holds max_contacts contacts, so
// BM_fcl_collide_* asks for as many contacts as the mesh has faces: every
// triangle in contact is reported and the deepest of them is returned (the
// figure comparable with production's deepest triangle).
// BM_fcl_collide_first_* (max_contacts = 1: the first triangle found, not
// the deepest) is there for reference. BM_prod_build / BM_fcl_build time one build of the
// mesh (the copy of the vertex and face arrays and the hierarchy: production
// TriangleMesh, FCL beginModel/addSubModel/endModel), per build.
// After the run the program prints ns/query (ns/build for the builds) and
// the FCL/production ratios.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "bench_common.hpp"
#include "bench_random.hpp"
#include "geomcheck/collide_cylinder_mesh.hpp"
#include "geomcheck/peers/fcl_convert.hpp"

namespace geomcheck::bench {
namespace {

constexpr std::size_t kBatch = 4096;
constexpr std::uint32_t kCells = 224;  // per side
constexpr double kHalfSide = 10;       // the mesh spans [-kHalfSide, kHalfSide]^2
constexpr std::size_t kDefaultVerify = 256;
constexpr std::uint32_t kNoFace = 0xffffffffu;

/// The surface: sines of amplitude 0.2 + 0.15 + 0.1 + 0.05 = 0.5 at most.
double height(double x, double y) {
  return 0.2 * std::sin(0.7 * x + 0.4) * std::sin(0.6 * y) + 0.15 * std::sin(1.3 * x - 0.9 * y + 1.0) +
         0.1 * std::cos(0.5 * x + 2.1 * y) + 0.05 * std::sin(3.7 * x) * std::cos(2.9 * y);
}

struct MeshData {
  std::vector<Vec3> vertices;
  std::vector<MeshFace> faces;
};

/// The heightfield: vertex (i, j) at index j * (kCells + 1) + i; cell (i, j)
/// split along its diagonal from (i, j) to (i + 1, j + 1), both triangles
/// counter-clockwise seen from +z.
MeshData heightfield() {
  MeshData d;
  const std::uint32_t n = kCells + 1;
  d.vertices.reserve(std::size_t{n} * n);
  for (std::uint32_t j = 0; j < n; ++j)
    for (std::uint32_t i = 0; i < n; ++i) {
      const double x = -kHalfSide + 2 * kHalfSide * i / kCells, y = -kHalfSide + 2 * kHalfSide * j / kCells;
      d.vertices.push_back({x, y, height(x, y)});
    }
  d.faces.reserve(2 * std::size_t{kCells} * kCells);
  for (std::uint32_t j = 0; j < kCells; ++j)
    for (std::uint32_t i = 0; i < kCells; ++i) {
      const std::uint32_t v00 = j * n + i, v10 = v00 + 1, v01 = v00 + n, v11 = v01 + 1;
      d.faces.push_back({v00, v10, v11});
      d.faces.push_back({v00, v11, v01});
    }
  return d;
}

/// A unit axis: a uniform unit quaternion (rejection in the 4-ball) applied
/// to +z (the third column of its rotation matrix), normalised.
Vec3 random_axis(Rng& rng) {
  const Vec3 u = rotation_columns(rng.unit_quaternion(0.01))[2];
  return (1 / length(u)) * u;
}

Cylinder random_cylinder(Rng& rng) {
  Cylinder c;
  c.r = rng.uniform(0.05, 1.0);
  const double len = rng.uniform(0.1, 3.0);
  const Vec3 u = random_axis(rng);
  const double x = rng.uniform(-kHalfSide, kHalfSide), y = rng.uniform(-kHalfSide, kHalfSide);
  const double uz = std::abs(u.z);
  const double e = 0.5 * len * uz + c.r * std::sqrt(std::max(0.0, 1 - uz * uz));  // vertical half extent
  const Vec3 mid{x, y, height(x, y) + rng.uniform(-1, 1) * (e + 0.5)};
  c.p = mid - 0.5 * len * u;
  c.q = mid + 0.5 * len * u;
  return c;
}

struct Batch {
  std::vector<Cylinder> cyl;
  std::vector<peers::FclCylinder> fcl;  // the same cylinders, converted for FCL
};

struct Inputs {
  std::uint64_t seed = 0;
  MeshData data;
  std::unique_ptr<TriangleMesh> mesh;
  std::unique_ptr<peers::FclMesh> fcl_mesh;
  int all_contacts = 1;  // max_contacts for BM_fcl_collide_*: the face count
  Batch random, contact;
  std::size_t contact_draws = 0;  // cylinders drawn for the contact batch
  double prod_build_ms = 0, fcl_build_ms = 0;  // the first build, for the printout
};

double ms_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

void shuffle_and_convert(Batch& b, Rng& rng) {
  shuffle(b.cyl, rng);
  b.fcl.reserve(b.cyl.size());
  for (const Cylinder& c : b.cyl) b.fcl.emplace_back(c);
}

Inputs make_inputs(std::uint64_t seed) {
  Inputs in;
  in.seed = seed;
  in.data = heightfield();
  auto t0 = std::chrono::steady_clock::now();
  in.mesh = std::make_unique<TriangleMesh>(in.data.vertices, in.data.faces);
  in.prod_build_ms = ms_since(t0);
  t0 = std::chrono::steady_clock::now();
  in.fcl_mesh = std::make_unique<peers::FclMesh>(*in.mesh);
  in.fcl_build_ms = ms_since(t0);
  in.all_contacts = static_cast<int>(in.mesh->size());
  const TriangleMesh& m = *in.mesh;
  Rng rng(seed);
  auto draw = [&] { return random_cylinder(rng); };
  auto hits = [&](const Cylinder& c) { return int(overlap(c, m)); };
  in.random.cyl = half_hitting(kBatch, draw, hits);
  in.contact.cyl = all_hitting(kBatch, draw, hits, in.contact_draws);
  shuffle_and_convert(in.random, rng);
  shuffle_and_convert(in.contact, rng);
  return in;
}

// --- verification: the hierarchy against the brute force, bit for bit --------

bool same_bits(double a, double b) {
  std::uint64_t x, y;
  std::memcpy(&x, &a, sizeof x);
  std::memcpy(&y, &b, sizeof y);
  return x == y;
}

bool same_bits(const Vec3& a, const Vec3& b) {
  return same_bits(a.x, b.x) && same_bits(a.y, b.y) && same_bits(a.z, b.z);
}

void print_contact(const char* who, const Contact& c, std::uint32_t face, bool ov) {
  std::fprintf(stderr,
               "  %-12s overlap %d, hit %d, face %lld, depth %a, normal (%a, %a, %a), point (%a, %a, %a)\n", who,
               ov, c.hit, face == kNoFace ? -1LL : static_cast<long long>(face), c.depth, c.normal.x, c.normal.y,
               c.normal.z, c.point.x, c.point.y, c.point.z);
}

/// How many queries of each batch to check (GEOMCHECK_BENCH_VERIFY).
std::size_t verify_count() {
  if (const char* s = std::getenv("GEOMCHECK_BENCH_VERIFY")) {
    if (std::strcmp(s, "all") == 0) return kBatch;
    return std::min<std::size_t>(kBatch, std::strtoull(s, nullptr, 0));
  }
  return kDefaultVerify;
}

void verify(const char* set, const Batch& b, const TriangleMesh& m, std::size_t n) {
  const auto t0 = std::chrono::steady_clock::now();
  n = std::min(n, b.cyl.size());
  std::size_t hits = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const Cylinder& c = b.cyl[i];
    std::uint32_t f_bvh = kNoFace, f_brute = kNoFace;
    const Contact bvh = collide(c, m, &f_bvh);
    const Contact brute = detail::collide_brute_force(c, m, &f_brute);
    const bool o_bvh = overlap(c, m), o_brute = detail::overlap_brute_force(c, m);
    hits += bvh.hit;
    if (bvh.hit != brute.hit || f_bvh != f_brute || !same_bits(bvh.depth, brute.depth) ||
        !same_bits(bvh.normal, brute.normal) || !same_bits(bvh.point, brute.point) || o_bvh != o_brute) {
      std::fprintf(stderr,
                   "FAILED: %s query %zu: production's answer through the hierarchy differs from the brute force "
                   "over all %zu faces\n  cylinder p (%a, %a, %a) q (%a, %a, %a) r %a\n",
                   set, i, m.size(), c.p.x, c.p.y, c.p.z, c.q.x, c.q.y, c.q.z, c.r);
      print_contact("hierarchy:", bvh, f_bvh, o_bvh);
      print_contact("brute force:", brute, f_brute, o_brute);
      std::exit(EXIT_FAILURE);
    }
  }
  std::printf("%-8s hierarchy == brute force, bit for bit (overlap; hit, point, normal, depth, face): %zu of %zu "
              "queries checked (%zu hits), %.1f s\n",
              set, n, b.cyl.size(), hits, ms_since(t0) / 1000);
}

// --- agreement with FCL ---------------------------------------------------------

double quantile(const std::vector<double>& sorted, double q) {
  return sorted[static_cast<std::size_t>(q * static_cast<double>(sorted.size() - 1) + 0.5)];
}

void print_excess(const char* set, const char* what, std::vector<double> excess) {
  if (excess.empty()) return;
  std::sort(excess.begin(), excess.end());
  const auto below = std::count_if(excess.begin(), excess.end(), [](double d) { return d < -1e-6; });
  std::printf("%-8s FCL depth - production depth, %s, over %zu common contacts: min %.3g, 10%% %.3g, median %.3g, "
              "90%% %.3g, max %.3g; below -1e-6: %lld\n",
              set, what, excess.size(), excess.front(), quantile(excess, 0.1), quantile(excess, 0.5),
              quantile(excess, 0.9), excess.back(), static_cast<long long>(below));
}

void print_batch(const char* set, const Batch& b, const Inputs& in) {
  const TriangleMesh& m = *in.mesh;
  std::size_t prod_overlap = 0, prod_hits = 0, fcl_hits = 0, agree = 0, prod_only = 0, fcl_only = 0, not_ok = 0;
  std::vector<double> excess_all, excess_first, contacts;
  for (std::size_t i = 0; i < b.cyl.size(); ++i) {
    const bool ov = overlap(b.cyl[i], m);
    const Contact p = collide(b.cyl[i], m);
    int n = 0;
    const peers::PeerContact f = peers::fcl_collide_prepared(b.fcl[i], *in.fcl_mesh, in.all_contacts, &n);
    const peers::PeerContact f1 = peers::fcl_collide_prepared(b.fcl[i], *in.fcl_mesh, 1);
    prod_overlap += ov;
    prod_hits += p.hit;
    if (!f.ok || !f1.ok) {
      ++not_ok;
      continue;
    }
    fcl_hits += f.hit;
    agree += (ov == f.hit);
    prod_only += (ov && !f.hit);
    fcl_only += (!ov && f.hit);
    if (f.hit) contacts.push_back(n);
    if (p.hit && f.hit) excess_all.push_back(f.depth - p.depth);
    if (p.hit && f1.hit) excess_first.push_back(f1.depth - p.depth);
  }
  std::printf("%-8s overlapping: production %zu (collide hits %zu), FCL %zu; verdicts agree on %zu/%zu "
              "(production only %zu, FCL only %zu; FCL not ok %zu)\n",
              set, prod_overlap, prod_hits, fcl_hits, agree, b.cyl.size(), prod_only, fcl_only, not_ok);
  if (!contacts.empty()) {
    std::sort(contacts.begin(), contacts.end());
    double mean = 0;
    for (double c : contacts) mean += c;
    mean /= static_cast<double>(contacts.size());
    std::printf("%-8s triangles in contact per FCL hit (max_contacts = %d): mean %.0f, median %.0f, 90%% %.0f, "
                "max %.0f\n",
                set, in.all_contacts, mean, quantile(contacts, 0.5), quantile(contacts, 0.9), contacts.back());
  }
  print_excess(set, "deepest of all FCL contacts", std::move(excess_all));
  print_excess(set, "FCL's first contact (max_contacts = 1)", std::move(excess_first));
}

/// Prints the mesh and the batches, checking the first queries of each
/// against the brute force on the way (verify: exits on a difference).
void check_and_print(const Inputs& in) {
  std::printf("mesh: heightfield %u x %u cells over [-%g, %g]^2, %zu faces, %zu vertices (shared); first build: "
              "production %.1f ms, FCL %.1f ms\n",
              kCells, kCells, kHalfSide, kHalfSide, in.mesh->size(), in.mesh->vertices().size(), in.prod_build_ms,
              in.fcl_build_ms);
  std::printf("cylinder batches: %zu queries each, %s; selected by production's overlap verdicts\n",
              in.random.cyl.size(), seed_text(in.seed).c_str());
  std::printf("cylinders overlapping the mesh: %zu of %zu drawn for the contact batch (%.0f%%)\n",
              in.contact.cyl.size(), in.contact_draws, 100.0 * in.contact.cyl.size() / in.contact_draws);
  const std::size_t nv = verify_count();
  std::printf("checking the first %zu queries of each batch against the brute force over all faces "
              "(GEOMCHECK_BENCH_VERIFY=<n|all> for another count)\n",
              nv);
  std::fflush(stdout);
  verify("random", in.random, *in.mesh, nv);
  verify("contact", in.contact, *in.mesh, nv);
  print_batch("random", in.random, in);
  print_batch("contact", in.contact, in);
  std::printf("\n");
  std::fflush(stdout);
}

// --- benchmarks --------------------------------------------------------------------

/// BM_prod_overlap_<set>, BM_prod_collide_<set>, BM_fcl_collide_<set> and
/// BM_fcl_collide_first_<set> over the batch.
void register_batch(const char* set, const Batch& b, const Inputs& in) {
  const std::string s = set_suffix(set);
  const TriangleMesh& m = *in.mesh;
  const peers::FclMesh& fm = *in.fcl_mesh;
  const int all = in.all_contacts;
  register_each("BM_prod_overlap" + s, b.cyl, [&m](const Cylinder& c) { return overlap(c, m); });
  register_each("BM_prod_collide" + s, b.cyl, [&m](const Cylinder& c) {
    std::uint32_t face = 0;
    const Contact hit = collide(c, m, &face);
    benchmark::DoNotOptimize(face);
    return hit;
  });
  register_each("BM_fcl_collide" + s, b.fcl,
                [&fm, all](const peers::FclCylinder& c) { return peers::fcl_collide_prepared(c, fm, all); });
  register_each("BM_fcl_collide_first" + s, b.fcl,
                [&fm](const peers::FclCylinder& c) { return peers::fcl_collide_prepared(c, fm, 1); });
}

/// BM_prod_build and BM_fcl_build: one build of the mesh an iteration
/// (their batch of 1 told to `reporter`).
void register_builds(const Inputs& in, CaptureReporter& reporter) {
  benchmark::RegisterBenchmark("BM_prod_build", [&in](benchmark::State& state) {
    for (auto _ : state) {
      const TriangleMesh m(in.data.vertices, in.data.faces);
      benchmark::DoNotOptimize(m.bvh().nodes.data());
    }
    set_per_query(state, 1);
  })->Unit(benchmark::kMillisecond);
  benchmark::RegisterBenchmark("BM_fcl_build", [&in](benchmark::State& state) {
    for (auto _ : state) {
      const peers::FclMesh m(*in.mesh);
      benchmark::DoNotOptimize(&m.model);
    }
    set_per_query(state, 1);
  })->Unit(benchmark::kMillisecond);
  reporter.set_batch("BM_prod_build", 1);
  reporter.set_batch("BM_fcl_build", 1);
}

}  // namespace
}  // namespace geomcheck::bench

int main(int argc, char** argv) {
  using namespace geomcheck::bench;
  const Inputs in = make_inputs(seed_from_env());
  check_and_print(in);
  CaptureReporter reporter(kBatch);
  register_batch("random", in.random, in);
  register_batch("contact", in.contact, in);
  register_builds(in, reporter);
  if (int rc = run_and_summarise(argc, argv, reporter,
                                 {fcl_over_prod("collide", "random"), fcl_over_prod("collide", "contact"),
                                  // overlap: FCL's first contact (max_contacts = 1) is its overlap test
                                  Ratio{"overlap fcl-first/prod (random)", {"BM_fcl_collide_first_random", "BM_prod_overlap_random"}},
                                  Ratio{"overlap fcl-first/prod (contact)", {"BM_fcl_collide_first_contact", "BM_prod_overlap_contact"}},
                                  fcl_over_prod("build")}))
    return rc;
  const double pb = reporter.ns_per_query("BM_prod_build"), fb = reporter.ns_per_query("BM_fcl_build");
  if (pb > 0 && fb > 0) std::printf("build per mesh: production %.2f ms, FCL %.2f ms\n", pb * 1e-6, fb * 1e-6);
  return 0;
}
