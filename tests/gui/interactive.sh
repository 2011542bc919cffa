#!/bin/bash
# Drives the real holefill-viewer window with synthetic input (xdotool, and WM_DELETE_WINDOW
# close requests as a window manager sends them) under the X server xvfb-run started.
#   interactive.sh SCENARIO VIEWER CLOSE_REQUEST ASSETS WORKDIR
# Scenarios: close-unsaved, close-saved, save-as, save-native, garbage-mesh, scripted-save,
# fill-all, fill-all-cancel, undo-redo, islands-bridge. Exits non-zero with a message on
# the first expectation that does not hold.
set -u
scenario=$1 viewer=$2 close_request=$3 assets=$4 work=$5
rm -rf "$work" && mkdir -p "$work" && cd "$work" || exit 1
export LIBGL_ALWAYS_SOFTWARE=1

fail() {
  echo "FAILED: $*" >&2
  [ -f "$work/state" ] && echo "viewer state:" >&2 && cat "$work/state" >&2
  [ -f "$work/viewer.log" ] && echo "viewer output:" >&2 && tail -5 "$work/viewer.log" >&2
  # A viewer that hangs: where each of its threads is.
  if [ -n "${pid:-}" ] && kill -0 "$pid" 2>/dev/null && command -v gdb >/dev/null; then
    gdb -p "$pid" -batch -ex "thread apply all bt 8" 2>/dev/null | grep -E "^(Thread|#)" >&2
  fi
  [ -n "${pid:-}" ] && kill "$pid" 2>/dev/null
  exit 1
}

# The viewer keeps its state in $work/state (--state-file): frames, keys received, idle, busy,
# question, title, message. Every step below waits on that state, never on a fixed pause, so a
# loaded machine only makes the test slower.
field() { sed -n "s/^$1 //p" "$work/state" 2>/dev/null; }
# Polls a command for up to $1 seconds.
eventually() {
  local seconds=$1
  shift
  for _ in $(seq $((seconds * 10))); do "$@" && return 0; sleep 0.1; done
  return 1
}
is_idle() { [ "$(field idle)" = 1 ]; }
# Waits until the viewer has nothing left to do or draw (it sleeps until an event).
settled() { eventually 60 is_idle || fail "the viewer did not settle: $(cat "$work/state")"; }

# Starts the viewer with the given arguments, waits for its window and its first frames.
start() {
  rm -f "$work/state"
  "$viewer" "$@" --state-file "$work/state" >"$work/viewer.log" 2>&1 &
  pid=$!
  window=$(timeout 60 xdotool search --sync --onlyvisible --name 'holefill viewer' | head -1)
  [ -n "$window" ] || fail "no viewer window appeared: $(cat "$work/viewer.log")"
  xdotool windowfocus --sync "$window"
  settled
}
received_at_least() { [ "$(field keys)" -ge "$1" ] 2>/dev/null; }
# Sends keys (each argument one press, as xdotool names it) and waits until the viewer has
# received them all.
press() {
  local want=$(($(field keys) + $#))
  xdotool key --delay 50 "$@"
  eventually 60 received_at_least "$want" ||
    fail "the viewer did not receive $*: $(cat "$work/state")"
}
# Sends keys and waits until the viewer has done what they asked (and drawn it).
keys() { press "$@"; settled; }
alive() { kill -0 "$pid" 2>/dev/null; }
gone() { ! alive; }
# Waits up to $1 seconds for the viewer to exit and checks its status is $2.
exits_within() {
  eventually "$1" gone || fail "the viewer is still running after $1 s"
  wait "$pid"
  local status=$?
  [ "$status" = "$2" ] || fail "the viewer exited with $status, expected $2"
}
asks() { [ "$(field question)" = "$1" ]; }
# A close request as a window manager sends it; the viewer must ask (save-changes) or exit.
close_and_expect_question() {
  "$close_request" "$window"
  eventually 60 asks save-changes || fail "a close request with unsaved fills got no question"
  settled
}
# Saves a screenshot (F12) as $1.png in the work folder, for people to look at.
screenshot() {
  press F12
  eventually 60 test -f holefill-screenshot.png || fail "F12 saved no screenshot"
  mv holefill-screenshot.png "$1.png" || fail "F12 saved no screenshot"
}
title() { xdotool getwindowname "$window"; }
title_is() { [ "$(title)" = "$1" ]; }
faces() { grep -c '^f ' "$1"; }
# How many edges of an OBJ's triangles have a single face: 0 for a closed surface.
open_edges() {
  awk '$1 == "f" {
    for (i = 2; i <= 4; i++) { a = $i + 0; b = $(i == 4 ? 2 : i + 1) + 0
      key = a < b ? a " " b : b " " a; count[key]++ } }
    END { n = 0; for (k in count) if (count[k] == 1) n++; print n }' "$1"
}

cp "$assets/bunny.obj" "$work/bunny.obj"
case $scenario in
close-saved)
  start bunny.obj
  "$close_request" "$window"
  exits_within 60 0
  ;;
