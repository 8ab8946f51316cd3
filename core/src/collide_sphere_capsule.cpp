#include "geomcheck/collide_sphere_capsule.hpp"

#include "geomcheck/detail/segment_pair.hpp"

namespace geomcheck {

namespace {
// The centre against the segment: the residual from the segment to the
// centre, turned into the sphere-to-capsule direction. One template for
// the verdict (the distance alone) and the contact: the same bits.
template <class Out>
GEOMCHECK_SOLVER_INLINE void centre_segment(const Sphere& a, const Capsule& b, Out& out) {
  Vec3 c;
  const Vec3 r = detail::point_segment_residual(a.c, b.p, b.q, c);
  out.dist2 = dot(r, r);
  out.points(a.c, c);
  out.direction(-r, false);
  out.touching(b.q - b.p, detail::SegmentPair::Across::PerpendicularOf);  // touching: across the segment
}
GEOMCHECK_FMA_CLONES void centre_segment_distance(const Sphere& a, const Capsule& b, detail::SegmentDistance& out) {
  centre_segment(a, b, out);
}
GEOMCHECK_FMA_CLONES void centre_segment_pair(const Sphere& a, const Capsule& b, detail::SegmentPair& out) {
  centre_segment(a, b, out);
}
}  // namespace

bool overlap(const Sphere& a, const Capsule& b) {
  return detail::ball_pair<detail::SegmentDistance>(a, b, centre_segment_distance).hit();
}

Contact collide(const Sphere& a, const Capsule& b) {
  return detail::ball_contact(detail::ball_pair<detail::SegmentPair>(a, b, centre_segment_pair));
}

}  // namespace geomcheck
