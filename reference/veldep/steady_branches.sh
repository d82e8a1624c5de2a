#!/bin/sh
# CONTACT's steady solutions of veldep_fric.inp's problem from both starts, at the issue's two creepages, for the
# exponential law (veldep_fric.inp's own, L = 4) and the rational law (its commented alternative, L = 3):
# 2 laws x 2 creepages (CKSI = -0.001, -0.0009999) x 2 starts (INISLP = +1 from below, -1 from above), every case
# case 1 of veldep_fric.inp with those three values changed; then the exponential law with friction memory (MEMDST =
# 0.003 mm, MEM_S0 = 1 mm/s, the user guide's example values) at both creepages from both starts (cases 9-12).
# Runs the CONTACT build given (default: the MKL build of
# r2707 on this machine) and writes reference/veldep/steady_branches.csv (CONTACT's printed figures, nothing
# computed by rollbem).
#
# Usage: sh reference/veldep/steady_branches.sh [path/to/contact_linux64]
set -eu
exe=${1:-/work/scratch-contact/run3d/contact-build/bin/contact_linux64}
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
inp="$work/branches.inp"
: > "$inp"
for law in exponential rational memory; do
  for cksi in -0.001 -0.0009999; do
    for inislp in 1 -1; do
      case $law in
        exponential) l=4; line="   0.180    0.120      100.    0.0     0.0     FKIN, FEXP1, SABSH1, FE2, SH2" ;;
        rational)    l=3; line="   0.180    0.060      100.    0.060   0.3162  FKIN, FRAT1, SABSH1, FR2, SH2" ;;
        memory)      l=4; line="   0.180    0.120      100.    0.0     0.0     FKIN, FEXP1, SABSH1, FE2, SH2" ;;
      esac
      memdst="0.000"; [ $law = memory ] && memdst="0.003"
      cat >> "$inp" <<CASE
% $law law, CKSI = $cksi, INISLP = $inislp
 3  MODULE
  203100     P-B-T-N-F-S   PVTIME, BOUND , TANG  , NORM  , FORCE , STRESS
  ${l}22020     L-D-C-M-Z-E   FRCLAW, DISCNS, INFLCF, MATER , RZNORM, EXRHS
 0201331   H-G-I-A-O-W-R   HEAT, GAUSEI, IESTIM, MATFIL, OUTPUT, FLOW, RETURN
  5000  2000    30      1     1e-7             MAXGS, MAXIN, MAXNR, MAXOUT, EPS
    0.5   1.0     $inislp    1.1                     OMEGAH, OMEGAS, INISLP, OMGSLP
 622216.   $cksi 0.000    0.000           FN, CKSI, CETA, CPHI
$line
   $memdst    1.000                              MEMDST, MEM_S0
   0.000    0.100    45000.                    CHI, DQ, VELOC
   0.280    0.280    82000.   82000.           POISS 1,2,  GG 1,2
    3                                          IPOTCN
  92   1   -4.600    0.000    0.100    200.0   MX,MY,XC1,YC1,DX,DY
       2           1                           IBASE, IPLAN
       2    0.000    460.0   -10.00    20.00   NN,XM,RX1,Y1,DY1
   0.000    0.000

CASE
    done
  done
done
echo " 0  MODULE" >> "$inp"
(cd "$work" && "$exe" 2 branches > branches.log 2>&1) || { cat "$work/branches.log"; exit 1; }
python3 - "$work/branches.out" > "$here/steady_branches.csv" <<'PY'
import re, sys
text = open(sys.argv[1], encoding="latin-1").read()
parts = re.split(r"^ Case +(\d+)\s*$", text, flags=re.M)
print("case,law,cksi,inislp,fx_fstat_fn,ncon,nadh,nslip,memdst")
order = [(law, c, i) for law in ("exponential", "rational", "memory") for c in (-0.001, -0.0009999) for i in (1, -1)]
for k in range(1, len(parts), 2):
    case, body = int(parts[k]), parts[k + 1]
    law, cksi, inislp = order[case - 1]
    fx = re.search(r"FN/G\s+FX/FSTAT/FN.*\n\s*(\S+)\s+(\S+)", body).group(2)
    stats = re.search(r"NPOT\s+NCON\s+NADH\s+NSLIP.*\n\s*(\d+)\s+(\d+)\s+(\d+)\s+(\d+)", body).group(2, 3, 4)
    memdst = 0.003 if law == "memory" else 0.0
    law = "exponential" if law == "memory" else law
    print(f"{case},{law},{cksi:.7g},{inislp},{fx},{','.join(stats)},{memdst}")
PY
cat "$here/steady_branches.csv"
