// geomcheck — teeth: the suite must catch each known-wrong variant within
// the CI budget (the fixed seed and max_success of ctest), with a shrunk
// counterexample saved as a case file.
#include <gtest/gtest.h>

#include <iostream>

#include "suites.hpp"
#include "teeth_variants.hpp"

namespace geomcheck {
namespace {

template <QueryId Q>
void expect_caught(const typename Suite<Q>::Impl& wrong) {
  const std::string name = std::string(info(Q).name) + ".teeth." + wrong.name;
  const PropertyRun r = run_property<Q>(
      name, Suite<Q>::targeted(), [&](const auto& c) { return check_all(c, wrong); },
      [&](const auto& c) { return Suite<Q>::hit(c, wrong); });
  ASSERT_FALSE(r.passed) << "the suite did not catch the known-wrong variant '" << wrong.name << "' in "
                         << r.cases << " cases";
  ASSERT_FALSE(r.case_file.empty()) << "no shrunk counterexample was saved";
  const ParseResult saved = load_case(r.case_file);
  ASSERT_TRUE(saved.ok()) << saved.error;
  // The shrunk counterexample must still show the variant wrong and production right.
  const auto c = to_case<Q>(saved.value);
  EXPECT_TRUE(check_all(c, wrong).has_value());
  EXPECT_FALSE(check_oracle(c).has_value());
  std::cout << "[teeth] " << wrong.name << " caught after " << r.cases << " cases; shrunk counterexample: "
            << r.case_file << "\n"
            << r.failure << "\n";
}

TEST(teeth, sphere_cylinder_as_capsule) { expect_caught<QueryId::collide_cylinder_sphere>(teeth::kCapsuleForCylinder); }
TEST(teeth, cast_infinite_cylinder_no_caps) { expect_caught<QueryId::cast_segment_cylinder>(teeth::kInfiniteCylinder); }
TEST(teeth, cast_ericson_as_printed) { expect_caught<QueryId::cast_segment_cylinder>(teeth::kEricsonPrinted); }
TEST(teeth, capsule_cylinder_as_capsule_capsule) { expect_caught<QueryId::collide_cylinder_capsule>(teeth::kCapsuleCapsule); }
TEST(teeth, sweep_without_corner_stage) { expect_caught<QueryId::sweep_sphere_cylinder>(teeth::kSweepNoCornerStage); }
TEST(teeth, sweep_talk_one_rim_point) { expect_caught<QueryId::sweep_sphere_cylinder>(teeth::kSweepTalkRimPoint); }
TEST(teeth, box_cylinder_as_box_capsule) { expect_caught<QueryId::collide_cylinder_obb>(teeth::kBoxAsCapsule); }
TEST(teeth, box_talk_one_ray_per_plane) { expect_caught<QueryId::collide_cylinder_obb>(teeth::kBoxTalkRays); }
TEST(teeth, triangle_without_cap_stage) { expect_caught<QueryId::collide_cylinder_triangle>(teeth::kTriangleNoCapStage); }
TEST(teeth, cylinder_pair_without_false_positive_planes) {
  expect_caught<QueryId::collide_cylinder_cylinder>(teeth::kCylinderNoPlanes);
}
TEST(teeth, cylinder_pair_without_parallel_branch) {
  expect_caught<QueryId::collide_cylinder_cylinder>(teeth::kCylinderNoParallelBranch);
}
TEST(teeth, cylinder_pair_plain_frame) { expect_caught<QueryId::collide_cylinder_cylinder>(teeth::kCylinderPlainFrame); }

}  // namespace
}  // namespace geomcheck
