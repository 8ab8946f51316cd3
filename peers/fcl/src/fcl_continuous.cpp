// geomcheck — FCL's continuous collision (fcl::continuousCollide,
// conservative advancement): a ball (a segment: radius 0) moving against a
// resting solid, validated, within range, guarded, and asked again in
// exactly equivalent frames after a miss (fcl_adapter.hpp, "Cast").
#include <cmath>

#include <fcl/narrowphase/continuous_collision.h>

#include "fcl_guards.hpp"
#include "geomcheck/peers/fcl_convert.hpp"

namespace geomcheck::peers {

namespace {

using fcl_detail::guarded_into;
using fcl_detail::to_fcl;

/// A sphere of radius r translated from `from` to `to` (a segment cast: r = 0).
struct Motion {
  Vec3 from, to;
  double r = 0;
};
Motion motion_of(const Segment& s) { return {s.a, s.b, 0.0}; }
Motion motion_of(const MovingSphere& m) { return {m.c, m.c + m.delta, m.r}; }

/// One fcl::continuousCollide call: the sphere of the motion against the
/// resting shape.
template <class B>
PeerCast continuous_collide_once(const Motion& m, const B& c) {
  PeerCast out;
  out.supported = true;
  const FclOf<B> cyl(c);
  const fcl::Sphered point(m.r);
  fcl::Transform3d begin = fcl::Transform3d::Identity(), end = fcl::Transform3d::Identity();
  begin.translation() = to_fcl(m.from);
  end.translation() = to_fcl(m.to);
  const fcl::ContinuousCollisionRequestd req(10, 1e-4, fcl::CCDM_TRANS, fcl::GST_LIBCCD,
                                             fcl::CCDC_CONSERVATIVE_ADVANCEMENT);
  fcl::ContinuousCollisionResultd res;
  fcl::continuousCollide(&point, begin, end, &cyl.shape, cyl.pose, cyl.pose, req, res);
  out.ok = true;
  out.hit = res.is_collide;
  out.t = res.is_collide ? res.time_of_contact : 0.0;
  if (!std::isfinite(out.t) || out.t < 0 || out.t > 1) {
    out.ok = false;
    out.error = "FCL returned a time of contact outside [0, 1]";
  }
  return out;
}

/// Exact re-expressions of the same scene (negations and a cyclic
/// permutation of the coordinates only): frame k of 4.
Vec3 in_frame(const Vec3& v, int k) {
  const Vec3 w = (k & 1) ? -v : v;
  return (k & 2) ? Vec3{w.y, w.z, w.x} : w;
}
Motion in_frame(const Motion& m, int k) { return {in_frame(m.from, k), in_frame(m.to, k), m.r}; }
/// Frame k as a map of space (shapes.hpp's mapped): points and directions
/// re-expressed alike, lengths kept (a box's extents are in its own frame).
struct InFrame {
  int k;
  Vec3 pt(Vec3 v) const { return in_frame(v, k); }
  Vec3 vec(Vec3 v) const { return in_frame(v, k); }
  double len(double r) const { return r; }
};
template <class Shape>
Shape in_frame(const Shape& s, int k) {
  return mapped(s, InFrame{k});
}

/// Largest size FCL's continuous collision is given: its bounding-volume
/// fit squares the shape's dimensions (beyond this it overflows, prints
/// "eigen: too many iterations in Jacobi transform." and answers garbage).
const double kCastMaxExtent = std::ldexp(1.0, 500);

/// The shape's offsets and sizes (fcl_detail::extent) with the ball's
/// radius and its two positions, from the shape's first point.
template <class B>
bool within_cast_range(const Motion& m, const B& c) {
  const Vec3 o = fcl_detail::reach(c).points[0];
  const double extent = std::fmax(std::fmax(fcl_detail::extent(c, c), m.r),
                                  std::fmax(max_abs(m.from - o), max_abs(m.to - o)));
  return extent <= kCastMaxExtent;  // false for NaN too
}

template <class B>
PeerCast cast_conservative_advancement(const Motion& m, const B& c, bool more_frames) {
  if (!within_cast_range(m, c)) {
    PeerCast out;
    out.supported = true;
    out.error = "outside FCL's range";
    return out;
  }
  const PeerCast first = continuous_collide_once(m, c);
  if (!more_frames || !first.ok || first.hit) return first;
  // FCL misses some hits (see the header): ask again in exactly equivalent
  // frames, where the rounding of the advancement steps differs.
  for (int k = 1; k < 4; ++k) {
    const PeerCast again = continuous_collide_once(in_frame(m, k), in_frame(c, k));
    if (again.ok && again.hit) return again;
  }
  return first;
}

/// fcl_cast and fcl_sweep: validation, range, exceptions.
template <class Moving, class B>
PeerCast continuous_collide(const Moving& moving, const B& c, FclCastMethod method) {
  PeerCast out;
  out.supported = true;
  if (const char* why = fcl_detail::refusal(moving, c)) {  // invalid input, a box frame FCL cannot take
    out.error = why;
    return out;
  }
  return guarded_into(out, [&]() -> PeerCast {
    return cast_conservative_advancement(motion_of(moving), c,
                                         method != FclCastMethod::kConservativeAdvancementOnce);
  });
}

}  // namespace

template <class B>
PeerCast fcl_cast(const Segment& s, const B& b, FclCastMethod method) {
  return continuous_collide(s, b, method);
}

template <class B>
PeerCast fcl_sweep(const MovingSphere& m, const B& b, FclCastMethod method) {
  return continuous_collide(m, b, method);
}

#define GEOMCHECK_X(B)                                                    \
  template PeerCast fcl_cast(const Segment&, const B&, FclCastMethod);    \
  template PeerCast fcl_sweep(const MovingSphere&, const B&, FclCastMethod);
GEOMCHECK_FCL_SOLIDS(GEOMCHECK_X)
#undef GEOMCHECK_X

}  // namespace geomcheck::peers
