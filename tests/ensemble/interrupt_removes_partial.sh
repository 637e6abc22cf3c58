#!/bin/sh
# A command stopped by SIGNAL while it writes OUT removes OUT.partial, keeps the older OUT, prints
# one line and exits 128 + the signal. Usage: interrupt_removes_partial.sh SIGNAL CODE OUT CMD...
set -u
signal=$1 code=$2 out=$3
shift 3
rm -f "$out.partial" "$out.txt"
echo "the older file" > "$out"
"$@" --out "$out" > /dev/null 2> "$out.txt" &
pid=$!
# Wait (up to 20 s) until the run is writing its partial file, then stop it.
n=0
while [ ! -e "$out.partial" ] && [ $n -lt 200 ]; do sleep 0.1; n=$((n + 1)); done
test -e "$out.partial" || { echo "no partial file appeared"; kill $pid; exit 1; }
kill -s "$signal" $pid
wait $pid
status=$?
test $status -eq "$code" || { echo "exit $status, expected $code"; exit 1; }
test ! -e "$out.partial" || { echo "$out.partial left behind"; exit 1; }
test "$(cat "$out")" = "the older file" || { echo "the older $out was not kept"; exit 1; }
test "$(wc -l < "$out.txt")" -eq 1 || { echo "expected one line, got:"; cat "$out.txt"; exit 1; }
grep -q "^interrupted (SIG$signal): partial output removed" "$out.txt" || { cat "$out.txt"; exit 1; }
echo "ok: exit $status, $out.partial removed, the older $out kept: $(cat "$out.txt")"
