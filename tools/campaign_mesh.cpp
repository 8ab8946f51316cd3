// geomcheck — the mesh family's part of a campaign (collide_cylinder_mesh):
// meshes drawn from gen::meshes, the subject held to every check of
// mesh_checks.hpp (the brute force bit for bit, the deepest face, the
// certified engine face by face), timed against the brute force; a failing
// mesh saved as a mesh file with its drawing beside it.
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <thread>

#include "campaign.hpp"
#include "geomcheck/mesh_file.hpp"
#include "geomcheck/properties/generators.hpp"
#include "geomcheck/properties/mesh_checks.hpp"
#include "geomcheck/reports/draw.hpp"
#include "geomcheck/reports/report.hpp"

namespace geomcheck {

namespace {

using Clock = std::chrono::steady_clock;

// One mesh's outcome.
struct MeshRow {
  std::string verdict;            // the exact verdict, or "invalid"
  std::string property, problem;  // the first failure, empty when none
  int by_box = 0, by_engine = 0;
  double prod_us = 0, brute_us = 0;
  bool run = false;
};

MeshRow check_mesh_case(const MeshCase& c, const MeshImpl& impl) {
  MeshRow r;
  const TriangleMesh mesh(c.vertices, c.faces);
  const auto t0 = Clock::now();
  (void)collide(c.cyl, mesh);
  const auto t1 = Clock::now();
  (void)detail::collide_brute_force(c.cyl, mesh);
  const auto t2 = Clock::now();
  r.prod_us = micros(t0, t1), r.brute_us = micros(t1, t2);
  MeshTruth truth;
  if (auto f = check_mesh_all(c.cyl, mesh, impl, &truth)) r.property = f->property, r.problem = f->detail;
  r.verdict = truth.valid ? oracle::to_string(truth.verdict) : "invalid";
  r.by_box = truth.faces_by_box, r.by_engine = truth.faces_by_engine;
  return r;
}

// A failing mesh saved as a mesh file, drawn beside it; its path for the report.
std::string save_mesh_case(const std::filesystem::path& dir, int index, const MeshCase& c, const MeshRow& r,
                           const std::string& query, const MeshImpl& impl, std::uint64_t seed) {
  std::filesystem::create_directories(dir);
  char name[96];
  std::snprintf(name, sizeof name, "%05d-%s.case", index, r.property.c_str());
  MeshFile f;
  f.query = query;
  f.cylinder = c.cyl, f.vertices = c.vertices, f.faces = c.faces;
  f.found_by = "campaign seed=" + std::to_string(seed) + " case=" + std::to_string(index) + " mode=" + c.mode;
  if (r.verdict != "invalid") f.oracle_verdict = r.verdict;
  f.note = r.property + ": " + r.problem;
  const std::filesystem::path path = dir / name;
  std::string err;
  if (!save_mesh_file(path, f, err)) {
    std::fprintf(stderr, "[campaign] cannot save %s: %s\n", path.string().c_str(), err.c_str());
    return "";
  }
  const std::string replay = "geomcheck replay " + path.string() +
                             (&impl == &production_mesh() ? std::string() : std::string(" --subject ") + impl.name);
  const TriangleMesh mesh = mesh_of(f);
  std::uint32_t face = 0xffffffffu;
  const Contact k = impl.collide(c.cyl, mesh, &face);
  report::write_counterexample_page(path.string() + ".html", name,
                                    draw::mesh_views(c.cyl, mesh, k, face, impl.name, std::string(name) + ": " + r.property),
                                    impl.name, replay);
  return path.string();
}

}  // namespace

report::MeshReport run_collide_cylinder_mesh(const CampaignOptions& opt, const std::filesystem::path& out_dir,
                                             int threads) {
  report::MeshReport rep;
  rep.name = "collide_cylinder_mesh";
  for (const auto& q : kAllQueries)
    if (rep.name == q.name) rep.summary = q.summary;
  const MeshImpl* impl = mesh_subject(opt.variant.empty() ? "production" : opt.variant);
  if (!impl) impl = &production_mesh();
  rep.under_test = impl->name;
  const int n = opt.cases > 0 ? opt.cases : kMeshDefaultCases;
  const auto mine = [&](int i) { return i % opt.shards == opt.shard; };
  // Drawn in sequence (one stream, as every shard sees it), checked in parallel.
  std::vector<MeshCase> cases;
  cases.reserve(n);
  const auto gen = gen::meshes(true);
  rc::Random random(opt.seed ^ 0x6d657368c0ffee00ull);
  for (int i = 0; i < n; ++i) {
    MeshCase c = gen(random.split(), rc::kNominalSize).value();
    if (!mine(i)) c = MeshCase{};  // not this shard's: not kept
    cases.push_back(std::move(c));
    rep.requested += mine(i);
  }
  std::vector<MeshRow> rows(cases.size());
  std::atomic<int> next{0}, done{0};
  const auto start = Clock::now();
  auto worker = [&] {
    for (int i; (i = next++) < static_cast<int>(cases.size());) {
      if (!mine(i)) continue;
      if (opt.seconds > 0 && std::chrono::duration<double>(Clock::now() - start).count() > opt.seconds) return;
      rows[i] = check_mesh_case(cases[i], *impl);
      rows[i].run = true;
      ++done;
    }
  };
  std::vector<std::thread> pool;
  for (int k = 0; k < threads; ++k) pool.emplace_back(worker);
  for (auto& th : pool) th.join();
  rep.seconds = std::chrono::duration<double>(Clock::now() - start).count();
  if (opt.progress)
    std::fprintf(stderr, "[campaign] %-24s %7d meshes in %.1fs\n", rep.name.c_str(), done.load(), rep.seconds);
  std::map<std::string, int> saved;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const MeshRow& r = rows[i];
    if (!r.run) continue;
    ++rep.meshes;
    rep.faces += cases[i].faces.size();
    rep.modes[cases[i].mode]++;
    rep.verdicts[r.verdict]++;
    rep.faces_by_box += r.by_box, rep.faces_by_engine += r.by_engine;
    rep.production_us += r.prod_us, rep.brute_force_us += r.brute_us;
    if (r.property.empty()) continue;
    ++rep.failures;
    rep.failures_by_property[r.property]++;
    if (saved[r.property]++ >= report::kMaxSavedPerKind) continue;
    const std::string path =
        save_mesh_case(out_dir / "counterexamples" / rep.name, static_cast<int>(i), cases[i], r, rep.name, *impl, opt.seed);
    if (!path.empty()) rep.counterexamples.push_back(path);
  }
  rep.stopped_by_time = rep.meshes < rep.requested;
  return rep;
}

}  // namespace geomcheck
