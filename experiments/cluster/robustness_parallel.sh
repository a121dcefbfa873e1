#!/usr/bin/env bash
# The robustness study over M shards with GNU parallel (local cores, or other machines with
# parallel's --sshloginfile), then the merge.
#   experiments/cluster/robustness_parallel.sh OUT_DIR CASES M [parallel options...]
set -euo pipefail
OUT="${1:?OUT_DIR}"
CASES="${2:?CASES per class}"
M="${3:?M shards}"
shift 3
BIN="${GHCLIP_BIN:-build/bin}"
command -v parallel >/dev/null || { echo "robustness_parallel: GNU parallel is not installed (apt-get install parallel)" >&2; exit 2; }
seq 1 "$M" | parallel "$@" "$BIN/robustness" "$OUT" --cases "$CASES" --shard "{}/$M"
"$BIN/robustness" "$OUT" --cases "$CASES" --merge "$OUT"/robustness-shard-*-of-"$M".json
