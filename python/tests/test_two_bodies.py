"""Two finite bodies from Python (issue 34): a twin disc posed from dicts and a pin in a bore from its reference
scene, solved through the model API and read as arrays; their sweep rows. Expected values are theory written out
here (2D Hertz with the pair's R*, Johnson §4.2; the linearity of the zero-clearance bore) or the CLI's own answer
for the same scene (a peer of the binding), never taken from the binding itself."""

from __future__ import annotations

import json
import math
import subprocess
from pathlib import Path

import numpy as np
import pytest

import rollbem
from conftest import REPO, hertz_2d, plane_strain_modulus

TWO_BODIES = REPO / "reference" / "two_bodies"
E, NU = 210000.0, 0.3
#: E* of two steel bodies: 1/E* = 2 (1 - nu^2)/E.
E_STAR = plane_strain_modulus(E, NU) / 2.0


def twin_disc(radius: float, a_over_r: float, elements: int = 40) -> rollbem.Scene:
    """Two equal steel discs on hubs of 0.2 R, pressed at the load that gives Hertz's a = a_over_r R with R* = R/2;
    the candidate arc 4a wide."""
    a = a_over_r * radius
    load = math.pi * a * a * E_STAR / (4.0 * radius / 2.0)  # a^2 = 4 P R*/(pi E*)
    hub = {"kind": "hub", "radius": 0.2 * radius}
    return rollbem.Scene.from_dict(
        {
            "name": "twin-disc",
            "wheel": {"radius": radius, "youngs_modulus": E, "poisson_ratio": NU, "support": hub},
            "counter_body": {
                "kind": "disc",
                "radius": radius,
                "youngs_modulus": E,
                "poisson_ratio": NU,
                "support": hub,
                "other_elements": 96,
            },
            "mesh": {
                "element": "quadratic",
                "contact_arc_deg": math.degrees(4.0 * a_over_r),
                "contact_elements": elements,
                "other_elements": 96,
            },
            "drive": {"normal_load": load},
            "solvers": {"use": ["lemke"]},
        }
    )


def edge_angle(run: rollbem.Run) -> float:
    """The loaded arc's right edge from the load's line, seen from the wheel's centre: p^2 extrapolated linearly to
    zero through the last two loaded nodes (p ~ sqrt(b - theta) at a smooth edge)."""
    theta = np.arctan2(run.x, -run.y)
    i = int(np.nonzero(run.pressure > 0)[0].max())
    q1, q2 = run.pressure[i - 1] ** 2, run.pressure[i] ** 2
    return float(theta[i] + q2 * (theta[i] - theta[i - 1]) / (q1 - q2))


def test_twin_disc_posed_from_dicts_is_hertz_with_half_the_radius() -> None:
    # Expected: Hertz with R* = R/2 and the pair's E* (a = 0.4 mm at a/R = 0.01), the loaded arc's edge within one
    # element of a/R and the peak pressure within 0.5 % of p0 (issue 34: a and p0 within 0.5 % at a/R = 0.01).
    s = twin_disc(40.0, 0.01)
    report = rollbem.run(s, check=True)
    h = hertz_2d(s.drive["normal_load"], 20.0, E_STAR)
    assert report.hertz is not None and report.hertz["half_width"] == pytest.approx(h["a"], rel=1e-12)
    run = report.run("lemke")
    assert run.normal_load == pytest.approx(s.drive["normal_load"], rel=1e-10)
    element = 4.0 * 0.01 / 40  # radians per contact element
    assert abs(edge_angle(run) - h["a"] / 40.0) < element
    assert run.pressure.max() == pytest.approx(h["p0"], rel=5e-3)
    # The counter-disc's nodes face the wheel's: the contact is symmetric about the line of centres.
    assert np.allclose(run.pressure, run.pressure[::-1], rtol=0, atol=1e-9 * run.pressure.max())


def test_pin_in_bore_near_hertz_and_at_zero_clearance() -> None:
    # Expected: at a small load (Hertz's half-angle 3.5 degrees) Hertz with 1/R* = 1/R - 1/(R + dR) within 0.5 %
    # in half-angle and peak pressure; at zero clearance the problem has no gap, so it is linear in the load: the
    # pressures at 10 and 1000 N/mm differ by the factor 100 and the contact arc is the same (theory of the
    # problem, not a tolerance on rollbem's figures).
    base = rollbem.Scene.from_file(TWO_BODIES / "pin-in-bore.toml").edit({"solvers.use": ["lemke"]})
    r, dr, load = 10.0, 0.01, 3.4615
    r_star = r * (r + dr) / dr
    h = hertz_2d(load, r_star, E_STAR)
    small = base.edit({"mesh.contact_arc_deg": 2.5 * math.degrees(h["a"] / r), "drive.normal_load": load})
    run = rollbem.run(small, check=True).run("lemke")
    assert edge_angle(run) == pytest.approx(h["a"] / r, rel=5e-3)
    assert run.pressure.max() == pytest.approx(h["p0"], rel=5e-3)
    tight = base.edit({"counter_body.radius": 10.0, "mesh.contact_arc_deg": 176.0})
    low, high = (x.run("lemke") for x in rollbem.Model(tight).solve_all([{"normal_load": 10.0}, {"normal_load": 1000.0}]))
    assert np.allclose(high.pressure, 100.0 * low.pressure, rtol=1e-9, atol=1e-9 * high.pressure.max())
    assert edge_angle(high) == pytest.approx(edge_angle(low), rel=1e-9)
    # A wide conformal arc: beyond 80 degrees (Persson's zero-clearance angle is 84.8, theory::pin_bore).
    assert math.degrees(edge_angle(high)) > 80.0


def test_pin_in_bore_from_python_is_the_cli_answer(cli: str, tmp_path: Path) -> None:
    # Expected: the CLI's result document for the same scene (a peer of the binding), node for node to 1e-12.
    scene = TWO_BODIES / "pin-in-bore.toml"
    out = tmp_path / "pin.json"
    subprocess.run([cli, "--quiet", "run", str(scene), "--solver", "lemke", "--json", str(out)], check=True)
    doc = json.loads(out.read_text())
    cli_run = next(x for x in doc["runs"] if x["solver"] == "lemke")
    run = rollbem.run(rollbem.Scene.from_file(scene).edit({"solvers.use": ["lemke"]})).run("lemke")
    p_cli = np.array([n["pressure"] for n in cli_run["nodes"]])
    assert np.allclose(run.pressure, p_cli, rtol=0, atol=1e-12 * p_cli.max())


def test_two_body_sweep_rows_carry_the_pairs_radius() -> None:
    # Expected: every row of the twin-disc load sweep has R* = R/2 = 20 mm, Hertz's a at its load with that R*
    # (the closed form, a^2 = 4PR*/(pi E*)), and the counter-body named; no pin-bore reference for a disc.
    rows = rollbem.sweep(TWO_BODIES / "sweeps" / "twin-disc-load.toml")
    assert len(rows) == 3
    for row in rows:
        assert row["status"] == "solved" and row["counter_body"] == "disc" and row["contact_radius"] == 20.0
        assert row["hertz_a"] == pytest.approx(hertz_2d(row["normal_load"], 20.0, E_STAR)["a"], rel=1e-10)
        assert row["pin_bore_half_angle"] is None
