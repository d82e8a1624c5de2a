#!/usr/bin/env python3
"""CONTACT's four 2D examples beside rollbem, case by case, in one table: carter2d, bentall, visc_cylindr,
veldep_fric (issue 33).

Not part of CI; run by benches/peer/contact.sh (or alone):

    python3 benches/peer/contact_examples.py CONTACT_BIN EXAMPLES_DIR ROLLBEM WORK_DIR [VELDEP_EXAMPLE] > TABLE.md

CONTACT_BIN is CONTACT's executable (run as `CONTACT_BIN 2 NAME` in a folder holding NAME.inp), EXAMPLES_DIR its
`examples/` folder, ROLLBEM rollbem's binary, VELDEP_EXAMPLE rollbem's example `veldep_fric` (`cargo build --release
--example veldep_fric`; without it veldep_fric's rollbem columns are empty). For every printed case of each input it
reads CONTACT's CREEP X (or FX/FSTAT/FN), PMAX, NCON and NADH from NAME.out and poses the same case to rollbem (the
strip of half-spaces DY wide, CONTACT's grid, its materials and loads; the mapping is written beside each input
below): `rollbem run --json` per case, and for veldep_fric the example, which runs the input's 53 steady and
transient cases in order. CPU time (user + sys, from the kernel's accounting of the child processes) per input:
CONTACT's one run of the input, rollbem's runs of its cases summed. Prints one Markdown table. CONTACT's code is only
run; nothing of it is copied.
"""
import json
import math
import os
import re
import resource
import shutil
import subprocess
import sys


def contact_cases(out_path):
    """Per printed case: (case number, {creepage or fx_over_mu_fn, pmax[, ncon, nadh]}) from CONTACT's output."""
    lines = open(out_path, encoding="latin-1").read().split("\n")
    cases, case = [], None
    for i, line in enumerate(lines):
        m = re.match(r"^ Case\s+(\d+)", line)
        if m:
            case = int(m.group(1))
        if "PMAX" in line and "APPROACH" in line:
            v = lines[i + 1].split()
            # CREEP X when the force is prescribed; FX/FSTAT/FN when the creepage is (carter2d, veldep_fric).
            key = "creepage" if "CREEP X" in line else "fx_over_mu_fn"
            cases.append((case, {key: float(v[1]), "pmax": float(v[4])}))
        if "NPOT" in line and "NCON" in line and cases and cases[-1][0] == case:
            v = lines[i + 1].split()
            cases[-1][1].update(ncon=int(v[1]), nadh=int(v[2]))
    return cases


def cpu_of(command, **kwargs):
    """Run a command; return (its completed process, the CPU seconds, user + sys, it and its children took)."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    done = subprocess.run(command, **kwargs)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return done, (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)


SCENE = """name = "{name}"
units = "N, mm, MPa"
[wheel]
radius = {radius}
youngs_modulus = {e1}
poisson_ratio = {nu1}
model = "half_plane"
profile = "{profile}"
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
{law}
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
                x1=0.108, mx=216, dy=1000, coupling="", p=16.2019, direction=-1, rolling_extra="", profile="parabola",
                law="")
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
                 direction=1, rolling_extra="" if tc is None else "velocity = 1000.0", profile="parabola", law="")
        out.append((case, s))
    return out


def carter_scene():
    """carter2d.inp: two half-planes G = 82 000, ν = 0.28 (E = 209 920), B1 = 0.001 (h = x²/(2·500)), 55 elements of
    0.04 from XC1 = −1.05, FN = 35 780 on DY = 200 (178.9 per unit width), μ = 0.3, CKSI = −0.00024, CHI = 0; the
    pair uncoupled (β = 0)."""
    return dict(name="carter2d-1", radius=500, e1=209920.0, nu1=0.28, e2=209920.0, nu2=0.28, visc="", x0=-1.07,
                x1=1.13, mx=55, dy=200, mu=0.3, coupling="coupling = false", p=178.9, tangential="", direction=1,
                rolling_extra="creepage = -0.00024", profile="parabola", law="")


def veldep_scene():
    """veldep_fric.inp: wheel R = 460 (circular profile, IBASE 2) on a flat, both G = 82 000, ν = 0.28; 92 elements
    of 0.1 from XC1 = −4.6; FN = 622 216 on DY = 200 (3111.08 per unit width); the exponential law FKIN 0.18, FEXP1
    0.12, SABSH1 100 mm/s (μ(0) = 0.3); VELOC 45 000 mm/s; CHI = 0. Its cases (steady or a time step of DQ = DX,
    CKSI, INISLP) are read from the input by `veldep_cases`."""
    return dict(name="veldep-fric", radius=460, e1=209920.0, nu1=0.28, e2=209920.0, nu2=0.28, visc="", x0=-4.65,
                x1=4.55, mx=92, dy=200, mu=0.3, coupling="",
                law='friction_law = { kind = "exponential", kinetic = 0.18, first = [0.12, 100.0] }', p=3111.08,
                tangential="", direction=1, rolling_extra="creepage = -0.0009999\nvelocity = 45000.0",
                profile="circle")


