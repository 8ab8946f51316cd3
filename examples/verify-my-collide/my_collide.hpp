// The user's own code: its vector and shape types, a sphere-vs-cylinder
// collide in single precision, and the adapter that lets geomcheck call it.
#pragma once

#include <cmath>

#include <geomcheck/verify.hpp>

struct V3 { float x, y, z; };
inline V3 operator+(V3 a, V3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline V3 operator-(V3 a, V3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline V3 operator*(float s, V3 a) { return {s * a.x, s * a.y, s * a.z}; }
inline float dot(V3 a, V3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline V3 unit(V3 a) { return (1 / std::sqrt(dot(a, a))) * a; }
struct MyCylinder { V3 p, q; float r; };
struct MyBall { V3 c; float r; };
struct MyContact { bool hit = false; V3 normal{}, point{}; float depth = 0; };

// Contact from the cylinder towards the ball; depth = how far they overlap.
inline MyContact my_collide(const MyCylinder& cy, const MyBall& b) {
  const V3 d = cy.q - cy.p, u = unit(d), w = b.c - cy.p;
  const float len = std::sqrt(dot(d, d)), t = dot(w, u);
  const V3 radial = w - t * u;
  const float rho = std::sqrt(dot(radial, radial));
  const V3 e = rho > 0 ? (1 / rho) * radial : unit(std::fabs(u.x) < 0.5f ? V3{0, u.z, -u.y} : V3{-u.z, 0, u.x});
  MyContact out;
  if (t >= 0 && t <= len && rho <= cy.r) {  // centre inside: out through the nearest face
    const float side = cy.r - rho, bottom = t, top = len - t;
    const float m = std::fmin(side, std::fmin(bottom, top));
    out.normal = m == side ? e : (m == bottom ? -1.f * u : u);
    out.depth = m + b.r;
    out.point = b.c + m * out.normal;
  } else {  // centre outside: the closest point of the cylinder
    const V3 x = cy.p + std::fmin(std::fmax(t, 0.f), len) * u + std::fmin(rho, cy.r) * e;
    const float dist = std::sqrt(dot(b.c - x, b.c - x));
    if (dist > b.r) return out;
    out.normal = unit(b.c - x);
    out.depth = b.r - dist;
    out.point = x;
  }
  out.hit = true;
  return out;
}

// The adapter: geomcheck's shapes in, geomcheck's contact out.
inline auto my_subject() {
  using namespace geomcheck;
  auto mine = [](Vec3 v) { return V3{float(v.x), float(v.y), float(v.z)}; };
  auto collide = [mine](const Cylinder& c, const Sphere& s) {
    const MyContact k = my_collide({mine(c.p), mine(c.q), float(c.r)}, {mine(s.c), float(s.r)});
    return Contact{k.hit, {k.point.x, k.point.y, k.point.z}, {k.normal.x, k.normal.y, k.normal.z}, k.depth};
  };
  auto overlap = [collide](const Cylinder& c, const Sphere& s) { return collide(c, s).hit; };
  return subject<QueryId::collide_cylinder_sphere>("my-float-collide", overlap, collide);
}
