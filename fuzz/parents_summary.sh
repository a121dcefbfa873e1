#!/usr/bin/env bash
# A fuzz target's row from the logs of its one-job fork-mode parents (./harness fuzz --jobs J):
#   parents_summary.sh LOG COVERAGE [LOG COVERAGE ...]
# Each parent's status lines, "#N: cov: C ft: F corp: K exec/s E oom/timeout/crash: a/b/c time: Ts"
# (fork mode prints "exec/s E"; the colon other modes print after exec/s is allowed), give its
# coverage over time, written to its COVERAGE file as "seconds edges" lines, and its last line its
# totals. Prints one line:
#   executions edges features a/b/c exec/s
# executions and traps summed over the parents, edges and features the most one parent reached
# (each counts its own), exec/s every parent's last line (" / " between them; 0 when none has one).
# A parent with no status line (it stopped before its first job ended) adds nothing.
set -euo pipefail
(($# >= 2 && $# % 2 == 0)) || { echo "usage: parents_summary.sh LOG COVERAGE [LOG COVERAGE ...]" >&2; exit 2; }
execs=0 cov=0 ft=0 eps="" c1=0 c2=0 c3=0
while (($#)); do
  log="$1" coverage="$2"
  shift 2
  status="$(grep -E '^#[0-9]+: cov:' "$log" || true)"
  sed -E 's/.*cov: ([0-9]+).* time: ([0-9]+)s.*/\2 \1/' <<<"$status" | grep . >"$coverage" || true
  last="$(tail -1 <<<"$status")"
  [[ -n "$last" ]] || continue
  n="$(sed -E 's/^#([0-9]+):.*/\1/' <<<"$last")"
  execs=$((execs + n))
  n="$(sed -E 's/.*cov: ([0-9]+).*/\1/' <<<"$last")"; ((n > cov)) && cov=$n
  n="$(sed -E 's/.*ft: ([0-9]+).*/\1/' <<<"$last")"; ((n > ft)) && ft=$n
  eps+="${eps:+ / }$(sed -E 's/.*exec\/s:? ([0-9]+).*/\1/' <<<"$last")"
  IFS=/ read -r a b c < <(sed -E 's/.*oom\/timeout\/crash: ([0-9]+\/[0-9]+\/[0-9]+).*/\1/' <<<"$last")
  c1=$((c1 + a)) c2=$((c2 + b)) c3=$((c3 + c))
done
echo "$execs $cov $ft $c1/$c2/$c3 ${eps:-0}"
