#!/usr/bin/env bash
# geomcheck — the curated failures of other engines (corpora/peers/<engine>/)
# still fail against their engine, and production passes every one of them.
# An engine not built here (its package missing) is skipped.
# usage: test_replay_peers.sh GEOMCHECK SOURCE_DIR
set -u
tool=$1 src=$2
fail() { echo "FAIL: $*"; exit 1; }
checked=0
for pair in ode:ODE bullet:Bullet mujoco:MuJoCo; do
  dir="$src/corpora/peers/${pair%%:*}" engine=${pair##*:}
  n=$(ls "$dir"/*.case 2>/dev/null | wc -l)
  [ "$n" -gt 0 ] || continue
  out=$("$tool" replay --subject "$engine" "$dir" 2>&1)
  rc=$?
  if echo "$out" | grep -q "no subject '$engine'"; then echo "skip: $engine not built"; continue; fi
  [ "$rc" -eq 1 ] && echo "$out" | grep -q "replay: 0 passed, $n failed, 0 unreadable" \
    || { echo "$out" | tail -5; fail "$engine: not every case of $dir fails again (exit $rc)"; }
  "$tool" replay --quiet "$dir" > /dev/null 2>&1 || fail "production fails a case of $dir"
  checked=$((checked + n))
  echo "$engine: $n cases fail again; production passes them"
done
echo "PASS: $checked curated peer cases"