def veldep_cases(inp_path):
    """(mode, CKSI, INISLP) per case of veldep_fric.inp, in order: T = 3 (the P-B-T-N-F-S digits) is steady, else a
    time step; CKSI from the `FN, CKSI` line; INISLP the last number but one of the `INISLP, OMGSLP` line."""
    out, mode, inislp = [], None, None
    number = re.compile(r"^[-+0-9.eE]+$")
    for line in open(inp_path, encoding="latin-1"):
        if line.lstrip().startswith("%"):
            continue
        if "P-B-T-N-F-S" in line:
            digits = line.split()[0].rjust(6, "0")
            mode = "steady" if digits[2] == "3" else "transient"
        if "INISLP, OMGSLP" in line:
            inislp = int([t for t in line.split() if number.match(t)][-2])
        if "FN, CKSI" in line:
            out.append((mode, float(line.split()[1]), inislp))
    return out


def rollbem_case(rollbem, work, scene):
    """Pose a scene, run `rollbem run --json`; its figures and the CPU seconds the run took."""
    path = os.path.join(work, scene["name"] + ".toml")
    with open(path, "w") as f:
        f.write(SCENE.format(**scene))
    js = path[:-5] + ".json"
    _, cpu = cpu_of([rollbem, "run", path, "--json", js], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    run = json.load(open(js))["runs"][0]
    nodes = run["nodes"]
    states = [n["state"] for n in nodes]
    resultants = run.get("resultants") or {}
    return {
        "status": run["status"],
        "creepage": (run.get("rolling") or {}).get("creepage"),
        "fx_over_mu_fn": resultants.get("tangential", 0.0) / (scene["mu"] * scene["p"]),
        "pmax": max(n["pressure"] for n in nodes),
        "ncon": sum(s != "separated" for s in states),
        "nadh": sum(s == "stick" for s in states),
    }, cpu


def run_contact(contact_bin, examples, work, name):
    """CONTACT on one of its inputs, as it is: its printed cases and the CPU seconds of the run."""
    folder = os.path.join(work, "contact-" + name)
    os.makedirs(folder, exist_ok=True)
    shutil.copy(os.path.join(examples, name + ".inp"), folder)
    _, cpu = cpu_of([contact_bin, "2", name], cwd=folder, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    return contact_cases(os.path.join(folder, name + ".out")), cpu


def run_veldep(example, work, examples):
    """rollbem's example on veldep_fric's cases: {case: (status, fx_over_mu_fn, ncon, nadh)} and its CPU seconds."""
    scene = veldep_scene()
    path = os.path.join(work, scene["name"] + ".toml")
    with open(path, "w") as f:
        f.write(SCENE.format(**scene))
    cases = os.path.join(work, "veldep_fric_cases.csv")
    with open(cases, "w") as f:
        f.write("mode,cksi,inislp\n")
        for mode, cksi, inislp in veldep_cases(os.path.join(examples, "veldep_fric.inp")):
            f.write(f"{mode},{cksi!r},{inislp}\n")
    done, cpu = cpu_of([example, path, cases], capture_output=True, text=True)
    out = {}
    for line in done.stdout.splitlines()[1:]:
        c = line.split(",")
        out[int(c[0])] = (c[1], float(c[3]), int(c[4]), int(c[5]), float(c[6]))
    return out, cpu, scene


def rel(a, b):
    return abs(a - b) / abs(b) if b else abs(a - b)


def row(name, case, compared, r, c, key, cpu_r, cpu_c):
    """One table row: the compared figure (rollbem, CONTACT, relative or absolute difference), PMAX, the counts."""
    rv, cv = r.get(key), c.get(key)
    if rv is None or cv is None:
        fig = f"| {'–' if rv is None else f'{rv:.6g}'} | {'–' if cv is None else f'{cv:.4g}'} | |"
    elif key == "creepage":
        fig = f"| {rv:.4e} | {cv:.3e} | {rel(rv, cv):.1e} (rel.) |"
    else:
        fig = f"| {rv:.5f} | {cv:.4f} | {abs(rv - cv):.1e} (abs.) |"
    pm = f"{r['pmax']:.5g} / {c['pmax']:.4g} ({rel(r['pmax'], c['pmax']):.1e})" if "pmax" in r else f"– / {c['pmax']:.4g}"
    counts = " | ".join(f"{r.get(k, '–')} / {c.get(k, '–')}" for k in ("ncon", "nadh"))
    return f"| {name} | {case} | {r.get('status', '–')} | {compared} {fig} {pm} | {counts} | {cpu_r} | {cpu_c} |"


def main():
    contact_bin, examples, rollbem, work = sys.argv[1:5]
    example = sys.argv[5] if len(sys.argv) > 5 else None
    os.makedirs(work, exist_ok=True)
    print("| input | case | rollbem status | compared | rollbem | CONTACT | difference | PMAX rollbem / CONTACT (rel.) "
          "| contact elements rollbem / CONTACT | stick elements rollbem / CONTACT | CPU rollbem, input [s] "
          "| CPU CONTACT, input [s] |")
    print("|---|---|---|---|---:|---:|---:|---:|---:|---:|---:|---:|")
    rows = []
    for name, scenes in [("carter2d", [(1, carter_scene())]), ("bentall", bentall_scenes()),
                         ("visc_cylindr", visc_scenes())]:
        printed, cpu_c = run_contact(contact_bin, examples, work, name)
        reference = dict(printed)
        results, cpu_r = [], 0.0
        for case, scene in scenes:
            r, cpu = rollbem_case(rollbem, work, scene)
            results.append((case, r))
            cpu_r += cpu
        for k, (case, r) in enumerate(results):
            c = reference.get(case, {})
            key = "creepage" if "creepage" in c else "fx_over_mu_fn"
            compared = "CREEP X" if key == "creepage" else "FX/(μ FN)"
            cells = (f"{cpu_r:.3g}", f"{cpu_c:.3g}") if k == 0 else ("″", "″")
            rows.append(row(name, case, compared, r, c, key, *cells))
    printed, cpu_c = run_contact(contact_bin, examples, work, "veldep_fric")
    if example:
        ours, cpu_r, scene = run_veldep(example, work, examples)
        cells = (f"{cpu_r:.3g}", f"{cpu_c:.3g}")
    else:
        ours, cells, scene = {}, ("(not run)", f"{cpu_c:.3g}"), veldep_scene()
    diffs = []
    for k, (case, c) in enumerate(printed):
        status, fx, ncon, nadh, pmax = ours.get(case, ("not run", None, None, None, None))
        r = {"status": status, "fx_over_mu_fn": fx}
        if ncon is not None:
            r.update(ncon=ncon, nadh=nadh, pmax=pmax)
        if fx is not None:
            diffs.append((abs(fx - c["fx_over_mu_fn"]), f"{fx:.4f}" == f"{c['fx_over_mu_fn']:.4f}", case))
        if case <= 4 or "ncon" in c:
            rows.append(row("veldep_fric", case, "FX/(μ FN)", r, c, "fx_over_mu_fn", *(cells if k == 0 else ("″", "″"))))
    steps = [d for d in diffs if d[2] >= 5]
    if steps:
        worst = max(steps)
        rows.append(f"| veldep_fric | 5–{max(d[2] for d in steps)} (time steps) | "
                    f"{'converged' if all(ours[d[2]][0] == 'converged' for d in steps) else 'see below'} | FX/(μ FN) "
                    f"| | | max {worst[0]:.1e} (abs., case {worst[2]}); {sum(d[1] for d in steps)} of {len(steps)} "
                    f"equal to the printed digits | | | | ″ | ″ |")
    ref_out = os.path.join(examples, "veldep_fric.ref_out")
    if os.path.exists(ref_out):
        author = dict(contact_cases(ref_out))
        spread = [(abs(c["fx_over_mu_fn"] - author[k]["fx_over_mu_fn"]), k) for k, c in printed if k in author]
        if spread:
            worst = max(spread)
            ours_author = [abs(ours[k][1] - author[k]["fx_over_mu_fn"]) for k, _ in printed if k in author and k in ours]
            vs = f"; rollbem against it: max {max(ours_author):.1e}" if ours_author else ""
            rows.append(f"| veldep_fric | 1–{max(k for _, k in spread)} | | FX/(μ FN): CONTACT (this build) against "
                        f"CONTACT's reference output (examples/veldep_fric.ref_out, the author's build) | | | max "
                        f"{worst[0]:.1e} (case {worst[1]}); {sum(d == 0 for d, _ in spread)} of {len(spread)} equal"
                        f"{vs} | | | | | |")
    print("\n".join(rows))
    print()
    print("CONTACT's printed CREEP X, FX/FSTAT/FN and PMAX have 4 digits: a relative difference below about 5e-4 (an "
          "absolute one below 5e-5 in FX/(μ FN)) is within its printing. carter2d: CONTACT's one case at CKSI = "
          "−0.00024 (rollbem prescribes the creepage, FX/(μ FN) compared). bentall: cases 2–6 (FX prescribed, the "
          "creepage compared). visc_cylindr: its six cases (FX prescribed). veldep_fric (friction falling with the slip "
          "velocity, Vollebregt & Schuttelaars 2012): rollbem's example `veldep_fric` (examples/veldep_fric.rs) runs "
          "the input's 53 cases in order with the same law, starts and CKSI: the steady cases 1 and 3 by "
          "`veldep::solve_steady` from the input's start, the time steps by `veldep::transient::roll`, each from the "
          "previous case's state; rows for cases 1–4 and the cases CONTACT prints in full, the other time steps "
          "summarised. CONTACT stops its outer iteration for the slip velocity when it changes by less than 1e-3 of "
          "its RMS, which moves FX/(μ FN) by up to about 6e-5 (tests/veldep.rs), and two builds of CONTACT differ by "
          "up to 1e-4 on these time steps (the last row): differences of that size are within CONTACT's tolerance. CPU: per input, CONTACT's one run of the whole input and rollbem's "
          "runs of its cases summed (one `rollbem run` per case, a whole process each; veldep_fric one process of the "
          "example), user + sys.")
    return 0


if __name__ == "__main__":
    sys.exit(main())
