// geomcheck — libFuzzer target for the point-set file parser (the Delaunay
// query's case files): any text is either rejected with a "line N: ..."
// message or parsed into a point set that writes back and re-parses to the
// same point set, bit for bit.
#include <cstdio>
#include <cstdlib>
#include <string_view>

#include "geomcheck/detail/text_format.hpp"
#include "geomcheck/pointset_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const geomcheck::PointSetParseResult r =
      geomcheck::detail::parse_or_abort(data, size, &geomcheck::parse_point_set, &geomcheck::write_point_set);
  if (!r.ok()) return 0;
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
