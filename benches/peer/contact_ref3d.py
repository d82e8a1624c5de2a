#!/usr/bin/env python3
"""CONTACT's 3D reference data for rollbem's tests: reference/contact3d/ from CONTACT's own inputs and outputs.

Usage:
  python3 benches/peer/contact_ref3d.py CONTACT_SRC CONTACT_BIN [OUT_DIR]

  CONTACT_SRC  a CONTACT source tree (examples/, perfc_test/, with the author's *.ref_out)
  CONTACT_BIN  a CONTACT executable that reproduces the reference outputs (benches/peer/contact3d.sh builds and
               checks one: KEEP=DIR bash benches/peer/contact3d.sh ..., then DIR/contact-build/bin/contact_linux64)
  OUT_DIR      default reference/contact3d (of this checkout)

What it does, per input (cattaneo, spence35, subsurf from examples/; norm_problm_1p, tang_problm_1s from
perfc_test/):
  1. decodes the .inp (module 3: control digits, solver constants, kinematics, friction, materials, grid,
     profile, subsurface points) into the parameter tables of OUT_DIR/README.md;
  2. runs CONTACT_BIN on a copy of the input whose only change is the Matlab-file digit A raised to 1 in every
     case (A writes CONTACT's per-element results to NAME.CASE.mat; it changes nothing that is computed or printed
     to the .out), checks the .out against the author's NAME.ref_out with contact_refcmp.py (examples) or the
     element counts against perfc_test/get_times.ref_out (perfc_test inputs), and stops if they differ;
  3. writes NAME_cases.csv: per case the totals CONTACT prints, taken from the author's .ref_out for the examples
     (from this run's .out for the perfc_test inputs, which have no .ref_out), the element counts and the largest
     tractions from this run's .mat files;
  4. writes NAME_caseK_elements.csv: the per-element results of selected cases from this run's .mat files (every
     element in contact), and for subsurf the author's subsurface results on the z axis (subsurf.ref_subs).
Python 3 standard library only. Nothing of CONTACT is copied but numbers from its inputs and outputs.
"""

import csv
import math
import os
import re
import shutil
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import contact_refcmp  # noqa: E402

# input name -> (folder in CONTACT's tree, cases whose element tables are written)
INPUTS = {
    "cattaneo": ("examples", [1, 2]),
    "spence35": ("examples", [1, 12, 24, 35]),
    "subsurf": ("examples", [1, 2]),
    "norm_problm_1p": ("perfc_test", [1]),
    "tang_problm_1s": ("perfc_test", [1]),
    "tang_problm_1c": ("perfc_test", [1]),
    "tang_problm_1f": ("perfc_test", [1]),
    "catt_to_cart": ("examples", [1, 2, 57]),
}

NUM = re.compile(r"^[+-]?(\d+\.?\d*|\.\d+)([EeDd][+-]?\d+)?d?$")


class InputError(Exception):
    pass


# ---------------------------------------------------------------------------------------------------------------
# 1. The .inp file (module 3), after CONTACT's user guide (doc/user-guide.tex): "Specification of the input file
#    <experim>.inp", "Module 3 -- basic Hertzian/non-Hertzian contact", and the control integers.


class Reader:
    """Lines of an .inp without comments ('%' to the end of a line) and blank lines; reads the leading numbers of
    successive lines, as CONTACT's line reader does (text after the numbers is a label)."""

    def __init__(self, path):
        self.lines = []
        with open(path, encoding="latin-1") as f:
            for n, line in enumerate(f, 1):
                line = line.split("%")[0].rstrip()
                if line.strip():
                    self.lines.append((n, line))
        self.i = 0

    def line(self):
        if self.i >= len(self.lines):
            raise InputError("unexpected end of input")
        n, line = self.lines[self.i]
        self.i += 1
        return n, line

    def numbers(self, count, what):
        """COUNT values from the leading numbers of the next line(s), for the quantity WHAT."""
        vals = []
        while len(vals) < count:
            n, line = self.line()
            lead = []
            for tok in line.split():
                tok = tok.rstrip(",")
                if NUM.match(tok):
                    lead.append(tok)
                else:
                    break
            if not lead:
                raise InputError(f"line {n}: expected {what}, found '{line.strip()}'")
            vals.extend(lead[: count - len(vals)])
        return [parse_num(t) for t in vals]


def parse_num(tok):
    if tok.endswith("d") and not re.search(r"[Ee]", tok[:-1]):  # CHI in degrees, e.g. 180d
        return math.radians(float(tok[:-1]))
    return float(tok.replace("D", "E").replace("d", "e"))


DEFAULT_LETTERS = ["PBTNFS", "LDCMZE", "XHGIAOWR"]


def control_word(reader, k):
    """Control word K (0, 1, 2) as {letter: digit}: letters from the word's label when it has one (e.g.
    'P-B-T-N-F-S'), else the user guide's order; missing leading digits are 0."""
    n, line = reader.line()
    toks = line.split()
    digits = toks[0]
    if not digits.isdigit():
        raise InputError(f"line {n}: expected control word {k + 1}, found '{line.strip()}'")
    letters = DEFAULT_LETTERS[k]
    if len(toks) > 1 and re.match(r"^[A-Z](-[A-Z0-9]+)+$", toks[1]):
        letters = toks[1].split("-")
    else:
        letters = list(letters)
    if len(digits) > len(letters):
        raise InputError(f"line {n}: {len(digits)} digits for {len(letters)} letters")
    digits = digits.rjust(len(letters), "0")
    return {letter: int(d) for letter, d in zip(letters, digits)}, n


def read_subsurface(reader, case, s_digit):
    """The subsurface input (S = 2: control digits; S = 3: control digits and blocks of points)."""
    a_s, o_s = reader.numbers(2, "MATFIL, OUTPUT of the subsurface calculation")
    case["subs_digits"] = (int(a_s), int(o_s))
    if s_digit != 3:
        return
    blocks = []
    while True:
        (isubs,) = reader.numbers(1, "ISUBS")
        isubs = int(isubs)
        if isubs == 0:
            break
        b = {"ISUBS": isubs}
        if isubs in (2, 6):
            b["IX"] = reader.numbers(3, "IXL, IXINC, IXH")
            b["IY"] = reader.numbers(3, "IYL, IYINC, IYH")
        elif isubs in (3, 7):
            (nx,) = reader.numbers(1, "NX")
            b["IX"] = reader.numbers(int(nx), "IX(:)")
            (ny,) = reader.numbers(1, "NY")
            b["IY"] = reader.numbers(int(ny), "IY(:)")
        if isubs in (1, 2, 3):
            b["Z"] = reader.numbers(3, "NZ, ZL, DZ")
        elif isubs in (5, 6, 7):
            (nz,) = reader.numbers(1, "NZ")
            b["Zlist"] = reader.numbers(int(nz), "Z(:)")
        elif isubs == 9:
            nx, ny, nz = (int(v) for v in reader.numbers(3, "NX, NY, NZ"))
            b["X"] = reader.numbers(nx, "X(:)")
            b["Y"] = reader.numbers(ny, "Y(:)")
            b["Zlist"] = reader.numbers(nz, "Z(:)")
        else:
            raise InputError(f"ISUBS = {isubs} not supported here")
        blocks.append(b)
    case["subs_blocks"] = blocks


