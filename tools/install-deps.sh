#!/usr/bin/env bash
# Installs the Debian packages GamePhysics builds and tests with, only when some are missing,
# so that ./run.sh and ./test.sh work on a fresh Debian machine run as root.
set -euo pipefail

packages=(
  build-essential cmake
  ninja-build          # ./test.sh's builds
  libeigen3-dev        # every vector and matrix
  libsundials-dev      # the oracle: CVODE and ARKODE
  catch2               # unit tests (catch2/catch.hpp)
  gcovr                # coverage summary in ./test.sh
  nlohmann-json3-dev   # all JSON: catalogue, scenes
  libcli11-dev         # the command line
  libboost-dev         # Boost.Units for the dimensional audit, Boost.Random's Sobol sequence
  libtbb-dev           # the step on several threads (src/engine), the ensembles (verification/ensemble)
  libopenmpi-dev openmpi-bin  # the ensembles across processes and machines (optional at build)
  libchipmunk-dev libbox2d-dev libbenchmark-dev  # peer engines and benchmarks (verification/)
  python3-matplotlib   # the plots of the verify report (run with /usr/bin/python3)
  pybind11-dev python3-dev python3-numpy python3-pytest  # the Python module (python/) and its tests
  python3-nbconvert python3-ipykernel  # the notebook test (docs/notebooks/)
  nodejs               # npm: KaTeX for the audit page, playwright-core (tools/install-web.sh)
  chromium             # headless browser of the browser tests (tests/browser/)
  clang libclang-rt-14-dev  # ./test.sh's libFuzzer target; ./run.sh's gcc-vs-clang CSV check
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "installing: ${missing[*]}"
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq
  apt-get install -y --no-install-recommends "${missing[@]}"
fi
