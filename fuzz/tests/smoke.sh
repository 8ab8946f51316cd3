#!/bin/sh
# geomcheck — one fuzz target's bounded smoke run (ctest: smoke_fuzz_*).
#
# usage: smoke.sh FUZZER SCRATCH SEEDS [libFuzzer flags...]
#
# The target's own flags (-dict, -max_len: FUZZER.options and FUZZER.dict,
# read by ../options_flags.sh) follow the given ones. New inputs go to the
# scratch corpus SCRATCH (emptied first); the seeds in SEEDS stay untouched.
# libFuzzer's progress lines go to SCRATCH.log, not to the test output: a
# passing run prints its dictionary's size and its closing lines, a failing
# one its exit status (or the signal that ended it) and everything in the
# log that is not a progress line (the failure, the case file, the crash
# input), so that a truncated test log still shows why it failed.
set -u
fuzzer=$1 scratch=$2 seeds=$3
shift 3
own=$(sh "$(dirname "$0")/../options_flags.sh" "$fuzzer") || exit 1
# Appended a line each (a path may hold spaces).
old_ifs=$IFS; IFS='
'
set -f; set -- "$@" $own; set +f
IFS=$old_ifs
rm -rf "$scratch" && mkdir -p "$scratch" "$seeds" || exit 1
log=$scratch.log
echo "smoke: $fuzzer $* $scratch $seeds (progress in $(pwd)/$log)"
"$fuzzer" "$@" "$scratch" "$seeds" > "$log" 2>&1
rc=$?
if [ "$rc" -eq 0 ]; then
  grep -E '^(Dictionary: |#[0-9]+[[:space:]]+DONE|Done [0-9]+ runs)' "$log"
  exit 0
fi
if [ "$rc" -gt 128 ]; then
  echo "smoke: FAILED: the fuzzer was killed by signal $((rc - 128))"
else
  echo "smoke: FAILED: the fuzzer exited with status $rc"
fi
echo "smoke: the last progress line:"
grep -E '^#[0-9]+[[:space:]]' "$log" | tail -1
echo "smoke: the log without its progress lines (last 200 lines):"
grep -vE '^#[0-9]+[[:space:]]+(NEW|REDUCE|pulse|RELOAD|INITED)[[:space:]]' "$log" | tail -200
unit=$(sed -n 's/.*Test unit written to \(.*\)$/\1/p' "$log" | tail -1)
[ -n "$unit" ] && echo "smoke: replay with: (cd $(pwd) && $fuzzer $unit)"
exit "$rc"
