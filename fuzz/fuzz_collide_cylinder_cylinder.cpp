// geomcheck — libFuzzer target for collide_cylinder_cylinder (see fuzz_query.hpp for the input layout).
#include "fuzz_query.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return geomcheck::fuzz::run_one<geomcheck::QueryId::collide_cylinder_cylinder>(data, size);
}
