"""A solver written in Python, plugged in with one call (issue 31: adding a solver is one file and one registry
line; tests/solver_plugin.rs does the same with a Rust solver through the CLI). The solver here is projected
Gauss–Seidel on the LCP in NumPy; its answers are compared with Lemke's on the same scenes (an independent solver)
to 1e-6 of the peak pressure, and rollbem certifies every run of it by its own residuals."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

import rollbem

from conftest import scene


def lcp_pgs(m: np.ndarray, q: np.ndarray) -> np.ndarray:
    """Projected Gauss–Seidel on w = M z + q >= 0, z >= 0, w.z = 0 (M with a positive diagonal)."""
    z = np.zeros_like(q)
    for _ in range(100_000):
        change, scale = 0.0, 0.0
        for i in range(len(q)):
            new = max(0.0, z[i] - (q[i] + m[i] @ z) / m[i, i])
            change, scale = max(change, abs(new - z[i])), max(scale, new)
            z[i] = new
        if change <= 1e-13 * scale:
            break
    return z


# The one registry line (a second registration of the name would be refused: tested below).
rollbem.register_solver("py_pgs", lcp_pgs, summary="projected Gauss-Seidel in NumPy (a test plug-in)")


def hertz_scene(*solvers: str) -> rollbem.Scene:
    """Hertz on the half-plane, the approach prescribed (a frictionless LCP without load rows), 40 elements."""
    return scene(
        "half-plane-hertz",
        drive={"normal_approach": 0.15},
        mesh__contact_elements=40,
        solvers__use=list(solvers),
    )


def test_a_python_solver_runs_through_the_model_and_agrees_with_lemke() -> None:
    report = rollbem.Model(hertz_scene("py_pgs", "lemke")).solve()
    plugin, lemke = report.run("py_pgs"), report.run("lemke")
    assert plugin.status == lemke.status == "solved", plugin.explanation
    assert plugin.residuals.max <= 1e-10
    np.testing.assert_allclose(plugin.pressure, lemke.pressure, rtol=0, atol=1e-6 * lemke.pressure.max())


def test_a_python_solver_is_refused_where_it_does_not_apply_and_a_wrong_answer_is_not_solved() -> None:
    with pytest.raises(rollbem.InputError) as e:
        scene("half-plane-hertz", contact__friction=0.3, solvers__use=["py_pgs"])
    assert e.value.key == "solvers.use" and "py_pgs" in str(e.value)
    with pytest.raises(ValueError):
        rollbem.register_solver("py_pgs", lcp_pgs)
    with pytest.raises(ValueError):
        rollbem.register_solver("Bad Name", lcp_pgs)
    with pytest.raises(TypeError):
        rollbem.register_solver("not_callable", 3)
    # A solver that returns garbage is not `solved`: rollbem's own residuals refuse it.
    try:
        rollbem.register_solver("py_zero", lambda m, q: np.zeros_like(q))
    except ValueError:
        pass
    run = rollbem.Model(hertz_scene("py_zero")).solve().run("py_zero")
    assert run.status == "numerical_error", run.status


def test_a_python_solver_runs_through_the_sweep(tmp_path: Path) -> None:
    base = tmp_path / "hertz.toml"
    base.write_text(hertz_scene("py_pgs", "lemke").to_toml())
    spec = tmp_path / "sweep.toml"
    spec.write_text('name = "py-plugin"\nbase = "hertz.toml"\n[[grid]]\n"drive.normal_approach" = [0.1, 0.15]\n')
    rows = rollbem.sweep(str(spec))
    plugin = [r for r in rows if r["solver"] == "py_pgs"]
    assert len(plugin) == 2 and all(r["status"] == "solved" for r in plugin), plugin
