#!/usr/bin/env bash
# Gradescope runs this once, when it builds the autograder's image (Ubuntu). pipelens is either
# shipped in the zip as source/bin/pipelens (built with `RUSTFLAGS= cargo build --release`, so
# that it runs on any x86-64 processor: see README.md), or built here from source/pipelens/.
set -euo pipefail
ROOT="${AUTOGRADER_ROOT:-/autograder}"
if [ -x "$ROOT/source/bin/pipelens" ]; then
  echo "pipelens is shipped: $("$ROOT/source/bin/pipelens" --version)"
  exit 0
fi
if [ ! -d "$ROOT/source/pipelens" ]; then
  echo "setup.sh: neither source/bin/pipelens nor source/pipelens/ is in the autograder zip" >&2
  exit 1
fi
apt-get update -qq
apt-get install -y -qq --no-install-recommends curl ca-certificates build-essential
if ! command -v cargo >/dev/null; then
  curl -sSf https://sh.rustup.rs | sh -s -- -y --profile minimal
  # shellcheck source=/dev/null
  source "$HOME/.cargo/env"
fi
cd "$ROOT/source/pipelens"
RUSTFLAGS= cargo build --release --locked
mkdir -p "$ROOT/source/bin"
cp target/release/pipelens "$ROOT/source/bin/pipelens"
