#!/bin/sh
# The whole test suite: set-up (packages, configure, build), then every ctest test under a
# virtual X server (the rendering tests need one). Exits non-zero when a test fails.
#   scripts/test.sh              ./build (the README's test command, what CI runs)
#   scripts/test.sh --sanitize   ./build-asan: the same suite under AddressSanitizer and
#                                UndefinedBehaviorSanitizer (RelWithDebInfo build; slower)
#   scripts/test.sh --valgrind   the C++ tests of ./build under valgrind memcheck (ctest -T
#                                memcheck; any memcheck error fails the test; slow: about an
#                                hour on 2 busy cores).
#                                Not under valgrind: the image tests (the OpenGL driver, loaded
#                                with dlopen, trips glibc's loader checks and leaks) and the
#                                predicate and projected-test kernel tests (their CGAL references
#                                use interval arithmetic, which switches rounding modes, and
#                                valgrind does not emulate rounding modes: the references come out
#                                wrong, with no memcheck error); both run under --sanitize.
# First X display number tried by xvfb-run -a, spread by the process id: two xvfb-run -a
# started at the same moment (other jobs on the host) can race for the same free number, and
# then a rendering test loses its X connection.
XVFB_FIRST=$(($$ % 800 + 100))
# -noreset: by default Xvfb resets when its last client disconnects, and a test connecting during
# that reset gets "bad X server connection" (SIGABRT in vtkXOpenGLRenderWindow). With ctest -j2
# one test's window closing while the other opens its own made this happen about once in a
# hundred connections (three loops of xdpyinfo against one xvfb-run: 31 failures in 450 without
# -noreset, 0 with it).
XVFB_SERVER_ARGS="-screen 0 1280x1024x24 -noreset"
set -eu
cd "$(dirname "$0")/.."
if [ "${1:-}" = "--sanitize" ]; then
  export BUILD_DIR=build-asan
  if [ ! -f build-asan/build.ninja ]; then
    ./scripts/setup.sh >/dev/null # packages
    cmake -S . -B build-asan -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
      -DPython3_EXECUTABLE=/usr/bin/python3 -DPOINTCLOUDSURFACE_ENABLE_SANITIZERS=ON
  fi
  ./scripts/setup.sh
  # Python and ParaView executables are not instrumented: the ASan runtime is preloaded into
  # them. Leak checking is off (the interpreters keep memory until exit by design); any other
  # ASan or UBSan report stops the test with an error.
  LD_PRELOAD="$(gcc -print-file-name=libasan.so) $(gcc -print-file-name=libubsan.so)"
  export LD_PRELOAD
  export ASAN_OPTIONS="detect_leaks=0:abort_on_error=1:detect_odr_violation=0"
  export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
  exec xvfb-run -a -n "$XVFB_FIRST" -s "$XVFB_SERVER_ARGS" ctest --test-dir build-asan --output-on-failure -j2
fi
./scripts/setup.sh
BUILD_DIR="${BUILD_DIR:-build}"
if [ "${1:-}" = "--valgrind" ]; then
  command -v valgrind >/dev/null 2>&1 || {
    SUDO=""; [ "$(id -u)" -ne 0 ] && SUDO=sudo
    $SUDO env DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends valgrind
  }
  # Time bounds of the tests (TestAbort) stretched for valgrind's slowdown.
  export PCS_TEST_TIME_SCALE=100
  exec xvfb-run -a -n "$XVFB_FIRST" -s "$XVFB_SERVER_ARGS" ctest --test-dir "$BUILD_DIR" -T memcheck -L "Filters|Kernel" \
    -E "Image|Kernel-TestPredicates|Kernel-TestProjectedTests" \
    --overwrite MemoryCheckCommand="$(command -v valgrind)" \
    --overwrite MemoryCheckCommandOptions="--error-exitcode=97 --leak-check=full --errors-for-leak-kinds=definite --track-origins=no" \
    --output-on-failure -j2 --timeout 3600
fi
xvfb-run -a -n "$XVFB_FIRST" -s "$XVFB_SERVER_ARGS" ctest --test-dir "$BUILD_DIR" --output-on-failure -j2
