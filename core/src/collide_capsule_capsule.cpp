#include "geomcheck/collide_capsule_capsule.hpp"

#include "geomcheck/detail/segment_pair.hpp"

namespace geomcheck {

namespace {
detail::SegmentPair segments(const Capsule& a, const Capsule& b) { return detail::closest_segments(a.p, a.q, b.p, b.q); }
}  // namespace

bool overlap(const Capsule& a, const Capsule& b) { return detail::ball_pair(a, b, segments).hit(); }

Contact collide(const Capsule& a, const Capsule& b) { return detail::ball_contact(detail::ball_pair(a, b, segments)); }

}  // namespace geomcheck
