#!/usr/bin/env bash
# geomcheck — the nightly job: every fuzz target for a budget (libFuzzer
# -fork on all cores, with the target's dictionary and options), corpora
# merged and minimised, findings de-duplicated, minimised and filed as
# corpora/regressions/<query>/NNNN-new-*.case, a fuzz report in
# fuzz-out/nightly/report.{json,html} and a JUnit XML file beside it,
# fuzz-out/nightly/junit.xml (a test case per target, failing when it found
# something new). Interrupt it at any time: nothing is lost, the next run
# picks up what was pending.
#   bash scripts/nightly.sh                  # 3600 s in all
#   bash scripts/nightly.sh --seconds 28800  # a whole night
#   bash scripts/nightly.sh --help           # every option
set -euo pipefail
cd "$(dirname "$0")/.."
case " $* " in *" -h "*|*" --help "*)
  echo "scripts/nightly.sh: builds the fuzz preset and the geomcheck tool, runs tools/nightly_fuzz.py (its"
  echo "options below) with each target's libFuzzer flags (<target>.options and <target>.dict beside the"
  echo "binary, read by fuzz/options_flags.sh), then writes a JUnit XML file of the run."
  echo
  echo "  --junit FILE   the JUnit XML (default WORK/junit.xml, beside report.json): a test case per fuzz"
  echo "                 target run (its fuzzing time; a failure with the case file, the crash file and the"
  echo "                 replay commands when it found something new; an error when it was interrupted)"
  echo
  exec python3 tools/nightly_fuzz.py --help ;;
esac

# The options this script reads too (in full: the driver would take a
# prefix of them for the whole word); every other one goes to the driver.
work=fuzz-out/nightly fuzz_dir=build/fuzz/fuzz junit='' args=()
while [ $# -gt 0 ]; do
  opt=${1%%=*}
  for full in --work --fuzz-dir; do
    if [ ${#opt} -gt 2 ] && [ "$opt" != "$full" ] && [ "${full#"$opt"}" != "$full" ]; then
      echo "nightly: give $full in full, not $opt" >&2; exit 2
    fi
  done
  case $1 in
    --junit|--work|--fuzz-dir) [ $# -ge 2 ] || { echo "nightly: $1 needs a value" >&2; exit 2; } ;;
  esac
  case $1 in
    --junit) junit=$2; shift ;;
    --junit=*) junit=${1#*=} ;;
    --work) work=$2; args+=("$1" "$2"); shift ;;
    --work=*) work=${1#*=}; args+=("$1") ;;
    --fuzz-dir) fuzz_dir=$2; shift ;;
    --fuzz-dir=*) fuzz_dir=${1#*=} ;;
    *) args+=("$1") ;;
  esac
  shift
done
junit=${junit:-$work/junit.xml}

bash scripts/install-deps.sh
jobs=$(nproc)
cmake --preset fuzz >/dev/null
cmake --build --preset fuzz -j "$jobs"
cmake --preset release >/dev/null
cmake --build --preset release -j "$jobs" --target geomcheck

# The driver runs the binaries of --fuzz-dir; here it gets a folder of the
# same names, each target a wrapper adding its own flags (last, so that its
# -max_len wins over the driver's default) and everything else (make_fuzz_seeds)
# a link.
bin=$(mktemp -d "${TMPDIR:-/tmp}/geomcheck-nightly-bin.XXXXXX")
trap 'rm -rf "$bin"' EXIT
for f in "$fuzz_dir"/*; do
  [ -f "$f" ] && [ -x "$f" ] || continue
  real=$(cd "$(dirname "$f")" && pwd)/$(basename "$f")
  mapfile -t own < <(sh fuzz/options_flags.sh "$real")
  if [ ${#own[@]} -eq 0 ]; then
    ln -s "$real" "$bin/"
    continue
  fi
  { echo '#!/usr/bin/env bash'; printf 'exec %q "$@"' "$real"; printf ' %q' "${own[@]}"; echo; } > "$bin/$(basename "$f")"
  chmod +x "$bin/$(basename "$f")"
done

# In the background, so that a SIGTERM or SIGINT sent to this script reaches
# the driver (which stops cleanly) and the JUnit file is still written.
touch "$bin/.started"
python3 tools/nightly_fuzz.py --fuzz-dir "$bin" "${args[@]}" &
driver=$!
trap 'kill -TERM "$driver" 2>/dev/null || true' TERM
trap 'kill -INT "$driver" 2>/dev/null || true' INT
while kill -0 "$driver" 2>/dev/null; do wait "$driver" || true; done
rc=0
wait "$driver" || rc=$?
if [ "$work/report.json" -nt "$bin/.started" ]; then
  python3 scripts/nightly_junit.py "$work" "$fuzz_dir" "$junit" || { echo "nightly: no JUnit file written" >&2; [ "$rc" -ne 0 ] || rc=1; }
else
  echo "nightly: no report from this run, so no JUnit file" >&2
fi
exit "$rc"
