#!/usr/bin/env bash
# geomcheck — production's open counterexamples (corpora/open/<query>/) still
# fail: a fix that makes one pass must move it to corpora/regressions/.
# usage: test_replay_open.sh GEOMCHECK SOURCE_DIR
set -u
tool=$1 src=$2
dir="$src/corpora/open"
n=$(find "$dir" -name '*.case' | wc -l)
[ "$n" -gt 0 ] || { echo "PASS: no open counterexample"; exit 0; }
out=$("$tool" replay "$dir" 2>&1)
rc=$?
if [ "$rc" -eq 1 ] && echo "$out" | grep -q "replay: 0 passed, $n failed, 0 unreadable"; then
  echo "PASS: the $n open counterexamples fail again"
  exit 0
fi
echo "$out" | grep -E "^PASS" || true
echo "$out" | tail -3
echo "FAIL: a case of corpora/open now passes (exit $rc): move it to corpora/regressions/<query>/ with a note"
exit 1
