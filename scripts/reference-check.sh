#!/usr/bin/env bash
# pipelens against a real OpenGL: Mesa's llvmpipe (../shared/peers/llvmpipe), pixel by pixel.
#
# Renders the bunny, Spot (plain and textured, trilinear), the cow and the GAMES101 assignment-2
# scene at 800×600 and 1280×720 with 1 and 4 samples, in pipelens (`pipelens export`) and in
# llvmpipe with the matrices of pipelens' own capture.json; then the 28 GLSL files of
# scripts/reference/shaders (a mirror's samplerCube, out/inout parameters, sampler2D parameters, the offset and grad
# lookups, integer ops, switch, structs, loops, a displacing vertex shader, …) on Spot and some on
# the bunny, the same source run by pipelens' interpreter and compiled by Mesa. It prints a table: coverage
# (identical), window depth (within 1e-5), colour (within 2/255 on ≥ 99.9 % of covered pixels).
# It fails, never skips: a peer that cannot be installed or data that is missing is a failure.
#
# Usage: scripts/reference-check.sh            (as root the first time: the peer's setup uses apt)
# Environment: PIPELENS_SHARED (default ../shared beside the repository),
#              PIPELENS_PEER_VENV (default /tmp/pipelens-llvmpipe-venv), PIPELENS_REFERENCE_OUT
#              (keep the exports there instead of a temporary folder).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
shared=${PIPELENS_SHARED:-$root/../shared}
peer=$shared/peers/llvmpipe
venv=${PIPELENS_PEER_VENV:-/tmp/pipelens-llvmpipe-venv}

fail() { echo "reference check FAILED: $*" >&2; exit 1; }
[ -f "$peer/setup.sh" ] && [ -f "$peer/render.py" ] || fail "no peer at $peer (set PIPELENS_SHARED)"
[ -d "$shared/data/models" ] || fail "no shared data at $shared/data (set PIPELENS_SHARED)"
if ! command -v python3 >/dev/null || ! python3 -c 'import venv, ensurepip' 2>/dev/null; then
  command -v apt-get >/dev/null || fail "python3 with venv is missing and apt-get is not there to install it"
  DEBIAN_FRONTEND=noninteractive apt-get update -qq
  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends python3 python3-venv >/dev/null \
    || fail "could not install python3-venv"
fi
echo "==> the peer (Mesa llvmpipe through moderngl, in $venv)"
bash "$peer/setup.sh" "$venv" || fail "the peer's setup.sh failed"
echo "==> pipelens (release build)"
(cd "$root" && cargo build --release --quiet --bin pipelens) || fail "cargo build failed"
args=(--pipelens "$root/target/release/pipelens" --peer "$peer" --data "$shared/data")
[ -n "${PIPELENS_REFERENCE_OUT:-}" ] && args+=(--work "$PIPELENS_REFERENCE_OUT")
exec "$venv/bin/python" "$root/scripts/reference/check.py" "${args[@]}"
