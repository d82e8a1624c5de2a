#!/usr/bin/env bash
# Run a sweep as a SLURM job array of N shards and a merge job that starts when all of them have succeeded:
#
#   scripts/slurm/submit.sh SPEC N DIR [extra sbatch options...]
#
# Task k (1..N) runs `rollbem sweep SPEC --shard k/N --out DIR/shard-k-of-N.csv --resume` (log DIR/shard-k.log);
# the merge job runs `rollbem sweep-merge --spec SPEC DIR/merged.csv DIR/shard-*-of-N.csv` (log DIR/merge.log),
# which checks that every case of the spec is there exactly once. Prints the two job ids: "ARRAY MERGE".
# What was submitted (spec, N, binary, options, job ids) is recorded in DIR/jobs.env for
# scripts/slurm/resubmit.sh, which submits failed or cancelled tasks again and re-chains the merge after every
# task of the sweep (see there). Extra options (e.g. --partition=..., --time=..., --account=...) go to every sbatch
# call, resubmit.sh's too. The rollbem binary is $ROLLBEM, else `rollbem` on the PATH.
# DIR must be on a file system that the compute nodes share with this one.
set -euo pipefail
if [ $# -lt 3 ]; then
    echo "usage: $0 SPEC N DIR [sbatch options...]" >&2
    exit 2
fi
here=$(cd "$(dirname "$0")" && pwd)
spec=$(realpath "$1")
n=$2
mkdir -p "$3"
dir=$(realpath "$3")
shift 3
case "$n" in '' | *[!0-9]* | 0) echo "$0: N must be a positive whole number, not '$n'" >&2; exit 2 ;; esac
[ -f "$spec" ] || { echo "$0: no spec $spec" >&2; exit 2; }
rollbem=${ROLLBEM:-$(command -v rollbem || true)}
[ -n "$rollbem" ] || { echo "$0: no rollbem binary: set ROLLBEM or put rollbem on the PATH" >&2; exit 2; }
rollbem=$(realpath "$rollbem")

array=$(sbatch --parsable --job-name=rollbem-sweep --array="1-$n" --output="$dir/shard-%a.log" "$@" \
    "$here/shard.sbatch" "$rollbem" "$spec" "$n" "$dir")
array=${array%%;*}
merge=$(sbatch --parsable --job-name=rollbem-merge --dependency="afterok:$array" --output="$dir/merge.log" "$@" \
    "$here/merge.sbatch" "$rollbem" "$spec" "$n" "$dir")
merge=${merge%%;*}
# For resubmit.sh: every value quoted for the shell (`printf %q`).
{
    echo "# Written by scripts/slurm/submit.sh; read by scripts/slurm/resubmit.sh. Job ids are appended."
    printf 'spec=%q\nn=%q\nrollbem=%q\n' "$spec" "$n" "$rollbem"
    printf 'options=('
    [ $# -gt 0 ] && printf ' %q' "$@"
    printf ' )\n'
    printf 'shard_jobs+=(%q)\nmerge_jobs+=(%q)\n' "$array" "$merge"
} >"$dir/jobs.env"
echo "$array $merge"
