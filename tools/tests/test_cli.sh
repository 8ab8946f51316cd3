#!/usr/bin/env bash
# geomcheck — command-line tests: help, bad arguments, replay verdicts and
# exit codes, both converters. Usage: test_cli.sh GEOMCHECK SOURCE_DIR
set -u
tool=$1; src=$2
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
fails=0; passes=0
ok() { passes=$((passes + 1)); }
bad() { echo "FAILED: $*"; fails=$((fails + 1)); }
expect_rc() {  # expected-rc description command...
  local want=$1 what=$2; shift 2
  "$@" > "$tmp/out" 2>&1; local rc=$?
  if [ "$rc" = "$want" ]; then ok; else bad "$what: exit $rc, wanted $want"; sed 's/^/    /' "$tmp/out" | head -20; fi
}

expect_rc 0 "--help" "$tool" --help
grep -q "campaign" "$tmp/out" && grep -q "replay" "$tmp/out" && ok || bad "--help lists the commands"
expect_rc 2 "unknown command" "$tool" frobnicate
grep -q "frobnicate" "$tmp/out" && ok || bad "unknown command is named"
expect_rc 2 "no command" "$tool"
expect_rc 0 "--version" "$tool" --version
grep -q "^geomcheck [0-9]" "$tmp/out" && ok || bad "--version says the version"
for cmd in campaign replay from-fuzz from-rapidcheck queries; do
  expect_rc 0 "$cmd --help" "$tool" $cmd --help
  grep -q "Usage: .* $cmd" "$tmp/out" && ok || bad "$cmd --help is the command's own help"
done
# Strict numbers: a usage error (2), the option named.
expect_rc 2 "--cases 10abc" "$tool" campaign --cases 10abc --out "$tmp/x"
grep -q -- "--cases: '10abc'" "$tmp/out" && ok || bad "--cases 10abc is named"
expect_rc 2 "--seconds -1" "$tool" campaign --seconds -1 --out "$tmp/x"
expect_rc 2 "--cases 0" "$tool" campaign --cases 0 --out "$tmp/x"
expect_rc 2 "--threads x" "$tool" campaign --threads x --out "$tmp/x"
# Nothing to replay is an input error, not a pass.
mkdir -p "$tmp/empty"
expect_rc 2 "replay of an empty directory" "$tool" replay "$tmp/empty"
grep -q "no .case file under" "$tmp/out" && ok || bad "an empty directory is named"
expect_rc 2 "replay of a missing file" "$tool" replay "$tmp/nope.case"
grep -q "no such file" "$tmp/out" && ok || bad "missing file is named"
expect_rc 0 "queries" "$tool" queries
grep -q "cast_segment_cylinder" "$tmp/out" && ok || bad "queries lists cast_segment_cylinder"
grep -q "^delaunay_2d  *point-set" "$tmp/out" && ok || bad "queries lists delaunay_2d as a point-set query"
grep -q "^collide_cylinder_mesh  *mesh" "$tmp/out" && ok || bad "queries lists collide_cylinder_mesh as a mesh query"
[ "$(awk '{ match($0, /^[^ ]+ +/); print RLENGTH }' "$tmp/out" | sort -u | wc -l)" = 1 ] && ok || bad "queries' family column starts at one column on every line"

