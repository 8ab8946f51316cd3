#!/usr/bin/env bash
# geomcheck — sharded campaigns: shards 0..2 of 3 run apart and merged give
# exactly the figures of the unsharded run (compare_reports.py: every count,
# verdict mix, failure signature, error percentile and histogram; timings
# and saved-file paths left out), for production (an engine-backed query, a
# closed-form one, the point sets) and for a known-wrong variant (failures
# counted the same, exit status 1 kept); one thread gives the report of two
# (the other engines side by side or one after another). GTEST_SHARD_INDEX/GTEST_TOTAL_SHARDS
# pick the shard when --shard is not given; merge refuses a missing, a
# repeated and a foreign shard (exit 2).
# usage: test_shards.sh GEOMCHECK OUT_DIR [ENGINES: how many other engines the build has, 0]
set -u
tool=$1 out=$2 engines=${3:-0}
here=$(cd "$(dirname "$0")" && pwd)
rm -rf "$out"; mkdir -p "$out"
fail() { echo "FAIL: $*"; exit 1; }
run() {  # expected-status log-name args...
  local want=$1 log=$out/$2.log; shift 2
  "$tool" "$@" > "$log" 2>&1
  local got=$?
  [ "$got" -eq "$want" ] || { tail -20 "$log"; fail "geomcheck $* exited $got ($want expected)"; }
}
same() { python3 "$here/compare_reports.py" "$1" "$2" || fail "$1 and $2 differ"; }

common=(--seed 20261121 --no-progress --threads 2)
prod=(--cases 90 --peer-cases 12 --query collide_cylinder_obb --query cast_segment_cylinder
      --query sweep_sphere_cylinder --query delaunay_2d --query collide_cylinder_mesh)
run 0 full campaign "${common[@]}" "${prod[@]}" --out "$out/full"
for i in 0 1 2; do run 0 "s$i" campaign "${common[@]}" "${prod[@]}" --shard "$i/3" --out "$out/s$i"; done
run 0 merge merge "$out/s2" "$out/s0" "$out/s1" --out "$out/merged"
same "$out/full/report.json" "$out/merged/report.json"
# Not vacuous: one shard alone is not the whole run.
python3 "$here/compare_reports.py" "$out/full/report.json" "$out/s1/report.json" > /dev/null 2>&1 &&
  fail "a single shard compared equal to the whole run"
# The merged report's saved cases exist where it says.
python3 - "$out/merged/report.json" <<'PY' || fail "the merged report lists files that are not there"
import json, os, sys
r = json.load(open(sys.argv[1]))
for q in r["queries"]:
    for p in q["counterexamples"] + q["fcl"]["cases"]:
        assert os.path.exists(p), p
    assert q["cases"] == 90 and sum(q["truth_stages"].values()) == q["valid"], q["id"]
assert [m["meshes"] for m in r["mesh_queries"]] == [90], r["mesh_queries"]
PY

# One thread: the same report (the other engines one after another in this
# process, where two threads run them side by side in child processes).
run 0 one-thread campaign --seed 20261121 --no-progress --threads 1 "${prod[@]}" --out "$out/one-thread"
same "$out/full/report.json" "$out/one-thread/report.json"
python3 -c "import json,sys; n=len(json.load(open(sys.argv[1]))['queries'][0]['peers']); assert n == int(sys.argv[2]), n" \
  "$out/full/report.json" "$engines" || fail "not every one of the build's $engines other engines ran on the box query"

# A failing subject: the failures are counted the same, the exit status kept.
bad=(--cases 150 --variant capsule-capsule)
run 1 bad-full campaign "${common[@]}" "${bad[@]}" --out "$out/bad-full"
for i in 0 1 2; do
  "$tool" campaign "${common[@]}" "${bad[@]}" --shard "$i/3" --out "$out/bad-s$i" > "$out/bad-s$i.log" 2>&1
done
run 1 bad-merge merge "$out/bad-s0" "$out/bad-s1" "$out/bad-s2" --out "$out/bad-merged"
same "$out/bad-full/report.json" "$out/bad-merged/report.json"
python3 -c "import json,sys; q=json.load(open(sys.argv[1]))['queries'][0]; assert q['check_failures'] > 0, q" \
  "$out/bad-merged/report.json" || fail "the variant failed nothing"

# The GTest convention picks the shard.
GTEST_SHARD_INDEX=1 GTEST_TOTAL_SHARDS=3 run 0 env campaign "${common[@]}" "${prod[@]}" --out "$out/env1"
python3 -c "import json,sys; assert json.load(open(sys.argv[1]))['shard'] == 1" "$out/env1/shard.json" ||
  fail "GTEST_SHARD_INDEX=1 did not run shard 1"
same "$out/s1/report.json" "$out/env1/report.json"

# Merge refuses what is not one whole campaign.
run 2 missing merge "$out/s0" "$out/s1" --out "$out/m-missing"
grep -q "missing" "$out/missing.log" || fail "a missing shard not named"
run 2 twice merge "$out/s0" "$out/s1" "$out/env1" "$out/s2" --out "$out/m-twice"
grep -q "twice" "$out/twice.log" || fail "a repeated shard not named"
run 2 foreign merge "$out/s0" "$out/bad-s1" "$out/s2" --out "$out/m-foreign"
grep -q "not shards of one campaign" "$out/foreign.log" || fail "a foreign shard not named"
run 2 badspec campaign --shard 3/3 --out "$out/none"
grep -q "I must be in" "$out/badspec.log" || fail "--shard 3/3 not refused with a reason"
echo "shards: merged = unsharded (production and a failing variant); GTest variables; merge refuses bad sets"