def parse_inp(path):
    """The cases of a module-3 input, each a dict of what it reads (values kept from earlier cases are copied,
    as CONTACT keeps them: D = 0, C = 0/1, Z = 0, L = 1, G = 1 'maintain')."""
    r = Reader(path)
    cases = []
    state = {}
    while True:
        (module,) = r.numbers(1, "MODULE")
        if int(module) == 0:
            break
        if int(module) != 3:
            raise InputError(f"module {int(module)}: only module 3 is decoded here")
        c = {"case": len(cases) + 1}
        w1, n1 = control_word(r, 0)
        w2, _ = control_word(r, 1)
        w3, _ = control_word(r, 2)
        c["digits"] = {**w1, **w2, **w3}
        c["words"] = (w1, w2, w3)
        d = c["digits"]
        for letter, bad in (("X", (1,)), ("V", (1, 2, 3)), ("H", (1, 3)), ("M", (1, 2, 3, 4, 5, 6, 7))):
            if d.get(letter, 0) in bad:
                raise InputError(f"case {c['case']}: {letter} = {d[letter]} is not decoded here")
        if d.get("E", 0) == 9 or d.get("C", 0) in (3, 4, 9):
            raise InputError(f"case {c['case']}: E = 9 or C = 3, 4, 9 are not decoded here")
        if d.get("L", 0) not in (0, 1):
            raise InputError(f"case {c['case']}: friction law L = {d['L']} is not decoded here")
        g = d.get("G", 0)
        if g in (0, 2, 3, 4, 5):
            state["solver"] = dict(zip(["MAXGS", "MAXIN", "MAXNR", "MAXOUT", "EPS"], r.numbers(5, "MAXGS ... EPS")))
        if g == 5:
            # GDsteady's parameters (user guide, G = 5): FDECAY, BETATH, KDOWFB, D_IFC, D_LIN, D_CNS, D_SLP, POW_S
            state["gdsteady"] = r.numbers(8, "FDECAY ... POW_S")
        if g in (2, 3):
            state["omegas"] = r.numbers(4, "OMEGAH, OMEGAS, INISLP, OMGSLP")
        if g == 4:
            state["slipit"] = r.numbers(2, "INISLP, OMGSLP")
        kin = r.numbers(4, "kinematics")
        names = ["PEN" if d["N"] == 0 else "FN",
                 "CKSI" if d["F"] == 0 else "FXREL",
                 "FYREL" if d["F"] == 2 else "CETA",
                 "CPHI"]
        c["kinematics"] = dict(zip(names, kin))
        if d["L"] == 0:
            state["friction"] = dict(zip(["FSTAT", "FKIN"], r.numbers(2, "FSTAT, FKIN")))
        if d["C"] >= 2:
            if d["T"] > 1:
                state["rolling"] = dict(zip(["CHI", "DQ", "VELOC"], r.numbers(3, "CHI, DQ, VELOC")))
            state["material"] = dict(zip(["POISS1", "POISS2", "GG1", "GG2"], r.numbers(4, "POISS 1,2, GG 1,2")))
            if d["B"] == 1:
                raise InputError("B = 1 (compressible layer) is not decoded here")
        if d["D"] == 2:
            (ipotcn,) = r.numbers(1, "IPOTCN")
            ipotcn = int(ipotcn)
            grid_names = {
                -1: ["MX", "MY", "A1", "B1", "SCALE"], -2: ["MX", "MY", "A1", "AOB", "SCALE"],
                -3: ["MX", "MY", "AA", "BB", "SCALE"], 1: ["MX", "MY", "XL", "YL", "DX", "DY"],
                2: ["MX", "MY", "XL", "YL", "XH", "YH"], 3: ["MX", "MY", "XC1", "YC1", "DX", "DY"],
                4: ["MX", "MY", "XC1", "YC1", "XCM", "YCM"],
            }
            if ipotcn not in grid_names:
                raise InputError(f"IPOTCN = {ipotcn} is not decoded here")
            vals = r.numbers(len(grid_names[ipotcn]), "the potential contact area")
            state["grid"] = {"IPOTCN": ipotcn, **dict(zip(grid_names[ipotcn], vals))}
            state["grid_case"] = c["case"]
        if d["Z"] > 1 and state["grid"]["IPOTCN"] > 0:
            ibase, iplan = (int(v) for v in r.numbers(2, "IBASE, IPLAN"))
            prof = {"IBASE": ibase, "IPLAN": iplan}
            if ibase == 1:
                prof["B"] = r.numbers(6, "B1 ... B6")
            elif ibase == 2:
                nn, xm, rm, y1, dy1 = r.numbers(5, "NN, XM, RM, Y1, DY1")
                prof.update(NN=int(nn), XM=xm, RM=rm, Y1=y1, DY1=dy1)
                prof["heights"] = r.numbers(int(nn), "profile heights")
            else:
                raise InputError(f"IBASE = {ibase} is not decoded here")
            if iplan != 1:
                raise InputError(f"IPLAN = {iplan} is not decoded here")
            state["profile"] = prof
            state["profile_case"] = c["case"]
        elif d["Z"] > 1:
            state["profile"] = {"IBASE": "Hertz"}
            state["profile_case"] = c["case"]
        if d["S"] in (2, 3):
            read_subsurface(r, c, d["S"])
        for k, v in state.items():
            c[k] = v
        cases.append(c)
    return cases


# ---------------------------------------------------------------------------------------------------------------
# 2. CONTACT's printed output (.out / .ref_out): per case the totals, relative totals, kinematics echo and element
#    counts, by their header lines.

HEADER_FIX = [("SHIFT X", "SHIFT_X"), ("SHIFT Y", "SHIFT_Y"), ("CREEP X", "CREEP_X"), ("CREEP Y", "CREEP_Y")]


