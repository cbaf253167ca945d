#!/bin/sh
# The whole test suite: set-up (packages, configure, build), then every ctest test under a
# virtual X server (the rendering tests need one). Exits non-zero when a test fails.
set -eu
cd "$(dirname "$0")/.."
./scripts/setup.sh
BUILD_DIR="${BUILD_DIR:-build}"
xvfb-run -a ctest --test-dir "$BUILD_DIR" --output-on-failure -j2
