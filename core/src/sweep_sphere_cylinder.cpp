#include "geomcheck/sweep_sphere_cylinder.hpp"

#include <algorithm>
#include <cmath>

#include "geomcheck/collide_cylinder_sphere.hpp"
#include "geomcheck/detail/frame.hpp"
#include "geomcheck/detail/segment_tube.hpp"
#include "geomcheck/detail/sweep_stages.hpp"

namespace geomcheck {

namespace detail {

namespace {

// The cylinder as the queries measure it: cap centre p, unit axis u, length.
struct Axis {
  Vec3 u;
  double len;
};

// The ball touches the cylinder with its centre at p + v (v measured from
// p): contact point and outward normal.
/// The outward normal of the face nearest to p + v (a cap, or the side):
/// for a centre on the surface to rounding, where the closest point's own
/// normal is a rounding toss-up.
Vec3 nearest_face_normal(const Cylinder& cyl, const Axis& a, Vec3 v) {
  const double ax = dot(v, a.u);
  const double rho = safe_length(v - ax * a.u);
  const double cap_gap = std::min(std::fabs(ax), std::fabs(ax - a.len));
  const double side_gap = std::fabs(cyl.r - rho);
  return cap_gap <= side_gap ? (2 * ax >= a.len ? a.u : -a.u) : unit_perpendicular_part(v, a.u);
}

CastHit contact_at(const Cylinder& cyl, const Axis& a, Vec3 v, double t, double noise) {
  CastHit out;
  const ClosestOnCylinder k = closest_on_cylinder(cyl, a.u, a.len, v, noise);
  out.hit = true;
  out.t = t;
  out.point = k.point;
  // A centre on the surface by rounding (the ball of radius 0, inside by
  // rounding): the normal of the nearest face (not always a cap: a point
  // on the side, 1e-17 inside, has the side's normal).
  out.normal = k.inside ? nearest_face_normal(cyl, a, v) : k.normal;
  return out;
}

// The talk's stage 2: clamp the stage-1 point to the cylinder's radius and
// axial extent (the rim point R) and sweep the ball's centre against the
// ball of radius s around R. A hit is a contact at R.
CastHit talk_rim_point(const Sphere& s, Vec3 m0, Vec3 delta, const Cylinder& cyl, const Axis& a, double t1,
                       double noise) {
  CastHit out;
  const Vec3 v1 = m0 + t1 * delta;
  const double ax = dot(v1, a.u);
  const Vec3 w = v1 - ax * a.u;
  const double rho = safe_length(w);
  const Vec3 rim = std::clamp(ax, 0.0, a.len) * a.u + (rho > cyl.r ? (cyl.r / rho) * w : w);
  // |m0 - rim + t delta|^2 = s^2: first root in [0, 1].
  const Vec3 m = m0 - rim;
  const double qa = dot(delta, delta), qb = dot(m, delta), qc = dot(m, m) - s.r * s.r;
  if (qc <= 0) return contact_at(cyl, a, m0, 0.0, noise);
  double t;
  if (qa == 0 || !entry_root(qa, qb, qc, t)) return out;
  out.hit = true;
  out.t = t;
  out.point = cyl.p + rim;
  out.normal = normalized(m + t * delta);
  return out;
}

// Production's stage 2: g(t) = dist(c(t), C) - s is convex (the distance
// from a point moving on a line to a convex set), so Newton steps from the
// left of its first root stay on the left and converge to it; each step is
// the talk's rim-point idea linearised: the rim point (closest cylinder
// point) of the current position and the plane tangent to the ball there.
CastHit newton_stage(const Sphere& s, Vec3 m0, Vec3 delta, const Cylinder& cyl, const Axis& a, double t, double noise,
                     double scene) {
  CastHit out;
  const double du = dot(delta, a.u);
  const Vec3 dperp = delta - du * a.u;
  // Stop once the ball is within a few roundings of the scene of touching.
  const double close = 0x1p-50 * scene;
  for (int it = 0; it < 100; ++it) {
    const Vec3 v = m0 + t * delta;
    const double ax = dot(v, a.u);
    const Vec3 w = v - ax * a.u;
    const double rho = safe_length(w);
    const double ea = ax < 0 ? -ax : (ax > a.len ? ax - a.len : 0.0);
    const double er = std::max(rho - cyl.r, 0.0);
    const double dist = safe_length(Vec3{ea, er, 0});
    const double g = dist - s.r;
    if (g <= close) return contact_at(cyl, a, v, t, noise);
    // g'(t): the rate at which the distance shrinks along delta.
    const double dea = ax < 0 ? -du : (ax > a.len ? du : 0.0);
    const double der = er > 0 && rho > 0 ? dot(w, dperp) / rho : 0.0;
    const double slope = (ea * dea + er * der) / dist;
    if (!(slope < 0)) return out;  // convex, positive and not decreasing: never touches
    const double next = t - g / slope;
    if (next > 1) return out;
    if (!(next > t)) return contact_at(cyl, a, v, t, noise);  // no progress left: at the root to rounding
    t = next;
  }
  return contact_at(cyl, a, m0 + t * delta, t, noise);
}

CastHit sweep_scaled(const Sphere& s, Vec3 delta, const Cylinder& cyl, SweepStage2 stage2) {
  CastHit out;
  if (!is_valid(cyl)) return out;  // an axis far below the scene's magnitude vanishes
  const UnitAndLength ul(cyl.q - cyl.p);
  const Axis a{ul.u, ul.len};
  const double scene = std::max({max_abs(s.c), max_abs(s.c + delta), s.r, largest(cyl)});
  const double noise = 16 * 0x1p-52 * std::max(scene, a.len);
  // Already touching at t = 0: the sphere query's own predicate.
  if (overlap(cyl, s)) {
    out.hit = true;
    out.starts_inside = true;
    out.point = collide(cyl, s).point;
    return out;
  }
  // Everything from here is measured from the cap centre p: a scene far
  // from the origin adds no rounding of its own.
  const Vec3 m0 = s.c - cyl.p;
  // Stage 1: the centre's segment against the augmented cylinder (radius
  // r + s, axis extended by s at both ends).
  const TubeInterval iv = tube_interval(m0, delta, a.u, a.len, s.r, cyl.r + s.r);
  if (iv.empty || iv.entry > 1 || iv.exit < 0) return out;
  const double t1 = std::max(iv.entry, 0.0);
  const Vec3 v1 = m0 + t1 * delta;
  // Corner region: beyond a cap plane (the axial offset) and outside the radius.
  const double ax = dot(v1, a.u);
  const Vec3 w = v1 - ax * a.u;
  const double rho = safe_length(w);
  const bool beyond = ax < 0 || ax > a.len;
  const bool corner = beyond && rho > cyl.r;
  if (stage2 == SweepStage2::None || (!corner && iv.entry > 0)) {
    // A face of the augmented cylinder: the ball touches the side or a cap.
    // The contact is the cylinder point closest to the centre (no side/cap
    // decision of its own: near a rim the stage-1 feature is a rounding
    // toss-up); the feature gives the normal only where the centre is on
    // the surface to rounding (a ball of radius 0).
    if (iv.entry <= 0) return contact_at(cyl, a, v1, t1, noise);
    const ClosestOnCylinder k = closest_on_cylinder(cyl, a.u, a.len, v1, noise);
    out.hit = true;
    out.t = t1;
    out.point = k.point;
    if (!k.inside && k.dist > noise) {
      out.normal = k.normal;
    } else {
      // The centre on the surface to rounding: the face it is nearest to
      // (the stage-1 side/cap flag is a rounding toss-up near a rim).
      out.normal = nearest_face_normal(cyl, a, v1);
    }
    return out;
  }
  if (stage2 == SweepStage2::TalkRimPoint) return talk_rim_point(s, m0, delta, cyl, a, t1, noise);
  return newton_stage(s, m0, delta, cyl, a, t1, noise, scene);
}

}  // namespace

CastHit sweep_with(const Sphere& s_in, Vec3 delta_in, const Cylinder& cyl_in, SweepStage2 stage2) {
  if (!is_valid(MovingSphere{s_in.c, s_in.r, delta_in}) || !is_valid(cyl_in)) return {};
  const SceneScale sc(std::max({largest(cyl_in), largest(s_in), max_abs(s_in.c + delta_in), max_abs(delta_in)}));
  CastHit out = sweep_scaled(sc.in(s_in), sc.in(delta_in), sc.in(cyl_in), stage2);
  out.point = sc.out(out.point);
  return out;
}

}  // namespace detail

CastHit sweep(const Sphere& s, Vec3 delta, const Cylinder& c) {
  return detail::sweep_with(s, delta, c, detail::SweepStage2::Newton);
}

}  // namespace geomcheck
