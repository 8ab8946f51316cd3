// geomcheck — turns the seed case files into libFuzzer seed inputs:
// corpora/seeds/<query>/*.case -> OUT/<query>/<name> (both fuzz modes), the
// point sets of corpora/seeds/delaunay_2d/*.case -> OUT/delaunay_2d/<name>.raw
// (fuzz_input_from_point_set), the meshes of corpora/seeds/<mesh query>/*.case
// small enough for its fuzz target's raw mode -> OUT/<mesh query>/<name>.raw
// (fuzz_input_from_mesh), every case file as-is into OUT/casefile/, every
// point-set file as-is into OUT/pointset_file/ and every mesh file as-is
// into OUT/mesh_file/.
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include "geomcheck/casefile.hpp"
#include "geomcheck/fuzz_decode.hpp"
#include "geomcheck/mesh_file.hpp"
#include "geomcheck/pointset_file.hpp"

namespace fs = std::filesystem;

int main(int argc, char** argv) {
  if (argc != 3) {
    std::cerr << "usage: make_fuzz_seeds CORPORA_SEEDS_DIR OUT_DIR\n";
    return 2;
  }
  const fs::path in(argv[1]), out(argv[2]);
  int n = 0;
  for (const auto& q : geomcheck::kQueries) fs::create_directories(out / q.name);
  fs::create_directories(out / geomcheck::kDelaunayQueryName);
  fs::create_directories(out / "casefile");
  fs::create_directories(out / "pointset_file");
  fs::create_directories(out / "mesh_file");
  for (const auto& q : geomcheck::kAllQueries)
    if (q.family == geomcheck::QueryFamily::Mesh) fs::create_directories(out / q.name);
  for (const auto& e : fs::recursive_directory_iterator(in)) {
    if (!e.is_regular_file() || e.path().extension() != geomcheck::kCaseFileExtension) continue;
    fs::copy_file(e.path(), out / "casefile" / e.path().filename(), fs::copy_options::overwrite_existing);
    std::ifstream file(e.path(), std::ios::binary);
    std::ostringstream text;
    text << file.rdbuf();
    if (geomcheck::is_point_set_text(text.str())) {
      // The Delaunay query: the parser's seed, and the points as the raw
      // input of its fuzz target.
      fs::copy_file(e.path(), out / "pointset_file" / e.path().filename(), fs::copy_options::overwrite_existing);
      const auto r = geomcheck::parse_point_set(text.str());
      if (!r.ok()) continue;
      const std::string bytes = geomcheck::fuzz_input_from_point_set(r.value.points);
      std::ofstream f(out / geomcheck::kDelaunayQueryName / (e.path().stem().string() + ".raw"), std::ios::binary);
      f.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
      ++n;
      continue;
    }
    if (const auto m = geomcheck::parse_mesh_file(text.str()); m.ok()) {
      // A mesh query: the parser's seed, and (when small) the raw input of its fuzz target.
      fs::copy_file(e.path(), out / "mesh_file" / e.path().filename(), fs::copy_options::overwrite_existing);
      if (const auto bytes = geomcheck::fuzz_input_from_mesh(m.value)) {
        std::ofstream f(out / m.value.query / (e.path().stem().string() + ".raw"), std::ios::binary);
        f.write(bytes->data(), static_cast<std::streamsize>(bytes->size()));
      }
      ++n;
      continue;
    }
    const auto r = geomcheck::parse_case(text.str());
    if (!r.ok()) continue;  // malformed files are seeds for the parser only
    // The raw-mode input of the case, and the same bytes read in structured
    // mode (a different but valid starting point for the structured decoder).
    auto bytes = geomcheck::fuzz::raw_input(r.value);
    const fs::path dir = out / geomcheck::info(r.value.query).name;
    for (std::uint8_t mode : {std::uint8_t(0), std::uint8_t(1)}) {
      bytes[0] = mode;
      std::ofstream f(dir / (e.path().stem().string() + (mode ? ".structured" : ".raw")), std::ios::binary);
      f.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
    }
    ++n;
  }
  std::cout << "make_fuzz_seeds: " << n << " case files converted into " << out << "\n";
  return 0;
}
