# Shared by smoke-app.sh and screenshots.sh: start Xvfb and clean up on exit.
# Sourced, not run. The caller sets $display (the display it prefers, e.g. :97) and may set
# $screen (WxH); start_xvfb moves $display to the first free one from there (a display another
# server holds, or a stale lock, would otherwise make the app fail to connect) and returns once
# the server accepts connections: a client has connected and read the screen's size (its
# socket alone appearing was once not enough: the app then failed to connect in CI).
start_xvfb() {
  local n=${display#:}
  while [ -e "/tmp/.X$n-lock" ] || [ -e "/tmp/.X11-unix/X$n" ]; do n=$((n + 1)); done
  display=:$n
  xvfb_log=$(mktemp)
  Xvfb "$display" -screen 0 "${screen:-1366x768}x24" -nolisten tcp >"$xvfb_log" 2>&1 &
  xvfb=$!
  app=
  trap 'cleanup_xvfb' EXIT
  for _ in $(seq 1 60); do
    if [ -S "/tmp/.X11-unix/X$n" ] && DISPLAY=$display xdotool getdisplaygeometry >/dev/null 2>&1; then
      return 0
    fi
    kill -0 "$xvfb" 2>/dev/null || break
    sleep 0.5
  done
  echo "Xvfb did not start on $display:"
  cat "$xvfb_log"
  exit 1
}
cleanup_xvfb() {
  if [ -n "${app:-}" ]; then kill "$app" 2>/dev/null || true; fi
  kill "$xvfb" 2>/dev/null || true
  wait 2>/dev/null || true
}
