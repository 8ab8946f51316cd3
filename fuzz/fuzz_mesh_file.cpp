// geomcheck — libFuzzer target for the mesh file parser (the mesh queries'
// case files): any text is either rejected with a "line N: ..." message or
// parsed into a case that writes back and re-parses to the same case, bit
// for bit.
#include <cstdio>
#include <cstdlib>
#include <string_view>

#include "geomcheck/detail/text_format.hpp"
#include "geomcheck/mesh_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const geomcheck::MeshParseResult r = geomcheck::parse_mesh_file(text);
  if (const auto broken =
          geomcheck::detail::broken_round_trip(r, &geomcheck::parse_mesh_file, &geomcheck::write_mesh_file)) {
    std::fputs(broken->c_str(), stderr);
    std::abort();
  }
  return 0;
}
