#!/usr/bin/env bash
# The robustness study over M shards with GNU parallel (local cores, or other machines with
# parallel's --sshloginfile), then the merge. GHCLIP_STUDY_ARGS adds options to every shard and
# the merge (e.g. "--methods exact").
#   experiments/cluster/robustness_parallel.sh OUT_DIR CASES M [parallel options...]
set -euo pipefail
OUT="${1:?OUT_DIR}"
CASES="${2:?CASES per class}"
M="${3:?M shards}"
shift 3
BIN="${GHCLIP_BIN:-build/bin}"
read -r -a EXTRA <<<"${GHCLIP_STUDY_ARGS:-}"
command -v parallel >/dev/null || { echo "robustness_parallel: GNU parallel is not installed (apt-get install parallel)" >&2; exit 2; }
seq 1 "$M" | parallel "$@" "$BIN/robustness" "$OUT" --cases "$CASES" "${EXTRA[@]}" --shard "{}/$M"
"$BIN/robustness" "$OUT" --cases "$CASES" "${EXTRA[@]}" --merge "$OUT"/robustness-shard-*-of-"$M".json
