#!/usr/bin/env bash
# The main job: installs what is missing, builds in Release into build/, and runs the
# verification suite (build/bin/gamephysics verify), whose audit page shows the unit tests' results.
set -euo pipefail
cd "$(dirname "$0")"
./tools/install-deps.sh
./tools/install-web.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j2
# The unit tests' results, for the audit page (out/report/audit.html), which shows the failures
# too: a failed test does not stop the main job from writing its report, but fails it at the end.
tests_status=0
build/bin/gamephysics_tests -r junit -o build/test-results.xml > /dev/null || tests_status=$?
verify_status=0
build/bin/gamephysics verify --test-results build/test-results.xml "$@" || verify_status=$?
# gcc and clang Release builds must give the same CSV to the byte on every shipped scene: a clang
# build of the command line program in build-clang/ (tests/determinism/same_csv_gcc_clang.sh).
compilers_status=0
CC=clang CXX=clang++ cmake -S . -B build-clang -DCMAKE_BUILD_TYPE=Release > /dev/null
cmake --build build-clang -j2 --target gamephysics_cli > /dev/null
tests/determinism/same_csv_gcc_clang.sh build/bin/gamephysics build-clang/bin/gamephysics scenes \
  build/compilers || compilers_status=$?
# And a pile solved colour by colour, whose one-point contacts go four at a time (AVX2).
mkdir -p build/compilers/coloured
cp build/scenes/bench/rain1000_coloured.json build/compilers/coloured/
tests/determinism/same_csv_gcc_clang.sh build/bin/gamephysics build-clang/bin/gamephysics \
  build/compilers/coloured build/compilers || compilers_status=$?
# The figures of README.md and docs/ against this report (tests/docs/README.md); not after --quick
# or --out, whose report is not the full one in out/report that they come from.
figures_status=0
if [[ " $* " != *" --quick "* && " $* " != *" --out"* ]]; then
  python3 tests/docs/check_figures.py --root . --bin build/bin/gamephysics --report out/report \
    > build/figures.txt || figures_status=$?
  grep -v '^ok' build/figures.txt || true
fi
if [ "$tests_status" -ne 0 ]; then
  echo "run.sh: unit tests failed (gamephysics_tests exit $tests_status; see build/test-results.xml)" >&2
  exit 1
fi
if [ "$compilers_status" -ne 0 ]; then
  echo "run.sh: gcc and clang builds gave different CSVs (build/compilers)" >&2
  exit 1
fi
if [ "$figures_status" -ne 0 ]; then
  echo "run.sh: a figure of README.md or docs/ is not what the program gives (build/figures.txt)" >&2
  exit 1
fi
exit "$verify_status"
