#!/usr/bin/env bash
# geomcheck — the point-set door as a user gets it: `cmake --install` of this
# build into a fresh prefix, examples/verify-my-delaunay copied outside the
# source tree and built against it with find_package(geomcheck CONFIG). The
# example's triangulator (exact orientation, an in-circle test in plain
# doubles) must fail `valid` and nothing else, with shrunk point-set files
# and their drawings saved and a printed replay command that reproduces the
# failure; built with its flaw fixed it must pass. A pair's case file given
# to its --replay, and `geomcheck replay --subject` naming a subject the
# file's query does not have, are usage errors (exit 2) for every family.
# usage: test_installed_delaunay.sh CMAKE BUILD_DIR SOURCE_DIR WORK_DIR
set -u
cmake=$1 build=$2 src=$3 work=$4
rm -rf "$work"; mkdir -p "$work"
fail() { echo "FAIL: $*"; exit 1; }
"$cmake" --install "$build" --prefix "$work/prefix" > "$work/install.log" 2>&1 || { cat "$work/install.log"; fail "cmake --install"; }
cp -r "$src/examples/verify-my-delaunay" "$work/example"
gen=(); command -v ninja > /dev/null && gen=(-G Ninja)
"$cmake" -S "$work/example" -B "$work/build" "${gen[@]}" -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH="$work/prefix" \
  > "$work/configure.log" 2>&1 || { cat "$work/configure.log"; fail "configuring the example against the installed package"; }
"$cmake" --build "$work/build" > "$work/build.log" 2>&1 || { cat "$work/build.log"; fail "building the example"; }

"$work/build/verify_my_delaunay" --cases 400 --out "$work/out" > "$work/run.log" 2>&1
status=$?
cat "$work/run.log"
[ "$status" -eq 1 ] || fail "exit status $status (1 expected: the in-circle test in doubles is wrong)"
properties=$(sed -n '/by property/,/saved/p' "$work/run.log" | grep -E '^ +[0-9]+ [a-z][a-z0-9()-]*$' | awk '{print $2}' | sort -u | tr '\n' ' ')
[ "$properties" = "valid " ] || fail "failing properties '$properties' ('valid ' expected: the flaw alone)"
grep -q "points dropped" "$work/run.log" || fail "no saved set was shrunk"
cases=$(find "$work/out" -name '*.case' | wc -l)
pages=$(find "$work/out" -name '*.html' ! -name report.html | wc -l)
[ "$cases" -gt 0 ] || fail "no failing set saved"
[ "$pages" -eq "$cases" ] || fail "$cases point-set files but $pages drawings"
grep -q "<polygon" "$(find "$work/out" -name '*.html' ! -name report.html | head -1)" || fail "the page draws no triangle"
grep -q '"verdict": "failed"' "$work/out/report.json" || fail "report.json does not say the run failed"
grep -q '"subject": "my-delaunay"' "$work/out/report.json" || fail "report.json does not name the subject"
if command -v python3 > /dev/null; then
  python3 "$src/tools/tests/test_report_schema.py" "$src/reports/report.schema.json" "$work/out/report.json"
  [ $? -eq 1 ] && fail "report.json does not validate against reports/report.schema.json"
fi
replay=$(grep -m1 '  replay: ' "$work/run.log" | sed 's/^  replay: //')
[ -n "$replay" ] || fail "no replay command printed"
eval "$replay" > "$work/replay.log" 2>&1
rstatus=$?
cat "$work/replay.log"
[ "$rstatus" -eq 1 ] && grep -q '^FAIL ' "$work/replay.log" || fail "the printed replay command does not reproduce the failure"
saved=$(find "$work/out" -name '*.case' | head -1)
# The command knows production, not the user's triangulator: naming it is a usage error.
"$work/prefix/bin/geomcheck" replay --subject my-delaunay "$saved" > "$work/cli.log" 2>&1
[ $? -eq 2 ] || { cat "$work/cli.log"; fail "geomcheck replay --subject my-delaunay on a point-set file did not exit 2"; }
grep -q "no subject 'my-delaunay' of query delaunay_2d" "$work/cli.log" || { cat "$work/cli.log"; fail "no usage message"; }
# The same for the pair and mesh families.
pair=$(find "$src/corpora/seeds/collide_cylinder_sphere" -name '*.case' | head -1)
mesh=$(find "$src/corpora/seeds/collide_cylinder_mesh" -name '*.case' | head -1)
for f in "$pair" "$mesh"; do
  [ -n "$f" ] || fail "no seed case to replay"
  "$work/prefix/bin/geomcheck" replay --subject no-such-subject "$f" > "$work/cli2.log" 2>&1
  [ $? -eq 2 ] || { cat "$work/cli2.log"; fail "geomcheck replay --subject no-such-subject $f did not exit 2"; }
done
# A pair's case file is not the point-set subject's to replay.
"$work/build/verify_my_delaunay" --replay "$pair" > "$work/wrong.log" 2>&1
[ $? -eq 2 ] || { cat "$work/wrong.log"; fail "--replay of a collide_cylinder_sphere case did not exit 2"; }

"$work/build/verify_my_delaunay_fixed" --cases 400 --out "$work/out-fixed" > "$work/fixed.log" 2>&1 \
  || { cat "$work/fixed.log"; fail "the triangulator with its flaw fixed failed (a false alarm on correct code)"; }
"$work/build/verify_my_delaunay_fixed" --replay "$saved" > "$work/fixed-replay.log" 2>&1 \
  || { cat "$work/fixed-replay.log"; fail "the fixed triangulator fails the saved set"; }
echo "PASS: the inexact in-circle test caught by valid alone ($cases sets saved, shrunk, replayed), fixed it passes; replay --subject is a usage error for every family"
