// geomcheck — the public door: verify anyone's implementation of a
// registered query, judged by its own claims and precision.
//
// A subject is ImplOf<Q> (properties/checks.hpp): a name and the query's
// entry points as callables: overlap(A, B) and collide(A, B) for a collide
// query, cast(A, B) or sweep(A, B) for the moving ones. Any callable with
// that signature serves: a function pointer, a lambda or an object with
// state, or an adapter that converts geomcheck's shapes into the caller's
// own vector and shape types (subject() below builds one). A subject is held
// to what production claims, or to its own Claims (checks.hpp): exact
// verdict or not, the depth's meaning (the true penetration depth, or an
// upper bound: a consistent contact; a claim stronger than production's is
// held too), point in both shapes or not, touching counted as contact or
// not, a margin, any input or valid scenes only, and its precision (the
// unit roundoff it computes with and the ulps of the scene it claims:
// Precision::single_precision() for float code), from which every bound
// derives (bounds_of; docs/semantics.md, "Yardsticks"); verify() prints the
// claims and the bounds before the figures and the report shows them.
//
//   int main(int argc, char** argv) {
//     auto mine = geomcheck::subject<geomcheck::QueryId::collide_cylinder_sphere>(
//         "my-collide", my_overlap, my_collide);
//     return geomcheck::verify(mine, argc, argv);
//   }
//
// rapidcheck(subject) is the same yardstick as a RapidCheck property (shrunk
// counterexamples, RC_PARAMS), for a user's own property suite.
//
// verify() draws `cases` targeted cases of the query from a fixed seed
// (printed; the same seed gives the same cases) and holds the subject to
// every property (check_every: robustness, agreement with the exact or
// certified truth outside the subject's verdict band and every error within
// the subject's bound, consistency, symmetry, the metamorphic moves,
// monotonicity), every failing property of a case counted, not only the
// first. Cases the subject does not state (its expresses(), its precision's
// range of scales, invalid input unless it claims any input) are not asked
// and are counted. A subject that throws fails the case ("subject-threw"), as
// does a non-finite or non-unit answer. The checks run in a child process:
// a subject that crashes the process ("subject-crashed") or gives no answer
// within a minute ("subject-hung") fails that case, and the run goes on
// after it. So a subject's own state changes (a call counter) stay in that
// child, and the subject object in the caller is left as it was; with
// `--in-process` (VerifyOptions::isolate false) the subject runs in the
// caller's process: its state changes stay, and a crash ends the run.
//
// Every failing case is counted under each property it fails; the first
// `max_saved` of each property (and at most report::kMaxSavedPerSignature of
// each property and generator mode) are saved under `out`, shrunk while they
// fail the same property (not with --no-shrink), as a case file (corpora/README.md's
// format, replayable) with a page beside it that draws the shapes, the
// subject's answer and the truth's witness. Each saved failure prints the
// command that replays it: the same program with `--replay FILE`. The run
// ends with `out`/report.json and report.html, the campaign's report of the
// subject: verdict mix, error percentiles and histograms against the
// bounds, the subject's median time per call, its claims, its failures.
//
// Command line (verify(subject, argc, argv)):
//   --cases N       cases to draw (default 2000)
//   --seconds S     start no case after S seconds (default: no limit)
//   --seed N        the seed (default 20261121)
//   --out DIR       where counterexamples and the report go (default geomcheck-out)
//   --max-saved N   case files saved per failing property (default 10)
//   --no-shrink     save failing cases as found
//   --replay FILE   replay saved case files instead (repeatable)
//   --quiet         no line per saved failure, no progress line (stderr)
//   --in-process    no child process (see above)
//   --no-report     no report.json / report.html
//   --junit FILE    also a JUnit XML file (a test case per property family)
// Exit status: 0 every case passed, 1 some case failed, 2 bad usage (--cases
// 0, a --replay file of another query). Replay commands are shell-quoted.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <iterator>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "geomcheck/casefile.hpp"
#include "geomcheck/properties/checks.hpp"
#include "geomcheck/properties/mesh_checks.hpp"
#include "geomcheck/properties/pointset_checks.hpp"
#include "geomcheck/properties/spec.hpp"
#include "geomcheck/reports/report.hpp"

