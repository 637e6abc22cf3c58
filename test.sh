#!/usr/bin/env bash
# Installs what is missing; builds with coverage in build-coverage/, runs ctest, prints the gcovr
# summary and fails when line coverage of models/ plus src/ is under 90%; then builds with
# AddressSanitizer and UndefinedBehaviorSanitizer in build-sanitize/ and runs ctest again, where
# any sanitizer report fails the run; then builds the libFuzzer target over the scene loader with
# clang in build-fuzz/ and fuzzes it with 100000 inputs (about 3 min), where a crash, a hang, a
# leak or a sanitizer report fails the run (verification/fuzz/README.md).
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

CC=clang CXX=clang++ cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=Debug -DGP_FUZZ=ON
cmake --build build-fuzz --target gamephysics_fuzz_scene -j2
mkdir -p build-fuzz/corpus build-fuzz/artifacts
# Seeds: the bad inputs of the tests, the crash inputs found so far and the shipped scenes; new
# inputs go to build-fuzz/corpus, a failing one to build-fuzz/artifacts/. A fixed seed and number
# of inputs (about 3 min here), so that clean checkouts fuzz much the same inputs (README); the time
# limit only guards against a much slower machine. The log is long: its end is printed, with the
# failure's report when there is one.
if ! build-fuzz/bin/gamephysics_fuzz_scene -seed=1 -runs=100000 -max_total_time=300 -timeout=5 \
  -rss_limit_mb=2048 -max_len=32768 -dict=verification/fuzz/scene.dict \
  -artifact_prefix=build-fuzz/artifacts/ \
  -print_final_stats=1 build-fuzz/corpus verification/fuzz/corpus verification/fuzz/crashes scenes \
  > build-fuzz/fuzz.log 2>&1; then
  tail -n 80 build-fuzz/fuzz.log
  echo "fuzzing failed: the input is in build-fuzz/artifacts/, the log in build-fuzz/fuzz.log"
  exit 1
fi
grep -E '^(Done|stat::number_of_executed_units|stat::peak_rss_mb)' build-fuzz/fuzz.log
