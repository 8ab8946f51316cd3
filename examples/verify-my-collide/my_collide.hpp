// The user's own code: its vector and shape types, a sphere-vs-cylinder
// collide in single precision, and the adapter that lets geomcheck call it.
// It has one deliberate bug (a ball whose centre is inside the cylinder gets
// a contact point on the nearest face, outside a ball smaller than that
// face's distance): built with -DMY_COLLIDE_FIXED it is fixed, and the run
// passes.
#pragma once

#include <algorithm>
#include <cmath>

#include <geomcheck/verify.hpp>

struct V3 { float x, y, z; };
inline V3 operator+(V3 a, V3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline V3 operator-(V3 a, V3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline V3 operator*(float s, V3 a) { return {s * a.x, s * a.y, s * a.z}; }
inline float dot(V3 a, V3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline float norm(V3 a) { return std::sqrt(dot(a, a)); }
inline V3 unit(V3 a) { return (1 / norm(a)) * a; }
struct MyCylinder { V3 p, q; float r; };
struct MyBall { V3 c; float r; };
struct MyContact { bool hit = false; V3 normal{}, point{}; float depth = 0; };

// Contact from the cylinder towards the ball; depth = how far they overlap.
inline MyContact my_collide(const MyCylinder& cy, const MyBall& b) {
  const V3 d = cy.q - cy.p, u = unit(d), w = b.c - cy.p;
  const float len = norm(d), t = dot(w, u);
  // The part of w across the axis, projected out along d itself (u is unit
  // only to rounding), twice; at the rounding level of w it is noise in any
  // direction: then the centre is on the axis.
  const float dd = dot(d, d);
  V3 radial = w - (dot(w, d) / dd) * d;
  radial = radial - (dot(radial, d) / dd) * d;
  const float big = std::max({std::fabs(w.x), std::fabs(w.y), std::fabs(w.z)});
  const float rho = norm(radial) > 16 * 0x1p-24f * big ? norm(radial) : 0.f;
  const V3 e = rho > 0 ? (1 / rho) * radial : unit(std::fabs(u.x) < 0.5f ? V3{0, u.z, -u.y} : V3{-u.z, 0, u.x});
  MyContact out;
  if (!(t >= 0 && t <= len && rho <= cy.r)) {  // centre outside: the closest point of the cylinder
    // The offset to it in the frame (u, e): the normal stays in the normal cone of the closest feature.
    const V3 off = (t < 0 ? t : std::max(t - len, 0.f)) * u + std::max(rho - cy.r, 0.f) * e;
    const float dist = norm(off);
    if (dist > b.r) return out;
    out.hit = true;
    if (dist > 0) {
      out.normal = (1 / dist) * off;
      out.depth = b.r - dist;
      out.point = cy.p + std::min(std::max(t, 0.f), len) * u + std::min(rho, cy.r) * e;
      return out;
    }
  }
  // Centre inside (or on the surface): out through the nearest face.
  const float side = cy.r - rho, bottom = t, top = len - t;
  const float m = std::max(0.f, std::min(side, std::min(bottom, top)));
  out.hit = true;
  out.normal = m == side ? e : (m == bottom ? -1.f * u : u);
  out.depth = m + b.r;
#ifdef MY_COLLIDE_FIXED
  out.point = b.c;  // in both: the centre is in the cylinder and in the ball
#else
  out.point = b.c + m * out.normal;  // the bug: on the nearest face, outside the ball when m > b.r
#endif
  return out;
}

// The adapter: geomcheck's shapes in, geomcheck's contact out; the claims:
// production's, computed in single precision, for valid scenes only.
inline auto my_subject() {
  using namespace geomcheck;
  auto mine = [](Vec3 v) { return V3{float(v.x), float(v.y), float(v.z)}; };
  auto collide = [mine](const Cylinder& c, const Sphere& s) {
    const MyContact k = my_collide({mine(c.p), mine(c.q), float(c.r)}, {mine(s.c), float(s.r)});
    return Contact{k.hit, {k.point.x, k.point.y, k.point.z}, {k.normal.x, k.normal.y, k.normal.z}, k.depth};
  };
  auto overlap = [collide](const Cylinder& c, const Sphere& s) { return collide(c, s).hit; };
  Claims claims = production_claims<QueryId::collide_cylinder_sphere>();
  claims.precision = Precision::single_precision();  // float: bounds from float's unit roundoff, scales in [2^-60, 2^60]
  claims.any_input = false;                          // no NaN, infinities or negative radii
  return subject<QueryId::collide_cylinder_sphere>("my-float-collide", overlap, collide, claims);
}
