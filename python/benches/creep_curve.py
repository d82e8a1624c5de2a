"""Benchmark: a 50-point creep curve from Python against the same curve through the Rust API.

    python python/benches/creep_curve.py [--rounds N] [--solver NAME]

Both sides build the model of the reference Carter scene (half-plane, 200 elements) once and solve it at the same 50
creepages, the solver `active_set` unless told otherwise:

- **Rust**: `rollbem._core._rust_creep_curve`, a loop in Rust over the library's API (`Model::build`, then
  `model.solve(&scene.with_creepage(xi)?)` per point, `resultants.tangential` read), the README's "Use as a library"
  loop; compiled into the same extension, so both sides run the same machine code of the library, and no Python
  runs between its solves. `rust` runs it on the calling (main) thread, as a Rust program would; `rust_on_worker`
  on the binding's worker thread, where the Python side's solves run (the two differ by the allocator's behaviour
  on the main thread and on another thread, not by anything Python does).
- **Python, one call**: `rollbem.Model(scene)` then `model.solve_all([{"creepage": xi} ...])` and
  `r.run().tangential_load` for each report (what a notebook does).
- **Python, a call per point**: `model.solve(creepage=xi)` in a Python loop (50 calls, each handed to the
  binding's kept worker thread).

The sides run interleaved, `rounds` times each (after one warm-up round), and the medians are compared, of the wall
time and of the process's CPU time (all threads; less sensitive to other work on a shared machine); the curves must
agree to round-off (1e-12 of max |Q|). `solve_all` starts each creepage from the previous one's solution
(`rollbem::pipeline::Warm`) and the other sides from rest, so `python_one_call` does less work than `rust` (measured
0.12 of its time): compare `python_per_point` with `rust` for the cost of the binding. The ratio asked for (issue 22)
is Python / Rust <= 1.2.
"""

from __future__ import annotations

import argparse
import statistics
import time
from pathlib import Path

import numpy as np

import rollbem
from rollbem._core import _rust_creep_curve

SCENE = Path(__file__).resolve().parents[2] / "reference" / "scenes" / "carter-steady-rolling.toml"


def python_one_call(scene: rollbem.Scene, xis: list) -> tuple:
    start = time.perf_counter()
    model = rollbem.Model(scene)
    reports = model.solve_all([{"creepage": x} for x in xis])
    q = [r.run().tangential_load for r in reports]
    return time.perf_counter() - start, q


def python_per_point(scene: rollbem.Scene, xis: list) -> tuple:
    start = time.perf_counter()
    model = rollbem.Model(scene)
    q = [model.solve(creepage=x).run().tangential_load for x in xis]
    return time.perf_counter() - start, q


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--rounds", type=int, default=15)
    ap.add_argument("--solver", default="active_set")
    args = ap.parse_args()
    scene = rollbem.Scene.from_file(SCENE).edit({"solvers.use": [args.solver]})
    xis = [float(x) for x in np.linspace(1e-4, 6e-3, 50)]
    sides = {
        "rust": lambda: _rust_creep_curve(scene, xis),
        "rust_on_worker": lambda: _rust_creep_curve(scene, xis, True),
        "python_one_call": lambda: python_one_call(scene, xis),
        "python_per_point": lambda: python_per_point(scene, xis),
    }
    reference = None
    for k, f in sides.items():  # warm-up, and the curves must agree
        _, q = f()
        reference = q if reference is None else reference
        # `solve_all` starts each creepage from the previous one's solution (rollbem::pipeline::Warm), the others
        # from rest: the same certified answer reached by another pivoting path, so equal to round-off (measured
        # 6e-15 of max |Q|), not bit for bit.
        scale = max(abs(v) for v in reference)
        worst = max(abs(a - b) for a, b in zip(q, reference))
        assert worst <= 1e-12 * scale, f"the curves differ: {k} by {worst / scale:.1e} of max |Q|"
    wall = {k: [] for k in sides}
    cpu = {k: [] for k in sides}
    for _ in range(args.rounds):
        for k, f in sides.items():
            c = time.process_time()
            wall[k].append(f()[0])
            cpu[k].append(time.process_time() - c)
    rust_wall, rust_cpu = statistics.median(wall["rust"]), statistics.median(cpu["rust"])
    print(f"50-point creep curve, {SCENE.name}, solver {args.solver}, {args.rounds} rounds, medians [ms]:")
    print(f"  {'':17s} {'wall':>8s} {'(min)':>8s} {'cpu':>8s}   wall/rust  cpu/rust")
    for k in sides:
        w, c = statistics.median(wall[k]), statistics.median(cpu[k])
        print(
            f"  {k:17s} {w * 1e3:8.1f} {min(wall[k]) * 1e3:8.1f} {c * 1e3:8.1f}   "
            f"{w / rust_wall:9.3f} {c / rust_cpu:9.3f}"
        )


if __name__ == "__main__":
    main()
