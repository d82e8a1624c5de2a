#!/usr/bin/env bash
# Peer benchmark: rollbem against CONTACT (E. Vollebregt's rolling-contact program, Fortran, Apache-2.0) on
# CONTACT's own 2D Carter inputs. Not part of CI. See benches/peer/README.md, section "CONTACT".
#
# Usage: bash benches/peer/contact.sh TABLE.md [CONTACT_SRC]
#   CONTACT_SRC (argument or env)  a CONTACT source tree (with src/, examples/, perfc_test/); without one the
#                                  script clones $CONTACT_REPO (default https://github.com/eve70a/CONTACT)
#   env PAIRS=3                    timed pairs (rollbem, then CONTACT) per input; the median is reported
#       CASES="carter2d carter2d_100 carter2d_800"   which inputs (examples/carter2d.inp, perfc_test/*.inp)
#       SOLVERS=active_set         rollbem solvers timed on every input
#       LEMKE_CASES="carter2d carter2d_100"          inputs on which rollbem's lemke is timed as well
#       GRID=exact                 exact: `[mesh] contact_x` on CONTACT's span; centred: `contact_half_width` with
#                                  CONTACT's element count and size (for a rollbem without contact_x)
#       SECTION=strip              strip: rollbem poses CONTACT's model of a 2D case, a strip DY wide on half-spaces
#                                  (`[mesh] strip_width = DY`, the same discrete problem); plane_strain: rollbem's
#                                  plane strain (a model difference of order (a/DY)² in the tractions)
#       CPU=0                      the core every timed run is pinned to (taskset)
#       WARM=1                     also time both warm-started: rollbem's sweep with `warm_start = true`, CONTACT
#                                  on a copy of the input whose cases after the first have I = 3 (each case starts
#                                  from the previous one's solution); the inputs, and rollbem's sweeps by default,
#                                  start every case cold (CONTACT: I = 0); WARM=0 skips the warm runs
#       CONTACT_EPS=               a tolerance for CONTACT's results run (default: the input's EPS; e.g. 1e-10 shows
#                                  how much of a difference is CONTACT's stopping criterion; the timed runs keep
#                                  the input's)
#       CONTACT_DY_SCALE=          a factor for DY and FN in CONTACT's results run (default: none; e.g. 100 takes
#                                  CONTACT's strip of width DY towards the plane strain rollbem solves, at the same
#                                  pressure: how much of a difference is the strip's finite width; the timed runs
#                                  keep the input's)
#       EXAMPLES=1                 also run CONTACT's four 2D examples carter2d, bentall, visc_cylindr and veldep_fric
#                                  beside rollbem, case by case with CPU times (contact_examples.py), in a second
#                                  table; EXAMPLES=0 skips them
#       VELDEP_EXAMPLE=PATH        rollbem's example veldep_fric (built by the script unless ROLLBEM is given)
#       KEEP=DIR                   keep the work folder (CONTACT build, inputs, outputs, scenes) in DIR
#       ROLLBEM=PATH               use this rollbem binary instead of building one
#       CONTACT_BIN=PATH           use this CONTACT executable instead of building one (it is checked all the same)
#       MKL=1                      build CONTACT with Intel oneMKL from PyPI (its FFT products and preconditioners:
#                                  CONTACT at its best, the default); MKL=0: gfortran without MKL (every FFT path
#                                  compiled out). MKL_VERSION= picks the PyPI version (default: the newest)
#
# CONTACT's code is only read, built in the work folder and run: nothing of it is copied into rollbem. The build
# (benches/peer/contact_build.sh, shared with contact3d.sh) makes a few edits to the work folder's copy of its
# sources (listed there and in the README); the user's tree is not touched. Before anything is timed the build must
# reproduce CONTACT's examples/carter2d.ref_out to its printed digits (contact_refcmp.py), else the script stops.
set -euo pipefail

