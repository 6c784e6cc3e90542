#!/usr/bin/env bash
# Builds autograder.zip for Gradescope from this checkout: a portable pipelens binary (no
# processor-specific instructions), setup.sh, run_autograder and lab.conf. Edit lab.conf first.
#   scripts/gradescope/make-zip.sh [OUT.zip]
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
repo="$(cd "$here/../.." && pwd)"
out="$(realpath -m "${1:-autograder.zip}")"
(cd "$repo" && RUSTFLAGS= cargo build --release --target-dir target/portable)
stage="$(mktemp -d)"
trap 'rm -rf "$stage"' EXIT
mkdir -p "$stage/bin"
cp "$repo/target/portable/release/pipelens" "$stage/bin/pipelens"
# Without its debug information (136 MB → 23 MB), which Gradescope uploads faster.
if command -v strip >/dev/null; then strip "$stage/bin/pipelens"; fi
cp "$here/setup.sh" "$here/run_autograder" "$here/lab.conf" "$stage/"
rm -f "$out"
(cd "$stage" && python3 -m zipfile -c "$out" setup.sh run_autograder lab.conf bin)
echo "wrote $out"
