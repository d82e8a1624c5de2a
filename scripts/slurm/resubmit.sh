#!/usr/bin/env bash
# Submit again the tasks of a sweep's job array that were cancelled, pre-empted, killed or ran out of time, and
# re-chain the merge so that it cannot start before every task of the sweep has ended:
#
#   scripts/slurm/resubmit.sh DIR TASK...      (DIR as given to scripts/slurm/submit.sh; TASK a shard number k)
#
# 1. Refuses a task that is still queued or running (two runs of one shard would write one journal).
# 2. Cancels the sweep's merge jobs still queued: the first one waits for the whole array to succeed
#    (afterok), which a failed task makes impossible, and a merge after an earlier resubmission is superseded.
# 3. Submits the tasks again as a job array of those task ids (same script, spec, N, DIR and sbatch options as
#    submit.sh): each goes on from its journal with --resume; a task that had finished runs nothing.
# 4. Submits a new merge with --dependency=afterany:EVERY EARLIER SHARD JOB STILL IN THE QUEUE,afterok:THE NEW ONES:
#    it waits for every task of the original array (and of earlier resubmissions) to end, whatever its state, and
#    for the resubmitted tasks to succeed. A job no longer in the queue has ended and is not waited for (SLURM
#    forgets finished jobs after MinJobAge). The merge itself (`sweep-merge --spec`) then checks that every shard
#    is complete and holds every case once, computed for the spec as it is now; if another task had failed, the
#    merge fails saying which shard is missing, and resubmit.sh is run again for it.
#
# Prints "RESUBMITTED MERGE" (the two new job ids) and records them in DIR/jobs.env.
set -euo pipefail
if [ $# -lt 2 ]; then
    echo "usage: $0 DIR TASK..." >&2
    exit 2
fi
here=$(cd "$(dirname "$0")" && pwd)
dir=$(realpath "$1")
shift
[ -f "$dir/jobs.env" ] || { echo "$0: no $dir/jobs.env: was the sweep submitted with scripts/slurm/submit.sh?" >&2; exit 2; }
spec='' n='' rollbem='' options=() shard_jobs=() merge_jobs=()
# shellcheck source=/dev/null
source "$dir/jobs.env"

# Whether a job (or array, or task ID_K) is still in the queue (pending, running, completing, ...).
queued() { [ -n "$(squeue -h -j "$1" -o %i 2>/dev/null || true)" ]; }

tasks=()
for k in "$@"; do
    case "$k" in '' | *[!0-9]*) echo "$0: a task is a shard number 1..$n, not '$k'" >&2; exit 2 ;; esac
    if [ "$k" -lt 1 ] || [ "$k" -gt "$n" ]; then
        echo "$0: task $k is not a shard of 1..$n" >&2
        exit 2
    fi
    for job in "${shard_jobs[@]}"; do
        if queued "${job}_$k"; then
            echo "$0: task $k (job ${job}_$k) is still queued or running: wait until it has ended (squeue)" >&2
            exit 2
        fi
    done
    tasks+=("$k")
done

for job in "${merge_jobs[@]}"; do
    if queued "$job"; then
        scancel "$job"
    fi
done
waited=()
for job in "${shard_jobs[@]}"; do
    if queued "$job"; then
        waited+=("$job")
    fi
done

list=$(IFS=,; echo "${tasks[*]}")
again=$(sbatch --parsable --job-name=rollbem-sweep --array="$list" --output="$dir/shard-%a.log" ${options[@]+"${options[@]}"} \
    "$here/shard.sbatch" "$rollbem" "$spec" "$n" "$dir")
again=${again%%;*}
dependency="afterok:$again"
if [ ${#waited[@]} -gt 0 ]; then
    dependency="afterany:$(IFS=:; echo "${waited[*]}"),$dependency"
fi
merge=$(sbatch --parsable --job-name=rollbem-merge --dependency="$dependency" --output="$dir/merge.log" \
    ${options[@]+"${options[@]}"} "$here/merge.sbatch" "$rollbem" "$spec" "$n" "$dir")
merge=${merge%%;*}
printf 'shard_jobs+=(%q)\nmerge_jobs+=(%q)\n' "$again" "$merge" >>"$dir/jobs.env"
echo "$again $merge"
