#!/usr/bin/env bash
# Peer benchmark: rollbem's Lemke engines against Siconos numerics (lcp_lexicolemke, lcp_pgs) on rollbem's own
# frictional LCPs at several sizes. Not part of CI. See benches/peer/README.md.
#
# Usage: bash benches/peer/run.sh TABLE.md
#   env SIZES="200 400 800 880"  contact elements of the scene variants (LCP size 3·m + 4)
#       REPEATS=3                timed runs per solver (the median is reported)
#       PGS_TOL=1e-10 PGS_MAX_ITER=1000   Siconos PGS settings (tolerance on lcp_compute_error)
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
sizes=${SIZES:-"200 400 800 880"}
repeats=${REPEATS:-3}
pgs_tol=${PGS_TOL:-1e-10}
pgs_max_iter=${PGS_MAX_ITER:-1000}
skip_after=${SKIP_AFTER:-120}
base_scene="$root/reference/scenes/cattaneo-decoupled.toml"

say() { echo "[peer] $*" >&2; }

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

now() { date +%s.%N; }
median() { sort -g | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }
# max |a_i − b_i| / max(max |a|, max |b|) of two files with one number per line.
rel_diff() {
  paste "$1" "$2" | awk '
    function abs(x) { return x < 0 ? -x : x }
    { d = abs($1 - $2); if (d > md) md = d; if (abs($1) > mz) mz = abs($1); if (abs($2) > mz) mz = abs($2) }
    END { if (NR == 0) print "n/a"; else if (mz == 0) printf "%.1e\n", md; else printf "%.1e\n", md / mz }'
}
kv() { awk -v k="$1" '$1 == k { print $2 }' "$2"; }
fmt_s() { if [[ $1 == n/a ]]; then echo "n/a"; else awk -v t="$1" 'BEGIN { if (t > 0) printf "%.3g", t; else print "≈0" }'; fi; }

# Run `rollbem lcp solve FILE --solver S --json OUT` REPEATS times; print "median_wall_seconds runs".
time_rollbem() {
  local file=$1 solver=$2 json=$3 t0 t1 dt runs=0 times=()
  for ((r = 0; r < repeats; r++)); do
    t0=$(now)
    "$rollbem" lcp solve "$file" --solver "$solver" --json "$json" >/dev/null || true
    t1=$(now)
    dt=$(awk -v a="$t0" -v b="$t1" 'BEGIN { print b - a }')
    times+=("$dt")
    runs=$((runs + 1))
    if awk -v d="$dt" -v s="$skip_after" 'BEGIN { exit !(d > s) }'; then break; fi
  done
  echo "$(printf '%s\n' "${times[@]}" | median) $runs"
}

