// geomcheck — the mesh family's part of a campaign (collide_cylinder_mesh):
// meshes drawn from gen::meshes, the subject (production, or a known-wrong
// variant) held to every check of mesh_checks.hpp (the brute force bit for
// bit, the deepest face, the certified engine face by face) and timed
// against the brute force. The run is verify()'s for a mesh subject
// (verify.hpp), in this process: the same runner, the same saved, shrunk and
// drawn failures.
#include <cstdio>
#include <filesystem>

#include "campaign.hpp"
#include "geomcheck/properties/generators.hpp"
#include "geomcheck/properties/mesh_checks.hpp"
#include "geomcheck/reports/report.hpp"
#include "geomcheck/verify.hpp"

namespace geomcheck {

report::MeshReport run_collide_cylinder_mesh(const CampaignOptions& opt, const std::filesystem::path& out_dir,
                                             int threads) {
  (void)threads;  // one thread: the family takes seconds
  const MeshImpl* impl = mesh_subject(opt.variant.empty() ? "production" : opt.variant);
  if (!impl) impl = &production_mesh();
  const int n = opt.cases > 0 ? opt.cases : kMeshDefaultCases;
  // Every mesh of the seed is drawn (the same meshes in every shard); this
  // shard's are run.
  auto all = gen::draw_meshes(opt.seed, n);
  std::vector<std::pair<MeshCase, std::string>> meshes;
  std::vector<int> index;
  for (int i = 0; i < n; ++i) {
    if (i % opt.shards != opt.shard) continue;
    meshes.push_back(std::move(all[i]));
    index.push_back(i);
  }
  VerifyOptions v;
  v.cases = static_cast<int>(meshes.size());
  v.seed = opt.seed;
  v.out = out_dir / "counterexamples";
  v.max_saved = report::kMaxSavedPerKind;
  v.quiet = true;
  v.summary = false;
  v.report = false;  // the campaign's report has the section
  v.isolate = false;
  v.program = "geomcheck";
  v.replay = impl == &production_mesh() ? "geomcheck replay " : std::string("geomcheck replay --subject ") + impl->name + " ";
  v.found_by = "campaign";
  v.seconds = opt.seconds;
  const VerifyResult res = verify(*impl, meshes, index, v);
  report::MeshReport rep = res.mesh_figures;
  rep.requested = static_cast<int>(meshes.size());
  if (opt.progress)
    std::fprintf(stderr, "[campaign] %-24s %7d meshes in %.1fs, %d failing\n", rep.name.c_str(), rep.meshes,
                 rep.seconds, rep.failures);
  return rep;
}

}  // namespace geomcheck
