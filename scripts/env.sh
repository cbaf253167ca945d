#!/bin/sh
# Prints the exports that make a build usable from Python and ParaView:
#   eval "$(scripts/env.sh)"            for ./build
#   eval "$(scripts/env.sh other-dir)"  for another build directory
root="$(cd "$(dirname "$0")/.." && pwd)"
build="${1:-$root/build}"
case "$build" in
  /*) ;;
  *) build="$PWD/$build" ;;
esac
echo "export PYTHONPATH=\"$build/lib/python3/dist-packages\${PYTHONPATH:+:\$PYTHONPATH}\""
echo "export PV_PLUGIN_PATH=\"$build/lib/paraview-plugins/PointCloudSurface\${PV_PLUGIN_PATH:+:\$PV_PLUGIN_PATH}\""
echo "export PV_PLUGIN_CONFIG_FILE=\"$build/lib/paraview-plugins/PointCloudSurface.plugins.xml\${PV_PLUGIN_CONFIG_FILE:+;\$PV_PLUGIN_CONFIG_FILE}\""
