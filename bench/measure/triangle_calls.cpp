// geomcheck — a fixed stream of cylinder/triangle calls (random triangles of
// size about 1 near a random cylinder, about a third of them overlapping),
// for counting instructions per call under callgrind and for checking that
// a change leaves every answer as it was (the printed sum).
// Built with -DGEOMCHECK_MEASURE=ON (the release preset): build/release/bench/measure/triangle_calls.
//   valgrind --tool=callgrind ./triangle_calls [collide|penetration|overlap|none]
// The query called is collide (default), penetration or overlap; `none`
// draws the same stream without a call, so that (instructions - none's) /
// 20000 is the query's own cost per call.
#include <cstdio>
#include <cstring>
#include <random>

#include "geomcheck/collide_cylinder_triangle.hpp"
#include "geomcheck/penetration_cylinder_triangle.hpp"
using namespace geomcheck;

int main(int argc, char** argv) {
  const char* what = argc > 1 ? argv[1] : "collide";
  const int mode = !std::strcmp(what, "collide") ? 0 : !std::strcmp(what, "penetration") ? 1
                 : !std::strcmp(what, "overlap") ? 2 : !std::strcmp(what, "none") ? 3 : -1;
  if (mode < 0) {
    std::fprintf(stderr, "usage: triangle_calls [collide|penetration|overlap|none]\n");
    return 2;
  }
  std::mt19937_64 g(7);
  std::uniform_real_distribution<double> U(-1, 1);
  double sink = 0;
  int hits = 0;
  for (int i = 0; i < 20000; ++i) {
    const Cylinder c{{U(g), U(g), U(g)}, {U(g) + 1, U(g), U(g)}, 0.5 + 0.3 * U(g)};
    const Vec3 m{U(g) * 0.8, U(g) * 0.8, U(g) * 0.8};
    auto vertex = [&] { return Vec3{m[0] + U(g), m[1] + U(g), m[2] + U(g)}; };
    const Vec3 a = vertex(), b = vertex(), d = vertex();
    const Triangle t{a, b, d};
    if (mode == 2) {
      hits += overlap(c, t);
      continue;
    }
    if (mode == 3) continue;
    const Contact k = mode == 0 ? collide(c, t) : penetration(c, t);
    if (k.hit) ++hits, sink += k.depth + k.normal[0];
  }
  std::printf("%s: %d hits of 20000, sum of depth + normal.x %.17g\n", what, hits, sink);
}