close-unsaved)
  start bunny.obj --select-hole 0 --run triangulate
  eventually 60 title_is "*bunny.obj - holefill viewer" || fail "title '$(title)' has no modified mark"
  close_and_expect_question
  alive || fail "a close request with unsaved fills quit the viewer"
  screenshot save-changes-question
  keys Escape  # Cancel
  asks none || fail "Esc left the question up"
  close_and_expect_question
  alive || fail "the viewer quit after Cancel and a second request"
  press d  # Discard
  exits_within 60 0
  ;;
save-as)
  export HOLEFILL_FILE_DIALOG=builtin
  start bunny.obj --select-hole 0 --run triangulate,refine,smooth
  keys ctrl+shift+s
  screenshot save-as-dialog
  keys Return  # the suggested name, bunny-filled.obj beside the mesh
  eventually 60 test -f bunny-filled.obj || fail "Save As did not write bunny-filled.obj: $(cat viewer.log)"
  [ "$(faces bunny-filled.obj)" -gt "$(faces bunny.obj)" ] || fail "the saved mesh is not filled"
  eventually 60 title_is "bunny-filled.obj - holefill viewer" || fail "title after saving: '$(title)'"
  cp bunny-filled.obj first-save.obj
  # Save As onto the existing file asks; Cancel returns to the dialog, Esc leaves it.
  keys ctrl+shift+s Return
  screenshot overwrite-question
  keys Escape Escape
  cmp -s bunny-filled.obj first-save.obj || fail "a cancelled overwrite changed the file"
  alive || fail "the viewer quit"
  "$close_request" "$window"  # saved: quits at once
  exits_within 60 0
  ;;
save-native)
  # A stand-in for zenity that records how it was called and answers with a file name.
  mkdir bin
  printf '#!/bin/sh\necho "$@" > "%s/zenity-args"\necho "%s/picked.ply"\n' "$work" "$work" \
    > bin/zenity
  chmod +x bin/zenity
  PATH="$work/bin:$PATH" start bunny.obj --select-hole 1 --run triangulate
  keys ctrl+s
  eventually 60 test -f picked.ply || fail "Save through the native dialog wrote nothing: $(cat viewer.log)"
  grep -q -- "--confirm-overwrite" zenity-args || fail "zenity was not asked to confirm overwrite"
  grep -q -- "--filename=$work/bunny-filled.obj" zenity-args ||
    fail "zenity did not propose bunny-filled.obj: $(cat zenity-args)"
  "$close_request" "$window"
  exits_within 60 0
  ;;
undo-redo)
  # Undo and redo rebuild the mesh on the worker; the title's modified mark follows them.
  start bunny.obj --select-hole 0 --run triangulate,refine
  eventually 60 title_is "*bunny.obj - holefill viewer" || fail "title '$(title)' has no modified mark"
  keys ctrl+z ctrl+z
  eventually 60 title_is "bunny.obj - holefill viewer" || fail "Ctrl+Z twice left '$(title)'"
  keys ctrl+y
  eventually 60 title_is "*bunny.obj - holefill viewer" || fail "Ctrl+Y left '$(title)'"
  screenshot undo-redo
  keys ctrl+z
  eventually 60 title_is "bunny.obj - holefill viewer" || fail "Ctrl+Z after redo left '$(title)'"
  "$close_request" "$window"  # back at the saved state: quits at once
  exits_within 60 0
  ;;
