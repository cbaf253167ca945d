#!/bin/sh
# Set-up on Debian 12: installs the packages PointCloudSurface needs (only those missing), then
# configures ./build (Ninja, Release) if it is not configured yet and builds it.
# Idempotent: a second run installs nothing and only rebuilds what changed.
#   BUILD_DIR=other ./scripts/setup.sh    builds in ./other instead
#   SETUP_PACKAGES_ONLY=1 ./scripts/setup.sh    only the packages
set -eu
cd "$(dirname "$0")/.."

# ParaView 5.11 SDK with its VTK 9.2 (+ the -dev packages its CMake config needs but does not
# pull in), CGAL (tests and benchmarks only) with its sample data, build tools, headless X.
PACKAGES="paraview-dev python3-paraview libglew-dev libopenmpi-dev libdouble-conversion-dev
  libcgal-dev libgmp-dev libmpfr-dev cmake ninja-build g++ xvfb xauth ccache python3-numpy
  libcgal-demo"

missing=""
for package in $PACKAGES; do
  if ! dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed"; then
    missing="$missing $package"
  fi
done
if [ -n "$missing" ]; then
  echo "setup: installing:$missing"
  SUDO=""
  if [ "$(id -u)" -ne 0 ]; then
    if command -v sudo >/dev/null 2>&1; then
      SUDO="sudo"
    else
      echo "setup: not root and sudo is missing; as root run: apt-get install$missing" >&2
      exit 1
    fi
  fi
  $SUDO env DEBIAN_FRONTEND=noninteractive apt-get update -q
  # shellcheck disable=SC2086
  $SUDO env DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends $missing
else
  echo "setup: all packages present"
fi
# SETUP_PACKAGES_ONLY=1: stop here (scripts/fuzz.sh builds its own ./build-fuzz only).
[ "${SETUP_PACKAGES_ONLY:-0}" = 1 ] && exit 0

BUILD_DIR="${BUILD_DIR:-build}"
if [ ! -f "$BUILD_DIR/build.ninja" ]; then
  cmake -S . -B "$BUILD_DIR" -G Ninja -DCMAKE_BUILD_TYPE=Release \
    -DPython3_EXECUTABLE=/usr/bin/python3
fi
cmake --build "$BUILD_DIR" -j "$(nproc)"