loadavg() { cut -d' ' -f1-3 /proc/loadavg; }
load_start=$(loadavg)
rows=()
notes=()
timing_source=""
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
  "$rollbem" lcp export "$scene" --out "$lcp" >/dev/null
  n=$(head -n 1 "$lcp")
  say "m = $m contact elements: LCP of size $n"

  declare -A t=() piv=() st=() runs=()
  for solver in lemke lemke_dense; do
    json="$work/peer-$m.$solver.json"
    read -r wall nruns < <(time_rollbem "$lcp" "$solver" "$json")
    piv[$solver]=$(jq -r '.pivots' "$json")
    st[$solver]=$(jq -r '.status' "$json")
    runs[$solver]=$nruns
    jq -r '.z[]' "$json" >"$work/peer-$m.$solver.z"
    solve_time=$(jq -r '.solve_time_s // empty' "$json")
    if [[ -n $solve_time ]]; then
      # `lcp solve` reports the solve alone: take the median of the reported times instead of the wall time.
      # (The JSON holds the last run's time; with REPEATS > 1 rerun to collect each.)
      ts=("$solve_time")
      for ((r = 1; r < nruns; r++)); do
        "$rollbem" lcp solve "$lcp" --solver "$solver" --json "$json.t" >/dev/null || true
        ts+=("$(jq -r '.solve_time_s' "$json.t")")
      done
      t[$solver]=$(printf '%s\n' "${ts[@]}" | median)
      timing_source="solve_time_s"
    else
      t[$solver]=$wall
    fi
    say "  rollbem $solver: ${st[$solver]}, ${piv[$solver]} pivots, ${t[$solver]} s (${nruns} run(s))"
  done
  baseline=n/a
  if [[ $timing_source != solve_time_s ]]; then
    # No solve time in the JSON: the wall time includes reading the file (large: ~56 bytes per entry of M) and
    # writing the JSON. Measure those on the same M with q replaced by |q| + 1 ≥ 0 (Lemke returns z = 0 after
    # equilibrating, before any pivot), and subtract.
    head -n -1 "$lcp" >"$work/base.dat"
    tail -n 1 "$lcp" | awk '{ for (i = 1; i <= NF; i++) { v = $i + 0; if (v < 0) v = -v; printf "%s%.17g", (i > 1 ? " " : ""), v + 1 } print "" }' >>"$work/base.dat"
    read -r baseline _ < <(time_rollbem "$work/base.dat" lemke "$work/base.json")
    for solver in lemke lemke_dense; do
      t[$solver]=$(awk -v a="${t[$solver]}" -v b="$baseline" 'BEGIN { d = a - b; print (d > 0 ? d : 0) }')
    done
    timing_source="wall-minus-baseline"
    rm -f "$work/base.dat"
  fi

  # The active-set solver works on the contact problem's physical unknowns, not on an LCP file: time it on the
  # scene the file was exported from (`timing_s.solve`: the solve alone, the flexibility already built) and
  # compare its nodal tractions with Lemke's run of the same scene.
  say "  rollbem active_set on the scene (${repeats} runs)"
  as_json="$work/peer-$m.active_set.json"
  "$rollbem" run "$scene" --solver lemke --solver active_set --json "$as_json" >/dev/null || true
  as_st=$(jq -r '.runs[] | select(.solver == "active_set") | .status' "$as_json")
  as_it=$(jq -r '.runs[] | select(.solver == "active_set") | .work.iterations // "?"' "$as_json")
  as_d=$(jq -r '[.runs[] | select(.solver == "lemke") | .nodes[] | .pressure] as $lp
      | [.runs[] | select(.solver == "lemke") | .nodes[] | .shear] as $lq
      | [.runs[] | select(.solver == "active_set") | .nodes[] | .pressure] as $ap
      | [.runs[] | select(.solver == "active_set") | .nodes[] | .shear] as $aq
      | ([$lp[] | fabs] | max) as $p0
      | [range(0; $lp | length) | ([($lp[.] - $ap[.]), ($lq[.] - $aq[.])] | map(fabs) | max)] | max / $p0' \
      "$as_json" 2>/dev/null || echo n/a)
  [[ $as_d == n/a ]] || as_d=$(awk -v d="$as_d" 'BEGIN { printf "%.1e", d }')
  as_ts=()
  for ((r = 0; r < repeats; r++)); do
    "$rollbem" run "$scene" --solver active_set --json "$as_json.t" >/dev/null || true
    as_ts+=("$(jq -r '.runs[0].timing_s.solve' "$as_json.t")")
  done
  t_as=$(printf '%s\n' "${as_ts[@]}" | median)
  say "  rollbem active_set: $as_st, $as_it iterations, $t_as s, max|Δ traction|/p0 vs lemke $as_d"

  say "  Siconos lcp_lexicolemke and lcp_pgs (${repeats} runs each)"
  "$work/peer" "$lcp" "$work/peer-$m.siconos" "$pgs_tol" "$pgs_max_iter" "$repeats" >"$work/peer-$m.siconos.kv"
  kvf="$work/peer-$m.siconos.kv"
  p_lemke_it=$(kv lemke_iterations "$kvf")
  p_lemke_st=$(kv lemke_status "$kvf")
  p_lemke_t=$(kv lemke_time_s "$kvf")
  p_lemke_err=$(kv lemke_error "$kvf")
  p_pgs_st=$(kv pgs_status "$kvf")
  if [[ $p_pgs_st == zero_diagonal ]]; then
    p_pgs_it="n/a"
    p_pgs_t="n/a"
    d_pgs="n/a"
    notes+=("size $n: lcp_pgs not run: M has $(kv pgs_zero_diagonal_entries "$kvf") zero diagonal entries (PGS divides by M_ii).")
  else
    p_pgs_it=$(kv pgs_iterations "$kvf")
    p_pgs_t=$(kv pgs_time_s "$kvf")
    d_pgs=$(rel_diff "$work/peer-$m.lemke.z" "$work/peer-$m.siconos.pgs.z")
    [[ $p_pgs_st == solved ]] || p_pgs_it="$p_pgs_it ($p_pgs_st, error $(kv pgs_error "$kvf"))"
  fi
  d_lemke=$(rel_diff "$work/peer-$m.lemke.z" "$work/peer-$m.siconos.lemke.z")
  d_dense=$(rel_diff "$work/peer-$m.lemke.z" "$work/peer-$m.lemke_dense.z")
  fastest=$(awk -v a="${t[lemke]}" -v b="${t[lemke_dense]}" 'BEGIN { print (a < b ? a : b) }')
  ratio=$(awk -v p="$p_lemke_t" -v f="$fastest" 'BEGIN { if (f > 0) printf "%.3g", p / f; else print "n/a" }')
  ratio_as=$(awk -v p="$p_lemke_t" -v f="$t_as" 'BEGIN { if (f > 0) printf "%.3g", p / f; else print "n/a" }')
  cell() { # pivots, with the status when not solved and the run count when not repeated
    local c=$1
    [[ $2 == solved ]] || c="$c ($2)"
    echo "$c"
  }
  for solver in lemke lemke_dense; do
    ((runs[$solver] == repeats)) || notes+=("size $n: rollbem $solver timed on ${runs[$solver]} run(s) (first run over ${skip_after} s).")
  done
  rows+=("| $n | $(cell "${piv[lemke]}" "${st[lemke]}") | $(cell "${piv[lemke_dense]}" "${st[lemke_dense]}") | $(cell "$((p_lemke_it + 1))" "$p_lemke_st") | $p_pgs_it | $(fmt_s "${t[lemke]}") | $(fmt_s "${t[lemke_dense]}") | $(fmt_s "$p_lemke_t") | $(fmt_s "$p_pgs_t") | $ratio | $d_lemke | $d_pgs | $d_dense | $(fmt_s "$baseline") | $p_lemke_err | $(cell "$as_it" "$as_st") | $(fmt_s "$t_as") | $ratio_as | $as_d |")
  unset t piv st runs
done

{
  echo "| unknowns | rollbem lemke pivots | rollbem lemke_dense pivots | Siconos Lemke pivots | Siconos PGS iterations | rollbem lemke [s] | rollbem lemke_dense [s] | Siconos Lemke [s] | Siconos PGS [s] | speed ratio (Siconos Lemke / fastest rollbem) | max\\|z − z_Siconos Lemke\\| / max\\|z\\| | vs Siconos PGS | lemke vs lemke_dense | read + setup [s] | Siconos Lemke error | rollbem active_set iterations | rollbem active_set [s] | speed ratio (Siconos Lemke / active_set) | active_set vs lemke: max\\|Δ traction\\| / p0 |"
  echo "|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
  printf '%s\n' "${rows[@]}"
  echo
  echo "Scenes: reference/scenes/cattaneo-decoupled.toml with \`[contact] coupling = true\` and \`[mesh] contact_elements\` = $sizes (hub support, μ = 0.3, load-driven P and Q, rotation held). Siconos numerics $siconos_version (Debian libsiconos-numerics-dev); PGS tolerance $pgs_tol on lcp_compute_error, at most $pgs_max_iter iterations."
  echo "Times: wall clock, median of $repeats runs, on this machine ($(nproc) cores; load average $load_start at the start, $(loadavg) at the end: other work on the machine inflates the times). Siconos: the solver call alone (benches/peer/driver.c)."
  if [[ $timing_source == solve_time_s ]]; then
    echo "rollbem: \`solve_time_s\` reported by \`rollbem lcp solve\` (the solve alone)."
  else
    echo "rollbem: \`rollbem lcp solve\` reports no solve time yet, so its times are the external wall time minus the 'read + setup' column (the same command on the same M with q ≥ 0: reading the file, equilibration, writing the JSON)."
  fi
  echo "active_set: \`rollbem run\` on the scene the LCP was exported from, \`timing_s.solve\` (the solve alone; the flexibility is built before it), median of $repeats runs; it solves the same contact problem on its physical unknowns, so its agreement is measured on the nodal tractions against Lemke's run of the scene (relative to Lemke's peak pressure)."
  echo "Pivots: Siconos' iteration count + 1 (it does not count the pivot that brings z0 into the basis; rollbem does)."
  for note in "${notes[@]}"; do echo "Note: $note"; done
} | tee "$table_out"
