#!/usr/bin/env bash
# Issue 55's "live", measured in the window: the release app under Xvfb at 1920×1080 on lesson
# 24's first step, its shader panel open (S), on N threads (RAYON_NUM_THREADS, default 2). A
# comment is typed into the fragment shader one key every 0.7 s (each key compiles the shader
# and draws the frame), then ten pixels of the sphere are clicked 1.5 s apart (each renders the
# frame keeping that pixel's trace). The app logs each input's time from the start of the frame
# that handled it to the end of the first frame that draws its picture (PIPELENS_FRAME_LOG,
# `app::latency`). Prints the medians and the worst as its last line:
#   window latency on 2 threads: keystroke 41.2 ms median (…worst), pixel click …
# Needs what scripts/smoke-app.sh needs (.ci/run installs it).
# Usage: scripts/window-latency.sh [THREADS]
set -euo pipefail
cd "$(dirname "$0")/.."
threads=${1:-2}
display=:94
screen=1920x1080
cargo build --release --quiet --bin pipelens
. scripts/xvfb-lib.sh
start_xvfb
log=target/window-latency.log
home=$(mktemp -d)
HOME=$home RAYON_NUM_THREADS=$threads PIPELENS_FRAME_LOG=1 DISPLAY=$display \
  target/release/pipelens --lang en --lesson lessons/24-shader-programs.toml --step 1 >"$log" 2>&1 &
app=$!
window=
for _ in $(seq 1 60); do
  window=$(DISPLAY=$display xdotool search --name "step 1/" 2>/dev/null | head -1) || true
  [ -n "$window" ] && break
  kill -0 "$app" 2>/dev/null || { echo "window-latency: the app exited:" >&2; cat "$log" >&2; exit 1; }
  sleep 1
done
[ -n "$window" ] || { echo "window-latency: no window after 60 s" >&2; exit 1; }
DISPLAY=$display xdotool windowsize "$window" 1920 1080 windowmove "$window" 0 0 windowfocus "$window"
sleep 3
DISPLAY=$display xdotool key --window "$window" s
sleep 2
# The empty line 16 of the fragment shader (the panel's code at 1920×1080), then a comment:
# the first "/" does not compile, each key after it does.
DISPLAY=$display xdotool mousemove 1714 440 click 1
sleep 1
DISPLAY=$display xdotool type --delay 700 "//abcdefghijklmn"
sleep 2
for xy in "580 435" "600 400" "520 500" "650 300" "560 460" "610 520" "480 420" "700 380" "590 350" "540 390"; do
  # shellcheck disable=SC2086
  DISPLAY=$display xdotool mousemove $xy click 1
  sleep 1.5
done
kill "$app" 2>/dev/null || true
wait "$app" 2>/dev/null || true
app=
rm -rf "$home"
summary() {
  local what=$1 times
  times=$(grep -E "^latency: .* \($what\)$" "$log" | sed -E 's/^latency: ([0-9.]+) ms.*/\1/' | sort -n) || true
  [ -n "$times" ] || { echo "window-latency: no $what was timed:" >&2; tail "$log" >&2; exit 1; }
  local n median worst
  n=$(echo "$times" | wc -l)
  median=$(echo "$times" | sed -n "$(((n + 1) / 2))p")
  worst=$(echo "$times" | tail -1)
  echo "$what $median ms median, $worst ms worst ($n timed)"
}
keys=$(summary keystroke)
clicks=$(summary "pixel click")
echo "window latency on $threads thread$([ "$threads" = 1 ] || echo s): $keys; $clicks"
