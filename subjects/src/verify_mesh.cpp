// geomcheck — verify() and replay() for a mesh subject (verify.hpp, "The mesh
// family"): the door of the families that are not pairs (family_door.hpp),
// the checks of mesh_checks.hpp, mesh files for the failures.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <system_error>

#include "family_door.hpp"
#include "geomcheck/collide_cylinder_mesh.hpp"
#include "geomcheck/mesh_file.hpp"
#include "geomcheck/properties/generators.hpp"
#include "geomcheck/properties/tolerances.hpp"
#include "geomcheck/reports/draw.hpp"
#include "geomcheck/verify.hpp"

namespace geomcheck {

namespace {

using Clock = std::chrono::steady_clock;
constexpr const char* kMeshQuery = "collide_cylinder_mesh";

double micros(Clock::time_point a, Clock::time_point b) { return std::chrono::duration<double, std::micro>(b - a).count(); }

/// The mesh without the faces [from, from + count).
MeshCase without(const MeshCase& c, std::size_t from, std::size_t count) {
  MeshCase d = c;
  d.faces.assign(c.faces.begin(), c.faces.begin() + from);
  d.faces.insert(d.faces.end(), c.faces.begin() + std::min(c.faces.size(), from + count), c.faces.end());
  return d;
}

/// The mesh family's part of the door (family_door.hpp).
struct MeshFamily {
  using Case = MeshCase;
  using Report = report::MeshReport;
  const MeshImpl& subject;
  const VerifyOptions& opt;

  static std::vector<std::pair<Case, std::string>> draw(std::uint64_t seed, int n) { return gen::draw_meshes(seed, n); }
  static constexpr detail::FamilyWords words{kMeshQuery, "meshes", "mesh", "mesh files"};
  const char* subject_name() const { return subject.name; }
  std::string in_all(const Report& r) const { return " (" + std::to_string(r.faces) + " faces)"; }
  bool asked(const MeshCase& c) const {
    if (!subject.claims || subject.claims->any_input) return true;
    return is_valid(c.cyl) && TriangleMesh(c.vertices, c.faces).valid();
  }
  const char* not_asked_why() const {
    return "an invalid cylinder, a non-finite vertex or an index out of range, and the subject claims valid input only";
  }
  void print_claims() const {
    if (!subject.claims) {
      std::printf("claims of %s: production's (the brute force and its triangle query's answers, bit for bit; the "
                  "certified engine face by face)\n",
                  subject.name);
      return;
    }
    const MeshClaims& c = *subject.claims;
    const Tolerances tol = bounds_of(QueryId::collide_cylinder_triangle, &c.face);
    std::printf("claims of %s: no robust hit missed; the reported face's contact as collide_cylinder_triangle's "
                "answer: verdict %s, depth: %s, point %s, touching %s contact; precision: %s%s; %s\n"
                "bounds of the face's contact (* scale): verdict band %.3g, depth %.3g, normal %.3g, point %.3g\n"
                "  not checked for this subject: %s\n",
                subject.name, c.face.exact_verdict ? "exact" : "not exact", to_string(c.face.depth),
                c.face.point_in_both ? "claimed" : "not claimed", c.face.touching_is_contact ? "is" : "is not",
                report::precision_text(c.face.precision).c_str(),
                c.deepest ? "; the deepest face (certified penetration depths)" : "",
                c.any_input ? "any input (invalid input: no hit)" : "valid input only (invalid meshes are not asked)",
                tol.verdict, tol.depth, tol.normal, tol.point,
                subject.collide_flipped ? "production's bits (a subject of its own is held to its claims)"
                                        : "production's bits; the argument order (no collide(mesh, cylinder) given)");
  }
  void start_report(Report& r) const {
    r.name = kMeshQuery;
    r.summary = info(MeshQueryId::collide_cylinder_mesh).summary;
    r.under_test = subject.name;
  }
  void keep(VerifyResult& res, const Report& r) const { res.mesh_figures = r; }
  void print_figures(const Report& r) const {
    std::printf("  faces separated by their boxes %zu, decided by the certified engine %zu\n", r.faces_by_box,
                r.faces_by_engine);
    if (r.brute_force_us > 0)
      std::printf("  time: %s %.3g s, the brute force over every face %.3g s on the same meshes\n", subject.name,
                  r.production_us * 1e-6, r.brute_force_us * 1e-6);
  }

