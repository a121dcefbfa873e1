#!/usr/bin/env bash
# ghclip from the outside: results, exit codes, one-line errors, and no output file on bad input.
#   cli_test.sh BIN_DIR EXAMPLES_DIR
set -uo pipefail
BIN="$1"
EX="$2"
TMP="$(mktemp -d)"
trap 'rm -rf "$TMP"' EXIT
fails=0
passes=0
check() {  # check NAME CONDITION...
  local name="$1"
  shift
  if "$@"; then passes=$((passes + 1)); else echo "FAIL: $name"; fails=$((fails + 1)); fi
}

# Bad input: exit 2, exactly one line on stderr naming the file, no output file.
bad() {  # bad NAME SUBJECT_TEXT
  local name="$1" text="$2"
  printf '%s' "$text" >"$TMP/$name.wkt"
  "$BIN/ghclip" --op intersection "$TMP/$name.wkt" "$EX/half_square.wkt" -o "$TMP/$name.out" \
    --svg "$TMP/$name.svg" 2>"$TMP/$name.err" >/dev/null
  local code=$?
  check "$name: exit 2 (got $code)" test "$code" -eq 2
  check "$name: one stderr line" test "$(wc -l <"$TMP/$name.err")" -eq 1
  check "$name: message names the file" grep -q "$name.wkt" "$TMP/$name.err"
  check "$name: no output file" test ! -e "$TMP/$name.out"
  check "$name: no svg file" test ! -e "$TMP/$name.svg"
  check "$name: no temporary file" test -z "$(ls "$TMP" | grep tmp)"
}
bad malformed 'POLYGON((0 0, 1 0, 1 1'
bad nan 'POLYGON((0 0, 1 0, nan 1, 0 0))'
bad twovertex 'POLYGON((0 0, 1 1, 0 0))'
bad notapolygon 'LINESTRING(0 0, 1 1)'
bad huge 'POLYGON((0 0, 1e300 0, 0 1, 0 0))'
bad badjson '{"type": "Polygon", "coordinates": [[[0, 0], [1]]]}'

"$BIN/ghclip" --op intersection "$TMP/missing.wkt" "$EX/half_square.wkt" 2>"$TMP/missing.err"
check "missing file: exit 2" test $? -eq 2
check "missing file: named" grep -q missing.wkt "$TMP/missing.err"
"$BIN/ghclip" --op frobnicate "$EX/pentagram.wkt" "$EX/half_square.wkt" 2>"$TMP/op.err"
check "unknown op: exit 2" test $? -eq 2
check "unknown op: one line" test "$(wc -l <"$TMP/op.err")" -eq 1
"$BIN/ghclip" "$EX/pentagram.wkt" 2>/dev/null
check "missing arguments: exit 2" test $? -eq 2

# Good input: WKT and GeoJSON out, stdin in, statistics as JSON.
"$BIN/ghclip" --op intersection "$EX/pentagram.wkt" "$EX/half_square.wkt" -o "$TMP/r.wkt" \
  --svg "$TMP/r.svg" --stats >"$TMP/stats.json"
check "pentagram: exit 0" test $? -eq 0
check "pentagram: result is WKT" grep -q '^MULTIPOLYGON' "$TMP/r.wkt"
check "pentagram: svg uses even-odd" grep -q 'fill-rule="evenodd"' "$TMP/r.svg"
check "pentagram: stats count 4 intersections" grep -q '"intersections":4' "$TMP/stats.json"
"$BIN/ghclip" --op union --format geojson - "$EX/gate.geojson" <"$EX/square.geojson" >"$TMP/u.json"
check "stdin + geojson: exit 0" test $? -eq 0
check "geojson output" grep -q '"type":"MultiPolygon"' "$TMP/u.json"
"$BIN/ghclip" --op xor "$TMP/r.wkt" "$TMP/r.wkt" >/dev/null
check "result reads back" test $? -eq 0

# Exact by default: a region minus itself is empty, exactly, with no --variant; the paper's
# arithmetic (named) leaves a sliver. The two axes can be given on their own, not with --variant.
"$BIN/ghclip" --op difference "$EX/square.geojson" "$EX/square.geojson" -o "$TMP/self.wkt" --stats >"$TMP/self.json"
check "A \\ A by default: exit 0" test $? -eq 0
check "A \\ A by default: no coordinates" test -z "$(grep '[0-9]' "$TMP/self.wkt")"
check "A \\ A by default: stats say exact" grep -q '"variant":"exact"' "$TMP/self.json"
"$BIN/ghclip" --op difference --variant naive "$EX/square.geojson" "$EX/square.geojson" -o "$TMP/self-naive.wkt"
check "A \\ A with --variant naive: a sliver" grep -q '[0-9]' "$TMP/self-naive.wkt"
"$BIN/ghclip" --op union --arithmetic paper --search sweep "$EX/square.geojson" "$EX/gate.geojson" -o "$TMP/ps.wkt" \
  --stats >"$TMP/ps.json"
