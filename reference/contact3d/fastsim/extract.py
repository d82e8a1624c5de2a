#!/usr/bin/env python3
"""Extract CONTACT's FASTSIM reference data for rollbem's tests/fastsim.rs (see README.md in this folder).

Usage: python3 extract.py fastsim|tractcurv CONTACT_SRC RUN_DIR OUT_DIR

CONTACT_SRC: CONTACT's source tree (examples/NAME.inp, examples/NAME.ref_out).
RUN_DIR:     a folder where CONTACT was run on a copy of examples/NAME.inp with the Matlab-file digit A raised to 1
             in every case (benches/peer/contact_ref3d.py's raise_matfile_digit), so that it wrote NAME.CASE.mat.
OUT_DIR:     where the CSVs are written: fastsim_cases.csv and fastsim_caseK_elements.csv (K = 2, 3, 4), or
             tractcurv_fastsim_cases.csv (tractcurv's cases 61-90, original FASTSIM) and tractcurv_exact_cases.csv
             (its cases 1-30, the exact half-space).

The printed totals are read from the author's NAME.ref_out; the flexibilities and the grid to six digits and the
per-element results from the run's .mat files. Standard library only.
"""
import csv
import os
import re
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "benches", "peer"))
import contact_ref3d as c  # noqa: E402  (parse_mat)


def printed_cases(path):
    """Per case: the printed FLX1-3, FN FX FY MZ ELAST.EN FRIC.POWER, FY/FSTAT/FN, PMAX, NPOT NCON NADH NSLIP."""
    cases, case = {}, None
    lines = open(path, encoding="latin-1").read().split("\n")
    for i, line in enumerate(lines):
        m = re.match(r"^ Case +(\d+)\s*$", line)
        if m:
            case = cases.setdefault(int(m.group(1)), {})
        elif case is None:
            continue
        elif re.match(r"^ +FLX1 +FLX2 +FLX3", line):
            case["flx"] = lines[i + 1].split()
        elif re.match(r"^ +FN +FX +FY +MZ", line):
            case["forces"] = lines[i + 1].split()
        elif re.match(r"^ +FN/G +FX/FSTAT/FN", line):
            case["relative"] = lines[i + 1].split()
        elif re.match(r"^ +NPOT +NCON", line):
            case["counts"] = lines[i + 1].split()
        elif re.match(r"^ +TANG: STEADY STATE ROLLING BY", line) or re.match(r"^ TANG:", line):
            case["method"] = line.strip()
    return cases


def mat_header(path):
    """The grid (MX MY XL YL DX DY) and the flexibilities FLX1-3 as written in a .mat file (six digits)."""
    text = open(path, encoding="latin-1").read().split("\n")
    out = {}
    for i, line in enumerate(text):
        if re.match(r"^%\s+MX\s+MY\s+XL", line):
            v = text[i + 1].split()
            out.update(mx=v[0], my=v[1], xl=v[2], yl=v[3], dx=v[4], dy=v[5])
        elif re.match(r"^%\s+T\s+M\s+GG1", line):
            v = text[i + 1].split()
            out.update(flx1_mat=v[5], flx2_mat=v[6], flx3_mat=v[7])
    return out


def tractcurv(src, run, out, first=61, name="tractcurv_fastsim_cases.csv"):
    """tractcurv.inp's third series (cases 61-90): original FASTSIM (M = 3, B = 3, K0_MF = ALFAMF = 1), Coulomb's
    law with FSTAT = FKIN = 0.33, ellipse from IPOTCN = -2 (A1 = 0.0008/mm, a/b = 0.5, FN = 106.7 kN), 48 x 44;
    or (first = 1) its first series, cases 1-30: the exact half-space (M = 0) on the same grid, Coulomb's law."""
    lines = open(os.path.join(src, "examples", "tractcurv.ref_out"), encoding="latin-1").read().split("\n")
    printed, case = {}, None
    for i, line in enumerate(lines):
        m = re.match(r"^ Case +(\d+)\s*$", line)
        if m:
            # A case that keeps the previous geometry (D = 0) does not print it again: carry it forward.
            keep = {k: case[k] for k in ("a", "b") if case and k in case}
            case = printed.setdefault(int(m.group(1)), keep)
        elif case is None:
            continue
        elif re.match(r"^ +BASIC SEMIAXES AA,BB, RATIO", line):
            case.update(a=line.split()[-3], b=line.split()[-2])
        elif re.match(r"^ +CHI +DQ +VELOC +CKSI", line):
            v = lines[i + 1].split()
            case.update(dq=v[1], xi=v[3], eta=v[4], phi=v[5])
        elif re.match(r"^ +FLX1 +FLX2 +FLX3", line):
            case.update(zip(["flx1", "flx2", "flx3"], lines[i + 1].split()))
        elif re.match(r"^ +FN +FX +FY +MZ", line):
            case.update(zip(["fn", "fx", "fy", "mz"], lines[i + 1].split()))
        elif re.match(r"^ +FN/G +FX/FSTAT/FN", line):
            v = lines[i + 1].split()
            case.update(fx_rel=v[1], pmax=v[4])
        elif re.match(r"^ +NPOT +NCON", line):
            case.update(zip(["ncon", "nadh", "nslip"], lines[i + 1].split()[1:4]))
    header = ["case", "mx", "my", "scale", "xl", "yl", "dx", "dy", "a", "b", "dq", "fn_input", "xi", "eta", "phi",
              "mu", "g", "nu", "flx1", "flx2", "flx3", "flx1_mat", "flx2_mat", "flx3_mat", "fx", "fy", "mz",
              "fx_rel", "pmax", "ncon", "nadh", "nslip"]
    with open(os.path.join(out, name), "w", newline="") as fh:
        w = csv.writer(fh, lineterminator="\n")
        w.writerow(header)
        for k in range(first, first + 30):
            p = printed[k]
            m = mat_header(os.path.join(run, f"tractcurv.{k:04d}.mat"))
            if first == 1:
                # The exact theory has no flexibilities.
                m.update(flx1_mat="", flx2_mat="", flx3_mat="")
            w.writerow([k, m["mx"], m["my"], 1.1, m["xl"], m["yl"], m["dx"], m["dy"], p["a"], p["b"], p["dq"],
                        106700.0, p["xi"], p["eta"], p["phi"], 0.33, 82000.0, 0.28, p.get("flx1", ""), p.get("flx2", ""), p.get("flx3", ""),
                        m["flx1_mat"], m["flx2_mat"], m["flx3_mat"], p["fx"], p["fy"], p["mz"], p["fx_rel"],
                        p["pmax"], p["ncon"], p["nadh"], p["nslip"]])