# The mesh family runs in the campaign: its own section in report.json.
expect_rc 0 "campaign of collide_cylinder_mesh" "$tool" campaign --query collide_cylinder_mesh --cases 60 --no-progress --out "$tmp/mesh"
python3 -c "import json,sys; q=json.load(open(sys.argv[1]))['mesh_queries']; sys.exit(0 if [x['id'] for x in q] == ['collide_cylinder_mesh'] and q[0]['meshes'] == 60 and q[0]['failures'] == 0 and q[0]['faces_by_engine'] > 0 else 1)" "$tmp/mesh/report.json" && ok || bad "report.json has collide_cylinder_mesh's 60 meshes"
# Its known-wrong variant is caught: saved as a mesh file, drawn beside it, and replayed as failing.
expect_rc 1 "campaign of the mesh variant" "$tool" campaign --variant mesh_first_face --cases 300 --no-progress --out "$tmp/meshv"
cx=$(ls "$tmp"/meshv/counterexamples/collide_cylinder_mesh/*.case 2>/dev/null | head -1)
[ -n "$cx" ] && [ -s "${cx%.case}.html" ] && grep -q "<svg" "${cx%.case}.html" && ok || bad "the variant's counterexample is saved with its drawing"
expect_rc 1 "replay of the variant's counterexample" "$tool" replay --subject mesh_first_face "$cx"
expect_rc 0 "replay of the variant's counterexample with production" "$tool" replay "$cx"
# A mesh seed replays; with a wrong filed verdict it fails.
expect_rc 0 "replay of a mesh seed" "$tool" replay "$src/corpora/seeds/collide_cylinder_mesh/rim-on-shared-edge.case"
grep -q "truth: touching" "$tmp/out" && ok || bad "replay shows the mesh's exact verdict"
sed 's/^oracle-verdict touching$/oracle-verdict separated/' "$src/corpora/seeds/collide_cylinder_mesh/rim-on-shared-edge.case" > "$tmp/mesh.case"
expect_rc 1 "replay of a mesh filed with a wrong verdict" "$tool" replay "$tmp/mesh.case"
grep -q "the truth differs" "$tmp/out" && ok || bad "wrong filed mesh verdict is pointed out"
# The benchmark's size of mesh (a 224 x 224 heightfield, 100352 faces) replays from its file.
python3 - "$tmp/big.case" <<'PY'
import math, sys
n = 224
lines = ["geomcheck-case 1", "query collide_cylinder_mesh", "found-by hand", "note a 224 x 224 heightfield",
         "cylinder 0.1 0.2 0.05 0.6 0.1 1.2 0.3"]
for i in range(n + 1):
    for j in range(n + 1):
        x, y = -4 + 8 * i / n, -4 + 8 * j / n
        lines.append("vertex %r %r %r" % (x, y, 0.1 * math.sin(3 * x) * math.cos(2 * y)))
at = lambda i, j: i * (n + 1) + j
for i in range(n):
    for j in range(n):
        lines += ["face %d %d %d" % (at(i, j), at(i + 1, j), at(i + 1, j + 1)),
                  "face %d %d %d" % (at(i, j), at(i + 1, j + 1), at(i, j + 1))]
open(sys.argv[1], "w").write("\n".join(lines + ["end"]) + "\n")
PY
expect_rc 0 "replay of a 100352-face mesh" "$tool" replay "$tmp/big.case"
grep -q "50625 vertices, 100352 faces" "$tmp/out" && grep -q "truth: overlapping" "$tmp/out" && ok || bad "the large mesh replays with its truth"

# The point-set family runs in the campaign: its own section in report.json.
expect_rc 0 "campaign of delaunay_2d" "$tool" campaign --query delaunay_2d --cases 200 --no-progress --out "$tmp/dl"
python3 -c "import json,sys; q=json.load(open(sys.argv[1]))['point_set_queries']; sys.exit(0 if [x['id'] for x in q] == ['delaunay_2d'] and q[0]['sets'] == 200 and q[0]['failures'] == 0 else 1)" "$tmp/dl/report.json" && ok || bad "report.json has delaunay_2d's 200 sets"
# A run cut by --seconds says so: requested and run counts, and a rerun line with --seconds.
expect_rc 0 "campaign cut by --seconds" "$tool" campaign --query collide_cylinder_capsule --cases 100000 --seconds 0.5 --no-progress --out "$tmp/cut"
python3 - "$tmp/cut/report.json" <<'PY' && ok || bad "a run cut by --seconds reports requested, run and the cut"
import json, sys
r = json.load(open(sys.argv[1]))
q = r["queries"][0]
assert q["requested"] == 100000 and 0 < q["cases"] < 100000 and q["stopped_by_time"], q
assert "--seconds 0.5" in r["replay"] and r["verdict"] == "passed" and r["schema_version"] >= 1, r["replay"]
PY
expect_rc 2 "campaign of an unknown query" "$tool" campaign --query nosuchquery --no-progress --out "$tmp/x"

# A malformed file: replay fails with the parser's line number.
mal=$(ls "$src"/corpora/tests/malformed/*.case | head -1)
"$tool" replay "$mal" > "$tmp/out" 2> "$tmp/err"; rc=$?
[ "$rc" = 2 ] && ok || bad "replay of a malformed file: exit $rc, wanted 2"
grep -q "$(basename "$mal"): line [0-9]" "$tmp/err" && ok || bad "malformed file error names the file and a line, on stderr"

# A seed replays and passes; with a wrong filed verdict it fails.
seed=$(ls "$src"/corpora/seeds/collide_cylinder_sphere/*.case | head -1)
expect_rc 0 "replay of a seed" "$tool" replay "$seed"
grep -q "production:" "$tmp/out" && grep -q "oracle:" "$tmp/out" && grep -q "FCL:" "$tmp/out" && ok || bad "replay shows production, oracle and FCL"
cat > "$tmp/wrong.case" <<'CASE'
geomcheck-case 1
query collide_cylinder_sphere
found-by hand
oracle-verdict separated
shape cylinder
  p 0 0 0
  q 0 0 2
  r 1
shape sphere
  c 0 0 1
  r 0.5
end
CASE
expect_rc 1 "replay of a case filed with a wrong verdict" "$tool" replay "$tmp/wrong.case"
grep -q "the oracle now says otherwise" "$tmp/out" && ok || bad "wrong filed verdict is pointed out"

# A verdict filed on invalid input (a NaN radius) is wrong: the truth there is "invalid".
sed 's/^  r 0.5$/  r nan/' "$tmp/wrong.case" | sed 's/^oracle-verdict separated$/oracle-verdict overlapping/' > "$tmp/nan.case"
expect_rc 1 "replay of a verdict filed on invalid input" "$tool" replay "$tmp/nan.case"
grep -q "filed on invalid input" "$tmp/out" && ok || bad "a verdict filed on invalid input is pointed out"

# A point-set seed (query delaunay_2d) replays; with a wrong filed verdict it fails.
expect_rc 0 "replay of a point-set seed" "$tool" replay "$src/corpora/seeds/delaunay_2d/square-cocircular.case"
grep -q "kind of the point set: triangulated" "$tmp/out" && ok || bad "replay shows the kind of the point set"
sed 's/^oracle-verdict triangulated$/oracle-verdict collinear/' "$src/corpora/seeds/delaunay_2d/square-cocircular.case" > "$tmp/ps.case"
expect_rc 1 "replay of a point set filed with a wrong verdict" "$tool" replay "$tmp/ps.case"
grep -q "the points are of another kind" "$tmp/out" && ok || bad "wrong filed point-set verdict is pointed out"

# from-rapidcheck: a printed counterexample becomes a case that replays.
echo 'Falsifiable... (cylinder{p=(0x0p+0, 0x0p+0, 0x0p+0), q=(0x0p+0, 0x0p+0, 0x1p+1), r=0x1p+0}, sphere{c=(0x1p+1, 0x0p+0, 0x1p+0), r=0x1p+0}, "side")' > "$tmp/rc.txt"
expect_rc 0 "from-rapidcheck" "$tool" from-rapidcheck collide_cylinder_sphere "$tmp/rc.txt" -o "$tmp/rc.case"
expect_rc 0 "replay of the converted RapidCheck case" "$tool" replay "$tmp/rc.case"
grep -q "touching" "$tmp/out" && ok || bad "converted RapidCheck case is the touching sphere"
expect_rc 2 "from-rapidcheck without shapes" "$tool" from-rapidcheck collide_cylinder_sphere /dev/null

# from-fuzz: raw bytes (mode byte, then doubles) become a case that replays.
python3 - "$tmp/crash" <<'PY'
import struct, sys
# mode byte 0 (raw), then segment a, b and cylinder p, q, r as little-endian doubles
open(sys.argv[1], 'wb').write(b'\x00' + struct.pack('<13d', -3,0,1, 3,0,1, 0,0,0, 0,0,2, 1))
PY
expect_rc 0 "from-fuzz" "$tool" from-fuzz cast_segment_cylinder "$tmp/crash" -o "$tmp/fz.case"
expect_rc 0 "replay of the converted fuzz case" "$tool" replay "$tmp/fz.case"
grep -q "hit side" "$tmp/out" && ok || bad "converted fuzz case is the side hit"
expect_rc 2 "from-fuzz with an unknown query" "$tool" from-fuzz nosuchquery "$tmp/crash"

echo "cli: $passes passed, $fails failed"
[ "$fails" = 0 ]