islands-bridge)
  # A sphere cut around a cap (hole 1 with its island 0) and a capsule cut in two (holes 0 and
  # 1 facing each other): Shift+F fills the hole around its island, B bridges the two loops.
  export HOLEFILL_FILE_DIALOG=builtin
  sphere="awk -f $(dirname "$0")/cut_sphere.awk -v rows=40"
  $sphere -v cols=64 -v from=6 -v to=12 -v stretch=1 > island.obj
  $sphere -v cols=48 -v from=18 -v to=22 -v stretch=2 > gap.obj
  start island.obj --select-hole 0
  keys shift+f
  eventually 60 title_is "*island.obj - holefill viewer" || fail "Shift+F changed nothing: '$(title)'"
  keys ctrl+s Return
  eventually 60 test -f island-filled.obj || fail "Save wrote nothing: $(cat viewer.log)"
  [ "$(open_edges island-filled.obj)" = 0 ] || fail "the island fill left open edges"
  "$close_request" "$window"
  exits_within 60 0
  start gap.obj --select-hole 0 --add-hole 1
  screenshot bridge-selected
  keys b
  eventually 60 title_is "*gap.obj - holefill viewer" || fail "B bridged nothing: '$(title)'"
  screenshot bridge-filled
  keys ctrl+s Return
  eventually 60 test -f gap-filled.obj || fail "Save wrote nothing: $(cat viewer.log)"
  [ "$(open_edges gap-filled.obj)" = 0 ] || fail "the bridge left open edges"
  "$close_request" "$window"
  exits_within 60 0
  ;;
fill-all)
  export HOLEFILL_FILE_DIALOG=builtin
  start bunny.obj
  keys ctrl+f
  title_is "*bunny.obj - holefill viewer" || fail "Fill all changed nothing: '$(title)'"
  screenshot fill-all-done
  keys ctrl+s Return
  eventually 60 test -f bunny-filled.obj || fail "Save wrote nothing: $(cat viewer.log)"
  [ "$(faces bunny-filled.obj)" -gt "$(faces bunny.obj)" ] || fail "the saved mesh is not filled"
  "$close_request" "$window"
  exits_within 60 0
  ;;
fill-all-cancel)
  # Nine holes of 560 edges in a bumpy grid: long enough to cancel on any machine.
  awk -v N=480 -v H=3 -v S=140 'BEGIN {
    for (j = 0; j <= N; j++) for (i = 0; i <= N; i++)
      printf "v %d %d %.6f\n", i, j, 3 * sin(i / 15.0) * sin(j / 17.0)
    tile = N / H; m = (tile - S) / 2
    for (j = 0; j < N; j++) for (i = 0; i < N; i++) {
      ti = i % tile; tj = j % tile
      if (ti >= m && ti < m + S && tj >= m && tj < m + S) continue
      a = j * (N + 1) + i + 1; b = a + 1; c = a + N + 1; d = c + 1
      print "f", a, b, d; print "f", a, d, c
    }
  }' > holes.obj
  start holes.obj
  eventually 60 title_is "holes.obj - holefill viewer" || fail "holes.obj did not open"
  press ctrl+f
  screenshot fill-all-progress  # the window draws (and takes screenshots) while it works
  [ "$(field busy)" = 1 ] || fail "Fill all ended before Esc: $(cat state)"
  keys Escape
  case "$(field notice)" in
  "Filling "*" holes: cancelled, mesh unchanged") ;;
  *) fail "Cancel said '$(field notice)'" ;;
  esac
  title_is "holes.obj - holefill viewer" || fail "Cancel left a change: '$(title)'"
  "$close_request" "$window"  # nothing unsaved: quits at once
  exits_within 60 0
  ;;
garbage-mesh)
  # The window opens anyway (from a desktop launcher there is no terminal to read), with the
  # reason in its status bar and on stderr, and no mesh.
  printf 'v 0 0 0\nv 1 0\nf 1 2 3\n' > garbage.obj
  start garbage.obj
  eventually 60 eval '[ "$(field idle)" = 1 ] && [ -n "$(field notice)" ]' ||
    fail "no message about garbage.obj"
  case "$(field notice)" in
  "Could not open "*garbage.obj*) ;;
  *) fail "the status bar says '$(field notice)'" ;;
  esac
  grep -q "holefill-viewer: Could not open .*garbage.obj" viewer.log ||
    fail "no clear message on stderr: $(cat viewer.log)"
  title_is "no mesh - holefill viewer" || fail "title '$(title)'"
  screenshot garbage-mesh
  "$close_request" "$window"
  exits_within 60 0
  ;;
scripted-save)
  timeout 60 "$viewer" bunny.obj --select-hole 0 --run triangulate,refine,smooth \
    --save out.off >out.log 2>err.log || fail "--save failed: $(cat err.log)"
  [ "$(sed -n 2p out.off | cut -d' ' -f2)" -gt 3000 ] || fail "out.off is not the filled bunny"
  timeout 60 "$viewer" bunny.obj --save /no/such/folder/out.obj 2>err.log
  [ $? = 4 ] || fail "an unwritable --save did not exit with 4"
  ;;
*)
  fail "unknown scenario $scenario"
  ;;
esac
echo "passed: $scenario"
