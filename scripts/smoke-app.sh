#!/usr/bin/env bash
# Starts the real pipelens app under Xvfb (Mesa's software OpenGL), waits for its window, takes a
# screenshot and fails if the window did not appear or the screenshot is blank.
# Needs: xvfb xauth libxcursor1 libxi6 libxkbcommon-x11-0 libegl1 libegl-mesa0 libgl1-mesa-dri
#        imagemagick xdotool (.ci/run installs them).
# Usage: scripts/smoke-app.sh [OUT.png] [extra pipelens arguments…]
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-target/smoke-app.png}
shift || true
display=:97
cargo build --quiet --bin pipelens
. scripts/xvfb-lib.sh
start_xvfb
# Once in a while a client that connects just as the server settles is refused ("Failed to open
# connection to X server") though the server then accepts the next one: that, and only that, is
# tried again, at most three times.
for attempt in 1 2 3; do
  DISPLAY=$display target/debug/pipelens "$@" >target/smoke-app.log 2>&1 &
  app=$!
  refused=
  for _ in $(seq 1 60); do
    if DISPLAY=$display xdotool search --name '^pipelens' >/dev/null 2>&1; then break; fi
    if ! kill -0 "$app" 2>/dev/null; then
      if [ "$attempt" -lt 3 ] && grep -q "Failed to open connection to X server" target/smoke-app.log; then
        echo "smoke: the X server refused the app (attempt $attempt); trying again"
        refused=yes; sleep 2; break
      fi
      echo "smoke: the app exited before its window appeared:"; cat target/smoke-app.log; exit 1
    fi
    sleep 1
  done
  [ -z "$refused" ] && break
done
if ! DISPLAY=$display xdotool search --name '^pipelens' >/dev/null 2>&1; then
  echo "smoke: no window named pipelens after 60 s"; cat target/smoke-app.log; exit 1
fi
sleep "${SMOKE_SETTLE:-4}"
DISPLAY=$display import -window root "$out"
# A blank screenshot has (nearly) one colour: require some variety.
colours=$(convert "$out" -format '%k' info:)
deviation=$(convert "$out" -colorspace Gray -format '%[fx:standard_deviation]' info:)
echo "smoke: window up; screenshot $out has $colours colours, grey deviation $deviation"
if [ "$colours" -lt 50 ]; then
  echo "smoke: the screenshot is blank"; exit 1
fi
if ! kill -0 "$app" 2>/dev/null; then
  echo "smoke: the app died after showing its window:"; cat target/smoke-app.log; exit 1
fi
echo "smoke: ok"