def parse_out(path):
    """{case: {name: printed text}} with names as CONTACT prints them (FN, FX, FY, MZ, ELAST.EN., FRIC.WORK or
    FRIC.POWER, FN/G, FX/FSTAT/FN, FY/FSTAT/FN or SHIFT_X, SHIFT_Y, APPROACH, PMAX, NPOT, NCON, NADH, NSLIP, INORM,
    ITANG) and the kinematics echo prefixed 'kin:'; the first occurrence per case."""
    cases = {}
    case = None
    lines = open(path, encoding="latin-1").read().split("\n")
    for i, line in enumerate(lines):
        m = re.match(r"^ Case +(\d+)\s*$", line)
        if m:
            case = int(m.group(1))
            cases[case] = {}
            continue
        if case is None or i + 1 >= len(lines):
            continue
        head = line
        for a, b in HEADER_FIX:
            head = head.replace(a, b)
        names = head.split()
        if not names or names[0] not in ("FN", "FN/G", "NPOT", "DT", "CHI"):
            continue
        if any(NUM.match(n) for n in names):
            continue
        vals = lines[i + 1].split()
        if len(vals) != len(names) or not all(NUM.match(v) for v in vals):
            continue
        prefix = "kin:" if names[0] in ("DT", "CHI") else ""
        for n, v in zip(names, vals):
            cases[case].setdefault(prefix + n, v)
    return cases


# ---------------------------------------------------------------------------------------------------------------
# 3. CONTACT's Matlab file NAME.CASE.mat (user guide, "Specification of the file <experim>.<case>.mat").

MAT_COLS = ["I", "IGS", "H", "MU", "PN", "PX", "PY", "UN", "UX", "UY", "SREL"]


def parse_mat(path):
    """(grid, rows): grid {MX, MY, XL, YL, DX, DY}; rows of the elements written (A = 1: those in contact)."""
    lines = open(path, encoding="latin-1").read().split("\n")
    grid = None
    rows = []
    in_table = False
    for i, line in enumerate(lines):
        if re.match(r"^%\s+MX\s+MY\s+XL", line):
            v = lines[i + 1].split()
            grid = {"MX": int(v[0]), "MY": int(v[1]), "XL": float(v[2]), "YL": float(v[3]),
                    "DX": float(v[4]), "DY": float(v[5])}
        elif re.match(r"^%\s+I\s+IGS", line):
            in_table = True
            cols = line[1:].split()
        elif in_table and line.strip():
            v = line.split()
            row = dict(zip(cols, v))
            rows.append(row)
    if grid is None or not in_table:
        raise InputError(f"{path}: not a CONTACT .mat file")
    return grid, rows


def element_rows(grid, rows):
    """Per element: ix, iy, x, y (centre), state and results as written (six significant digits)."""
    out = []
    for r in rows:
        i = int(r["I"])
        ix = (i - 1) % grid["MX"] + 1
        iy = (i - 1) // grid["MX"] + 1
        x = grid["XL"] + (ix - 0.5) * grid["DX"]
        y = grid["YL"] + (iy - 0.5) * grid["DY"]
        state = {"0": "exterior", "1": "adhesion", "2": "slip"}.get(r["IGS"], r["IGS"])
        last = "SHFT" if "SHFT" in r else "SREL"
        out.append([ix, iy, f"{x:.6g}", f"{y:.6g}", state, r["H"], r["MU"], r["PN"], r["PX"], r["PY"],
                    r["UN"], r["UX"], r["UY"], r.get(last, "")])
    return out


ELEMENT_HEADER = ["ix", "iy", "x", "y", "state", "h", "mu", "pn", "px", "py", "un", "ux", "uy", "shift_or_srel"]

# ---------------------------------------------------------------------------------------------------------------
# 4. Running CONTACT on the input with A >= 1.


def raise_matfile_digit(src, dst):
    """Copy SRC to DST with the A digit (Matlab file) of every case set to at least 1."""
    out = []
    for line in open(src, encoding="latin-1").read().split("\n"):
        body = line.split("%")[0]
        toks = body.split()
        if len(toks) >= 2 and toks[0].isdigit() and re.match(r"^[A-Z](-[A-Z])+$", toks[1]) and "A" in toks[1].split("-"):
            letters = toks[1].split("-")
            digits = toks[0].rjust(len(letters), "0")
            k = letters.index("A")
            if int(digits[k]) < 1:
                digits = digits[:k] + "1" + digits[k + 1:]
            m = re.search(r"\d+", line)
            line = line[: m.start()] + digits + line[m.end():]
        out.append(line)
    open(dst, "w", encoding="latin-1").write("\n".join(out))


def run_contact(binary, name, inp, work):
    d = os.path.join(work, name)
    os.makedirs(d, exist_ok=True)
    raise_matfile_digit(inp, os.path.join(d, name + ".inp"))
    with open(os.path.join(d, "stdout.txt"), "w") as so:
        subprocess.run([binary, "2", name], cwd=d, stdin=subprocess.DEVNULL, stdout=so, stderr=subprocess.STDOUT,
                       check=True)
    return d


def perfc_counts(src, name):
    text = open(os.path.join(src, "perfc_test", "get_times.ref_out"), encoding="latin-1").read()
    m = re.search(r"^" + re.escape(name) + r"\s*:\s*(ncon|nslp)=\s*(\d+),\s*(ItCG|ItGS)=\s*(\d+)", text, re.M)
    if not m:
        raise InputError(f"{name} is not in perfc_test/get_times.ref_out")
    return m.group(1), int(m.group(2)), int(m.group(4))


# ---------------------------------------------------------------------------------------------------------------
# 5. The files.

