#!/bin/sh
# geomcheck — the libFuzzer flags a fuzz target is run with, read from the
# files beside its binary the way ClusterFuzz reads them: the [libfuzzer]
# section of FUZZER.options, each "key = value" as -key=value, the dict
# relative to the binary's folder; FUZZER.dict when the options name none.
# Prints one flag a line (nothing when neither file exists). Used by the
# smoke tests (tests/smoke.sh), scripts/nightly.sh and scripts/cfl-local.sh.
#   usage: options_flags.sh FUZZER
set -u
fuzzer=$1
dir=$(cd "$(dirname "$fuzzer")" && pwd) || exit 1
name=$(basename "$fuzzer")
has_dict=0
if [ -f "$dir/$name.options" ]; then
  flags=$(awk -v dir="$dir" '
    /^[ \t]*([#;]|$)/ { next }
    /^[ \t]*\[/ { section = $0; gsub(/[][ \t\r]/, "", section); next }
    section == "libfuzzer" && index($0, "=") > 0 {
      key = substr($0, 1, index($0, "=") - 1); value = substr($0, index($0, "=") + 1)
      gsub(/^[ \t]+|[ \t\r]+$/, "", key); gsub(/^[ \t]+|[ \t\r]+$/, "", value)
      if (key == "dict" && value !~ /^\//) value = dir "/" value
      print "-" key "=" value
    }' "$dir/$name.options") || exit 1
  [ -n "$flags" ] && printf '%s\n' "$flags"
  case "$flags" in -dict=*|*"
-dict="*) has_dict=1 ;; esac
fi
if [ "$has_dict" -eq 0 ] && [ -f "$dir/$name.dict" ]; then
  printf '%s\n' "-dict=$dir/$name.dict"
fi
exit 0
