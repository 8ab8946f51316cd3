#!/usr/bin/env bash
# geomcheck — the campaign's HTML report as a person sees it: a small
# campaign (fixed seed) whose FCL disagreements are drawn, the page rendered
# in headless Chromium (screenshot and DOM), and checked: it renders with no
# console message, the screenshot is a real image, and the
# page holds the report's parts (the glance matrix first, the precision table with FCL's rows, the
# queries' sections, histograms, the drawn disagreements in three views
# each, every one with the oracle's witness and FCL's answer).
# usage: test_report_page.sh GEOMCHECK OUT_DIR
set -u
tool=$1 out=$2
browser=$(command -v chromium || command -v chromium-browser || true)
if [ -z "$browser" ]; then echo "SKIP: no chromium (apt-get install chromium)"; exit 77; fi
rm -rf "$out"; mkdir -p "$out"
fail() { echo "FAIL: $*"; exit 1; }
"$tool" campaign --seed 20261121 --cases 600 --query cast_segment_cylinder --query collide_cylinder_capsule --no-progress --out "$out/report" \
  > "$out/campaign.log" 2>&1 || { cat "$out/campaign.log"; fail "campaign failed"; }
page="$out/report/report.html"
flags=(--headless --no-sandbox --disable-gpu --disable-quic --no-first-run --disable-background-networking
       --disable-component-update --disable-sync --hide-scrollbars --user-data-dir="$out/profile"
       --enable-logging=stderr --v=0)
timeout 120 "$browser" "${flags[@]}" --window-size=1200,2400 --screenshot="$out/report.png" "file://$page" \
  > "$out/chromium.log" 2>&1
timeout 120 "$browser" "${flags[@]}" --dump-dom "file://$page" > "$out/dom.html" 2>> "$out/chromium.log"
[ -s "$out/report.png" ] || { cat "$out/chromium.log"; fail "no screenshot"; }
[ "$(head -c 8 "$out/report.png" | od -An -tx1 | tr -d ' \n')" = "89504e470d0a1a0a" ] || fail "the screenshot is not a PNG"
size=$(stat -c %s "$out/report.png")
[ "$size" -gt 20000 ] || fail "the screenshot is only $size bytes: a blank page?"
# The page has no script: any console line (an error, a failed load) is a defect.
if grep -E "CONSOLE|Uncaught|Failed to load" "$out/chromium.log"; then fail "the page logged to the console (above)"; fi
for q in cast_segment_cylinder collide_cylinder_capsule; do
  grep -q "<h2 id=\"$q\">" "$out/dom.html" || fail "no section for $q"
done
grep -q "<h2 id=\"precision\">" "$out/dom.html" || fail "no precision table"
for col in depth normal point distance; do
  grep -q "<th>$col</th>" "$out/dom.html" || fail "the precision table has no $col column"
done
fcl_rows=$(grep -o "<td class=\"l\">FCL</td>" "$out/dom.html" | wc -l)
[ "$fcl_rows" -eq 2 ] || fail "$fcl_rows FCL rows in the precision table (2 expected)"
figures=$(grep -o "<figure class=\"cx\">" "$out/dom.html" | wc -l)
views=$(grep -o "<title>[a-z]* view</title>" "$out/dom.html" | wc -l)
[ "$figures" -gt 0 ] || fail "no counterexample drawn (FCL's cast disagreements are expected at this seed)"
[ "$views" -eq $((3 * figures)) ] || fail "$figures figures but $views views (three each expected)"
grep -q "log10 histogram" "$out/dom.html" || fail "no histogram"
# Where other engines ran, production and FCL have rows on the same cases.
python3 - "$out/report/report.json" "$out/dom.html" <<'PY' || fail "no like-for-like rows beside the engines"
import json, sys
rep = json.load(open(sys.argv[1]))
dom = open(sys.argv[2]).read()
for q in rep["queries"]:
    if not q["peers"]:
        continue
    same = q["same_cases"]
    for p in q["peers"]:  # the cases asked plus those the engine cannot state
        assert same["cases"] == p["cases"] + p["not_expressed"], (q["id"], p["engine"], same["cases"], p["cases"])
    assert same["production"]["valid"] <= same["cases"] and same["fcl"]["answered"] <= same["cases"]
    assert f"production (the first {same['cases']}, as the engines)" in dom, q["id"]
    print(f"{q['id']}: production and FCL on the engines' {same['cases']} cases")
