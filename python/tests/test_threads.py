"""Solves release the GIL and Ctrl-C interrupts them: shown by the order of events and by counts, not by wall-clock
bounds (a busy machine makes every duration longer, never reorders these events); answers from racing threads are
compared to a tolerance, not bit for bit."""

from __future__ import annotations

import _thread
import signal
import subprocess
import sys
import textwrap
import threading
import time

import numpy as np

import rollbem
from conftest import SCENES, scene

#: Two certified answers of one problem agree to this fraction of the peak pressure: src/tolerances.rs
#: SOLVER_AGREEMENT, the tolerance the harness's own checks hold two solvers' tractions to. Every run compared here
#: is certified by the solver-independent residuals (status `solved`, residual <= RESIDUAL_REFUSE = 1e-8), so an
#: answer that differs by more is a wrong answer, not round-off.
AGREEMENT = 1e-6
#: src/tolerances.rs RESIDUAL_REFUSE: a run whose largest residual exceeds it is refused by the harness.
RESIDUAL_REFUSE = 1e-8

#: How long a helper waits for an event that must come before failing the test (a guard against hanging, not a
#: bound on how fast anything is: on a sound build the events come in milliseconds to seconds).
PATIENCE_S = 120.0


def wait_until_idle(settle_s: float = 0.2, quantum_s: float = 0.02) -> None:
    """Wait until this process stops using CPU (its background worker threads have nothing left to do): until the
    process's CPU time grows by less than a quarter of a window of `settle_s` while this thread sleeps."""
    deadline = time.monotonic() + PATIENCE_S
    while time.monotonic() < deadline:
        c0, t0 = time.process_time(), time.monotonic()
        while time.monotonic() - t0 < settle_s:
            time.sleep(quantum_s)
        if time.process_time() - c0 < 0.25 * settle_s:
            return
    raise AssertionError(f"the process was still busy after {PATIENCE_S} s")


def test_the_gil_is_released_during_a_solve() -> None:
    # Order of events: a Python thread, woken just before the main thread calls `solve`, finishes a little Python
    # work (`work` loop iterations, ~2 ms) before the main thread sees `solve` return. The interpreter's switch interval
    # is set to 30 s for the test, so the main thread hands the GIL over only where it lets go of it itself: inside
    # `solve`, if the binding releases it there. With the GIL held for the whole solve (~1 s: Lemke on 800
    # frictional elements; the helper's work is 1/500 of it, room for a busy machine to hold the helper back), the
    # helper could not run a bytecode until after `during` was read (checked by holding the GIL in
    # `sum(range(3 * 10**7))` instead of solving: `during` is then False).
    s = scene("carter-steady-rolling", solvers__use=["lemke"], mesh__contact_elements=800)
    model = rollbem.Model(s)
    work = 50_000
    go, finished = threading.Event(), threading.Event()

    def helper() -> None:
        go.wait()
        n = 0
        for _ in range(work):
            n += 1
        if n == work:
            finished.set()

    t = threading.Thread(target=helper)
    interval = sys.getswitchinterval()
    sys.setswitchinterval(30.0)
    try:
        t.start()
        go.set()
        model.solve()
        during = finished.is_set()
    finally:
        sys.setswitchinterval(interval)
        t.join()
    assert during, "the helper thread could not run while the solve ran: the GIL was held"


def test_ctrl_c_stops_a_list_of_drives_before_the_next_drive() -> None:
    # Lemke, 400 drives (10-20 ms each here). The interrupt comes from a helper once the third drive has started
    # (ordered by the model's count of solves, not by a timer), the way Ctrl-C does it: SIGINT's flag for the main
    # thread. The worker checks the flag before each drive, so after the KeyboardInterrupt at most the drive that
    # had passed its check when the flag rose starts: the count of solves grows by at most 1, however long we wait.
    s = scene("carter-steady-rolling", solvers__use=["lemke"])
    model = rollbem.Model(s)
    drives = [{"creepage": 1e-5 * (k + 1)} for k in range(400)]
    started = threading.Event()

    def interrupt_when_started() -> None:
        deadline = time.monotonic() + PATIENCE_S
        while model.solves < 3 and time.monotonic() < deadline:
            time.sleep(0.001)
        started.set()
        _thread.interrupt_main()

    helper = threading.Thread(target=interrupt_when_started)
    interrupted = False
    # A runner started in the background (nohup, `&`) hands pytest SIGINT ignored, and interrupt_main then does
    # nothing: Python's own handler for the duration of the test.
    previous = signal.signal(signal.SIGINT, signal.default_int_handler)
    helper.start()
    try:
        model.solve_all(drives)
    except KeyboardInterrupt:
        interrupted = True
    finally:
        helper.join()
        signal.signal(signal.SIGINT, previous)
    assert started.is_set() and interrupted, "the list ended before the interrupt"
    done = model.solves
    assert 3 <= done < len(drives)
    wait_until_idle()  # the worker has finished the drive in progress and stopped (or, if it went on, the whole list)
    assert model.solves - done <= 1, (done, model.solves)


