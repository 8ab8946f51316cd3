#!/bin/bash -eu
# Builds every geomcheck fuzz target with the engine's compiler and flags.
# FuzzedDataProvider.h is found through $CXX's resource directory (CMakeLists.txt).
cmake -S "$SRC/geomcheck" -B build-cfl -G Ninja \
  -DCMAKE_CXX_COMPILER="$CXX" -DCMAKE_CXX_FLAGS="$CXXFLAGS" \
  -DGEOMCHECK_FUZZ=ON -DGEOMCHECK_FUZZ_LOCAL=OFF -DGEOMCHECK_FUZZ_ENGINE="$LIB_FUZZING_ENGINE" \
  -DGEOMCHECK_TESTS=OFF -DGEOMCHECK_TOOLS=OFF -DGEOMCHECK_BENCH=OFF -DCMAKE_BUILD_TYPE=RelWithDebInfo
cmake --build build-cfl
./build-cfl/fuzz/make_fuzz_seeds "$SRC/geomcheck/corpora/seeds" build-cfl/seeds
for t in build-cfl/fuzz/fuzz_*; do
  # The binaries only; their <target>.dict and <target>.options (written
  # beside each by fuzz/CMakeLists.txt) go with them, as ClusterFuzz expects.
  if [ ! -f "$t" ] || [ ! -x "$t" ]; then continue; fi
  name=$(basename "$t")
  cp "$t" "$t.dict" "$t.options" "$OUT/"
  q=${name#fuzz_}
  if [ -d "build-cfl/seeds/$q" ]; then
    (cd "build-cfl/seeds/$q" && zip -q -r "$OUT/${name}_seed_corpus.zip" .)
  fi
done
