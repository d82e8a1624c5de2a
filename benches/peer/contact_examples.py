#!/usr/bin/env python3
"""CONTACT's 2D examples beside rollbem, case by case: bentall, visc_cylindr, veldep_fric (issue 33).

Not part of CI; run by benches/peer/contact.sh (or alone):

    python3 benches/peer/contact_examples.py CONTACT_BIN EXAMPLES_DIR ROLLBEM WORK_DIR > TABLE.md

CONTACT_BIN is CONTACT's executable (run as `CONTACT_BIN 2 NAME` in a folder holding NAME.inp), EXAMPLES_DIR its
`examples/` folder, ROLLBEM rollbem's binary. For every printed case of each input it reads CONTACT's CREEP X, PMAX,
NCON and NADH from NAME.out and poses the same case as a rollbem scene (the strip of half-spaces DY wide, CONTACT's
grid, its materials and loads; the mapping is written beside each input below), runs `rollbem run --json` and prints
one Markdown table with the differences. CONTACT's code is only run; nothing of it is copied.
"""
import json
import math
import os
import re
import shutil
import subprocess
import sys


def contact_cases(out_path):
    """Per printed case: (case number, creepage, pmax, ncon, nadh) from CONTACT's output file."""
    lines = open(out_path).read().split("\n")
    cases, case, pending = [], None, {}
    for i, line in enumerate(lines):
        m = re.match(r"^ Case\s+(\d+)", line)
        if m:
            case = int(m.group(1))
        if "PMAX" in line and "APPROACH" in line:
            v = lines[i + 1].split()
            # CREEP X when the force is prescribed; FX/FSTAT/FN when the creepage is (veldep_fric).
            key = "creepage" if "CREEP X" in line else "fx_over_mu_fn"
            pending = {key: float(v[1]), "pmax": float(v[4])}
        if "NPOT" in line and "NCON" in line and pending:
            v = lines[i + 1].split()
            pending.update(ncon=int(v[1]), nadh=int(v[2]))
            cases.append((case, pending))
            pending = {}
    return cases


SCENE = """name = "{name}"
units = "N, mm, MPa"
[wheel]
radius = {radius}
youngs_modulus = {e1}
poisson_ratio = {nu1}
model = "half_plane"
profile = "parabola"
{visc}
[counter_body]
kind = "half_plane"
youngs_modulus = {e2}
poisson_ratio = {nu2}
{visc}
[mesh]
element = "constant"
contact_x = [{x0}, {x1}]
contact_elements = {mx}
strip_width = {dy}
[contact]
friction = {mu}
{coupling}
[drive]
normal_load = {p}
{tangential}
[rolling]
mode = "steady"
direction = {direction}
{rolling_extra}
[solvers]
use = ["active_set"]
"""


def bentall_scenes():
    """bentall.inp: aluminium (G = 23 000, ν = 0.31) on steel (G = 82 000, ν = 0.28), E = 2G(1 + ν); B1 = 0.02
    (h = x²/(2·25)); 216 elements of 0.001 from XL = −0.108; FN = 16 201.9 on DY = 1000; CHI = 180° (direction −1);
    the coupling on (rollbem's default); cases 2–6 prescribe FX/(μ FN): Q = FX·μ·P."""
    base = dict(radius=25, e1=2 * 23000 * 1.31, nu1=0.31, e2=2 * 82000 * 1.28, nu2=0.28, visc="", x0=-0.108,
                x1=0.108, mx=216, dy=1000, coupling="", p=16.2019, direction=-1, rolling_extra="")
    out = []
    for case, mu, fx in [(2, 1e-4, 0.0), (3, 10.0, 0.0), (4, 0.05, 0.0), (5, 0.05, 0.75), (6, 0.05, -0.75)]:
        s = dict(base, name=f"bentall-{case}", mu=mu, tangential=f"tangential_load = {fx * mu * 16.2019!r}")
        out.append((case, s))
    return out


