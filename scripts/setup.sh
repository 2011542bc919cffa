#!/usr/bin/env bash
# Installs the Debian packages holefill needs (when run as root; otherwise prints the exact
# apt-get line), then configures and builds everything in Release with all cores.
# Used by scripts/run.sh and scripts/test.sh; BUILD_DIR overrides the build folder (build/).
set -euo pipefail
cd "$(dirname "$0")/.."

PACKAGES=(
  g++ cmake ninja-build pkg-config
  libopenmesh-dev libeigen3-dev libgmp-dev libnanoflann-dev libtinyobjloader-dev
  libgtest-dev libbenchmark-dev libcli11-dev nlohmann-json3-dev
  libglfw3-dev libglm-dev libimgui-dev libepoxy-dev libstb-dev
  xvfb xauth libgl1-mesa-dri
  xdotool libx11-dev
  python3-dev python3-pybind11 python3-numpy python3-pytest
)

missing=()
for package in "${PACKAGES[@]}"; do
  dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed" ||
    missing+=("$package")
done
if [ ${#missing[@]} -gt 0 ]; then
  if [ "$(id -u)" = 0 ]; then
    echo "setup: installing ${missing[*]}"
    export DEBIAN_FRONTEND=noninteractive
    apt-get update -qq
    apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
  else
    echo "setup: missing packages; install them with:" >&2
    echo "  sudo apt-get install -y ${missing[*]}" >&2
    exit 1
  fi
fi

BUILD_DIR=${BUILD_DIR:-build}
extra=()
# CI treats warnings in our own code as errors.
[ "${CI:-}" = true ] && extra+=(-DHOLEFILL_WARNINGS_AS_ERRORS=ON)
cmake -S . -B "$BUILD_DIR" -G Ninja -DCMAKE_BUILD_TYPE=Release "${extra[@]}" "$@" >/dev/null
cmake --build "$BUILD_DIR" --parallel "$(nproc)"
