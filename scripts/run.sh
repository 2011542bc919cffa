#!/usr/bin/env bash
# Builds holefill, then fills the bundled bunny's holes (or MESH, if given) and prints the
# report. Until the viewer lands this runs the command-line tool.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
mesh=${1:-assets/bunny.obj}
out=${TMPDIR:-/tmp}/holefill-$(basename "${mesh%.*}")-filled.obj
build=${BUILD_DIR:-build}
"$build/app/cli/holefill" info "$mesh"
"$build/app/cli/holefill" fill "$mesh" -o "$out"
echo "wrote $out"
