"""The Python API's shapes: scenes from text, files and dicts; models built once; result arrays (shapes, dtypes,
state codes); the report as a dict; load-path histories; stresses as 2D arrays."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest

import rollbem
from conftest import SCENES, scene

HALF_PLANE = {
    "name": "hp",
    "units": "N, mm, MPa",
    "wheel": {"radius": 460.0, "youngs_modulus": 210000.0, "poisson_ratio": 0.3, "model": "half_plane"},
    "mesh": {"element": "constant", "contact_half_width": 9.0, "contact_elements": 60},
    "drive": {"normal_load": 20000.0},
    "solvers": {"use": ["lemke", "active_set"]},
}


def test_scene_from_text_file_dict_and_keywords_are_one_scene() -> None:
    path = SCENES / "half-plane-hertz.toml"
    a = rollbem.Scene.from_file(path)
    b = rollbem.Scene.from_toml(path.read_text())
    c = rollbem.Scene.from_dict(a.to_dict())
    d = rollbem.Scene.from_dict(**a.to_dict())
    e = rollbem.Scene.from_toml(a.to_toml())
    assert a == b == c == d == e
    assert a.origin == path and c.origin == Path("<scene>")
    assert (a.name, a.model, a.element, a.rolling, a.units) == ("half-plane-hertz", "half_plane", "constant", None, "N, mm, MPa")
    assert a.radius == 460.0 and a.friction == 0.0
    # A strip of half-spaces (CONTACT's 2D model) is a mesh key; plane strain without it.
    assert a.strip_width is None and a.edit({"mesh.strip_width": 200.0}).strip_width == 200.0
    # E* of a rigid flat: E/(1 - nu^2).
    assert a.contact_modulus == pytest.approx(210000.0 / (1 - 0.09), rel=1e-15)
    # Keywords override the mapping's top-level tables.
    f = rollbem.Scene.from_dict(HALF_PLANE, drive={"normal_approach": 0.05})
    assert f.drive == {"normal_approach": 0.05}


def test_edit_with_drive_and_with_steps() -> None:
    s = rollbem.Scene.from_dict(HALF_PLANE)
    t = s.edit({"contact.friction": 0.3, "drive.tangential_load": 1000.0, "units": None})
    assert t.friction == 0.3 and t.drive == {"normal_load": 20000.0, "tangential_load": 1000.0} and t.units is None
    # A drive key replaces its degree of freedom and keeps the others.
    u = t.with_drive(normal_approach=0.1)
    assert u.drive == {"normal_approach": 0.1, "tangential_load": 1000.0}
    # Creepage and tangential load replace each other in steady rolling.
    c = scene("carter-steady-rolling")
    assert c.rolling == "steady" and c.creepage == 0.0015
    q = c.with_drive(tangential_load=-1000.0)
    assert q.creepage is None and q.drive["tangential_load"] == -1000.0
    assert q.with_drive(creepage=1e-3).creepage == 1e-3 and "tangential_load" not in q.with_drive(creepage=1e-3).drive
    assert c.with_creepage(2e-3).creepage == 2e-3
    p = s.with_steps([{"normal_load": 1000.0, "substeps": 2}, {"normal_load": 2000.0}])
    assert p.steps == [{"normal_load": 1000.0, "substeps": 2}, {"normal_load": 2000.0}] and p.drive == {}
    assert p.with_drive(normal_load=5.0).steps == []


def test_node_arrays_shapes_dtypes_and_states() -> None:
    report = rollbem.run(scene("carter-steady-rolling"), check=True)
    assert len(report) == 3 and [r.solver for r in report.runs] == ["lemke", "active_set", "pgs"]
    run = report.run("active_set")
    n = report.mesh["contact_nodes"]
    assert n == 200 == run.n_nodes
    for name in ("x", "y", "pressure", "shear", "gap", "slip", "u_x", "u_y", "slip_velocity"):
        a = getattr(run, name)
        assert isinstance(a, np.ndarray) and a.shape == (n,) and a.dtype == np.float64, name
    assert run.state.shape == (n,) and run.state.dtype == np.int8
    assert rollbem.NODE_STATES == ["stick", "slip", "contact", "separated"]
    assert [rollbem.NODE_STATES[k] for k in run.state] == run.state_names
    assert set(run.state_names) == {"stick", "slip", "separated"}
    # Separated nodes carry no pressure; steady rolling's slip is a velocity (`slip_velocity`), so the slip
    # displacement is NaN (not computed) at every node.
    sep = run.state == 3
    assert np.all(run.pressure[sep] == 0) and np.all(np.isnan(run.slip))
    # Coulomb: |q| <= mu p, with equality (to round-off) where the node slips.
    mu = 0.3
    assert np.all(np.abs(run.shear) <= mu * run.pressure * (1 + 1e-9) + 1e-9)
    slip = run.state == 1
    np.testing.assert_allclose(np.abs(run.shear[slip]), mu * run.pressure[slip], rtol=1e-9)
    # Steady rolling: the slip velocity is known everywhere in contact.
    assert not np.any(np.isnan(run.slip_velocity[~sep]))
    # Resultants and rigid motion are floats; residuals are attributes.
    assert isinstance(run.normal_load, float) and isinstance(run.tangential_shift, float)
    assert run.normal_load == pytest.approx(run.to_dict()["resultants"]["normal"])
    r = run.residuals
    assert r is not None and r.max == run.residual and r.max < 1e-9 and r.friction is not None
    assert (run.status, run.termination, run.verdict, run.solved) == ("solved", "solved", None, True)
    assert set(run.timing) == {"assembly", "condensation", "formulation", "solve", "total", "setup"}
    assert run.work and all(isinstance(v, int) for v in run.work.values())


def test_report_as_dict_and_json_round_trip() -> None:
    report = rollbem.run(scene("hertz-hub-fine", solvers__use=["lemke", "clarabel"]))
    d = report.to_dict()
    assert d["schema"] == rollbem.SCHEMA_VERSION
    assert [r["solver"] for r in d["runs"]] == ["lemke", "clarabel"]
    assert report.run("clarabel").to_dict() == d["runs"][1]
    assert report.hertz == d["references"]["hertz"] and report.hertz["load"] == 20000.0
    assert report.all_pass and report.ok and report.checks == d["checks"]
    again = rollbem.Report.from_json(report.to_json(indent=2))
    assert json.loads(again.to_json()) == json.loads(report.to_json())
    assert report.scene == scene("hertz-hub-fine", solvers__use=["lemke", "clarabel"])
    with pytest.raises(KeyError, match="pgs"):
        report.run("pgs")


def test_model_is_built_once_and_refuses_other_bodies() -> None:
    s = rollbem.Scene.from_dict(HALF_PLANE)
    model = rollbem.Model(s)
    loads = [500.0, 1000.0, 2000.0]
    reports = model.solve_all([{"normal_load": p} for p in loads])
    assert model.solves == 3 and model.accepts(s) and set(model.build_time) == {"assembly", "condensation"}
    for p, r in zip(loads, reports):
        assert r.run().normal_load == pytest.approx(p, rel=1e-12)
    one = model.solve(normal_load=1000.0)
    assert one.run().normal_load == pytest.approx(1000.0, rel=1e-12)
    assert model.solve(s.with_drive(normal_load=1000.0)).run().normal_load == pytest.approx(1000.0, rel=1e-12)
    other = s.edit({"mesh.contact_elements": 61})
    assert not model.accepts(other)
    with pytest.raises(rollbem.InputError) as e:
        model.solve(other)
    assert e.value.key == "mesh"


def test_load_path_history() -> None:
    s = scene("md-fretting-loop", solvers__use=["lemke"])
    report = rollbem.Model(s).solve_path(s.steps)
    h = report.history()
    n = 1 + 10 + 20 + 20
    for k in ("step", "substep", "rolled", "normal_load", "tangential_load", "tangential_shift", "dissipated"):
        assert h[k].shape == (n,), k
    assert h["step"].dtype == np.int64 and h["tangential_load"].dtype == np.float64
    assert h["tangential_load"][10] == pytest.approx(3000.0) and h["tangential_load"][30] == pytest.approx(-3000.0)
    assert [st.substep for st in report.steps[:3]] == [1, 1, 2]
    # A static path computes the slip displacement where the nodes touch, NaN where they are separated.
    last = report.run()
    sep = last.state == 3
    assert np.all(np.isnan(last.slip[sep])) and not np.any(np.isnan(last.slip[~sep])) and np.any(sep)
    assert np.all(np.isnan(last.slip_velocity))  # no [rolling]
    assert report.steps[5].drive["tangential"] == {"Load": pytest.approx(1500.0)}
    assert report.history("pgs")["step"].shape == (0,)  # no run of pgs: empty arrays


def test_stresses_are_2d_arrays() -> None:
    report = rollbem.run(scene("stresses-hertz-hub"), check=True)
    st = report.run().stresses
    assert st is not None
    nz, nx = st.shape
    assert st.x.shape == (nx,) and st.depth.shape == (nz,)
    for q in st.quantities:
        assert q in st and st[q].shape == (nz, nx) and st[q].dtype == np.float64
    assert set(st.maxima) == set(st.quantities)
    with pytest.raises(KeyError):
        st["nonsense"]
    # The maximum of von Mises is the largest value on the grid, where it says.
    vm = st["von_mises"]
    m = st.maxima["von_mises"]
    j, i = np.unravel_index(np.nanargmax(np.abs(vm)), vm.shape)
    assert m["value"] == vm[j, i] and m["x"] == st.x[i] and m["depth"] == st.depth[j]
