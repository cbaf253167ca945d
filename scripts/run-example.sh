#!/bin/sh
# The main job on the bundled default cloud: set-up, then generate the cloud and reconstruct it
# with the command line, writing build/default_mesh.vtp and build/default_mesh.png.
#   ./scripts/run-example.sh [pointcloud-surface options]   e.g. -m delaunay, --distances, --ascii
set -eu
cd "$(dirname "$0")/.."
./scripts/setup.sh
BUILD_DIR="${BUILD_DIR:-build}"
/usr/bin/python3 Examples/generate_default_cloud.py "$BUILD_DIR/default_cloud.vtp"
# 2.5D Delaunay of the terrain (-m terrain); later options (-m ...) replace the earlier ones.
# Without an X display the command renders the PNG under xvfb-run -a by itself.
exec "$BUILD_DIR/bin/pointcloud-surface" "$BUILD_DIR/default_cloud.vtp" -m terrain \
  -o "$BUILD_DIR/default_mesh.vtp" --png "$BUILD_DIR/default_mesh.png" "$@"