if [[ $# -lt 1 || $# -gt 2 ]]; then
  echo "usage: $0 TABLE.md [CONTACT_SRC]" >&2
  exit 2
fi
table_out=$1
contact_src=${2:-${CONTACT_SRC:-}}
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
pairs=${PAIRS:-3}
cases=${CASES:-"carter2d carter2d_100 carter2d_800"}
solvers=${SOLVERS:-active_set}
lemke_cases=${LEMKE_CASES:-"carter2d carter2d_100"}
grid_mode=${GRID:-exact}
section=${SECTION:-strip}
cpu=${CPU:-0}
warm=${WARM:-1}
export LC_ALL=C

say() { echo "[contact-peer] $*" >&2; }
die() {
  echo "[contact-peer] error: $*" >&2
  exit 1
}
[[ $grid_mode == exact || $grid_mode == centred ]] || die "GRID must be exact or centred"
[[ $section == strip || $section == plane_strain ]] || die "SECTION must be strip or plane_strain"

# 1. The work folder; tools from Debian's packages (contact_build.sh: gfortran, make, GNU time, taskset, git, and
#    python3-pip + unzip for MKL, reference LAPACK/BLAS without), jq for rollbem's JSON.
if [[ -n ${KEEP:-} ]]; then
  work=$(mkdir -p "$KEEP" && cd "$KEEP" && pwd)
else
  work=$(mktemp -d)
  trap 'rm -rf "$work"' EXIT
fi
: >"$work/log"
contact_mkl=${MKL:-1}
[[ $contact_mkl == 0 || $contact_mkl == 1 ]] || die "MKL must be 1 (build with Intel oneMKL, the default) or 0"
# shellcheck source=benches/peer/contact_build.sh
source "$here/contact_build.sh"
contact_install_tools jq

# 2. CONTACT's sources and build (contact_build.sh; README "Building CONTACT"), checked against the author's
#    reference output of carter2d before anything is timed.
contact_get_source "$contact_src"
for f in examples/carter2d.inp examples/carter2d.ref_out perfc_test/carter2d_100.inp perfc_test/carter2d_800.inp; do
  [[ -f $contact_src/$f ]] || die "$contact_src is not a CONTACT source tree (no $f)"
done
contact_obtain_bin "$work"
contact_ref_summary=()
mkdir -p "$work/refcheck"
cp "$contact_src/examples/carter2d.inp" "$work/refcheck/"
say "checking the build against CONTACT's examples/carter2d.ref_out"
contact_ref_check carter2d "$work/refcheck" "$contact_src/examples/carter2d.ref_out"
gfortran_version=$(gfortran --version | head -n 1)

# 3. rollbem.
if [[ -n ${ROLLBEM:-} ]]; then
  built=$ROLLBEM
else
  say "building rollbem (cargo build --release)"
  (cd "$root" && nice cargo build --release --quiet)
  built="${CARGO_TARGET_DIR:-$root/target}/release/rollbem"
fi
[[ -x $built ]] || die "no rollbem binary at $built"
# A private copy: a build of another checkout sharing CARGO_TARGET_DIR cannot replace it during the run.
rollbem="$work/rollbem"
cp "$built" "$rollbem"
rollbem_version=$("$rollbem" --version)
# rollbem's example that runs veldep_fric's steady and transient cases (contact_examples.py); VELDEP_EXAMPLE=PATH
# uses a given one, and with ROLLBEM given and no VELDEP_EXAMPLE veldep_fric's rollbem columns stay empty.
veldep_example=""
if [[ ${EXAMPLES:-1} == 1 ]]; then
  if [[ -n ${VELDEP_EXAMPLE:-} ]]; then
    veldep_example=$VELDEP_EXAMPLE
  elif [[ -z ${ROLLBEM:-} ]]; then
    say "building rollbem's example veldep_fric (cargo build --release --example veldep_fric)"
    (cd "$root" && nice cargo build --release --quiet --example veldep_fric)
    veldep_example="${CARGO_TARGET_DIR:-$root/target}/release/examples/veldep_fric"
  fi
  if [[ -n $veldep_example ]]; then
    cp "$veldep_example" "$work/veldep_fric"
    veldep_example="$work/veldep_fric"
  fi
fi

median() { sort -g | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }
loadavg() { cut -d' ' -f1-3 /proc/loadavg; }
kv() { awk -v k="$1" '$1 == k { print $2; exit }' "$2"; }
g() { awk -v v="$1" 'BEGIN { printf "%.6g", v }'; }
# CPU seconds for the table (GNU time resolves 0.01 s) and the ratio of two.
cpu_cell() { awk -v t="$1" 'BEGIN { if (t > 0) printf "%.3g", t; else print "< 0.01" }'; }
cpu_ratio() { awk -v a="$1" -v b="$2" 'BEGIN { if (a > 0 && b > 0) printf "%.3g", a / b; else print "n/a (< 0.01 s)" }'; }
# Run a command pinned to one core under GNU time: "user+sys seconds, peak RSS in MB" appended to TIMES.
timed() {
  local times=$1 tf="$work/time.tmp" rc=0
  shift
  taskset -c "$cpu" /usr/bin/time -o "$tf" -f '%U %S %M' "$@" </dev/null >>"$work/log" 2>&1 || rc=$?
  # (GNU time writes "Command exited with non-zero status N" before the format line when the command fails.)
  tail -n 1 "$tf" | awk '{ printf "%.3f %.1f\n", $1 + $2, $3 / 1024 }' >>"$times"
  return $rc
}

# 4. CONTACT's inputs: what each case prescribes. inp_params INP writes "key value" lines (the grid, profile,
#    materials, friction, tolerance) and one "case K FN CKSI" line per case.
inp_params() {
  awk '
    function digits(line, names, n, i, d, L) { # control digits by letter, e.g. D["T"] of P-B-T-N-F-S
      split(names, L, "-"); n = length(L); d = line
      while (length(d) < n) d = "0" d
      for (i = 1; i <= n; i++) D[L[i]] = substr(d, length(d) - n + i, 1)
    }
    /^[ \t]*%/ { next }
    $2 == "MODULE" { if ($1 == 3) ncase++; next }
    $2 ~ /P-B-T-N-F-S$/ {
      digits($1, $2)
      if (D["T"] != 3 || D["N"] != 1 || D["F"] != 0) bad = "case " ncase ": not steady rolling (T=3) with FN (N=1) and creepages (F=0) prescribed"
      next
    }
    /FN, *CKSI/ { printf "case %d %s %s\n", ncase, $1, $2; if ($3 + 0 != 0 || $4 + 0 != 0) bad = "CETA or CPHI nonzero"; next }
    /FN, *FX/ { bad = "FX prescribed" }
    /MAXGS.*EPS/ { print "eps", $5 }
    /FSTAT, *FKIN/ { print "fstat", $1 }
    /CHI, *(DQ|S), *VELOC/ { print "chi", $1; print "dq", $2 }
    /POISS 1,2, *GG 1,2/ { print "nu1", $1; print "nu2", $2; print "g1", $3; print "g2", $4 }
    /IPOTCN/ { print "ipotcn", $1 }
    /MX,MY,XC1,YC1,DX,DY/ { print "mx", $1; print "my", $2; print "xc1", $3; print "yc1", $4; print "dx", $5; print "dy", $6 }
    /IBASE, *IPLAN/ { print "ibase", $1; ibase = $1; next }
    ibase == 1 && /B1,B2,B3,B4,B5,B6/ { print "b1", $1; if ($2 + 0 != 0 || $3 + 0 != 0 || $4 + 0 != 0 || $5 + 0 != 0 || $6 + 0 != 0) bad = "B2..B6 nonzero"; ibase = 0; next }
    ibase == 2 && /NN,XM,RM,Y1,DY1/ { print "xm", $2; print "rm", $3; heights = $1; next }
    heights > 0 { for (i = 1; i <= NF; i++) if ($i + 0 != 0) bad = "a nonzero profile height"; heights -= NF; if (heights <= 0) ibase = 0; next }
    END { if (bad != "") print "unsupported", bad }
  ' "$1"
}

# Copy of an input with every case printing its global results (O >= 2) and writing its Matlab file (A = 1): the
# results run. The timed runs use the input as it is.
# With CONTACT_EPS set, the results run also solves to that tolerance (EPS, and MAXGS = MAXIN = 9999 so that the
# iterations can get there): how much of a difference is CONTACT's stopping criterion.
results_variant() {
  awk -v eps="${CONTACT_EPS:-}" -v dys="${CONTACT_DY_SCALE:-}" -v digits="O>2 A=1" -f "$here/contact_inp.awk" "$1"
}

# Copy of an input with the I digit (initial estimate) of every case after the first set to $1, and the last case
# printing its global results (O >= 2), to compare with the cold run's.
iestim_variant() {
  awk -v want="$1" '
    FNR == NR { if ($2 == "MODULE" && $1 == 3) last++; next }
    $2 == "MODULE" && $1 == 3 { ncase++ }
    $2 ~ /G-I-A-O-W-R$/ && $0 !~ /^[ \t]*%/ && ncase > 1 {
      n = split($2, L, "-"); d = $1
      while (length(d) < n) d = "0" d
      out = ""
      for (i = 1; i <= n; i++) {
        c = substr(d, i, 1)
        if (L[i] == "I") c = want
        if (L[i] == "O" && ncase == last && c < 2) c = 2
        out = out c
      }
      match($0, /[0-9]+/)
      $0 = substr($0, 1, RSTART - 1) out substr($0, RSTART + RLENGTH)
    }
    { print }
  ' "$2" "$2"
}

# CONTACT's .out: one line per case "K CKSI FN FX FX/(FSTAT FN) NCON NADH DQ".
parse_out() {
  awk '
    /^ Case +[0-9]+/ { k = $2; next }
    /CHI +DQ +VELOC +CKSI/ { want = "kin"; next }
    /FN +FX +FY +MZ/ { want = "force"; next }
    /FN\/G +FX\/FSTAT\/FN/ { want = "rel"; next }
    /NPOT +NCON +NADH +NSLIP/ { want = "stat"; next }
    want == "kin" { dq[k] = $2; cksi[k] = $4; want = ""; next }
    want == "force" { fn[k] = $1; fx[k] = $2; want = ""; next }
    want == "rel" { rel[k] = $2; want = ""; next }
    want == "stat" { ncon[k] = $2; nadh[k] = $3; want = ""; seen[k] = 1; if (k > n) n = k; next }
    END { for (i = 1; i <= n; i++) if (seen[i]) print i, cksi[i], fn[i], fx[i], rel[i], ncon[i], nadh[i], dq[i] }
  ' "$1"
}

# CONTACT's Matlab file of one case: "XL DX NCON NADH SUM_PX" on stdout, "I PN PX" per element in contact to $2.
parse_mat() {
  awk -v el="$2" '
    /^% +MX +MY +XL/ { hdr = 1; next }
    hdr == 1 { xl = $3; dx = $5; hdr = 0; next }
    /^% +I +IGS/ { body = 1; next }
    body == 1 && NF >= 6 { if ($2 >= 1) { nc++; if ($2 == 1) na++; s += $6; print $1, $5, $6 > el } }
    END { printf "%.17g %.17g %d %d %.17g\n", xl, dx, nc, na, s }
  ' "$1"
}

inp_path() {
  case $1 in
    carter2d) echo "$contact_src/examples/carter2d.inp" ;;
    *) echo "$contact_src/perfc_test/$1.inp" ;;
  esac
}

