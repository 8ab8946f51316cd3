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

report::MeshReport run_collide_cylinder_mesh(const CampaignOptions& opt, const std::filesystem::path& out_dir) {
  const MeshImpl* impl = mesh_subject(opt.variant.empty() ? "production" : opt.variant);
  if (!impl) impl = &production_mesh();
  // Every mesh of the seed is drawn (the same meshes in every shard); this
  // shard's are run, on one thread (the family takes seconds).
  auto meshes = gen::draw_meshes(opt.seed, opt.cases > 0 ? opt.cases : kMeshDefaultCases);
  std::vector<int> index;
  keep_this_shard(meshes, opt, index);
  const std::string replay =
      impl == &production_mesh() ? "geomcheck replay " : std::string("geomcheck replay --subject ") + impl->name + " ";
  report::MeshReport rep =
      verify(*impl, meshes, index, family_run_options(opt, out_dir, static_cast<int>(meshes.size()), replay)).mesh_figures;
  rep.requested = static_cast<int>(meshes.size());
  if (opt.progress)
    std::fprintf(stderr, "[campaign] %-24s %7d meshes in %.1fs, %d failing\n", rep.name.c_str(), rep.meshes,
                 rep.seconds, rep.failures);
  return rep;
}

}  // namespace geomcheck
