#!/usr/bin/env bash
# geomcheck — .clusterfuzzlite/build.sh run here with the variables
# ClusterFuzzLite (and OSS-Fuzz) set for an ASan libFuzzer build, then every
# target it put in $OUT run for a few seconds on its seed corpus with the
# flags of its $OUT/<target>.options and .dict, as the engine's run_fuzzers
# step does. Checks the layout without Docker: every target has its
# dictionary and options beside it.
#   bash scripts/cfl-local.sh [SECONDS_PER_TARGET]   (default 5)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
secs=${1:-5}
bash "$root/scripts/install-deps.sh"
w=$(mktemp -d /tmp/geomcheck-cfl.XXXXXX)
mkdir -p "$w/src" "$w/out" "$w/work"
ln -s "$root" "$w/src/geomcheck"
flags="-O1 -fno-omit-frame-pointer -gline-tables-only -fsanitize=address -fsanitize-address-use-after-scope -fsanitize=fuzzer-no-link"
export SRC=$w/src OUT=$w/out CC=clang CXX=clang++ CFLAGS="$flags" CXXFLAGS="$flags" \
       LIB_FUZZING_ENGINE=-fsanitize=fuzzer SANITIZER=address FUZZING_ENGINE=libfuzzer ARCHITECTURE=x86_64
(cd "$w/work" && bash "$root/.clusterfuzzlite/build.sh")
n=0
for t in "$OUT"/fuzz_*; do
  case "$t" in *.zip|*.dict|*.options) continue ;; esac
  name=$(basename "$t"); corpus="$w/corpus/$name"; mkdir -p "$corpus"
  [ -f "$t.dict" ] && [ -f "$t.options" ] || { echo "cfl-local: $name has no $name.dict or $name.options in \$OUT"; exit 1; }
  mapfile -t own < <(sh "$root/fuzz/options_flags.sh" "$t")
  [ -f "$t"_seed_corpus.zip ] && unzip -q -o "$t"_seed_corpus.zip -d "$corpus"
  "$t" -max_total_time="$secs" -print_funcs=0 -print_final_stats=1 "${own[@]}" "$corpus" > "$w/$name.log" 2>&1 ||
    { tail -40 "$w/$name.log"; echo "cfl-local: $name failed (log $w/$name.log)"; exit 1; }
  echo "cfl-local: $name: $(grep -E '^Dictionary: ' "$w/$name.log"), $(grep -E '^#[0-9]+.*DONE' "$w/$name.log" | tail -1)"
  n=$((n + 1))
done
echo "cfl-local: $n targets built by build.sh and run from \$OUT ($w)"
