#!/usr/bin/env bash
# Fuzz jobs of one campaign (libFuzzer's fork mode) append to one findings file at once: each
# process's lines must arrive whole, never run into another's (the campaign at b82520d lost its
# report to two lines cut by another job's block). Three processes replay the naive target's
# seed and regression inputs many times into one file: every line has its six fields, each
# appears as often as three runs give it, and fuzz_findings reads the file. A collision is rare
# (a few microseconds between two writes), so the test also checks its cause: one write(2) per
# flush.
# And a line names its own input's operands: fuzz/findings.h writes the operands' WKT once for
# the findings in a row that share them (an execution records one per operation), and must never
# carry it over to the next input's findings: the inputs replayed in one process give the same
# lines as each replayed in a process of its own.
#   findings_log_concurrent_test.sh BIN_DIR SOURCE_DIR
set -euo pipefail
BIN="$1"
SRC="$2"
TMP="$(mktemp -d)"
trap 'rm -rf "$TMP"' EXIT
mapfile -t inputs < <(find "$SRC/fuzz/fuzz_clip_naive_seed_corpus" "$SRC/tests/regressions/fuzz/fuzz_clip_naive" \
  -type f 2>/dev/null | sort)
GHCLIP_FUZZ_FINDINGS="$TMP/one.tsv" "$BIN/fuzz_clip_naive" "${inputs[@]}" >/dev/null 2>&1
once=$(wc -l <"$TMP/one.tsv")
test "$once" -gt 0 || { echo "FAIL: the naive target recorded nothing on its seeds"; exit 1; }
for input in "${inputs[@]}"; do
  GHCLIP_FUZZ_FINDINGS="$TMP/alone.tsv" "$BIN/fuzz_clip_naive" "$input" >/dev/null 2>&1
done
inputsWithFindings=$(cut -f6 "$TMP/alone.tsv" | sort -u | wc -l)
test "$inputsWithFindings" -ge 2 || { echo "FAIL: findings on $inputsWithFindings inputs, the test needs several"; exit 1; }
diff <(sort "$TMP/alone.tsv") <(sort "$TMP/one.tsv") >"$TMP/diff" ||
  { echo "FAIL: replayed together, other lines than one process per input:"; head -c 2000 "$TMP/diff"; exit 1; }
# Enough repeats for several blocks per process (fuzz/findings.h flushes every 64 KiB).
repeats=$(( 4 * 65536 / $(wc -c <"$TMP/one.tsv") + 1 ))
many=()
for ((i = 0; i < repeats; ++i)); do many+=("${inputs[@]}"); done
for job in 1 2 3; do
  GHCLIP_FUZZ_FINDINGS="$TMP/shared.tsv" "$BIN/fuzz_clip_naive" "${many[@]}" >/dev/null 2>&1 &
done
wait
# The kernel appends one write(2) whole, not several: each flush must be one (strace -y names
# the file behind each descriptor).
# A container that forbids ptrace cannot run strace: said on the test's output, the rest runs.
opens=unchecked
if strace -qq -e trace=none true >/dev/null 2>&1; then
  GHCLIP_FUZZ_FINDINGS="$TMP/traced.tsv" strace -f -qq -y -e trace=openat,write -o "$TMP/trace" \
    "$BIN/fuzz_clip_naive" "${many[@]}" >/dev/null 2>&1
  opens=$(grep -c 'openat(.*traced\.tsv"' "$TMP/trace" || true)
  writes=$(grep -c '^[0-9]* *write([0-9]*<[^>]*traced\.tsv>' "$TMP/trace" || true)
  test "$opens" -gt 1 || { echo "FAIL: $opens flushes of $(wc -c <"$TMP/traced.tsv") bytes, expected several"; exit 1; }
  test "$writes" -eq "$opens" || { echo "FAIL: $writes writes in $opens flushes"; exit 1; }
else
  echo "NOTE: strace cannot trace here (ptrace refused): one write per flush not checked"
fi
bad=$(awk -F'\t' 'NF != 6' "$TMP/shared.tsv" | wc -l)
test "$bad" -eq 0 || { echo "FAIL: $bad lines without six fields"; exit 1; }
test "$(wc -l <"$TMP/shared.tsv")" -eq $((3 * repeats * once)) ||
  { echo "FAIL: $(wc -l <"$TMP/shared.tsv") lines, not $((3 * repeats * once))"; exit 1; }
diff <(sort -u "$TMP/one.tsv") <(sort -u "$TMP/shared.tsv") >/dev/null || { echo "FAIL: other lines"; exit 1; }
"$BIN/fuzz_findings" "$TMP/shared.tsv" >/dev/null
echo "PASS: one write per flush ($opens); $((3 * repeats * once)) lines from 3 processes, all whole; each input's own operands ($inputsWithFindings inputs alone and together)"
