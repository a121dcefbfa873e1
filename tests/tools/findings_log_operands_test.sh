#!/usr/bin/env bash
# A finding's line names its own input's operands: fuzz/findings.h writes the operands' WKT once
# for the findings in a row that share them (an execution records one per operation), and must
# never carry it over to the next input's findings. The naive target's seed and regression
# inputs replayed in one process give the same lines as each replayed in a process of its own.
#   findings_log_operands_test.sh BIN_DIR SOURCE_DIR
set -euo pipefail
BIN="$1"
SRC="$2"
TMP="$(mktemp -d)"
trap 'rm -rf "$TMP"' EXIT
mapfile -t inputs < <(find "$SRC/fuzz/fuzz_clip_naive_seed_corpus" "$SRC/tests/regressions/fuzz/fuzz_clip_naive" \
  -type f 2>/dev/null | sort)
GHCLIP_FUZZ_FINDINGS="$TMP/together.tsv" "$BIN/fuzz_clip_naive" "${inputs[@]}" >/dev/null 2>&1
: >"$TMP/alone.tsv"
for input in "${inputs[@]}"; do
  GHCLIP_FUZZ_FINDINGS="$TMP/alone.tsv" "$BIN/fuzz_clip_naive" "$input" >/dev/null 2>&1
done
inputsWithFindings=$(cut -f6 "$TMP/alone.tsv" | sort -u | wc -l)
test "$inputsWithFindings" -ge 2 || { echo "FAIL: findings on $inputsWithFindings inputs, the test needs several"; exit 1; }
diff <(sort "$TMP/alone.tsv") <(sort "$TMP/together.tsv") >"$TMP/diff" ||
  { echo "FAIL: replayed together, other lines than one process per input:"; head -c 2000 "$TMP/diff"; exit 1; }
echo "PASS: $(wc -l <"$TMP/together.tsv") findings on $inputsWithFindings inputs, the same lines together as alone"
