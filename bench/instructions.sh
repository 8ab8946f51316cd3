#!/usr/bin/env bash
# Instructions per query (callgrind): production vs FCL on the same inputs.
# Usage: bench/instructions.sh [BUILD_DIR]   (default build/release)
set -euo pipefail
build=${1:-build/release}
exe=$build/bench/count_instructions
[ -x "$exe" ] || { echo "build $exe first (cmake --build $build --target count_instructions)" >&2; exit 2; }
out=$(mktemp)
valgrind --tool=callgrind --callgrind-out-file="$out" "$exe" >/dev/null 2>&1
callgrind_annotate --inclusive=yes "$out" 2>/dev/null | awk -v calls=100000 '
  /run_(prod|fcl)_(overlap|collide)/ {
    gsub(",", "", $1); n = $1
    match($0, /run_[a-z_]+/); f = substr($0, RSTART + 4, RLENGTH - 4)
    ir[f] = n / calls
  }
  END {
    for (q in ir) printf "%-14s %8.0f instructions/query\n", q, ir[q]
    if (ir["prod_overlap"] > 0) printf "ratio overlap fcl/prod = %.1fx (instructions)\n", ir["fcl_overlap"] / ir["prod_overlap"]
    if (ir["prod_collide"] > 0) printf "ratio collide fcl/prod = %.1fx (instructions)\n", ir["fcl_collide"] / ir["prod_collide"]
  }' | sort
rm -f "$out"
