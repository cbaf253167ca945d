#!/bin/sh
# Installs what PointCloudSurface needs on Debian 12 (only the missing packages), then configures
# and builds it in ./build (Release, Ninja). Safe to run again: it only does what is missing.
set -eu
cd "$(dirname "$0")/.."

PACKAGES="paraview-dev python3-paraview libglew-dev libopenmpi-dev libdouble-conversion-dev
  libcgal-dev libgmp-dev libmpfr-dev cmake ninja-build g++ make xvfb xauth ccache python3-numpy"

missing=""
for p in $PACKAGES; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing="$missing $p"
  fi
done
if [ -n "$missing" ]; then
  echo "setup: installing:$missing"
  SUDO=""
  if [ "$(id -u)" -ne 0 ]; then
    if command -v sudo >/dev/null 2>&1; then SUDO="sudo"; else
      echo "setup: not root and no sudo; install these packages first:$missing" >&2; exit 1
    fi
  fi
  $SUDO env DEBIAN_FRONTEND=noninteractive apt-get update -q
  # shellcheck disable=SC2086
  $SUDO env DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends $missing
fi

BUILD_DIR="${BUILD_DIR:-build}"
if [ ! -f "$BUILD_DIR/build.ninja" ]; then
  cmake -S . -B "$BUILD_DIR" -G Ninja -DCMAKE_BUILD_TYPE=Release -DPython3_EXECUTABLE=/usr/bin/python3
fi
cmake --build "$BUILD_DIR" -j "$(nproc)"
