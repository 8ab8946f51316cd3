#!/usr/bin/env bash
# geomcheck — the test command (README; .ci/run calls exactly this).
# Installs the Debian dependencies, builds the default preset and runs every
# ctest suite (properties with a fixed printed seed, oracle self-tests, case
# files, regression and seed replays, campaign smoke), then builds the fuzz
# preset (clang, libFuzzer, ASan+UBSan) and runs the bounded fuzz smoke test
# of every fuzz target over its seeds.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
jobs=$(nproc)
echo "== default build (g++)"
cmake --preset default >/dev/null
cmake --build --preset default -j "$jobs"
echo "== tests (RapidCheck seed and case count are printed by each property)"
ctest --preset default -j "$jobs" --output-junit junit-default.xml
echo "== fuzz build (clang, libFuzzer, ASan+UBSan)"
cmake --preset fuzz >/dev/null
cmake --build --preset fuzz -j "$jobs"
echo "== fuzz smoke"
ctest --preset fuzz -j "$jobs" --output-junit junit-fuzz.xml
