#!/usr/bin/env bash
# One fuzzing campaign of one target: `RUNS` executions (default 10 million) in one libFuzzer process (one core),
# from the committed corpus and seeds, new units kept in fuzz/work/<target>/, crash artefacts in
# fuzz/artifacts/<target>/, the log in fuzz/work/<target>.log. FUZZING.md says what each target checks and records
# the campaigns run.
#
#   fuzz/campaign.sh scene                    # from the repository root; cargo-fuzz installed (FUZZING.md)
#   RUNS=1000000 SANITIZER=address fuzz/campaign.sh lcp_file
#
# SANITIZER is cargo-fuzz's `-s` (default `none`: debug assertions and overflow checks stay on; see FUZZING.md for
# why the campaign ran without AddressSanitizer). Exit status: libFuzzer's (0 when all runs passed).
set -euo pipefail

target=${1:?"usage: fuzz/campaign.sh scene|lcp_file|sweep_spec"}
runs=${RUNS:-10000000}
sanitizer=${SANITIZER:-none}
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
log="fuzz/work/$target.log"
{
    echo "# $(date -u +%FT%TZ) target $target, runs $runs, sanitizer $sanitizer, main at $(git rev-parse --short HEAD)"
    echo "# corpus at start: work $(find "fuzz/work/$target" -type f | wc -l), committed $(find "fuzz/corpus/$target" -type f | wc -l), seeds $(find "fuzz/seeds/$target" -type f | wc -l)"
} | tee "$log"
start=$(date +%s)
set +e
RUSTC_BOOTSTRAP=1 cargo fuzz run -s "$sanitizer" "$target" \
    "fuzz/work/$target" "fuzz/corpus/$target" "fuzz/seeds/$target" -- \
    -runs="$runs" -timeout=10 -rss_limit_mb=2048 -dict="fuzz/dicts/$target.dict" \
    -artifact_prefix="fuzz/artifacts/$target/" -print_final_stats=1 >>"$log" 2>&1
status=$?
set -e
echo "# $(date -u +%FT%TZ) exit $status after $(($(date +%s) - start)) s" | tee -a "$log"
grep -E '^stat::|^(==|SUMMARY|Done)' "$log" | tail -12
exit "$status"