PY
# The first screen: the glance matrix (a row per query, a column per engine)
# comes before the tables, each cell links to an element of the page, and its
# colour agrees with report.json's counts; numbers read as numbers (no
# "1e+03" anywhere in the page's text but its code).
python3 - "$out/report/report.json" "$out/dom.html" <<'PY' || fail "the glance matrix or the numbers' form is wrong"
import json, re, sys
from html.parser import HTMLParser
rep = json.load(open(sys.argv[1]))
dom = open(sys.argv[2]).read()
assert '<h2 id="glance">' in dom, "no glance matrix"
assert dom.index('<h2 id="glance">') < dom.index('<h2 id="precision">'), "the glance matrix is not first"
class Page(HTMLParser):
    def __init__(self):
        super().__init__(); self.ids = set(); self.rows = []; self.head = []; self.in_glance = False
        self.cell = None; self.code = 0; self.text = []; self.th = None
    def handle_starttag(self, tag, attrs):
        a = dict(attrs)
        if "id" in a: self.ids.add(a["id"])
        if tag == "code": self.code += 1
        if tag == "table" and a.get("class") == "glance": self.in_glance = True
        if not self.in_glance: return
        if tag == "tr": self.rows.append([])
        if tag == "th": self.th = ""
        if tag == "td": self.cell = {"state": a.get("data-state"), "href": None, "text": ""}; self.rows[-1].append(self.cell)
        if tag == "a" and self.cell is not None and self.cell["href"] is None: self.cell["href"] = a.get("href")
    def handle_endtag(self, tag):
        if tag == "code": self.code -= 1
        if tag == "table": self.in_glance = False
        if tag == "td": self.cell = None
        if tag == "th" and self.th is not None: self.head.append(self.th.strip()); self.th = None
    def handle_data(self, d):
        if not self.code: self.text.append(d)
        if self.cell is not None: self.cell["text"] += d
        if self.th is not None: self.th += d
page = Page(); page.feed(dom)
head, rows = page.head, [r for r in page.rows if r]
assert head[0] == "query" and head[1] == rep["implementation"], head
engines = sorted({p["engine"] for q in rep["queries"] for p in q["peers"]})
assert head[2] == "FCL" and sorted(head[3:]) == engines, (head, engines)
assert len(rows) == len(rep["queries"]), (len(rows), len(rep["queries"]))
def judged(cell, bad, what):
    assert cell["state"] in ("ok", "near", "bad"), (what, cell)
    assert (cell["state"] == "bad") >= bad, (what, "counts say bad, the cell says", cell["state"])
for q, row in zip(rep["queries"], rows):
    assert row[0]["text"].strip() == q["id"] and len(row) == len(head), (q["id"], len(row))
    for c in row:
        assert c["href"] and c["href"][1:] in page.ids, (q["id"], "a cell links nowhere", c)
    judged(row[1], q["beyond_band"] > 0 or q["check_failures"] > 0, q["id"])
    f = q["fcl"]
    assert row[2]["state"] == ("bad" if f["beyond_band"] + f["distance_verdicts_beyond_band"] else "ok"), (q["id"], "FCL")
    for p in q["peers"]:
        judged(row[head.index(p["engine"])], p["beyond_band"] > 0 or p["check_failures"] > 0, (q["id"], p["engine"]))
text = " ".join(page.text)
exp = re.findall(r"(?<![\w.-])\d+(?:\.\d+)?[eE][+-]?\d+(?![\w-])", text)  # a generator mode's name ("coaxial-1e-8-deep") is a word
assert not exp, f"numbers in e-notation in the page's text: {exp[:5]}"
assert "\u00d710" in text, "no number written as a power of ten"
print(f"glance: {len(rows)} queries x {len(head) - 1} engines, every cell linked and coloured as report.json counts")
PY
# The tails show: every non-empty bin has a bar of visible height, and the
# histograms of bounded errors draw their bound.
python3 - "$out/dom.html" <<'PY' || fail "a histogram hides a non-empty bin, or draws no bound"
import re, sys
dom = open(sys.argv[1]).read()
bars = re.findall(r'<rect [^>]*height="(\d+)"[^>]*data-count="(\d+)"', dom)
assert bars, "no histogram bars"
hidden = [(h, n) for h, n in bars if int(n) > 0 and int(h) < 3]
assert not hidden, f"{len(hidden)} non-empty bins drawn below 3 px: {hidden[:5]}"
assert "bound " in dom and 'stroke-dasharray="3,2"' in dom, "no bound line"
print(f"histograms: {sum(int(n) > 0 for h, n in bars)} non-empty bins, all visible")
PY
# Every drawing carries the oracle's witness and FCL's answer in its legend,
# and at this seed both kinds of witness geometry appear.
witnesses=$(grep -o "&#9679; oracle: \|● oracle: " "$out/dom.html" | wc -l)
fcl_marks=$(grep -o "&#9679; FCL: \|● FCL: " "$out/dom.html" | wc -l)
[ "$witnesses" -eq "$figures" ] || fail "$figures figures but $witnesses oracle witnesses"
[ "$fcl_marks" -eq "$figures" ] || fail "$figures figures but $fcl_marks FCL answers"
grep -q "oracle: nearest points" "$out/dom.html" || fail "no nearest-points witness drawn"
grep -q "oracle: first touch S(t)\|oracle: overlapping, depth" "$out/dom.html" || fail "no first-touch or penetration witness drawn"
echo "report page: $figures disagreements drawn in $views views ($witnesses oracle witnesses, $fcl_marks FCL answers), screenshot $out/report.png ($size bytes), no console errors"
