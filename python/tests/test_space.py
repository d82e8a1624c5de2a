"""Half-space (3D) scenes from Python (issue 32): arrays of shape (MY, MX) against Hertz's ellipse (theory,
computed here from the closed form of the circle) and against the CLI's JSON (the same library run), the kernels
built only for the effects asked for, bad input naming the key."""

import json
import math
import os
import subprocess
from pathlib import Path

import numpy as np
import pytest

import rollbem
from rollbem.errors import InputError

ROOT = Path(__file__).resolve().parents[2]
SCENES = ROOT / "reference" / "scenes" / "half-space"

SPHERE = """
name = "sphere"
[wheel]
model = "half_space"
youngs_modulus = 210000.0
poisson_ratio = 0.3
[counter_body]
kind = "half_space"
youngs_modulus = 210000.0
poisson_ratio = 0.3
[mesh]
mx = 30
my = 24
contact_x = [-1.5, 1.5]
contact_y = [-1.2, 1.2]
[profile]
curvatures = [0.01, 0.01]
[drive]
normal_load = 1000.0
"""


def test_arrays_have_the_grid_shape_and_meet_hertz():
    scene = rollbem.SpaceScene.from_toml(SPHERE)
    assert scene.shape == (24, 30)
    model = rollbem.SpaceModel(scene)
    assert not model.has_tangential and not model.has_coupling  # frictionless: C_zz only
    report = model.solve()
    step = report.steps[0]
    assert step.status == "solved"
    for a in (step.pressure, step.px, step.py, step.gap, step.state):
        assert a.shape == (24, 30) and not a.flags.writeable
    assert step.pressure is step.pressure
    assert step.state.dtype == np.int8
    # Hertz on the circle (Johnson eqs. 4.22-4.23): a^3 = 3PR/(4E*), R = 1/(2A) = 50, E* = E/(2(1 - nu^2)).
    e_star = 210000.0 / (2 * (1 - 0.3**2))
    a = (3 * 1000.0 * 50.0 / (4 * e_star)) ** (1 / 3)
    p0 = 3 * 1000.0 / (2 * math.pi * a * a)
    assert abs(report.hertz["a_x"] - a) < 1e-12 * a
    dx = 3.0 / 30
    assert abs(step.pressure.sum() * dx * 0.1 - 1000.0) < 1e-9 * 1000.0
    assert abs(step.pressure.max() - p0) < 0.02 * p0  # the element at the centre: within 2 % at 10 across
    # Rows are y: the contact is symmetric in x about the grid's middle column pair.
    x, y = report.x, report.y
    assert x.shape == y.shape == (24, 30) and x[0, 1] > x[0, 0] and y[1, 0] > y[0, 0]
    assert np.allclose(step.pressure, step.pressure[:, ::-1], rtol=1e-9, atol=1e-9 * p0)


def test_friction_builds_the_tangential_kernels_and_the_states():
    scene = rollbem.SpaceScene.from_file(SCENES / "cattaneo-shift.toml")
    model = rollbem.SpaceModel(scene)
    assert model.has_tangential and not model.has_coupling
    report = model.solve()
    assert report.all_pass
    last = report.steps[-1]
    contact, stick, slip = last.counts
    assert (last.state == 1).sum() == stick and (last.state == 2).sum() == slip
    assert rollbem.ELEMENT_STATES == ["exterior", "stick", "slip"]
    assert last.force[0] < 0  # body 1 shifted along +x: friction on it along -x


def test_the_same_answer_as_the_cli(tmp_path):
    cli = os.environ.get("ROLLBEM_CLI", str(ROOT / "target" / "release" / "rollbem"))
    out = tmp_path / "h.json"
    scene_file = SCENES / "hertz-ellipse.toml"
    subprocess.run([cli, "run", str(scene_file), "--json", str(out)], check=True, capture_output=True)
    doc = json.loads(out.read_text())
    py = rollbem.run3d(rollbem.SpaceScene.from_file(scene_file))
    p_cli = np.array(doc["steps"][0]["elements"]["pressure"]).reshape(24, 48)
    assert np.array_equal(py.steps[0].pressure, p_cli)
    assert py.to_dict()["model"] == "half_space"


def test_with_gap_and_bad_input():
    scene = rollbem.SpaceScene.from_toml(SPHERE)
    x, y = rollbem.run3d(scene).x, rollbem.run3d(scene).y
    gap = 0.01 * x**2 + 0.01 * y**2
    a = rollbem.run3d(scene).steps[0].pressure
    b = rollbem.run3d(scene.with_gap(gap)).steps[0].pressure
    assert np.allclose(a, b, rtol=0, atol=1e-9 * a.max())
    with pytest.raises(InputError) as e:
        scene.with_gap(gap[:-1])
    assert e.value.key == "profile.gap"
    with pytest.raises(InputError) as e:
        scene.edit({"wheel.youngs_modulus": -1.0})
    assert e.value.key == "wheel.youngs_modulus"
    with pytest.raises(InputError) as e:
        rollbem.SpaceScene.from_toml(SPHERE.replace("[wheel]\n", "[wheel]\nradius = 1.0\n"))
    assert e.value.key == "wheel.radius"
