"""Errors are Python exceptions naming the key, as the command line's messages do: `InputError` (a ValueError) for
bad input, `SolveError` for a run that did not solve when the caller asks; nothing else escapes."""

from __future__ import annotations

import math

import numpy as np
import pytest

import rollbem
from conftest import SCENES, scene

BASE = scene("half-plane-hertz")


@pytest.mark.parametrize(
    "changes,key,words",
    [
        ({"wheel.radius": -1.0}, "wheel.radius", "must be a finite number > 0"),
        ({"wheel.poisson_ratio": 0.7}, "wheel.poisson_ratio", "poisson"),
        ({"wheel.radus": 3.0}, "wheel.radus", "unknown field `radus`"),
        ({"mesh.contact_elements": "many"}, "mesh.contact_elements", "invalid type"),
        ({"mesh.contact_elements": 0}, "mesh.contact_elements", ""),
        ({"contact.friction": math.nan}, "contact.friction", "finite"),
        ({"drive.normal_load": np.float64(math.inf)}, "drive.normal_load", "finite"),
        ({"solvers.use": ["lemk"]}, "solvers.use", "unknown solver `lemk`"),
        ({"solvers.use": ["clarabel"], "contact.friction": 0.3}, "solvers.use", "does not apply"),
        ({"steps": [{"normal_load": 1.0, "substeps": -2}]}, "steps[0].substeps", "expected usize"),
    ],
)
def test_bad_scene_values_name_their_key(changes: dict, key: str, words: str) -> None:
    with pytest.raises(rollbem.InputError) as e:
        rollbem.run(BASE.edit(changes))
    assert e.value.key == key, str(e.value)
    assert key.split("[")[0].split(".")[-1] in str(e.value) or key in str(e.value)
    assert words.lower() in str(e.value).lower()
    assert isinstance(e.value, ValueError) and isinstance(e.value, rollbem.RollbemError)


def test_bad_toml_and_files() -> None:
    text = (SCENES / "half-plane-hertz.toml").read_text()
    # TOML that does not parse: the parser's message with the line; no key to name.
    with pytest.raises(rollbem.InputError, match="line 1") as e:
        rollbem.Scene.from_toml("name = \n" + text)
    assert e.value.key is None
    # An unknown key in TOML: the CLI's message (line, column, the text) and the dotted key.
    with pytest.raises(rollbem.InputError, match="unknown field `radus`") as e:
        rollbem.Scene.from_toml(text.replace("[wheel]\n", "[wheel]\nradus = 3\n"), "my.toml")
    assert e.value.key == "wheel.radus" and e.value.path == "my.toml" and "radus = 3" in str(e.value)
    # A missing key.
    with pytest.raises(rollbem.InputError, match="missing field `mesh`") as e:
        rollbem.Scene.from_dict({"name": "x", "wheel": BASE.to_dict()["wheel"]})
    # A file that cannot be read.
    with pytest.raises(rollbem.InputError, match="cannot read") as e:
        rollbem.Scene.from_file(SCENES / "no-such-scene.toml")
    assert e.value.path.endswith("no-such-scene.toml")
    # A value Python has but a scene cannot hold.
    with pytest.raises(rollbem.InputError, match="not a scene value") as e:
        BASE.edit({"description": object()})
    assert e.value.key == "description"


def test_bad_drives() -> None:
    model = rollbem.Model(BASE)
    with pytest.raises(rollbem.InputError, match="unknown field `normal_lod`") as e:
        model.solve(normal_lod=1.0)
    assert e.value.key == "drive.normal_lod"
    with pytest.raises(rollbem.InputError) as e:
        model.solve(creepage=1e-3)  # the scene does not roll
    assert e.value.key == "rolling.creepage"
    with pytest.raises(rollbem.InputError) as e:
        model.solve_all([{"normal_load": 1.0}, {"tangential_load": 10.0}])  # frictionless: no tangential load
    assert e.value.key == "drive.tangential_load"
    with pytest.raises(rollbem.InputError) as e:
        model.solve_path([])
    assert e.value.key == "steps"
    with pytest.raises(rollbem.InputError, match="shard"):
        rollbem.sweep(SCENES.parent / "sweeps" / "creep-curves.toml", shard="3/2")


def test_a_run_that_does_not_solve_raises_only_when_asked() -> None:
    # Gross sliding: |Q| > mu P has no static solution (infeasible), the CLI's exit code 5.
    s = BASE.edit({"contact.friction": 0.3, "drive.tangential_load": 7000.0, "solvers.use": ["lemke"]})
    report = rollbem.run(s)
    run = report.run()
    assert (run.status, run.solved, report.ok) == ("infeasible", False, False)
    assert run.normal_load is None and run.residuals is None and run.x.shape == (0,)
    assert "friction limit" in run.explanation
    with pytest.raises(rollbem.SolveError) as e:
        rollbem.run(s, check=True)
    assert (e.value.status, e.value.solver) == ("infeasible", "lemke")
    assert e.value.report.run().status == "infeasible" and "friction limit" in str(e.value)
    with pytest.raises(rollbem.SolveError):
        report.raise_for_status()
    with pytest.raises(rollbem.SolveError):
        run.raise_for_status()
    # A scene that declares the status it expects does not raise (as `rollbem run` exits 0 for it).
    declared = s.edit({"checks": {"status": "infeasible"}})
    assert rollbem.run(declared, check=True).ok
    # Not an input error.
    assert not isinstance(e.value, ValueError)
