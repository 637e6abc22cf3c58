#!/bin/sh
# Determinism: `gamephysics simulate SCENE [OPTIONS]` run twice, in two processes (so with
# different heap addresses), must write the same CSV to the byte. Fails on any difference.
# Usage: same_csv_twice.sh GAMEPHYSICS SCENE [OPTIONS...]
set -eu
bin=$1
scene=$2
shift 2
name=$(basename "$scene" .json)
first=determinism_$name.first.csv
second=determinism_$name.second.csv
rm -f "$first" "$second"
"$bin" simulate "$scene" --out "$first" "$@" > /dev/null
"$bin" simulate "$scene" --out "$second" "$@" > /dev/null
if [ $# -gt 0 ]; then echo "$name: shortened with $*"; fi
cmp "$first" "$second"
rows=$(($(wc -l < "$first") - 1))
test "$rows" -gt 0
echo "$name: both runs wrote the same $rows rows"
rm -f "$first" "$second"