def visc_scenes():
    """visc_cylindr.inp: PA6, G = 1143, ν = 0.4 (E = 3200.4), R = 50 combined (B1 = 0.01), 99 elements of 0.16 from
    XC1 = −7.92, FN = 600 000 on DY = 1000, FX/(μ FN) = −0.6 (Q = −108), μ = 0.3, V = 1000 mm/s, CHI = 0; cases 1–4
    FG = 1 with TC = 0, 0.009, 0.045, 2 s; cases 5, 6 elastic with G = 571.5 and 1143."""
    out = []
    for case, tc, g in [(1, 0.0, 1143.0), (2, 0.009, 1143.0), (3, 0.045, 1143.0), (4, 2.0, 1143.0), (5, None, 571.5),
                        (6, None, 1143.0)]:
        e = 2 * g * 1.4
        visc = "" if tc is None else f"viscoelastic = {{ compliance_ratio = 1.0, creep_time = {tc!r} }}"
        s = dict(name=f"visc-cylindr-{case}", radius=50, e1=e, nu1=0.4, e2=e, nu2=0.4, visc=visc, x0=-8.0, x1=7.84,
                 mx=99, dy=1000, mu=0.3, coupling="coupling = false", p=600.0, tangential="tangential_load = -108.0",
                 direction=1, rolling_extra="" if tc is None else "velocity = 1000.0")
        out.append((case, s))
    return out


def rollbem_case(rollbem, work, scene):
    path = os.path.join(work, scene["name"] + ".toml")
    with open(path, "w") as f:
        f.write(SCENE.format(**scene))
    js = path[:-5] + ".json"
    subprocess.run([rollbem, "run", path, "--json", js], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    run = json.load(open(js))["runs"][0]
    nodes = run["nodes"]
    states = [n["state"] for n in nodes]
    return {
        "status": run["status"],
        "creepage": (run.get("rolling") or {}).get("creepage"),
        "pmax": max(n["pressure"] for n in nodes),
        "ncon": sum(s != "separated" for s in states),
        "nadh": sum(s == "stick" for s in states),
    }


def run_contact(contact_bin, examples, work, name):
    folder = os.path.join(work, "contact-" + name)
    os.makedirs(folder, exist_ok=True)
    shutil.copy(os.path.join(examples, name + ".inp"), folder)
    subprocess.run([contact_bin, "2", name], cwd=folder, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    return contact_cases(os.path.join(folder, name + ".out"))


def rel(a, b):
    return abs(a - b) / abs(b) if b else abs(a - b)


def main():
    contact_bin, examples, rollbem, work = sys.argv[1:5]
    os.makedirs(work, exist_ok=True)
    print("| input | case | status | creepage rollbem | creepage CONTACT | rel. diff | pmax rollbem | pmax CONTACT "
          "| rel. diff | contact rollbem / CONTACT | stick rollbem / CONTACT |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    for name, scenes in [("bentall", bentall_scenes()), ("visc_cylindr", visc_scenes())]:
        reference = dict(run_contact(contact_bin, examples, work, name))
        for case, scene in scenes:
            c = reference.get(case)
            r = rollbem_case(rollbem, work, scene)
            if c is None or r["creepage"] is None:
                print(f"| {name} | {case} | {r['status']} | {r['creepage']} | (not printed) | | | | | | |")
                continue
            print(f"| {name} | {case} | {r['status']} | {r['creepage']:.4e} | {c['creepage']:.3e} "
                  f"| {rel(r['creepage'], c['creepage']):.1e} | {r['pmax']:.4f} | {c['pmax']:.4g} "
                  f"| {rel(r['pmax'], c['pmax']):.1e} | {r['ncon']} / {c['ncon']} | {r['nadh']} / {c['nadh']} |")
    veldep = run_contact(contact_bin, examples, work, "veldep_fric")
    for case, c in veldep[:4]:
        print(f"| veldep_fric | {case} | not posed | | CKSI prescribed, FX/(μ FN) = {c['fx_over_mu_fn']:.4f} | | "
              f"| {c['pmax']:.4g} | | – / {c['ncon']} | – / {c['nadh']} |")
    print("| veldep_fric | the others | not posed | | (time steps CONTACT does not print in full) | | | | | | |")
    print()
    print("CONTACT's printed CREEP X has 4 digits and PMAX 4: a relative difference below about 5e-4 is within its "
          "printing. veldep_fric (slip-velocity-dependent friction, Vollebregt & Schuttelaars 2012) is run by CONTACT "
          "only: rollbem's friction laws of the slip velocity are a library-level solver so far (src/veldep.rs: steady rolling and single time steps; "
          "tests/veldep.rs reproduces cases 1, 2 and 4), not a scene, so the input is not posed here.")
    return 0


if __name__ == "__main__":
    sys.exit(main())
