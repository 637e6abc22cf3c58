#!/usr/bin/env bash
# Installs what is missing; builds with coverage in build-coverage/, runs ctest, prints the gcovr
# summary and fails when line coverage of models/ plus src/ is under 90%; then builds with
# AddressSanitizer and UndefinedBehaviorSanitizer in build-sanitize/ and runs ctest again, where
# any sanitizer report fails the run.
set -euo pipefail
cd "$(dirname "$0")"
./tools/install-deps.sh
./tools/install-web.sh

cmake -S . -B build-coverage -DCMAKE_BUILD_TYPE=Debug -DGP_COVERAGE=ON
cmake --build build-coverage -j2
find build-coverage -name '*.gcda' -delete
ctest --test-dir build-coverage --output-on-failure -j2
gcovr --root . --filter 'models/' --filter 'src/' --exclude-unreachable-branches \
  --print-summary --fail-under-line 90 build-coverage

cmake -S . -B build-sanitize -DCMAKE_BUILD_TYPE=Debug -DGP_SANITIZE=ON
cmake --build build-sanitize -j2
ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
  ctest --test-dir build-sanitize --output-on-failure -j2
