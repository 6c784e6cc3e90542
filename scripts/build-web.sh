#!/usr/bin/env bash
# Builds pipelens for the browser into dist/ (or $1): the `web/` crate compiled to WebAssembly
# twice, its JavaScript glue written by the wasm-bindgen CLI, web/index.html and the service
# worker web/sw.js (stamped with the build's version):
#   dist/            the single-threaded build (stable Rust): any page
#   dist/threads/    the threaded build: a rayon pool on Web Workers over shared memory, for a
#                    page that is cross-origin isolated (nightly Rust, `+atomics,+bulk-memory`,
#                    the standard library rebuilt with them: `-Z build-std`)
# Installs what is missing first: the wasm32 target, the pinned nightly with its rust-src
# (rustup), and wasm-bindgen-cli at the version Cargo.lock pins (the CLI and the library must
# agree exactly). The two builds compile side by side: after a change to pipelens alone each is
# mostly its one-unit link-time optimization, which runs on one core. PIPELENS_WEB_SIMD=0
# builds without wasm SIMD (+simd128, on by default); PIPELENS_WEB_THREADS=0 skips the threaded
# build. Prints each phase's time and each wasm's size, raw and gzipped.
set -euo pipefail
started=$SECONDS
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
want=$(awk '/^name = "wasm-bindgen"$/ { getline; gsub(/"/, "", $3); print $3; exit }' Cargo.lock)
have=$(wasm-bindgen --version 2>/dev/null | awk '{ print $2 }' || true)
if [ "$have" != "$want" ]; then
  echo "installing wasm-bindgen-cli $want (found: ${have:-none})"
  # Optimized lightly, in parallel units, without link-time optimization: 1 min 51 s to
  # compile on two cores instead of 14 min, and its output is the same bytes, as fast (1.3
  # against 1.2 s on pipelens' wasm; BENCHMARKS.md). Forced: cargo skips a version it has
  # installed before, even when its program was removed since.
  CARGO_PROFILE_RELEASE_OPT_LEVEL=1 CARGO_PROFILE_RELEASE_CODEGEN_UNITS=16 \
    CARGO_PROFILE_RELEASE_LTO=false CARGO_PROFILE_RELEASE_DEBUG=0 \
    cargo install --quiet --force wasm-bindgen-cli --version "$want"
fi

simd=""
suffix=""
if [ "${PIPELENS_WEB_SIMD:-1}" = 1 ]; then
  simd=",+simd128"
else
  # Its own target folder: switching the flags back and forth would rebuild everything.
  suffix="-nosimd"
fi

took() { # took WHAT: prints WHAT with the minutes and seconds since the script started
  local t=$((SECONDS - started))
  printf '%s: %d min %02d s\n' "$1" $((t / 60)) $((t % 60))
}

# The `web` profile: one code unit optimized across crates, no debug tables (Cargo.toml).
# No Binaryen `wasm-opt -Os` pass after wasm-bindgen: through npm's binaryen.js it took 2 min
# 25 s a build on two cores (8 min without SIMD), for a wasm 8 % smaller raw but 2 % larger
# gzipped, as a host sends it (BENCHMARKS.md).
bindgen() { # bindgen NAME DIR WASM: wasm-bindgen's glue and wasm into DIR, their sizes printed
  local name=$1 dir=$2 wasm
  # No function names: 1.5 MB that only a debugger reads (a panic's message still says where).
  wasm-bindgen --target web --no-typescript --remove-name-section --remove-producers-section \
    --out-dir "$dir" "$3"
  wasm="$dir/pipelens_web_bg.wasm"
  local raw gz
  raw=$(stat -c %s "$wasm")
  gz=$(gzip -9 -c "$wasm" | wc -c)
  awk -v name="$name" -v raw="$raw" -v gz="$gz" -v simd="${simd:+, +simd128}" \
    'BEGIN { printf "built %s: wasm %.1f MB, %.1f MB gzipped%s\n", name, raw / 1e6, gz / 1e6, simd }'
}

rm -rf "$out"
mkdir -p "$out"
one_thread_build() {
  CARGO_TARGET_WASM32_UNKNOWN_UNKNOWN_RUSTFLAGS="-C target-feature=+bulk-memory$simd" \
    cargo build --quiet -p pipelens-web --profile web --target wasm32-unknown-unknown \
    --target-dir "target/web$suffix"
  took "compiled the one-thread build"
}
threaded_build() {
  # Shared memory (imported, so that every worker gets the same), up to the 4 GiB a wasm32
  # address space has: a capture at 1080p with 4 samples is a quarter of a gigabyte, and a page
  # may hold several. The thread-local storage's symbols are what wasm-bindgen's thread
  # set-up calls in each worker.
  local link="" arg
  for arg in --shared-memory --import-memory --max-memory=4294967296 --export=__wasm_init_tls \
    --export=__tls_size --export=__tls_align --export=__tls_base; do
    link="$link -C link-arg=$arg"
  done
  CARGO_TARGET_WASM32_UNKNOWN_UNKNOWN_RUSTFLAGS="-C target-feature=+atomics,+bulk-memory,+mutable-globals$simd$link" \
    cargo "+$nightly" build --quiet -p pipelens-web --features threads --profile web \
    --target wasm32-unknown-unknown -Z build-std=panic_abort,std \
    --target-dir "target/web-threads$suffix"
  took "compiled the threaded build"
}
if [ "$threads" = 1 ]; then
  threaded_build &
  pending=$!
  # A failed one-thread build leaves no compile behind it.
  trap 'pkill -P "$pending" 2>/dev/null || true' EXIT
  one_thread_build
  # `wait` returns the background build's status: a failed compile stops here (set -e).
  wait "$pending"
else
  one_thread_build
fi
bindgen "$out (one thread)" "$out" "target/web$suffix/wasm32-unknown-unknown/web/pipelens_web.wasm"
if [ "$threads" = 1 ]; then
  bindgen "$out/threads" "$out/threads" \
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
took "built $out"
