#!/bin/sh
# The main job on the bundled default cloud: set-up, then generate the cloud, reconstruct it and
# write build/default_mesh.vtp and build/default_mesh.png.
set -eu
cd "$(dirname "$0")/.."
./scripts/setup.sh
BUILD_DIR="${BUILD_DIR:-build}"
PYTHONPATH="$PWD/$BUILD_DIR/lib/python3/dist-packages" \
  xvfb-run -a /usr/bin/python3 Examples/reconstruct_default.py --output-dir "$BUILD_DIR" "$@"
