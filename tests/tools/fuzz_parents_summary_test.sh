#!/usr/bin/env bash
# ./harness fuzz --jobs J sums its parents' logs into one row (fuzz/parents_summary.sh):
# executions and traps summed, coverage and features the most one parent reached, each parent's
# last exec/s listed, each parent's coverage over time in its own file; a parent without a status
# line adds nothing, and other lines in a log are not status lines.
#   fuzz_parents_summary_test.sh SOURCE_DIR
set -euo pipefail
SUMMARY="$1/fuzz/parents_summary.sh"
TMP="$(mktemp -d)"
trap 'rm -rf "$TMP"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

cat >"$TMP/one.log" <<'LOG'
INFO: -fork=1: fuzzing in separate process(s)
INFO: -fork=1: 25 seed inputs, starting to fuzz in /dev/shm/x
#1000: cov: 100 ft: 200 corp: 10 exec/s 50 oom/timeout/crash: 0/0/0 time: 20s job: 1 dft_time: 0
#3000	NEW    cov: 999 ft: 999 corp: 11/1Kb exec/s: 999 rss: 45Mb
#5000: cov: 150 ft: 300 corp: 20 exec/s 120 oom/timeout/crash: 1/2/0 time: 40s job: 2 dft_time: 0
INFO: fuzzed for 41 seconds, wrapping up soon
LOG
cat >"$TMP/two.log" <<'LOG'
#7000: cov: 140 ft: 320 corp: 25 exec/s 95 oom/timeout/crash: 0/1/3 time: 41s job: 2 dft_time: 0
LOG
echo "INFO: stopped before its first job ended" >"$TMP/none.log"

got="$("$SUMMARY" "$TMP/one.log" "$TMP/one.cov" "$TMP/two.log" "$TMP/two.cov" "$TMP/none.log" "$TMP/none.cov")"
[[ "$got" == "12000 150 320 1/3/3 120 / 95" ]] || fail "two parents and one without a status line: got '$got'"
[[ "$(cat "$TMP/one.cov")" == $'20 100\n40 150' ]] || fail "first parent's coverage: $(cat "$TMP/one.cov")"
[[ "$(cat "$TMP/two.cov")" == "41 140" ]] || fail "second parent's coverage: $(cat "$TMP/two.cov")"
[[ ! -s "$TMP/none.cov" ]] || fail "a parent without status lines has coverage: $(cat "$TMP/none.cov")"

# What the harness reads: the exec/s list, with its spaces, is the rest of the line.
read -r execs cov ft crashes eps < <("$SUMMARY" "$TMP/two.log" "$TMP/a.cov" "$TMP/one.log" "$TMP/b.cov")
[[ "$execs/$cov/$ft/$crashes/$eps" == "12000/150/320/1/3/3/95 / 120" ]] || fail "read back: $execs/$cov/$ft/$crashes/$eps"

got="$("$SUMMARY" "$TMP/none.log" "$TMP/none.cov")"
[[ "$got" == "0 0 0 0/0/0 0" ]] || fail "no status line at all: got '$got'"

if "$SUMMARY" "$TMP/one.log" 2>"$TMP/err"; then fail "a log without its coverage file accepted"; fi
[[ $(wc -l <"$TMP/err") -eq 1 ]] || fail "the usage error is not one line"
echo "ok"
