#!/usr/bin/env bash
# The degenerate-case study sharded over M processes and merged gives the same report as one run
# (dates and commands aside); a bad --shard, a missing shard or a shard of another study is
# refused with exit 2.
#   exact_degenerate_shards_test.sh BIN_DIR
set -euo pipefail
BIN="$1"
TMP="$(mktemp -d)"
trap 'rm -rf "$TMP"' EXIT
"$BIN/exact_degenerate" "$TMP/one" 40 >/dev/null
for k in 1 2 3; do "$BIN/exact_degenerate" "$TMP/sharded" 40 --shard "$k/3" >/dev/null; done
"$BIN/exact_degenerate" "$TMP/sharded" --merge "$TMP"/sharded/exact-degenerate-shard-*-of-3.json >/dev/null
strip() { grep -v -e '^| made by' -e '^| date' "$1"; }
diff <(strip "$TMP/one/exact-degenerate.md") <(strip "$TMP/sharded/exact-degenerate.md")
grep -q 'naive: worst relative' "$TMP/sharded/exact-degenerate.md"
"$BIN/exact_degenerate" "$TMP/other" 16 --shard 1/2 >/dev/null
expect2() {
  set +e
  "$@" >/dev/null 2>&1
  local code=$?
  set -e
  test "$code" -eq 2 || { echo "FAIL: exit $code, not 2: $*"; exit 1; }
}
expect2 "$BIN/exact_degenerate" "$TMP/mixed" --merge "$TMP/sharded/exact-degenerate-shard-1-of-3.json" "$TMP/other/exact-degenerate-shard-1-of-2.json"
expect2 "$BIN/exact_degenerate" "$TMP/part" --merge "$TMP/sharded/exact-degenerate-shard-1-of-3.json" "$TMP/sharded/exact-degenerate-shard-2-of-3.json"
expect2 "$BIN/exact_degenerate" "$TMP/bad" 40 --shard 3/2
echo '{"shard": 1}' >"$TMP/broken.json"
expect2 "$BIN/exact_degenerate" "$TMP/bad" --merge "$TMP/broken.json"
echo "sharded and merged: the same report"
