// geomcheck — the one serialiser (report.hpp, "Serialising"): every field of
// every structure it carries comes back as it went, bit for bit (NaN,
// infinities, -0.0 and subnormals included), and a text missing a field is
// refused. Each structure is filled with values that differ from its
// defaults and compared field by field (the field lists written out here,
// apart from the serialiser's), so that a field the serialiser skipped both
// ways would come back as its default and fail.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <string>
#include <tuple>

#include "geomcheck/reports/report.hpp"

namespace geomcheck::report {
namespace {

double next_value() {
  static double v = 0.25;
  return v += 0.125;
}

Series series() {
  Series s;
  s.v = {next_value(), NAN, -INFINITY, -0.0, std::ldexp(1.0, -1070)};
  return s;
}

Claims claims() {
  Claims c;
  c.exact_verdict = false;
  c.depth = Claims::Depth::UpperBound;
  c.point_in_both = false;
  c.normal = "a normal\twith a tab";
  c.truth = "the truth \"quoted\"";
  c.touching_is_contact = false;
  c.margin = next_value();
  c.any_input = false;
  c.precision = Precision::single_precision(77);
  c.precision.exact_moves = true;
  return c;
}

QueryReport query_report(int depth) {
  QueryReport r;
  r.name = "collide_cylinder_sphere", r.summary = "a summary\nover two lines", r.subject = "mine";
  r.replay = "verify --replay ";
  r.claims = claims();
  r.own_claims = true;
  r.requested = 11, r.stopped_by_time = true, r.cases = 12, r.valid = 13, r.prod_hits = 14, r.truth_hits = 15;
  r.not_expressed = 16;
  r.verdicts = {{"overlapping", 3}, {"touching", 4}};
  r.disagree = 17, r.excused = 18, r.beyond = 19, r.check_failures = 20;
  r.worst_margin = next_value();
  r.depth = series(), r.normal = series(), r.point = series(), r.t = series();
  r.fcl_supported = 21, r.fcl_ok = 22, r.fcl_disagree = 23, r.fcl_beyond = 24;
  r.fcl_depth = series(), r.fcl_normal = series(), r.fcl_point = series(), r.fcl_t_gap = series(), r.fcl_t = series();
  r.fcl_distance = series();
  r.fcl_distance_asked = 25, r.fcl_distance_beyond = 26;
  r.fcl_cases = {"a.case"};
  r.fcl_by_signature = {{"verdict @ mode", 2}};
  r.fcl_shrunk = 27;
  r.prod_ns = next_value(), r.oracle_us = INFINITY;
  r.truth_stages = {{"filter", 5}};
  r.counterexamples = {"b.case", "c.case"};
  r.drawings = {"<svg/>"};
  r.fcl_drawings = {"<svg></svg>"};
  r.failures_by_property = {{"oracle-point", 6}};
  r.failures_by_signature = {{"oracle-point @ mode", 6}};
  r.shrunk = 28;
  r.tol = Tolerances{next_value(), next_value(), next_value(), next_value(), next_value(), next_value(), next_value(), next_value()};
  r.depth_is_bound = true;
  r.depth_ratio = series();
  if (depth > 0) r.peers = {query_report(depth - 1)}, r.first = {query_report(depth - 1)};
  r.bugreports = 29;
  r.bugreports_failed = {"bugreport-1"};
  return r;
}

template <class T>
void round_trip(const T& x) {
  const std::string text = to_json(x);
  EXPECT_EQ(text.find('\n'), std::string::npos);
  EXPECT_EQ(text.find('\t'), std::string::npos);
  T y;
  from_json(text, y);
  EXPECT_EQ(to_json(y), text);
}

// Every field of y is x's (the field list written out here, apart from the
// serialiser's, so that a field the serialiser skips both ways is caught).
void expect_same(const QueryReport& y, const QueryReport& x) {
  const auto same = [](double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0 || (std::isnan(a) && std::isnan(b)); };
  const auto same_series = [&](const Series& a, const Series& b) {
    if (a.v.size() != b.v.size()) return false;
    for (std::size_t k = 0; k < a.v.size(); ++k)
      if (!same(a.v[k], b.v[k])) return false;
    return true;
  };
  EXPECT_EQ(y.name, x.name);
  EXPECT_EQ(y.summary, x.summary);
  EXPECT_EQ(y.subject, x.subject);
  EXPECT_EQ(y.replay, x.replay);
  EXPECT_EQ(y.claims.exact_verdict, x.claims.exact_verdict);
  EXPECT_EQ(y.claims.depth, x.claims.depth);
  EXPECT_EQ(y.claims.point_in_both, x.claims.point_in_both);
  EXPECT_STREQ(y.claims.normal, x.claims.normal);
  EXPECT_STREQ(y.claims.truth, x.claims.truth);
  EXPECT_EQ(y.claims.touching_is_contact, x.claims.touching_is_contact);
  EXPECT_TRUE(same(y.claims.margin, x.claims.margin));
  EXPECT_EQ(y.claims.any_input, x.claims.any_input);
  EXPECT_TRUE(same(y.claims.precision.unit_roundoff, x.claims.precision.unit_roundoff));
  EXPECT_TRUE(same(y.claims.precision.ulps, x.claims.precision.ulps));
  EXPECT_TRUE(same(y.claims.precision.min_scale, x.claims.precision.min_scale));
  EXPECT_TRUE(same(y.claims.precision.max_scale, x.claims.precision.max_scale));
  EXPECT_EQ(y.claims.precision.exact_moves, x.claims.precision.exact_moves);
  EXPECT_EQ(y.own_claims, x.own_claims);
  EXPECT_EQ(y.requested, x.requested);
  EXPECT_EQ(y.stopped_by_time, x.stopped_by_time);
  EXPECT_EQ(y.cases, x.cases);
  EXPECT_EQ(y.valid, x.valid);
  EXPECT_EQ(y.prod_hits, x.prod_hits);
  EXPECT_EQ(y.truth_hits, x.truth_hits);
  EXPECT_EQ(y.not_expressed, x.not_expressed);
  EXPECT_EQ(y.verdicts, x.verdicts);
  EXPECT_EQ(y.disagree, x.disagree);
  EXPECT_EQ(y.excused, x.excused);
  EXPECT_EQ(y.beyond, x.beyond);
  EXPECT_EQ(y.check_failures, x.check_failures);
  EXPECT_TRUE(same(y.worst_margin, x.worst_margin));
  EXPECT_TRUE(same_series(y.depth, x.depth));
  EXPECT_TRUE(same_series(y.normal, x.normal));
  EXPECT_TRUE(same_series(y.point, x.point));
  EXPECT_TRUE(same_series(y.t, x.t));
  EXPECT_EQ(y.fcl_supported, x.fcl_supported);
  EXPECT_EQ(y.fcl_ok, x.fcl_ok);
  EXPECT_EQ(y.fcl_disagree, x.fcl_disagree);
  EXPECT_EQ(y.fcl_beyond, x.fcl_beyond);
  EXPECT_TRUE(same_series(y.fcl_depth, x.fcl_depth));
  EXPECT_TRUE(same_series(y.fcl_normal, x.fcl_normal));
  EXPECT_TRUE(same_series(y.fcl_point, x.fcl_point));
  EXPECT_TRUE(same_series(y.fcl_t_gap, x.fcl_t_gap));
  EXPECT_TRUE(same_series(y.fcl_t, x.fcl_t));
  EXPECT_TRUE(same_series(y.fcl_distance, x.fcl_distance));
  EXPECT_EQ(y.fcl_distance_asked, x.fcl_distance_asked);
  EXPECT_EQ(y.fcl_distance_beyond, x.fcl_distance_beyond);
  EXPECT_EQ(y.fcl_cases, x.fcl_cases);
  EXPECT_EQ(y.fcl_by_signature, x.fcl_by_signature);
  EXPECT_EQ(y.fcl_shrunk, x.fcl_shrunk);
  EXPECT_TRUE(same(y.prod_ns, x.prod_ns));
  EXPECT_TRUE(same(y.oracle_us, x.oracle_us));
  EXPECT_EQ(y.truth_stages, x.truth_stages);
  EXPECT_EQ(y.counterexamples, x.counterexamples);
  EXPECT_EQ(y.drawings, x.drawings);
  EXPECT_EQ(y.fcl_drawings, x.fcl_drawings);
  EXPECT_EQ(y.failures_by_property, x.failures_by_property);
  EXPECT_EQ(y.failures_by_signature, x.failures_by_signature);
  EXPECT_EQ(y.shrunk, x.shrunk);
  EXPECT_TRUE(same(y.tol.verdict, x.tol.verdict));
  EXPECT_TRUE(same(y.tol.depth, x.tol.depth));
  EXPECT_TRUE(same(y.tol.normal, x.tol.normal));
  EXPECT_TRUE(same(y.tol.point, x.tol.point));
  EXPECT_TRUE(same(y.tol.t, x.tol.t));
  EXPECT_TRUE(same(y.tol.unit, x.tol.unit));
  EXPECT_TRUE(same(y.tol.depth_ratio, x.tol.depth_ratio));
  EXPECT_TRUE(same(y.tol.input, x.tol.input));
  EXPECT_EQ(y.depth_is_bound, x.depth_is_bound);
  EXPECT_TRUE(same_series(y.depth_ratio, x.depth_ratio));
  ASSERT_EQ(y.peers.size(), x.peers.size());
  for (std::size_t k = 0; k < x.peers.size(); ++k) expect_same(y.peers[k], x.peers[k]);
  ASSERT_EQ(y.first.size(), x.first.size());
  for (std::size_t k = 0; k < x.first.size(); ++k) expect_same(y.first[k], x.first[k]);
  EXPECT_EQ(y.bugreports, x.bugreports);
  EXPECT_EQ(y.bugreports_failed, x.bugreports_failed);
}

TEST(Serialize, QueryReportEveryField) {
  const QueryReport r = query_report(1);
  round_trip(r);
  QueryReport y;
  from_json(to_json(r), y);
  expect_same(y, r);
  // The fields shard.json once dropped: a subject's precision and input claim, two bounds.
  EXPECT_EQ(y.claims.precision.unit_roundoff, 0x1p-24);
  EXPECT_EQ(y.claims.precision.ulps, 77);
  EXPECT_TRUE(y.claims.precision.exact_moves);
  EXPECT_FALSE(y.claims.any_input);
  EXPECT_EQ(y.tol.input, r.tol.input);
  EXPECT_EQ(y.tol.depth_ratio, r.tol.depth_ratio);
  ASSERT_EQ(y.depth.v.size(), 5u);
  EXPECT_TRUE(std::isnan(y.depth.v[1]));
  EXPECT_TRUE(std::signbit(y.depth.v[3]));
  EXPECT_EQ(y.depth.v[4], std::ldexp(1.0, -1070));
  ASSERT_EQ(y.peers.size(), 1u);
  EXPECT_STREQ(y.peers[0].claims.normal, "a normal\twith a tab");
}

TEST(Serialize, PointSetAndMeshReportsAndRunInfo) {
  PointSetReport p;
  p.name = "delaunay_2d", p.summary = "s", p.subject = "mine", p.not_asked = 3, p.requested = 4, p.stopped_by_time = true;
  p.sets = 5, p.points = 600, p.modes = {{"grid", 2}}, p.kinds = {{"triangulated", 5}}, p.failures = 1;
  p.failures_by_property = {{"valid", 1}}, p.cgal_choices_differ = 2, p.production_us = 0.5, p.cgal_us = 0.75;
  p.counterexamples = {"d.case"};
  round_trip(p);
  PointSetReport q;
  from_json(to_json(p), q);
  EXPECT_EQ(std::make_tuple(q.name, q.summary, q.subject, q.not_asked, q.requested, q.stopped_by_time, q.sets, q.points,
                            q.modes, q.kinds, q.failures, q.failures_by_property, q.cgal_choices_differ, q.production_us,
                            q.cgal_us, q.counterexamples),
            std::make_tuple(p.name, p.summary, p.subject, p.not_asked, p.requested, p.stopped_by_time, p.sets, p.points,
                            p.modes, p.kinds, p.failures, p.failures_by_property, p.cgal_choices_differ, p.production_us,
                            p.cgal_us, p.counterexamples));
  MeshReport m;
  m.name = "collide_cylinder_mesh", m.summary = "s", m.under_test = "mesh_first_face", m.requested = 7;
  m.stopped_by_time = true, m.meshes = 8, m.faces = 900, m.modes = {{"sheet", 1}}, m.verdicts = {{"touching", 1}};
  m.failures = 2, m.failures_by_property = {{"brute-force", 2}}, m.faces_by_box = 10, m.faces_by_engine = 11;
  m.production_us = 1.5, m.brute_force_us = 2.5, m.seconds = 3.5, m.counterexamples = {"e.case"};
  round_trip(m);
  MeshReport n;
  from_json(to_json(m), n);
  EXPECT_EQ(std::make_tuple(n.name, n.summary, n.under_test, n.requested, n.stopped_by_time, n.meshes, n.faces, n.modes,
                            n.verdicts, n.failures, n.failures_by_property, n.faces_by_box, n.faces_by_engine,
                            n.production_us, n.brute_force_us, n.seconds, n.counterexamples),
            std::make_tuple(m.name, m.summary, m.under_test, m.requested, m.stopped_by_time, m.meshes, m.faces, m.modes,
                            m.verdicts, m.failures, m.failures_by_property, m.faces_by_box, m.faces_by_engine,
                            m.production_us, m.brute_force_us, m.seconds, m.counterexamples));
  RunInfo run{"1.2.3", "2026-12-02T00:00:00Z", "geomcheck campaign", 20261121, "100 cases", "rerun", "production"};
  round_trip(run);
  RunInfo back;
  from_json(to_json(run), back);
  EXPECT_EQ(std::make_tuple(back.version, back.started, back.command, back.seed, back.per_query, back.rerun, back.under_test),
            std::make_tuple(run.version, run.started, run.command, run.seed, run.per_query, run.rerun, run.under_test));
}

TEST(Serialize, MergeAddsEveryCount) {
  PointSetReport a, b;
  a.sets = 2, a.points = 10, a.modes = {{"grid", 2}}, a.production_us = 1, a.cgal_us = 2, a.not_asked = 1;
  b.sets = 3, b.points = 20, b.modes = {{"grid", 1}, {"uniform", 2}}, b.production_us = 3, b.cgal_us = 4, b.not_asked = 2;
  merge_into(a, b);
  EXPECT_EQ(a.sets, 5);
  EXPECT_EQ(a.points, 30u);
  EXPECT_EQ(a.modes.at("grid"), 3);
  EXPECT_EQ(a.modes.at("uniform"), 2);
  EXPECT_EQ(a.production_us, 4);
  EXPECT_EQ(a.cgal_us, 6);
  EXPECT_EQ(a.not_asked, 3);
}

TEST(Serialize, MissingFieldRefused) {
  QueryReport r;
  EXPECT_THROW(from_json("{\"name\": \"x\"}", r), std::runtime_error);
  EXPECT_THROW(from_json("not json", r), std::runtime_error);
  Evaluation e;
  std::string text = to_json(e);
  text.replace(text.find("\"scale\""), 7, "\"scalf\"");
  EXPECT_THROW(from_json(text, e), std::runtime_error);
}

}  // namespace
}  // namespace geomcheck::report
