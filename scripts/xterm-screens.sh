#!/usr/bin/env bash
# A real-terminal check: starts the app in xterm under Xvfb, types keys with xdotool
# and saves screenshots (ImageMagick's import) on a white and on a black background,
# and of the video view drawn with sixel (xterm -ti vt340) from a synthetic clip (a
# folder of frames written by `cargo run --example film`). `--theme` is left at auto,
# so each screenshot also shows that xterm's answer to OSC 11 chose the palette.
# Needs: Xvfb, xterm, xdotool, imagemagick, the DejaVu Sans Mono font, and a built
# binary (BIN, default target/debug/groovelab). Writes OUT (default docs/screens).
# Look at the pictures: every label must read on white and on black.
set -euo pipefail
cd "$(dirname "$0")/.."
BIN=$(realpath "${BIN:-target/debug/groovelab}")
OUT=${OUT:-docs/screens}
mkdir -p "$OUT"
OUT=$(realpath "$OUT")
TMP=$(mktemp -d)
DISPLAY_NUM=${DISPLAY_NUM:-77}
export DISPLAY=":$DISPLAY_NUM"
PIDS=()
cleanup() {
  for p in "${PIDS[@]}"; do kill "$p" 2>/dev/null || true; done
  rm -rf "$TMP"
}
trap cleanup EXIT

Xvfb "$DISPLAY" -screen 0 1600x1000x24 -nolisten tcp >/dev/null 2>&1 &
PIDS+=($!)
for _ in $(seq 50); do xdpyinfo >/dev/null 2>&1 && break; sleep 0.1; done

# The clip for the video view: 50 frames of paper-b4.9 at 100 frames/s (FILM: a
# built `film` example, else cargo builds it).
if [ -n "${FILM:-}" ]; then "$FILM" "$TMP/clip" >/dev/null
else cargo run -q --example film -- "$TMP/clip" >/dev/null; fi

# start NAME BG FG ARGS…: the app in an xterm titled NAME; sets WID.
start() {
  local name=$1 bg=$2 fg=$3
  shift 3
  xterm -title "$name" -geometry 120x40+0+0 -bg "$bg" -fg "$fg" \
    -fa "DejaVu Sans Mono" -fs 10 -ti vt340 \
    -xrm 'XTerm*numColorRegisters: 256' \
    -xrm 'XTerm*decGraphicsID: vt340' -xrm 'XTerm*sixelScrolling: true' \
    -e env TERM=xterm-256color GROOVELAB_PRESETS="$TMP/presets" "$BIN" "$@" &
  PIDS+=($!)
  WID=""
  for _ in $(seq 100); do
    WID=$(xdotool search --name "^$name\$" 2>/dev/null | head -1) && [ -n "$WID" ] && break
    sleep 0.1
  done
  [ -n "$WID" ] || { echo "xterm-screens: no window $name"; exit 1; }
  sleep "${SETTLE:-3}"
}

# keys KEY…: xdotool key names (e.g. question, Escape, v, shift+v), a pause after each.
# Typed through XTEST to the window under the pointer (no window manager here): sent
# events (`--window`) would need xterm's allowSendEvents, which turns off its answer
# to the colour query that `--theme auto` asks.
keys() {
  xdotool mousemove --window "$WID" 5 5
  for k in "$@"; do
    xdotool key "$k"
    sleep 0.4
  done
}

# shot FILE: the window as a small PNG.
shot() {
  sleep 1
  import -display "$DISPLAY" -window "$WID" "$TMP/shot.png"
  convert "$TMP/shot.png" -strip -colors 128 "PNG8:$OUT/$1"
  echo "wrote $OUT/$1"
}

quit() {
  keys q
  sleep 0.5
}

for bg in white black; do
  if [ "$bg" = white ]; then fg=black; else fg=white; fi
  start "groovelab-$bg" "$bg" "$fg"
  shot "$bg-charts.png"
  keys v
  shot "$bg-forces.png"
  keys v f
  shot "$bg-fit.png"
  keys f question
  shot "$bg-help.png"
  keys Escape
  quit
done

# The video view with sixel: the clip tracked on a worker, then V.
# From the clip's folder, so that the status line names it `clip`.
cd "$TMP"
SETTLE=8 start "groovelab-video" white black --data clip --fps 100 \
  --radius 2.75cm --width 4.9cm
keys V
sleep 4
shot "white-video-sixel.png"
quit
