#!/bin/sh
# Checks that HEADER, included alone, pulls in no engine header outside the public list
# (public_headers.txt) and no Eigen module beyond Eigen/Core.
# Usage: check_public_headers.sh CXX SOURCE_DIR BINARY_DIR HEADER
cxx=$1 src=$2 bin=$3 header=$4
dir=$(dirname "$0")
# A probe file of its own: ctest runs this check and its control side by side in one folder.
probe=$(mktemp --suffix=.cpp) || exit 1
trap 'rm -f "$probe"' EXIT
echo "#include \"$header\"" > "$probe"
deps=$("$cxx" -std=c++20 -M -I"$src/src" -I"$bin/scene_include" -I"$src/models/include" \
  -I/usr/include/eigen3 "$probe") || exit 1
bad=$(echo "$deps" | tr ' ' '\n' | grep -o 'src/engine/.*\.hpp' | sed 's#^src/##' |
  grep -vxF -f "$dir/public_headers.txt")
dense=$(echo "$deps" | tr ' ' '\n' | grep -E 'eigen3/Eigen/[A-Z][A-Za-z]*$' | grep -v 'Eigen/Core$')
if [ -n "$bad$dense" ]; then
  echo "$header includes what is not public API:"
  echo "$bad$dense"
  exit 1
fi
echo "$header includes only the public headers"
