#!/usr/bin/env python3
"""Compare the Pareto fronts and recommendations of two or more `rollbem report` outputs, times masked.

Usage:
    for x in a b; do rollbem report --out /tmp/rep-$x; done
    python3 reference/tools/front_stability.py /tmp/rep-a/README.md /tmp/rep-b/README.md

A report's front page (README.md) links one page per problem family (families/*.md), which holds the sweeps' fronts
and recommendation tables: the README given and every families/*.md beside it are read (a report from before the
split has everything in its README).

For every (sweep, error measure, problem) it extracts the front (discretisation, elements, error, solvers with this
answer) and the recommendations (target, recommended, solver, elements, error, alternatives), drops every time and time
ratio, and
reports per pair of reports how many fronts and recommendation tables are identical, printing the differences.
Exit status 0 when all are identical, 1 otherwise. This is how the front's stability was measured (issue 12): the
times differ between runs by construction; membership and recommendations must not.
"""
import glob
import itertools
import os
import re
import sys

TIME = re.compile(r" [0-9.]+e-?[0-9]+ s")
RATIO = re.compile(r" \([0-9.]+×\)")


def pages(path):
    """The report's pages: its README and the family pages beside it."""
    return [path] + sorted(glob.glob(os.path.join(os.path.dirname(path), "families", "*.md")))


def tables(path):
    """{(sweep, measure, problem, kind): [row tuples]} of one report (README and family pages)."""
    out = {}
    for page in pages(path):
        tables_of_page(page, out)
    return out


def tables_of_page(path, out):
    """Add the tables of one page to `out`."""
    sweep = measure = problem = kind = None
    for line in open(path, encoding="utf-8"):
        # Links on a family page are relative to it (`](../sweeps/…)`): the same heading as on a single page.
        line = line.rstrip("\n").replace("](../", "](")
        if line.startswith("### "):
            sweep, measure, problem, kind = line, None, None, None
        elif line.startswith("#### "):
            measure, problem, kind = line, None, None
        elif line.startswith("##### "):
            problem, kind = line, None
        elif line.startswith("Pareto front:"):
            kind = "front"
        elif line.startswith(("Cheapest configurations", "Recommended configuration", "Recommended (")):
            kind = "recommendations"
        elif kind and line.startswith("| ") and not line.startswith(("| discretisation", "| target")):
            cells = [c.strip() for c in line.strip("|").split("|")]
            if kind == "front" and len(cells) == 5:
                row = (cells[0], cells[1], cells[2], TIME.sub("", cells[4]))
            elif kind == "recommendations" and len(cells) == 7:
                row = tuple(cells[:5]) + (RATIO.sub("", cells[6]),)
            else:
                row = tuple(cells)
            out.setdefault((sweep, measure, problem, kind), []).append(row)
        elif kind and line and not line.startswith("|"):
            kind = None


def main(paths):
    if len(paths) < 2:
        print(__doc__)
        return 2
    reports = {p: tables(p) for p in paths}
    same_all = True
    for a, b in itertools.combinations(paths, 2):
        ta, tb = reports[a], reports[b]
        keys = sorted(set(ta) | set(tb), key=str)
        counts = {"front": [0, 0], "recommendations": [0, 0]}
        for k in keys:
            c = counts[k[3]]
            c[1] += 1
            if ta.get(k) == tb.get(k):
                c[0] += 1
            else:
                same_all = False
                print(f"differs: {' / '.join(x for x in k[:3] if x)} ({k[3]})")
                for row in sorted(set(ta.get(k, [])) ^ set(tb.get(k, []))):
                    side = a if row in ta.get(k, []) else b
                    print(f"    only in {side}: {row}")
        print(
            f"{a} vs {b}: fronts identical {counts['front'][0]}/{counts['front'][1]}, "
            f"recommendations identical {counts['recommendations'][0]}/{counts['recommendations'][1]}"
        )
    return 0 if same_all else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
