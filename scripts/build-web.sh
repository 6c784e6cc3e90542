#!/usr/bin/env bash
# Builds pipelens for the browser into dist/ (or $1): the `web/` crate compiled to WebAssembly,
# its JavaScript glue written by the wasm-bindgen CLI, and web/index.html. Installs what is
# missing first: the wasm32 target (rustup) and wasm-bindgen-cli at the version Cargo.lock pins
# (the CLI and the library must agree exactly). PIPELENS_WEB_SIMD=1 builds with wasm SIMD
# (+simd128). Prints the wasm's size, raw and gzipped.
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-dist}

if ! rustup target list --installed | grep -qx wasm32-unknown-unknown; then
  echo "installing the wasm32-unknown-unknown target"
  rustup target add wasm32-unknown-unknown
fi
want=$(awk '/^name = "wasm-bindgen"$/ { getline; gsub(/"/, "", $3); print $3; exit }' Cargo.lock)
have=$(wasm-bindgen --version 2>/dev/null | awk '{ print $2 }' || true)
if [ "$have" != "$want" ]; then
  echo "installing wasm-bindgen-cli $want (found: ${have:-none})"
  cargo install --quiet wasm-bindgen-cli --version "$want"
fi

flags=""
target_dir=target
if [ "${PIPELENS_WEB_SIMD:-0}" = 1 ]; then
  # Its own target folder: switching the flags back and forth would rebuild everything.
  flags="-C target-feature=+simd128"
  target_dir=target/web-simd
fi
# No debug line tables in the browser: they would double the download.
CARGO_PROFILE_RELEASE_DEBUG=false CARGO_TARGET_WASM32_UNKNOWN_UNKNOWN_RUSTFLAGS="$flags" \
  cargo build --quiet -p pipelens-web --release --target wasm32-unknown-unknown \
  --target-dir "$target_dir"

rm -rf "$out"
mkdir -p "$out"
wasm-bindgen --target web --no-typescript --out-dir "$out" \
  "$target_dir/wasm32-unknown-unknown/release/pipelens_web.wasm"
cp web/index.html "$out/"
wasm="$out/pipelens_web_bg.wasm"
raw=$(stat -c %s "$wasm")
gz=$(gzip -9 -c "$wasm" | wc -c)
awk -v out="$out" -v raw="$raw" -v gz="$gz" -v simd="${flags:+, with +simd128}" \
  'BEGIN { printf "built %s: wasm %.1f MB, %.1f MB gzipped%s\n", out, raw / 1e6, gz / 1e6, simd }'
