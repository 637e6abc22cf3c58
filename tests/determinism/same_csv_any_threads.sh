#!/bin/sh
# Determinism across threads: `gamephysics simulate SCENE [OPTIONS]` on 1, 2 and 4 threads must
# write the same CSV to the byte, as the order of a step's arithmetic does not depend on them.
# Usage: same_csv_any_threads.sh GAMEPHYSICS SCENE [OPTIONS...]
set -eu
bin=$1
scene=$2
shift 2
name=$(basename "$scene" .json)
for n in 1 2 4; do
  rm -f "threads_$name.$n.csv"
  "$bin" simulate "$scene" --out "threads_$name.$n.csv" --threads "$n" "$@" > /dev/null
done
cmp "threads_$name.1.csv" "threads_$name.2.csv"
cmp "threads_$name.1.csv" "threads_$name.4.csv"
rows=$(($(wc -l < "threads_$name.1.csv") - 1))
test "$rows" -gt 0
echo "$name: 1, 2 and 4 threads wrote the same $rows rows"
rm -f "threads_$name".*.csv
