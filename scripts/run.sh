#!/usr/bin/env bash
# Installs what is missing, builds, and opens the viewer on the bundled bunny (or on MESH).
# Without a display it runs the command-line tool instead: fills every hole and prints the report.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
build=${BUILD_DIR:-build}
mesh=${1:-assets/bunny.obj}
if [ -n "${DISPLAY:-}${WAYLAND_DISPLAY:-}" ]; then
  exec "$build/app/viewer/holefill-viewer" "$@"
fi
echo "run: no display, so running the command-line tool on $mesh instead of the viewer"
out=${TMPDIR:-/tmp}/holefill-$(basename "${mesh%.*}")-filled.obj
"$build/app/cli/holefill" info "$mesh"
"$build/app/cli/holefill" fill "$mesh" -o "$out"
echo "wrote $out"
