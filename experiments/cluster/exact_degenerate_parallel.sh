#!/usr/bin/env bash
# The degenerate-case study over M shards with GNU parallel (local cores, or other machines with
# parallel's --sshloginfile), then the merge.
#   experiments/cluster/exact_degenerate_parallel.sh OUT_DIR CASES M [parallel options...]
set -euo pipefail
OUT="${1:?OUT_DIR}"
CASES="${2:?CASES in all}"
M="${3:?M shards}"
shift 3
BIN="${GHCLIP_BIN:-build/bin}"
command -v parallel >/dev/null || { echo "exact_degenerate_parallel: GNU parallel is not installed (apt-get install parallel)" >&2; exit 2; }
seq 1 "$M" | parallel "$@" "$BIN/exact_degenerate" "$OUT" "$CASES" --shard "{}/$M"
"$BIN/exact_degenerate" "$OUT" --merge "$OUT"/exact-degenerate-shard-*-of-"$M".json
