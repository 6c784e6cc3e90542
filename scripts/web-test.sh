#!/usr/bin/env bash
# The browser test: builds dist/ (scripts/build-web.sh), serves it on localhost, and loads it in
# Debian's Chromium (installed here if missing) through playwright-core (scripts/web-test/):
# the service worker isolates the page and the threaded build runs, the tour draws, a key
# advances a step, Chinese renders, the page opens offline; the tour's heaviest step's frame
# times are printed beside the native render's and the native app's (scripts/native-frames.sh).
# Screenshots land in target/web-test/.
set -euo pipefail
cd "$(dirname "$0")/.."

missing=()
command -v chromium >/dev/null 2>&1 || missing+=(chromium)
command -v node >/dev/null 2>&1 || missing+=(nodejs)
command -v npm >/dev/null 2>&1 || missing+=(npm)
if [ ${#missing[@]} -gt 0 ]; then
  echo "installing: ${missing[*]}"
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq
  apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

scripts/build-web.sh target/web-dist
(cd scripts/web-test && npm ci --no-audit --no-fund --silent)

# Two free ports on localhost, the page's and the isolating host's: a server left on one of
# them (a probe started by hand) would answer in place of the test's own, which then tests
# another folder's build. $PORT names the first; without it the first free pair from 8765.
port_free() {
  python3 -c "import socket,sys; s=socket.socket(); s.bind(('127.0.0.1', int(sys.argv[1])))" "$1" 2>/dev/null
}
if [ -n "${PORT:-}" ]; then
  port=$PORT
  for p in "$port" $((port + 1)); do
    port_free "$p" || { echo "web-test: port $p is in use (PORT=$PORT); stop what listens there or pick another PORT" >&2; exit 1; }
  done
else
  port=8765
  until port_free "$port" && port_free $((port + 1)); do
    port=$((port + 2))
    [ "$port" -lt 8865 ] || { echo "web-test: no two free ports between 8765 and 8864" >&2; exit 1; }
  done
fi
echo "serving on ports $port and $((port + 1))"
python3 -m http.server "$port" --bind 127.0.0.1 --directory target/web-dist >target/web-serve.log 2>&1 &
server=$!
# The same build from a host that isolates the page itself (scripts/serve-web.sh sends the
# headers), where the page runs from its first load with no reload through the worker: opened
# once there, it must open again offline. A copy of the build, whose worker the test changes to
# play a new build's.
rm -rf target/web-dist-isolated
cp -r target/web-dist target/web-dist-isolated
PORT=$((port + 1)) scripts/serve-web.sh target/web-dist-isolated >target/web-serve-isolated.log 2>&1 &
isolated=$!
trap 'kill $server $isolated 2>/dev/null || true' EXIT
for p in "$port" $((port + 1)); do
  for _ in $(seq 1 50); do
    python3 -c "import urllib.request; urllib.request.urlopen('http://127.0.0.1:$p/index.html')" 2>/dev/null && break
    sleep 0.2
  done
done
for pid in "$server" "$isolated"; do
  kill -0 "$pid" 2>/dev/null || { echo "web-test: a server died at start (target/web-serve*.log):" >&2; cat target/web-serve*.log >&2; exit 1; }
done
# The native frame times of the same steps, printed beside the page's: the render alone
# (bench --steps), and the app as it runs, its window painting under Xvfb at 1920×1080 as the
# page's canvas is painted (scripts/native-frames.sh; skipped where Xvfb is not installed).
cargo build --release --quiet --bin pipelens
native=$(target/release/pipelens bench --steps 00-tour --frames 5)
echo "$native"
heaviest=$(echo "$native" | tail -1 | sed -E 's/^heaviest step ([0-9]+):.*/\1/')
app_frames=
if command -v Xvfb >/dev/null && command -v xdotool >/dev/null; then
  app_frames=$(scripts/native-frames.sh "$heaviest" | tail -1)
  echo "$app_frames"
fi
NATIVE_STEPS=$(echo "$native" | tail -1) NATIVE_APP=$app_frames SERVER_PID=$server \
  ISOLATED_URL="http://127.0.0.1:$((port + 1))/index.html" ISOLATED_PID=$isolated \
  ISOLATED_DIR=target/web-dist-isolated \
  PIPELENS_BIN=$PWD/target/release/pipelens \
  node scripts/web-test/test.mjs "http://127.0.0.1:$port/index.html" target/web-test
