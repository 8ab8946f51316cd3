// geomcheck — libFuzzer target for sweep_sphere_cylinder (see fuzz_query.hpp for the input layout).
#include "fuzz_query.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return geomcheck::fuzz::run_one<geomcheck::QueryId::sweep_sphere_cylinder>(data, size);
}
