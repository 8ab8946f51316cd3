// geomcheck — libFuzzer target for the case-file parser: any text is either
// rejected with a "line N: ..." message or parsed into a case that writes
// back and re-parses to the same case, bit for bit.
#include <cstdio>
#include <cstdlib>
#include <string_view>

#include "geomcheck/casefile.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const geomcheck::ParseResult r = geomcheck::parse_case(text);
  if (!r.ok()) {
    if (r.error.rfind("line ", 0) != 0 && r.error.find("too large") == std::string::npos &&
        r.error.find("empty") == std::string::npos) {
      std::fprintf(stderr, "parse error without a line number: %s\n", r.error.c_str());
      std::abort();
    }
    return 0;
  }
  const std::string written = geomcheck::write_case(r.value);
  const geomcheck::ParseResult again = geomcheck::parse_case(written);
  if (!again.ok() || !(again.value == r.value)) {
    std::fprintf(stderr, "round trip failed: %s\n%s\n", again.error.c_str(), written.c_str());
    std::abort();
  }
  return 0;
}
