#!/usr/bin/env bash
# CONTACT in 3D: CONTACT (E. Vollebregt's rolling-contact program) built at its best (gfortran + Intel oneMKL from
# PyPI), checked against its own reference outputs, and timed on its 3D inputs: the examples cattaneo, spence35,
# subsurf and the performance series norm_problm_1p ... 8p, tang_problm_1s ... 8s. The peer figures rollbem's 3D
# half-space is measured against. Not part of CI. See benches/peer/README.md, "CONTACT in 3D, MKL build".
#
# Usage: bash benches/peer/contact3d.sh TABLE.md [CONTACT_SRC]
#   CONTACT_SRC (argument or env)  a CONTACT source tree (src/, examples/, perfc_test/); without one the script
#                                  clones $CONTACT_REPO (default https://github.com/eve70a/CONTACT)
#   env CASES3D="cattaneo spence35 subsurf norm_problm_1p norm_problm_2p norm_problm_4p norm_problm_8p
#                tang_problm_1s tang_problm_2s tang_problm_4s tang_problm_8s"   the inputs (examples/, perfc_test/)
#       REPEATS=3        timed runs per input; the median is reported
#       MALLOC_TUNED=1   also time every input with glibc's malloc told to keep freed memory (GLIBC_TUNABLES=
#                        glibc.malloc.mmap_max=0:glibc.malloc.trim_threshold=4294967296): CONTACT allocates and
#                        frees its large work arrays over and over, and with glibc's defaults each large block is a
#                        fresh mmap whose pages the kernel zero-fills again (half of 8p's and 8s's CPU is system
#                        time); 0 skips these runs
#       ONCE_OVER=180    CPU seconds: an input whose first run takes longer is timed once
#       CPU=0            the core every timed run is pinned to (taskset)
#       KEEP=DIR         keep the work folder (MKL wheels, CONTACT build, inputs, outputs) in DIR; a second run
#                        with the same DIR reuses the wheels
#       CONTACT_BIN=PATH use this CONTACT executable instead of building one (it is checked all the same)
#       MKL=1            build with Intel oneMKL (the default, and what the table is for); MKL=0 builds without,
#                        which then has to pass the same checks (it does not: see the README)
#       MKL_VERSION=     the PyPI version of mkl-static / mkl-include (default: the newest)
#       CONTACT_COMMIT=  the commit to name when CONTACT_SRC is not a git checkout
#
# Checks, before and while timing (a failed check stops the script: nothing is timed on a wrong build):
#   - the build on examples/carter2d.inp and examples/cattaneo.inp against carter2d.ref_out and cattaneo.ref_out
#     (contact_refcmp.py: every printed result to one unit of its last digit);
#   - each example's first timed run against its .ref_out the same way;
#   - each perfc_test input's first timed run against the author's perfc_test/get_times.ref_out: the number of
#     elements in contact (norm_problm_*, NCON) or in slip (tang_problm_*, NSLIP) must be equal.
#
# Examples with rollbem beside (EXAMPLES3D, e.g. "fastsim tractcurv:30 catt_to_cart:57"; none by default): CONTACT's
# example NAME, cut after its case K when given as NAME:K (its first K cases and the closing "0 MODULE": the cases
# rollbem reproduces), timed as above and checked against the reference output's cases 1..K; rollbem's time is that
# of the tests which compute the same cases and check them against the author's printed results
# (tests/rolling3d.rs, tests/fastsim.rs; their test binaries run one test each, pinned, median of REPEATS). A second
# table. CASES3D="" with EXAMPLES3D runs only the examples.
#
# rollbem beside it: each perfc_test input (norm_problm_kp, tang_problm_ks, kc, kf) is also timed as rollbem's
# `examples/halfspace_perfc_series` (built here with cargo; the same discrete problem: grid, profile, materials,
# approach, shift, EPS) under the same conditions (pinned, GNU time, median of REPEATS); its elements in contact and
# in slip are printed beside CONTACT's, and the ratio is CONTACT's best CPU (the smaller of its two runs) over
# rollbem's. ROLLBEM=0 skips these runs.
set -euo pipefail

