#!/bin/sh
# The do-no-harm evaluation (issue 29): builds the set, runs each binary over it with default
# options and prints the tables of README.md. Needs python3 and Debian's assimp-testmodels.
# usage: bench/do_no_harm/run.sh BEFORE AFTER [BUILD_DIR]   (OUT=folder for the set and outputs)
set -eu
here=$(dirname "$0")
build=${3:-build}
out=${OUT:-/tmp/do_no_harm}
python3 "$here/make_set.py" "$out/set"
python3 "$here/run.py" "$build/bench/do_no_harm/holefill-check-fill" "$out/set" "$out/runs" \
  before="$1" after="$2" --reasons
