#!/usr/bin/env bash
# Serves the browser build (dist/, or $1) on http://127.0.0.1:${PORT:-8080}/ until stopped: open
# that address in a browser with WebGL2. Build it first with scripts/build-web.sh.
set -euo pipefail
cd "$(dirname "$0")/.."
dir=${1:-dist}
port=${PORT:-8080}
if [ ! -f "$dir/index.html" ]; then
  echo "no $dir/index.html: run scripts/build-web.sh first" >&2
  exit 1
fi
echo "pipelens on http://127.0.0.1:$port/ (Ctrl+C stops)"
exec python3 -m http.server "$port" --bind 127.0.0.1 --directory "$dir"
