"""Sweeps of 3D half-space scenes from Python (issue 32): ``rollbem.sweep`` on a spec whose base scene is a
half-space scene gives the 3D columns, one row per case; each row agrees with a single run of the same case built
another way (``SpaceScene.edit`` and ``run3d``) and with Hertz's circle (Johnson eqs. 4.22-4.23, computed here); a
bad key is refused naming it."""

from __future__ import annotations

import math
from pathlib import Path

import pytest

import rollbem
from rollbem.errors import InputError
from test_space import SPHERE  # two steel half-spaces, h = 0.01 (x^2 + y^2), P = 1000 N, 30 x 24 elements of 0.1

SPEC = """
name = "sphere3d"
base = "sphere.toml"
[[grid]]
"mesh.mx & mesh.my" = [[30, 24], [40, 32]]
"drive.normal_load" = [500.0, 1000.0]
"""


@pytest.fixture()
def spec(tmp_path: Path) -> Path:
    (tmp_path / "sphere.toml").write_text(SPHERE)
    p = tmp_path / "sphere3d.toml"
    p.write_text(SPEC)
    return p


def test_a_3d_sweep_has_the_3d_columns_and_agrees_with_single_runs_and_hertz(spec: Path) -> None:
    rows = rollbem.sweep(spec)
    assert [(r["case"], r["solver"], r["status"]) for r in rows] == [(k, "half_space", "solved") for k in range(4)]
    first = rows[0]
    assert list(first)[:4] == ["case", "drive.normal_load", "mesh.mx", "mesh.my"]
    for column in ("mx", "my", "contact_count", "stick_count", "peak_pressure", "hertz_a_x_err", "hertz_approach_err"):
        assert column in first
    for gone in ("contact_elements", "element", "problem_size", "radius"):
        assert gone not in first, gone
    base = rollbem.SpaceScene.from_toml(SPHERE)
    e_star = 210000.0 / (2 * (1 - 0.3**2))
    for r in rows:
        load, mx, my = r["drive.normal_load"], r["mesh.mx"], r["mesh.my"]
        assert (r["mx"], r["my"]) == (mx, my)
        # The same case by another path.
        single = rollbem.run3d(base.edit({"mesh.mx": mx, "mesh.my": my, "drive.normal_load": load}))
        step = single.steps[-1]
        assert r["normal_load"] == pytest.approx(step.load, rel=1e-12)
        assert r["approach"] == pytest.approx(step.approach, rel=1e-12)
        assert r["contact_count"] == step.counts[0]
        assert r["peak_pressure"] == pytest.approx(float(step.pressure.max()), rel=1e-12)
        # Hertz's circle, computed here: a^3 = 3PR/(4E*), R = 1/(2A) = 50, p0 = 3P/(2 pi a^2).
        a = (3 * load * 50.0 / (4 * e_star)) ** (1 / 3)
        assert r["hertz_a_x"] == pytest.approx(a, rel=1e-12) and r["hertz_a_y"] == pytest.approx(a, rel=1e-12)
        assert r["hertz_p0"] == pytest.approx(3 * load / (2 * math.pi * a * a), rel=1e-12)
        # About 11 to 18 elements across the contact: within the Hertz check's 1.5 % (src/tolerances.rs).
        for e in ("hertz_a_x_err", "hertz_a_y_err", "hertz_p0_err", "hertz_approach_err"):
            assert 0 <= r[e] <= 0.015, (e, r[e])


def test_a_bad_key_of_a_3d_sweep_is_refused_by_name(tmp_path: Path) -> None:
    (tmp_path / "sphere.toml").write_text(SPHERE)
    p = tmp_path / "bad.toml"
    p.write_text('name = "bad"\nbase = "sphere.toml"\n[[grid]]\n"mesh.contact_elements" = [10]\n')
    with pytest.raises(InputError, match="mesh.contact_elements"):
        rollbem.sweep(p)
