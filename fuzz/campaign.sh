#!/usr/bin/env bash
# One fuzzing campaign of one target: `RUNS` executions (default 10 million) in one libFuzzer process (one core),
# from the committed corpus and seeds, new units kept in fuzz/work/<target>/, crash artefacts in
# fuzz/artifacts/<target>/, the log in fuzz/work/<target>.log. FUZZING.md says what each target checks and records
# the campaigns run.
#
#   fuzz/campaign.sh scene                    # from the repository root; cargo-fuzz installed (FUZZING.md)
#   RUNS=1000000 SANITIZER=address fuzz/campaign.sh lcp_file
#   JOBS=2 fuzz/campaign.sh scene             # two processes of RUNS/2 executions each, one core each
#
# With JOBS = n > 1, n libFuzzer processes run side by side, each RUNS/n executions, sharing fuzz/work/<target>/
# (libFuzzer reloads it as the others add units); each logs to fuzz/work/<target>.<i>.log, and the exit status is
# the first non-zero one. The campaign's count is the sum of theirs.
#
# SANITIZER is cargo-fuzz's `-s` (default `none`: debug assertions and overflow checks stay on; see FUZZING.md for
# why the campaign ran without AddressSanitizer). Exit status: libFuzzer's (0 when all runs passed).
set -euo pipefail

target=${1:?"usage: fuzz/campaign.sh scene|lcp_file|sweep_spec"}
runs=${RUNS:-10000000}
sanitizer=${SANITIZER:-none}
jobs=${JOBS:-1}
case "$target" in
scene | lcp_file | sweep_spec) ;;
*)
    echo "fuzz/campaign.sh: unknown target '$target' (scene, lcp_file or sweep_spec)" >&2
    exit 2
    ;;
esac
cd "$(dirname "$0")/.."
if [ -n "${CARGO_TARGET_DIR:-}" ]; then
    echo "fuzz/campaign.sh: unset CARGO_TARGET_DIR (cargo-fuzz builds into fuzz/target/)" >&2
    exit 2
fi
mkdir -p "fuzz/work/$target" "fuzz/artifacts/$target"
if [ "$jobs" -lt 1 ] || [ $((runs % jobs)) -ne 0 ]; then
    echo "fuzz/campaign.sh: JOBS=$jobs must be ≥ 1 and divide RUNS=$runs" >&2
    exit 2
fi
# Build once, before the processes start (each `cargo fuzz run` would otherwise race for the build lock).
RUSTC_BOOTSTRAP=1 cargo fuzz build -s "$sanitizer" "$target"
# One libFuzzer process: `one <log> <runs>`.
one() {
    local log=$1 n=$2 start status
    {
        echo "# $(date -u +%FT%TZ) target $target, runs $n, sanitizer $sanitizer, main at $(git rev-parse --short HEAD)"
        echo "# corpus at start: work $(find "fuzz/work/$target" -type f | wc -l), committed $(find "fuzz/corpus/$target" -type f | wc -l), seeds $(find "fuzz/seeds/$target" -type f | wc -l)"
    } | tee "$log"
    start=$(date +%s)
    set +e
    RUSTC_BOOTSTRAP=1 cargo fuzz run -s "$sanitizer" "$target" \
        "fuzz/work/$target" "fuzz/corpus/$target" "fuzz/seeds/$target" -- \
        -runs="$n" -timeout=10 -rss_limit_mb=2048 -dict="fuzz/dicts/$target.dict" \
        -artifact_prefix="fuzz/artifacts/$target/" -print_final_stats=1 >>"$log" 2>&1
    status=$?
    set -e
    echo "# $(date -u +%FT%TZ) exit $status after $(($(date +%s) - start)) s" | tee -a "$log"
    grep -E '^stat::|^(==|SUMMARY|Done)' "$log" | tail -12
    return "$status"
}
if [ "$jobs" -eq 1 ]; then
    one "fuzz/work/$target.log" "$runs"
    exit $?
fi
pids=()
for i in $(seq 1 "$jobs"); do
    one "fuzz/work/$target.$i.log" $((runs / jobs)) &
    pids+=($!)
done
status=0
for pid in "${pids[@]}"; do
    wait "$pid" || { s=$?; [ "$status" -ne 0 ] || status=$s; }
done
exit "$status"
