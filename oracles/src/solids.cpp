#include "geomcheck/oracles/solids.hpp"

#include <cmath>
#include <limits>

#include "geomcheck/oracles/cylinder_sphere.hpp"

namespace geomcheck::oracle {

QInterval signed_distance(const QCylinder& cyl, const QVec& x) {
  return solve_cylinder_sphere(cyl, QSphere{x, Q(0)}).signed_distance;
}

QInterval signed_distance(const QSphere& s, const QVec& x) {
  const QVec v = x - s.c;
  return sqrt_interval(dot(v, v)) - point(s.r);
}

QInterval support(const QCylinder& cyl, const QVec& n) {
  const QVec d = cyl.q - cyl.p;
  const Q np = dot(n, cyl.p), nq = dot(n, cyl.q);
  const QVec nxd = cross(n, d);
  // r |n_perp| = r |n x d| / |d|
  const QInterval disk = point(cyl.r) * sqrt_interval(dot(nxd, nxd) / dot(d, d));
  return point(np > nq ? np : nq) + disk;
}

QInterval support(const QSphere& s, const QVec& n) {
  return point(dot(n, s.c)) + point(s.r) * sqrt_interval(dot(n, n));
}

double extent(Vec3 a, Vec3 b) {
  // |b - a| without overflow (halves first), clamped to the largest double.
  const double e = 2 * length(0.5 * b - 0.5 * a);
  return std::isfinite(e) ? e : std::numeric_limits<double>::max();
}

double magnitude(const Cylinder& c) { return std::max({max_abs(c.p), max_abs(c.q), c.r, extent(c.p, c.q)}); }
double magnitude(const Capsule& c) { return std::max({max_abs(c.p), max_abs(c.q), c.r, extent(c.p, c.q)}); }
double magnitude(const Sphere& s) { return std::max(max_abs(s.c), s.r); }
double magnitude(const Segment& s) { return std::max(max_abs(s.a), max_abs(s.b)); }
double magnitude(const Obb& b) { return std::max(max_abs(b.c), max_abs(b.e)); }
double magnitude(const Triangle& t) { return std::max({max_abs(t.a), max_abs(t.b), max_abs(t.c)}); }
double magnitude(const MovingSphere& s) {
  const Vec3 end = s.c + s.delta;
  return std::max({max_abs(s.c), is_finite(end) ? max_abs(end) : 0.0, s.r});
}

}  // namespace geomcheck::oracle
