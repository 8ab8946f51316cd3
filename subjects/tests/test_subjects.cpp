// geomcheck — the public door (verify.hpp) tried as a user would: subjects
// written with and without bugs, with state, with claims, and subjects that
// throw, answer NaN, crash or hang. Fixed seed (VerifyOptions' default).
#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <sstream>
#include <stdexcept>
#include <thread>
#include <vector>

#include "geomcheck/casefile.hpp"
#include "geomcheck/collide_cylinder_cylinder.hpp"
#include "geomcheck/collide_cylinder_sphere.hpp"
#include "geomcheck/oracles/solids.hpp"
#include "geomcheck/properties/teeth.hpp"
#include "geomcheck/reports/report.hpp"
#include "geomcheck/verify.hpp"

namespace geomcheck {
namespace {

constexpr QueryId kSphere = QueryId::collide_cylinder_sphere;

/// Options writing under a fresh folder of the test's own.
VerifyOptions options(const std::string& name, int cases) {
  VerifyOptions opt;
  opt.cases = cases;
  opt.out = std::filesystem::path(::testing::TempDir()) / ("geomcheck-subjects-" + name);
  std::filesystem::remove_all(opt.out);
  opt.quiet = true;
  return opt;
}

std::string read_text(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

int count(const VerifyResult& r, const std::string& property) {
  const auto it = r.by_property.find(property);
  return it == r.by_property.end() ? 0 : it->second;
}

// Production's collide behind a lambda with state (a call counter) and an
// adapter: held to the same yardsticks, it passes them.
TEST(Subjects, ProductionBehindAStatefulAdapterPasses) {
  int calls = 0;
  auto collide_fn = [&calls](const Cylinder& c, const Sphere& s) {
    ++calls;
    return collide(c, s);
  };
  const auto mine = subject<kSphere>("adapter", [](const Cylinder& c, const Sphere& s) { return overlap(c, s); },
                                     collide_fn);
  ASSERT_EQ(mine.collide(Cylinder{{0, 0, 0}, {0, 0, 1}, 1}, Sphere{{0, 0, 0.5}, 0.25}).hit, true);
  EXPECT_EQ(calls, 1);  // the subject holds the lambda itself: its state is the caller's
  const VerifyResult r = verify(mine, options("adapter", 400));
  EXPECT_EQ(r.cases, 400);
  EXPECT_EQ(r.failures, 0) << (r.by_property.empty() ? "" : r.by_property.begin()->first);
  EXPECT_TRUE(r.saved.empty());
  const int before = calls;
  EXPECT_EQ(calls, before);  // checked in a child process: the caller's counter did not move

  // In process: the subject's own state changes are the caller's.
  VerifyOptions in_process = options("adapter-in-process", 50);
  in_process.isolate = false;
  EXPECT_EQ(verify(mine, in_process).failures, 0);
  EXPECT_GE(calls, before + 50);
}

// A subject that cannot state some cases (an engine's model refuses a
// shape) says so with `expresses`: those cases are not asked, not failed,
// and counted apart. Here a subject throws on balls under a fifth of the
// cylinder's radius (a limit the checks' moves keep: they move, turn and
// scale the whole scene) and declares them out of its reach: the run
// passes, every refused case counted.
TEST(Subjects, CasesASubjectCannotStateAreNotAsked) {
  auto small = [](const Cylinder& c, const Sphere& s) { return !(s.r >= 0.2 * c.r); };
  auto collide_fn = [small](const Cylinder& c, const Sphere& s) {
    if (small(c, s)) throw std::runtime_error("this engine has no ball under a fifth of the cylinder's radius");
    return collide(c, s);
  };
  auto mine = subject<kSphere>("no-small-balls", [collide_fn](const Cylinder& c, const Sphere& s) {
    return collide_fn(c, s).hit;
  }, collide_fn);
  const VerifyResult asked_all = verify(mine, options("no-small-balls-all", 300));
  ASSERT_GT(count(asked_all, "subject-threw"), 0) << "no small ball among the cases: the test tests nothing";
  mine.expresses = [small](const Cylinder& c, const Sphere& s) { return !small(c, s); };
  const VerifyResult r = verify(mine, options("no-small-balls", 300));
  EXPECT_EQ(r.failures, 0) << (r.by_property.empty() ? "" : r.by_property.begin()->first);
  EXPECT_GT(r.not_expressed, 0);
  EXPECT_EQ(r.cases + r.not_expressed, 300);
  EXPECT_EQ(r.figures.not_expressed, r.not_expressed);
}

/// Production's collide on the scene rounded to float, its depth and normal
/// (and with `point`, its point) rounded to float: float code.
Contact float_collide(const Cylinder& c, const Sphere& s, bool point) {
  auto f = [](Vec3 v) { return Vec3{float(v.x), float(v.y), float(v.z)}; };
  Contact k = collide(Cylinder{f(c.p), f(c.q), float(c.r)}, Sphere{f(s.c), float(s.r)});
  k.depth = float(k.depth);
  k.normal = f(k.normal);
  if (point) k.point = f(k.point);
  return k;
}

// Single precision: caught, each saved case a valid case file of the query
// whose replay fails again.
TEST(Subjects, SinglePrecisionIsCaughtAndReplays) {
  auto collide_fn = [](const Cylinder& c, const Sphere& s) { return float_collide(c, s, false); };
  const auto mine = subject<kSphere>("float-inputs", [collide_fn](const Cylinder& c, const Sphere& s) {
    return collide_fn(c, s).hit;
  }, collide_fn);
  const VerifyResult r = verify(mine, options("float", 400));
  EXPECT_GT(r.failures, 0);
  ASSERT_FALSE(r.saved.empty());
  // Shrunk in the child process that found them, counted by the parent.
  EXPECT_GT(r.figures.shrunk, 0);
  EXPECT_LE(r.figures.shrunk, static_cast<int>(r.saved.size()));
  for (const auto& path : r.saved) {
    const ParseResult p = load_case(path);
    ASSERT_TRUE(p.ok()) << path << ": " << p.error;
    EXPECT_EQ(p.value.query, kSphere);
    EXPECT_TRUE(std::filesystem::exists(std::filesystem::path(path).replace_extension(".html"))) << path;
  }
  EXPECT_EQ(replay(mine, r.saved), static_cast<int>(r.saved.size()));
  EXPECT_EQ(replay(production_of<kSphere>(), r.saved), 0);
  // The same files through verify(): each fails again, named by its file.
  VerifyOptions again = options("float-files", 1);
  again.report = false;
  const VerifyResult f = verify(mine, r.saved, again);
  EXPECT_EQ(f.cases, static_cast<int>(r.saved.size()));
  EXPECT_EQ(f.failed_cases.size(), r.saved.size());
  EXPECT_EQ(verify(production_of<kSphere>(), r.saved, again).failures, 0);

  // The report of the run: the subject, its claims and the same counts.
  ASSERT_FALSE(r.report.empty());
  const std::string json = read_text(r.report.parent_path() / "report.json");
  EXPECT_NE(json.find("\"subject\": \"float-inputs\""), std::string::npos);
  EXPECT_NE(json.find("\"verdict\": \"failed\""), std::string::npos);
  EXPECT_NE(json.find("\"check_failures\": " + std::to_string(r.failures) + ","), std::string::npos);
  const std::string page = read_text(r.report);
  EXPECT_NE(page.find(" --replay "), std::string::npos);  // the program's own replay command
}

// The same float code declaring its precision is judged by float's bounds:
// no false alarm; its report's bounds are the subject's.
TEST(Subjects, FloatCodeDeclaringItsPrecisionPasses) {
  auto collide_fn = [](const Cylinder& c, const Sphere& s) { return float_collide(c, s, true); };
  Claims single = production_claims<kSphere>();
  single.precision = Precision::single_precision();
  single.any_input = false;
  const auto mine = subject<kSphere>("float-declared", [collide_fn](const Cylinder& c, const Sphere& s) {
    return collide_fn(c, s).hit;
  }, collide_fn, single);
  const VerifyResult r = verify(mine, options("float-declared", 2000));
  EXPECT_EQ(r.failures, 0) << (r.by_property.empty() ? "" : r.by_property.begin()->first);
  EXPECT_DOUBLE_EQ(r.figures.tol.verdict, bounds_of(kSphere, &single).verdict);
  EXPECT_GT(r.figures.tol.verdict, 1e3 * tolerances(kSphere).verdict);
}

// Every failing property of a case is counted: a normal twice too long (the
// unit-length properties) does not hide the capsule's round ends (the
// verdict), and each property has its own saved case.
TEST(Subjects, EveryFailingPropertyOfACaseIsReported) {
  auto collide_fn = [](const Cylinder& c, const Sphere& s) {
    Contact k = teeth::kCapsuleForCylinder.collide(c, s);  // round ends
    k.normal = 2.0 * k.normal;
    return k;
  };
  const auto mine = subject<kSphere>("long-normal-capsule", [collide_fn](const Cylinder& c, const Sphere& s) {
    return collide_fn(c, s).hit;
  }, collide_fn);
  const VerifyResult r = verify(mine, options("two-flaws", 600));
  EXPECT_GT(count(r, "robust-unit-normal"), 0);
  EXPECT_GT(count(r, "oracle-verdict"), 0) << "the verdict's failures hidden behind the normal's";
  int by_property = 0;
  for (const auto& kv : r.by_property) by_property += kv.second;
  EXPECT_GT(by_property, r.failures) << "a case failing several properties is counted under each";
  bool saved_verdict = false;
  for (const auto& p : r.saved) saved_verdict |= p.filename().string().find("oracle-verdict") != std::string::npos;
  EXPECT_TRUE(saved_verdict);
  const std::string json = read_text(r.report.parent_path() / "report.json");
  EXPECT_NE(json.find("\"oracle-verdict\""), std::string::npos);
  EXPECT_NE(json.find("\"robust-unit-normal\""), std::string::npos);
}

// In process on two threads, a wrong subject gives what it gives on one:
// the same failing cases, counts, saved files (same names, same bytes) and
// figures, as the checks run at once but the cases are saved and counted in
// case order. Every failure is shrunk, secondary properties included. The
// hooks see every case once: evaluate() on the checking threads, counted()
// in case order, under the numbers given.
TEST(Subjects, ThreadsChangeNothingButTheTime) {
  const auto mine = subject<kSphere>(
      "capsule-ends", [](const Cylinder& c, const Sphere& s) { return teeth::kCapsuleForCylinder.collide(c, s).hit; },
      [](const Cylinder& c, const Sphere& s) { return teeth::kCapsuleForCylinder.collide(c, s); });
  const auto cases = gen::draw<kSphere>(VerifyOptions{}.seed, 400);
  std::vector<int> index(cases.size());
  for (std::size_t k = 0; k < index.size(); ++k) index[k] = static_cast<int>(1000 + 2 * k);  // a shard's numbers
  auto run = [&](const std::string& name, int threads, std::vector<int>* evaluated, std::vector<int>* counted) {
    VerifyOptions opt = options(name, 0);
    opt.isolate = false;
    opt.threads = threads;
    RunHooks<kSphere> hooks;
    std::mutex mu;
    hooks.evaluate = [&](int k, const QueryTraits<kSphere>::Case& c) {
      std::lock_guard<std::mutex> lock(mu);
      evaluated->push_back(k);
      return evaluate(c, static_cast<const ImplOf<kSphere>&>(mine));
    };
    hooks.counted = [&](int k, const Evaluation&, const std::vector<std::string>&) { counted->push_back(k); };
    return verify<kSphere>(mine, cases, index, opt, hooks);
  };
  std::vector<int> e1, c1, e2, c2;
  const VerifyResult one = run("threads-1", 1, &e1, &c1), two = run("threads-2", 2, &e2, &c2);
  ASSERT_GT(one.failures, 0);
  EXPECT_EQ(one.cases, 400);
  EXPECT_EQ(two.failed_cases, one.failed_cases);
  EXPECT_EQ(one.figures.shrunk, static_cast<int>(one.saved.size())) << "every saved failure shrunk";
  EXPECT_FALSE(two.figures.drawings.empty());
  // Every figure of the report the same, but the times and the folders.
  auto figures = [](report::QueryReport r) {
    r.prod_ns = r.oracle_us = NAN;
    r.counterexamples.clear();
    return report::to_json(r);
  };
  EXPECT_EQ(figures(two.figures), figures(one.figures));
  ASSERT_EQ(two.saved.size(), one.saved.size());
  for (std::size_t k = 0; k < one.saved.size(); ++k) {
    EXPECT_EQ(two.saved[k].filename(), one.saved[k].filename());
    std::string a = read_text(one.saved[k]), b = read_text(two.saved[k]);
    EXPECT_EQ(b, a);
    const int number = std::atoi(one.saved[k].filename().string().c_str());
    EXPECT_TRUE(number >= 1000 && number % 2 == 0) << "saved under the number given: " << one.saved[k];
  }
  std::sort(e2.begin(), e2.end());
  EXPECT_EQ(e1, index);
  EXPECT_EQ(e2, index);
  EXPECT_EQ(c1, index);
  EXPECT_EQ(c2, index) << "counted in case order";
}

// A relation's failure is drawn with the case it compared: a subject that
// answers for one cap order only fails symmetry-caps-swapped, and that
// page shows the case with its caps swapped beside the original.
TEST(Subjects, RelationFailurePageDrawsBothCases) {
  const auto& prod = production_of<kSphere>();
  auto one_order = [&prod](const Cylinder& c, const Sphere& s) {
    Contact k = prod.collide(c, s);
    if (c.p.x > c.q.x) k = Contact{};  // "p first": the other order never touches
    return k;
  };
  const auto mine = subject<kSphere>("one-cap-order", [one_order](const Cylinder& c, const Sphere& s) {
    return one_order(c, s).hit;
  }, one_order);
  VerifyOptions opt = options("relation-page", 300);
  opt.shrink_budget = 0;
  const VerifyResult r = verify(mine, opt);
  ASSERT_GT(count(r, "symmetry-caps-swapped"), 0);
  int pages = 0;
  for (const auto& p : r.saved) {
    if (p.filename().string().find("symmetry-caps-swapped") == std::string::npos) continue;
    const std::string page = read_text(std::filesystem::path(p).replace_extension(".html"));
    const std::size_t heading = page.find("compared it with");
    ASSERT_NE(heading, std::string::npos) << p;
    // The original case's views before the heading, the transformed case's
    // three views after it.
    auto svgs = [&page](std::size_t from, std::size_t to) {
      std::size_t n = 0;
      for (std::size_t at = from; (at = page.find("<svg", at)) < to; ++at) ++n;
      return n;
    };
    EXPECT_GE(svgs(0, heading), 3u) << p;
    EXPECT_GE(svgs(heading, std::string::npos), 3u) << p;
    ++pages;
  }
  EXPECT_GT(pages, 0);
}

// The child's line loses no field of an evaluation: every field set to a
// value of its own (NaN, infinities, a negative zero, a subnormal, texts
// with tabs, newlines and quotes) comes back bit for bit.
TEST(Subjects, ChildLineKeepsEveryField) {
  Evaluation e;
  double next = 1;
  auto num = [&next] { return next += 0.125; };
  e.valid = true, e.prod_hit = true, e.truth_hit = false, e.verdict = oracle::Verdict::Touching;
  e.disagree = true, e.excused = false, e.near_boundary = true;
  e.scale = std::ldexp(1.0, -1070);  // subnormal
  e.signed_distance = -0.0, e.margin = INFINITY, e.depth_err = -INFINITY, e.normal_err = NAN;
  e.point_err = num(), e.t_err = 0.1, e.t_true = num(), e.unit_err = num(), e.distance = num();
  e.peer.depth_err = num(), e.peer.normal_err = num(), e.peer.point_err = num(), e.peer.unit_err = num();
  e.peer.t_err = num(), e.depth_ratio = num(), e.depth_ratio_lo = num(), e.depth_short = num(), e.depth_over = num();
  e.tol = Tolerances{num(), num(), num(), num(), num(), num(), num(), num()};
  e.extra_failure = "tab\there";
  e.truth_text = "line\nbreak \"quoted\"";
  e.prod_text = "overlap=yes \x1f sep";
  const std::string line = report::to_json(e);
  EXPECT_EQ(line.find('\n'), std::string::npos);
  EXPECT_EQ(line.find('\t'), std::string::npos);
  Evaluation b;
  report::from_json(line, b);
  auto same = [](double x, double y) { return std::memcmp(&x, &y, sizeof x) == 0 || (std::isnan(x) && std::isnan(y)); };
  EXPECT_EQ(b.valid, e.valid);
  EXPECT_EQ(b.prod_hit, e.prod_hit);
  EXPECT_EQ(b.truth_hit, e.truth_hit);
  EXPECT_EQ(b.verdict, e.verdict);
  EXPECT_EQ(b.disagree, e.disagree);
  EXPECT_EQ(b.excused, e.excused);
  EXPECT_EQ(b.near_boundary, e.near_boundary);
  EXPECT_EQ(b.extra_failure, e.extra_failure);
  EXPECT_EQ(b.truth_text, e.truth_text);
  EXPECT_EQ(b.prod_text, e.prod_text);
  const std::pair<const char*, std::pair<double, double>> doubles[] = {
      {"scale", {b.scale, e.scale}}, {"signed_distance", {b.signed_distance, e.signed_distance}},
      {"margin", {b.margin, e.margin}}, {"depth_err", {b.depth_err, e.depth_err}},
      {"normal_err", {b.normal_err, e.normal_err}}, {"point_err", {b.point_err, e.point_err}},
      {"t_err", {b.t_err, e.t_err}}, {"t_true", {b.t_true, e.t_true}}, {"unit_err", {b.unit_err, e.unit_err}},
      {"distance", {b.distance, e.distance}}, {"peer.depth_err", {b.peer.depth_err, e.peer.depth_err}},
      {"peer.normal_err", {b.peer.normal_err, e.peer.normal_err}},
      {"peer.point_err", {b.peer.point_err, e.peer.point_err}}, {"peer.unit_err", {b.peer.unit_err, e.peer.unit_err}},
      {"peer.t_err", {b.peer.t_err, e.peer.t_err}}, {"depth_ratio", {b.depth_ratio, e.depth_ratio}},
      {"depth_ratio_lo", {b.depth_ratio_lo, e.depth_ratio_lo}}, {"depth_short", {b.depth_short, e.depth_short}},
      {"depth_over", {b.depth_over, e.depth_over}}, {"tol.verdict", {b.tol.verdict, e.tol.verdict}},
      {"tol.depth", {b.tol.depth, e.tol.depth}}, {"tol.normal", {b.tol.normal, e.tol.normal}},
      {"tol.point", {b.tol.point, e.tol.point}}, {"tol.t", {b.tol.t, e.tol.t}}, {"tol.unit", {b.tol.unit, e.tol.unit}},
      {"tol.depth_ratio", {b.tol.depth_ratio, e.tol.depth_ratio}}, {"tol.input", {b.tol.input, e.tol.input}}};
  for (const auto& [name, v] : doubles) EXPECT_TRUE(same(v.first, v.second)) << name << ": " << v.first << " vs " << v.second;
  EXPECT_EQ(report::to_json(b), line);
  Evaluation partial;
  EXPECT_THROW(report::from_json("{\"valid\": true}", partial), std::exception) << "a line missing fields";
}

// The program's usage errors exit 2: no cases, a case file of another query.
TEST(Subjects, UsageErrorsExitTwo) {
  const auto& prod = production_of<kSphere>();
  const std::string out = (std::filesystem::path(::testing::TempDir()) / "geomcheck-subjects-usage").string();
  std::vector<std::string> zero = {"verify", "--cases", "0", "--out", out};
  auto run = [&](std::vector<std::string> args) {
    std::vector<char*> argv;
    for (auto& a : args) argv.push_back(a.data());
    return verify(prod, static_cast<int>(argv.size()), argv.data());
  };
  EXPECT_EQ(run(zero), 2);
  const std::filesystem::path other = std::filesystem::path(::testing::TempDir()) / "geomcheck-subjects-other.case";
  const SegmentCylinderCase c{{{0, 0, -2}, {0, 0, 2}}, {{0, 0, 0}, {0, 0, 1}, 1}};
  std::string err;
  ASSERT_TRUE(save_case(other, from_case<QueryId::cast_segment_cylinder>(c, "test", "hit", ""), err)) << err;
  EXPECT_EQ(run({"verify", "--replay", other.string()}), 2);
  EXPECT_EQ(run({"verify", "--cases", "20", "--no-shrink", "--quiet", "--no-report", "--out", out}), 0);
}

// A subject that throws on some inputs fails those cases, and the run goes on.
TEST(Subjects, ThrowingSubjectFailsItsCases) {
  const auto mine = subject<kSphere>(
      "throws", [](const Cylinder& c, const Sphere& s) { return overlap(c, s); },
      [](const Cylinder& c, const Sphere& s) {
        if (s.r > c.r) throw std::runtime_error("radius too large for me");
        return collide(c, s);
      });
  const VerifyResult r = verify(mine, options("throws", 300));
  EXPECT_EQ(r.cases, 300);
  EXPECT_GT(count(r, "subject-threw"), 0);
  EXPECT_EQ(r.failures, count(r, "subject-threw"));
}

// NaN in the answer: a failure of the subject, saved.
TEST(Subjects, NaNAnswerFails) {
  const auto mine = subject<kSphere>("nan", [](const Cylinder& c, const Sphere& s) { return overlap(c, s); },
                                     [](const Cylinder& c, const Sphere& s) {
                                       Contact k = collide(c, s);
                                       if (k.hit) k.depth = NAN;
                                       return k;
                                     });
  const VerifyResult r = verify(mine, options("nan", 200));
  EXPECT_GT(count(r, "robust-finite-output"), 0);
  EXPECT_FALSE(r.saved.empty());
}

// A subject that crashes the process on some inputs: those cases fail as
// "subject-crashed", saved; every case is still checked.
TEST(Subjects, CrashingSubjectIsContained) {
  const auto mine = subject<kSphere>("aborts", [](const Cylinder& c, const Sphere& s) { return overlap(c, s); },
                                     [](const Cylinder& c, const Sphere& s) {
                                       if (s.r > 2 * c.r && s.r < 2.5 * c.r) std::abort();
                                       return collide(c, s);
                                     });
  const VerifyResult r = verify(mine, options("aborts", 300));
  EXPECT_EQ(r.cases, 300);
  EXPECT_GT(count(r, "subject-crashed"), 0);
  EXPECT_EQ(r.failures, count(r, "subject-crashed"));
  EXPECT_FALSE(r.saved.empty());
}

// A subject that hangs once (a marker file keeps it to one case): that case
// fails as "subject-hung" after case_seconds, the run goes on.
TEST(Subjects, HangingSubjectIsContained) {
  VerifyOptions opt = options("hangs", 100);
  opt.case_seconds = 1;
  std::filesystem::create_directories(opt.out);
  const std::string marker = (opt.out / "hung-once").string();
  const auto mine = subject<kSphere>("hangs", [](const Cylinder& c, const Sphere& s) { return overlap(c, s); },
                                     [marker](const Cylinder& c, const Sphere& s) {
                                       if (s.r > c.r && !std::filesystem::exists(marker)) {
                                         std::FILE* f = std::fopen(marker.c_str(), "w");
                                         if (f) std::fclose(f);
                                         for (;;) std::this_thread::sleep_for(std::chrono::milliseconds(100));
                                       }
                                       return collide(c, s);
                                     });
  const VerifyResult r = verify(mine, opt);
  EXPECT_EQ(r.cases, 100);
  EXPECT_EQ(count(r, "subject-hung"), 1);
  EXPECT_EQ(r.failures, 1);
}

// Claims: a subject whose ball is 1e-9 larger than the case's answers
// "hit" on near-touching cases (1e-9 of the case's scale). Held to
// production's claims it fails the verdict; claiming a margin of 1e-8 *
// scale, it passes every check; claiming an inexact verdict only, it still
// fails on its depth.
TEST(Subjects, ClaimsAreWhatTheSubjectIsJudgedBy) {
  auto grown = [](const Cylinder& c, const Sphere& s) { return Sphere{s.c, s.r + 1e-9 * oracle::case_scale(c, s)}; };
  auto ov = [grown](const Cylinder& c, const Sphere& s) { return overlap(c, grown(c, s)); };
  auto co = [grown](const Cylinder& c, const Sphere& s) { return collide(c, grown(c, s)); };
  const VerifyResult strict = verify(subject<kSphere>("grown", ov, co), options("strict", 600));
  EXPECT_GT(count(strict, "oracle-verdict"), 0);

  Claims loose = production_claims<kSphere>();
  loose.margin = 1e-8;
  const VerifyResult judged = verify(subject<kSphere>("grown-with-margin", ov, co, loose), options("loose", 600));
  EXPECT_EQ(judged.failures, 0) << (judged.by_property.empty() ? "" : judged.by_property.begin()->first);

  Claims inexact = production_claims<kSphere>();
  inexact.exact_verdict = false;
  const VerifyResult unjudged = verify(subject<kSphere>("grown-inexact", ov, co, inexact), options("inexact", 600));
  EXPECT_EQ(count(unjudged, "oracle-verdict"), 0);
  EXPECT_GT(count(unjudged, "oracle-depth"), 0);
}

// The same yardstick as a RapidCheck property (RC_PARAMS from ctest: a fixed
// seed): production through the door passes, the float subject is caught.
// A depth claim other than production's is judged by its own side(s) of
// the certified penetration depth PD: an upper bound only from below, the
// true PD (stronger than cylinder/cylinder production's upper bound) from
// both sides.
TEST(Subjects, DepthClaimsOtherThanProductionsAreJudgedByTheirSides) {
  Evaluation e;
  e.valid = true;
  e.verdict = oracle::Verdict::Overlapping;
  e.prod_hit = e.truth_hit = true;
  e.depth_err = e.depth_over = 0.1;  // 0.1 * scale above PD
  e.depth_short = 0;
  // penetration(Cylinder, Obb) claims the penetration depth; cylinder/cylinder's collide an upper bound.
  constexpr QueryId kBox = QueryId::penetration_cylinder_obb, kCyl = QueryId::collide_cylinder_cylinder;
  Claims upper = production_claims<kBox>();
  upper.depth = Claims::Depth::UpperBound;
  EXPECT_TRUE(judge(kBox, e, nullptr).has_value());  // production's claim: PD
  EXPECT_FALSE(judge(kBox, e, &upper).has_value());  // an upper bound may lie above
  e.depth_short = 0.1;
  EXPECT_TRUE(judge(kBox, e, &upper).has_value());  // but never below

  e.depth_err = 0, e.depth_short = 0;  // cylinder/cylinder's depth_err: the shortfall alone
  Claims minimal = production_claims<kCyl>();
  minimal.depth = Claims::Depth::Penetration;
  EXPECT_FALSE(judge(kCyl, e, nullptr).has_value());  // production claims an upper bound
  const CheckResult f = judge(kCyl, e, &minimal);
  ASSERT_TRUE(f.has_value());
  EXPECT_EQ(f->property, "oracle-depth");
}

// Production's cylinder/cylinder contact claimed as the true penetration
// depth: its depth is the overlap along one of the talk's candidate
// directions, above PD on some cases, and the stronger claim fails there.
TEST(Subjects, StrongerClaimThanProductionsIsHeld) {
  constexpr QueryId kCyl = QueryId::collide_cylinder_cylinder;
  Claims minimal = production_claims<kCyl>();
  minimal.depth = Claims::Depth::Penetration;
  const auto mine = subject<kCyl>(
      "claims-minimal", [](const Cylinder& a, const Cylinder& b) { return overlap(a, b); },
      [](const Cylinder& a, const Cylinder& b) { return collide(a, b); }, minimal);
  const VerifyResult r = verify(mine, options("claims-minimal", 300));
  EXPECT_GT(count(r, "oracle-depth"), 0);
  EXPECT_EQ(count(r, "oracle-depth"), r.failures);
}

TEST(Subjects, RapidCheckPropertyOfASubject) {
  EXPECT_TRUE(rapidcheck(subject<kSphere>(
      "production-again", [](const Cylinder& c, const Sphere& s) { return overlap(c, s); },
      [](const Cylinder& c, const Sphere& s) { return collide(c, s); })));
  auto f = [](Vec3 v) { return Vec3{float(v.x), float(v.y), float(v.z)}; };
  auto floated = [f](const Cylinder& c, const Sphere& s) {
    Contact k = collide(c, s);
    k.normal = f(k.normal);
    return k;
  };
  EXPECT_FALSE(rapidcheck(subject<kSphere>(
      "float-normal", [](const Cylinder& c, const Sphere& s) { return overlap(c, s); }, floated)));
}

}  // namespace
}  // namespace geomcheck
