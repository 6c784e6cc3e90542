#!/usr/bin/env bash
# Serves the browser build (dist/, or $1) on http://127.0.0.1:${PORT:-8080}/ until stopped: open
# that address in a browser with WebGL2. Build it first with scripts/build-web.sh. The page is
# served cross-origin isolated (the two headers below), so it runs the threaded build on every
# core at once; a static host without them gets them from the page's service worker instead.
set -euo pipefail
cd "$(dirname "$0")/.."
dir=${1:-dist}
port=${PORT:-8080}
if [ ! -f "$dir/index.html" ]; then
  echo "no $dir/index.html: run scripts/build-web.sh first" >&2
  exit 1
fi
echo "pipelens on http://127.0.0.1:$port/ (Ctrl+C stops)"
exec python3 - "$dir" "$port" <<'PY'
import functools, http.server, sys

class Isolated(http.server.SimpleHTTPRequestHandler):
    def end_headers(self):
        self.send_header("Cross-Origin-Opener-Policy", "same-origin")
        self.send_header("Cross-Origin-Embedder-Policy", "require-corp")
        super().end_headers()

handler = functools.partial(Isolated, directory=sys.argv[1])
http.server.ThreadingHTTPServer(("127.0.0.1", int(sys.argv[2])), handler).serve_forever()
PY
