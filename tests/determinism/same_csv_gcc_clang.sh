#!/bin/sh
# Determinism across compilers: every shipped scene under each integrator, simulated by a gcc
# build and by a clang build of `gamephysics`, must give the same CSV to the byte (both Release,
# no -ffast-math: IEEE arithmetic in the order the source gives). Fails on any difference.
# Usage: same_csv_gcc_clang.sh GCC_GAMEPHYSICS CLANG_GAMEPHYSICS SCENES_DIR OUT_DIR
set -eu
gcc_bin=$1
clang_bin=$2
scenes=$3
out=$4
mkdir -p "$out"
runs=0
failed=0
for scene in "$scenes"/*.json; do
  name=$(basename "$scene" .json)
  for integrator in symplectic_euler velocity_verlet rk4; do
    for compiler in gcc clang; do
      eval bin=\$${compiler}_bin
      "$bin" simulate "$scene" --integrator "$integrator" \
        --out "$out/$name.$integrator.$compiler.csv" > /dev/null
    done
    runs=$((runs + 1))
    if ! cmp -s "$out/$name.$integrator.gcc.csv" "$out/$name.$integrator.clang.csv"; then
      echo "differ: $name with $integrator ($out/$name.$integrator.{gcc,clang}.csv)"
      failed=$((failed + 1))
    fi
  done
done
echo "gcc and clang builds: $((runs - failed)) of $runs scene and integrator runs gave the same CSV"
test "$failed" -eq 0