LONG_SOLVE = textwrap.dedent(
    """
    import signal, sys, threading, time, rollbem
    signal.signal(signal.SIGINT, signal.default_int_handler)  # even when the runner was started with SIGINT ignored
    s = rollbem.Scene.from_file(sys.argv[1]).edit({"mesh.contact_elements": 800, "solvers.use": ["pgs"]})
    if sys.argv[2] == "path":  # a fretting path of 2000 substeps on a static frictional copy of the scene
        s = s.edit({"rolling": None, "mesh.contact_elements": 120, "solvers.use": ["lemke"]})
        m = rollbem.Model(s)
        steps = [{"normal_load": 2e4}, {"normal_load": 2e4, "tangential_load": 3e3, "substeps": 1000},
                 {"normal_load": 2e4, "tangential_load": -3e3, "substeps": 1000}]
        work = lambda: m.solve_path(steps)
    else:
        m = rollbem.Model(s)
        work = lambda: m.solve()

    def announce():  # "solving" once the solve has started (the model counts a solve when it starts it)
        while m.solves == 0:
            time.sleep(0.001)
        print("solving", flush=True)

    def idle():  # wait (up to 60 s) until the process uses no more CPU: under 20 ms in a 200 ms window
        deadline = time.monotonic() + 60
        while time.monotonic() < deadline:
            c = time.process_time()
            time.sleep(0.2)
            if time.process_time() - c < 0.02:
                return

    threading.Thread(target=announce, daemon=True).start()
    try:
        work()
        print("solved", m.solves, flush=True)
    except KeyboardInterrupt:
        # The solve is cancelled (README "Threads and Ctrl-C"): its worker stops at its next pivot. The CPU time the
        # process uses from here until it is idle, against the CPU time of the same solve run to its end afterwards.
        c0 = time.process_time()
        idle()
        after = time.process_time() - c0
        c1 = time.process_time()
        work()
        whole = time.process_time() - c1
        print("interrupted", m.solves, after < 0.25 * whole, f"{after:.3f}", f"{whole:.3f}", flush=True)
    """
)


def test_ctrl_c_cancels_a_long_single_solve() -> None:
    # One solve of a few seconds (NORM-TANG with PGS sweeps on 800 elements, steady rolling: its cancellation points
    # are its sweeps, thousands of them), interrupted by SIGINT once it has started. The
    # caller gets KeyboardInterrupt and the solve's worker stops within a pivot: the CPU time used after the
    # interrupt is a small fraction of what the whole solve takes (measured in the same process right after, so the
    # ratio does not depend on the machine). Before cancellation reached the solvers, the worker ran the solve on to
    # its end in the background (a fraction near 1).
    line = interrupted_run("solve")
    assert line[:3] == ["interrupted", "2", "True"], line


def test_ctrl_c_cancels_a_load_path_and_leaves_no_thread_working() -> None:
    # A load path of 2000 substeps, interrupted once it has started: the walk stops before its next substep (and the
    # solver at its next iteration), so the process goes idle at once; measured as above against the whole path.
    line = interrupted_run("path")
    assert line[:3] == ["interrupted", "2", "True"], line


def interrupted_run(mode: str) -> list:
    """Run LONG_SOLVE in `mode` in a child process, SIGINT it once its work has started; its report line."""
    p = subprocess.Popen(
        [sys.executable, "-c", LONG_SOLVE, str(SCENES / "carter-steady-rolling.toml"), mode],
        stdout=subprocess.PIPE,
        text=True,
    )
    try:
        assert p.stdout is not None
        assert p.stdout.readline().strip() == "solving"
        p.send_signal(signal.SIGINT)
        line = p.stdout.readline().split()
        p.wait(timeout=PATIENCE_S)
    finally:
        p.kill()
    assert p.returncode == 0, line
    return line


def test_a_model_solves_from_several_threads() -> None:
    # A model is shared by threads (each solve on its own worker), started together; each answer is certified and
    # agrees with the serial solve of the same drive to AGREEMENT of the peak pressure, node by node.
    s = scene("carter-steady-rolling", solvers__use=["active_set"])
    model = rollbem.Model(s)
    xis = [1e-3, 2e-3, 1e-3, 2e-3]
    serial = {x: model.solve(creepage=x).run() for x in set(xis)}
    out: list = [None] * len(xis)
    barrier = threading.Barrier(len(xis))

    def work(k: int) -> None:
        barrier.wait()
        out[k] = model.solve(creepage=xis[k]).run()

    threads = [threading.Thread(target=work, args=(k,)) for k in range(len(xis))]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    for x, run in zip(xis, out):
        ref = serial[x]
        assert run is not None and run.status == ref.status == "solved", run
        assert run.residual is not None and run.residual <= RESIDUAL_REFUSE
        scale = AGREEMENT * ref.pressure.max()
        np.testing.assert_allclose(run.pressure, ref.pressure, rtol=0, atol=scale)
        np.testing.assert_allclose(run.shear, ref.shear, rtol=0, atol=scale)
        width = ref.x.max() - ref.x.min()
        assert abs(run.tangential_load - ref.tangential_load) <= scale * width, (x, run.tangential_load)
