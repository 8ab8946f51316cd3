#include "geomcheck/collide_sphere_sphere.hpp"

#include "geomcheck/detail/segment_pair.hpp"

namespace geomcheck {

namespace {
// The difference of the centres, exactly rounded from its exact parts. One
// template for the verdict (the distance alone) and the contact: the same
// bits. No fma here: inlined, not cloned.
template <class Out>
GEOMCHECK_SOLVER_INLINE void centres(const Sphere& a, const Sphere& b, Out& out) {
  const detail::ExactDiff d = detail::exact_diff(b.c, a.c);
  const Vec3 v = d.hi + d.lo;
  out.dist2 = dot(v, v);
  out.points(a.c, b.c);
  out.direction(v, false);
  out.touching(Vec3{0, 0, 1}, detail::SegmentPair::Across::Unit);  // concentric: any direction, the z axis
}
}  // namespace

bool overlap(const Sphere& a, const Sphere& b) {
  return detail::ball_pair<detail::SegmentDistance>(a, b, centres<detail::SegmentDistance>).hit();
}

Contact collide(const Sphere& a, const Sphere& b) {
  return detail::ball_contact(detail::ball_pair<detail::SegmentPair>(a, b, centres<detail::SegmentPair>));
}

}  // namespace geomcheck
