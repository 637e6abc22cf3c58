#!/bin/sh
# Determinism across threads and SIMD widths: `gamephysics simulate SCENE OPTION N [OPTIONS]` with
# N = 1, 2 and 4 must write the same CSV to the byte. With --threads, the order of a step's
# arithmetic does not depend on them; with --lanes (doubles the vector paths take at a time:
# SSE2's 2, AVX2's 4, as far as the CPU has them), each lane repeats the one-at-a-time loop's
# operations in its order.
# Usage: same_csv_1_2_4.sh GAMEPHYSICS OPTION SCENE [OPTIONS...]
set -eu
bin=$1
option=$2
scene=$3
shift 3
name=$(basename "$scene" .json)_${option#--}
for n in 1 2 4; do
  rm -f "$name.$n.csv"
  "$bin" simulate "$scene" --out "$name.$n.csv" "$option" "$n" "$@" > /dev/null
done
cmp "$name.1.csv" "$name.2.csv"
cmp "$name.1.csv" "$name.4.csv"
rows=$(($(wc -l < "$name.1.csv") - 1))
test "$rows" -gt 0
echo "$name: $option 1, 2 and 4 wrote the same $rows rows"
rm -f "$name".*.csv
