#!/usr/bin/env bash
# How CONTACT's answer on examples/carter2d.inp approaches the exact discrete one as its tolerance EPS is tightened,
# against rollbem on the same discrete problem (`[mesh] strip_width = DY`) and an independent 40-digit solve of its
# normal problem (strip_reference.py). Not part of CI. See benches/peer/README.md, "CONTACT's tolerance".
#
# Usage: bash benches/peer/contact_eps.sh KEEP_DIR [TABLE.md]
#   KEEP_DIR  the work folder of a `KEEP=KEEP_DIR bash benches/peer/contact.sh ...` run (SECTION=strip, the default,
#             with carter2d among CASES): its CONTACT build, CONTACT's results input of carter2d and rollbem's scene
#   env EPS_LADDER="1e-5 1e-6 1e-7 1e-8 1e-9 1e-10"   the tolerances; MAXGS = MAXIN = 9999 (CONTACT's largest)
#       ROLLBEM=PATH   the rollbem binary (default: target/release/rollbem)
#       CONTACT_BIN=PATH   CONTACT's executable (default: the one KEEP_DIR's run built)
#       PYTHON=python3 with mpmath (pip install mpmath)
set -euo pipefail
[[ $# -ge 1 && $# -le 2 ]] || { echo "usage: $0 KEEP_DIR [TABLE.md]" >&2; exit 2; }
keep=$(cd "$1" && pwd)
table_out=${2:-/dev/stdout}
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
rollbem=${ROLLBEM:-$root/target/release/rollbem}
python=${PYTHON:-python3}
ladder=${EPS_LADDER:-"1e-5 1e-6 1e-7 1e-8 1e-9 1e-10"}
contact=${CONTACT_BIN:-$keep/contact-build/bin/contact_linux64}
inp=$keep/carter2d/results/carter2d.inp
scene=$keep/carter2d/rollbem/run-1.toml
for f in "$contact" "$inp" "$scene" "$rollbem"; do [[ -e $f ]] || { echo "missing $f" >&2; exit 1; }; done
grep -q '^strip_width' "$scene" || { echo "$scene is not posed on CONTACT's strip (run contact.sh with SECTION=strip)" >&2; exit 1; }
command -v jq >/dev/null || { echo "needs jq" >&2; exit 1; }
export LC_ALL=C
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# Which build this is (MKL or not), for the table: contact_build.sh's look at the executable.
contact_mkl=0
# shellcheck source=benches/peer/contact_build.sh
source "$here/contact_build.sh"
contact_build_line "$contact"

# The scene's numbers (the script's reference and the comparison use them, not carter2d's as printed).
key() { awk -F' *= *' -v k="$1" '$1 == k { print $2; exit }' "$scene"; }
dy=$(key strip_width)
mu=$(key friction)
fn=$(key normal_load)
nel=$(key contact_elements)
dx=$(key contact_x | tr -d '[],' | awk -v n="$nel" '{ printf "%.17g", ($2 - $1) / n }')
"$python" "$here/strip_reference.py" "$dy" >"$work/reference.json"
"$rollbem" run "$scene" --json "$work/rollbem.json" >/dev/null
jq -r '.runs[0].nodes[] | "\(.pressure) \(.shear)"' "$work/rollbem.json" >"$work/rollbem.pq"
[[ $(wc -l <"$work/rollbem.pq") -eq 55 ]] || { echo "the scene is not carter2d's 55 elements" >&2; exit 1; }
jq -r '.p[]' "$work/reference.json" >"$work/reference.p"

{
  echo "| CONTACT EPS | NormCG iterations per call | max\\|p_CONTACT − p_exact\\| / max p | elements 6–46 only | max\\|p_rollbem − p_exact\\| / max p | max\\|q_CONTACT − q_rollbem\\| / max p | \\|FX_CONTACT − FX_rollbem\\| / (μ FN) |"
  echo "|---|---:|---:|---:|---:|---:|---:|"
  for eps in $ladder; do
    d=$work/eps$eps
    mkdir -p "$d"
    # EPS and MAXGS = MAXIN = 9999; the flow digit W at least 5, so that every NormCG call prints its iterations.
    awk -v eps="$eps" -v digits="W>5" -f "$here/contact_inp.awk" "$inp" >"$d/carter2d.inp"
    (cd "$d" && "$contact" 2 carter2d.inp >stdout.txt 2>&1) || { echo "CONTACT failed at EPS $eps" >&2; exit 1; }
    # Iterations per NormCG call (one call per change of NORM's element division), as printed at W >= 5.
    itcg=$(awk '/NormCG: *[0-9]+ iterations/ { sub(/.*NormCG: */, ""); split($0, a, " "); s = s (s == "" ? "" : " + ") a[1] }
      END { print s }' "$d/carter2d.out")
    # CONTACT's Matlab file: per element I, IGS, ..., PN (column 5), PX (column 6).
    awk '/^% +I +IGS/ { body = 1; next } body == 1 && NF >= 6 && $1 ~ /^[0-9]+$/ { print $1, $5, $6 }' \
      "$d/carter2d.0001.mat" >"$d/contact.pq"
    # Signed shear and force: CONTACT's PX and rollbem's q are both the traction on body 1, the wheel (README,
    # "Signs"), so a sign error shows.
    row=$(awk -v dx="$dx" -v mu="$mu" -v fn="$fn" '
      FILENAME == ARGV[1] { pe[FNR] = $1; if ($1 > pm) pm = $1; next }
      FILENAME == ARGV[2] { pr[FNR] = $1; qr[FNR] = $2; fr += $2 * dx; next }
      { pc[$1] = $2; qc[$1] = $3; fc += $3 }
      END {
        for (i = 1; i <= 55; i++) {
          a = pc[i] - pe[i]; if (a < 0) a = -a; if (a > m1) m1 = a
          if (i >= 6 && i <= 46 && a > m2) m2 = a
          b = pr[i] - pe[i]; if (b < 0) b = -b; if (b > m3) m3 = b
          c = qc[i] - qr[i]; if (c < 0) c = -c; if (c > m4) m4 = c
        }
        f = fc * dx - fr; if (f < 0) f = -f
        printf "%.2e | %.2e | %.1e | %.2e | %.1e", m1 / pm, m2 / pm, m3 / pm, m4 / pm, f / (mu * fn)
      }' "$work/reference.p" "$work/rollbem.pq" "$d/contact.pq")
    echo "| $eps | $itcg | $row |"
  done
  echo
  echo "Input: CONTACT's examples/carter2d.inp (55 elements, DY = $dy, CKSI = −0.00024), its results variant from $keep, with EPS as listed, MAXGS = MAXIN = 9999 (CONTACT refuses more: each NormCG call stops there) and the flow digit W = 5 (NormCG's iterations printed per call). p_exact: benches/peer/strip_reference.py, the normal problem in 40-digit arithmetic. rollbem: \`rollbem run\` of the same scene, \`[mesh] strip_width = $dy\`, solver active_set. CONTACT prints 6 significant digits: 4.4e-6 of max p is its print resolution at the peak. FX_CONTACT = Σ PX·DX from its Matlab file (also 6 digits)."
  echo "Versions: $("$rollbem" --version); CONTACT $(awk '/Revision/ { for (i = 1; i <= NF; i++) if ($i == "$Revision:") print $(i + 1); exit }' "$work/eps${ladder%% *}/carter2d.out"). **CONTACT build measured: $contact_build.**"
} >"$table_out"