def main():
    which, src, run, out = sys.argv[1:5]
    if which == "tractcurv":
        tractcurv(src, run, out)
        tractcurv(src, run, out, first=1, name="tractcurv_exact_cases.csv")
        return
    ref = printed_cases(os.path.join(src, "examples", "fastsim.ref_out"))
    # The inputs (examples/fastsim.inp): per case, CONTACT's M and B digits, the grid and the kinematics.
    spec = {
        1: ("exact half-space (M=0, B=0)", "hertz", 44, 0.0, 0.4, 0.000625),
        2: ("fastsim (M=3)", "parabolic", 44, 0.0, 0.4, 0.000625),
        3: ("fastsim (M=3)", "elliptic", 44, 0.0, 0.4, 0.000625),
        4: ("fastrip (M=5)", "elliptic", 44, 0.0, 0.4, 0.000625),
        5: ("fastsim (M=3)", "parabolic", 220, 0.0, 0.08, 0.000625),
        6: ("fastsim (M=3)", "elliptic", 220, 0.0, 0.08, 0.000625),
        7: ("fastrip (M=5)", "elliptic", 220, 0.0, 0.08, 0.000625),
        8: ("fastsim (M=3)", "parabolic", 220, 180.0, 0.08, -0.000625),
    }
    header = ["case", "method", "bound", "mx", "my", "a", "b", "scale", "chi_deg", "dq", "fn", "xi", "eta", "phi",
              "mu", "g", "nu", "flx1", "flx2", "flx3", "flx1_mat", "flx2_mat", "flx3_mat", "fx", "fy", "mz",
              "fy_rel", "pmax", "ncon", "nadh", "nslip"]
    rows = []
    for k, (method, bound, m, chi, dq, phi) in spec.items():
        p = ref[k]
        flx = p.get("flx", ["", "", ""])
        flx_mat = ["", "", ""]
        mat = os.path.join(run, f"fastsim.{k:04d}.mat")
        text = open(mat, encoding="latin-1").read().split("\n")
        for i, line in enumerate(text):
            if re.match(r"^%\s+T\s+M\s+GG1", line):
                v = text[i + 1].split()
                flx_mat = v[5:8] if v[1] in ("3", "5") else ["", "", ""]
        f, r, n = p["forces"], p["relative"], p["counts"]
        rows.append([k, method, bound, m, m, 8.0, 4.0, 1.1, chi, dq, 82000.0, 0.0, -0.000625, phi, 0.3, 82000.0, 0.28,
                     *flx, *flx_mat, f[1], f[2], f[3], r[2], r[4], n[1], n[2], n[3]])
    with open(os.path.join(out, "fastsim_cases.csv"), "w", newline="") as fh:
        w = csv.writer(fh, lineterminator="\n")
        w.writerow(header)
        w.writerows(rows)
    for k in (2, 3, 4):
        grid, elems = c.parse_mat(os.path.join(run, f"fastsim.{k:04d}.mat"))
        with open(os.path.join(out, f"fastsim_case{k}_elements.csv"), "w", newline="") as fh:
            w = csv.writer(fh, lineterminator="\n")
            w.writerow(["ix", "iy", "state", "pn", "px", "py"])
            for e in elems:
                i = int(e["I"])
                state = {"0": "exterior", "1": "adhesion", "2": "slip"}[e["IGS"]]
                w.writerow([(i - 1) % grid["MX"] + 1, (i - 1) // grid["MX"] + 1, state, e["PN"], e["PX"], e["PY"]])


if __name__ == "__main__":
    main()
