#!/usr/bin/env bash
# The native app's frame times as it runs, its window painting: the release app under Xvfb at
# 1920×1080 (Mesa's software OpenGL paints it, as SwiftShader paints the page), the tour's step
# STEP entered five times from the step before it (arrow keys, 1.5 s apart, the page test's
# timing), on one thread and on every thread (RAYON_NUM_THREADS). The time is the one the page
# reports in <html data-frame-ms>: the app logs it with PIPELENS_FRAME_LOG set. Prints
#   native app, step 5: 24.1 ms on 1 thread (…), 13.0 ms on 2 threads (…)
# as its last line (scripts/web-test.sh prints the page's frames beside it).
# Needs what scripts/smoke-app.sh needs (.ci/run installs it).
# Usage: scripts/native-frames.sh [STEP]
set -euo pipefail
cd "$(dirname "$0")/.."
step=${1:-5}
display=:93
screen=1920x1080
cargo build --release --quiet --bin pipelens
. scripts/xvfb-lib.sh
start_xvfb
cores=$(nproc)

# The median of five fresh renders of the step, each entered from the step before.
measure() {
  local threads=$1 log=target/native-frames-$1.log window= times=()
  local attempt
  # Up to three launches: once in CI the app could not connect to an Xvfb that had just
  # answered xdotool (start_xvfb); what the server said and whether it lives are printed.
  for attempt in 1 2 3; do
    RAYON_NUM_THREADS=$threads PIPELENS_FRAME_LOG=1 DISPLAY=$display \
      target/release/pipelens --lang en --step "$step" >"$log" 2>&1 &
    app=$!
    for _ in $(seq 1 60); do
      window=$(DISPLAY=$display xdotool search --name "step $step/" 2>/dev/null | head -1) || true
      [ -n "$window" ] && break
      kill -0 "$app" 2>/dev/null || break
      sleep 1
    done
    [ -n "$window" ] && break
    if ! kill -0 "$app" 2>/dev/null; then
      echo "native-frames: the app exited (launch $attempt of 3):" >&2
      cat "$log" >&2
      if kill -0 "$xvfb" 2>/dev/null; then echo "native-frames: Xvfb $display is running" >&2; else echo "native-frames: Xvfb $display has exited" >&2; fi
      DISPLAY=$display xdotool getdisplaygeometry >&2 || echo "native-frames: xdotool cannot reach $display either" >&2
      echo "native-frames: Xvfb's log:" >&2
      cat "$xvfb_log" >&2
      [ "$attempt" = 3 ] && exit 1
      sleep 2
    else
      break
    fi
  done
  [ -n "$window" ] || { echo "native-frames: no window on step $step after 60 s" >&2; exit 1; }
  DISPLAY=$display xdotool windowsize "$window" 1920 1080 windowmove "$window" 0 0 windowfocus "$window"
  DISPLAY=$display xdotool mousemove 1918 1078
  sleep 3
  for _ in 1 2 3 4 5; do
    DISPLAY=$display xdotool key --window "$window" Left
    sleep 1.5
    DISPLAY=$display xdotool key --window "$window" Right
    sleep 1.5
    # The latest frame logged on the step (its title ends "step N/M").
    times+=("$(grep -E "^frame: .* step $step/[0-9]+\)$" "$log" | tail -1 | sed -E 's/^frame: ([0-9.]+) ms.*/\1/')")
  done
  kill "$app" 2>/dev/null || true
  wait "$app" 2>/dev/null || true
  app=
  [ -n "${times[0]}" ] || { echo "native-frames: no frame logged on step $step:" >&2; tail "$log" >&2; exit 1; }
  local sorted
  sorted=$(printf '%s\n' "${times[@]}" | sort -n | paste -sd' ')
  echo "$(echo "$sorted" | cut -d' ' -f3) ms on $threads thread$([ "$threads" = 1 ] || echo s) (${sorted// /, })"
}

one=$(measure 1)
all=$(measure "$cores")
echo "native app, step $step: $one, $all"
