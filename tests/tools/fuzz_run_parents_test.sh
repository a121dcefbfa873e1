#!/usr/bin/env bash
# ./harness fuzz starts a target's parents with fuzz/run_parents.sh. With stand-ins for libFuzzer's
# fork-mode parents (each a process that starts a "job" in its own group and waits for it):
# every copy runs with its own log and the report stays when none is interrupted; interrupted
# (SIGTERM, SIGINT), every parent and every job is stopped, the report removed, the logs kept,
# and the status is 130; a parent that ignores SIGTERM is killed after the grace period; usage
# errors are one line and status 2.
#   fuzz_run_parents_test.sh SOURCE_DIR
set -euo pipefail
RUN="$1/fuzz/run_parents.sh"
TMP="$(mktemp -d)"
cleanup() {
  # Whatever a failed case left running.
  local p
  if [[ -f "$TMP/pids" ]]; then for p in $(cat "$TMP/pids"); do kill -KILL "$p" 2>/dev/null || true; done; fi
  rm -rf "$TMP"
}
trap cleanup EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

# fake MODE: a parent's shape. It writes its pid and its job's to $TMP/pids, says so in its log,
# and waits for the job (300 s) or, "quick", ends it and exits 3 at once. "stubborn" ignores
# SIGTERM, and so does its job (an ignored signal is inherited).
cat >"$TMP/fake" <<'FAKE'
#!/usr/bin/env bash
mode="$1"
[[ "$mode" == stubborn ]] && trap '' TERM
sleep 300 &
job=$!
echo "$$ $job" >>"$PIDS"
echo "parent $$ with job $job"
if [[ "$mode" == quick ]]; then kill "$job"; exit 3; fi
wait
FAKE
chmod +x "$TMP/fake"
export PIDS="$TMP/pids"

# Alive, and not a zombie waiting for its parent or init to reap it.
alive() { [[ -r "/proc/$1/stat" ]] && [[ "$(sed -E 's/^[0-9]+ \(.*\) (.).*/\1/' "/proc/$1/stat" 2>/dev/null)" != Z ]]; }
anyAlive() {
  local p
  for p in $(cat "$PIDS"); do alive "$p" && return 0; done
  return 1
}
# Waits until n parents have written their pids (at most 10 s).
started() {
  local i
  for ((i = 0; i < 100; i++)); do
    [[ -f "$PIDS" ]] && (($(wc -l <"$PIDS") >= $1)) && return 0
    sleep 0.1
  done
  fail "$1 parents did not start"
}

# Uninterrupted: every copy runs, each with its own log; the report stays; status 0 although the
# parents exited 3.
: >"$PIDS"
echo "report" >"$TMP/report.md"
"$RUN" "$TMP/report.md" "$TMP/a.log" "$TMP/b.log" "$TMP/c.log" -- "$TMP/fake" quick || fail "uninterrupted: status $?"
[[ -f "$TMP/report.md" ]] || fail "uninterrupted: the report was removed"
[[ $(wc -l <"$PIDS") -eq 3 ]] || fail "uninterrupted: $(wc -l <"$PIDS") copies ran, not 3"
for l in a b c; do grep -q '^parent [0-9]* with job' "$TMP/$l.log" || fail "uninterrupted: $l.log lacks its parent's line"; done
[[ "$(cat "$TMP/a.log")" != "$(cat "$TMP/b.log")" ]] || fail "two copies wrote one log"

# Interrupted by `signal` after both parents have started: status 130 within a few seconds,
# nothing of either group left (parents and jobs), the report removed, the logs kept.
interrupted() {
  local signal="$1" mode="$2" runner status t0
  : >"$PIDS"
  echo "report" >"$TMP/report.md"
  rm -f "$TMP/a.log" "$TMP/b.log"
  # With job control, a command started with & keeps SIGINT (bash ignores SIGINT in background
  # commands otherwise, as a terminal's Ctrl-C reaches only the foreground).
  set -m
  GHCLIP_PARENTS_GRACE=1 "$RUN" "$TMP/report.md" "$TMP/a.log" "$TMP/b.log" -- "$TMP/fake" "$mode" 2>"$TMP/err" &
  runner=$!
  set +m
  started 2
  t0=$SECONDS
  kill "-$signal" "$runner"
  while kill -0 "$runner" 2>/dev/null; do
    ((SECONDS - t0 <= 8)) || fail "$signal, $mode parents: not stopped after 8 s"
    sleep 0.1
  done
  status=0
  wait "$runner" || status=$?
  ((status == 130)) || fail "$signal, $mode parents: status $status, not 130"
  anyAlive && fail "$signal, $mode parents: a parent or job still runs: $(tr '\n' ' ' <"$PIDS")"
  [[ ! -e "$TMP/report.md" ]] || fail "$signal, $mode parents: the unfinished report was kept"
  [[ -s "$TMP/a.log" && -s "$TMP/b.log" ]] || fail "$signal, $mode parents: a log was removed"
  [[ $(wc -l <"$TMP/err") -eq 1 ]] && grep -q interrupted "$TMP/err" || fail "$signal, $mode parents: stderr: $(cat "$TMP/err")"
}
interrupted TERM wait
interrupted INT wait
interrupted TERM stubborn

# Usage errors: one line on stderr, status 2, nothing run.
: >"$PIDS"
for args in "$TMP/r.md $TMP/a.log" "$TMP/r.md $TMP/a.log $TMP/fake quick" "$TMP/r.md -- $TMP/fake quick"; do
  status=0
  # shellcheck disable=SC2086
  "$RUN" $args 2>"$TMP/err" || status=$?
  ((status == 2)) || fail "usage error ($args): status $status"
  [[ $(wc -l <"$TMP/err") -eq 1 ]] || fail "usage error ($args): stderr is not one line"
done
[[ ! -s "$PIDS" ]] || fail "a usage error ran the command"
echo "ok"
