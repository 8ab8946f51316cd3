// geomcheck — a fixed stream of collide(Cylinder, Triangle) calls (random
// triangles of size about 1 near a random cylinder, about a third of them
// overlapping), for counting instructions per call under callgrind and for
// checking that a change leaves every answer as it was (the printed sum).
// Built with -DGEOMCHECK_MEASURE=ON (the release preset): build/release/bench/measure/triangle_calls.
//   valgrind --tool=callgrind ./triangle_calls   (instructions / 20000 = per call)
#include <cstdio>
#include <random>

#include "geomcheck/collide_cylinder_triangle.hpp"
using namespace geomcheck;

int main() {
  std::mt19937_64 g(7);
  std::uniform_real_distribution<double> U(-1, 1);
  double sink = 0;
  int hits = 0;
  for (int i = 0; i < 20000; ++i) {
    const Cylinder c{{U(g), U(g), U(g)}, {U(g) + 1, U(g), U(g)}, 0.5 + 0.3 * U(g)};
    const Vec3 m{U(g) * 0.8, U(g) * 0.8, U(g) * 0.8};
    auto vertex = [&] { return Vec3{m[0] + U(g), m[1] + U(g), m[2] + U(g)}; };
    const Vec3 a = vertex(), b = vertex(), d = vertex();
    const Contact k = collide(c, Triangle{a, b, d});
    if (k.hit) ++hits, sink += k.depth + k.normal[0];
  }
  std::printf("%d hits of 20000, sum of depth + normal.x %.17g\n", hits, sink);
}
