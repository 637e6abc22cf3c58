#!/bin/sh
# A user's clone has no ../shared beside it: copies the repository's files (those git tracks or
# would track, else the tree without build folders) to a new temporary folder, configures it, and
# runs the catalogue test there, which must be reported skipped with its reason. Nothing is built:
# that test needs only Python, and a full build would double the cost of ./test.sh's ctest stage.
# Usage: fresh_copy_skips_catalogue.sh SOURCE_DIR
set -eu
src=$1
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
mkdir "$tmp/repo"
if git -C "$src" rev-parse --is-inside-work-tree > /dev/null 2>&1; then
  # The tracked files and the new ones not yet added (not the ignored), as they are on disk.
  (cd "$src" && git ls-files -z --cached --others --exclude-standard |
    xargs -0 sh -c 'for f; do [ -f "$f" ] && printf "%s\0" "$f"; done' sh |
    xargs -0 cp --parents -t "$tmp/repo")
else
  (cd "$src" && tar --exclude='./build*' --exclude=./out --exclude=node_modules -cf - .) |
    tar -C "$tmp/repo" -xf -
fi
test ! -e "$tmp/shared"
test ! -e "$tmp/repo/srs/GamePhysics_SRS.md"
cmake -S "$tmp/repo" -B "$tmp/repo/build" > "$tmp/configure.txt" 2>&1 || {
  cat "$tmp/configure.txt"
  exit 1
}
grep -F 'get GamePhysics_SRS.md from the Drasil project' "$tmp/configure.txt"
ctest --test-dir "$tmp/repo/build" -R '^srs\.catalogue_matches_srs$' -V > "$tmp/ctest.txt" 2>&1 || {
  cat "$tmp/ctest.txt"
  exit 1
}
cat "$tmp/ctest.txt"
grep -q 'srs\.catalogue_matches_srs .*Skipped' "$tmp/ctest.txt"
grep -q 'skipped: no SRS Markdown; get GamePhysics_SRS.md from the Drasil project' "$tmp/ctest.txt"
