#!/usr/bin/env bash
# Runs one entry of tests/cli/bad_input.txt: the exit code and the message must be the
# expected ones, within 60 s.   bad_input_test.sh EXE SRC OUT NAME
set -u
exe="$1"; src="$2"; out="$3"; name="$4"
line=$(grep -E "^$name \| " "$src/tests/cli/bad_input.txt") || { echo "no entry $name"; exit 1; }
IFS='|' read -r _ want regex args <<< "$line"
want=$(echo $want); regex=$(echo "$regex" | sed 's/^ *//; s/ *$//'); args=$(echo "$args" | sed 's/^ *//')
rm -rf "$out/$name"; mkdir -p "$out"
args=${args//@CASES@/$src/cases}; args=${args//@IN@/$src/tests/cli/inputs}; args=${args//@OUT@/$out/$name}
eval "set -- $args"
timeout 60 "$exe" "$@" > "$out/$name.txt" 2>&1; rc=$?
echo "debrisflow $*"; echo "exit $rc"; cat "$out/$name.txt"
[ $rc -ne 124 ] || { echo "FAIL: no answer within 60 s"; exit 1; }
[ "$rc" = "$want" ] || { echo "FAIL: exit $rc, expected $want"; exit 1; }
grep -Eq -- "$regex" "$out/$name.txt" || { echo "FAIL: output does not match: $regex"; exit 1; }
echo "OK"
