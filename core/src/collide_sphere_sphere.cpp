#include "geomcheck/collide_sphere_sphere.hpp"

#include "geomcheck/detail/segment_pair.hpp"

namespace geomcheck {

namespace {
detail::SegmentPair centres(const Sphere& a, const Sphere& b) {
  detail::SegmentPair out;
  const detail::ExactDiff d = detail::exact_diff(b.c, a.c);
  const Vec3 v = d.hi + d.lo;
  out.dist = detail::norm_of(v);
  out.a = a.c;
  out.b = b.c;
  out.n = out.dist > 0 ? detail::unit_of(v) : Vec3{0, 0, 1};
  out.across = Vec3{0, 0, 1};
  return out;
}
}  // namespace

bool overlap(const Sphere& a, const Sphere& b) { return detail::ball_pair(a, b, centres).hit(); }

Contact collide(const Sphere& a, const Sphere& b) { return detail::ball_contact(detail::ball_pair(a, b, centres)); }

}  // namespace geomcheck
