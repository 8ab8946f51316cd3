// geomcheck — libFuzzer target for the mesh file parser (the mesh queries'
// case files): any text is either rejected with a "line N: ..." message or
// parsed into a case that writes back and re-parses to the same case, bit
// for bit.
#include "geomcheck/detail/text_format.hpp"
#include "geomcheck/mesh_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  geomcheck::detail::parse_or_abort(data, size, &geomcheck::parse_mesh_file, &geomcheck::write_mesh_file);
  return 0;
}
