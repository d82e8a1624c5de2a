#!/usr/bin/env bash
# Peer benchmark: rollbem's LCP solvers (lemke, lemke_dense on the exported file; active_set on the scene) against
# every LCP solver of Siconos numerics 4.4 (benches/peer/driver.c) on rollbem's own frictional LCPs at several
# sizes. Not part of CI. See benches/peer/README.md.
#
# Usage: bash benches/peer/run.sh TABLE.md
#   env SIZES="200 400 800 880 3332"  contact elements of the scene variants (LCP size 3·m + 4)
#       REPEATS=3                timed runs per solver (the median is reported)
#       TOL=1e-10                tolerance on Siconos' lcp_compute_error, for every Siconos solver that takes one
#       TIME_LIMIT=120           seconds per Siconos solver (all its runs) and per rollbem run
#       LARGE=5000               LCPs of more unknowns run only the Siconos solvers that reached TOL at a smaller
#                                size of this run (the others are listed as not run, with where they failed),
#                                each once; the time limit there is LARGE_TIME_LIMIT (default 600) seconds
#       SKIP_AFTER=120           a rollbem solver whose first run takes longer (s) is not repeated
#       KEEP=DIR                 keep the scenes, LCP files and outputs in DIR (default: a temporary folder)
#       ROLLBEM=PATH             use this rollbem binary instead of building one
set -euo pipefail

