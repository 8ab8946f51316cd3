// geomcheck — known-wrong variants of production: the suites prove they can
// fail by catching each of them (properties/tests/test_teeth.cpp).
#include "geomcheck/properties/teeth.hpp"

#include <algorithm>
#include <cmath>

#include "geomcheck/detail/cylinder_pair.hpp"
#include "geomcheck/detail/frame.hpp"
#include "geomcheck/detail/obb_stages.hpp"
#include "geomcheck/detail/sweep_stages.hpp"
#include "geomcheck/detail/triangle_stages.hpp"

namespace geomcheck::teeth {

namespace {
// Closest point to x on segment pq.
Vec3 closest_on_segment(Vec3 x, Vec3 p, Vec3 q) {
  const Vec3 d = q - p;
  const double t = std::clamp(dot(x - p, d) / dot(d, d), 0.0, 1.0);
  return p + t * d;
}

// The contact of two rounded shapes whose cores are closest at a (on the
// cylinder's axis, radius ra) and b (radius rb): the normal from a to b (any
// perpendicular of the axis when they coincide), the depth ra + rb - |b - a|,
// the point on a's rounded surface.
Contact rounded_contact(Vec3 a, Vec3 b, double ra, double rb, Vec3 axis) {
  Contact out;
  const Vec3 v = b - a;
  const double l = length(v);
  out.hit = true;
  out.normal = l > 0 ? (1.0 / l) * v : any_perpendicular(axis);
  out.depth = ra + rb - l;
  out.point = a + ra * out.normal;
  return out;
}
}  // namespace

// Sphere against the cylinder's capsule: the end-cap discontinuity ignored
// (round caps instead of flat ones).
bool capsule_overlap(const Cylinder& c, const Sphere& s) {
  if (!is_valid(c) || !is_valid(s)) return false;
  const Vec3 x = closest_on_segment(s.c, c.p, c.q);
  const double r = c.r + s.r;
  return length2(s.c - x) <= r * r;
}

Contact capsule_collide(const Cylinder& c, const Sphere& s) {
  if (!capsule_overlap(c, s)) return {};
  return rounded_contact(closest_on_segment(s.c, c.p, c.q), s.c, c.r, s.r, c.q - c.p);
}

// The segment cast against the infinite cylinder: no cap test at all.
CastHit infinite_cylinder_cast(const Segment& seg, const Cylinder& cyl) {
  CastHit out;
  if (!is_valid(seg) || !is_valid(cyl)) return out;
  const Vec3 d = cyl.q - cyl.p, m = seg.a - cyl.p, n = seg.b - seg.a;
  const double dd = dot(d, d);
  const Vec3 mxd = cross(m, d), nxd = cross(n, d);
  const double qa = dot(nxd, nxd), qb = dot(mxd, nxd), qc = dot(mxd, mxd) - cyl.r * cyl.r * dd;
  if (qc <= 0) {
    out.hit = out.starts_inside = true;
    out.point = seg.a;
    return out;
  }
  double t;
  if (!detail::entry_root(qa, qb, qc, t)) return out;
  out.hit = true;
  out.t = t;
  out.point = seg.a + t * n;
  const Vec3 x = m + t * n;
  const Vec3 radial = x - (dot(x, d) / dd) * d;
  const double l = length(radial);
  out.normal = l > 0 ? (1.0 / l) * radial : any_perpendicular(d);
  return out;
}

// Ericson's IntersectSegmentCylinder as printed (p. 197), absolute EPSILON
// and all: rejects a negative first root (start inside, or a cap entry whose
// side root lies before the start) and uses k + 2t(mn + t nn) for the p cap.
CastHit ericson_printed_cast(const Segment& seg, const Cylinder& cyl) {
  CastHit out;
  if (!is_valid(seg) || !is_valid(cyl)) return out;
  const Vec3 d = cyl.q - cyl.p, m = seg.a - cyl.p, n = seg.b - seg.a;
  const double md = dot(m, d), nd = dot(n, d), dd = dot(d, d);
  if (md < 0 && md + nd < 0) return out;
  if (md > dd && md + nd > dd) return out;
  const double nn = dot(n, n), mn = dot(m, n);
  const double a = dd * nn - nd * nd;
  const double k = dot(m, m) - cyl.r * cyl.r;
  const double c = dd * k - md * md;
  double t = 0;
  const Vec3 u = (1.0 / std::sqrt(dd)) * d;
  int feature = 1;
  if (std::fabs(a) < 1e-6) {
    if (c > 0) return out;
    if (md < 0) { t = -mn / nn; feature = 2; }
    else if (md > dd) { t = (nd - mn) / nn; feature = 3; }
    else t = 0;
  } else {
    const double b = dd * mn - nd * md;
    const double discr = b * b - a * c;
    if (discr < 0) return out;
    t = (-b - std::sqrt(discr)) / a;
    if (t < 0 || t > 1) return out;
    if (md + t * nd < 0) {
      if (nd <= 0) return out;
      t = -md / nd;
      if (!(k + 2 * t * (mn + t * nn) <= 0)) return out;
      feature = 2;
    } else if (md + t * nd > dd) {
      if (nd >= 0) return out;
      t = (dd - md) / nd;
      if (!(k + dd - 2 * md + t * (2 * (mn - nd) + t * nn) <= 0)) return out;
      feature = 3;
    }
  }
  if (!(t >= 0 && t <= 1)) return out;
  out.hit = true;
  out.t = t;
  out.point = seg.a + t * n;
  if (t == 0 && feature == 1) {
    out.starts_inside = true;
    return out;
  }
  if (feature == 2) out.normal = -u;
  else if (feature == 3) out.normal = u;
  else {
    const Vec3 x = m + t * n;
    const Vec3 radial = x - dot(x, u) * u;
    const double l = length(radial);
    out.normal = l > 0 ? (1.0 / l) * radial : any_perpendicular(u);
  }
  return out;
}

const CylinderSphereImpl kCapsuleForCylinder = {"sphere-vs-capsule", capsule_overlap, capsule_collide};
const CastSegmentCylinderImpl kInfiniteCylinder = {"infinite-cylinder-no-caps", infinite_cylinder_cast};
const CastSegmentCylinderImpl kEricsonPrinted = {"ericson-as-printed", ericson_printed_cast};

namespace {
// Closest points of segments p1q1 and p2q2 (Ericson, ClosestPtSegmentSegment).
void closest_segments(Vec3 p1, Vec3 q1, Vec3 p2, Vec3 q2, Vec3& c1, Vec3& c2) {
  const Vec3 d1 = q1 - p1, d2 = q2 - p2, r = p1 - p2;
  const double a = dot(d1, d1), e = dot(d2, d2), f = dot(d2, r);
  double s = 0, t = 0;
  if (a == 0 && e == 0) {
  } else if (a == 0) {
    t = std::clamp(f / e, 0.0, 1.0);
  } else {
    const double c = dot(d1, r);
    if (e == 0) {
      s = std::clamp(-c / a, 0.0, 1.0);
    } else {
      const double b = dot(d1, d2), denom = a * e - b * b;
      s = denom != 0 ? std::clamp((b * f - c * e) / denom, 0.0, 1.0) : 0.0;
      t = (b * s + f) / e;
      if (t < 0) t = 0, s = std::clamp(-c / a, 0.0, 1.0);
      else if (t > 1) t = 1, s = std::clamp((b - c) / a, 0.0, 1.0);
    }
  }
  c1 = p1 + s * d1;
  c2 = p2 + t * d2;
}

bool capsule_capsule_overlap(const Cylinder& c, const Capsule& k) {
  if (!is_valid(c) || !is_valid(k)) return false;
  Vec3 a, b;
  closest_segments(c.p, c.q, k.p, k.q, a, b);
  const double r = c.r + k.r;
  return length2(b - a) <= r * r;
}
Contact capsule_capsule_collide(const Cylinder& c, const Capsule& k) {
  if (!capsule_capsule_overlap(c, k)) return {};
  Vec3 a, b;
  closest_segments(c.p, c.q, k.p, k.q, a, b);
  return rounded_contact(a, b, c.r, k.r, c.q - c.p);
}
}  // namespace

const CylinderCapsuleImpl kCapsuleCapsule = {"capsule-capsule", capsule_capsule_overlap, capsule_capsule_collide};
const SweepSphereCylinderImpl kSweepNoCornerStage = {
    "sweep-without-corner-stage", [](const MovingSphere& m, const Cylinder& c) {
      return detail::sweep_with(Sphere{m.c, m.r}, m.delta, c, detail::SweepStage2::None);
    }};
const SweepSphereCylinderImpl kSweepTalkRimPoint = {
    "sweep-talk-one-rim-point", [](const MovingSphere& m, const Cylinder& c) {
      return detail::sweep_with(Sphere{m.c, m.r}, m.delta, c, detail::SweepStage2::TalkRimPoint);
    }};

namespace {
/// overlap() of the cylinder against B with the cap stage `stage`
/// (detail::overlap_with_stage).
template <class B, auto stage>
bool overlap_with(const Cylinder& c, const B& b) {
  return detail::overlap_with_stage(c, b, stage);
}
/// collide() of the cylinder against B with the cap stage `stage`
/// (detail::collide_with_stage).
template <class B, auto stage>
Contact collide_with(const Cylinder& c, const B& b) {
  return detail::collide_with_stage(c, b, stage);
}
/// collide() of the cylinder against B without the circle search
/// (detail::collide_consistent).
template <class B>
Contact collide_without_circle_search(const Cylinder& c, const B& b) {
  return detail::collide_consistent(c, b, false);
}
/// Production's overlap() of the cylinder against B.
template <class B>
bool production_overlap(const Cylinder& c, const B& b) {
  return overlap(c, b);
}
}  // namespace

const CylinderObbImpl kBoxAsCapsule = {"box-as-capsule", &overlap_with<Obb, detail::ObbCapStage::Capsule>,
                                       &collide_with<Obb, detail::ObbCapStage::Capsule>};
const CylinderObbImpl kBoxTalkRays = {"box-talk-rays", &overlap_with<Obb, detail::ObbCapStage::TalkRays>,
                                      &collide_with<Obb, detail::ObbCapStage::TalkRays>};

const CylinderObbImpl kBoxNoCircleSearch = {"box-without-circle-search", &production_overlap<Obb>,
                                            &collide_without_circle_search<Obb>};

const CylinderTriangleImpl kTriangleNoCapStage = {"triangle-without-cap-stage",
                                                  &overlap_with<Triangle, detail::TriCapStage::None>,
                                                  &collide_with<Triangle, detail::TriCapStage::None>};

const CylinderTriangleImpl kTriangleNoCircleSearch = {"triangle-without-circle-search", &production_overlap<Triangle>,
                                                      &collide_without_circle_search<Triangle>};

namespace {
detail::CylinderPairOptions without(int part) {
  detail::CylinderPairOptions o;
  if (part == 0) o.false_positive_planes = false;
  if (part == 1) o.parallel_branch = false;
  if (part == 2) o.accurate_frame = false;
  if (part == 3) o.newton_steps = 1, o.relative_stop = false, o.rim_steps = 0;
  return o;
}
/// overlap() of the cylinder pair with the part `without(part)` removed.
template <int part>
bool pair_overlap_without(const Cylinder& a, const Cylinder& b) {
  return detail::cylinder_pair(a, b, false, without(part)).hit;
}
/// collide() of the cylinder pair with the part `without(part)` removed.
template <int part>
Contact pair_collide_without(const Cylinder& a, const Cylinder& b) {
  return detail::cylinder_pair(a, b, true, without(part));
}
}  // namespace

const CylinderCylinderImpl kCylinderNoPlanes = {"cylinder-pair-without-false-positive-planes",
                                                &pair_overlap_without<0>, &pair_collide_without<0>};

const CylinderCylinderImpl kCylinderNoParallelBranch = {"cylinder-pair-without-parallel-branch",
                                                        &pair_overlap_without<1>, &pair_collide_without<1>};

const CylinderCylinderImpl kCylinderPlainFrame = {"cylinder-pair-plain-frame", &pair_overlap_without<2>,
                                                  &pair_collide_without<2>};

const CylinderCylinderImpl kCylinderShortSearch = {"cylinder-pair-short-search", &pair_overlap_without<3>,
                                                   &pair_collide_without<3>};

}  // namespace geomcheck::teeth
