#!/usr/bin/env bash
# The main job: installs what is missing, builds in Release into build/, and runs the
# verification suite (build/bin/gamephysics verify).
set -euo pipefail
cd "$(dirname "$0")"
./tools/install-deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j2
build/bin/gamephysics verify "$@"