CASE_COLUMNS = [
    ("case", "case number"),
    ("problem", "T digit: frictionless (T=0), shift (T=1), steady rolling (T=3)"),
    ("prescribed", "what the case prescribes (N and F digits) with its value as read from the input"),
    ("fn", "FN, total normal force on body 1 [N] (printed)"),
    ("fx", "FX, total tangential force on body 1 in x [N] (printed)"),
    ("fy", "FY, likewise in y [N] (printed)"),
    ("mz", "MZ, torsional moment about the z axis [N mm] (printed)"),
    ("elastic_energy", "ELAST.EN., elastic energy [N mm] (printed)"),
    ("fric_work", "FRIC.WORK (shift, T=1: frictional work in the step [N mm]) or FRIC.POWER (rolling [N mm/s]) (printed)"),
    ("fn_over_g", "FN/G, FN divided by the combined modulus of rigidity G [mm^2] (printed)"),
    ("fx_rel", "FX/(FSTAT FN) (printed; empty when the case prescribes it and CONTACT prints the shift or creepage it found instead)"),
    ("fy_rel", "FY/(FSTAT FN) (printed; likewise)"),
    ("shift_x", "SHIFT X: the rigid shift CKSI CONTACT found for a prescribed FX [mm] (printed when F >= 1 in a shift)"),
    ("shift_y", "SHIFT Y: likewise CETA [mm]"),
    ("creep_x", "CREEP X: the creepage CKSI CONTACT found for a prescribed FX in rolling (printed when F >= 1, T = 3)"),
    ("creep_y", "CREEP Y: likewise CETA"),
    ("approach", "APPROACH, the approach PEN of the bodies [mm] (printed; prescribed when N=0)"),
    ("pmax", "PMAX, the largest pressure [N/mm^2] (printed)"),
    ("npot", "NPOT, elements of the potential contact area (printed at output level O >= 2)"),
    ("ncon", "NCON, elements in contact (printed at O >= 2)"),
    ("nadh", "NADH, elements in adhesion (stick) (printed at O >= 2)"),
    ("nslip", "NSLIP, elements in slip (printed at O >= 2)"),
    ("inorm", "INORM, outer iterations of the normal problem (printed at O >= 2)"),
    ("itang", "ITANG, outer iterations of the tangential problem (printed at O >= 2)"),
    ("ncon_mat", "elements in contact in this run's .mat file (every case)"),
    ("nadh_mat", "elements in adhesion in this run's .mat file"),
    ("nslip_mat", "elements in slip in this run's .mat file"),
    ("pn_max_mat", "largest pn in this run's .mat file [N/mm^2] (six digits)"),
    ("pt_max_mat", "largest |(px, py)| in this run's .mat file [N/mm^2]"),
    ("source_printed", "where the printed columns come from: the author's .ref_out, or this run's .out"),
]
PRINTED = {"fn": "FN", "fx": "FX", "fy": "FY", "mz": "MZ", "elastic_energy": "ELAST.EN.", "fn_over_g": "FN/G",
           "fx_rel": "FX/FSTAT/FN", "fy_rel": "FY/FSTAT/FN", "shift_x": "SHIFT_X", "shift_y": "SHIFT_Y", "creep_x": "CREEP_X", "creep_y": "CREEP_Y",
           "approach": "APPROACH", "pmax": "PMAX", "npot": "NPOT", "ncon": "NCON", "nadh": "NADH",
           "nslip": "NSLIP", "inorm": "INORM", "itang": "ITANG"}
TANG = {0: "frictionless compression (T=0)", 1: "shift (T=1)", 2: "transient rolling (T=2)",
        3: "steady rolling (T=3)"}


def prescribed(c):
    d = c["digits"]
    k = c["kinematics"]
    parts = []
    parts.append(f"FN = {k['FN']:g} N" if d["N"] == 1 else f"PEN = {k['PEN']:g} mm")
    if d["T"] == 0:
        return "; ".join(parts)
    unit = "mm" if d["T"] == 1 else ""
    if d["F"] == 0:
        parts.append(f"CKSI = {k['CKSI']:g}{(' ' + unit) if unit else ''}")
    else:
        parts.append(f"FX/(FSTAT FN) = {k['FXREL']:g}")
    if d["F"] == 2:
        parts.append(f"FY/(FSTAT FN) = {k['FYREL']:g}")
    else:
        parts.append(f"CETA = {k['CETA']:g}{(' ' + unit) if unit else ''}")
    parts.append(f"CPHI = {k['CPHI']:g} {'rad' if d['T'] == 1 else 'rad/mm'}")
    return "; ".join(parts)


def write_cases(path, cases, printed, mats, source):
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow([c for c, _ in CASE_COLUMNS])
        for c in cases:
            k = c["case"]
            p = printed.get(k, {})
            row = [k, TANG[c["digits"]["T"]], prescribed(c)]
            for col, _ in CASE_COLUMNS[3:-6]:
                if col == "fric_work":
                    row.append(p.get("FRIC.WORK", p.get("FRIC.POWER", "")))
                else:
                    row.append(p.get(PRINTED[col], ""))
            rows = mats.get(k, [])
            ncon = sum(1 for r in rows if r["IGS"] in ("1", "2"))
            nadh = sum(1 for r in rows if r["IGS"] == "1")
            nslip = sum(1 for r in rows if r["IGS"] == "2")
            pn = max((float(r["PN"]) for r in rows), default=0.0)
            pt = max((math.hypot(float(r["PX"]), float(r["PY"])) for r in rows), default=0.0)
            row += [ncon, nadh, nslip, f"{pn:.6g}", f"{pt:.6g}", source]
            w.writerow(row)


def combined(m):
    """CONTACT's combined material constants (user guide eq. combined_mater): G, nu, K."""
    g1, g2, n1, n2 = m["GG1"], m["GG2"], m["POISS1"], m["POISS2"]
    g = 1.0 / (0.5 * (1 / g1 + 1 / g2))
    nu = g * 0.5 * (n1 / g1 + n2 / g2)
    k = g * 0.25 * ((1 - 2 * n1) / g1 - (1 - 2 * n2) / g2)
    return g, nu, k


def fmt(v):
    return f"{v:.6g}"


def dedup(items):
    """[(case, value)] without values equal to the previous one's."""
    out = []
    for k, v in items:
        if not out or out[-1][1] != v:
            out.append((k, v))
    return out


def hertz_printed(ref_text, case):
    """CONTACT's printed Hertz data of a case with IPOTCN < 0: curvatures A1, B1."""
    m = re.search(r"THE CURVATURES A1,B1 ARE:\s+(\S+)\s+(\S+)", ref_text)
    return (m.group(1), m.group(2)) if m else None


