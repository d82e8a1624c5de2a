"""The Python API's shapes: scenes from text, files and dicts; models built once; result arrays (shapes, dtypes,
state codes), made once per run and read-only, and absent for a run without an answer; the report as a dict;
load-path histories and step drives in the scene's vocabulary; stresses as 2D arrays; Dundurs' beta and its sign."""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np
import pytest

import rollbem
from conftest import REPO, SCENES, scene

NODE_ARRAYS = ("x", "y", "pressure", "shear", "gap", "slip", "u_x", "u_y", "slip_velocity", "state")

# tests/trust.rs (item 1): a steel wheel (R = 0.46 m) whose Hertz contact at P = 1e7 N/m (a = 5.04 mm) is wider than
# its 1-degree candidate zone: the discrete answer presses on the zone's last nodes, and the harness refuses it
# (`contact_at_zone_edge`), keeping the nodes as the verdict's evidence.
ZONE_EDGE = """
name = "steel-arc1"
[wheel]
radius = 0.46
youngs_modulus = 210e9
poisson_ratio = 0.3
support = { kind = "hub", radius = 0.1 }
[mesh]
element = "constant"
contact_arc_deg = 1.0
contact_elements = 100
other_elements = 120
[contact]
friction = 0.0
[drive]
normal_load = 1e7
[solvers]
use = ["lemke"]
"""

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
    assert tuple(rollbem.NODE_STATES[k] for k in run.state) == run.state_names
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
    # A solver the report has no run of is a KeyError, as `report.run` raises it.
    with pytest.raises(KeyError, match="no run of solver 'pgs'"):
        report.history("pgs")


def test_a_refused_run_has_no_node_arrays() -> None:
    # A run the harness refused keeps the refused answer as evidence in the document, not in the arrays: every node
    # array is empty and every figure derived from the nodes says "none", as `stick_zone` (which reads the answer
    # nodes, `SolverRun::answer_nodes`) always did. Two refusals: a contact cut off by the candidate zone
    # (frictionless) and a moment the linearised kinematics cannot carry (frictional: the evidence has sticking
    # nodes, so old arrays showed a stick zone that `stick_zone` denied).
    edge = rollbem.run(rollbem.Scene.from_toml(ZONE_EDGE)).run()
    moment = rollbem.run(
        rollbem.Scene.from_file(REPO / "reference" / "hard" / "moment-nearly-overturning.toml").edit(
            {"solvers.use": ["lemke"]}
        )
    ).run()
    assert (edge.status, moment.status) == ("contact_at_zone_edge", "kinematics_out_of_range")
    for run, n in ((edge, 100), (moment, 60)):
        assert not run.solved and run.n_nodes == 0, run.status
        for name in NODE_ARRAYS:
            a = getattr(run, name)
            assert a.shape == (0,), (run.status, name)
        assert run.state.dtype == np.int8 and run.pressure.dtype == np.float64
        assert run.state_names == () and run.stick_zone is None and run.stresses is None
        assert run.normal_load is None and run.contact is None and run.residuals is None
        # The evidence is in the document: the refused answer, node by node.
        evidence = run.to_dict()["nodes"]
        assert len(evidence) == n
    # The zone-edge evidence presses on both ends of the zone (tests/trust.rs item 1), and the moment's evidence has
    # sticking nodes: what the arrays must not pass off as an answer.
    nodes = edge.to_dict()["nodes"]
    assert nodes[0]["pressure"] > 0 and nodes[-1]["pressure"] > 0
    assert "stick" in [n["state"] for n in moment.to_dict()["nodes"]]
    # A solved run of the same scene family has them all (contact inside a wider zone: trust.rs's advice).
    wide = rollbem.Scene.from_toml(ZONE_EDGE).edit({"mesh.contact_arc_deg": 2.0})
    ok = rollbem.run(wide).run()
    assert ok.status == "solved" and ok.n_nodes == 100 and ok.pressure.shape == (100,)


def test_arrays_are_made_once_and_read_only() -> None:
    # A run's arrays are made on first access and kept: the same object on every access, so a loop over
    # `run.pressure[i]` reads one array. Kept arrays are read-only, so one caller cannot change what another reads.
    report = rollbem.run(scene("stresses-hertz-hub"), check=True)
    run = report.run()
    assert report.run() is run and report.runs[0] is run and report.runs is report.runs
    for name in NODE_ARRAYS + ("state_names",):
        assert getattr(run, name) is getattr(run, name), name
    for name in NODE_ARRAYS:
        a = getattr(run, name)
        assert not a.flags.writeable, name
        with pytest.raises(ValueError):
            a[0] = 1
        with pytest.raises(ValueError):  # the arrays do not own their memory: the flag cannot be set back
            a.flags.writeable = True
    # A copy is the caller's own.
    mine = run.pressure.copy()
    mine[0] = -1.0
    assert run.pressure[0] != -1.0
    st = run.stresses
    assert st is not None and run.stresses is st
    for q in st.quantities:
        assert st[q] is st[q] and not st[q].flags.writeable
        assert st.surface(q) is st.surface(q)
    assert st.x is st.x and st.depth is st.depth and st.surface_x is st.surface_x and not st.x.flags.writeable
    # A load path's steps, their runs and the history arrays too (the dict is new, the arrays in it are kept).
    s = scene("md-fretting-loop", solvers__use=["lemke"])
    path = rollbem.Model(s).solve_path(s.steps)
    assert path.steps is path.steps and path.steps[3].runs is path.steps[3].runs
    assert path.steps[3].runs[0].shear is path.steps[3].runs[0].shear
    h1, h2 = path.history(), path.history("lemke")
    assert h1 is not h2 and all(h1[k] is h2[k] for k in h1)
    assert not h1["tangential_load"].flags.writeable


