// geomcheck — libFuzzer target for the case-file parser: any text is either
// rejected with a "line N: ..." message or parsed into a case that writes
// back and re-parses to the same case, bit for bit.
#include "geomcheck/casefile.hpp"
#include "geomcheck/detail/text_format.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  geomcheck::detail::parse_or_abort(data, size, &geomcheck::parse_case, &geomcheck::write_case);
  return 0;
}
