#!/usr/bin/env bash
# geomcheck — the test command (README; .ci/run calls exactly this).
# Installs the Debian dependencies, builds the default preset and runs every
# ctest suite (properties with a fixed printed seed, oracle self-tests, case
# files, regression and seed replays, campaign smoke, CLI), runs them again
# under ASan+UBSan (preset asan: -O1, fewer cases, no teeth), then builds the
# fuzz preset (clang, libFuzzer, ASan+UBSan) and runs the bounded fuzz smoke
# test of every fuzz target over its seeds (20000 runs or 120 s each).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
jobs=$(nproc)
phase() { echo "== $1 (at $((SECONDS / 60)) min $((SECONDS % 60)) s)"; }
phase "default build (g++)"
cmake --preset default >/dev/null
cmake --build --preset default -j "$jobs"
seed=$(sed -n 's/^GEOMCHECK_RC_SEED:STRING=//p' build/default/CMakeCache.txt)
cases=$(sed -n 's/^GEOMCHECK_RC_CASES:STRING=//p' build/default/CMakeCache.txt)
phase "tests (RapidCheck seed $seed, $cases cases per property; a failure prints its replay command)"
summary=()
run_ctest() {  # preset; keeps ctest's closing line for the summary
  local log; log=$(mktemp)
  set +e
  ctest --preset "$1" -j "$jobs" --output-junit "junit-$1.xml" 2>&1 | tee "$log"
  local rc=${PIPESTATUS[0]}
  set -e
  summary+=("$(grep -E '^[0-9]+% tests passed' "$log" || echo "$1: no ctest summary")")
  rm -f "$log"
  return "$rc"
}
status=0
run_ctest default || status=1
phase "sanitizer build (g++, ASan+UBSan)"
cmake --preset asan >/dev/null
cmake --build --preset asan -j "$jobs"
phase "tests under ASan+UBSan"
run_ctest asan || status=1
phase "fuzz build (clang, libFuzzer, ASan+UBSan)"
cmake --preset fuzz >/dev/null
cmake --build --preset fuzz -j "$jobs"
phase "fuzz smoke"
run_ctest fuzz || status=1
# One closing line over both runs: "N passed, N failed".
passed=0; failed=0
for line in "${summary[@]}"; do
  t=$(sed -n 's/.* out of \([0-9]*\).*/\1/p' <<< "$line"); f=$(sed -n 's/.*passed, \([0-9]*\) tests failed.*/\1/p' <<< "$line")
  [ -n "$t" ] && passed=$((passed + t - f)) && failed=$((failed + f))
done
echo
echo "tests: $passed passed, $failed failed ($((SECONDS / 60)) min $((SECONDS % 60)) s in all)"
exit "$status"
