// geomcheck — the body shared by every query's libFuzzer target, and the
// fuzz door for anyone's subject (verify.hpp's subject()):
//
//   extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
//     return geomcheck::fuzz::run_one<geomcheck::QueryId::collide_cylinder_sphere>(data, size, mine);
//   }
//
// (compiled by clang with -fsanitize=fuzzer; the package's target
// geomcheck::fuzzing).
//
// Inputs decode with fuzz_decode.hpp. Raw mode checks robustness
// (check_robust: no crash, no UB, invalid input gives no hit, finite output,
// unit normals); structured mode runs every property against the exact
// oracle (check_all). A failure prints the property and the case file and
// aborts, so libFuzzer keeps the input; `geomcheck from-fuzz QUERY CRASH`
// turns it into a case file.
//
// A subject is asked only what it claims to handle: raw inputs only when
// its claims say any input (Claims::any_input; production's do), and of the
// structured inputs only the valid cases it states (subject_states: its
// expresses() and its precision's range of scales). The others are skipped,
// so libFuzzer's first, empty input does not end the run. To include raw
// inputs, claim them: `claims.any_input = true`.
#pragma once

#include <cstdio>
#include <cstdlib>

#include "geomcheck/fuzz_decode.hpp"
#include "geomcheck/properties/checks.hpp"

namespace geomcheck::fuzz {

template <QueryId Q>
[[noreturn]] void report(const typename QueryTraits<Q>::Case& c, const Failure& f, const char* mode) {
  const CaseFile cf = from_case<Q>(c, std::string("fuzz mode=") + mode, "", f.property + ": " + f.detail);
  std::fprintf(stderr, "\n==== geomcheck %s property failed: %s\n%s\n---- case file:\n%s====\n", info(Q).name,
               f.property.c_str(), f.detail.c_str(), write_case(cf).c_str());
  std::abort();
}

/// One input: raw mode checks robustness, structured mode every property,
/// of `impl`: production by default; the teeth targets pass a known-wrong
/// variant (test-only binaries, see fuzz/CMakeLists.txt), a user their own
/// subject.
template <QueryId Q>
int run_one(const std::uint8_t* data, std::size_t size, const ImplOf<Q>& impl = production_of<Q>()) {
  const auto c = decode<Q>(data, size);
  if (mode_of(data, size) == Mode::Raw) {
    if (impl.claims && !impl.claims->any_input) return 0;  // raw inputs not claimed
    if (impl.expresses && !subject_states(c, impl)) return 0;
    if (auto f = check_robust(c, impl)) report<Q>(c, *f, "raw");
    return 0;
  }
  if (!is_valid(c.a) || !is_valid(c.b) || !subject_states(c, impl)) return 0;
  if (auto f = check_all(c, impl)) report<Q>(c, *f, "structured");
  return 0;
}

}  // namespace geomcheck::fuzz
