// A sphere-vs-cylinder collide written the plausible way (its own vector
// and shape types, single precision), held by geomcheck to every property
// of collide_cylinder_sphere. Failing cases are saved, drawn and replayable:
//   verify_my_collide [--cases N] [--seed N] [--out DIR] [--replay FILE]
#include <cmath>

#include <geomcheck/verify.hpp>

// --- the user's own code ----------------------------------------------------
struct V3 { float x, y, z; };
V3 operator+(V3 a, V3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
V3 operator-(V3 a, V3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
V3 operator*(float s, V3 a) { return {s * a.x, s * a.y, s * a.z}; }
float dot(V3 a, V3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
V3 unit(V3 a) { return (1 / std::sqrt(dot(a, a))) * a; }
struct MyCylinder { V3 p, q; float r; };
struct MyBall { V3 c; float r; };
struct MyContact { bool hit = false; V3 normal{}, point{}; float depth = 0; };

// Contact from the cylinder towards the ball; depth = how far they overlap.
MyContact my_collide(const MyCylinder& cy, const MyBall& b) {
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

// --- the adapter: geomcheck's shapes in, geomcheck's contact out ------------
V3 mine(geomcheck::Vec3 v) { return {float(v.x), float(v.y), float(v.z)}; }
geomcheck::Vec3 theirs(V3 v) { return {v.x, v.y, v.z}; }

int main(int argc, char** argv) {
  using namespace geomcheck;
  auto collide = [](const Cylinder& c, const Sphere& s) {
    const MyContact k = my_collide({mine(c.p), mine(c.q), float(c.r)}, {mine(s.c), float(s.r)});
    return Contact{k.hit, theirs(k.point), theirs(k.normal), k.depth};
  };
  auto overlap = [collide](const Cylinder& c, const Sphere& s) { return collide(c, s).hit; };
  return verify(subject<QueryId::collide_cylinder_sphere>("my-float-collide", overlap, collide), argc, argv);
}
