// geomcheck — what a campaign writes: report.json, report.html (a precision
// table, then per query the verdict mix, error percentiles, histograms and
// the counterexamples drawn) and a page beside every saved counterexample.
// The campaign (tools/campaign.cpp) fills one QueryReport per query; this
// library turns them into files.
#pragma once

#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "geomcheck/properties/checks.hpp"
#include "geomcheck/properties/tolerances.hpp"

namespace geomcheck::report {

/// A sample of one error measure (multiples of the case scale); non-finite values are left out.
struct Series {
  std::vector<double> v;
  /// Adds x when finite.
  void add(double x) {
    if (std::isfinite(x)) v.push_back(x);
  }
  /// The p-quantile (0..1) of the sample; NaN when empty.
  double pct(double p) {
    if (v.empty()) return NAN;
    std::sort(v.begin(), v.end());
    return v[std::min(v.size() - 1, static_cast<std::size_t>(p * (v.size() - 1) + 0.5))];
  }
  /// Histogram of log10(error / scale), buckets -18..-4 plus "0".
  std::vector<int> hist() const {
    std::vector<int> h(16, 0);
    for (double x : v) {
      if (x <= 0) { ++h[0]; continue; }
      int b = static_cast<int>(std::floor(std::log10(x))) + 19;  // 1e-18 -> bucket 1
      h[std::clamp(b, 1, 15)]++;
    }
    return h;
  }
};


/// Everything reported about one query of a campaign.
struct QueryReport {
  std::string name, summary;
  std::string subject = "production";  ///< the subject under test (a variant's name)
  /// The command that replays a counterexample, its path appended; empty:
  /// geomcheck replay (with --subject for a built-in subject).
  std::string replay;
  Claims claims{};               ///< what the subject is held to
  bool own_claims = false;       ///< the subject's own claims (else production's)
  int requested = 0;             ///< cases asked for
  bool stopped_by_time = false;  ///< --seconds ran out before every requested case ran
  int cases = 0, valid = 0, prod_hits = 0, truth_hits = 0;
  int not_expressed = 0;  ///< cases not asked: the subject cannot state them (its expresses())
  std::map<std::string, int> verdicts;
  int disagree = 0, excused = 0, beyond = 0, check_failures = 0;
  double worst_margin = 0;
  Series depth, normal, point, t;
  int fcl_supported = 0, fcl_ok = 0, fcl_disagree = 0, fcl_beyond = 0;
  Series fcl_depth, fcl_normal, fcl_point;  // the yardsticks of production's depth, normal, point
  Series fcl_t_gap;  // production's t yardstick (the gap at FCL's t)
  Series fcl_t;  // |t_FCL - t_exact| (absolute, t in [0, 1])
  Series fcl_distance;  // |FCL distance - certified distance| on separated pairs FCL calls separated
  int fcl_distance_asked = 0, fcl_distance_beyond = 0;  // distance's verdict (< 0: meet) beyond the band
  std::vector<std::string> fcl_cases;  // FCL disagreements beyond the band, saved (capped as counterexamples are)
  /// FCL's disagreements beyond the band by signature, "kind @ generator
  /// mode" (kind: false-hit, missed-hit, distance-says-meet,
  /// distance-says-apart); at most kMaxSavedPerSignature of each saved.
  std::map<std::string, int> fcl_by_signature;
  int fcl_shrunk = 0;  ///< saved FCL disagreements made simpler before saving
  double prod_ns = NAN, oracle_us = NAN;
  /// Valid cases by the deepest stage of the engine's cascade their truth
  /// needed (oracle::to_string(Stage)).
  std::map<std::string, int> truth_stages;
  std::vector<std::string> counterexamples;
  std::vector<std::string> drawings;      // the subject's counterexamples, drawn (the first kInlineDrawings)
  std::vector<std::string> fcl_drawings;  // FCL's disagreements beyond the band, drawn (the first 3 saved of each kind)
  std::map<std::string, int> failures_by_property;
  /// Failing cases by signature, "property @ generator mode": the kinds of
  /// failure (at most kMaxSavedPerSignature of each saved).
  std::map<std::string, int> failures_by_signature;
  int shrunk = 0;  ///< saved counterexamples made simpler before saving (shrink.hpp)
  Tolerances tol{};
  // Queries whose depth is an upper bound, not the penetration depth
  // (collide_cylinder_cylinder, _obb, _triangle): depth / certified penetration depth over
  // the overlapping cases where the engine encloses it within 1%.
  bool depth_is_bound = false;
  Series depth_ratio;
  /// The other engines (peers/) on the first cases of this query, each held
  /// to every property under its own claims: one report per engine (its
  /// name in `subject`; prod_ns its median time per call).
  std::vector<QueryReport> peers;
  /// Production and FCL on the same first cases as the engines (one
  /// element when engines ran; its counts, errors and FCL fields only).
  std::vector<QueryReport> first;
  /// An engine's row: the bug-report configurations of this query
  /// (corpora/seeds/<query>/bugreport-*.case) put to it, and those it failed.
  int bugreports = 0;
  std::vector<std::string> bugreports_failed;
};


/// One evaluated case of query `id` counted into `rep`: a case run; where
/// valid, the hits, the verdict mix, a disagreement (excused inside the
/// band, else beyond it, with its margin) and every error measure. The
/// campaign and verify() both report through it.
void add_evaluation(QueryReport& rep, QueryId id, const Evaluation& e);

/// Everything reported about one point-set query (delaunay_2d) of a campaign.
struct PointSetReport {
  std::string name, summary;
  std::string subject = "production";  ///< the subject's name (production, or a user's under verify())
  int not_asked = 0;  ///< sets the subject was not asked: a non-finite coordinate, and it claims finite input only
  int requested = 0;             ///< point sets asked for
  bool stopped_by_time = false;  ///< --seconds ran out first
  int sets = 0;             ///< point sets run
  std::size_t points = 0;   ///< points in all of them
  std::map<std::string, int> modes;  ///< sets by generator mode
  std::map<std::string, int> kinds;  ///< sets by kind: triangulated, collinear, single point, empty, rejected
  int failures = 0;
  std::map<std::string, int> failures_by_property;
  /// Sets whose triangles differ from CGAL's where four or more points are
  /// cocircular (both choices legitimate, checked exactly).
  int cgal_choices_differ = 0;
  double production_us = 0, cgal_us = 0;  ///< time summed over the sets both triangulated (the subject's, and CGAL's)
  std::vector<std::string> counterexamples;  ///< failing sets, saved as point-set files
};

/// Everything reported about one mesh query (collide_cylinder_mesh) of a campaign.
struct MeshReport {
  std::string name, summary;
  std::string under_test = "production";  ///< the subject's name (production or a known-wrong variant)
  int requested = 0;             ///< meshes asked for
  bool stopped_by_time = false;  ///< --seconds ran out first
  int meshes = 0;                ///< meshes run
  std::size_t faces = 0;         ///< faces in all of them
  std::map<std::string, int> modes;     ///< meshes by generator mode
  std::map<std::string, int> verdicts;  ///< meshes by exact verdict (overlapping, touching, separated, undecided, invalid)
  int failures = 0;
  std::map<std::string, int> failures_by_property;
  /// Faces decided separated by their bounding boxes, and by the certified engine.
  std::size_t faces_by_box = 0, faces_by_engine = 0;
  /// Time of production's collide (the hierarchy) and of the brute force over every face, summed over the meshes.
  double production_us = 0, brute_force_us = 0;
  double seconds = 0;                        ///< wall time of the checks
  std::vector<std::string> counterexamples;  ///< failing meshes, saved as mesh files (a drawing beside each)
};

/// One campaign run: what was run, and how to run it again.
struct RunInfo {
  std::string version;     ///< the build's version (geomcheck --version)
  std::string started;     ///< UTC start time, ISO 8601
  std::string command;     ///< the command line as given
  unsigned long long seed = 0;
  std::string per_query;   ///< the case counts, in words
  std::string rerun;       ///< the command line that reproduces the run
  std::string under_test;  ///< "production" or a variant's name
};

/// Case files saved per kind (a property's failures, a kind of FCL
/// disagreement) and query; the rest are counted, not saved.
inline constexpr int kMaxSavedPerKind = 25;
/// Case files saved per failure signature (property and generator mode).
inline constexpr int kMaxSavedPerSignature = 5;
/// Saved failures of a query drawn inline in its report section (the first
/// ones; every saved one has its page beside its case file).
inline constexpr std::size_t kInlineDrawings = 12;

// ---- Serialising -------------------------------------------------------------
//
// The one serialiser of the harness's figures: every field of an evaluation,
// a query's report (with its claims, precision and bounds, its peers and
// first cases), a point-set or a mesh query's report and a run's facts, as
// one line of JSON (doubles exact; NaN and infinities as the strings "nan",
// "inf", "-inf"; no raw tab or newline), and back. It writes shard.json (read
// by `geomcheck merge`), the other engines' processes' reports and verify()'s
// child lines, so that nothing is lost between a child and its parent or a
// shard and the merge: from_json(to_json(x)) equals x field for field. A
// field added to one of these structures stops the build until it is
// written there (reports/src/serialize.cpp). from_json throws
// std::runtime_error naming what it read and the field missing or malformed.
std::string to_json(const Evaluation& e);
std::string to_json(const QueryReport& r);
std::string to_json(const PointSetReport& r);
std::string to_json(const MeshReport& r);
std::string to_json(const RunInfo& r);
void from_json(const std::string& text, Evaluation& e);
void from_json(const std::string& text, QueryReport& r);
void from_json(const std::string& text, PointSetReport& r);
void from_json(const std::string& text, MeshReport& r);
void from_json(const std::string& text, RunInfo& r);

/// b's counts, samples and saved cases added into a: two parts of one
/// query's run (two shards of a campaign, or a case of verify() and the
/// cases before it). Per-case times are weighted by the cases.
void merge_into(QueryReport& a, const QueryReport& b);
void merge_into(PointSetReport& a, const PointSetReport& b);
void merge_into(MeshReport& a, const MeshReport& b);

/// A subject's precision in words, for verify's summary and the report's
/// claims line: "production's (...)" for production's, else the type, its
/// unit roundoff, the ulps claimed, the range of scales, and whether exact
/// moves are bit-exact.
std::string precision_text(const Precision& p);
/// Checks a counterexample's shrink may spend before it is saved.
inline constexpr int kShrinkBudget = 60;

/// The version of report.json's layout (reports/report.schema.json).
inline constexpr int kReportSchemaVersion = 2;

/// Writes report.json.
void write_json(const std::filesystem::path& file, const RunInfo& run, std::vector<QueryReport>& reps,
                const std::vector<PointSetReport>& point_sets, const std::vector<MeshReport>& meshes = {});
/// Writes report.html.
void write_html(const std::filesystem::path& file, const RunInfo& run, std::vector<QueryReport>& reps,
                const std::vector<PointSetReport>& point_sets, const std::vector<MeshReport>& meshes = {});
/// Writes a JUnit XML file of the run (for CI dashboards): a test case per
/// query and family of properties (verdict, robust, oracle, consistency,
/// symmetry, metamorphic, monotone; a point-set query's valid and
/// agrees-with-cgal; a mesh query's families of mesh_checks.hpp), a failure
/// carrying the counts and the replay command of a saved counterexample.
void write_junit(const std::filesystem::path& file, const RunInfo& run, const std::vector<QueryReport>& reps,
                 const std::vector<PointSetReport>& point_sets, const std::vector<MeshReport>& meshes = {});
/// A counterexample's page: its drawing, the subject that fails it and the
/// command that replays it.
void write_counterexample_page(const std::filesystem::path& file, const std::string& name, const std::string& drawing,
                               const std::string& subject, const std::string& replay_command);
/// Now, UTC, ISO 8601 (a report's `started`).
std::string utc_now();
/// s with <, > and & escaped for HTML.
std::string html(const std::string& s);
/// x as a page shows it to a person: plain decimals from 0.001 up to a
/// million (`digits` significant digits, trailing zeros dropped: "1000",
/// "0.25"), else a mantissa times a power of ten with a superscript exponent
/// ("2.5×10⁻⁹"); "–" where x is NaN, "∞" where it is infinite. UTF-8, fit for
/// HTML text and SVG alike; report.json keeps its own numbers.
std::string readable(double x, int digits = 3);
/// `text` with every number it writes in e-notation ("depth=5.35e-06")
/// written as readable() writes it, with the digits it had ("5.35×10⁻⁶");
/// a number inside a word ("coaxial-1e-8-deep") is left alone.
std::string readable_numbers(const std::string& text);

}  // namespace geomcheck::report
