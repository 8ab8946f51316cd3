// geomcheck — libFuzzer target for the point-set file parser (the Delaunay
// query's case files): any text is either rejected with a "line N: ..."
// message or parsed into a point set that writes back and re-parses to the
// same point set, bit for bit.
#include <cstdio>
#include <cstdlib>
#include <string_view>

#include "geomcheck/pointset_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const geomcheck::PointSetParseResult r = geomcheck::parse_point_set(text);
  if (!r.ok()) {
    if (r.error.rfind("line ", 0) != 0 && r.error.find("too large") == std::string::npos &&
        r.error.find("empty") == std::string::npos) {
      std::fprintf(stderr, "parse error without a line number: %s\n", r.error.c_str());
      std::abort();
    }
    return 0;
  }
  const std::string written = geomcheck::write_point_set(r.value);
  const geomcheck::PointSetParseResult again = geomcheck::parse_point_set(written);
  if (!again.ok() || !(again.value == r.value)) {
    std::fprintf(stderr, "round trip failed: %s\n%s\n", again.error.c_str(), written.c_str());
    std::abort();
  }
  // The verdict of any parsed point set is one of the known words.
  const std::string_view verdict = geomcheck::classify_point_set(r.value.points);
  bool known = false;
  for (auto v : geomcheck::point_set_verdicts()) known = known || v == verdict;
  if (!known) {
    std::fprintf(stderr, "classify_point_set gave an unknown verdict\n");
    std::abort();
  }
  return 0;
}