  /// A one-mesh report: its mode, faces and verdict (`truth` when known).
  static Report one_mesh(const MeshCase& c, const std::string& tag, const MeshTruth& truth) {
    Report one;
    one.meshes = 1;
    one.faces = c.faces.size();
    one.modes[tag] = 1;
    one.verdicts[truth.valid ? oracle::to_string(truth.verdict) : "invalid"] = 1;
    one.faces_by_box = truth.faces_by_box;
    one.faces_by_engine = truth.faces_by_engine;
    return one;
  }

  detail::Checked check(const MeshCase& c, const std::string& tag) const {
    const TriangleMesh mesh(c.vertices, c.faces);
    const auto t0 = Clock::now();
    try {
      std::uint32_t face = 0;
      (void)subject.collide(c.cyl, mesh, &face);
    } catch (...) {
    }
    const auto t1 = Clock::now();
    (void)detail::collide_brute_force(c.cyl, mesh);
    const auto t2 = Clock::now();
    detail::Checked out;
    MeshTruth truth;
    try {
      out.failure = check_mesh_all(c.cyl, mesh, subject, &truth);
    } catch (const std::exception& ex) {
      out.failure = Failure{"subject-threw", std::string("the subject threw: ") + ex.what()};
      truth = mesh_truth(c.cyl, mesh);
    } catch (...) {
      out.failure = Failure{"subject-threw", "the subject threw something that is not a std::exception"};
      truth = mesh_truth(c.cyl, mesh);
    }
    Report one = one_mesh(c, tag, truth);
    one.production_us = micros(t0, t1);
    one.brute_force_us = micros(t1, t2);
    one.seconds = std::chrono::duration<double>(Clock::now() - t0).count();
    out.figures = report::to_json(one);
    out.ns = micros(t0, t1) * 1e3;
    return out;
  }
  std::string lost_figures(const MeshCase& c, const std::string& tag) const {
    return report::to_json(one_mesh(c, tag, mesh_truth(c.cyl, TriangleMesh(c.vertices, c.faces))));
  }

  /// Whether the subject fails `property` on c.
  bool fails(const MeshCase& c, const std::string& property) const {
    try {
      const CheckResult f = check_mesh_all(c.cyl, TriangleMesh(c.vertices, c.faces), subject);
      return f && f->property == property;
    } catch (...) {
      return property == "subject-threw";
    }
  }

  /// Shrinks a failing mesh while it fails `property`: drops runs of faces,
  /// halving the run, within `budget` checks. The number of faces dropped.
  std::size_t shrink_mesh(MeshCase& c, const std::string& property, int budget) const {
    const std::size_t before = c.faces.size();
    for (std::size_t run = std::max<std::size_t>(1, c.faces.size() / 2); budget > 0 && c.faces.size() > 1;) {
      bool dropped = false;
      for (std::size_t from = 0; from < c.faces.size() && budget > 0 && c.faces.size() > 1;) {
        const MeshCase d = without(c, from, run);
        --budget;
        if (!d.faces.empty() && d.faces.size() < c.faces.size() && fails(d, property)) {
          c = d;
          dropped = true;
        } else {
          from += run;
        }
      }
      if (!dropped) {
        if (run == 1) break;
        run = std::max<std::size_t>(1, run / 2);
      }
    }
    return before - c.faces.size();
  }

