#!/usr/bin/env python3
"""Compare a CONTACT output file (.out) with CONTACT's shipped reference output (.ref_out), number by number.

Usage: python3 contact_refcmp.py OUT REF_OUT [--units N] [--cases K]

--cases K compares the reference's cases 1..K only (OUT from an input cut after its case K: contact3d.sh's
examples mode).

Used by benches/peer/contact_build.sh (contact_ref_check) to refuse a CONTACT build that does not reproduce the
author's answers. Standard library only.

What is compared: for every case (a line ` Case     K`), CONTACT's printed results, the part of the case that
starts at the line `PBTNFS.` (the echo of the control digits that CONTACT's output routine writes first at output
level O >= 2) or, at O = 1, at the header of the total forces (`FN FX FY MZ ...`), and ends at the next case, at
the timer table (lines starting with `|`, or `Performance timers:`) or at a line `Parallel run using ...`. That part holds the
problem echo (materials, friction, kinematics), the total forces (FN FX FY MZ, elastic energy, frictional work), the
relative forces and approach (FN/G, FX/FSTAT/FN, FY/FSTAT/FN or the shifts, APPROACH, PMAX), the element counts
(NPOT NCON NADH NSLIP, outer iterations INORM ITANG), the map of element states and, at output level O >= 3, the
table of distributed quantities per element (H-PEN, PN, TRCBND, ABS(PT), ARG(PT), ABS(S), rigid shift/slip). The
iteration logs that precede it (inner iteration counts, intermediate creepages) are not results and are skipped.

The two parts must have the same lines (a different contact area or element state is a different answer). Words
must be equal. Numbers must agree to N units (default 1) of the last printed digit of the coarser of the two as
printed ("0.815E-02": 1e-5; "6955.": 1; "0.6480": 1e-4; a trailing ';' or ',' is punctuation), with three
exceptions that are print artefacts, not answers, each counted apart in the summary: values both under 1e-12 in
magnitude count as zero (round-off around zero printed in E format); a difference under 1e-8 of the largest
magnitude on the same line is round-off in a near-zero component (spence35's subsurface points at y = 1e-4: the
lateral displacement and shear stresses, 1e-7 beside 1e-1); angles of +-180 degrees (ARG of a traction along -x)
are equal whatever their printed sign.

Prints one line: how many numbers were compared, in how many cases, how many differed at all and the largest
difference in units of the last digit; exit 0 if all agree, else 1 with the first differences listed.
"""

import re
import sys

NUM = re.compile(r"^[+-]?(\d+\.?\d*|\.\d+)([EeDd][+-]?\d+)?$")
ZERO = 1e-12
TOTALS = re.compile(r"^ +FN +FX +FY +MZ ")
ROUNDOFF = 1e-8


def ulp(tok):
    """One unit of the last printed digit of the number token TOK."""
    m = NUM.match(tok)
    mant, exp = m.group(1), m.group(2)
    dec = len(mant.split(".")[1]) if "." in mant else 0
    e = int(exp[1:]) if exp else 0
    return 10.0 ** (e - dec)


def to_float(tok):
    return float(tok.replace("D", "E").replace("d", "e"))


def result_parts(path):
    """{case number: [lines of its printed results]} of a CONTACT .out file."""
    parts = {}
    case = None
    keep = False
    with open(path, encoding="latin-1") as f:
        for line in f:
            m = re.match(r"^ Case +(\d+)\s*$", line)
            if m:
                case = int(m.group(1))
                keep = False
                continue
            if case is None:
                continue
            if "PBTNFS." in line or (not keep and TOTALS.match(line)):
                keep = True
                parts[case] = []
            if line.startswith("|") or "Parallel run using" in line or "Performance timers" in line:
                keep = False
            if keep and line.strip():
                parts[case].append(line.rstrip("\n"))
    return parts


def main():
    args = sys.argv[1:]
    units = 1.0
    if "--units" in args:
        i = args.index("--units")
        units = float(args[i + 1])
        del args[i : i + 2]
    first_cases = None
    if "--cases" in args:
        i = args.index("--cases")
        if i + 1 >= len(args) or not args[i + 1].isdigit():
            print("--cases needs a whole number K (compare the reference's cases 1..K)", file=sys.stderr)
            return 2
        first_cases = int(args[i + 1])
        del args[i : i + 2]
    if len(args) != 2:
        print(__doc__.split("\n\n")[1], file=sys.stderr)
        return 2
    out, ref = result_parts(args[0]), result_parts(args[1])
    if first_cases is not None:
        ref = {k: v for k, v in ref.items() if k <= first_cases}
    errors = []
    if sorted(out) != sorted(ref):
        errors.append(f"cases with printed results differ: {sorted(out)} against the reference's {sorted(ref)}")
    ncmp = ndiff = nzero = nround = 0
    worst = 0.0
    worst_at = ""
    for k in sorted(set(out) & set(ref)):
        a, b = out[k], ref[k]
        if len(a) != len(b):
            errors.append(f"case {k}: {len(a)} result lines, the reference has {len(b)}")
        for j, (la, lb) in enumerate(zip(a, b)):
            ta = [t.rstrip(";,") or t for t in la.split()]
            tb = [t.rstrip(";,") or t for t in lb.split()]
            nums = [abs(to_float(t)) for t in ta + tb if NUM.match(t)]
            line_max = max(nums) if nums else 0.0
            if len(ta) != len(tb):
                errors.append(f"case {k}, result line {j + 1}: '{la.strip()}' against '{lb.strip()}'")
                continue
            for x, y in zip(ta, tb):
                xn, yn = NUM.match(x), NUM.match(y)
                if not (xn and yn):
                    if x != y:
                        errors.append(f"case {k}, result line {j + 1}: '{x}' against '{y}' in '{lb.strip()}'")
                    continue
                ncmp += 1
                fx, fy = to_float(x), to_float(y)
                if fx == fy:
                    continue
                ndiff += 1
                if abs(fx) < ZERO and abs(fy) < ZERO:
                    nzero += 1
                    continue
                if abs(fx - fy) < ROUNDOFF * line_max:
                    nround += 1
                    continue
                if abs(abs(fx) - 180.0) < 0.05 and abs(abs(fy) - 180.0) < 0.05:
                    d = abs(abs(fx) - abs(fy))
                else:
                    d = abs(fx - fy)
                u = max(ulp(x), ulp(y))
                if d / u > worst:
                    worst = d / u
                    worst_at = f"case {k}: {x} against {y} in '{lb.strip()}'"
                if d > units * u * (1 + 1e-9):
                    errors.append(f"case {k}, result line {j + 1}: {x} against the reference's {y} "
                                  f"({d / u:.3g} units of the last digit) in '{lb.strip()}'")
    summary = (f"{ncmp} printed numbers in {len(ref)} cases compared with the reference output: {ndiff} differ, "
               f"{nzero} of them both under 1e-12, {nround} by under 1e-8 of their line's largest value; of the others "
               f"the largest by {worst:.3g} unit(s) of the last printed digit"
               + (f" ({worst_at})" if worst_at else "") + f"; allowed: {units:g}")
    if errors:
        print(summary)
        for e in errors[:20]:
            print("  " + e)
        if len(errors) > 20:
            print(f"  ... and {len(errors) - 20} more")
        return 1
    print(summary)
    return 0


if __name__ == "__main__":
    sys.exit(main())
