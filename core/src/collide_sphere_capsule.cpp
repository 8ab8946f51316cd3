#include "geomcheck/collide_sphere_capsule.hpp"

#include "geomcheck/detail/segment_pair.hpp"

namespace geomcheck {

namespace {
// The centre against the segment: the residual from the segment to the
// centre, turned into the sphere-to-capsule direction.
detail::SegmentPair centre_segment(const Sphere& a, const Capsule& b) {
  detail::SegmentPair out;
  Vec3 c;
  const Vec3 r = detail::point_segment_residual(a.c, b.p, b.q, c);
  out.dist = detail::norm_of(r);
  out.a = a.c;
  out.b = c;
  out.across = detail::some_perpendicular(b.q - b.p);
  out.n = out.dist > 0 ? -detail::unit_of(r) : out.across;
  return out;
}
}  // namespace

bool overlap(const Sphere& a, const Capsule& b) { return detail::ball_pair(a, b, centre_segment).hit(); }

Contact collide(const Sphere& a, const Capsule& b) {
  return detail::ball_contact(detail::ball_pair(a, b, centre_segment));
}

}  // namespace geomcheck