  /// Saves a failing mesh (shrunk unless the subject is not to be asked
  /// again) as a mesh file, with its page.
  std::string save(const MeshCase& found, const std::string& tag, int number, const Failure& f, bool ask_subject,
                   int& shrunk) const {
    MeshCase c = found;
    Failure shown = f;
    if (ask_subject && opt.shrink_budget > 0) {
      const std::size_t dropped = shrink_mesh(c, f.property, opt.shrink_budget);
      if (dropped > 0) {
        ++shrunk;
        try {
          if (const CheckResult g = check_mesh_all(c.cyl, TriangleMesh(c.vertices, c.faces), subject)) shown = *g;
        } catch (...) {
        }
        shown.detail += " (shrunk: " + std::to_string(dropped) + " faces dropped)";
      }
    }
    std::string name;
    const std::filesystem::path path = detail::failure_path(opt, kMeshQuery, number, f.property, name);
    const TriangleMesh mesh(c.vertices, c.faces);
    const MeshTruth truth = mesh_truth(c.cyl, mesh);
    MeshFile file;
    file.query = kMeshQuery;
    file.cylinder = c.cyl, file.vertices = c.vertices, file.faces = c.faces;
    file.found_by = opt.found_by + " " + subject.name + " seed=" + std::to_string(opt.seed) +
                    " case=" + std::to_string(number) + " mode=" + tag;
    if (truth.valid) file.oracle_verdict = oracle::to_string(truth.verdict);
    file.note = shown.property + ": " + shown.detail;
    std::string err;
    if (!save_mesh_file(path, file, err)) {
      std::fprintf(stderr, "verify: cannot save %s: %s\n", path.string().c_str(), err.c_str());
      return "";
    }
    std::uint32_t face = 0xffffffffu;
    Contact k;  // a subject that crashed is not asked again
    if (ask_subject) {
      try {
        k = subject.collide(c.cyl, mesh, &face);
      } catch (...) {
      }
    }
    report::write_counterexample_page(
        std::filesystem::path(path).replace_extension(".html"), name,
        draw::mesh_views(c.cyl, mesh, k, face, ask_subject ? subject.name : std::string(subject.name) + " (not asked again)",
                         report::html(name + ": " + shown.property + ": " + shown.detail)),
        subject.name, detail::replay_command(opt, path));
    detail::announce_failure(opt, subject.name, "mesh", f.property, number, tag, shown.detail, path);
    return path.string();
  }

  std::optional<std::string> load(const std::filesystem::path& path, MeshCase& c) const {
    const std::string q = declared_query(path);
    if (!q.empty() && q != kMeshQuery) return "a case of " + q + ", not of " + kMeshQuery;
    const MeshParseResult pr = load_mesh_file(path);
    if (!pr.ok()) return pr.error;
    c = MeshCase{pr.value.cylinder, pr.value.vertices, pr.value.faces, path.stem().string()};
    return std::nullopt;
  }

  bool replay_one(const std::filesystem::path& path, const MeshCase& c) const {
    const TriangleMesh mesh(c.vertices, c.faces);
    if (!asked(c)) {
      std::printf("NOT ASKED %s\n  invalid input: %s claims valid input only\n", path.string().c_str(), subject.name);
      return true;
    }
    MeshTruth truth;
    CheckResult failure;
    std::uint32_t face = 0xffffffffu;
    Contact k;
    try {
      failure = check_mesh_all(c.cyl, mesh, subject, &truth);
      k = subject.collide(c.cyl, mesh, &face);
    } catch (const std::exception& ex) {
      failure = Failure{"subject-threw", std::string("the subject threw: ") + ex.what()};
    }
    std::printf("%s %s\n  mesh: %zu vertices, %zu faces\n", failure ? "FAIL" : "PASS", path.string().c_str(),
                c.vertices.size(), c.faces.size());
    if (k.hit)
      std::printf("  %s: hit, face %u, depth %.17g\n", subject.name, face, k.depth);
    else
      std::printf("  %s: no hit\n", subject.name);
    std::printf("  truth: %s\n  checks: %s\n", truth.valid ? oracle::to_string(truth.verdict) : "invalid",
                failure ? (failure->property + ": " + failure->detail).c_str() : "all pass");
    return !failure;
  }
};

}  // namespace

GEOMCHECK_FAMILY_DOOR(MeshImpl, MeshFamily)

}  // namespace geomcheck
