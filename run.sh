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
# too: a failed test does not stop the main job.
build/bin/gamephysics_tests -r junit -o build/test-results.xml > /dev/null || true
build/bin/gamephysics verify --test-results build/test-results.xml "$@"
