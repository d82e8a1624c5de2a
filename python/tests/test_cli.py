"""The Python API gives the same answer as the command line: `rollbem run SCENE --json -` parsed with `json`, node
by node, every solver, to 1e-12 of the peak pressure (the same library code runs in both, so the difference is
round-off at most; measured 0)."""

from __future__ import annotations

import json
import subprocess
from typing import Any, Dict, List, Optional

import numpy as np
import pytest

import rollbem
from conftest import SCENES

# (scene, the CLI's --solver, or None for the scene's own solvers)
CASES = [
    ("hertz-hub-fine", None),  # a BEM wheel, frictionless, five solvers
    ("carter-steady-rolling", None),  # steady rolling with friction, three solvers
    ("stresses-hertz-hub", None),  # a BEM wheel with its subsurface stresses
    ("md-fretting-loop", "active_set"),  # a load path, 51 substeps
]


def cli_document(cli: str, name: str, solver: Optional[str]) -> Dict[str, Any]:
    cmd = [cli, "run", str(SCENES / f"{name}.toml"), "--json", "-", "--quiet"]
    if solver:
        cmd += ["--solver", solver]
    out = subprocess.run(cmd, check=True, capture_output=True, text=True)
    return json.loads(out.stdout)


def compare_runs(cli_runs: List[Dict[str, Any]], py_runs: List[rollbem.Run]) -> None:
    assert [r["solver"] for r in cli_runs] == [r.solver for r in py_runs]
    for c, p in zip(cli_runs, py_runs):
        assert c["status"] == p.status
        # The arrays are the answer: the document's nodes of a solved run, none otherwise (the document keeps a
        # refused answer as evidence).
        nodes = c["nodes"] if c["status"] == "solved" else []
        scale = max([n["pressure"] for n in nodes] + [1e-300])
        tol = 1e-12 * scale
        np.testing.assert_array_equal(np.array([n["x"] for n in nodes]), p.x)
        np.testing.assert_allclose(p.pressure, [n["pressure"] for n in nodes], rtol=0, atol=tol)
        np.testing.assert_allclose(p.shear, [n["shear"] for n in nodes], rtol=0, atol=tol)
        np.testing.assert_allclose(p.gap, [n["gap"] for n in nodes], rtol=0, atol=1e-12 * max(abs(p.gap).max(), 1e-300))
        assert list(p.state_names) == [n["state"] for n in nodes]
        if c["resultants"] is not None:
            assert p.normal_load == pytest.approx(c["resultants"]["normal"], rel=1e-12, abs=tol)
            assert p.tangential_load == pytest.approx(c["resultants"]["tangential"], rel=1e-12, abs=tol)


@pytest.mark.parametrize("name,solver", CASES)
def test_same_tractions_as_the_cli_json(cli: str, name: str, solver: Optional[str]) -> None:
    doc = cli_document(cli, name, solver)
    s = rollbem.Scene.from_file(SCENES / f"{name}.toml")
    if solver:
        s = s.edit({"solvers.use": [solver]})
    report = rollbem.run(s)
    assert doc["schema"] == rollbem.SCHEMA_VERSION == report.to_dict()["schema"]
    compare_runs(doc["runs"], report.runs)
    assert len(doc.get("steps", [])) == len(report.steps)
    for cs, ps in zip(doc.get("steps", []), report.steps):
        assert (cs["step"], cs["substep"]) == (ps.step, ps.substep)
        compare_runs(cs["runs"], ps.runs)
    for c, p in zip(doc["runs"], report.runs):
        if c.get("stresses"):
            st = p.stresses
            assert st is not None
            for q in st.quantities:
                want = np.array([np.nan if v is None else v for v in c["stresses"]["field"]["values"][q]])
                np.testing.assert_allclose(st[q].ravel(), want, rtol=1e-12, atol=1e-12 * np.nanmax(abs(want)))
    # The whole document matches too, timings aside.
    mine = report.to_dict()
    for d in (doc, mine):
        for run in d["runs"] + [r for st in d.get("steps", []) for r in st["runs"]]:
            run.pop("timing_s")
            if run.get("stresses"):
                run["stresses"].pop("time_s")
    assert json.dumps(mine["runs"], sort_keys=True) == json.dumps(doc["runs"], sort_keys=True)