if [[ $# -ne 1 ]]; then
  echo "usage: $0 TABLE.md" >&2
  exit 2
fi
table_out=$1
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
sizes=${SIZES:-"200 400 800 880 3332"}
repeats=${REPEATS:-3}
tol=${TOL:-1e-10}
time_limit=${TIME_LIMIT:-120}
large=${LARGE:-5000}
large_time_limit=${LARGE_TIME_LIMIT:-600}
skip_after=${SKIP_AFTER:-120}
base_scene="$root/reference/scenes/cattaneo-decoupled.toml"
# Siconos links OpenBLAS: one thread, as rollbem (faer without its parallel feature) and Siconos' own loops.
export OPENBLAS_NUM_THREADS=1 OMP_NUM_THREADS=1

say() { echo "[peer] $(date -u +%H:%M:%S) $*" >&2; }

# 1. Siconos, a C compiler and jq from Debian's packages.
need=()
for pkg in libsiconos-numerics-dev gcc jq; do
  dpkg -s "$pkg" >/dev/null 2>&1 || need+=("$pkg")
done
if ((${#need[@]})); then
  sudo=()
  if [[ $(id -u) -ne 0 ]]; then sudo=(sudo); fi
  say "installing ${need[*]}"
  "${sudo[@]}" apt-get update -qq
  DEBIAN_FRONTEND=noninteractive "${sudo[@]}" apt-get install -y -qq "${need[@]}" >/dev/null
fi
siconos_version=$(dpkg-query -W -f='${Version}' libsiconos-numerics-dev)

if [[ -n ${KEEP:-} ]]; then
  work=$KEEP
  mkdir -p "$work"
else
  work=$(mktemp -d)
  trap 'rm -rf "$work"' EXIT
fi

# 2. The peer driver and rollbem.
gcc -O2 -Wall -I/usr/include/siconos -I/usr/include/siconos/numerics -o "$work/peer" "$here/driver.c" \
  -lsiconos_numerics -lm
if [[ -n ${ROLLBEM:-} ]]; then
  built=$ROLLBEM
else
  say "building rollbem (cargo build --release)"
  (cd "$root" && cargo build --release --quiet)
  built="${CARGO_TARGET_DIR:-$root/target}/release/rollbem"
fi
[[ -x $built ]] || { echo "no rollbem binary at $built" >&2; exit 1; }
# A private copy: a build of another checkout sharing CARGO_TARGET_DIR cannot replace it during the run.
rollbem="$work/rollbem"
cp "$built" "$rollbem"

median() { sort -g | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }
# max |a_i − b_i| / max(max |a|, max |b|) of two files with one number per line.
rel_diff() {
  [[ -s $1 && -s $2 ]] || { echo "n/a"; return; }
  paste "$1" "$2" | awk '
    function abs(x) { return x < 0 ? -x : x }
    { d = abs($1 - $2); if (d > md) md = d; if (abs($1) > mz) mz = abs($1); if (abs($2) > mz) mz = abs($2) }
    END { if (NR == 0) print "n/a"; else if (mz == 0) printf "%.1e\n", md; else printf "%.1e\n", md / mz }'
}
# Agreement of two answers on the contact forces: with m nodes, z = (f, λ⁺, λ⁻, u⁺, u⁻) and w = (g, γ⁺, γ⁻, v⁺, v⁻),
# γ± = μf ∓ h, so the tangential force is h = (γ⁻ − γ⁺)/2. Prints maxᵢ max(|Δfᵢ|, |Δhᵢ|) / maxᵢ fᵢ. (z itself is not
# unique: a node out of contact has f = h = 0, γ± = 0 and any λ⁺ = λ⁻ + const; u⁺ and u⁻ may share any amount.)
force_diff() { # zA wA zB wB m
  [[ -s $1 && -s $2 && -s $3 && -s $4 ]] || { echo "n/a"; return; }
  paste "$1" "$2" "$3" "$4" | awk -v m="$5" '
    function abs(x) { return x < 0 ? -x : x }
    { za[NR] = $1; wa[NR] = $2; zb[NR] = $3; wb[NR] = $4 }
    END {
      for (i = 1; i <= m; i++) {
        if (za[i] > f0) f0 = za[i]
        d = abs(za[i] - zb[i]); if (d > md) md = d
        ha = (wa[2 * m + i] - wa[m + i]) / 2; hb = (wb[2 * m + i] - wb[m + i]) / 2
        d = abs(ha - hb); if (d > md) md = d
      }
      if (f0 > 0) printf "%.1e\n", md / f0; else printf "%.1e (f = 0)\n", md
    }'
}
kv() { awk -v k="$1" '$1 == k { $1 = ""; sub(/^ /, ""); print; exit }' "$2"; }
fmt_s() { if [[ -z $1 || $1 == n/a ]]; then echo "n/a"; else awk -v t="$1" 'BEGIN { if (t > 0) printf "%.3g", t; else print "≈0" }'; fi; }
fmt_e() { awk -v e="$1" 'BEGIN { printf "%.1e", e }'; }
loadavg() { cut -d' ' -f1-3 /proc/loadavg; }

# `rollbem lcp solve FILE --solver S --json OUT` up to REPEATS times (not repeated after a run over SKIP_AFTER s;
# each run killed after $lim s: TIME_LIMIT, or LARGE_TIME_LIMIT over LARGE unknowns); prints "median_solve_time_s runs" or "timeout 0".
time_rollbem() {
  local file=$1 solver=$2 json=$3 runs=0 times=() t0 t1
  for ((r = 0; r < repeats; r++)); do
    t0=$(date +%s.%N)
    if ! timeout "$lim" "$rollbem" lcp solve "$file" --solver "$solver" --json "$json.r" --quiet >/dev/null; then
      [[ -s $json.r ]] || { echo "timeout 0"; return; }
    fi
    t1=$(date +%s.%N)
    mv "$json.r" "$json"
    times+=("$(jq -r '.solve_time_s' "$json")")
    runs=$((runs + 1))
    if awk -v a="$t0" -v b="$t1" -v s="$skip_after" 'BEGIN { exit !(b - a > s) }'; then break; fi
  done
  echo "$(printf '%s\n' "${times[@]}" | median) $runs"
}

load_start=$(loadavg)
declare -A solved_somewhere=() failed_at=()
summary_rows=()
rollbem_rows=()
declare -A sic_cell=()
ns=()
notes=()
siconos_solvers=""
for m in $sizes; do
  scene="$work/peer-$m.toml"
  sed -e "s/^name = .*/name = \"peer-$m\"/" \
    -e 's/^coupling = false/coupling = true/' \
    -e "s/^contact_elements = .*/contact_elements = $m/" \
    "$base_scene" >"$scene"
  if ! grep -q '^coupling = true' "$scene" || ! grep -q "^contact_elements = $m\$" "$scene"; then
    echo "scene variant $scene not as intended" >&2
    exit 1
  fi
  lcp="$work/peer-$m.dat"
  [[ -s $lcp ]] || "$rollbem" lcp export "$scene" --out "$lcp" --quiet >/dev/null
  n=$(head -n 1 "$lcp")
  mc=$(((n - 4) / 3))
  ((3 * mc + 4 == n)) || { echo "$lcp: $n unknowns is not 3 m + 4" >&2; exit 1; }
  ns+=("$n")
  lim=$time_limit
  ((n <= large)) || lim=$large_time_limit
  size_load=$(loadavg)
  say "m = $m contact elements: LCP of size $n ($(du -h "$lcp" | cut -f1)), load average $size_load"

  # --- rollbem on the file --------------------------------------------------------------------------------------
  declare -A t=() piv=() st=() runs=()
  for solver in lemke lemke_dense; do
    json="$work/peer-$m.$solver.json"
    read -r ts nruns < <(time_rollbem "$lcp" "$solver" "$json")
    if [[ $ts == timeout ]]; then
      t[$solver]=n/a; piv[$solver]="?"; st[$solver]="over ${lim} s"; runs[$solver]=0
      : >"$work/peer-$m.$solver.z"
      : >"$work/peer-$m.$solver.w"
    else
      t[$solver]=$ts
      piv[$solver]=$(jq -r '.pivots' "$json")
      st[$solver]=$(jq -r '.status' "$json")
      runs[$solver]=$nruns
      jq -r '.z[]' "$json" >"$work/peer-$m.$solver.z"
      jq -r '.w[]' "$json" >"$work/peer-$m.$solver.w"
    fi
    say "  rollbem $solver: ${st[$solver]}, ${piv[$solver]} pivots, ${t[$solver]} s (${runs[$solver]} run(s))"
  done
  for solver in lemke lemke_dense; do
    ((runs[$solver] == repeats)) || notes+=("$n unknowns: rollbem $solver timed on ${runs[$solver]} run(s) (first run over ${skip_after} s, or over the ${lim} s limit).")
  done

  # --- rollbem active_set on the scene ----------------------------------------------------------------------------
  # The active-set solver works on the contact problem's physical unknowns, not on an LCP file: time it on the
  # scene the file was exported from (`timing_s.solve`: the solve alone, the flexibility already built) and
  # compare its nodal tractions with Lemke's run of the same scene.
  say "  rollbem active_set on the scene (${repeats} runs)"
  as_json="$work/peer-$m.active_set.json"
  as_ts=()
  for ((r = 0; r < repeats; r++)); do
    rm -f "$as_json.t"
    timeout "$lim" "$rollbem" run "$scene" --solver active_set --json "$as_json.t" --quiet >/dev/null || true
    as_ts+=("$(jq -r '.runs[0].timing_s.solve' "$as_json.t" 2>/dev/null || echo n/a)")
    if ((r == 0)); then
      as_st=$(jq -r '.runs[0].status' "$as_json.t" 2>/dev/null || echo "over ${lim} s")
      as_it=$(jq -r '.runs[0].work.iterations // "?"' "$as_json.t" 2>/dev/null || echo "?")
    fi
  done
  t_as=$(printf '%s\n' "${as_ts[@]}" | median)
  # Its nodal tractions against Lemke's run of the same scene.
  rm -f "$as_json"
  timeout "$lim" "$rollbem" run "$scene" --solver lemke --solver active_set --json "$as_json" --quiet >/dev/null || true
  as_d=$(jq -r '[.runs[] | select(.solver == "lemke") | .nodes[] | .pressure] as $lp
      | [.runs[] | select(.solver == "lemke") | .nodes[] | .shear] as $lq
      | [.runs[] | select(.solver == "active_set") | .nodes[] | .pressure] as $ap
      | [.runs[] | select(.solver == "active_set") | .nodes[] | .shear] as $aq
      | ([$lp[] | fabs] | max) as $p0
      | [range(0; $lp | length) | ([($lp[.] - $ap[.]), ($lq[.] - $aq[.])] | map(fabs) | max)] | max / $p0' \
    "$as_json" 2>/dev/null || echo n/a)
  [[ -n $as_d && $as_d != n/a ]] && as_d=$(fmt_e "$as_d") || as_d="n/a (Lemke's run of the scene over ${lim} s)"
  say "  rollbem active_set: $as_st, $as_it iterations, $t_as s, max|Δ traction|/p0 vs lemke $as_d"

  # --- Siconos ----------------------------------------------------------------------------------------------------
  kvf="$work/peer-$m.siconos.kv"
  if ((n > large)); then
    only="${!solved_somewhere[*]}"
    say "  Siconos (n > $large: only ${only:-none}, once each, ${large_time_limit} s limit)"
    if [[ -n $only ]]; then
      SOLVERS="$only" REPEATS=1 TIME_LIMIT=$large_time_limit TOL=$tol \
        "$work/peer" "$lcp" "$work/peer-$m.siconos" >"$kvf"
    else
      echo "solvers" >"$kvf"
    fi
    sic_limit=$large_time_limit
  else
    say "  Siconos: every LCP solver (${repeats} runs each when solved, ${time_limit} s limit per solver)"
    SOLVERS="" REPEATS=$repeats TIME_LIMIT=$time_limit TOL=$tol "$work/peer" "$lcp" "$work/peer-$m.siconos" >"$kvf"
    sic_limit=$time_limit
  fi
  [[ -n $siconos_solvers ]] || siconos_solvers=$(kv solvers "$kvf")
  [[ -n $siconos_solvers ]] || siconos_solvers=$(kv solvers "$work/peer-$m.siconos.kv")
  best_name="" best_t=""
  for s in $siconos_solvers; do
    status=$(kv "${s}_status" "$kvf")
    case $status in
      solved)
        ts=$(kv "${s}_time_s" "$kvf")
        d=$(force_diff "$work/peer-$m.lemke.z" "$work/peer-$m.lemke.w" "$work/peer-$m.siconos.$s.z" "$work/peer-$m.siconos.$s.w" "$mc")
        r=$(kv "${s}_runs" "$kvf")
        cell="**$(fmt_s "$ts")** ($(kv "${s}_iterations" "$kvf") it, err $(fmt_e "$(kv "${s}_error" "$kvf")"), Δ $d$( ((r == repeats)) || echo ", $r run$( ((r == 1)) || echo s)"))"
        ((n > large)) || solved_somewhere[$s]=1
        if [[ -z $best_t ]] || awk -v a="$ts" -v b="$best_t" 'BEGIN { exit !(a < b) }'; then
          best_name=$s best_t=$ts
        fi
        ;;
      failed)
        cell="failed: info $(kv "${s}_info" "$kvf"), err $(fmt_e "$(kv "${s}_error" "$kvf")") after $(kv "${s}_iterations" "$kvf") it, $(fmt_s "$(kv "${s}_time_s" "$kvf")") s"
        failed_at[$s]="${failed_at[$s]:-}${failed_at[$s]:+, }$n"
        ;;
      time_limit)
        cell="over ${sic_limit} s (time limit)"
        failed_at[$s]="${failed_at[$s]:-}${failed_at[$s]:+, }$n"
        ;;
      crashed)
        cell="crashed: $(kv "${s}_reason" "$kvf" | sed 's/ (see stderr.*//')"
        failed_at[$s]="${failed_at[$s]:-}${failed_at[$s]:+, }$n"
        ;;
      not_applicable) cell="not applicable: $(kv "${s}_reason" "$kvf")" ;;
      skipped) cell="not run (n > $large: reached ${tol} at no smaller size)" ;;
      *) cell="?" ;;
    esac
    sic_cell[$s,$n]=$cell
  done
  say "  Siconos fastest reaching $tol: ${best_name:-none} ${best_t:-}"

  # --- summary ----------------------------------------------------------------------------------------------------
  rb_name="" rb_t=""
  for solver in lemke lemke_dense active_set; do
    if [[ $solver == active_set ]]; then s_st=$as_st s_t=$t_as; else s_st=${st[$solver]} s_t=${t[$solver]}; fi
    [[ $s_st == solved && $s_t != n/a ]] || continue
    if [[ -z $rb_t ]] || awk -v a="$s_t" -v b="$rb_t" 'BEGIN { exit !(a < b) }'; then rb_name=$solver rb_t=$s_t; fi
  done
  if [[ -n $best_t && -n $rb_t ]]; then
    ratio=$(awk -v p="$best_t" -v f="$rb_t" 'BEGIN { if (f > 0) printf "%.3g", p / f; else print "n/a" }')
    sic_best="$best_name $(fmt_s "$best_t") s"
  elif [[ -n $rb_t ]]; then
    ratio="> $(awk -v p="$sic_limit" -v f="$rb_t" 'BEGIN { printf "%.3g", p / f }') (none within ${sic_limit} s)"
    sic_best="none within ${sic_limit} s"
  else
    ratio=n/a
    sic_best="${best_name:-none} $(fmt_s "${best_t:-n/a}") s"
  fi
  case $(kv lemke_status "$kvf") in
    solved | failed) sic_lemke=$(fmt_s "$(kv lemke_time_s "$kvf")") ;;
    time_limit) sic_lemke="over ${sic_limit} s" ;;
    *) sic_lemke="not run" ;;
  esac
  cell() { local c=$1; [[ $2 == solved ]] || c="$c ($2)"; echo "$c"; }
  rollbem_rows+=("| $n | $(cell "${piv[lemke]}" "${st[lemke]}") | $(fmt_s "${t[lemke]}") | $(cell "${piv[lemke_dense]}" "${st[lemke_dense]}") | $(fmt_s "${t[lemke_dense]}") | $(cell "$as_it" "$as_st") | $(fmt_s "$t_as") | $(force_diff "$work/peer-$m.lemke.z" "$work/peer-$m.lemke.w" "$work/peer-$m.lemke_dense.z" "$work/peer-$m.lemke_dense.w" "$mc") / $(rel_diff "$work/peer-$m.lemke.z" "$work/peer-$m.lemke_dense.z") | $as_d | $size_load |")
  summary_rows+=("| $n | ${rb_name:-none} $(fmt_s "${rb_t:-n/a}") s | $sic_best | $ratio | $sic_lemke |")
  unset t piv st runs
