// geomcheck — turns the seed case files into libFuzzer seed inputs:
// corpora/seeds/<query>/*.case -> OUT/<query>/<name> (both fuzz modes), and
// every case file as-is into OUT/casefile/.
#include <filesystem>
#include <fstream>
#include <iostream>

#include "geomcheck/casefile.hpp"
#include "geomcheck/fuzz_decode.hpp"

namespace fs = std::filesystem;

int main(int argc, char** argv) {
  if (argc != 3) {
    std::cerr << "usage: make_fuzz_seeds CORPORA_SEEDS_DIR OUT_DIR\n";
    return 2;
  }
  const fs::path in(argv[1]), out(argv[2]);
  int n = 0;
  for (const auto& q : geomcheck::kQueries) fs::create_directories(out / q.name);
  fs::create_directories(out / "casefile");
  for (const auto& e : fs::recursive_directory_iterator(in)) {
    if (!e.is_regular_file() || e.path().extension() != geomcheck::kCaseFileExtension) continue;
    fs::copy_file(e.path(), out / "casefile" / e.path().filename(), fs::copy_options::overwrite_existing);
    const auto r = geomcheck::load_case(e.path());
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
