#!/usr/bin/env bash
# Installs what is missing, builds with coverage in build-coverage/, runs ctest, prints the gcovr
# summary, and fails when line coverage of models/ plus src/ is under 90%.
set -euo pipefail
cd "$(dirname "$0")"
./tools/install-deps.sh
cmake -S . -B build-coverage -DCMAKE_BUILD_TYPE=Debug -DGP_COVERAGE=ON
cmake --build build-coverage -j2
find build-coverage -name '*.gcda' -delete
ctest --test-dir build-coverage --output-on-failure -j2
gcovr --root . --filter 'models/' --filter 'src/' --exclude-unreachable-branches \
  --print-summary --fail-under-line 90 build-coverage
