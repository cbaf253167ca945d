#!/bin/sh
# Builds the libFuzzer targets of Testing/Fuzz with clang in ./build-fuzz and runs each for
# SECONDS (default 600) on its corpus. Inputs that break an invariant are copied into
# Testing/Fuzz/corpus/<target>/ (commit them: ctest replays that corpus), new coverage-increasing
# inputs stay in build-fuzz/corpus/<target>/. An input that runs longer than 30 s counts as a
# hang (the instrumented build is 30 to 100 times slower than Release).
#   scripts/fuzz.sh [SECONDS] [TARGET...]     targets: delaunay3d delaunay2d quality (kernels),
#                                             peel localoptimum cdt greedy (filters)
set -eu
cd "$(dirname "$0")/.."
SECONDS_PER_TARGET="${1:-600}"
[ $# -gt 0 ] && shift
TARGETS="${*:-delaunay3d delaunay2d quality peel localoptimum cdt greedy}"
SETUP_PACKAGES_ONLY=1 ./scripts/setup.sh >/dev/null # packages only (not ./build)
if ! command -v clang++ >/dev/null 2>&1; then
  SUDO=""; [ "$(id -u)" -ne 0 ] && SUDO=sudo
  $SUDO env DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends clang
fi
if [ ! -f build-fuzz/build.ninja ]; then
  CC=clang CXX=clang++ cmake -S . -B build-fuzz -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DPython3_EXECUTABLE=/usr/bin/python3 \
    -DPOINTCLOUDSURFACE_BUILD_FUZZERS=ON -DPOINTCLOUDSURFACE_WRAP_PYTHON=OFF \
    -DPOINTCLOUDSURFACE_BUILD_PLUGIN=OFF
fi
status=0
for target in $TARGETS; do
  cmake --build build-fuzz --target "pcsFuzz_$target" -j "${FUZZ_BUILD_JOBS:-2}"
  mkdir -p "build-fuzz/corpus/$target" "build-fuzz/crashes/$target"
  echo "fuzz: $target for $SECONDS_PER_TARGET s"
  if ! "build-fuzz/bin/pcsFuzz_$target" -max_total_time="$SECONDS_PER_TARGET" -max_len=1024 \
      -timeout=30 -artifact_prefix="build-fuzz/crashes/$target/" \
      "build-fuzz/corpus/$target" "Testing/Fuzz/corpus/$target"; then
    status=1
  fi
  for crash in "build-fuzz/crashes/$target"/*; do
    [ -f "$crash" ] && cp "$crash" "Testing/Fuzz/corpus/$target/" && echo "fuzz: kept $crash"
  done
done
exit $status
