#!/usr/bin/env bash
# ctest `slurm_cluster`: a one-node Slurm cluster on localhost (scripts/slurm_cluster.sh), the
# README's "Running on a cluster" commands verbatim on the quick profile of E4 (a 4-task array plus
# the merge job), then:
#   1. one array task is cancelled before it runs; the merge job is stranded; the README's resume
#      line re-submits only that shard, and the other shards' results are not touched;
#   2. the merged runs.jsonl / runs.csv / experiment.yaml equal a single-process run's byte for
#      byte, except the measured wall times (every value, series or column named *seconds*);
#   3. one shard's results are deleted; the resume line re-runs only that shard; equal again.
# The daemons are stopped by their PIDs on exit. Exit 77 (skip) only when Slurm is not installed.
# Usage: slurm_cluster_test.sh <sextant binary> <source dir>
set -euo pipefail
sextant=$1
source_dir=$(cd "$2" && pwd)
start_time=$SECONDS
tmp=$(mktemp -d /tmp/sextant-slurm.XXXXXX)
cluster="$tmp/cluster"
cleanup() {
  "$source_dir/scripts/slurm_cluster.sh" stop "$cluster" || true
  rm -rf "$tmp"
}
trap cleanup EXIT
fail() {
  echo "slurm_cluster_test: FAIL: $*" >&2
  tail -n 5 "$tmp"/work/results/_slurm/logs/* 2>/dev/null >&2 || true
  exit 1
}

status=0
"$source_dir/scripts/slurm_cluster.sh" start "$cluster" || status=$?
if ((status == 77)); then
  echo "slurm_cluster_test: SKIP: Slurm (slurm-wlm) or munge is not installed; scripts/test.sh installs them"
  exit 77
fi
((status == 0)) || fail "the test cluster did not start"
# shellcheck disable=SC1091
source "$cluster/env"

# The README's commands, verbatim: the `sextant slurm` lines of the block after the marker.
mapfile -t commands < <(awk '/<!-- slurm-test:/ {on = 1; next} on && /^```$/ && seen {exit}
                             on && /^```/ {seen = 1; next} on && /^build\/app\/sextant slurm / {print}' \
  "$source_dir/README.md")
((${#commands[@]} == 2)) || fail "expected 2 'sextant slurm' lines in README.md's cluster block, found ${#commands[@]}"
submit_line=${commands[0]}
resume_line=${commands[1]}
[[ $resume_line == *--resume* && $submit_line != *--resume* ]] || fail "README: submit line, then resume line"

# The README runs from the source folder after the build: the same layout, with this build's binary.
work="$tmp/work"
mkdir -p "$work/build/app"
ln -s "$(realpath "$sextant")" "$work/build/app/sextant"
ln -s "$source_dir/experiments" "$work/experiments"
ln -s "$source_dir/data" "$work/data"
cd "$work"
exp=e04_init_vs_layer

# The single-process reference (it also fills the dataset cache the tasks share).
"$sextant" run "experiments/$exp.yaml" --quick --jobs 2 --no-progress --results single \
  --cache results/_cache >/dev/null || fail "single-process run"

# Waiting is for events, never for a fixed time: on a loaded machine every step may be slow, and
# slow is no failure (ctest's TIMEOUT is the bound). What fails at once is a state no job leaves by
# itself: a daemon died; a task ended FAILED (or killed: node failure, out of memory, time limit),
# after which its merge job's afterok can never be met; a job held after a failed launch or waiting
# for a dependency that can never be met; the node drained or failed by slurmctld (after a failed
# launch or an unkillable task). Not among them: a node DOWN because slurmd answered a ping late
# (ReturnToService=2 brings it back once it answers) and "ReqNodeNotAvail" while the node returns.
node=$(hostname -s)  # the cluster's one node (scripts/slurm_cluster.sh names it so)
never_states='BOOT_FAIL|DEADLINE|FAILED|NODE_FAIL|OUT_OF_MEMORY|PREEMPTED|REQUEUE_HOLD|SPECIAL_EXIT|TIMEOUT'
never_reasons='DependencyNeverSatisfied|JobHeld|JobLaunchFailure|launch failed|BadConstraints|Partition(Down|Inactive)'
fail_queue() {  # fail, with Slurm's view: the queue (ended jobs too) and the node
  { squeue -t all; sinfo -N -l; } >&2 2>/dev/null || true
  fail "$@"
}
cluster_alive() {  # fail when a daemon has died: no job ends then
  local d
  for d in munged slurmctld slurmd; do
    [ -s "$cluster/run/$d.pid" ] && kill -0 "$(cat "$cluster/run/$d.pid")" 2>/dev/null && continue
    tail -n 20 "$cluster"/log/*.out >&2 || true
    fail "$d (of the test cluster) is no longer running"
  done
}
jobs_known() {  # known = "<array job id> <job id> <state> <reason>" of each job, ended ones too
  # Asked again until slurmctld answers: a timed-out squeue prints nothing, which is not "no jobs".
  until known=$(squeue -h -t all -o '%F %i %T %r' 2>/dev/null); do
    cluster_alive
    sleep 0.5
  done
}
wait_gone() {  # wait_gone IDS: until none of the jobs IDS (comma-separated) is queued, running or ending
  local ids=" ${1//,/ } " jobs stuck state
  while :; do
    cluster_alive
    jobs_known
    jobs=$(awk -v ids="$ids" 'index(ids, " " $1 " ")' <<<"$known")
    stuck=$(grep -E "^\S+ \S+ (($never_states) |PENDING .*($never_reasons))" <<<"$jobs") &&
      fail_queue "jobs $1 can never finish: $stuck"
    if state=$(sinfo -h -n "$node" -o %T 2>/dev/null) && [[ $state =~ drain|fail ]]; then
      fail_queue "the node is $state (slurmctld's reason: $(sinfo -h -n "$node" -o %E)); jobs $1 cannot finish"
    fi
    grep -Evq '^(\S+ \S+ (COMPLETED|CANCELLED) .*)?$' <<<"$jobs" || return 0
    sleep 0.5
  done
}
job_id() {  # job_id array|merge <output>
  sed -n "s/^submitted: $1 job \([0-9]*\).*/\1/p" <<<"$2"
}
# Wall times are measured, not computed: every value, series or column named *seconds* is masked.
# Timings (…seconds…, …_ms…, E21's registration_extra, a ratio of two times) differ run to run.
timing='seconds|_ms|registration_extra'
masked_jsonl() { sed -E 's/"([A-Za-z0-9_]*('"$timing"')[A-Za-z0-9_]*)": (\[[^]]*\]|[^,}]*)/"\1": T/g' "$1" | sort; }
masked_csv() {
  awk -F, -v re="$timing" 'NR == 1 {for (i = 1; i <= NF; i++) t[i] = ($i ~ re)} {for (i = 1; i <= NF; i++) if (NR > 1 && t[i]) $i = "T"} 1' OFS=, "$1"
}
check_equal_to_single() {
  local merged="results/$exp" single="single/$exp"
  cmp "$merged/experiment.yaml" "$single/experiment.yaml" || fail "experiment.yaml differs"
  cmp <(masked_csv "$merged/runs.csv") <(masked_csv "$single/runs.csv") || fail "runs.csv differs (timings masked)"
  cmp <(masked_jsonl "$merged/runs.jsonl") <(masked_jsonl "$single/runs.jsonl") || fail "runs.jsonl differs"
  # The merged file lists its rows in expansion order: the same order as the single run's runs.csv.
  cmp <(sed -E 's/^\{"key": "([0-9a-f]*)".*/\1/' "$merged/runs.jsonl") <(tail -n +2 "$single/runs.csv" | cut -d, -f1) ||
    fail "merged runs.jsonl is not in expansion order"
  grep -q "<section id=\"$exp\">" report/index.html || fail "the merge job wrote no report section for $exp"
}
shard_sums() { for k in "$@"; do md5sum "results/_shards/$k-of-4/$exp/runs.jsonl"; done; }

