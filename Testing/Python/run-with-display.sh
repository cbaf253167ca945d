#!/bin/sh
# Runs a command on the X display it was given (ctest under scripts/test.sh's xvfb-run), or
# under its own xvfb-run -a when there is none. Starting a second Xvfb beside another test's
# windows raced for the same display number on CI ("bad X server connection", SIGABRT).
if [ -n "${DISPLAY:-}" ]; then
  exec "$@"
fi
exec xvfb-run -a -s "-screen 0 1280x1024x24 -noreset" "$@"
