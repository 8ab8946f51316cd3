#!/usr/bin/env bash
# geomcheck — the package as a user gets it: `cmake --install` of this build
# into a fresh prefix, examples/verify-my-collide copied outside the source
# tree and built against it with find_package(geomcheck CONFIG), then run.
# The example's collide (single precision, declared as such) has one
# deliberate bug, so the run must exit 1 with that bug's property alone
# (oracle-point: float code judged by float bounds has no other failure),
# save failing cases with their drawings, and print a replay command that
# reproduces the failure; the same code with the bug fixed
# (verify_my_collide_fixed) must pass 2000 cases; a run of production's own
# collide through the same door (the float code swapped out) must pass; and,
# where clang is, the example's libFuzzer target must find a failure. The
# run's report.json validates against the schema.
# usage: test_installed_example.sh CMAKE BUILD_DIR SOURCE_DIR WORK_DIR
set -u
cmake=$1 build=$2 src=$3 work=$4
rm -rf "$work"; mkdir -p "$work"
fail() { echo "FAIL: $*"; exit 1; }
"$cmake" --install "$build" --prefix "$work/prefix" > "$work/install.log" 2>&1 || { cat "$work/install.log"; fail "cmake --install"; }
[ -f "$work/prefix/lib/cmake/geomcheck/geomcheckConfig.cmake" ] || fail "no geomcheckConfig.cmake installed"
cp -r "$src/examples/verify-my-collide" "$work/example"
# The same example with production's collide in place of the float one: the door must let a right answer pass.
sed -e 's/const MyContact k = my_collide.*/return geomcheck::collide(c, s);/' -e '/return Contact{k.hit/d' \
    -e 's/"my-float-collide"/"production-through-verify"/' "$work/example/my_collide.hpp" > "$work/example/production.hpp"
grep -q "return geomcheck::collide(c, s);" "$work/example/production.hpp" || fail "could not derive the production variant"
sed 's/my_collide.hpp/production.hpp/' "$work/example/main.cpp" > "$work/example/main_production.cpp"
cat >> "$work/example/CMakeLists.txt" <<'CM'
add_executable(verify_production main_production.cpp)
target_link_libraries(verify_production PRIVATE geomcheck::subjects)
CM
gen=(); command -v ninja > /dev/null && gen=(-G Ninja)
"$cmake" -S "$work/example" -B "$work/build" "${gen[@]}" -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH="$work/prefix" \
  > "$work/configure.log" 2>&1 || { cat "$work/configure.log"; fail "configuring the example against the installed package"; }
"$cmake" --build "$work/build" > "$work/build.log" 2>&1 || { cat "$work/build.log"; fail "building the example"; }

"$work/build/verify_my_collide" --cases 400 --out "$work/out" > "$work/run.log" 2>&1
status=$?
cat "$work/run.log"
[ "$status" -eq 1 ] || fail "exit status $status (1 expected: the float collide is wrong)"
properties=$(sed -n '/by property/,/saved/p' "$work/run.log" | grep -E '^ +[0-9]+ [a-z][a-z0-9()-]*$' | awk '{print $2}' | sort -u | tr '\n' ' ')
[ "$properties" = "oracle-point " ] || fail "failing properties '$properties' ('oracle-point ' expected: the deliberate bug alone)"
cases=$(find "$work/out" -name '*.case' | wc -l)
pages=$(find "$work/out" -name '*.html' ! -name report.html | wc -l)
[ "$cases" -gt 0 ] || fail "no failing case saved"
[ "$pages" -eq "$cases" ] || fail "$cases case files but $pages drawings"
grep -q "<svg" "$(find "$work/out" -name '*.html' ! -name report.html | head -1)" || fail "the page has no drawing"
# The run's report: report.html, and report.json valid against the schema with the failure in it.
[ -f "$work/out/report.html" ] || fail "no report.html"
grep -q '"verdict": "failed"' "$work/out/report.json" || fail "report.json does not say the run failed"
if command -v python3 > /dev/null; then
  python3 "$src/tools/tests/test_report_schema.py" "$src/reports/report.schema.json" "$work/out/report.json"
  [ $? -eq 1 ] && fail "report.json does not validate against reports/report.schema.json"
fi
replay=$(grep -m1 '  replay: ' "$work/run.log" | sed 's/^  replay: //')
[ -n "$replay" ] || fail "no replay command printed"
$replay > "$work/replay.log" 2>&1
rstatus=$?
cat "$work/replay.log"
[ "$rstatus" -eq 1 ] && grep -q '^FAIL ' "$work/replay.log" || fail "the printed replay command does not reproduce the failure"

"$work/build/verify_my_collide_fixed" --cases 2000 --out "$work/out-fixed" > "$work/fixed.log" 2>&1 \
  || { cat "$work/fixed.log"; fail "the float collide with its bug fixed failed (a false alarm on correct float code)"; }
"$work/build/verify_production" --cases 400 --out "$work/out-production" > "$work/production.log" 2>&1 \
  || { cat "$work/production.log"; fail "production's collide through the same door failed"; }
# With clang: the same subject as a libFuzzer target (geomcheck::fuzzing) finds a failing input.
fuzz="not built (no clang++)"
if command -v clang++ > /dev/null; then
  "$cmake" -S "$work/example" -B "$work/build-clang" "${gen[@]}" -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER=clang++ \
    -DCMAKE_PREFIX_PATH="$work/prefix" > "$work/configure-clang.log" 2>&1 || { cat "$work/configure-clang.log"; fail "configuring with clang"; }
  "$cmake" --build "$work/build-clang" --target fuzz_my_collide > "$work/build-clang.log" 2>&1 \
    || { cat "$work/build-clang.log"; fail "building the fuzz target"; }
  (cd "$work" && "$work/build-clang/fuzz_my_collide" -seed=1 -runs=200000 -max_total_time=120) > "$work/fuzz.log" 2>&1
  fstatus=$?
  tail -20 "$work/fuzz.log"
  [ "$fstatus" -ne 0 ] && grep -q "==== geomcheck collide_cylinder_sphere property failed" "$work/fuzz.log" \
    || fail "the fuzz target did not find the float collide's failure (exit $fstatus)"
  fuzz="the fuzz target finds it too"
fi
[ -x "$work/prefix/bin/geomcheck" ] || fail "cmake --install did not install the geomcheck command"
echo "PASS: installed package found, the float collide's bug caught by oracle-point alone ($cases cases saved), fixed it passes, production passes; $fuzz"
