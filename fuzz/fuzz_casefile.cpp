// geomcheck — libFuzzer target for the case-file parser: any text is either
// rejected with a "line N: ..." message or parsed into a case that writes
// back and re-parses to the same case, bit for bit.
#include <cstdio>
#include <cstdlib>
#include <string_view>

#include "geomcheck/casefile.hpp"
#include "geomcheck/detail/text_format.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const geomcheck::ParseResult r = geomcheck::parse_case(text);
  if (const auto broken = geomcheck::detail::broken_round_trip(r, &geomcheck::parse_case, &geomcheck::write_case)) {
    std::fputs(broken->c_str(), stderr);
    std::abort();
  }
  return 0;
}