# rollbem's scene for one input (and solver): CONTACT's grid, profile, materials, load per unit width.
write_scene() {
  local p=$1 name=$2 solver=$3 cksi=$4 out=$5 mesh strip=""
  local mx xc1 dx dy r e1 e2 nu1 nu2 mu fn dir
  mx=$(kv mx "$p")
  xc1=$(kv xc1 "$p")
  dx=$(kv dx "$p")
  dy=$(kv dy "$p")
  nu1=$(kv nu1 "$p")
  nu2=$(kv nu2 "$p")
  e1=$(awk -v g="$(kv g1 "$p")" -v n="$nu1" 'BEGIN { printf "%.17g", 2 * g * (1 + n) }')
  e2=$(awk -v g="$(kv g2 "$p")" -v n="$nu2" 'BEGIN { printf "%.17g", 2 * g * (1 + n) }')
  mu=$(kv fstat "$p")
  fn=$(awk -v f="$(kv fn1 "$p")" -v d="$dy" 'BEGIN { printf "%.17g", f / d }')
  case $(kv ibase "$p") in
    1) r=$(awk -v b="$(kv b1 "$p")" 'BEGIN { printf "%.17g", 1 / (2 * b) }') ;;
    2) r=$(kv rm "$p") ;;
  esac
  dir=$(awk -v c="$(kv chi "$p")" 'BEGIN { print (c > 90 && c < 270) ? -1 : 1 }')
  if [[ $grid_mode == exact ]]; then
    mesh=$(awk -v m="$mx" -v x="$xc1" -v d="$dx" 'BEGIN { printf "contact_x = [%.17g, %.17g]", x - d / 2, x + (m - 0.5) * d }')
  else
    mesh=$(awk -v m="$mx" -v d="$dx" 'BEGIN { printf "contact_half_width = %.17g", m * d / 2 }')
  fi
  # CONTACT's strip (scaled as its results run's, CONTACT_DY_SCALE): the load per unit width stays FN/DY.
  [[ $section == strip ]] && strip=$(awk -v d="$dy" -v s="${CONTACT_DY_SCALE:-1}" 'BEGIN { printf "strip_width = %.17g", d * s }')
  cat >"$out" <<EOF
