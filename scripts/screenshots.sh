#!/usr/bin/env bash
# Takes the README's screenshots from the real app under Xvfb, at a projector's 1920×1080: the
# built-in lesson in English and Chinese, classroom mode, a pixel explained, stages of the default
# scene, the side-by-side comparisons. Needs the packages .ci/run installs.
# Usage: scripts/screenshots.sh [OUT_DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-docs/screenshots}
mkdir -p "$out"
display=:96
screen=1920x1080
w=${screen%x*}; h=${screen#*x}
cargo build --quiet --release --bin pipelens
. scripts/xvfb-lib.sh
start_xvfb
# open ARGS…: starts the app, waits for its window, fills the screen with it.
open() {
  DISPLAY=$display target/release/pipelens "$@" >/dev/null 2>&1 &
  app=$!
  win=
  for _ in $(seq 1 60); do
    win=$(DISPLAY=$display xdotool search --name '^pipelens' 2>/dev/null | head -1) && [ -n "$win" ] && break
    sleep 1
  done
  [ -n "$win" ] || { echo "screenshots: no window for pipelens $*"; exit 1; }
  DISPLAY=$display xdotool windowsize "$win" "$w" "$h" windowmove "$win" 0 0 windowfocus "$win"
  # The pointer in a corner, away from tooltips.
  DISPLAY=$display xdotool mousemove "$((w - 2))" "$((h - 2))"
  sleep 5
}
keys() { for k in "$@"; do DISPLAY=$display xdotool key --window "$win" "$k"; sleep 1.5; done; sleep 3; }
shoot() { DISPLAY=$display import -window root "$out/$1.png"; echo "wrote $out/$1.png"; }
close() { kill "$app"; wait "$app" 2>/dev/null || true; app=; }

# The built-in lesson: its first step, the projection beside the observer, the shading comparison.
for lang in en zh; do
  open --lang "$lang"
  [ "$lang" = en ] && shoot "lesson-$lang-1"
  keys Right Right Right Right
  shoot "lesson-$lang-5"
  keys Right Right Right Right Right
  shoot "lesson-$lang-10"
  close
done
# What a teacher projects: classroom mode (C), the picture first, large type.
open --lang en --classroom --step 5
shoot classroom-en-5
close
# The top-left rule, the pixel on the shared diagonal explained in the inspector (I).
open --lang en --lesson lessons/07-rasterization.toml --step 4
keys i
shoot explain-pixel
close
# Stages of the default scene, with the parameters and the inspector.
open --lang en --scene assets/scenes/default.toml
shoot en-world
keys Right
shoot en-view
keys Right
shoot en-clip
keys Right
shoot en-ndc
keys Right Right
shoot en-rasterization
close
open --lang zh --scene assets/scenes/default.toml
shoot zh-world
close
open --lang en --scene assets/scenes/default.toml --stage shading --compare shading
shoot en-compare-shading
close
open --lang en --scene assets/scenes/texture.toml --stage output --compare filtering
shoot en-compare-filtering
close
# The lesson editor (R), on a copy of lesson 17: a lesson opened from a file is edited in place.
copy=$(mktemp -d)
cp lessons/17-hierarchy.toml "$copy/"
open --lang en --lesson "$copy/17-hierarchy.toml" --step 3
keys r
shoot editor
close
rm -rf "$copy"
