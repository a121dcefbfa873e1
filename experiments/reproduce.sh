#!/usr/bin/env bash
# Regenerates everything in results/ from a built tree. Called by `./harness reproduce`;
# GHCLIP_FULL=1 selects the large runs.
#   experiments/reproduce.sh BUILD_DIR RESULTS_DIR
set -euo pipefail
BUILD="$1"
RESULTS="$2"
HERE="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
BIN="$BUILD/bin"
export GHCLIP_COMMIT="${GHCLIP_COMMIT:-$(git -C "$HERE" rev-parse --short HEAD 2>/dev/null || echo unknown)}"
if [[ -n "$(git -C "$HERE" status --porcelain 2>/dev/null)" ]]; then GHCLIP_COMMIT+="-dirty"; fi

step() { printf '[reproduce] %s\n' "$*" >&2; }

step "examples -> results/examples/"
rm -rf "$RESULTS/examples"
(cd "$HERE/.." && "$BIN/run_examples" experiments/examples "${RESULTS#$PWD/}/examples")