def describe(name, folder, cases, grids, out_text):
    """The README section of one input: its parameters, decoded."""
    L = []
    L.append(f"### {name} (`{folder}/{name}.inp`, {len(cases)} case{'s' if len(cases) > 1 else ''})")
    L.append("")
    L.append("| case | P-B-T-N-F-S | L-D-C-M-Z-E | (H-)G-I-A-O-W-R | problem | prescribed |")
    L.append("|---:|---|---|---|---|---|")
    for c in cases:
        w = ["".join(str(v) for v in word.values()) for word in c["words"]]
        L.append(f"| {c['case']} | {w[0]} | {w[1]} | {w[2]} | {TANG[c['digits']['T']]} | {prescribed(c)} |")
    L.append("")
    L.append("Digits as read (left-padded with zeros to the letters of their label); a case whose D, C, Z, L or G "
             "digit says 'keep' uses what an earlier case read.")
    L.append("")
    for k, g in dedup([(c["case"], c["grid"]) for c in cases if c["digits"]["D"] == 2]):
        gm = grids[k]
        span = (f"[{fmt(gm['XL'])}, {fmt(gm['XL'] + gm['MX'] * gm['DX'])}] × "
                f"[{fmt(gm['YL'])}, {fmt(gm['YL'] + gm['MY'] * gm['DY'])}] mm")
        if g["IPOTCN"] > 0:
            L.append(f"- **Grid** (case {k}, IPOTCN = {g['IPOTCN']}): MX × MY = {int(g['MX'])} × {int(g['MY'])} "
                     f"elements of DX × DY = {fmt(gm['DX'])} × {fmt(gm['DY'])} mm; potential contact area "
                     f"[XL, XL + MX·DX] × [YL, YL + MY·DY] = {span}; element (ix, iy) has its centre at "
                     f"x = XL + (ix − ½)·DX, y = YL + (iy − ½)·DY. As read: "
                     + ", ".join(f"{a} = {fmt(v)}" for a, v in g.items() if a != "IPOTCN") + ".")
        else:
            L.append(f"- **Grid** (case {k}, IPOTCN = {g['IPOTCN']}, a Hertzian option: "
                     + ", ".join(f"{a} = {fmt(v)}" for a, v in g.items() if a != "IPOTCN")
                     + "): CONTACT takes the potential contact area [−AA·SCALE, AA·SCALE] × [−BB·SCALE, BB·SCALE] "
                     f"= {span} and divides it into MX × MY elements: XL = {fmt(gm['XL'])}, "
                     f"YL = {fmt(gm['YL'])}, DX = {fmt(gm['DX'])}, DY = {fmt(gm['DY'])} mm (as its .mat file "
                     f"states).")
    for k, m in dedup([(c["case"], c["material"]) for c in cases if c["digits"]["C"] >= 2]):
        G, nu, K = combined(m)
        E1 = 2 * m["GG1"] * (1 + m["POISS1"])
        E2 = 2 * m["GG2"] * (1 + m["POISS2"])
        L.append(f"- **Materials** (case {k}; C = 2: Kalker's closed-form influence coefficients of the "
                 f"half-space for piecewise constant tractions; M = 0: elastic): body 1 (upper, z > 0) "
                 f"G₁ = {fmt(m['GG1'])} N/mm², ν₁ = {fmt(m['POISS1'])} (E₁ = 2G₁(1 + ν₁) = {fmt(E1)}); body 2 "
                 f"(lower) G₂ = {fmt(m['GG2'])}, ν₂ = {fmt(m['POISS2'])} (E₂ = {fmt(E2)}). Combined (user guide, "
                 f"GA, NU, AK, and src/m_hierarch_data.f90 for K): 1/G = ½(1/G₁ + 1/G₂) → G = {fmt(G)}; "
                 f"ν = G·½(ν₁/G₁ + ν₂/G₂) = {fmt(nu)}; K = G·¼((1 − 2ν₁)/G₁ − (1 − 2ν₂)/G₂) = {fmt(K)}"
                 + (" (quasi-identical: K = 0, no normal–tangential coupling)" if abs(K) < 1e-12 else
                    " (K ≠ 0: normal and tangential problems are coupled; CONTACT iterates between them, "
                    "Panagiotopoulos' process, up to MAXOUT times)") + ".")
    for k, f in dedup([(c["case"], c["friction"]) for c in cases if c["digits"]["L"] == 0]):
        L.append(f"- **Friction** (case {k}; L = 0: Coulomb): FSTAT = {fmt(f['FSTAT'])}, FKIN = {fmt(f['FKIN'])}"
                 + (" (equal: one coefficient μ)" if f["FSTAT"] == f["FKIN"] else "") + ".")
    for k, p in dedup([(c["case"], c["profile"]) for c in cases if c["digits"]["Z"] > 1]):
        if p["IBASE"] == 1:
            b = p["B"]
            L.append(f"- **Profile** (case {k}; IBASE = 1, quadratic): h(x, y) = b₁x² + b₂xy + b₃y² + b₄x + b₅y "
                     f"+ b₆ with b = ({', '.join(fmt(v) for v in b)}) (b₁₋₃ in 1/mm, b₄₋₅ dimensionless, b₆ in "
                     f"mm), the distance between the undeformed surfaces, positive where they are apart; the gap "
                     f"with the approach is h − PEN. In rollbem's terms A x² + B y² with A = b₁ = {fmt(b[0])}, "
                     f"B = b₃ = {fmt(b[2])} 1/mm, A = 1/(2R_x): relative radii R_x = {fmt(1 / (2 * b[0]))} mm, "
                     f"R_y = {fmt(1 / (2 * b[2]))} mm. IPLAN = 1: every element may enter contact.")
        elif p["IBASE"] == 2:
            L.append(f"- **Profile** (case {k}; IBASE = 2, a body of revolution): h(x, y) = p(y) + (x − XM)²/(2·RM) "
                     f"with XM = {fmt(p['XM'])} mm, RM = {fmt(p['RM'])} mm, and p(y) given at NN = {p['NN']} points "
                     f"y_k = Y1 + (k − 1)·DY1, Y1 = {fmt(p['Y1'])}, DY1 = {fmt(p['DY1'])} mm, linearly "
                     f"interpolated (user guide, IBASE = 2); the heights are in {name}_profile.csv. IPLAN = 1.")
        else:
            hz = hertz_printed(out_text, k)
            L.append(f"- **Profile** (case {k}): from the Hertzian grid option: CONTACT derives the curvatures "
                     f"A1, B1 from AA, BB, FN and the materials and uses h = A1·x² + B1·y²; it prints "
                     f"A1, B1 = {hz[0]}, {hz[1]} 1/mm." if hz else "- **Profile**: Hertzian.")
    for k, sv in dedup([(c["case"], c["solver"]) for c in cases if c["digits"]["G"] in (0, 2, 3, 4)]):
        L.append(f"- **Solver constants** (case {k}; G = 0: the default solvers, NormCG for the normal problem, "
                 f"TangCG for shifts, SteadyGS for steady rolling): MAXGS = {int(sv['MAXGS'])}, "
                 f"MAXIN = {int(sv['MAXIN'])}, MAXNR = {int(sv['MAXNR'])}, MAXOUT = {int(sv['MAXOUT'])}, "
                 f"**EPS = {sv['EPS']:g}** (the stop criterion ‖pᵏ − pᵏ⁻¹‖ < EPS·‖pᵏ‖ of the iterations: not an "
                 f"error bound).")
    for k, rr in dedup([(c["case"], c["rolling"]) for c in cases if "rolling" in c and c["digits"]["T"] > 1]):
        L.append(f"- **Rolling** (case {k}): CHI = {fmt(rr['CHI'])} rad (rolling direction, 0 = +x), "
                 f"DQ = {fmt(rr['DQ'])} mm (distance per step), VELOC = {fmt(rr['VELOC'])} mm/s.")
    for c in cases:
        if "subs_blocks" in c:
            blocks = []
            for b in c["subs_blocks"]:
                if b["ISUBS"] == 2:
                    blocks.append(f"ISUBS = 2: element centres of columns {int(b['IX'][0])}:{int(b['IX'][1])}:"
                                  f"{int(b['IX'][2])} (first:step:last), rows {int(b['IY'][0])}:{int(b['IY'][1])}:"
                                  f"{int(b['IY'][2])}, NZ = {int(b['Z'][0])} depth(s) from z = {b['Z'][1]:g} by "
                                  f"{b['Z'][2]:g} mm")
                elif b["ISUBS"] == 9:
                    blocks.append(f"ISUBS = 9: x = ({', '.join(fmt(v) for v in b['X'])}), y = "
                                  f"({', '.join(fmt(v) for v in b['Y'])}), z = ({', '.join(fmt(v) for v in b['Zlist'])}) "
                                  f"mm ({len(b['X'])}·{len(b['Y'])}·{len(b['Zlist'])} points)")
                else:
                    blocks.append(f"ISUBS = {b['ISUBS']}")
            L.append(f"- **Subsurface points** (case {c['case']}, S = 3; digits A_s, O_s = "
                     f"{c['subs_digits'][0]}, {c['subs_digits'][1]}): " + "; ".join(blocks)
                     + ". Cases with S = 1 compute the stresses at the same points.")
    L.append("")
    return "\n".join(L)


