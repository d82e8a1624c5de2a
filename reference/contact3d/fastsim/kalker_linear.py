#!/usr/bin/env python3
"""Kalker's creep coefficients computed by CONTACT's exact half-space solver: inputs and extraction for
reference/contact3d/fastsim/kalker_linear.csv (README.md in this folder).

  python3 kalker_linear.py gen NAME MX MY [SPECS]  writes NAME.inp: steady rolling at vanishing creepage on MX x MY
                                                 elements, one case per (a/b, nu) of SPECS (indices into SPECS
                                                 below, comma-separated; default all) and per creepage xi, eta, phi
  CONTACT_BIN 2 NAME < /dev/null                 (run CONTACT in that folder: writes NAME.out)
  python3 kalker_linear.py csv OUT NAME...       reads NAME.inp and NAME.out of each run, appends rows to OUT

Each case: CONTACT module 3, P-B-T-N-F-S = 2-0-3-1-0-0 (steady rolling, Hertzian normal problem solved by the
half-space model, creepages prescribed), M = 0 (elastic half-spaces, the exact theory), IPOTCN = -3 (semi-axes a, b
prescribed, c = sqrt(ab) = 4 mm), SCALE 1.1, DQ = DX, G = 82000 N/mm^2, FN = 1000 N, FSTAT = FKIN = 1e4 (no slip:
the linear theory), one creepage of 1e-6 (xi, eta) or 1e-6/c (phi). Standard library only.
"""
import csv
import os
import re
import sys

SPECS = [(1.0, 0.25), (0.2, 0.25), (5.0, 0.25), (1.0, 0.0), (1.0, 0.5)]
C = 4.0


def case(a, b, nu, n, m, xi, eta, phi):
    dx = 2.2 * a / n
    return f""" 3 MODULE
  203100     P-B-T-N-F-S
  022020     L-D-C-M-Z-E
 0000141   H-G-I-A-O-W-R
   200   400    5    1      1e-8    MAXGS , MAXIN , MAXNR , MAXOUT, EPS
   1000.     {xi:.6e}     {eta:.6e}   {phi:.6e}        FN, CKSI, CETA, CPHI
   1.0e4      1.0e4                                 FSTAT, FKIN
   0.000      {dx:.10f}      30000.                     CHI, DQ, VELOC
   {nu}      {nu}      82000.     82000.          POISS 1,2,  GG 1,2
   -3                                               IPOTCN
   {n}   {m}     {a:.10f}      {b:.10f}      1.100          MX,MY,AA,BB,SCALE
"""


def gen(name, n, m, specs):
    out = []
    for ab, nu in specs:
        a, b = C * ab ** 0.5, C / ab ** 0.5
        for xi, eta, phi in [(1e-6, 0, 0), (0, 1e-6, 0), (0, 0, 1e-6 / C)]:
            out.append(case(a, b, nu, n, m, xi, eta, phi))
    open(name + ".inp", "w").write("\n".join(out) + "\n 0 MODULE\n")


def read(name):
    inp = open(name + ".inp").read().split("\n")
    cases = []
    for line in inp:
        v = line.split()
        if line.endswith("FN, CKSI, CETA, CPHI"):
            cases.append({"xi": v[1], "eta": v[2], "phi": v[3]})
        elif line.endswith("POISS 1,2,  GG 1,2"):
            cases[-1]["nu"] = v[0]
        elif line.endswith("MX,MY,AA,BB,SCALE"):
            cases[-1].update(mx=v[0], my=v[1], a=v[2], b=v[3])
    lines = open(name + ".out", encoding="latin-1").read().split("\n")
    k = 0
    for i, line in enumerate(lines):
        if re.match(r"^ +Tang: final element division: A, S=", line):
            cases[k]["nslip"] = line.split()[-3]
        if re.match(r"^ +FN +FX +FY +MZ", line):
            v = lines[i + 1].split()
            cases[k].update(fx=v[1], fy=v[2], mz=v[3])
            k += 1
    assert k == len(cases), (name, k, len(cases))
    return cases


def main():
    if sys.argv[1] == "gen":
        specs = SPECS if len(sys.argv) < 6 else [SPECS[int(s)] for s in sys.argv[5].split(",")]
        gen(sys.argv[2], int(sys.argv[3]), int(sys.argv[4]), specs)
    else:
        path = sys.argv[2]
        cols = ["a", "b", "nu", "mx", "my", "xi", "eta", "phi", "nslip", "fx", "fy", "mz"]
        new = not os.path.exists(path)
        with open(path, "a", newline="") as fh:
            w = csv.writer(fh, lineterminator="\n")
            if new:
                w.writerow(cols)
            for name in sys.argv[3:]:
                for c in read(name):
                    w.writerow([c[k] for k in cols])


if __name__ == "__main__":
    main()
