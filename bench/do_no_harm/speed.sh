#!/bin/sh
# Clean-mesh fill speed of two binaries, alternating run by run: user seconds (/usr/bin/time) of
# `fill -q` on the 20,000-hole mesh (holefill-make-big-mesh 2000000 20000) and of 20 fills of
# the bunny; then whether the bundled assets' outputs (default fill) are byte-identical.
# usage: bench/do_no_harm/speed.sh BEFORE AFTER [BUILD_DIR] [SAMPLES]   (OUT=scratch folder)
set -eu
before=$1 after=$2 build=${3:-build} samples=${4:-5}
assets="$(dirname "$0")/../../assets"
out=${OUT:-/tmp/do_no_harm}/speed
mkdir -p "$out"
[ -f "$out/many.ply" ] || "$build/bench/holefill-make-big-mesh" 2000000 20000 "$out/many.ply" >/dev/null
many() {  # user seconds of one fill of the big mesh
  /usr/bin/time -f %U -o "$out/time" "$1" fill -q "$out/many.ply" -o "$out/many-out.ply" \
    >/dev/null 2>&1 || true
  cat "$out/time"
}
bunny() {  # user seconds of 20 fills of the bunny
  /usr/bin/time -f %U -o "$out/time" sh -c 'i=0; while [ $i -lt 20 ]; do
    "$0" fill -q "$1" -o "$2" || true; i=$((i + 1)); done' "$1" "$assets/bunny.obj" \
    "$out/bunny-out.obj" >/dev/null 2>&1
  cat "$out/time"
}
echo "sample many_before many_after bunny20_before bunny20_after"
s=1
while [ "$s" -le "$samples" ]; do
  echo "$s $(many "$before") $(many "$after") $(bunny "$before") $(bunny "$after")"
  s=$((s + 1))
done
echo
echo "assets (default fill): exit before / after, outputs"
for mesh in "$assets"/*.obj; do
  name=$(basename "$mesh")
  rb=0 ra=0
  "$before" fill -q "$mesh" -o "$out/before-$name" >/dev/null 2>&1 || rb=$?
  "$after" fill -q "$mesh" -o "$out/after-$name" >/dev/null 2>&1 || ra=$?
  same=identical
  cmp -s "$out/before-$name" "$out/after-$name" || same=differ
  echo "$name: $rb / $ra, $same"
done