if [[ $# -lt 1 || $# -gt 2 ]]; then
  echo "usage: $0 TABLE.md [CONTACT_SRC]" >&2
  exit 2
fi
table_out=$1
contact_src=${2:-${CONTACT_SRC:-}}
here=$(cd "$(dirname "$0")" && pwd)
cases=${CASES3D-"cattaneo spence35 subsurf norm_problm_1p norm_problm_2p norm_problm_4p norm_problm_8p tang_problm_1s tang_problm_2s tang_problm_4s tang_problm_8s"}
if [[ -z $cases && -z ${EXAMPLES3D-} ]]; then
  echo "[contact3d] error: nothing to time: CASES3D and EXAMPLES3D are both empty" >&2
  exit 2
fi
repeats=${REPEATS:-3}
once_over=${ONCE_OVER:-180}
cpu=${CPU:-0}
malloc_tuned=${MALLOC_TUNED:-1}
with_rollbem=${ROLLBEM:-1}
tunables="glibc.malloc.mmap_max=0:glibc.malloc.trim_threshold=4294967296"
export LC_ALL=C

say() { echo "[contact3d] $*" >&2; }
die() {
  echo "[contact3d] error: $*" >&2
  exit 1
}

if [[ -n ${KEEP:-} ]]; then
  work=$(mkdir -p "$KEEP" && cd "$KEEP" && pwd)
else
  work=$(mktemp -d)
  trap 'rm -rf "$work"' EXIT
fi
contact_mkl=${MKL:-1}
[[ $contact_mkl == 0 || $contact_mkl == 1 ]] || die "MKL must be 1 (build with Intel oneMKL, the default) or 0"
# shellcheck source=benches/peer/contact_build.sh
source "$here/contact_build.sh"
contact_install_tools

# 1. CONTACT: sources, build, and the build's check against the author's reference outputs.
contact_get_source "$contact_src"
for f in examples/carter2d.inp examples/carter2d.ref_out examples/cattaneo.inp examples/cattaneo.ref_out \
  perfc_test/get_times.ref_out; do
  [[ -f $contact_src/$f ]] || die "$contact_src is not a CONTACT source tree (no $f)"
done
contact_obtain_bin "$work"
contact_ref_summary=()
mkdir -p "$work/refcheck"
for name in carter2d cattaneo; do
  cp "$contact_src/examples/$name.inp" "$work/refcheck/"
  say "checking the build against CONTACT's examples/$name.ref_out"
  contact_ref_check "$name" "$work/refcheck" "$contact_src/examples/$name.ref_out"
done
gfortran_version=$(gfortran --version | head -n 1)

median() { sort -g | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }
loadavg() { cut -d' ' -f1-3 /proc/loadavg; }
# One timed run of CONTACT on NAME.inp in DIR, pinned to one core under GNU time, with the environment
# assignments ENV... (none, or GLIBC_TUNABLES=...): "user sys maxrss_kB" appended to DIR/times.
timed_run() {
  local dir=$1 name=$2 tf="$1/time.tmp"
  shift 2
  (cd "$dir" && env "$@" taskset -c "$cpu" /usr/bin/time -o "$tf" -f '%U %S %M' "$contact_bin" 2 "$name" \
    </dev/null >stdout.txt 2>&1) || die "CONTACT failed on $name (see $dir/stdout.txt)"
  tail -n 1 "$tf" >>"$dir/times"
}
# The median run of DIR/times (by user + sys): "cpu user sys rss_MiB".
median_run() {
  awk '{ printf "%.2f %.2f %.2f %.1f\n", $1 + $2, $1, $2, $3 / 1024 }' "$1/times" | sort -g |
    awk '{ v[NR] = $0 } END { print v[int((NR + 1) / 2)] }'
}
# Time DIR's input REPEATS times (once when the first run takes over ONCE_OVER s); prints the number of runs.
time_input() {
  local dir=$1 name=$2 first r runs=1
  shift 2
  timed_run "$dir" "$name" "$@"
  first=$(awk '{ print $1 + $2 }' "$dir/times")
  if awk -v t="$first" -v o="$once_over" 'BEGIN { exit !(t <= o) }'; then
    for ((r = 2; r <= repeats; r++)); do
      say "$name: run $r/$repeats${*:+ ($*)}"
      timed_run "$dir" "$name" "$@"
      runs=$r
    done
  fi
  echo "$runs"
}

# CONTACT's .out, last case: "NPOT NCON NADH NSLIP" and its inner iteration counts (sum over cases of the
# ItCG/ItGS printed by Norm and Tang, as the author's get_times.sh counts them).
out_stats() {
  awk '
    /NPOT +NCON +NADH +NSLIP/ { getline; s = $1 " " $2 " " $3 " " $4 }
    /Norm: final element division/ { n += $NF }
    /Tang: final element division/ { t += $NF }
    END { print s, n + 0, t + 0 }
  ' "$1"
}
# The author's figures for a perfc_test input: "ncon" or "nslp", and ItCG / ItGS, from get_times.ref_out.
perfc_ref() {
  # (lines like "norm_problm_8p: ncon=200980, ItCG=   31, ...": no blank after '=' at six digits)
  grep -E "^$1 *:" "$contact_src/perfc_test/get_times.ref_out" | head -n 1 |
    sed -nE 's/.*(ncon|nslp)= *([0-9]+).*(ItCG|ItGS)= *([0-9]+).*/\2 \4/p'
}
# Grid of the input's first case (MX × MY) from the .inp: the line tagged MX,MY.
inp_grid() { awk '/MX, *MY/ && $0 !~ /^[ \t]*%/ { print $1 " × " $2; exit }' "$1"; }
# Number of cases (MODULE 3 blocks).
inp_cases() { awk '$0 !~ /^[ \t]*%/ && $1 == 3 && tolower($2) == "module" { n++ } END { print n + 0 }' "$1"; }
# Its own timers (CPU): total, Algorithm Norm, Algorithm Tang.
out_timers() {
  awk -F'|' '$2 ~ /^Total / { t = $4 + 0 } $2 ~ /^Algorithm Norm/ { n = $4 + 0 } $2 ~ /^Algorithm Tang/ { g = $4 + 0 }
    END { printf "%s / %s / %s", t, (n == "" ? "–" : n), (g == "" ? "–" : g) }' "$1"
}

rollbem_ex=""
if ((with_rollbem)); then
  say "building rollbem's examples/halfspace_perfc_series"
  (cd "$here/../.." && cargo build --release --quiet --example halfspace_perfc_series) || die "cargo build failed"
  rollbem_ex="$here/../../target/release/examples/halfspace_perfc_series"
fi
# rollbem on perfc input NAME (norm_problm_kp / tang_problm_ks) in DIR/rollbem, REPEATS times: prints
# "cpu rss_MiB contact slip" (median run; counts from its last line of output).
rollbem_cells() {
  local dir=$1/rollbem name=$2 lvl=${2##*_problm_}
  mkdir -p "$dir"
  : >"$dir/times"
  for ((r = 0; r < repeats; r++)); do
    taskset -c "$cpu" /usr/bin/time -o "$dir/time.tmp" -f '%U %S %M' "$rollbem_ex" "$lvl" >"$dir/out.txt" ||
      die "$name: rollbem failed"
    tail -n 1 "$dir/time.tmp" >>"$dir/times"
  done
  read -r rcpu _ _ rrss <<<"$(median_run "$dir")"
  tail -n 1 "$dir/out.txt" | awk -F'|' -v c="$rcpu" -v m="$rrss" '{ split($3, a, " "); split($5, b, " ");
    printf "%s %s %s %s\n", c, m, a[1], (b[1] == "" ? "-" : b[1]) }'
}

load_start=$(loadavg)
growth=()
rows=()
notes=()
for name in $cases; do
  if [[ -f $contact_src/examples/$name.inp ]]; then
    inp=$contact_src/examples/$name.inp
    kind=example
  elif [[ -f $contact_src/perfc_test/$name.inp ]]; then
    inp=$contact_src/perfc_test/$name.inp
    kind=perfc
  else
    die "no input $name.inp in $contact_src/examples or perfc_test"
  fi
  d="$work/runs/$name"
  rm -rf "$d"
  mkdir -p "$d"
  cp "$inp" "$d/"
  say "$name: first run (checked)"
  runs=$(time_input "$d" "$name") || exit 1
  # The check of the first run's answers (the runs after it compute the same).
  read -r npot ncon nadh nslip itn itt < <(out_stats "$d/$name.out")
  if [[ $kind == example ]]; then
    ref=$contact_src/examples/$name.ref_out
    [[ -f $ref ]] || die "no reference output $ref"
    check=$(python3 "$here/contact_refcmp.py" "$d/$name.out" "$ref") || {
      echo "$check" >&2
      die "$name: CONTACT's answers differ from $name.ref_out beyond the printed digits"
    }
    checkcell="= $name.ref_out ($(echo "$check" | awk '{ print $1 }') numbers)"
    notes+=("$name: $check.")
  else
    rcount="" rit=""
    read -r rcount rit < <(perfc_ref "$name") || true
    if [[ $name == norm_* ]]; then mine=$ncon what=NCON; else mine=$nslip what=NSLIP; fi
    if [[ $name == norm_* ]]; then myit=$itn; else myit=$itt; fi
    if [[ -n $rcount ]]; then
      [[ $mine == "$rcount" ]] || die "$name: $what = $mine, the author's get_times.ref_out has $rcount"
      checkcell="$what $mine = get_times.ref_out"
      notes+=("$name: $what $mine as the author's get_times.ref_out (CONTACT r1274, 2016); inner iterations $myit (the author's: $rit).")
    else
      # tang_problm_8c is not in the author's table: this run's count is the reference rollbem is held to.
      checkcell="$what $mine (not in get_times.ref_out)"
      notes+=("$name: not in the author's get_times.ref_out; CONTACT's $what here is $mine; inner iterations $myit.")
    fi
  fi
  ((runs < repeats)) && notes+=("$name: timed once (its first run took over ONCE_OVER = $once_over s of CPU).")
  read -r tcpu tuser tsys trss <<<"$(median_run "$d")"
  tcells="$tcpu | $tuser | $tsys | $trss | $runs"
  if ((malloc_tuned)); then
    mkdir -p "$d/tuned"
    cp "$inp" "$d/tuned/"
    say "$name: with GLIBC_TUNABLES=$tunables"
    truns=$(time_input "$d/tuned" "$name" "GLIBC_TUNABLES=$tunables") || exit 1
    # The same answers as the run with glibc's defaults, to every printed digit.
    same=$(python3 "$here/contact_refcmp.py" "$d/tuned/$name.out" "$d/$name.out") || {
      echo "$same" >&2
      die "$name: the run with GLIBC_TUNABLES printed other results"
    }
    read -r ucpu uuser usys urss <<<"$(median_run "$d/tuned")"
    tcells="$tcells | $ucpu | $uuser | $usys | $urss | $truns"
  fi
  rcells="– | – | – | –"
  if [[ -n $rollbem_ex && $kind == perfc ]]; then
    say "$name: rollbem"
    read -r rcpu rrss rcon rslip <<<"$(rollbem_cells "$d" "$name")"
    best=$tcpu
    ((malloc_tuned)) && best=$(awk -v a="$tcpu" -v b="$ucpu" 'BEGIN { print (b < a) ? b : a }')
    ratio=$(awk -v a="$best" -v b="$rcpu" 'BEGIN { if (b > 0) printf "%.2f", a / b; else print "n/a" }')
    rcells="$rcon / $rslip | $rcpu | $rrss | $ratio"
    notes+=("$name: rollbem's elements in contact / in slip $rcon / $rslip (CONTACT's $ncon / $nslip); CONTACT's best CPU $best s.")
    [[ $rcon == "$ncon" && ($name == norm_* || $rslip == "$nslip") ]] ||
      notes+=("$name: **rollbem's counts differ from CONTACT's** (contact $rcon / $ncon, slip $rslip / $nslip).")
    growth+=("${name%_*}_${name: -1} $npot $rcpu $best")
  fi
  grid=$(inp_grid "$inp")
  ncases=$(inp_cases "$inp")
  rows+=("| $name | $grid | $npot | $ncases | $ncon | $nadh | $nslip | $checkcell | $tcells | $(out_timers "$d/$name.out") | $rcells |")
  say "$name: $tcells"
done

# Examples with rollbem beside (EXAMPLES3D): the tests of rollbem that compute and check each example's cases.
examples=${EXAMPLES3D-}
ex_rows=()
ex_notes=()
# "NAME:K": the rollbem tests (binary test-name) that compute and check these cases; empty: none.
example_tests() {
  case $1 in
    fastsim) echo "fastsim:contact_fastsim_cases_reproduced_to_the_printed_digits fastsim:contact_fastrip_cases_reproduced_to_the_printed_digits rolling3d:fastsim_inp_exact_case_agrees_with_contact" ;;
    tractcurv:30) echo "rolling3d:tractcurv_exact_series_agrees_with_contact" ;;
    catt_to_cart:57) echo "rolling3d:catt_to_cart_agrees_with_contact" ;;
    *) echo "" ;;
  esac
}
if [[ -n $examples ]]; then
  ((with_rollbem)) || die "EXAMPLES3D needs rollbem (ROLLBEM=1)"
  say "building rollbem's tests rolling3d and fastsim"
  json=$(cd "$here/../.." && cargo test --release --no-run --test rolling3d --test fastsim --message-format=json \
    2>"$work/cargo-test.log") || die "cargo test --no-run failed (see $work/cargo-test.log)"
  test_bin() {
    python3 -c 'import json, sys
for line in sys.stdin:
    m = json.loads(line)
    if m.get("reason") == "compiler-artifact" and m.get("executable") and m["target"]["name"] == sys.argv[1]:
        print(m["executable"])' "$1" <<<"$json" | head -n 1
  }
  declare -A bins=([rolling3d]=$(test_bin rolling3d) [fastsim]=$(test_bin fastsim))
  [[ -x ${bins[rolling3d]} && -x ${bins[fastsim]} ]] || die "no test binaries rolling3d and fastsim in cargo's output"
  for spec in $examples; do
    name=${spec%%:*} upto=""
    [[ $spec == *:* ]] && upto=${spec#*:}
    tests=$(example_tests "$spec")
    [[ -n $tests ]] || die "EXAMPLES3D: no rollbem tests for $spec (known: fastsim, tractcurv:30, catt_to_cart:57)"
    inp=$contact_src/examples/$name.inp
    [[ -f $inp ]] || die "no input $inp"
    d="$work/examples/$name${upto:+_1-$upto}"
    rm -rf "$d"
    mkdir -p "$d"
    if [[ -n $upto ]]; then
      awk -v k="$upto" '$0 !~ /^[ \t]*%/ && $1 == 3 && tolower($2) == "module" { n++ } n > k { exit } { print }' \
        "$inp" >"$d/$name.inp"
      echo " 0  MODULE" >>"$d/$name.inp"
    else
      cp "$inp" "$d/"
    fi
    say "$spec: CONTACT"
    runs=$(time_input "$d" "$name") || exit 1
    check=$(python3 "$here/contact_refcmp.py" "$d/$name.out" "$contact_src/examples/$name.ref_out" ${upto:+--cases "$upto"}) || {
      echo "$check" >&2
      die "$spec: CONTACT's answers differ from $name.ref_out beyond the printed digits"
    }
    read -r tcpu _ _ trss <<<"$(median_run "$d")"
    rcpu=0 rrss=0
    for t in $tests; do
      bin=${bins[${t%%:*}]} test=${t#*:}
      mkdir -p "$d/rollbem-$test"
      : >"$d/rollbem-$test/times"
      say "$spec: rollbem's $test"
      for ((r = 0; r < repeats; r++)); do
        taskset -c "$cpu" /usr/bin/time -o "$d/rollbem-$test/time.tmp" -f '%U %S %M' "$bin" --exact "$test" \
          --test-threads=1 >"$d/rollbem-$test/out.txt" 2>&1 || die "$spec: rollbem's $test failed (see $d/rollbem-$test/out.txt)"
        grep -q "test result: ok. 1 passed" "$d/rollbem-$test/out.txt" || die "$spec: $test did not run"
        tail -n 1 "$d/rollbem-$test/time.tmp" >>"$d/rollbem-$test/times"
      done
      read -r c _ _ m <<<"$(median_run "$d/rollbem-$test")"
      rcpu=$(awk -v a="$rcpu" -v b="$c" 'BEGIN { printf "%.2f", a + b }')
      rrss=$(awk -v a="$rrss" -v b="$m" 'BEGIN { print (b > a) ? b : a }')
    done
    ratio=$(awk -v a="$tcpu" -v b="$rcpu" 'BEGIN { if (b > 0) printf "%.1f", a / b; else print "n/a (rollbem under 0.01 s)" }')
    ex_rows+=("| $name${upto:+ (cases 1–$upto)} | $(inp_cases "$d/$name.inp") | = $name.ref_out ($(echo "$check" | awk '{ print $1 }') numbers) | $tcpu | $trss | $runs | $(echo "$tests" | sed -E 's/([a-z0-9]+):([a-z0-9_]+)/`\1::\2`/g; s/ /, /g') | $rcpu | $rrss | $ratio |")
    ex_notes+=("$spec: $check.")
    awk -v r="$rcpu" 'BEGIN { exit !(r < 0.1) }' &&
      ex_notes+=("$spec: rollbem's $rcpu s is the sum of $(echo "$tests" | wc -w) processes each timed to GNU time's 0.01 s: the ratio is rough (±0.01 s per process).")
  done
fi

{
  if ((${#rows[@]} == 0)); then
    :
  elif ((malloc_tuned)); then
    echo "| input | grid MX × MY (first case) | NPOT | cases | NCON | NADH | NSLIP | check of this run | CPU user+sys [s] | user [s] | sys [s] | peak RSS [MiB] | runs | with malloc tunables: CPU user+sys [s] | user [s] | sys [s] | peak RSS [MiB] | runs | CONTACT's own timers, CPU total / NORM / TANG [s] | rollbem: contact / slip | rollbem CPU [s] | rollbem peak RSS [MiB] | CONTACT best ÷ rollbem |"
    echo "|---|---|---:|---:|---:|---:|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|---:|---:|---:|---:|"
  else
    echo "| input | grid MX × MY (first case) | NPOT | cases | NCON | NADH | NSLIP | check of this run | CPU user+sys [s] | user [s] | sys [s] | peak RSS [MiB] | runs | CONTACT's own timers, CPU total / NORM / TANG [s] | rollbem: contact / slip | rollbem CPU [s] | rollbem peak RSS [MiB] | CONTACT best ÷ rollbem |"
    echo "|---|---|---:|---:|---:|---:|---:|---|---:|---:|---:|---:|---:|---|---:|---:|---:|---:|"
  fi
  if ((${#rows[@]})); then
    printf '%s\n' "${rows[@]}"
    echo
  fi
  if ((${#ex_rows[@]})); then
    echo "| example | cases | check of this run | CONTACT CPU [s] | CONTACT peak RSS [MiB] | runs | rollbem: the tests computing and checking the same cases | rollbem CPU [s] | rollbem peak RSS [MiB] | CONTACT ÷ rollbem |"
    echo "|---|---:|---|---:|---:|---:|---|---:|---:|---:|"
    printf '%s\n' "${ex_rows[@]}"
    echo
    echo "Examples: CONTACT's input as shipped, or cut after case K (NAME:K, its first K cases, the cases rollbem reproduces); CONTACT's time as above (pinned, GNU time, median, glibc's defaults). rollbem's: the test binaries (\`cargo test --release\`) running each named test alone (\`--exact NAME --test-threads=1\`), pinned, median of $repeats, summed over the tests; each test computes the example's cases and asserts the author's printed results (so the time includes reading the reference CSVs and the checks, and catt_to_cart's also a steady-rolling solve for its final comparison)."
    for note in "${ex_notes[@]}"; do echo "Note: $note"; done
  fi
  echo "**CONTACT build measured: $contact_build.** CONTACT $contact_rev, commit $contact_commit, $gfortran_version."
  ((${#rows[@]})) && echo "Element counts (NPOT potential contact, NCON contact, NADH adhesion, NSLIP slip) are those CONTACT prints for the last case of each input."
  echo "Times: CPU (user + sys) and peak RSS of the whole process (GNU time, resolution 0.01 s), pinned to core $cpu (taskset), one thread (OPENMP= build, MKL sequential), median of $repeats runs (one run when the first took over $once_over s); \`contact_linux64 2 NAME\` in a folder holding NAME.inp.$( ((${#rows[@]})) && echo " CONTACT's own timers are from the last run with glibc's defaults (its .out, rounded to 0.1 s).")"
  ((malloc_tuned && ${#rows[@]})) && echo "With malloc tunables: the same runs with \`GLIBC_TUNABLES=$tunables\` (glibc's malloc serves every block from its heap and keeps freed memory instead of returning it to the kernel, so CONTACT's repeated allocations of large work arrays are not zero-filled by the kernel again each time); each such run's printed results equal the default run's to every digit (contact_refcmp.py). CONTACT's best time is the smaller of the two."
  [[ -n $rollbem_ex && ${#rows[@]} -gt 0 ]] && echo "rollbem: \`target/release/examples/halfspace_perfc_series kp|ks|kc|kf\` (rollbem $(awk -F'"' '/^version/ { print $2; exit }' "$here/../../Cargo.toml"), commit $(git -C "$here/../.." rev-parse --short HEAD 2>/dev/null || echo unknown)), the same discrete problem; normal problem by the FFT-preconditioned CG, the shift by the preconditioned nonlinear CG on the stick and slip sets (TangCG-type, halfspace::tangential), steady rolling (kc: creepages, kf: forces prescribed) by the semismooth Newton method with preconditioned GMRES (halfspace::rolling), tolerance 1e-7; the same pinning, GNU time and median; the whole process (reading the profile, building the influence operators, solving)."
  echo "Build check before timing (contact_refcmp.py, every printed result to one unit of its last digit): $(printf '%s. ' "${contact_ref_summary[@]}")"
  echo "Machine: $(nproc) cores, shared; load average $load_start at the start, $(loadavg) at the end."
  for note in "${notes[@]}"; do echo "Note: $note"; done
  # How each program's CPU grows with the elements, per series: the exponent x of CPU ∝ NPOT^x between the series'
  # first input well above GNU time's 0.01 s resolution (rollbem ≥ 0.03 s or CONTACT ≥ 0.1 s) and its last, beside
  # the exponent N log N would give over the same range.
  ((${#growth[@]})) && printf '%s\n' "${growth[@]}" | awk '
    { s = $1; if (!(s in first) && ($3 >= 0.03 || $4 >= 0.1)) { first[s] = NR; n0[s] = $2; r0[s] = $3; c0[s] = $4 }
      n1[s] = $2; r1[s] = $3; c1[s] = $4 }
    END { for (s in first) if (n1[s] > n0[s] && r0[s] > 0 && c0[s] > 0)
      printf "Growth (%s, NPOT %d → %d, %.0f×): rollbem CPU ∝ N^%.2f (%s → %s s), CONTACT best ∝ N^%.2f (%s → %s s); N log N would be N^%.2f.\n",
        s, n0[s], n1[s], n1[s] / n0[s], log(r1[s] / r0[s]) / log(n1[s] / n0[s]), r0[s], r1[s],
        log(c1[s] / c0[s]) / log(n1[s] / n0[s]), c0[s], c1[s], 1 + log(log(n1[s]) / log(n0[s])) / log(n1[s] / n0[s]) }'
  : # (the block's status is not that of an empty list's test above: pipefail)
} | tee "$table_out"
