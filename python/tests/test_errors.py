"""Errors are Python exceptions naming the key, as the command line's messages do: `InputError` (a ValueError) for
bad input, `SolveError` for a run that did not solve when the caller asks; and Python's own classes where Python has
one: `FileNotFoundError` (and the other `OSError`s) for a file, `KeyError` for a name a result does not hold,
`TypeError` for an argument of the wrong kind. Nothing else escapes."""

from __future__ import annotations

import errno
import math
from pathlib import Path

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


def test_bad_toml_and_files(tmp_path: Path) -> None:
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
    # A file that is there but is not UTF-8 text: bad input (no errno to make an OSError of).
    binary = tmp_path / "binary.toml"
    binary.write_bytes(b"name = \"\xff\xfe\"\n")
    with pytest.raises(rollbem.InputError) as e:
        rollbem.Scene.from_file(binary)
    assert e.value.path.endswith("binary.toml")
    # A value Python has but a scene cannot hold.
    with pytest.raises(rollbem.InputError, match="not a scene value") as e:
        BASE.edit({"description": object()})
    assert e.value.key == "description"


def test_files_that_are_not_there_raise_pythons_os_errors(tmp_path: Path) -> None:
    # As `open()` raises them: FileNotFoundError with errno and filename, not an InputError.
    missing = SCENES / "no-such-scene.toml"
    calls = [
        lambda: rollbem.Scene.from_file(missing),
        lambda: rollbem.Report.read(tmp_path / "no-such-report.json"),
        lambda: rollbem.sweep(tmp_path / "no-such-spec.toml"),
    ]
    for call in calls:
        with pytest.raises(FileNotFoundError) as e:
            call()
        assert e.value.errno == errno.ENOENT and "no-such" in e.value.filename
        assert not isinstance(e.value, rollbem.InputError)
    # A sweep spec whose `base` names a scene that is not there: the spec is the file given, and it is bad input
    # naming its key (as the CLI's exit 2 says), not a missing file of the caller's.
    spec = tmp_path / "spec.toml"
    spec.write_text('name = "s"\nbase = "gone.toml"\n[[grid]]\n"drive.normal_load" = [1.0]\n')
    with pytest.raises(rollbem.InputError, match="gone.toml") as ie:
        rollbem.sweep(spec)
    assert ie.value.key == "base"
    # A directory where a file is expected.
    with pytest.raises(IsADirectoryError):
        rollbem.Scene.from_file(SCENES)


def test_names_a_result_does_not_hold_are_key_errors() -> None:
    report = rollbem.run(BASE.edit({"solvers.use": ["lemke"]}))
    for call in (lambda: report.run("pgs"), lambda: report.history("pgs")):
        with pytest.raises(KeyError) as e:
            call()
        text = str(e.value)
        assert "'pgs'" in text and "lemke" in text and "Some(" not in text, text
    st = rollbem.run(scene("stresses-hertz-hub", **{"stresses.quantities": ["von_mises"]})).run().stresses
    assert st is not None
    with pytest.raises(KeyError, match="not a stress quantity"):
        st["nonsense"]
    with pytest.raises(KeyError, match="not computed"):
        st["sxx"]
    with pytest.raises(KeyError, match="not computed"):
        st.surface("sxx")


def test_arguments_of_the_wrong_kind_are_type_errors() -> None:
    model = rollbem.Model(BASE)
    for call in (
        lambda: model.solve(5.0),
        lambda: model.solve("normal_load"),
        lambda: model.solve_all([5.0]),
        lambda: model.solve_path("steps"),
        lambda: model.solve_path({"normal_load": 1.0}),
        lambda: BASE.with_steps(3),
        lambda: BASE.edit(["wheel.radius", 1.0]),
        lambda: rollbem.Scene.from_dict([1, 2]),
    ):
        with pytest.raises(TypeError):
            call()


def test_a_drive_given_twice_is_bad_input() -> None:
    c = scene("carter-steady-rolling", solvers__use=["lemke"])
    model = rollbem.Model(c)
    # The same key in the mapping and as a keyword: nothing is resolved silently.
    with pytest.raises(rollbem.InputError, match="given twice") as e:
        model.solve({"creepage": 1e-3}, creepage=2e-3)
    assert e.value.key == "drive.creepage"
    # Both keys of one degree of freedom in one mapping, or the creepage and the tangential load of steady rolling.
    for drive, key in (
        ({"normal_load": 1e4, "normal_approach": 0.1}, "drive.normal_approach"),
        ({"creepage": 1e-3, "tangential_load": -100.0}, "drive.creepage"),
    ):
        for call in (lambda: model.solve(drive), lambda: model.solve_all([drive]), lambda: c.with_drive(**drive)):
            with pytest.raises(rollbem.InputError, match="not both") as e:
                call()
            assert e.value.key == key
    # One key per degree of freedom is a drive (the other of the pair is dropped, as documented).
    assert model.solve({"normal_load": 1e4}, creepage=1e-3).run().solved


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
