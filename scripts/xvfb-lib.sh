# Shared by smoke-app.sh and screenshots.sh: start Xvfb on $display and clean up on exit.
# Sourced, not run. Needs $display set by the caller.
start_xvfb() {
  Xvfb "$display" -screen 0 "${screen:-1366x768}x24" -nolisten tcp >/dev/null 2>&1 &
  xvfb=$!
  app=
  trap 'cleanup_xvfb' EXIT
  sleep 1
}
cleanup_xvfb() {
  if [ -n "${app:-}" ]; then kill "$app" 2>/dev/null || true; fi
  kill "$xvfb" 2>/dev/null || true
  wait 2>/dev/null || true
}
