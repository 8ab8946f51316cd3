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

// The ball touches the cylinder at t: contact point and outward normal from
// the ball centre x = c(t) (outside the cylinder, or on its surface).
CastHit contact_at(const Cylinder& cyl, const AxisFrame& f, Vec3 x, double t, double noise) {
  CastHit out;
  const ClosestOnCylinder k = closest_on_cylinder(cyl, f, x, noise);
  out.hit = true;
  out.t = t;
  out.point = k.point;
  // A centre on the surface by rounding (the ball of radius 0): the normal
  // of the face it is farther out of, as closest_on_cylinder picks it, or
  // the cap normal when it is inside by rounding.
  out.normal = k.inside ? (dot(x - f.mid, f.u) >= 0 ? f.u : -f.u) : k.normal;
  return out;
}

// The talk's stage 2: clamp the stage-1 point to the cylinder's radius and
// axial extent (the rim point R) and sweep the ball's centre against the
// ball of radius s around R. A hit is a contact at R.
CastHit talk_rim_point(const Sphere& s, Vec3 delta, const Cylinder& cyl, const AxisFrame& f, double t1, double noise) {
  CastHit out;
  const Vec3 x1 = s.c + t1 * delta;
  const Vec3 v = x1 - f.mid;
  const double ax = std::clamp(dot(v, f.u), -f.half, f.half);
  const Vec3 w = v - dot(v, f.u) * f.u;
  const double rho = safe_length(w);
  const Vec3 rim = f.mid + ax * f.u + (rho > cyl.r ? (cyl.r / rho) * w : w);
  // |s.c - rim + t delta|^2 = s^2: first root in [0, 1].
  const Vec3 m = s.c - rim;
  const double a = dot(delta, delta), b = dot(m, delta), c = dot(m, m) - s.r * s.r;
  if (c <= 0) return contact_at(cyl, f, s.c, 0.0, noise);
  if (a == 0 || b >= 0) return out;
  const double disc = b * b - a * c;
  if (disc < 0) return out;
  const double t = c / (-b + std::sqrt(disc));
  if (t > 1) return out;
  out.hit = true;
  out.t = t;
  out.point = rim;
  out.normal = normalized(s.c + t * delta - rim);
  return out;
}

// Production's stage 2: g(t) = dist(c(t), C) - s is convex (the distance
// from a point moving on a line to a convex set), so Newton steps from the
// left of its first root stay on the left and converge to it; each step is
// the talk's rim-point idea linearised: the rim point (closest cylinder
// point) of the current position and the plane tangent to the ball there.
CastHit newton_stage(const Sphere& s, Vec3 delta, const Cylinder& cyl, const AxisFrame& f, double t, double noise,
                     double scene) {
  CastHit out;
  const double du = dot(delta, f.u);
  const Vec3 dperp = delta - du * f.u;
  // Stop once the ball is within a few roundings of the scene of touching.
  const double close = 0x1p-50 * scene;
  for (int it = 0; it < 100; ++it) {
    const Vec3 x = s.c + t * delta;
    const Vec3 v = x - f.mid;
    const double ax = dot(v, f.u);
    const Vec3 w = v - ax * f.u;
    const double rho = safe_length(w);
    const double ea = std::max(std::fabs(ax) - f.half, 0.0);
    const double er = std::max(rho - cyl.r, 0.0);
    const double dist = safe_length(Vec3{ea, er, 0});
    const double g = dist - s.r;
    if (g <= close) return contact_at(cyl, f, x, t, noise);
    // g'(t): the rate at which the distance shrinks along delta.
    const double dea = ea > 0 ? (ax >= 0 ? du : -du) : 0.0;
    const double der = er > 0 && rho > 0 ? dot(w, dperp) / rho : 0.0;
    const double slope = (ea * dea + er * der) / dist;
    if (!(slope < 0)) return out;  // convex, positive and not decreasing: never touches
    const double next = t - g / slope;
    if (next > 1) return out;
    if (!(next > t)) return contact_at(cyl, f, x, t, noise);  // no progress left: at the root to rounding
    t = next;
  }
  return contact_at(cyl, f, s.c + t * delta, t, noise);
}

CastHit sweep_scaled(const Sphere& s, Vec3 delta, const Cylinder& cyl, SweepStage2 stage2) {
  CastHit out;
  if (!is_valid(cyl)) return out;  // an axis far below the scene's magnitude vanishes
  const AxisFrame f(cyl);
  const double scene = std::max({max_abs(s.c), max_abs(s.c + delta), s.r, largest(cyl)});
  const double noise = 16 * 0x1p-52 * std::max(scene, f.half);
  // Already touching at t = 0: the sphere query's own predicate.
  if (overlap(cyl, s)) {
    out.hit = true;
    out.starts_inside = true;
    out.point = collide(cyl, s).point;
    return out;
  }
  // Stage 1: the centre's segment against the augmented cylinder (radius
  // r + s, axis extended by s at both ends).
  const UnitAndLength axis(cyl.q - cyl.p);
  const TubeInterval iv = tube_interval(s.c - cyl.p, delta, axis.u, axis.len, s.r, cyl.r + s.r);
  if (iv.empty || iv.entry > 1 || iv.exit < 0) return out;
  const double t1 = std::max(iv.entry, 0.0);
  const Vec3 x1 = s.c + t1 * delta;
  // Corner region: beyond a cap plane by the axial offset from the mid
  // point, and outside the radius.
  const Vec3 v = x1 - f.mid;
  const double ax = dot(v, f.u);
  const double rho = safe_length(v - ax * f.u);
  const bool corner = std::fabs(ax) > f.half && rho > cyl.r;
  if (stage2 == SweepStage2::None || (!corner && iv.entry > 0)) {
    // A face of the augmented cylinder: the ball touches the side or a cap.
    out.hit = true;
    out.t = t1;
    const Vec3 w = v - ax * f.u;
    if (iv.side_entry || !(std::fabs(ax) > f.half)) {
      out.normal = unit_perpendicular_part(v, f.u);
      out.point = f.mid + std::clamp(ax, -f.half, f.half) * f.u + cyl.r * out.normal;
    } else {
      out.normal = ax >= 0 ? f.u : -f.u;
      out.point = f.mid + (ax >= 0 ? f.half : -f.half) * f.u + (rho > cyl.r ? cyl.r / rho : 1.0) * w;
    }
    if (iv.entry <= 0) out = contact_at(cyl, f, x1, t1, noise);
    return out;
  }
  if (stage2 == SweepStage2::TalkRimPoint) return talk_rim_point(s, delta, cyl, f, t1, noise);
  return newton_stage(s, delta, cyl, f, t1, noise, scene);
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
