#!/usr/bin/env bash
# Takes the README's screenshots from the real app under Xvfb: every stage in English, a few in
# Chinese. Needs the packages .ci/run installs. Usage: scripts/screenshots.sh [OUT_DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-docs/screenshots}
mkdir -p "$out"
display=:96
cargo build --quiet --release --bin pipelens
. scripts/xvfb-lib.sh
start_xvfb
shoot() { DISPLAY=$display import -window root "$out/$1.png"; echo "wrote $out/$1.png"; }
start() {
  DISPLAY=$display target/release/pipelens "$@" >/dev/null 2>&1 &
  app=$!
  for _ in $(seq 1 60); do
    win=$(DISPLAY=$display xdotool search --name '^pipelens$' 2>/dev/null | head -1) && [ -n "$win" ] && break
    sleep 1
  done
  DISPLAY=$display xdotool windowsize "$win" 1366 768 windowmove "$win" 0 0 windowfocus "$win"
  sleep 4
}
start --lang en --scene assets/scenes/default.toml
# A scene file opens on World; walk back to Model, then through every stage.
DISPLAY=$display xdotool key --window "$win" Left; sleep 3
for stage in model world view clip ndc viewport rasterization depth shading texturing output; do
  shoot "en-$stage"
  DISPLAY=$display xdotool key --window "$win" Right; sleep 3
done
kill "$app"; wait "$app" 2>/dev/null || true
start --lang zh --scene assets/scenes/default.toml
shoot "zh-world"
for _ in 1 2 3 4 5; do DISPLAY=$display xdotool key --window "$win" Right; sleep 1.5; done
sleep 2
shoot "zh-rasterization"
kill "$app"; wait "$app" 2>/dev/null || true
# The built-in lesson (the tour): its first step, the projection step, the shading comparison.
for lang in en zh; do
  start --lang "$lang"
  shoot "lesson-$lang-1"
  for _ in 1 2 3 4; do DISPLAY=$display xdotool key --window "$win" Right; sleep 1.5; done
  sleep 2
  shoot "lesson-$lang-5"
  for _ in 1 2 3 4 5; do DISPLAY=$display xdotool key --window "$win" Right; sleep 1.5; done
  sleep 4
  shoot "lesson-$lang-10"
  kill "$app"; wait "$app" 2>/dev/null || true
done