def main():
    if len(sys.argv) not in (3, 4):
        print(__doc__, file=sys.stderr)
        return 2
    src, binary = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
    out_dir = sys.argv[3] if len(sys.argv) == 4 else os.path.join(HERE, "..", "..", "reference", "contact3d")
    out_dir = os.path.abspath(out_dir)
    os.makedirs(out_dir, exist_ok=True)
    work = tempfile.mkdtemp(prefix="contact_ref3d.")
    sections = []
    checks = []
    try:
        for name, (folder, map_cases) in INPUTS.items():
            inp = os.path.join(src, folder, name + ".inp")
            cases = parse_inp(inp)
            d = run_contact(binary, name, inp, work)
            out = os.path.join(d, name + ".out")
            if folder == "examples":
                ref = os.path.join(src, folder, name + ".ref_out")
                # The A digit raised above is echoed in the problem echo ("MATFIL 1"): blank that word's value
                # in both before comparing; nothing else may differ.
                cmp_out, cmp_ref = os.path.join(d, "cmp.out"), os.path.join(d, "cmp.ref_out")
                for a, b in ((out, cmp_out), (ref, cmp_ref)):
                    text = open(a, encoding="latin-1").read()
                    open(b, "w", encoding="latin-1").write(re.sub(r"MATFIL +\d", "MATFIL x", text))
                res = subprocess.run([sys.executable, os.path.join(HERE, "contact_refcmp.py"), cmp_out, cmp_ref],
                                     capture_output=True, text=True)
                if res.returncode != 0:
                    raise InputError(f"{name}: this CONTACT differs from {name}.ref_out:\n{res.stdout}")
                checks.append(f"{name}: {res.stdout.strip()}")
                printed = parse_out(ref)
                source = f"{name}.ref_out (the author's)"
            else:
                kind, count, its = perfc_counts(src, name)
                printed = parse_out(out)
                last = printed[max(printed)]
                mine = int(last["NCON" if kind == "ncon" else "NSLIP"])
                if mine != count:
                    raise InputError(f"{name}: {kind} {mine}, get_times.ref_out has {count}")
                checks.append(f"{name}: {'NCON' if kind == 'ncon' else 'NSLIP'} = {mine} as the author's "
                              f"perfc_test/get_times.ref_out")
                source = f"{name}.out (this CONTACT build; no .ref_out is shipped)"
            mats = {}
            grids = {}
            for c in cases:
                path = os.path.join(d, f"{name}.{c['case']:04d}.mat")
                if not os.path.exists(path):
                    raise InputError(f"{name}: no {path}")
                grids[c["case"]], rows = parse_mat(path)
                mats[c["case"]] = rows
                # The .mat file's counts against the printed ones where CONTACT prints them.
                p = printed.get(c["case"], {})
                if "NCON" in p:
                    got = (sum(1 for r in rows if r["IGS"] in ("1", "2")), sum(1 for r in rows if r["IGS"] == "1"))
                    if got != (int(p["NCON"]), int(p["NADH"])):
                        raise InputError(f"{name} case {c['case']}: .mat counts {got}, printed "
                                         f"{p['NCON']}, {p['NADH']}")
            write_cases(os.path.join(out_dir, f"{name}_cases.csv"), cases, printed, mats, source)
            for k in map_cases:
                g, rows = parse_mat(os.path.join(d, f"{name}.{k:04d}.mat"))
                with open(os.path.join(out_dir, f"{name}_case{k}_elements.csv"), "w", newline="") as f:
                    w = csv.writer(f)
                    w.writerow(ELEMENT_HEADER)
                    w.writerows(element_rows(g, rows))
            prof = cases[0]["profile"]
            if prof.get("IBASE") == 2:
                with open(os.path.join(out_dir, f"{name}_profile.csv"), "w", newline="") as f:
                    w = csv.writer(f)
                    w.writerow(["k", "y", "p"])
                    for j, h in enumerate(prof["heights"]):
                        w.writerow([j + 1, f"{prof['Y1'] + j * prof['DY1']:.6g}", f"{h:.6g}"])
            if name == "subsurf":
                write_subsurf_axis(src, d, out_dir)
            out_text = open(os.path.join(d, name + ".out"), encoding="latin-1").read()
            sections.append(describe(name, folder, cases, grids, out_text))
            print(f"[contact_ref3d] {name}: {len(cases)} cases, {checks[-1]}", file=sys.stderr)
        write_readme(out_dir, sections, checks, src)
    finally:
        shutil.rmtree(work, ignore_errors=True)
    return 0


def write_subsurf_axis(src, run_dir, out_dir):
    """subsurf's first block of subsurface points (x = y = 1e-5, 15 depths): case 2 from the author's
    subsurf.ref_subs (the .subs file of the last case), case 1 from this run's subsurf.0001.subs."""
    for case, path in ((1, os.path.join(run_dir, "subsurf.0001.subs")),
                       (2, os.path.join(src, "examples", "subsurf.ref_subs"))):
        lines = open(path, encoding="latin-1").read().split("\n")
        head = None
        rows = []
        for i, line in enumerate(lines):
            if line.startswith("%") and " X " in line + " " and "SIGXX" in line:
                if head is not None:
                    break
                head = line[1:].split()
                continue
            if head is not None and line.strip():
                rows.append(line.split())
        with open(os.path.join(out_dir, f"subsurf_case{case}_axis.csv"), "w", newline="") as f:
            w = csv.writer(f)
            w.writerow([h.lower() for h in head])
            w.writerows(rows)


