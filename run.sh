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
if [ "$tests_status" -ne 0 ]; then
  echo "run.sh: unit tests failed (gamephysics_tests exit $tests_status; see build/test-results.xml)" >&2
  exit 1
fi
exit "$verify_status"