namespace geomcheck {

/// A subject of query Q: its entry points as callables under a name
/// (ImplOf<Q>), with the query in its type so that verify() can be called
/// without naming it, and its own claims when it has any.
template <QueryId Q>
struct Subject : ImplOf<Q> {
  std::shared_ptr<const Claims> own_claims;  ///< what `claims` points to, when the subject has claims
};

/// What production claims for query Q: the start of a subject's own claims.
template <QueryId Q>
Claims production_claims() {
  return spec_of<Q>().claims;
}

/// The cases a subject of query Q can state at all: expresses(A, B) -> bool.
template <QueryId Q>
using Expresses = Callable<bool(const typename QueryTraits<Q>::ShapeA&, const typename QueryTraits<Q>::ShapeB&)>;

/// A subject of collide query Q from two callables, overlap(A, B) -> bool
/// and collide(A, B) -> Contact (copied: pass std::ref(object) to share
/// one), held to production's claims or to `claims` (judge() in checks.hpp
/// says how each claim is judged, docs/semantics.md how its precision gives
/// its bounds); `expresses`, when given, names the cases it can state (the
/// others are not asked, and counted).
template <QueryId Q, class Overlap, class Collide,
          std::enable_if_t<QueryTraits<Q>::kind == QueryKind::Collide, int> = 0>
Subject<Q> subject(const char* name, Overlap overlap, Collide collide, std::optional<Claims> claims = std::nullopt,
                   Expresses<Q> expresses = {}) {
  Subject<Q> s{{name, std::move(overlap), std::move(collide)}, nullptr};
  if (claims) s.claims = (s.own_claims = std::make_shared<const Claims>(*claims)).get();
  s.expresses = std::move(expresses);
  return s;
}

/// A subject of cast or sweep query Q from one callable (A, B) -> CastHit;
/// claims and expresses as for a collide query's.
template <QueryId Q, class Answer, std::enable_if_t<QueryTraits<Q>::kind != QueryKind::Collide, int> = 0>
Subject<Q> subject(const char* name, Answer answer, std::optional<Claims> claims = std::nullopt,
                   Expresses<Q> expresses = {}) {
  Subject<Q> s{{name, std::move(answer)}, nullptr};
  if (claims) s.claims = (s.own_claims = std::make_shared<const Claims>(*claims)).get();
  s.expresses = std::move(expresses);
  return s;
}

/// How verify() runs.
struct VerifyOptions {
  int cases = 2000;                          ///< targeted cases to draw
  std::uint64_t seed = 20261121;             ///< their seed
  std::filesystem::path out = "geomcheck-out";  ///< counterexamples go to out/<query>/
  int max_saved = 10;                        ///< case files saved per failing property
  bool quiet = false;                        ///< no line per saved failure
  std::string program = "verify";            ///< names the replay command printed
  unsigned case_seconds = 60;                ///< a case's checks taking longer: the subject hung
  /// The subject runs in a child process (a crash or a hang is its case's
  /// failure); false: in this process (its state changes stay, a crash
  /// ends the run).
  bool isolate = true;
  bool report = true;                        ///< write out/report.json and out/report.html
  std::string junit;                         ///< also write a JUnit XML file here (empty: none)
  bool summary = true;                       ///< print the claims and the summary (stdout)
  int shrink_budget = report::kShrinkBudget;  ///< checks a saved case's shrink may spend (0: saved as found)
  /// The command that replays a saved case, its path appended (default:
  /// program + " --replay ").
  std::string replay;
  double seconds = 0;                        ///< no case started after this many seconds (0: no limit); the rest are not run
  std::string found_by = "verify";           ///< a saved case file's found-by line starts with it (then the subject, seed and case)
  std::string command;                       ///< for the report: the command line (default: program)
  std::string started;                       ///< for the report: the UTC start time (default: now)
  /// In process (isolate false): the cases' checks on this many threads
  /// (the subject must be safe to call from several at once), then each
  /// case saved and counted in case order, so that the run's figures and
  /// files do not depend on it.
  int threads = 1;
  /// Heads a progress line on stderr (redrawn every 0.5 s on a terminal, a
  /// line every 10 s into a file); empty: none. verify(subject, argc, argv)
  /// shows one unless --quiet.
  std::string progress;
};

/// What verify() found.
struct VerifyResult {
  int cases = 0;                                 ///< cases checked
  int not_expressed = 0;                         ///< cases not asked: the subject's expresses() refused them
  int failures = 0;                              ///< cases that failed a property
  std::map<std::string, int> by_property;       ///< failing cases by the property they failed
  std::vector<std::filesystem::path> saved;      ///< case files saved (a .html drawing beside each)
  std::filesystem::path report;                  ///< report.html written (empty: none)
  report::QueryReport figures;                   ///< what the report shows: counts, error tails, time per call
  std::vector<std::string> failed_cases;         ///< the failing cases' tags (generator mode, or file name), in order
  report::PointSetReport point_set_figures;      ///< a point-set subject's report: sets by mode and kind, times against CGAL
  report::MeshReport mesh_figures;               ///< a mesh subject's report: meshes by mode and verdict, faces decided
};

/// The subject as a RapidCheck property: targeted cases of Q drawn by
/// RapidCheck (its seed and case count: RC_PARAMS), every property
/// (check_all) on each; a failing case is shrunk by RapidCheck and printed
/// with its failure and its case file. True when every case passed.
template <QueryId Q>
bool rapidcheck(const Subject<Q>& subject) {
  const auto gen = Spec<Q>::targeted();
  const ImplOf<Q>& impl = subject;
  return rc::check(std::string(impl.name) + " holds every property of " + info(Q).name, [&gen, &impl] {
    const auto tagged = *gen;
    if (const CheckResult f = check_all(tagged.first, impl))
      RC_FAIL(f->property + ": " + f->detail + "\n" +
              write_case(from_case<Q>(tagged.first, "rapidcheck " + tagged.second, "", f->property)));
  });
}

// For every registered query Q, as templates naming it (verify<Q>(subject,
// opt), ...), and as plain overloads on its subject type ImplOf<Q> (a
// Subject<Q> converts), so that they link the same from any compiler. Two
// queries over the same shapes share a subject type (penetration_cylinder_obb
// and collide_cylinder_obb): the plain overloads are the pair's collide
// query's, and the other is verified by naming it.
//   VerifyResult verify(subject, const VerifyOptions& opt)
//       holds `subject` to every property on opt.cases targeted cases (see
//       the header comment); prints a summary and returns the counts;
//   VerifyResult verify(subject, files, opt)
//       the same on the cases of these case files (each tagged by its file
//       name: failed_cases lists the files that failed);
//   int replay(subject, files)
//       replays case files of Q against `subject`: every property, the
//       truth and the subject's answer printed; the number of failing cases;
//   int verify(subject, argc, argv)
//       the whole program: options from the command line (see the header
//       comment), then verify() or replay(); the exit status.
template <QueryId Q>
VerifyResult verify(const ImplOf<Q>& subject, const VerifyOptions& opt);
template <QueryId Q>
VerifyResult verify(const ImplOf<Q>& subject, const std::vector<std::filesystem::path>& files, const VerifyOptions& opt);
template <QueryId Q>
int replay(const ImplOf<Q>& subject, const std::vector<std::filesystem::path>& files);
template <QueryId Q>
int verify(const ImplOf<Q>& subject, int argc, char** argv);

/// What a run of verify() on given cases may add beside the subject's
/// checks: a campaign's engine asked on every case, and its own count of
/// each one (tools/campaign.cpp).
template <QueryId Q>
struct RunHooks {
  using Case = typename QueryTraits<Q>::Case;
  /// The subject's answer to case k held to the truth (Evaluation), in
  /// place of evaluate(c, subject): it may score another engine beside it
  /// (Evaluation::peer). Called where the checks run, once per case: on the
  /// checking threads (opt.threads) in process; with opt.isolate in the
  /// child process, so that what it keeps aside stays there (a campaign runs
  /// in process). The checks judge what it returns.
  std::function<Evaluation(int k, const Case& c)> evaluate;
  /// Case k counted, in case order, after its failures were saved: its
  /// evaluation and the properties it failed (none: it passed).
  std::function<void(int k, const Evaluation& e, const std::vector<std::string>& failed)> counted;
};

/// verify() of a subject on these cases (each tagged by its generator
/// mode), case k saved and named by the number index[k] (its place in the
/// seed's sequence: a campaign's shard runs some of them); `hooks` as
/// above. opt.cases is not read (the cases are given).
template <QueryId Q>
VerifyResult verify(const ImplOf<Q>& subject, const std::vector<std::pair<typename QueryTraits<Q>::Case, std::string>>& cases,
                    const std::vector<int>& index, const VerifyOptions& opt, const RunHooks<Q>& hooks = {});

/// The subject type the plain overloads of query Q take: ImplOf<Q>, or, for
/// a query answered by penetration() (whose subject type is its pair's
/// collide query's), a wrapper no subject converts to implicitly
/// (NamedOnly<Q>{subject}; or name the query: verify<Q>(subject, ...)).
template <QueryId Q>
struct NamedOnly {
  const ImplOf<Q>& subject;
};
template <QueryId Q>
using PlainSubject = std::conditional_t<answers_penetration(Q), NamedOnly<Q>, ImplOf<Q>>;

#define GEOMCHECK_X(id, kind, A, B, summary)                                                          \
  VerifyResult verify(const PlainSubject<QueryId::id>& subject, const VerifyOptions& opt);            \
  VerifyResult verify(const PlainSubject<QueryId::id>& subject, const std::vector<std::filesystem::path>& files, \
                      const VerifyOptions& opt);                                                         \
  int replay(const PlainSubject<QueryId::id>& subject, const std::vector<std::filesystem::path>& files); \
  int verify(const PlainSubject<QueryId::id>& subject, int argc, char** argv);
GEOMCHECK_QUERY_LIST(GEOMCHECK_X)
#undef GEOMCHECK_X

// ---- The point-set family ---------------------------------------------------
//
// A user's 2D Delaunay triangulation through the same door:
//
//   auto mine = geomcheck::subject<geomcheck::PointSetQueryId::delaunay_2d>(
//       "my-delaunay", [](const std::vector<geomcheck::Vec2>& p) { return my_triangulate(p); });
//   return geomcheck::verify(mine, argc, argv);
//
// The callable answers the Delaunay triangles as triples of input indices
// (any integer type, any container of three), counter-clockwise; an index
// outside the input, or a triangle of other than three entries, fails
// `valid`. Equal points may be named by any of their indices (each is read
// as the smallest index of its coordinates). They are
// held to the exact validity checker and to CGAL's triangulation
// (pointset_checks.hpp: every distinct point a vertex, no triangle for
// collinear input, every triangle counter-clockwise
// and non-degenerate, every interior edge locally Delaunay, the boundary the
// convex hull with its collinear points, the same triangles as CGAL's but
// for cocircular choices). verify() draws point sets from the campaign's
// generators (uniform, grids, cocircular, collinear, duplicates, clusters,
// huge and tiny, perturbed by ulps), in a child process as for a pair; a
// failing set is shrunk (points removed while it fails the same property),
// saved as a point-set file (corpora/README.md) with a page drawing the
// subject's triangles, and replays with `--replay FILE`. The command line,
// the exit status and the report are those of a pair's verify() (the cap of
// saved files is per property only: a point set has no generator mode cap).

/// What a point-set subject claims beyond a valid triangulation.
struct PointSetClaims {
  /// Any input: a NaN or infinite coordinate is rejected by throwing
  /// DelaunayInputError naming the first such index. Without it (the
  /// default), such sets are not asked, and counted.
  bool any_input = false;
};

/// A subject of point-set query Q.
template <PointSetQueryId Q>
struct PointSetSubject : PointSetImpl {};

/// A subject of point-set query Q from triangulate(points) -> triangles
/// (a container of index triples: std::array<int, 3>, std::vector<int>,
/// ...), copied (std::ref to share one).
template <PointSetQueryId Q, class Triangulate>
PointSetSubject<Q> subject(const char* name, Triangulate triangulate, PointSetClaims claims = {}) {
  PointSetSubject<Q> s{{name, {}, {}, claims.any_input}};
  s.triangles = [f = std::move(triangulate)](const std::vector<Vec2>& points) {
    // An index outside [0, 2^32 - 1) (negative, or too large to be one)
    // becomes 2^32 - 1, and a triangle of other than three entries three of
    // them: the checks then say the triangle names no input point.
    constexpr std::uint32_t kBad = 0xFFFFFFFFu;
    const auto index = [](auto v) -> std::uint32_t {
      using V = std::decay_t<decltype(v)>;
      if constexpr (std::is_signed_v<V>) {
        if (v < 0) return kBad;
      }
      return static_cast<unsigned long long>(v) >= kBad ? kBad : static_cast<std::uint32_t>(v);
    };
    IndexTriangles out;
    for (const auto& t : f(points)) {
      if (std::size(t) != 3) {
        out.push_back({kBad, kBad, kBad});
        continue;
      }
      const auto at = std::begin(t);
      out.push_back({index(at[0]), index(at[1]), index(at[2])});
    }
    return out;
  };
  return s;
}

/// verify(), replay() and the whole program for a point-set subject, as for
/// a pair's (above); case files are point-set files.
VerifyResult verify(const PointSetImpl& subject, const VerifyOptions& opt);
/// verify() of a point-set subject on these sets (each tagged by its
/// generator mode), set k saved under the number index[k] (its place in the
/// seed's sequence): what the campaign runs for the point-set family.
VerifyResult verify(const PointSetImpl& subject, const std::vector<std::pair<std::vector<Vec2>, std::string>>& sets,
                    const std::vector<int>& index, const VerifyOptions& opt);
VerifyResult verify(const PointSetImpl& subject, const std::vector<std::filesystem::path>& files, const VerifyOptions& opt);
int replay(const PointSetImpl& subject, const std::vector<std::filesystem::path>& files);
int verify(const PointSetImpl& subject, int argc, char** argv);

// --- The mesh family --------------------------------------------------------
//
//   int main(int argc, char** argv) {
//     auto mine = geomcheck::subject<geomcheck::MeshQueryId::collide_cylinder_mesh>(
//         "my-mesh", [](const geomcheck::Cylinder& c, const geomcheck::TriangleMesh& m, std::uint32_t* face) {
//           return my_collide(c, m, face);  // a geomcheck::Contact, *face the reported face's index
//         });
//     return geomcheck::verify(mine, argc, argv);
//   }
//
// A mesh subject answers collide(cylinder, mesh) with the index of the face
// its contact is on (m.vertices(), m.faces() and m.triangle(f) give the
// mesh); overlap(cylinder, mesh) where it has one (else collide's hit is its
// verdict) and collide(mesh, cylinder) where it has that order (else the
// argument order is not checked). It is held to its MeshClaims
// (mesh_checks.hpp), never to production's bits: collide and overlap agree;
// a hit's contact is finite; no face that the certified engine finds
// overlapping beyond the subject's verdict band is missed; the reported
// face's contact meets the subject's claims as an answer of
// collide_cylinder_triangle for the cylinder and that face (verdict, depth,
// normal, point, within the bounds of its precision); and, where claimed,
// the reported face is the deepest: its certified penetration depth, times
// the claimed ratio, is not exceeded by another face's beyond twice the
// depth bound. verify() draws meshes from the campaign's generators (grids
// of heights, fans, soups, degenerate and sliver faces, faces on the caps
// and the side), in a child process as for a pair; a failing mesh is saved
// as a mesh file (corpora/README.md) with a page drawing the cylinder, the
// mesh and the subject's contact, and replays with `--replay FILE`. The
// command line, the exit status and the report are those of a pair's
// verify().

/// A subject of mesh query Q: its entry points and its own claims (held
/// by the subject, shared by its copies).
template <MeshQueryId Q>
struct MeshSubject : MeshImpl {
  std::shared_ptr<const MeshClaims> own;
};

/// A subject of mesh query Q from collide(cylinder, mesh, face*) ->
/// Contact; `claims` what it claims (collide_cylinder_triangle's production
/// claims for the face's contact, the deepest face, valid input only, by
/// default); the callables copied (std::ref to share one).
template <MeshQueryId Q, class Collide>
MeshSubject<Q> subject(const char* name, Collide collide, MeshClaims claims = {}) {
  MeshSubject<Q> s;
  s.name = name;
  s.collide = std::move(collide);
  s.own = std::make_shared<const MeshClaims>(claims);
  s.claims = s.own.get();
  return s;
}
/// The same with overlap(cylinder, mesh) -> bool and, optionally,
/// collide(mesh, cylinder, face*) -> Contact (the flipped order: the normal
/// from the mesh towards the cylinder).
template <MeshQueryId Q, class Overlap, class Collide, class Flipped = std::nullptr_t>
MeshSubject<Q> subject(const char* name, Overlap overlap, Collide collide, Flipped flipped = nullptr,
                       MeshClaims claims = {}) {
  MeshSubject<Q> s = subject<Q>(name, std::move(collide), claims);
  s.overlap = std::move(overlap);
  if constexpr (!std::is_same_v<Flipped, std::nullptr_t>) s.collide_flipped = std::move(flipped);
  return s;
}

/// verify(), replay() and the whole program for a mesh subject, as for a
/// pair's (above); case files are mesh files. A subject without claims
/// (production, its known-wrong variants) is held to production's
/// yardsticks.
VerifyResult verify(const MeshImpl& subject, const VerifyOptions& opt);
/// verify() of a mesh subject on these meshes (each tagged by its
/// generator mode), mesh k saved under the number index[k] (its place in
/// the seed's sequence): what the campaign runs for the mesh family.
VerifyResult verify(const MeshImpl& subject, const std::vector<std::pair<MeshCase, std::string>>& meshes,
                    const std::vector<int>& index, const VerifyOptions& opt);
VerifyResult verify(const MeshImpl& subject, const std::vector<std::filesystem::path>& files, const VerifyOptions& opt);
int replay(const MeshImpl& subject, const std::vector<std::filesystem::path>& files);
int verify(const MeshImpl& subject, int argc, char** argv);

}  // namespace geomcheck