README_HEAD = """# CONTACT's 3D reference data (written by benches/peer/contact_ref3d.py: do not edit by hand)

Reference data for rollbem's 3D half-space (issue 32) from CONTACT, E. Vollebregt's program for 3D frictional
contact (Fortran, Apache-2.0, https://github.com/eve70a/CONTACT, {rev}): its own example inputs and the author's
reference outputs shipped with them (`examples/*.ref_out`, written by the author's Windows build with Intel MKL),
an independent peer. Regenerate with

```sh
KEEP=/tmp/c3d bash benches/peer/contact3d.sh /tmp/c3d.md CONTACT_SRC      # builds CONTACT with MKL, checks it
python3 benches/peer/contact_ref3d.py CONTACT_SRC /tmp/c3d/contact-build/bin/contact_linux64
```

## Where each number comes from

- **Printed totals of the examples** (cattaneo, spence35, subsurf: the columns fn … itang of `NAME_cases.csv`) are
  the author's, read from `NAME.ref_out` as printed (4 significant digits).
- **Per-element tables** (`NAME_caseK_elements.csv`) and the columns `*_mat` of `NAME_cases.csv` are from **our
  build of CONTACT** (gfortran + Intel oneMKL from PyPI, benches/peer/contact_build.sh), because the `.ref_out`
  files print tractions, if at all, to 3 digits and only in some cases: the script runs our build on a copy of each
  input with the Matlab-file digit A raised to 1 in every case (that digit only makes CONTACT write
  `NAME.CASE.mat`, its per-element results to 6 significant digits; nothing computed or printed changes) and first
  checks that the run reproduces the author's `.ref_out` to every printed digit (benches/peer/contact_refcmp.py,
  with the echo of the raised digit, "MATFIL 1", blanked in both; results below). It also checks that the `.mat` counts equal the printed NCON, NADH wherever CONTACT prints them.
- **norm_problm_1p and tang_problm_1s** (`perfc_test/`) ship no `.ref_out`: everything of theirs is from our build;
  the author's `perfc_test/get_times.ref_out` (CONTACT r1274, 2016) gives their contact / slip element counts, which
  our build reproduces (checked).
- **subsurf's subsurface results on the z axis**: case 2 from the author's `subsurf.ref_subs`, case 1 from our
  build's `subsurf.0001.subs` (its printed maxima match the `.ref_out`).

Checks of this generation:
{checks}

## Conventions (CONTACT's, user guide `doc/user-guide.tex`, "Data units and sign conventions", "Formulation of the contact problem")

- Units: mm, N, N/mm² (MPa); angles in rad (degrees where printed so).
- Body 1 is the upper body (z > 0), body 2 the lower (z < 0). **Tractions and forces act on body 1**:
  pn > 0 is compression, (px, py) is the tangential traction on body 1, FX = Σ px·DX·DY. Displacements (un, ux,
  uy) and slips are those **of body 1 relative to body 2** (displacement difference u = u⁽¹⁾ − u⁽²⁾).
- Gap: h(x, y) is the undeformed distance between the surfaces (the profile); with the approach PEN the gap is
  h − PEN, and the deformed distance e = h − PEN + un ≥ 0, = 0 in contact.
- Shift (T = 1): the rigid shift per step W = (CKSI − CPHI·y, CETA + CPHI·x) [mm, rad]; the slip (shift) per step
  S = W + u_t − u_t′ (u_t′: the previous case's displacement difference of the same particles; a case with P = 2
  starts from zero previous tractions, P = 0 continues from the previous case). Adhesion: S = 0, |p_t| ≤ μ pn; slip:
  p_t = −μ pn S/|S|. With FX prescribed (F ≥ 1) CONTACT finds the shift CKSI that gives it (printed as SHIFT X).
- Steady rolling (T = 3): W = DQ·(CKSI − CPHI·(y + sin(CHI)·DQ/6), CETA + CPHI·(x + cos(CHI)·DQ/6)) with
  creepages CKSI, CETA and spin CPHI [rad/mm], rolling direction CHI (0: +x), DQ the distance per step.
- Combined material constants: 1/G = ½(1/G₁ + 1/G₂), ν/G = ½(ν₁/G₁ + ν₂/G₂), K/G = ¼((1 − 2ν₁)/G₁ −
  (1 − 2ν₂)/G₂): the user guide prints a '+' in K's formula; CONTACT's source (src/m_hierarch_data.f90, `m%ak =`)
  has the '−' used here, and K = 0 for identical bodies, as the reference outputs print (AK). K > 0 when body 1 is
  the more compliant in compression.
- Elements: MX × MY rectangles DX × DY; element number I = ix + (iy − 1)·MX; centres x = XL + (ix − ½)·DX,
  y = YL + (iy − ½)·DY; tractions piecewise constant per element, displacements at the centres (C = 2).
- Control digits (user guide, "The control integers", module 3): P (0: continue the sequence, 2: new sequence);
  B (0: full elastic model); T (0 frictionless, 1 shift / transient, 3 steady rolling); N (0: approach PEN
  prescribed, 1: normal force FN); F (0: creepages / shifts CKSI, CETA; 1: FX/(FSTAT·FN) and CETA; 2: FX and FY
  relative); S (subsurface stresses: 0 none, 1 at stored points, 3 read points); L (0 Coulomb, 1 keep); D (0 keep
  the grid, 2 read it); C (0/1 keep, 2 half-space, piecewise constant); M (0 elastic); Z (0 keep the profile, 2
  read it); E (0 no extra rigid slip); H (0 no heat); G (0 default solvers, read MAXGS…EPS; 1 keep); I (0 start
  from zero tractions, 1 from the previous solution); A (Matlab file: 0 none, 1 elements in contact); O (output
  level: 1 totals, 2 + problem echo and counts, 3 + state map, 5 + per-element table); W (trace); R (1 return).

## Files

- `NAME_cases.csv`: one row per case; columns:
{case_cols}
- `NAME_caseK_elements.csv`: the elements in contact in case K (the `.mat` file with A = 1 lists only those), one
  row each: ix, iy (1-based column and row), x, y (element centre, mm), state (adhesion = stick, slip), h
  (undeformed distance without the approach, mm), mu (friction coefficient), pn, px, py (tractions on body 1,
  N/mm²), un, ux, uy (displacement difference, mm), shift_or_srel (T = 1: the shift |S| in the step, mm; rolling:
  the relative slip velocity); values as CONTACT writes them, 6 significant digits.
- `spence35`: element tables for stages 1, 12, 24 and 35 (the file would be 35 times as large with all).
- `norm_problm_1p_profile.csv`, `tang_problm_1s_profile.csv`: the profile heights p(y_k) of IBASE = 2.
- `subsurf_case1_axis.csv`, `subsurf_case2_axis.csv`: subsurface displacements and stresses at x = y = 1e-5 mm,
  15 depths z (mm): ux, uy, uz (mm), sighyd (hydrostatic), sigvm (von Mises), sigxx, sigxy, sigxz, sigyy, sigyz,
  sigzz (N/mm²).

## The inputs, decoded

Every parameter below is read from the `.inp` by contact_ref3d.py following the user guide's input
specification (module 3); derived values say how they are derived.

"""