echo "slurm_cluster_test: single-process reference done after $((SECONDS - start_time)) s"

# 1. Submit while the node is drained, so that no task can start; cancel task 3; resume the node.
#    Task 3 is cancelled before it started however fast or slow the machine (not merely because the
#    node's 2 CPUs keep tasks 3 and 4 waiting for 1 and 2, which a fast task 1 would undo).
scontrol update NodeName="$node" State=DRAIN Reason=slurm_cluster_test || fail "could not drain the node"
out=$(eval "$submit_line") || fail "submit: $out"
echo "$out"
array=$(job_id array "$out")
# The resume command it prints is the README's resume line (with this binary's path).
grep -qxF "resume:  $(realpath "$sextant") ${resume_line#build/app/sextant }" <<<"$out" ||
  fail "the printed resume command is not the README's resume line"
merge=$(job_id merge "$out")
[[ -n $array && -n $merge ]] || fail "no job ids in the output"
scancel "${array}_3" || fail "could not cancel task 3"
scontrol update NodeName="$node" State=RESUME || fail "could not resume the node"
wait_gone "$array"
echo "slurm_cluster_test: array done (task 3 cancelled) after $((SECONDS - start_time)) s"
jobs_known
merge_state=$(awk -v id="$merge" '$2 == id {print $3}' <<<"$known")
[ "$merge_state" = PENDING ] || fail "the merge job is ${merge_state:-gone}, not pending, although task 3 was cancelled"
[ ! -s "results/_shards/3-of-4/$exp/runs.jsonl" ] || fail "task 3 ran although it was cancelled"
before=$(shard_sums 1 2 4)
out=$(eval "$resume_line") || fail "resume: $out"
echo "$out"
grep -q "^resume:  shard 3 of 4 is missing or incomplete" <<<"$out" || fail "resume did not select shard 3 alone"
grep -q "cancelled the previous merge job $merge " <<<"$out" || fail "the stranded merge job was not cancelled"
array2=$(job_id array "$out")
merge2=$(job_id merge "$out")
grep -q "^submitted: array job $array2 (tasks 3)" <<<"$out" || fail "not exactly task 3 re-submitted"
wait_gone "$array2,$merge2"
[ "$(shard_sums 1 2 4)" = "$before" ] || fail "a finished shard was redone"
grep -q "runs executed, 0 already done" results/_slurm/logs/*-"${array2}"_3.out ||
  fail "task 3's log shows no run"
check_equal_to_single
echo "slurm_cluster_test: cancelled task re-run alone, merged = single-process run ($((SECONDS - start_time)) s)"

# 3. Delete one shard's results (a lost disk, a task killed by hand); resume re-runs only it.
rm -rf "results/_shards/2-of-4/$exp" "results/$exp" report
before=$(shard_sums 1 3 4)
out=$(eval "$resume_line") || fail "second resume: $out"
echo "$out"
array3=$(job_id array "$out")
merge3=$(job_id merge "$out")
grep -q "^submitted: array job $array3 (tasks 2)" <<<"$out" || fail "not exactly task 2 re-submitted"
wait_gone "$array3,$merge3"
[ "$(shard_sums 1 3 4)" = "$before" ] || fail "a finished shard was redone"
check_equal_to_single
echo "slurm_cluster_test: deleted shard re-run alone, merged = single-process run ($((SECONDS - start_time)) s)"
# `slurm reproduce --quick`: every experiment as one array plus the merge job; the merged results
# equal a single-process `reproduce --quick` run for run (timings masked), and the report is written.
"$sextant" reproduce --quick --jobs 2 --no-progress --experiments experiments --results single_all \
  --report single_report >/dev/null || fail "single-process reproduce --quick"
echo "slurm_cluster_test: single-process reproduce --quick done after $((SECONDS - start_time)) s"
out=$("$sextant" slurm reproduce --quick -n 3 --experiments experiments --results all --report all_report --submit) ||
  fail "slurm reproduce: $out"
echo "$out"
array4=$(job_id array "$out")
merge4=$(job_id merge "$out")
[[ -n $array4 && -n $merge4 ]] || fail "slurm reproduce: no job ids in the output"
wait_gone "$array4,$merge4"
echo "slurm_cluster_test: slurm reproduce jobs done after $((SECONDS - start_time)) s"
experiments=0
for single in single_all/*/; do
  name=$(basename "$single")
  [ -f "$single/experiment.yaml" ] || continue
  experiments=$((experiments + 1))
  [ -f "all/$name/runs.jsonl" ] || fail "slurm reproduce: no merged results for $name"
  cmp "all/$name/experiment.yaml" "$single/experiment.yaml" || fail "slurm reproduce: $name's experiment.yaml differs"
  cmp <(masked_jsonl "all/$name/runs.jsonl") <(masked_jsonl "$single/runs.jsonl") ||
    fail "slurm reproduce: $name's runs.jsonl differs from the single-process run (timings masked)"
  cmp <(masked_csv "all/$name/runs.csv") <(masked_csv "$single/runs.csv") ||
    fail "slurm reproduce: $name's runs.csv differs (timings masked)"
  grep -q "<section id=\"$name\">" all_report/index.html || fail "slurm reproduce: no report section for $name"
done
((experiments >= 22)) || fail "slurm reproduce: only $experiments experiments compared"
echo "slurm_cluster_test: slurm reproduce --quick merged = single-process reproduce --quick ($experiments experiments)"
echo "slurm_cluster_test: passed in $((SECONDS - start_time)) s"
