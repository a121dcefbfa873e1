#!/usr/bin/env bash
# The commands of experiments/cluster/ as the README gives them give the report of one unsharded
# run (dates, commands and durations aside), for both studies: the Slurm job-array scripts run as
# Slurm runs them (each array task with SLURM_ARRAY_TASK_ID and SLURM_ARRAY_TASK_COUNT set, then
# the merge job; no Slurm needed, as #SBATCH lines are comments to bash) and the GNU parallel
# scripts with two jobs at a time. Also: a Slurm task started outside an array is refused.
#   cluster_scripts_test.sh SOURCE_DIR BIN_DIR
set -euo pipefail
SRC="$1"
export GHCLIP_BIN="$2"
TMP="$(mktemp -d)"
trap 'rm -rf "$TMP"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }
CLUSTER="$SRC/experiments/cluster"
M=3
# slurmArray SCRIPT OUT CASES: the M array tasks of SCRIPT, one after the other, as Slurm starts
# them, then its merge job.
slurmArray() {
  local script="$1" out="$2" cases="$3" k
  for ((k = 1; k <= M; k++)); do
    SLURM_ARRAY_TASK_ID=$k SLURM_ARRAY_TASK_COUNT=$M bash "$CLUSTER/$script" "$out" "$cases" >/dev/null 2>&1 ||
      fail "$script, array task $k of $M"
  done
  bash "$CLUSTER/$script" "$out" "$cases" merge >/dev/null 2>&1 || fail "$script merge"
}

# A report without what differs from run to run: its command, date and duration.
strip() { grep -v -e '^| made by' -e '^| date' -e 'The study took' "$1"; }

# The robustness study: 3 cases a class, the exact method alone (as GHCLIP_STUDY_ARGS passes it).
export GHCLIP_STUDY_ARGS="--methods exact"
"$GHCLIP_BIN/robustness" "$TMP/rob-one" --cases 3 --methods exact >/dev/null 2>&1
slurmArray robustness.slurm "$TMP/rob-slurm" 3
"$CLUSTER/robustness_parallel.sh" "$TMP/rob-parallel" 3 $M -j2 --will-cite >/dev/null 2>&1 || fail "robustness_parallel.sh"
for way in slurm parallel; do
  [[ $(ls "$TMP/rob-$way"/robustness-shard-*-of-$M.json | wc -l) -eq $M ]] || fail "robustness, $way: not $M shards"
  diff <(strip "$TMP/rob-one/robustness.md") <(strip "$TMP/rob-$way/robustness.md") >&2 ||
    fail "robustness, $way: the merged report differs from one run's"
  diff <(grep -v '"seconds"' "$TMP/rob-one/robustness.json") <(grep -v '"seconds"' "$TMP/rob-$way/robustness.json") >&2 ||
    fail "robustness, $way: the merged JSON differs from one run's"
done
unset GHCLIP_STUDY_ARGS

# The degenerate-case study: 40 cases in all.
"$GHCLIP_BIN/exact_degenerate" "$TMP/deg-one" 40 >/dev/null 2>&1
slurmArray exact_degenerate.slurm "$TMP/deg-slurm" 40
"$CLUSTER/exact_degenerate_parallel.sh" "$TMP/deg-parallel" 40 $M -j2 --will-cite >/dev/null 2>&1 || fail "exact_degenerate_parallel.sh"
for way in slurm parallel; do
  [[ $(ls "$TMP/deg-$way"/exact-degenerate-shard-*-of-$M.json | wc -l) -eq $M ]] || fail "degenerate, $way: not $M shards"
  diff <(strip "$TMP/deg-one/exact-degenerate.md") <(strip "$TMP/deg-$way/exact-degenerate.md") >&2 ||
    fail "degenerate, $way: the merged report differs from one run's"
done

# A Slurm task outside an array (no SLURM_ARRAY_TASK_ID) is refused, and writes no shard.
if env -u SLURM_ARRAY_TASK_ID -u SLURM_ARRAY_TASK_COUNT bash "$CLUSTER/robustness.slurm" "$TMP/rob-none" 3 >/dev/null 2>&1; then
  fail "robustness.slurm ran outside a job array"
fi
[[ ! -e "$TMP/rob-none" ]] || fail "robustness.slurm outside an array wrote $TMP/rob-none"
echo "ok"
