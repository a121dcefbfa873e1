#!/usr/bin/env bash
# Regenerates everything in results/ from a built tree. Called by `./harness reproduce`;
# GHCLIP_FULL=1 selects the large runs. Paths are relative to the repository root so that the
# provenance of each file reads the same on every machine.
#   experiments/reproduce.sh BUILD_DIR
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$ROOT"
BUILD="$(realpath --relative-to="$ROOT" "$1")"
BIN="$BUILD/bin"
export GHCLIP_COMMIT="${GHCLIP_COMMIT:-$(git rev-parse --short HEAD 2>/dev/null || echo unknown)}"
if [[ -n "$(git status --porcelain -- clipper io oracles workloads tools experiments 2>/dev/null)" ]]; then
  GHCLIP_COMMIT+="-dirty"
fi

step() { printf '[reproduce] %s\n' "$*" >&2; }

step "examples -> results/examples/"
rm -rf results/examples
"$BIN/run_examples" experiments/examples results/examples

step "naive variant judged by the exact oracle -> results/oracle-first-look.md"
rm -rf results/oracle-first-look results/oracle-first-look.md
"$BIN/oracle_first_look" results 1000
