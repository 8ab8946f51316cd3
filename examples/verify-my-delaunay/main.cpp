// Holds mine::triangulate (my_delaunay.hpp) to every property of
// delaunay_2d; failing point sets are shrunk, saved, drawn and replayable:
//   verify_my_delaunay [--cases N] [--seed N] [--out DIR] [--replay FILE]
#include <geomcheck/verify.hpp>

#include "my_delaunay.hpp"

int main(int argc, char** argv) {
  // The adapter: geomcheck's points into the user's own, triangles back.
  auto mine = geomcheck::subject<geomcheck::PointSetQueryId::delaunay_2d>(
      "my-delaunay", [](const std::vector<geomcheck::Vec2>& points) {
        std::vector<mine::P> p;
        for (const geomcheck::Vec2& v : points) p.push_back({v.x, v.y});
        return mine::triangulate(p);
      });
  return geomcheck::verify(mine, argc, argv);
}
