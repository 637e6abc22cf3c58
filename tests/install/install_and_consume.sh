#!/bin/sh
# Installs the build into a new prefix, builds examples/two_bodies.cpp in the separate project
# tests/install/consumer with find_package(gamephysics) against that prefix alone, and runs it
# and the installed command line.
# Usage: install_and_consume.sh BUILD_DIR SOURCE_DIR [LINK_FLAGS [PYTHON]]: LINK_FLAGS the build's
# own (e.g. --coverage, which a static library built with them needs); PYTHON, when the build has
# the Python module, imports the installed one.
set -eu
build=$1
src=$2
flags=${3:-}
python=${4:-}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cmake --install "$build" --prefix "$tmp/prefix" > "$tmp/install.txt"
test -f "$tmp/prefix/lib/cmake/gamephysics/gamephysicsConfig.cmake"
test -f "$tmp/prefix/lib/cmake/gamephysics/gamephysicsConfigVersion.cmake"
test -f "$tmp/prefix/include/gamephysics/gamephysics/gamephysics.hpp"
cmake -S "$src/tests/install/consumer" -B "$tmp/consumer" -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_PREFIX_PATH="$tmp/prefix" -DGP_PROGRAM="$src/examples/two_bodies.cpp" \
  -DCMAKE_EXE_LINKER_FLAGS="$flags" > "$tmp/configure.txt"
cmake --build "$tmp/consumer" > "$tmp/build.txt"
"$tmp/consumer/two_bodies" > "$tmp/run.txt"
cat "$tmp/run.txt"
# Free fall from 5 m to t = 0.5 s: y = 5 − ½ 9.81 · 0.5² = 3.77375 m.
grep -Eq '^t=0\.50 s  y=3\.773[78] m' "$tmp/run.txt"
"$tmp/prefix/bin/gamephysics" simulate "$src/scenes/projectile.json" --out "$tmp/projectile.csv"
test "$(head -n 1 "$tmp/projectile.csv")" = t,body,x,y,angle,vx,vy,omega
if [ -n "$python" ]; then
  PYTHONPATH="$tmp/prefix/lib/python3/dist-packages" "$python" -c \
    'import gamephysics, gamephysics.models.dd as dd; assert dd.kinetic_energy(2.0, (3.0, 4.0)) == 25.0; print("installed module:", gamephysics.__file__)'
fi