README_NOTES = """
### Notes on the examples (user guide chapter "Examples", and the inputs' own comments)

- **cattaneo**: a polyethylene ball (G = 200 N/mm², ν = 0.42) on a plane of the same material, R = 50 mm
  (A = B = 0.01 1/mm), FN = 9.1954 N chosen for a contact radius a = 1 mm (Hertz: a = (3/2·FN·(1 − ν²)/E·1/(A + B))^(1/3)).
  Case 1 is the frictionless normal problem on the Hertzian grid option (IPOTCN = −3: AA = BB = 1, SCALE = 19/15,
  so two spare rows and columns on each side); case 2 poses the same geometry as a quadratic profile on the same
  grid and shifts the ball from zero tractions (P = 2) with FX/(μFN) = −0.875 prescribed (F = 2, FY = 0), and
  prints the shift it needed, SHIFT X. Cattaneo–Mindlin's stick radius is c/a = (1 − 0.875)^(1/3) = 0.5 (the input's
  comment: "a circular adhesion area with radius 0.5"); that solution takes the traction parallel to x everywhere,
  exact for ν = 0; here ν = 0.42 (K = 0, identical bodies), and CONTACT's py is small but not zero (element table).
- **spence35**: Spence's compression of dissimilar bodies: body 1 (the sphere) G₁ = 0.5, ν₁ = 0, body 2 rigid
  (G₂ = 1e5, ν₂ = 0): combined G = 1, ν = 0, K = 0.5 (the largest difference). R = 121.5 mm (b₁ = b₃ = 0.004116),
  μ = 0.2986, 45 × 45 elements of 0.2 mm. The load rises as FN = (k/45)³, k = 1 … 35, one case per stage, each a
  shift (T = 1) with W = 0 continuing the previous stage (P = 0; stage 1 starts from zero, P = 2); the growth of the
  tangential displacement difference between stages is the slip. Spence: the stick radius is a constant fraction of
  the contact radius (one half for these μ, ν). Stage 1 reads subsurface points at the element centres of row 23
  (y = 1e-4, the grid's centre row), depth 1e-6 mm, computed in every stage (S ≥ 1). In the last stage CONTACT has
  NCON = 921, NADH = 225: radii √(N/π)·DX of 3.42 and 1.69 mm, a ratio 0.49.
- **subsurf**: one element of 1 × 1 mm (Kalker 1990, fig. 5.20: subsurface stresses under a uniformly loaded
  square): case 1 FN = 1 (pn = 1), case 2 steady rolling with FX/(μFN) = 0.999 (μ = 1), i.e. px ≈ 0.999 as well;
  G = 1, ν = 0.28. Its point is the subsurface field, in `subsurf_case*_axis.csv` and CONTACT's `.subs` files.
- **norm_problm_1p / tang_problm_1s**: the smallest of CONTACT's performance series, a wheel on a rail (the inputs'
  comment: "right wheel, lateral displacement 6.2 mm"): G = 82 000, ν = 0.28, μ = 0.3, approach PEN = 0.02084 mm
  prescribed (N = 0), profile IBASE = 2 (radius RM = 483.931 mm in x, the wheel–rail gap p(y) given pointwise in y),
  71 × 81 elements of 0.1 mm. norm_problm_1p: the normal problem only (T = 0); tang_problm_1s: the same with a shift
  (T = 1, P = 2 from zero tractions) CKSI = 0.0005 mm, CETA = −0.001 mm, CPHI = 0.0008 rad. The rotation CPHI is
  about the origin of the grid's coordinates (the spin centre SPINXO, SPINYO defaults to (0, 0)), not about the
  patch's centre: the contact occupies x ∈ [−3.3, 3.3], y ∈ [−5.9, 1.6] (element centres in contact). The larger
  members (2p … 8p, 2s … 8s) refine the grid by 2, 4, 8 (DX = 0.05 … 0.0125 mm) on the same problem.

### What was read

CONTACT's user guide (`doc/user-guide.tex` of the tree named above): "The control integers" (module 3's digits),
"Specification of the input file <experim>.inp" (module 3: the order of the input lines), "Potential contact
area and discretisation" (IPOTCN, grid, element numbering and centres), "Non-Hertzian geometry specification"
(IBASE, IPLAN), "Kinematic variables" (PEN, FN, shifts, creepages, rigid shift formulas), "Homogeneous elastic
materials" (G, ν, combined constants), "Solution processes" (MAXGS … EPS), "Subsurface stresses" (ISUBS blocks),
"Specification of the file <experim>.<case>.mat", "Data units and sign conventions", "Formulation of the contact
problem" and "Discretisation of the problem" (signs, shift S = W + u − u′), and the examples' chapters ("The Cattaneo
shift problem", "Dissimilar materials: Spence compression"); CONTACT's source `src/m_hierarch_data.f90` for the
difference parameter K; the inputs' own comments.
"""


def contact_version(src):
    """CONTACT's revision (src/VERSION) and commit (git, or CONTACT_COMMIT for a tree that is not a checkout)."""
    text = open(os.path.join(src, "src", "VERSION"), encoding="latin-1").read()
    m = re.search(r"\$Revision: *(\d+) *\$, *\$Date:: *([0-9-]+)", text)
    rev = f"r{m.group(1)} ({m.group(2)})" if m else "revision unknown"
    commit = os.environ.get("CONTACT_COMMIT")
    if not commit:
        try:
            commit = subprocess.run(["git", "-C", src, "rev-parse", "--short=12", "HEAD"], capture_output=True,
                                    text=True, check=True).stdout.strip()
        except (subprocess.CalledProcessError, FileNotFoundError):
            commit = "unknown (not a git checkout; set CONTACT_COMMIT)"
    return f"{rev}, commit {commit}"


def write_readme(out_dir, sections, checks, src):
    vers = contact_version(src)
    case_cols = "\n".join(f"  - `{c}`: {d}" for c, d in CASE_COLUMNS)
    text = README_HEAD.format(rev=vers, checks="\n".join(f"- {c}" for c in checks), case_cols=case_cols)
    text += "\n".join(sections) + README_NOTES
    open(os.path.join(out_dir, "README.md"), "w").write(text)


if __name__ == "__main__":
    try:
        sys.exit(main())
    except (InputError, subprocess.CalledProcessError) as e:
        print(f"[contact_ref3d] error: {e}", file=sys.stderr)
        sys.exit(1)
