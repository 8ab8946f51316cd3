// geomcheck — the one serialiser (report.hpp, "Serialising"): every field of
// every structure it carries comes back as it went, bit for bit (NaN,
// infinities, -0.0 and subnormals included), and a text missing a field is
// refused. Each structure is filled with values that differ from its
// defaults, so that a field the serialiser dropped would come back as its
// default and the comparison of the texts would fail.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <string>

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

TEST(Serialize, QueryReportEveryField) {
  const QueryReport r = query_report(1);
  round_trip(r);
  QueryReport y;
  from_json(to_json(r), y);
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
  MeshReport m;
  m.name = "collide_cylinder_mesh", m.summary = "s", m.under_test = "mesh_first_face", m.requested = 7;
  m.stopped_by_time = true, m.meshes = 8, m.faces = 900, m.modes = {{"sheet", 1}}, m.verdicts = {{"touching", 1}};
  m.failures = 2, m.failures_by_property = {{"brute-force", 2}}, m.faces_by_box = 10, m.faces_by_engine = 11;
  m.production_us = 1.5, m.brute_force_us = 2.5, m.seconds = 3.5, m.counterexamples = {"e.case"};
  round_trip(m);
  RunInfo run{"1.2.3", "2026-12-02T00:00:00Z", "geomcheck campaign", 20261121, "100 cases", "rerun", "production"};
  round_trip(run);
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