def test_step_drive_speaks_the_scene_vocabulary() -> None:
    # A substep's drive has the keys of a scene's `[drive]` (not the document's serde tags), so it can be given back
    # as a drive: `Scene.with_drive` and `Model.solve` accept it.
    s = scene("md-fretting-loop", solvers__use=["lemke"])
    model = rollbem.Model(s)
    report = model.solve_path(s.steps)
    assert report.steps[0].drive == {"normal_load": 20000.0}
    assert report.steps[5].drive == {"normal_load": pytest.approx(20000.0), "tangential_load": pytest.approx(1500.0)}
    keys = {"normal_approach", "normal_load", "tangential_shift", "tangential_load", "rotation", "moment"}
    for st in report.steps:
        assert set(st.drive) <= keys, st.drive
        s.with_drive(**st.drive)  # validated like a scene file
    # Solved from rest at the first step's end: Q is the prescribed load, to LOAD_RESULTANT (1e-10, src/tolerances.rs:
    # the equilibrium rows are part of the LCP).
    end = report.steps[10]
    assert (end.step, end.substep) == (1, 10)
    again = model.solve(end.drive).run()
    assert again.tangential_load == pytest.approx(3000.0, rel=1e-10)
    # A scene's drive and steps use the same keys.
    assert set(scene("half-plane-hertz").drive) == {"normal_load"}


def dundurs_beta(e1: float, nu1: float, e2: float, nu2: float) -> float:
    """Dundurs (1969), plane strain, computed here: beta = [(1-2nu1)/G1 - (1-2nu2)/G2] / [2((1-nu1)/G1 + (1-nu2)/G2)],
    G = E/(2(1+nu)); a rigid body has 1/G = 0 (e = inf)."""
    k1 = 0.0 if math.isinf(e1) else 2 * (1 + nu1) / e1
    k2 = 0.0 if math.isinf(e2) else 2 * (1 + nu2) / e2
    return ((1 - 2 * nu1) * k1 - (1 - 2 * nu2) * k2) / (2 * ((1 - nu1) * k1 + (1 - nu2) * k2))


def test_dundurs_beta_sign_convention() -> None:
    # Body 1 is the wheel: an elastic wheel on a rigid flat has beta = (1 - 2 nu)/(2 (1 - nu)) > 0 (2/7 at nu = 0.3).
    s = rollbem.Scene.from_dict(HALF_PLANE)
    assert s.dundurs_beta == pytest.approx(0.4 / 1.4, rel=1e-15) == dundurs_beta(210000.0, 0.3, math.inf, 0.3)
    assert rollbem.run(s).dundurs_beta == s.dundurs_beta
    # A steel wheel on an aluminium half-plane: the stiffer body first gives beta < 0, and swapping the materials
    # flips the sign (beta(a, b) = -beta(b, a)).
    pair = {
        "wheel": {**HALF_PLANE["wheel"], "youngs_modulus": 210000.0, "poisson_ratio": 0.3},
        "counter_body": {"kind": "half_plane", "youngs_modulus": 70000.0, "poisson_ratio": 0.33},
    }
    steel_on_al = rollbem.Scene.from_dict(HALF_PLANE, **pair)
    al_on_steel = rollbem.Scene.from_dict(
        HALF_PLANE,
        wheel={**HALF_PLANE["wheel"], "youngs_modulus": 70000.0, "poisson_ratio": 0.33},
        counter_body={"kind": "half_plane", "youngs_modulus": 210000.0, "poisson_ratio": 0.3},
    )
    want = dundurs_beta(210000.0, 0.3, 70000.0, 0.33)
    assert want < 0 and steel_on_al.dundurs_beta == pytest.approx(want, rel=1e-14)
    assert al_on_steel.dundurs_beta == pytest.approx(-want, rel=1e-14)
    # Identical materials: 0 (the coupling vanishes).
    assert scene("steel-on-steel-cattaneo").dundurs_beta == 0.0


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
