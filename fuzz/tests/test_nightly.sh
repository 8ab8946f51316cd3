#!/usr/bin/env bash
# geomcheck — the nightly fuzz job loses nothing when it is interrupted.
#
# Runs tools/nightly_fuzz.py on two targets (a test-only target with a
# known-wrong variant, which finds failures within seconds, and the case-file
# parser), interrupts it ROUNDS times at random moments (SIGINT or SIGTERM,
# from a fixed, printed seed) while a watcher records every corpus entry and
# every finding input it sees on disk, then lets one run finish. Then:
#   - every finding input seen is filed (moved to findings/T/done/), none pending;
#   - every corpus entry seen is in the corpus or in pruned/ (kept by the merge);
#   - each signature has exactly one case file, and every case file replays;
#   - the report says the last run finished;
#   - the JUnit file of every run (scripts/nightly_junit.py, as
#     scripts/nightly.sh writes it) is well-formed, counts its test cases,
#     and names, for every new finding, a crash file and a case file that
#     exist and a replay command; some run has such a failure.
# usage: test_nightly.sh NIGHTLY_PY FUZZ_DIR GEOMCHECK SEEDS_DIR [ROUNDS] [SEED]
set -u
py=$1 fuzz_dir=$2 tool=$3 seeds=$4 rounds=${5:-4} seed=${6:-20261121}
if [ ! -x "$tool" ]; then echo "SKIP: $tool is not built (build the default preset first)"; exit 77; fi
w=$(mktemp -d /tmp/geomcheck-nightly-test.XXXXXX)
work=$w/work regs=$w/regressions obs=$w/observed
mkdir -p "$obs"
T1=teeth_fuzz_sphere_as_capsule T2=fuzz_casefile
fail() { echo "FAIL: $*"; echo "(state kept in $w)"; exit 1; }
junit_py=$(dirname "$0")/../../scripts/nightly_junit.py
junit() { python3 "$junit_py" "$work" "$fuzz_dir" "$w/junit-$1.xml" > "$w/junit-$1.log" 2>&1 || { cat "$w/junit-$1.log"; fail "nightly_junit.py after run $1"; }; }
common=(--work "$work" --fuzz-dir "$fuzz_dir" --geomcheck "$tool" --regressions "$regs" --seeds "$seeds"
        --target "$T1=collide_cylinder_sphere" --target "$T2" --jobs 1 --minimise-seconds 3)
watch_disk() {  # names of corpus entries and finding inputs, as often as it can
  while :; do
    for t in $T1 $T2; do
      ls "$work/corpus/$t" 2>/dev/null | sed "s|^|$t/|" >> "$obs/corpus.txt"
      ls "$work/findings/$t" 2>/dev/null | grep -E '^(crash|leak|timeout|oom)-' | sed "s|^|$t/|" >> "$obs/findings.txt"
    done
    sleep 0.05
  done
}
echo "test_nightly: seed $seed, $rounds interrupted runs, state in $w"
RANDOM=$seed
watch_disk & watcher=$!
trap 'kill $watcher 2>/dev/null' EXIT
for i in $(seq 1 "$rounds"); do
  delay=$((2 + RANDOM % 22)); sig=$([ $((RANDOM % 2)) -eq 0 ] && echo INT || echo TERM)
  python3 "$py" "${common[@]}" --seconds 24 > "$w/run$i.log" 2>&1 &
  pid=$!
  sleep "$delay"
  kill -s "$sig" "$pid" 2>/dev/null
  wait "$pid"; rc=$?
  last=$(grep -E 'nightly: (\[|  )' "$w/run$i.log" | tail -1)
  echo "round $i: SIG$sig after $delay s, exit $rc; last step: $last"
  case $rc in 0|1|130) ;; *) cat "$w/run$i.log"; fail "round $i exited $rc";; esac
  junit "$i"
done
python3 "$py" "${common[@]}" --seconds 8 > "$w/final.log" 2>&1; rc=$?
kill $watcher 2>/dev/null; wait $watcher 2>/dev/null
cat "$w/final.log"
case $rc in 0|1) ;; *) fail "the final run exited $rc";; esac
junit final

