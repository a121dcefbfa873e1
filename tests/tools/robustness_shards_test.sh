#!/usr/bin/env bash
# The robustness study sharded over M processes and merged gives the same report as one run:
# the same tables, findings, counterexamples and counts (dates, commands and durations aside).
#   robustness_shards_test.sh BIN_DIR
set -euo pipefail
BIN="$1"
TMP="$(mktemp -d)"
trap 'rm -rf "$TMP"' EXIT
"$BIN/robustness" "$TMP/one" --cases 3 >/dev/null 2>&1
for k in 1 2 3; do "$BIN/robustness" "$TMP/sharded" --cases 3 --shard "$k/3" >/dev/null 2>&1; done
"$BIN/robustness" "$TMP/sharded" --cases 3 --merge "$TMP"/sharded/robustness-shard-*-of-3.json >/dev/null 2>&1
strip() { grep -v -e '^| made by' -e '^| date' -e 'The study took' "$1"; }
diff <(strip "$TMP/one/robustness.md") <(strip "$TMP/sharded/robustness.md")
diff -r "$TMP/one/counterexamples" "$TMP/sharded/counterexamples"
diff <(grep -v '"seconds"' "$TMP/one/robustness.json") <(grep -v '"seconds"' "$TMP/sharded/robustness.json")
# A shard of another study, or a bad --shard, is refused with exit 2.
"$BIN/robustness" "$TMP/other" --cases 2 --shard 1/2 >/dev/null 2>&1
if "$BIN/robustness" "$TMP/mixed" --merge "$TMP/sharded/robustness-shard-1-of-3.json" "$TMP/other/robustness-shard-1-of-2.json" 2>/dev/null; then
  echo "FAIL: shards of different studies merged"; exit 1
fi
if "$BIN/robustness" "$TMP/part" --merge "$TMP/sharded/robustness-shard-1-of-3.json" "$TMP/sharded/robustness-shard-2-of-3.json" 2>/dev/null; then
  echo "FAIL: 2 of 3 shards merged"; exit 1
fi
set +e
"$BIN/robustness" "$TMP/bad" --shard 3/2 2>/dev/null
test $? -eq 2 || { echo "FAIL: --shard 3/2 not refused with exit 2"; exit 1; }
echo "sharded and merged: the same report"