name = "$name"
description = "CONTACT's $case_name.inp on rollbem's half-planes: $mx elements of $dx mm from x = $xc1 (centre of the first), load FN/DY per unit width"
units = "N, mm, MPa"

[wheel]
radius = $r
youngs_modulus = $e1
poisson_ratio = $nu1
model = "half_plane"
profile = "parabola"

[counter_body]
kind = "half_plane"
youngs_modulus = $e2
poisson_ratio = $nu2

[mesh]
element = "constant"
$mesh
contact_elements = $mx
$strip

[contact]
friction = $mu
coupling = false

[drive]
normal_load = $fn

[rolling]
mode = "steady"
creepage = $cksi
direction = $dir

[solvers]
use = ["$solver"]
EOF
}

csv_col() { # print column NAME of a CSV (header row), one value per row
  awk -F, -v name="$1" 'NR == 1 { for (i = 1; i <= NF; i++) if ($i == name) c = i; next } { print $c }' "$2"
}

load_start=$(loadavg)
rows=()
notes=()
declare -A fx_note=()
for case_name in $cases; do
  inp=$(inp_path "$case_name")
  [[ -f $inp ]] || die "no input $inp"
  cw="$work/$case_name"
  mkdir -p "$cw/timed" "$cw/results" "$cw/rollbem"
  p="$cw/params"
  inp_params "$inp" >"$p"
  grep -q '^unsupported' "$p" && die "$case_name.inp: $(kv unsupported "$p")"
  [[ $(kv ipotcn "$p") == 3 && $(kv my "$p") == 1 ]] || die "$case_name.inp: expected IPOTCN = 3 and MY = 1"
  awk '$1 == "case" { print $3 }' "$p" | sort -u | awk 'NR > 1 { exit 1 }' || die "$case_name.inp: FN changes between cases"
  echo "fn1 $(awk '$1 == "case" { print $3; exit }' "$p")" >>"$p"
  awk '$1 == "case" { print $4 }' "$p" >"$cw/cksi"
  awk '!seen[$1]++' "$cw/cksi" >"$cw/cksi.unique"
  ncases=$(wc -l <"$cw/cksi")
  nuniq=$(wc -l <"$cw/cksi.unique")
  mx=$(kv mx "$p")
  say "$case_name: $mx elements, $ncases cases ($nuniq creepages), EPS $(kv eps "$p")"

  # CONTACT: the results run (every case printed and written to a Matlab file; not timed).
  cp "$inp" "$cw/timed/$case_name.inp"
  warm_here=$((warm && ncases > 1))
  if ((warm_here)); then
    mkdir -p "$cw/warm"
    iestim_variant 3 "$inp" >"$cw/warm/$case_name.inp"
  fi
  results_variant "$inp" >"$cw/results/$case_name.inp"
  say "  CONTACT results run (output of every case)"
  (cd "$cw/results" && "$contact_bin" 2 "$case_name" </dev/null >stdout.txt 2>&1) || die "CONTACT failed on $case_name (results run)"
  parse_out "$cw/results/$case_name.out" >"$cw/contact.cases"
  [[ $(wc -l <"$cw/contact.cases") -eq $ncases ]] || die "$case_name: $(wc -l <"$cw/contact.cases") cases in CONTACT's output, $ncases in the input"
  awk -v d="$(kv dx "$p")" '{ if ($8 - d > 1e-9 * d || d - $8 > 1e-9 * d) { print "DQ " $8 " is not DX " d; exit 1 } }' "$cw/contact.cases" >&2 ||
    notes+=("$case_name: CONTACT's time step DQ differs from DX; rollbem's upwind difference uses the element spacing.")
  : >"$cw/contact.mat"
  for ((k = 1; k <= ncases; k++)); do
    mat=$(printf '%s/results/%s.%04d.mat' "$cw" "$case_name" "$k")
    [[ -f $mat ]] || die "no Matlab file $mat"
    echo "$k $(parse_mat "$mat" "$cw/contact.el.$k")" >>"$cw/contact.mat"
  done
  # The grid convention, as CONTACT writes it: XL (left edge) = XC1 − DX/2.
  awk -v x="$(kv xc1 "$p")" -v d="$(kv dx "$p")" 'NR == 1 { if ($2 - (x - d / 2) > 1e-9 || (x - d / 2) - $2 > 1e-9) { print "XL " $2 " is not XC1 - DX/2"; exit 1 } }' \
    "$cw/contact.mat" >&2 || die "$case_name: unexpected grid in CONTACT's Matlab file"

  # rollbem: the sweep spec (every case of the input, in its order: the 1000 cases of carter2d_100 are its 50
  # creepages 20 times, as in CONTACT's input), one base scene per solver.
  case_solvers=$solvers
  [[ " $lemke_cases " == *" $case_name "* && " $solvers " != *" lemke "* ]] && case_solvers="$solvers lemke"
  for solver in $case_solvers; do
    write_scene "$p" "contact-$case_name" "$solver" "$(head -n 1 "$cw/cksi")" "$cw/rollbem/base-$solver.toml"
    {
      echo "name = \"contact-$case_name-$solver\""
      echo "description = \"CONTACT's $case_name.inp: its $ncases creepages in its order\""
      echo "base = \"base-$solver.toml\""
      echo
      echo "[[grid]]"
      printf '"rolling.creepage" = [%s]\n' "$(paste -sd, "$cw/cksi" | sed 's/,/, /g')"
    } >"$cw/rollbem/sweep-$solver.toml"
    # The same sweep warm-started (each case from the previous case's solution on the model).
    sed -e "s/^name = \"contact-$case_name-$solver\"/name = \"contact-$case_name-$solver-warm\"/" \
      -e 's/^base = /warm_start = true\nbase = /' "$cw/rollbem/sweep-$solver.toml" >"$cw/rollbem/sweep-$solver-warm.toml"
  done

  # rollbem's per-creepage runs (nodal tractions and states; not timed): one scene per distinct creepage.
  scenes=()
  j=0
  while read -r c; do
    j=$((j + 1))
    write_scene "$p" "contact-$case_name-$j" "active_set" "$c" "$cw/rollbem/run-$j.toml"
    scenes+=("$cw/rollbem/run-$j.toml")
  done <"$cw/cksi.unique"
  say "  rollbem run on the $nuniq creepages (nodal tractions)"
  run_flags=()
  for solver in $case_solvers; do run_flags+=(--solver "$solver"); done
  "$rollbem" run "${scenes[@]}" "${run_flags[@]}" --out-dir "$cw/rollbem/runs" --quiet >>"$work/log" 2>&1 ||
    say "  (rollbem run exited with $? — statuses are checked below)"

  # Timed runs, alternating: rollbem's sweep (each solver), then CONTACT's unmodified input; PAIRS times.
  for ((r = 1; r <= pairs; r++)); do
    for solver in $case_solvers; do
      say "  pair $r/$pairs: rollbem sweep ($solver)"
      RAYON_NUM_THREADS=1 timed "$cw/time.rollbem.$solver" "$rollbem" sweep "$cw/rollbem/sweep-$solver.toml" \
        --out "$cw/rollbem/sweep-$solver.csv" --quiet || notes+=("$case_name: rollbem sweep ($solver) exited with a nonzero code in pair $r.")
      if ((warm_here)); then
        say "  pair $r/$pairs: rollbem sweep ($solver, warm_start = true)"
        RAYON_NUM_THREADS=1 timed "$cw/time.rollbem.$solver.warm" "$rollbem" sweep "$cw/rollbem/sweep-$solver-warm.toml" \
          --out "$cw/rollbem/sweep-$solver-warm.csv" --quiet || notes+=("$case_name: rollbem warm sweep ($solver) exited with a nonzero code in pair $r.")
      fi
    done
    say "  pair $r/$pairs: CONTACT"
    (cd "$cw/timed" && timed "$cw/time.contact" "$contact_bin" 2 "$case_name") || die "CONTACT failed on $case_name"
    if ((warm_here)); then
      say "  pair $r/$pairs: CONTACT warm-started (I = 3)"
      (cd "$cw/warm" && timed "$cw/time.contact.warm" "$contact_bin" 2 "$case_name") || die "CONTACT failed on $case_name (I = 3)"
    fi
  done
  # The timed run and the results run compute the same thing: their first case's printed FX agree.
  parse_out "$cw/timed/$case_name.out" | head -n 1 >"$cw/contact.timed.first"
  if [[ -z ${CONTACT_EPS:-} && $(awk '{ print $4 }' "$cw/contact.timed.first") != $(awk 'NR == 1 { print $4 }' "$cw/contact.cases") ]]; then
    die "$case_name: the timed run's FX of case 1 differs from the results run's"
  fi
  # Its timer table: |name |#times |cpu sec |% |wall sec |% |
  t_norm=$(awk -F'|' '$2 ~ /^Algorithm Norm/ { print $4 + 0 }' "$cw/timed/$case_name.out")
  t_tang=$(awk -F'|' '$2 ~ /^Algorithm Tang/ { print $4 + 0 }' "$cw/timed/$case_name.out")
  t_all=$(awk -F'|' '$2 ~ /^Total / { print $4 + 0 }' "$cw/timed/$case_name.out")
  notes+=("$case_name: CONTACT's own timers (last timed run, CPU): total $t_all s, NORM $t_norm s, TANG $t_tang s.")

  c_cpu=$(awk '{ print $1 }' "$cw/time.contact" | median)
  c_mem=$(awk '{ print $2 }' "$cw/time.contact" | median)
  if ((warm_here)); then
    w_cpu=$(awk '{ print $1 }' "$cw/time.contact.warm" | median)
    w_mem=$(awk '{ print $2 }' "$cw/time.contact.warm" | median)
    # The warm run's answer: its last case's printed FX/(FSTAT FN) against the results run's.
    wl=$(parse_out "$cw/warm/$case_name.out" | tail -n 1 | awk '{ print $5 }')
    cl=$(tail -n 1 "$cw/contact.cases" | awk '{ print $5 }')
    notes+=("$case_name: CONTACT warm-started (I = 3): last case's FX/(FSTAT FN) $wl (cold: $cl).")
  else
    w_cpu=$c_cpu
    w_mem=$c_mem
  fi
  mid=$(((nuniq + 1) / 2))
  mid_cksi=$(sed -n "${mid}p" "$cw/cksi.unique")
  for solver in $case_solvers; do
    csv="$cw/rollbem/sweep-$solver.csv"
    bad=$(csv_col status "$csv" | grep -vc '^solved$' || true)
    ((bad == 0)) || notes+=("$case_name, $solver: $bad of $ncases sweep cases not solved.")
    # Q/(μP) per case against CONTACT's FX/(FSTAT FN), FX summed from its Matlab file (PX to 6 digits).
    paste -d' ' <(csv_col tangential_load "$csv") <(csv_col normal_load "$csv") <(csv_col friction "$csv") \
      >"$cw/rollbem.q.$solver"
    dfx=$(paste -d' ' "$cw/rollbem.q.$solver" "$cw/contact.mat" | awk -v dx="$(kv dx "$p")" -v dy="$(kv dy "$p")" \
      -v fn="$(kv fn1 "$p")" -v mu="$(kv fstat "$p")" '
      { r = $1 / ($3 * $2); c = $9 * dx * dy / (mu * fn); d = r - c; if (d < 0) d = -d; if (d > m) { m = d; at = NR } }
      END { printf "%.1e %d\n", m, at }')
    read -r dfx dfx_at <<<"$dfx"
    # CONTACT's printed FX/(FSTAT FN) (4 digits) against its Matlab sum: a check of the parsing.
    chk=$(awk -v dx="$(kv dx "$p")" -v dy="$(kv dy "$p")" -v fn="$(kv fn1 "$p")" -v mu="$(kv fstat "$p")" '
      NR == FNR { rel[$1] = $5; next } { c = $6 * dx * dy / (mu * fn); d = c - rel[$1]; if (d < 0) d = -d; if (d > m) m = d }
      END { printf "%.1e", m }' "$cw/contact.cases" "$cw/contact.mat")
    fx_note[$case_name]="max |printed FX/(FSTAT FN) − ΣPX·DX·DY/(FSTAT FN)| = $chk"

    # Node states and tractions per distinct creepage.
    agree=0
    worst_p=0
    worst_q=0
    worst_at=""
    tract="n/a"
    mid_counts=""
    j=0
    while read -r c; do
      j=$((j + 1))
      json="$cw/rollbem/runs/contact-$case_name-$j.json"
      k=$(awk -v c="$c" '$1 == c { print NR; exit }' "$cw/cksi")
      read -r _ _ _ cn ca _ < <(awk -v k="$k" '$1 == k' "$cw/contact.mat")
      if [[ ! -f $json ]] || [[ $(jq -r --arg s "$solver" '.runs[] | select(.solver == $s) | .status' "$json") != solved ]]; then
        notes+=("$case_name, $solver: rollbem run at CKSI = $c not solved.")
        continue
      fi
      jq -r --arg s "$solver" '.runs[] | select(.solver == $s) | .nodes | to_entries[] |
        "\(.key) \(.value.x) \(.value.pressure) \(.value.shear) \(.value.state)"' "$json" >"$cw/rollbem.nodes"
      read -r rn ra < <(awk '$5 == "stick" || $5 == "slip" { n++ } $5 == "stick" { a++ } END { print n + 0, a + 0 }' "$cw/rollbem.nodes")
      [[ $rn == "$cn" && $ra == "$ca" ]] && agree=$((agree + 1))
      ((j == mid)) && mid_counts="$rn / $cn|$ra / $ca"
      # Node i is CONTACT's element i + 1 when the grids coincide (exact grid, or a centred grid that is CONTACT's).
      off=$(awk -v x="$(kv xc1 "$p")" -v d="$(kv dx "$p")" 'NR == 1 { o = ($2 - x) / d; if (o < 0) o = -o; print (o < 1e-6) ? 0 : o }' "$cw/rollbem.nodes")
      if [[ $off == 0 ]]; then
        read -r dp dq < <(awk 'NR == FNR { pn[$1] = $2; px[$1] = $3; if ($2 > pm) pm = $2; next }
          { i = $1 + 1; a = $3 - pn[i]; b = $4 - px[i]; if (a < 0) a = -a; if (b < 0) b = -b; if (a > mp) mp = a; if (b > mq) mq = b }
          END { printf "%.17g %.17g\n", mp / pm, mq / pm }' "$cw/contact.el.$k" "$cw/rollbem.nodes")
        if awk -v a="$dp" -v b="$dq" -v wp="$worst_p" -v wq="$worst_q" 'BEGIN { exit !((a > b ? a : b) > (wp > wq ? wp : wq)) }'; then
          worst_at=$c
        fi
        worst_p=$(awk -v a="$dp" -v b="$worst_p" 'BEGIN { print (a > b) ? a : b }')
        worst_q=$(awk -v a="$dq" -v b="$worst_q" 'BEGIN { print (a > b) ? a : b }')
        tract=ok
      fi
    done <"$cw/cksi.unique"
    if [[ $tract == ok ]]; then
      tp=$(awk -v v="$worst_p" 'BEGIN { printf "%.1e", v }')
      tq=$(awk -v v="$worst_q" 'BEGIN { printf "%.1e", v }')
      tcell="$tp | $tq (at $worst_at)"
    else
      tcell="n/a | n/a (grids differ by a fraction of an element)"
    fi
    r_cpu=$(awk '{ print $1 }' "$cw/time.rollbem.$solver" | median)
    r_mem=$(awk '{ print $2 }' "$cw/time.rollbem.$solver" | median)
    ratio=$(cpu_ratio "$r_cpu" "$c_cpu")
    if ((warm_here)); then
      rw_cpu=$(awk '{ print $1 }' "$cw/time.rollbem.$solver.warm" | median)
      rw_mem=$(awk '{ print $2 }' "$cw/time.rollbem.$solver.warm" | median)
      wmem="$(printf '%.1f' "$rw_mem") | $(printf '%.1f' "$w_mem")"
      wratio=$(cpu_ratio "$rw_cpu" "$w_cpu")
      wcells="$(cpu_cell "$rw_cpu") | $(cpu_cell "$w_cpu")"
      # The warm sweep's answers against the cold sweep's, case by case.
      dw=$(paste -d' ' <(csv_col tangential_load "$csv") <(csv_col normal_load "$csv") <(csv_col friction "$csv") \
        <(csv_col tangential_load "$cw/rollbem/sweep-$solver-warm.csv") |
        awk '{ d = ($1 - $4) / ($3 * $2); if (d < 0) d = -d; if (d > m) m = d } END { printf "%.1e", m }')
      notes+=("$case_name, $solver: rollbem's warm sweep against its cold one: max |ΔQ|/(μP) over the cases = $dw.")
    else
      wratio="(1 case)"
      wcells="(1 case) | (1 case)"
      wmem="(1 case) | (1 case)"
    fi
    rows+=("| $case_name | $mx | $ncases | $solver | $dfx (case $dfx_at) | ${mid_counts%%|*} | ${mid_counts##*|} | $agree of $nuniq | $tcell | $(cpu_cell "$r_cpu") | $(cpu_cell "$c_cpu") | $ratio | $wcells | $wratio | $(printf '%.1f' "$r_mem") | $(printf '%.1f' "$c_mem") | $wmem |")
    say "  $solver: max ΔFX/(μFN) $dfx, counts equal at $agree of $nuniq, tractions $tcell, CPU $r_cpu s vs $c_cpu s"
  done
  # rollbem's solvers against each other (each solves the same discrete problem, to round-off).
  read -ra sv <<<"$case_solvers"
  if ((${#sv[@]} > 1)); then
    d=$(paste -d' ' "$cw/rollbem.q.${sv[0]}" "$cw/rollbem.q.${sv[1]}" | awk '{ d = ($1 - $4) / ($3 * $2); if (d < 0) d = -d; if (d > m) m = d } END { printf "%.1e", m }')
    notes+=("$case_name: rollbem ${sv[0]} against ${sv[1]}: max |ΔQ|/(μP) over the cases = $d.")
  fi
  grid_desc=$(awk -v m="$mx" -v x="$(kv xc1 "$p")" -v d="$(kv dx "$p")" 'BEGIN { printf "[%.6g, %.6g]", x - d / 2, x + (m - 0.5) * d }')
  notes+=("$case_name: MX = $mx, XC1 = $(g "$(kv xc1 "$p")"), DX = $(g "$(kv dx "$p")") (elements on $grid_desc), DY = $(g "$(kv dy "$p")"), FN = $(g "$(kv fn1 "$p")") (rollbem: $(awk -v f="$(kv fn1 "$p")" -v d="$(kv dy "$p")" 'BEGIN { printf "%.6g", f / d }') per unit width), EPS = $(g "$(kv eps "$p")"); counts shown at CKSI = $(g "$mid_cksi"); ${fx_note[$case_name]}.")
done

if [[ $grid_mode == exact ]]; then
  grid_text="rollbem's grid is CONTACT's: \`[mesh] contact_x = [XC1 − DX/2, XC1 + (MX − 1/2)·DX]\`, \`contact_elements = MX\` (node i is CONTACT's element i + 1)."
else
  grid_text="GRID=centred: rollbem's grid has CONTACT's element count and size but is centred on x = 0 (\`contact_half_width = MX·DX/2\`), shifted from CONTACT's unless its span is symmetric; tractions are compared only where the grids coincide."
fi
{
  echo "| input | elements | cases | rollbem solver | max\\|FX_rollbem − FX_CONTACT\\| / (μ FN) | contact elements rollbem / CONTACT | stick elements rollbem / CONTACT | creepages with equal counts | max\\|p_rollbem − p_CONTACT\\| / max p | max\\|q_rollbem − q_CONTACT\\| / max p (worst CKSI) | CPU rollbem [s] | CPU CONTACT [s] | ratio rollbem ÷ CONTACT | CPU rollbem warm [s] | CPU CONTACT warm (I = 3) [s] | ratio warm ÷ warm | peak memory rollbem, cold [MB] | peak memory CONTACT, cold [MB] | peak memory rollbem, warm [MB] | peak memory CONTACT, warm (I = 3) [MB] |"
  echo "|---|---:|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
  printf '%s\n' "${rows[@]}"
  echo
  echo "Inputs: CONTACT's examples/carter2d.inp and perfc_test/carter2d_100.inp, carter2d_800.inp (steady rolling of two identical half-planes, G = 82 000, ν = 0.28, profile x²/(2·500), μ = 0.3, FN = 35 780 on a strip DY = 200 wide: 178.9 per unit width). rollbem: \`[wheel] model = \"half_plane\"\`, \`profile = \"parabola\"\` (CONTACT's IBASE 1 and 2 both give h = x²/(2R)), E = 2G(1 + ν), \`[counter_body] kind = \"half_plane\"\` of the same material, \`coupling = false\`, \`normal_load = FN/DY\`, \`[rolling] mode = \"steady\"\`, \`direction = +1\` (CHI = 0), creepage = CKSI (the same sign convention: CKSI > 0 is braking, FX < 0 on body 1; rollbem's Q on the wheel likewise). $grid_text"
  if [[ $section == strip ]]; then
    echo "Model: both programs solve the same discrete problem, CONTACT's model of a 2D case: one row of elements DX × DY on two elastic half-spaces, displacements at the strip's centre line (rollbem \`[mesh] strip_width = DY\`)."
  else
    echo "Model: SECTION=plane_strain: rollbem in plane strain against CONTACT's strip DY wide, a model difference of order (a/DY)² in the tractions."
  fi
  [[ -n ${CONTACT_DY_SCALE:-} ]] && echo "CONTACT_DY_SCALE=$CONTACT_DY_SCALE: CONTACT's results (the comparison columns) were computed on a strip $CONTACT_DY_SCALE times as wide (DY and FN scaled: the same pressure)$([[ $section == strip ]] && echo ", and rollbem's strip likewise"); its timed runs on the inputs as they are."
  [[ -n ${CONTACT_EPS:-} ]] && echo "CONTACT_EPS=$CONTACT_EPS: CONTACT's results (the comparison columns) were computed with EPS = $CONTACT_EPS and MAXGS = MAXIN = 9999; its timed runs with the inputs' own EPS."
  echo "Compared: FX per case (all cases of the input; CONTACT's FX = Σ PX·DX·DY from its Matlab files); contact (adhesion + slip) and stick (adhesion) element counts at every distinct creepage (equal counts: both equal), shown at the middle creepage; nodal tractions p, q at every distinct creepage (rollbem \`run\`), the largest difference over the curve relative to CONTACT's peak pressure. CONTACT's output is from a copy of each input with O = 2 and A = 1 in every case (its printed case 1 equals the timed run's)."
  echo "Times: CPU (user + sys) and peak RSS of the whole process (GNU time), pinned to core $cpu (taskset), median of $pairs runs alternating rollbem and CONTACT. rollbem: \`rollbem sweep\` of the input's creepages in its order (carter2d_100: its 50 creepages 20 times, one process, one model built once, as CONTACT builds its influence coefficients once), RAYON_NUM_THREADS=1; cold: every case from scratch (the default), warm: \`warm_start = true\` (each case from the previous case's solution). CONTACT: \`contact_linux64 2 INPUT\` on the input (cold: every case from zero tractions, I = 0) and, warm, on a copy whose cases after the first have I = 3 (start from the previous case's tractions and element division)."
  echo "Versions: $rollbem_version; CONTACT $contact_rev, commit $contact_commit, built with $gfortran_version. **CONTACT build measured: $contact_build.** CONTACT's solvers here: NORM by NormCG, TANG by SteadyGS (T = 3), tolerance EPS as noted per input."
  echo "Machine: $(nproc) cores, shared; load average $load_start at the start, $(loadavg) at the end (other work inflates times, CONTACT's and rollbem's alike)."
  echo "CONTACT build checked against its reference output before timing (contact_refcmp.py): ${contact_ref_summary[*]}"
  for note in "${notes[@]}"; do echo "Note: $note"; done
  if [[ ${EXAMPLES:-1} == 1 ]]; then
    echo
    echo "### CONTACT's four 2D examples, case by case (benches/peer/contact_examples.py)"
    echo
    say "CONTACT's examples carter2d, bentall, visc_cylindr, veldep_fric beside rollbem"
    python3 "$here/contact_examples.py" "$contact_bin" "$contact_src/examples" "$rollbem" "$work/examples" $veldep_example ||
      die "contact_examples.py failed"
  fi
} | tee "$table_out"
