// The same subject as a libFuzzer target (clang -fsanitize=fuzzer): a
// failing input aborts with its property and its case file.
#include <geomcheck/fuzz_query.hpp>

#include "my_collide.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const auto subject = my_subject();
  return geomcheck::fuzz::run_one<geomcheck::QueryId::collide_cylinder_sphere>(data, size, subject);
}
