#!/usr/bin/env bash
# geomcheck — the nightly job: every fuzz target for a budget (libFuzzer
# -fork on all cores), corpora merged and minimised, findings de-duplicated,
# minimised and filed as corpora/regressions/<query>/NNNN-new-*.case, and a
# fuzz report in fuzz-out/nightly/report.{json,html}. Interrupt it at any
# time: nothing is lost, the next run picks up what was pending.
#   bash scripts/nightly.sh                  # 3600 s in all
#   bash scripts/nightly.sh --seconds 28800  # a whole night
#   bash scripts/nightly.sh --help           # every option
set -euo pipefail
cd "$(dirname "$0")/.."
case " $* " in *" -h "*|*" --help "*) exec python3 tools/nightly_fuzz.py --help ;; esac
bash scripts/install-deps.sh
jobs=$(nproc)
cmake --preset fuzz >/dev/null
cmake --build --preset fuzz -j "$jobs"
cmake --preset release >/dev/null
cmake --build --preset release -j "$jobs" --target geomcheck
exec python3 tools/nightly_fuzz.py "$@"