check "--arithmetic paper --search sweep is the sweep variant" grep -q '"variant":"sweep"' "$TMP/ps.json"
"$BIN/ghclip" --op union --variant naive --arithmetic exact "$EX/square.geojson" "$EX/gate.geojson" 2>"$TMP/both.err" >/dev/null
check "--variant with --arithmetic: exit 2" test $? -eq 2
check "--variant with --arithmetic: one line" test "$(wc -l <"$TMP/both.err")" -eq 1
"$BIN/ghclip" --op union --search diagonal "$EX/square.geojson" "$EX/gate.geojson" 2>/dev/null >/dev/null
check "unknown --search: exit 2" test $? -eq 2

# Threads do not change the answer: byte for byte the same file.
"$BIN/ghgen" circles --n 30000 --seed 2 -o "$TMP/circles.wkt"
sed -n 1p "$TMP/circles.wkt" >"$TMP/cs.wkt"
sed -n 2p "$TMP/circles.wkt" >"$TMP/cc.wkt"
"$BIN/ghclip" --op union --threads 1 "$TMP/cs.wkt" "$TMP/cc.wkt" -o "$TMP/t1.wkt"
"$BIN/ghclip" --op union --threads 2 "$TMP/cs.wkt" "$TMP/cc.wkt" -o "$TMP/t2.wkt"
check "--threads 1 and 2: the same answer" cmp -s "$TMP/t1.wkt" "$TMP/t2.wkt"
"$BIN/ghclip" --op union --threads many "$TMP/cs.wkt" "$TMP/cc.wkt" 2>/dev/null >/dev/null
check "--threads many: exit 2" test $? -eq 2

# ghcheck: pass (0), fail (1), bad input (2); --expected writes the exact answer.
"$BIN/ghcheck" --op intersection "$EX/pentagram.wkt" "$EX/half_square.wkt" "$TMP/r.wkt" >"$TMP/v.txt"
check "ghcheck passes ghclip's answer" test $? -eq 0
check "ghcheck prints the verdict" grep -q '^verdict: pass' "$TMP/v.txt"
"$BIN/ghcheck" --op union "$EX/pentagram.wkt" "$EX/half_square.wkt" "$TMP/r.wkt" --json \
  --svg "$TMP/wrong.svg" >"$TMP/v.json"
check "ghcheck fails a confused operation" test $? -eq 1
check "ghcheck json has a witness" grep -q '"witness":\[' "$TMP/v.json"
check "ghcheck svg marks wrong faces" grep -q 'wrong faces' "$TMP/wrong.svg"
"$BIN/ghcheck" --op union --oracle sample "$EX/pentagram.wkt" "$EX/half_square.wkt" "$TMP/r.wkt" >/dev/null
check "sampling oracle fails it too" test $? -eq 1
"$BIN/ghcheck" --op intersection "$EX/pentagram.wkt" "$EX/half_square.wkt" "$TMP/nan.wkt" 2>/dev/null
check "ghcheck bad input: exit 2" test $? -eq 2
"$BIN/ghcheck" --op intersection --expected "$EX/pentagram.wkt" "$EX/half_square.wkt" -o "$TMP/e.wkt"
check "ghcheck --expected writes the answer" grep -q '^MULTIPOLYGON' "$TMP/e.wkt"
"$BIN/ghcheck" --op intersection "$EX/pentagram.wkt" "$EX/half_square.wkt" "$TMP/e.wkt" >/dev/null
check "the exact answer passes" test $? -eq 0
"$BIN/ghclip" --op intersection "$EX/pentagram.wkt" "$EX/half_square.wkt" --check exact >/dev/null 2>"$TMP/chk.err"
check "ghclip --check exact passes" test $? -eq 0

# The report generators refuse JSON that is not Google Benchmark's: exit 2, one line, no table.
printf '{"context": {}, "benchmarks": [' >"$TMP/cut.json"
mkdir -p "$TMP/tables"
"$BIN/report_tables" "$TMP/cut.json" "$TMP/tables" 2>"$TMP/rt.err"
check "report_tables on cut JSON: exit 2" test $? -eq 2
check "report_tables on cut JSON: one line naming the file" \
  test "$(wc -l <"$TMP/rt.err")" -eq 1 -a -n "$(grep cut.json "$TMP/rt.err")"
check "report_tables on cut JSON: no table" test ! -e "$TMP/tables/table1.md"

# --help prints the usage and exits 0, in every tool that parses its command line with CLI11.
for tool in ghclip ghcheck ghgen robustness; do
  "$BIN/$tool" --help >"$TMP/help.out" 2>"$TMP/help.err"
  check "$tool --help: exit 0" test $? -eq 0
  check "$tool --help: prints the options" grep -q -- "--help" "$TMP/help.out"
done

# exact_speed with a filter that matches nothing: exit 2 and one line, not an abort.
"$BIN/exact_speed" "$TMP/speed.md" --benchmark_filter=matches-nothing >/dev/null 2>"$TMP/es.err"
check "exact_speed, empty filter: exit 2" test $? -eq 2
check "exact_speed, empty filter: the reason on stderr" grep -q "matched" "$TMP/es.err"
check "exact_speed, empty filter: no report" test ! -e "$TMP/speed.md"

echo "$passes passed, $fails failed"
test "$fails" -eq 0
