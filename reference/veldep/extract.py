#!/usr/bin/env python3
"""Extract CONTACT's printed figures of `examples/veldep_fric.inp` from its reference output.

Usage: python3 reference/veldep/extract.py PATH/TO/veldep_fric.ref_out > reference/veldep/veldep_fric_cases.csv

One row per case: the case number, whether it is steady or transient, the creepage CKSI, FX/FSTAT/FN as printed
(4 digits), and NCON, NADH, NSLIP where CONTACT printed its contact statistics (full output), else empty. CKSI
and the start INISLP are read from the input file beside it (`veldep_fric.inp`, the line ending in `FN, CKSI, ...`
and the one holding INISLP), case by case. Nothing is computed: the figures are CONTACT's as printed (r2707's
reference output).
"""
import re
import sys


def main(path):
    text = open(path, encoding="latin-1").read()
    parts = re.split(r"^ Case +(\d+)\s*$", text, flags=re.M)
    inp = open(path.replace(".ref_out", ".inp"), encoding="latin-1").read().splitlines()
    cksis = [float(l.split()[1]) for l in inp if l.rstrip().endswith("FN, CKSI, CETA, CPHI")]
    # "[OMEGAH OMEGAS] INISLP OMGSLP   names": INISLP is the last number but one.
    numbers = lambda l: [t for t in l.split() if re.fullmatch(r"[-+0-9.eE]+", t)]
    inislps = [int(numbers(l)[-2]) for l in inp if "INISLP, OMGSLP" in l]
    print("case,mode,cksi,inislp,fx_fstat_fn,ncon,nadh,nslip")
    for k in range(1, len(parts), 2):
        case, body = int(parts[k]), parts[k + 1]
        mode = "steady" if "STEADY STATE ROLLING" in body else "transient"
        cksi, inislp = cksis[case - 1], inislps[case - 1]
        m = re.search(r"FN/G\s+FX/FSTAT/FN.*\n\s*(\S+)\s+(\S+)", body)
        if not m:
            raise SystemExit(f"case {case}: no FX/FSTAT/FN")
        fx = m.group(2)
        m = re.search(r"NPOT\s+NCON\s+NADH\s+NSLIP.*\n\s*(\d+)\s+(\d+)\s+(\d+)\s+(\d+)", body)
        stats = m.group(2, 3, 4) if m else ("", "", "")
        print(f"{case},{mode},{cksi:.7g},{inislp},{fx},{','.join(stats)}")


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "/work/scratch-contact/src-CONTACT/examples/veldep_fric.ref_out")
