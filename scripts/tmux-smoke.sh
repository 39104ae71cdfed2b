#!/usr/bin/env bash
# Smoke test of the real terminal app in tmux: start it, press keys, read the screen,
# quit; then check that a panic, Ctrl-C, and SIGINT, SIGTERM, SIGHUP or SIGQUIT sent
# with kill leave the terminal restored (and that Ctrl-Z suspends and fg resumes) (line mode and echo, main screen, cursor shown,
# mouse off) with the right exit status. Needs tmux and a built
# binary (BIN, default target/debug/groovelab). Exits non-zero on the first failure.
set -euo pipefail
cd "$(dirname "$0")/.."
BIN=${BIN:-target/debug/groovelab}
BIN=$(realpath "$BIN")
SESSION=groovelab-smoke-$$
TMP=$(mktemp -d)
trap 'tmux kill-session -t "$SESSION" 2>/dev/null || true; rm -rf "$TMP"' EXIT

fail() { echo "tmux smoke: FAIL: $*"; echo "--- screen ---"; tmux capture-pane -p -t "$SESSION" 2>/dev/null || true; exit 1; }
screen() { tmux capture-pane -p -t "$SESSION"; }
wait_for() { # text, timeout in tenths of a second
  for _ in $(seq 1 "${2:-50}"); do screen | grep -qF -- "$1" && return 0; sleep 0.1; done
  fail "did not see: $1"
}

tmux new-session -d -s "$SESSION" -x 120 -y 40 \
  "GROOVELAB_PRESETS=$TMP/presets $BIN; echo \"exit status \$?\"; stty -a | tr ' ' '\n' | grep -x -e icanon -e -icanon -e echo -e -echo; sleep 60"
wait_for "RECOLLIDE" 100
wait_for "preset paper-b4.9"
# Select b (already selected), type 3.5 cm: the regime changes at once.
tmux send-keys -t "$SESSION" Enter 3.5cm Enter
wait_for "DEPART"
wait_for "3.50 cm"
# Play for a moment: the time in the status line moves.
tmux send-keys -t "$SESSION" Space
sleep 0.6
tmux send-keys -t "$SESSION" Space
screen | grep -q "t = -0.200 s" && fail "playback did not move the time"
# Help and preset picker open and close.
tmux send-keys -t "$SESSION" '?'
wait_for "Keys  (Esc or q closes"
# q in a popup closes the popup, not the app.
sleep 0.2; tmux send-keys -t "$SESSION" q; sleep 0.3
screen | grep -qF "Keys  (" && fail "q did not close the help"
screen | grep -q "exit status" && fail "q in the help quit the app"
tmux send-keys -t "$SESSION" p
wait_for "Presets  (Enter or a second click loads"
tmux send-keys -t "$SESSION" Down Enter
wait_for "Billiard balls on a flat table"
# Quit: exit status 0 and the shell's terminal back in canonical mode with echo.
tmux send-keys -t "$SESSION" q
wait_for "exit status 0"
wait_for "icanon"
screen | grep -qx -- "-icanon" && fail "terminal left in raw mode"
tmux kill-session -t "$SESSION"

# A panic must restore the terminal too.
tmux new-session -d -s "$SESSION" -x 120 -y 40 \
  "GROOVELAB_TEST_PANIC=1 $BIN 2>$TMP/panic.txt; echo \"exit status \$?\"; stty -a | tr ' ' '\n' | grep -x -e icanon -e -icanon; sleep 60"
wait_for "exit status 101" 100
wait_for "icanon"
screen | grep -qx -- "-icanon" && fail "terminal left in raw mode after a panic"
grep -q "GROOVELAB_TEST_PANIC" "$TMP/panic.txt" || fail "panic message missing: $(cat "$TMP/panic.txt")"
tmux kill-session -t "$SESSION"

