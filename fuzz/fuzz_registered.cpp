// geomcheck — the libFuzzer target of a registered query, built once per query
// id with GEOMCHECK_FUZZ_QUERY=<id> (fuzz/CMakeLists.txt; input layout in fuzz_decode.hpp).
#include "geomcheck/fuzz_query.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return geomcheck::fuzz::run_one<geomcheck::QueryId::GEOMCHECK_FUZZ_QUERY>(data, size);
}
