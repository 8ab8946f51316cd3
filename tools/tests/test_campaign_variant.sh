#!/usr/bin/env bash
# geomcheck — a failing campaign, end to end: a known-wrong variant
# (capsule-capsule: the cylinder's caps rounded) runs in production's place
# (fixed seed). The campaign must exit 1, save every failing case with its
# drawing (three views, the variant's answer, the oracle's witness), list
# them in the report, and each case must replay as a pass against
# production (the failure is the variant's, not production's).
# usage: test_campaign_variant.sh GEOMCHECK OUT_DIR
set -u
tool=$1 out=$2
rm -rf "$out"; mkdir -p "$out"
fail() { echo "FAIL: $*"; exit 1; }
"$tool" campaign --seed 20261121 --cases 300 --variant capsule-capsule --no-progress --out "$out/report" --junit "$out/junit.xml" \
  > "$out/campaign.log" 2>&1
status=$?
[ "$status" -eq 1 ] || { cat "$out/campaign.log"; fail "exit status $status (1 expected: the variant is wrong)"; }
grep -q "FAILURES found" "$out/campaign.log" || fail "the campaign did not say it found failures"
dir="$out/report/counterexamples/collide_cylinder_capsule"
cases=$(ls "$dir"/*.case 2>/dev/null | wc -l)
[ "$cases" -gt 0 ] || fail "no counterexample saved"
# Every failure counted; at most saved_cases_per_kind saved per property, each listed.
python3 - "$out/report/report.json" "$cases" <<'PY' || fail "report.json's counts and saved cases do not add up"
import collections, json, re, sys
r = json.load(open(sys.argv[1])); saved = int(sys.argv[2]); cap = r["saved_cases_per_kind"]
q, = r["queries"]
assert len(q["counterexamples"]) == saved, (len(q["counterexamples"]), saved)
# A failing case counts once, and under each property it fails.
by_property = sum(q["failures_by_property"].values())
assert 0 < q["check_failures"] <= by_property and by_property >= saved, (q["check_failures"], by_property, saved)
sigs = q["failures_by_signature"]  # "property @ mode": count
assert sum(sigs.values()) == by_property, sigs
# Saved per signature (the mode is in each file's found-by line) at most
# saved_cases_per_signature, per property at most saved_cases_per_kind, and
# every signature has a saved case unless its property's cap was reached.
per_sig, per_prop = collections.Counter(), collections.Counter()
for path in q["counterexamples"]:
    text = open(path).read()
    prop = re.search(r"\d{5}-(.*)\.case$", path).group(1)
    mode = re.search(r"mode=(\S+)", text).group(1)
    per_sig[prop + " @ " + mode] += 1
    per_prop[prop] += 1
assert all(n <= r["saved_cases_per_signature"] for n in per_sig.values()), per_sig
assert all(n <= cap for n in per_prop.values()), per_prop
for sig in sigs:
    prop = sig.split(" @ ")[0]
    assert per_sig[sig] > 0 or per_prop[prop] == cap, (sig, per_sig, per_prop)
print(f"{saved} saved of {q['check_failures']} failures, {len(sigs)} signatures, {q['shrunk']} shrunk")
PY
grep -q '"implementation": "capsule-capsule' "$out/report/report.json" || fail "report.json does not name the variant"
grep -q '"verdict": "failed"' "$out/report/report.json" || fail "report.json's overall verdict is not failed"
# JUnit: a test case per property family, the failing ones carrying a replay command of the variant.
python3 - "$out/junit.xml" <<'PY' || fail "the JUnit file does not show the failures"
import sys, xml.etree.ElementTree as ET
cases = ET.parse(sys.argv[1]).getroot().iter("testcase")
failed = {c.get("name"): c.find("failure").text for c in cases if c.find("failure") is not None}
assert "collide_cylinder_capsule.oracle" in failed, failed
assert "geomcheck replay --subject capsule-capsule " in failed["collide_cylinder_capsule.oracle"], failed
PY
for c in "$dir"/*.case; do
  page="${c%.case}.html"
  [ -s "$page" ] || fail "no drawing beside $c"
  # Three views of the case; a relation's page three more of the case it compared.
  views=3
  grep -q "compared it with" "$page" && views=6
  [ "$(grep -o "<title>[a-z]* view</title>" "$page" | wc -l)" -eq "$views" ] || fail "$page: not $views views"
  grep -q "capsule-capsule: " "$page" || fail "$page: the variant's answer is not drawn"
  grep -q "truth: " "$page" || fail "$page: no witness of the truth"
done
"$tool" replay --quiet "$dir" > "$out/replay.log" 2>&1 || { cat "$out/replay.log"; fail "production fails a case only the variant should fail"; }
# The command each page gives reproduces the failure: every case fails again
# against the variant.
grep -q "geomcheck replay --subject capsule-capsule " "$dir"/*.html || fail "the pages do not give the variant's replay command"
"$tool" replay --subject capsule-capsule "$dir" > "$out/replay-variant.log" 2>&1
rc=$?
[ "$rc" -eq 1 ] || { tail "$out/replay-variant.log"; fail "replay --subject capsule-capsule: exit $rc, 1 expected"; }
grep -q "replay: 0 passed, $cases failed, 0 unreadable" "$out/replay-variant.log" || { tail -3 "$out/replay-variant.log"; fail "not every case fails again against the variant"; }
grep -q "counterexamples drawn" "$out/report/report.html" || fail "the report draws no counterexample"
# A disagreement too small for the views (the answer and the witness under
# 1/50 of the scene apart) gets a zoomed panel.
grep -q "<title>zoom at the contact</title>" "$dir"/*.html || fail "no page zooms in on a small disagreement"
echo "variant campaign: $cases counterexamples saved and drawn, all replay as passes against production"