# Ctrl-C quits and restores as well.
tmux new-session -d -s "$SESSION" -x 100 -y 30 \
  "$BIN; echo \"exit status \$?\"; stty -a | tr ' ' '\n' | grep -x -e icanon -e -icanon; sleep 60"
wait_for "RECOLLIDE" 100
tmux send-keys -t "$SESSION" C-c
wait_for "exit status 0"
screen | grep -qx -- "-icanon" && fail "terminal left in raw mode after Ctrl-C"
tmux kill-session -t "$SESSION"

flag() { tmux display -p -t "$SESSION" "#{$1}"; }
# A signal from outside ends the app: exit status 128 + its number, terminal restored.
signals=0
for sig in INT TERM HUP QUIT; do
  num=$(kill -l "$sig")
  rm -f "$TMP/pid"
  tmux new-session -d -s "$SESSION" -x 100 -y 30 \
    "sh -c 'echo \$\$ > $TMP/pid; exec $BIN'; echo \"exit status \$?\"; stty -a | tr ' ' '\n' | grep -x -e icanon -e -icanon -e echo -e -echo; sleep 60"
  wait_for "RECOLLIDE" 100
  tmux send-keys -t "$SESSION" m   # mouse capture on, to see it turned off again
  sleep 0.3
  [ "$(flag alternate_on)" = 1 ] || fail "SIG$sig: app not on the alternate screen before the signal"
  [ "$(flag cursor_flag)" = 0 ] || fail "SIG$sig: cursor not hidden before the signal"
  kill -s "$sig" "$(cat "$TMP/pid")"
  wait_for "exit status $((128 + num))" 50
  wait_for "icanon"
  screen | grep -qx -- "-icanon" && fail "SIG$sig: terminal left in raw mode"
  screen | grep -qx -- "-echo" && fail "SIG$sig: terminal left without echo"
  screen | grep -qx -- "echo" || fail "SIG$sig: stty shows no echo"
  [ "$(flag alternate_on)" = 0 ] || fail "SIG$sig: terminal left on the alternate screen"
  [ "$(flag cursor_flag)" = 1 ] || fail "SIG$sig: cursor left hidden"
  [ "$(flag mouse_any_flag)" = 0 ] || fail "SIG$sig: mouse capture left on"
  tmux kill-session -t "$SESSION"
  signals=$((signals + 1))
done
# Ctrl-Z suspends as any job does: the terminal restored and the job stopped; `fg`
# takes the terminal again and draws the whole screen.
tmux new-session -d -s "$SESSION" -x 100 -y 30 "bash --norc --noprofile -i"
tmux send-keys -t "$SESSION" "PS1='SHELL> '; $BIN" Enter
wait_for "RECOLLIDE" 100
tmux send-keys -t "$SESSION" C-z
wait_for "Stopped" 50
tmux send-keys -t "$SESSION" "stty -a | tr ' ' '\\n' | grep -x -e icanon -e -icanon -e echo -e -echo" Enter
for _ in $(seq 1 30); do screen | grep -qx -e icanon -e -icanon && break; sleep 0.1; done
screen | grep -qx -- "icanon" || fail "Ctrl-Z: terminal left in raw mode"
screen | grep -qx -- "echo" || fail "Ctrl-Z: terminal left without echo"
[ "$(flag alternate_on)" = 0 ] || fail "Ctrl-Z: terminal left on the alternate screen"
[ "$(flag cursor_flag)" = 1 ] || fail "Ctrl-Z: cursor left hidden"
tmux send-keys -t "$SESSION" "clear; fg" Enter
wait_for "RECOLLIDE" 50
wait_for "preset paper-b4.9"
[ "$(flag alternate_on)" = 1 ] || fail "fg: the app did not take the alternate screen again"
tmux send-keys -t "$SESSION" q
wait_for "SHELL>" 50
[ "$(flag alternate_on)" = 0 ] || fail "q after fg: terminal left on the alternate screen"
tmux kill-session -t "$SESSION"

echo "smoke: $((4 + signals)) passed, 0 failed"