sort -u -o "$obs/corpus.txt" "$obs/corpus.txt"; sort -u -o "$obs/findings.txt" "$obs/findings.txt"
nf=$(wc -l < "$obs/findings.txt"); nc=$(wc -l < "$obs/corpus.txt")
echo "seen on disk: $nc corpus entries, $nf finding inputs"
[ "$nf" -gt 0 ] || fail "the known-wrong target produced no finding: the test saw nothing to lose"
lost=0
while IFS=/ read -r t n; do
  [ -f "$work/findings/$t/done/$n" ] || { echo "finding not filed: $t/$n"; lost=$((lost + 1)); }
done < "$obs/findings.txt"
while IFS=/ read -r t n; do
  [ -f "$work/corpus/$t/$n" ] || [ -f "$work/pruned/$t/$n" ] || { echo "corpus entry lost: $t/$n"; lost=$((lost + 1)); }
done < "$obs/corpus.txt"
[ "$lost" -eq 0 ] || fail "$lost corpus entries or findings lost"
pending=$(ls "$work/findings/$T1" "$work/findings/$T2" | grep -cE '^(crash|leak|timeout|oom)-')
[ "$pending" -eq 0 ] || fail "$pending finding inputs still pending after a finished run"

cases=$(find "$regs" -name '*-new-*.case' | wc -l)
[ "$cases" -gt 0 ] || fail "no case file was filed"
dups=$(grep -h '^note nightly-signature' -r "$regs" | sort | uniq -d)
[ -z "$dups" ] || fail "a signature was filed twice: $dups"
grep -q '^note NEW: found by the nightly fuzz run' $(find "$regs" -name '*.case' | head -1) || fail "case not marked new"
# Production passes every filed case (the failures were the known-wrong variant's).
"$tool" replay --quiet "$regs" > "$w/replay.log" 2>&1 || { cat "$w/replay.log"; fail "a filed case does not replay"; }
python3 - "$work/report.json" <<'PY' || fail "report.json"
import json, sys
r = json.load(open(sys.argv[1]))
assert r["status"] == "finished", r["status"]
assert {t["name"] for t in r["targets"]} == {"teeth_fuzz_sphere_as_capsule", "fuzz_casefile"}
assert all(t["fuzz"]["execs"] > 0 for t in r["targets"]), "a target was not fuzzed"
PY
python3 - "$w" <<'PY' || fail "a JUnit file"
import glob, os, sys
import xml.etree.ElementTree as ET
failing = 0
for path in sorted(glob.glob(os.path.join(sys.argv[1], "junit-*.xml"))):
    suite = ET.parse(path).getroot().find("testsuite")
    cases = suite.findall("testcase")
    status = suite.find("properties/property[@name='status']").get("value")
    assert int(suite.get("tests")) == len(cases), path
    assert int(suite.get("failures")) == sum(c.find("failure") is not None for c in cases), path
    for c in cases:
        assert c.get("name") in ("teeth_fuzz_sphere_as_capsule", "fuzz_casefile") and float(c.get("time")) >= 0, path
        f = c.find("failure")
        if f is None:
            continue
        failing += 1
        lines = [l.split(": ", 1) for l in f.text.splitlines() if ": " in l]
        assert any(k == "replay" for k, _ in lines), path
        for k, v in lines:
            assert k not in ("crash file", "filed as") or os.path.isfile(v), f"{path}: no {k} {v}"
    if status == "interrupted" and cases:
        assert cases[-1].find("error") is not None or cases[-1].find("failure") is not None, path
final = ET.parse(os.path.join(sys.argv[1], "junit-final.xml")).getroot()
assert final.find("testsuite/properties/property[@name='status']").get("value") == "finished"
assert not list(final.iter("error")), "an error in the finished run"
assert failing > 0, "no JUnit test case failed, yet the known-wrong target's findings were filed"
PY
echo "test_nightly: $cases case files (one per signature), every one of $nf finding inputs filed, every one of $nc corpus entries kept"
echo "test_nightly: PASS"
rm -rf "$w"
