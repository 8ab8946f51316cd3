#!/usr/bin/env bash
# geomcheck — the test command (README; .ci/run calls exactly this).
# Installs the Debian dependencies, builds the default preset and runs every
# ctest suite (properties with a fixed printed seed, oracle self-tests, case
# files, regression and seed replays, campaign smoke, CLI), runs them again
# under ASan+UBSan (preset asan: clang, -O1, fewer cases, no teeth), then builds the
# fuzz preset (clang, libFuzzer, ASan+UBSan) and runs the bounded fuzz smoke
# test of every fuzz target over its seeds (a fixed run count each).
#
# --quick: the quick preset (build/quick: the default build's code at -O2
# without debug information and without the benchmarks) and every suite of
# the default preset with a tenth of the cases (2000 per property, 40 per
# engine property, 2000 per precision query, 100 per query in the campaign
# smoke test; the teeth keep theirs), no sanitizer or fuzz run.
set -euo pipefail
cd "$(dirname "$0")/.."
quick=0
for arg in "$@"; do
  case "$arg" in
    --quick) quick=1 ;;
    -h|--help)
      sed -n '2,/^set -euo/p' "$0" | sed '$d; s/^# \{0,1\}//'
      echo "usage: bash scripts/test.sh [--quick]"
      exit 0 ;;
    *) echo "test.sh: unknown argument '$arg' (try --help)" >&2; exit 2 ;;
  esac
done
bash scripts/install-deps.sh
jobs=$(nproc)
phase() { echo "== $1 (at $((SECONDS / 60)) min $((SECONDS % 60)) s)"; }
main=default
[ "$quick" = 1 ] && main=quick
phase "$main build (g++)"
cmake --preset "$main" >/dev/null
cmake --build --preset "$main" -j "$jobs"
built=$SECONDS
seed=$(sed -n 's/^GEOMCHECK_RC_SEED:STRING=//p' "build/$main/CMakeCache.txt")
cases=$(sed -n 's/^GEOMCHECK_RC_CASES:STRING=//p' "build/$main/CMakeCache.txt")
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
run_ctest "$main" || status=1
if [ "$quick" = 1 ]; then
  echo
  echo "tests (quick): ${summary[0]} ($((SECONDS / 60)) min $((SECONDS % 60)) s in all, $(((SECONDS - built) / 60)) min $(((SECONDS - built) % 60)) s after the build)"
  exit "$status"
fi
phase "sanitizer build (clang, ASan+UBSan)"
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
