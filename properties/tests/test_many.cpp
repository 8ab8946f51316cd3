// The list queries (collide_many.hpp): every element bit-identical to the
// scalar query, for batches of spheres, capsules and boxes around one
// cylinder. A batch is the first case's cylinder and the shapes B of several
// cases of the campaign's targeted generators, each moved by the offset
// between its own cylinder's p and the batch's (so that most stay near the
// cylinder: hits, misses and touching poses mixed), plus invalid shapes (a
// NaN or a negative radius) at random places; an invalid cylinder is tried
// too. Fixed seed from RC_PARAMS (ctest).
#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "geomcheck/collide_cylinder_capsule.hpp"
#include "geomcheck/collide_cylinder_obb.hpp"
#include "geomcheck/collide_cylinder_sphere.hpp"
#include "geomcheck/collide_many.hpp"
#include "geomcheck/properties/generators.hpp"
#include "geomcheck/registry.hpp"

using namespace geomcheck;

namespace {

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }
bool same_bits(Vec3 a, Vec3 b) { return same_bits(a.x, b.x) && same_bits(a.y, b.y) && same_bits(a.z, b.z); }
bool same_bits(const Contact& a, const Contact& b) {
  return a.hit == b.hit && same_bits(a.point, b.point) && same_bits(a.normal, b.normal) && same_bits(a.depth, b.depth);
}

Sphere moved(Sphere s, Vec3 t) { return {s.c + t, s.r}; }
Capsule moved(Capsule c, Vec3 t) { return {c.p + t, c.q + t, c.r}; }
Obb moved(Obb b, Vec3 t) { return {b.c + t, b.axes, b.e}; }
Sphere broken(Sphere s, int k) { s.r = k ? -1.0 : std::numeric_limits<double>::quiet_NaN(); return s; }
Capsule broken(Capsule c, int k) { c.r = k ? -1.0 : std::numeric_limits<double>::quiet_NaN(); return c; }
Obb broken(Obb b, int k) { b.e.x = k ? -1.0 : std::numeric_limits<double>::quiet_NaN(); return b; }

template <QueryId Q>
void batch_is_scalar() {
  using B = typename QueryTraits<Q>::ShapeB;
  const auto gen = gen::targeted<Q>();
  // elementOf draws uniformly at every size (inRange narrows at small sizes).
  const int n = *rc::gen::elementOf(std::vector<int>{1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16});
  Cylinder cyl{};
  std::vector<B> b;
  for (int i = 0; i < n; ++i) {
    const auto tc = *gen;
    if (i == 0) cyl = tc.first.a;
    b.push_back(moved(tc.first.b, cyl.p - tc.first.a.p));
    if (*rc::gen::elementOf(std::vector<int>{0, 1, 2, 3, 4, 5, 6, 7}) == 0)
      b.back() = broken(b.back(), *rc::gen::elementOf(std::vector<int>{0, 1}));
  }
  if (*rc::gen::elementOf(std::vector<int>{0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19}) == 0)
    cyl.r = -1;  // an invalid cylinder: no contact anywhere
  std::unique_ptr<bool[]> ov(new bool[b.size()]);
  std::vector<Contact> ct(b.size());
  overlap_many(cyl, b.data(), b.size(), ov.get());
  collide_many(cyl, b.data(), b.size(), ct.data());
  for (std::size_t i = 0; i < b.size(); ++i) {
    const bool o = overlap(cyl, b[i]);
    RC_ASSERT(ov[i] == o);
    RC_ASSERT(same_bits(ct[i], collide(cyl, b[i])));
    if (!is_valid(cyl) || !is_valid(b[i])) RC_ASSERT(!ov[i] && !ct[i].hit);
  }
  RC_TAG(std::string(std::count(ov.get(), ov.get() + b.size(), true) > 0 ? "some hits" : "no hit"),
         std::string(b.size() >= 8 ? "8-16 shapes" : "1-7 shapes"));
}

}  // namespace

RC_GTEST_PROP(ListQueries, SpheresBitIdenticalToScalar, ()) { batch_is_scalar<QueryId::collide_cylinder_sphere>(); }
RC_GTEST_PROP(ListQueries, CapsulesBitIdenticalToScalar, ()) { batch_is_scalar<QueryId::collide_cylinder_capsule>(); }
RC_GTEST_PROP(ListQueries, BoxesBitIdenticalToScalar, ()) { batch_is_scalar<QueryId::collide_cylinder_obb>(); }

// The vector forms and an empty batch.
TEST(ListQueries, VectorFormsAndEmptyBatch) {
  const Cylinder cyl{{0, 0, 0}, {0, 0, 2}, 1};
  const std::vector<Sphere> s{{{0, 0, 1}, 0.5}, {{5, 0, 1}, 0.5}, {{1.5, 0, 1}, 0.5}, {{0, 0, 1}, -1}};
  const std::vector<bool> o = overlap_many(cyl, s);
  ASSERT_EQ(o, (std::vector<bool>{true, false, true, false}));  // the third touches the side
  const std::vector<Contact> c = collide_many(cyl, s);
  ASSERT_EQ(c.size(), 4u);
  EXPECT_TRUE(c[0].hit);
  EXPECT_FALSE(c[1].hit);
  EXPECT_TRUE(c[2].hit);
  EXPECT_EQ(c[2].depth, 0.0);
  EXPECT_FALSE(c[3].hit);
  EXPECT_TRUE(overlap_many(cyl, std::vector<Capsule>{}).empty());
  EXPECT_TRUE(collide_many(cyl, std::vector<Obb>{}).empty());
}

// Spheres the batch arithmetic leaves to the scalar query (squares that
// would overflow or underflow: the scalar query rescales), beside ordinary
// ones, and an axis too short to square: the same answers as the scalar query.
TEST(ListQueries, ScalarFallbackInsideABatch) {
  const std::vector<Sphere> s{{{0, 0, 1}, 0.5},       {{1e250, 0, 0}, 2e250},  {{1e-300, 0, 1}, 1e-300},
                              {{0, 3e160, 1}, 1e160}, {{0, 0, 1}, 0x1p+201},   {{2, 0, 1}, 0.5},
                              {{0, 0, 1e-170}, 1e-171}};
  for (const Cylinder& cyl : {Cylinder{{0, 0, 0}, {0, 0, 2}, 1}, Cylinder{{0, 0, 0}, {0, 0, 1e-170}, 1e-170}}) {
    const std::vector<bool> o = overlap_many(cyl, s);
    int hits = 0;
    for (std::size_t i = 0; i < s.size(); ++i) {
      EXPECT_EQ(o[i], overlap(cyl, s[i])) << "sphere " << i;
      hits += o[i];
    }
    EXPECT_GT(hits, 1);
    EXPECT_LT(hits, static_cast<int>(s.size()));
  }
}
