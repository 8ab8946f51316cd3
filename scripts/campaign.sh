#!/usr/bin/env bash
# geomcheck — the main job: a verification campaign of every registered query
# on the built-in defaults (fixed seed, 100000 cases per query, 10000 point
# sets, 2000 meshes, all cores),
# ending in reports/out/report.json and reports/out/report.html.
# Extra arguments go to `geomcheck campaign` (see --help).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
cmake --preset release >/dev/null
cmake --build --preset release -j "$(nproc)" --target geomcheck
exec build/release/tools/geomcheck campaign --out reports/out "$@"
