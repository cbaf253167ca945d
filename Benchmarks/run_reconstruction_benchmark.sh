#!/bin/sh
# Reconstruction benchmark: every surface filter of this build and the peers (vtkDelaunay3D with
# Alpha, CGAL's advancing front, CGAL's Delaunay_triangulation_3) on generated and real surfaces.
# Builds ./build (scripts/setup.sh) and ./build-bench (Release, benchmark executables), then writes
# Benchmarks/results/reconstruction.md and the scaling plots next to it.
#   Benchmarks/run_reconstruction_benchmark.sh [--quick] [--skip-scaling]
set -eu
cd "$(dirname "$0")/.."
./scripts/setup.sh >/dev/null
# Plots need matplotlib (Debian package python3-matplotlib).
if ! dpkg-query -W -f='${Status}' python3-matplotlib 2>/dev/null | grep -q "install ok installed"; then
  SUDO=""; [ "$(id -u)" -ne 0 ] && SUDO=sudo
  $SUDO env DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends python3-matplotlib
fi
if [ ! -f build-bench/build.ninja ]; then
  cmake -S . -B build-bench -G Ninja -DCMAKE_BUILD_TYPE=Release -DBUILD_TESTING=OFF \
    -DPOINTCLOUDSURFACE_BUILD_BENCHMARKS=ON -DPOINTCLOUDSURFACE_WRAP_PYTHON=OFF \
    -DPOINTCLOUDSURFACE_BUILD_PLUGIN=OFF
fi
cmake --build build-bench
# Real surfaces: meshes of CGAL's demo data (Debian package libcgal-demo, installed by setup.sh).
DATA=build-bench/cgal-data
mkdir -p "$DATA"
for mesh in bunny00 armadillo camel knot1; do
  if [ ! -f "$DATA/data/meshes/$mesh.off" ]; then
    tar xzf /usr/share/doc/libcgal-dev/data.tar.gz -C "$DATA" "data/meshes/$mesh.off"
  fi
done
eval "$(scripts/env.sh build)"
exec /usr/bin/python3 Benchmarks/run_reconstruction_benchmark.py --bench-bin build-bench/bin \
  --data "$DATA/data" --output-dir Benchmarks/results "$@"