done

{
  echo "**Summary.** Fastest certified rollbem solver (status solved: rollbem's own residual check) against Siconos' fastest solver reaching lcp_compute_error ≤ $tol on the same LCP, solve time alone, median of the runs."
  echo
  echo "| unknowns | fastest certified rollbem | fastest Siconos reaching $tol | speed ratio (Siconos / rollbem) | Siconos Lemke [s] |"
  echo "|---:|---|---|---:|---:|"
  printf '%s\n' "${summary_rows[@]}"
  echo
  echo "**rollbem.** \`lcp solve FILE --solver lemke|lemke_dense\` (\`solve_time_s\`) and \`run SCENE --solver active_set\` (\`timing_s.solve\`)."
  echo
  echo "| unknowns | lemke pivots | lemke [s] | lemke_dense pivots | lemke_dense [s] | active_set iterations | active_set [s] | lemke vs lemke_dense: Δ forces / Δz | active_set vs lemke: max\\|Δ traction\\| / p0 | load average at the size's start |"
  echo "|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|"
  printf '%s\n' "${rollbem_rows[@]}"
  echo
  echo "**Siconos numerics $siconos_version, every LCP solver.** Solved (lcp_compute_error ≤ $tol): **time [s]** (iterations as Siconos counts them, lcp_compute_error, Δ = max over nodes of the difference in normal and tangential nodal force from rollbem lemke's answer / rollbem lemke's largest normal force); otherwise how it ended."
  echo
  printf '| solver |'; for n in "${ns[@]}"; do printf ' %s |' "$n"; done; echo
  printf '|---|'; for n in "${ns[@]}"; do printf -- '---|'; done; echo
  for s in $siconos_solvers; do
    printf '| %s |' "$s"
    for n in "${ns[@]}"; do printf ' %s |' "${sic_cell[$s,$n]:-}"; done
    echo
  done
  echo
  echo "Scenes: reference/scenes/cattaneo-decoupled.toml with \`[contact] coupling = true\` and \`[mesh] contact_elements\` = $sizes (hub support, μ = 0.3, load-driven P and Q, rotation held), exported with \`rollbem lcp export\` (dense)."
  echo "Times: wall clock of the solve call alone, median of up to $repeats runs (a solver that does not reach the tolerance is run once), single-threaded (OPENBLAS_NUM_THREADS=1), on this machine ($(nproc --all) cores; load average $load_start at the start, $(loadavg) at the end: other work on the machine inflates the times)."
  echo "Siconos: benches/peer/driver.c, each solver in a forked child with a time limit of $time_limit s (all its runs); tolerance $tol on lcp_compute_error for the solvers that take one, iteration caps: 10000 sweeps (PGS, PSOR, RPGS, CPG, Latin, projected gradient), 1000 Newton iterations, 50 n + 100 pivots. LCPs over $large unknowns: only the solvers that reached $tol at a smaller size, once each, with a $large_time_limit s limit."
  echo "active_set: \`rollbem run\` on the scene, \`timing_s.solve\` (the solve alone; the flexibility is built before it); it solves the same contact problem on its physical unknowns, so its agreement is measured on the nodal tractions against Lemke's run of the scene (relative to Lemke's peak pressure)."
  for note in "${notes[@]}"; do echo "Note: $note"; done
} | tee "$table_out"
