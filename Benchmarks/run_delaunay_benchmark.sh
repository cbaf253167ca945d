#!/bin/sh
# Delaunay benchmark: vtkIncrementalDelaunay3D vs vtkDelaunay3D vs CGAL, side by side, one
# process per run. Builds ./build-bench (Release, benchmarks on), then writes
# Benchmarks/results/delaunay.md. Usage: Benchmarks/run_delaunay_benchmark.sh [repeats]
set -eu
cd "$(dirname "$0")/.."
./scripts/setup.sh >/dev/null
if [ ! -f build-bench/build.ninja ]; then
  cmake -S . -B build-bench -G Ninja -DCMAKE_BUILD_TYPE=Release -DBUILD_TESTING=OFF \
    -DPOINTCLOUDSURFACE_BUILD_BENCHMARKS=ON -DPOINTCLOUDSURFACE_WRAP_PYTHON=OFF \
    -DPOINTCLOUDSURFACE_BUILD_PLUGIN=OFF
fi
cmake --build build-bench
# Real surface samples: CGAL's demo data (Debian package libcgal-demo).
DATA=build-bench/cgal-data
if [ ! -d "$DATA" ]; then
  if ! dpkg-query -W -f='${Status}' libcgal-demo 2>/dev/null | grep -q "install ok installed"; then
    SUDO=""; [ "$(id -u)" -ne 0 ] && SUDO=sudo
    $SUDO env DEBIAN_FRONTEND=noninteractive apt-get install -y -q libcgal-demo
  fi
  mkdir -p "$DATA"
  tar xzf /usr/share/doc/libcgal-dev/data.tar.gz -C "$DATA" data/points_3/kitten.xyz \
    data/meshes/armadillo.off
fi
exec /usr/bin/python3 Benchmarks/run_delaunay_benchmark.py --exe build-bench/bin/pcsBenchDelaunay \
  --data "$DATA/data" --repeats "${1:-3}" --output Benchmarks/results/delaunay.md
