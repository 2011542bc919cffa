#!/bin/sh
# Both cores against one (issue 30): whole-process `fill -q` of the three cases of bench/README.md's
# Threads table, each binary on every core the shell gives it and under `taskset -c 0`, the runs
# interleaved; then per case and binary the medians of wall and user seconds and the largest peak
# memory, and the load averages seen. Outputs of every binary and core count compared byte for byte.
# usage: bench/threads.sh BINARY... (BUILD=build, RUNS=5, CASES="h20k big4 hole1000", OUT=folder)
set -eu
build=${BUILD:-build} runs=${RUNS:-5} cases=${CASES:-h20k big4 hole1000}
out=${OUT:-/tmp/holefill-threads}
here=$(dirname "$0")
mkdir -p "$out"
[ -f "$out/h20k.ply" ] || "$build/bench/holefill-make-big-mesh" 2000000 20000 "$out/h20k.ply" >/dev/null
[ -f "$out/big4.ply" ] || "$build/bench/holefill-make-big-mesh" 1400000 4 "$out/big4.ply" >/dev/null
[ -f "$out/hole1000.obj" ] || python3 "$here/make_tube_hole.py" 1000 40 "$out/hole1000.obj"
input() { case $1 in hole1000) echo "$out/hole1000.obj" ;; *) echo "$out/$1.ply" ;; esac; }
: >"$out/runs"
r=1
while [ "$r" -le "$runs" ]; do
  for c in $cases; do
    b=0
    for binary in "$@"; do
      b=$((b + 1))
      for cores in both one; do
        pin=""; [ "$cores" = one ] && pin="taskset -c 0"
        load=$(cut -d' ' -f1 /proc/loadavg)
        in=$(input "$c")
        /usr/bin/time -f "%e %U %M" -o "$out/time" $pin "$binary" fill -q "$in" \
          -o "$out/out-$b-$cores-$(basename "$in")" >/dev/null 2>&1 || true
        echo "$c $b $cores $(cat "$out/time") $load" >>"$out/runs"
      done
    done
  done
  r=$((r + 1))
done
echo "| case | binary | cores | wall s (median) | user s (median) | peak MB | load |"
echo "|---|---|---|---|---|---|---|"
for c in $cases; do
  b=0
  for binary in "$@"; do
    b=$((b + 1))
    for cores in both one; do
      awk -v c="$c" -v b="$b" -v k="$cores" -v name="$binary" '
        $1 == c && $2 == b && $3 == k { n++; wall[n] = $4; user[n] = $5;
          if ($6 > mem) mem = $6; if (lo == "" || $7 < lo) lo = $7; if ($7 > hi) hi = $7 }
        function median(a, n,   i, j, t) {
          for (i = 1; i <= n; i++) for (j = i + 1; j <= n; j++) if (a[j] < a[i]) { t = a[i]; a[i] = a[j]; a[j] = t }
          return n % 2 ? a[(n + 1) / 2] : (a[n / 2] + a[n / 2 + 1]) / 2 }
        END { printf "| %s | %s | %s | %.2f | %.2f | %.0f | %s-%s |\n", c, name, k,
              median(wall, n), median(user, n), mem / 1024, lo, hi }' "$out/runs"
    done
  done
done
echo
for c in $cases; do
  in=$(basename "$(input "$c")")
  set -- "$out"/out-*-"$in"
  same=identical
  for f in "$@"; do cmp -s "$1" "$f" || same=differ; done
  echo "$c: $# outputs $same"
done
