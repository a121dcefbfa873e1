#!/usr/bin/env bash
# Runs one command once per log, side by side, and waits for every copy:
#   run_parents.sh REPORT LOG [LOG ...] -- COMMAND [ARG ...]
# ./harness fuzz --jobs J starts a target's J one-job fork-mode parents so (one corpus, one
# findings file; each parent's output in its own LOG). Each copy leads a process group of its own
# (setsid), which holds the fork-mode jobs it starts. Exits 0 once every copy has ended, whatever
# their status (a parent that ran with -ignore_crashes ends non-zero after a trapped job, and its
# log says so).
# Interrupted (SIGINT or SIGTERM), it stops every group, not only the parents (a job left behind
# would go on fuzzing): SIGTERM, then SIGKILL to what is left after GHCLIP_PARENTS_GRACE seconds
# (default 10). It then removes REPORT (a campaign's unfinished report; the logs stay) and exits
# 130, once nothing of the groups runs.
set -euo pipefail
usage() { echo "usage: run_parents.sh REPORT LOG [LOG ...] -- COMMAND [ARG ...]" >&2; exit 2; }
(($# >= 4)) || usage
report="$1"
shift
logs=()
while (($#)) && [[ "$1" != -- ]]; do logs+=("$1"); shift; done
(($# >= 2 && ${#logs[@]} >= 1)) || usage
shift  # --
grace="${GHCLIP_PARENTS_GRACE:-10}"
[[ "$grace" =~ ^[0-9]+$ ]] || { echo "run_parents.sh: GHCLIP_PARENTS_GRACE must be a whole number of seconds" >&2; exit 2; }

groups=()
# Whether any process of the groups still runs (kill -0 on a group: any member).
anyLeft() {
  local g
  for g in "${groups[@]}"; do kill -0 -- "-$g" 2>/dev/null && return 0; done
  return 1
}
stopAll() {
  local g waited=0
  # bash's notes of the parents it reaps killed ("Killed") left out: the line at the end says it.
  exec 3>&2 2>/dev/null
  for g in "${groups[@]}"; do kill -TERM -- "-$g" 2>/dev/null || true; done
  while anyLeft && ((waited < grace * 10)); do sleep 0.1; waited=$((waited + 1)); done
  for g in "${groups[@]}"; do kill -KILL -- "-$g" 2>/dev/null || true; done
  wait || true  # the parents, reaped
  # Their jobs, killed, are reaped by init: a moment (bounded: a container's init may never reap,
  # and a zombie still answers kill -0).
  waited=0
  while anyLeft && ((waited < 50)); do sleep 0.1; waited=$((waited + 1)); done
  rm -f -- "$report"
  echo "run_parents.sh: interrupted: every parent and job stopped, $report removed, logs kept" >&3
  exit 130
}
# Set before the first copy starts: no interrupt finds a group it does not know.
trap stopAll INT TERM
for log in "${logs[@]}"; do
  # setsid from a background shell: the copy is its own group's leader, so its pid names the group.
  setsid "$@" >"$log" 2>&1 &
  groups+=($!)
done
wait "${groups[@]}" || true
