#!/usr/bin/env bash
# Builds pipelens for the browser into dist/ (or $1): the `web/` crate compiled to WebAssembly
# twice, its JavaScript glue written by the wasm-bindgen CLI, web/index.html and the service
# worker web/sw.js (stamped with the build's version):
#   dist/            the single-threaded build (stable Rust): any page
#   dist/threads/    the threaded build: a rayon pool on Web Workers over shared memory, for a
#                    page that is cross-origin isolated (nightly Rust, `+atomics,+bulk-memory`,
#                    the standard library rebuilt with them: `-Z build-std`)
# Installs what is missing first: the wasm32 target, the pinned nightly with its rust-src
# (rustup), wasm-bindgen-cli at the version Cargo.lock pins (the CLI and the library must
# agree exactly), and Binaryen's wasm-opt (npm, scripts/web-tools). PIPELENS_WEB_SIMD=0 builds without wasm SIMD (+simd128, on by default);
# PIPELENS_WEB_THREADS=0 skips the threaded build. Prints each wasm's size, raw and gzipped.
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-dist}
# The nightly the threaded build is made with: pinned, so that a new nightly cannot break it.
nightly=nightly-2026-10-30

if ! rustup target list --installed | grep -qx wasm32-unknown-unknown; then
  echo "installing the wasm32-unknown-unknown target"
  rustup target add wasm32-unknown-unknown
fi
threads=${PIPELENS_WEB_THREADS:-1}
if [ "$threads" = 1 ] \
  && ! rustup component list --toolchain "$nightly" --installed 2>/dev/null | grep -q '^rust-src'; then
  echo "installing $nightly with rust-src (for the threaded build)"
  rustup toolchain install "$nightly" --profile minimal --component rust-src
fi
if ! command -v node >/dev/null 2>&1 || ! command -v npm >/dev/null 2>&1; then
  echo "installing nodejs and npm (for Binaryen's wasm-opt)"
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq
  apt-get install -y -qq --no-install-recommends nodejs npm >/dev/null
fi
if [ ! -x scripts/web-tools/node_modules/.bin/wasm-opt ]; then
  echo "installing Binaryen's wasm-opt (scripts/web-tools)"
  (cd scripts/web-tools && npm ci --no-audit --no-fund --silent)
fi
want=$(awk '/^name = "wasm-bindgen"$/ { getline; gsub(/"/, "", $3); print $3; exit }' Cargo.lock)
have=$(wasm-bindgen --version 2>/dev/null | awk '{ print $2 }' || true)
if [ "$have" != "$want" ]; then
  echo "installing wasm-bindgen-cli $want (found: ${have:-none})"
  cargo install --quiet wasm-bindgen-cli --version "$want"
fi

simd=""
suffix=""
if [ "${PIPELENS_WEB_SIMD:-1}" = 1 ]; then
  simd=",+simd128"
else
  # Its own target folder: switching the flags back and forth would rebuild everything.
  suffix="-nosimd"
fi

# The `web` profile: one code unit optimized across crates, no debug tables (Cargo.toml).
build() { # build NAME DIR: compiles, runs wasm-bindgen into DIR, prints the size
  local name=$1 dir=$2 wasm
  # No function names: 1.5 MB that only a debugger reads (a panic's message still says where).
  wasm-bindgen --target web --no-typescript --remove-name-section --remove-producers-section \
    --out-dir "$dir" "$3"
  wasm="$dir/pipelens_web_bg.wasm"
  # Binaryen's size passes: 10.5 → 9.7 MB, the frame times unchanged (BENCHMARKS.md). The
  # features are those the wasm declares (its target_features section).
  node scripts/web-tools/node_modules/binaryen/bin/wasm-opt -Os "$wasm" -o "$wasm.opt"
  mv "$wasm.opt" "$wasm"
  local raw gz
  raw=$(stat -c %s "$wasm")
  gz=$(gzip -9 -c "$wasm" | wc -c)
  awk -v name="$name" -v raw="$raw" -v gz="$gz" -v simd="${simd:+, +simd128}" \
    'BEGIN { printf "built %s: wasm %.1f MB, %.1f MB gzipped%s\n", name, raw / 1e6, gz / 1e6, simd }'
}

rm -rf "$out"
mkdir -p "$out"
CARGO_TARGET_WASM32_UNKNOWN_UNKNOWN_RUSTFLAGS="-C target-feature=+bulk-memory$simd" \
  cargo build --quiet -p pipelens-web --profile web --target wasm32-unknown-unknown \
  --target-dir "target/web$suffix"
build "$out (one thread)" "$out" "target/web$suffix/wasm32-unknown-unknown/web/pipelens_web.wasm"

if [ "$threads" = 1 ]; then
  # Shared memory (imported, so that every worker gets the same), up to the 4 GiB a wasm32
  # address space has: a capture at 1080p with 4 samples is a quarter of a gigabyte, and a page
  # may hold several. The thread-local storage's symbols are what wasm-bindgen's thread
  # set-up calls in each worker.
  link=""
  for arg in --shared-memory --import-memory --max-memory=4294967296 --export=__wasm_init_tls \
    --export=__tls_size --export=__tls_align --export=__tls_base; do
    link="$link -C link-arg=$arg"
  done
  CARGO_TARGET_WASM32_UNKNOWN_UNKNOWN_RUSTFLAGS="-C target-feature=+atomics,+bulk-memory,+mutable-globals$simd$link" \
    cargo "+$nightly" build --quiet -p pipelens-web --features threads --profile web \
    --target wasm32-unknown-unknown -Z build-std=panic_abort,std \
    --target-dir "target/web-threads$suffix"
  build "$out/threads" "$out/threads" \
    "target/web-threads$suffix/wasm32-unknown-unknown/web/pipelens_web.wasm"
fi

cp web/index.html "$out/"
version=$(find "$out" -name '*.wasm' | sort | xargs cat | sha256sum | cut -c1-16)
# Each build's files, for the service worker to keep the one in use from the page's first visit
# (a JSON list of paths relative to the page).
list() { # list FIND-ARGS...: the files, as "a","b"
  (cd "$out" && find . -type f "$@" -printf '%P\n' | sort | sed 's/.*/"&"/' | paste -sd, -)
}
one=$(list ! -path './threads/*' ! -name index.html)
threaded=$(list -path './threads/*')
sed -e "s/@BUILD@/$version/" -e "s|\"@ONE@\"|$one|" -e "s|\"@THREADS@\"|$threaded|" web/sw.js >"$out/sw.js"
