// geomcheck — a test-only libFuzzer target: collide_cylinder_sphere's
// checks run on a known-wrong variant (the sphere tested against the
// cylinder's capsule, teeth::kCapsuleForCylinder), so that it finds
// failures within seconds. It exercises the nightly job's pipeline (find,
// de-duplicate, minimise, convert, survive interruption) in
// fuzz/tests/test_nightly.sh; it is not a fuzz target of production and is
// not built by .clusterfuzzlite/build.sh.
#include "geomcheck/fuzz_query.hpp"
#include "geomcheck/properties/teeth.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return geomcheck::fuzz::run_one<geomcheck::QueryId::collide_cylinder_sphere>(data, size,
                                                                              geomcheck::teeth::kCapsuleForCylinder);
}
