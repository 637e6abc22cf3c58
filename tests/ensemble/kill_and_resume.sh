#!/bin/sh
# An ensemble stopped by SIGTERM midway keeps its completed chunks, removes nothing else, and
# --resume runs only the missing chunks; the result is the same, to the byte, as an uninterrupted
# run. Usage: kill_and_resume.sh GAMEPHYSICS SCENE ENSEMBLE-OPTIONS...
set -u
bin=$1 scene=$2
shift 2
rm -rf resume_whole resume_killed
"$bin" ensemble "$scene" "$@" --out resume_whole > /dev/null || exit 1
total=$(ls resume_whole/chunks | wc -l)
"$bin" ensemble "$scene" "$@" --out resume_killed > /dev/null 2> resume_killed.txt &
pid=$!
# Stop it as soon as its first chunk is written (polled every 10 ms, with no process started).
n=0
while [ ! -e resume_killed/chunks/chunk_000000.csv ] && [ $n -lt 3000 ]; do
  sleep 0.01
  n=$((n + 1))
done
kill -s TERM $pid
wait $pid
status=$?
test $status -eq 143 || { echo "exit $status, expected 143"; exit 1; }
grep -q "^interrupted (SIGTERM)" resume_killed.txt || { cat resume_killed.txt; exit 1; }
test -z "$(ls resume_killed/chunks | grep -v '^chunk_[0-9]*\.csv$')" || { echo "leftovers:"; ls resume_killed/chunks; exit 1; }
done_chunks=$(ls resume_killed/chunks | wc -l)
test "$done_chunks" -lt "$total" || { echo "the run ended before the signal"; exit 1; }
test ! -e resume_killed/samples.csv || { echo "samples.csv of a stopped run"; exit 1; }
# Without --resume the folder is refused; with it, only the missing chunks run.
"$bin" ensemble "$scene" "$@" --out resume_killed > /dev/null 2>&1
test $? -eq 2 || { echo "a second run without --resume was not refused"; exit 1; }
"$bin" ensemble "$scene" "$@" --out resume_killed --resume > resume_killed.txt || exit 1
grep -qF "; $((total - done_chunks)) of $total chunks to run" resume_killed.txt || { cat resume_killed.txt; exit 1; }
for f in samples.csv energy.csv summary.json; do
  cmp resume_whole/$f resume_killed/$f || exit 1
done
echo "ok: stopped after $done_chunks of $total chunks, resumed, same bytes as one whole run"
