#include "geomcheck/collide_capsule_capsule.hpp"

#include "geomcheck/detail/segment_pair.hpp"

namespace geomcheck {

namespace {
// The solver, for the verdict (the distance alone) and for the contact:
// one template, so both compute the same distance bit for bit.
GEOMCHECK_FMA_CLONES void segments_distance(const Capsule& a, const Capsule& b, detail::SegmentDistance& out) {
  detail::closest_segments(a.p, a.q, b.p, b.q, out);
}
GEOMCHECK_FMA_CLONES void segments(const Capsule& a, const Capsule& b, detail::SegmentPair& out) {
  detail::closest_segments(a.p, a.q, b.p, b.q, out);
}
}  // namespace

bool overlap(const Capsule& a, const Capsule& b) {
  return detail::ball_pair<detail::SegmentDistance>(a, b, segments_distance).hit();
}

Contact collide(const Capsule& a, const Capsule& b) {
  return detail::ball_contact(detail::ball_pair<detail::SegmentPair>(a, b, segments));
}

}  // namespace geomcheck
