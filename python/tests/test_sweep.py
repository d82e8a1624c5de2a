"""Sweeps from Python: the rows of `rollbem sweep` as dicts (or a pandas DataFrame when pandas is there)."""

from __future__ import annotations

import sys
import types
from pathlib import Path
from typing import Any, List

import pytest

import rollbem
from conftest import SCENES, hertz_2d, plane_strain_modulus

SPEC = """
name = "loads"
base = "{base}"
[[grid]]
"drive.normal_load" = [1000.0, 4000.0]
"solvers.use" = [["lemke"], ["active_set"]]
"""


@pytest.fixture()
def spec(tmp_path: Path) -> Path:
    p = tmp_path / "loads.toml"
    p.write_text(SPEC.format(base=SCENES / "half-plane-hertz.toml"))
    return p


def test_sweep_rows_are_typed_dicts(spec: Path) -> None:
    rows = rollbem.sweep(spec)
    assert len(rows) == 4
    assert [(r["case"], r["solver"]) for r in rows] == [(0, "lemke"), (1, "active_set"), (2, "lemke"), (3, "active_set")]
    first = rows[0]
    assert list(first)[:3] == ["case", "drive.normal_load", "solvers.use"]
    assert isinstance(first["case"], int) and isinstance(first["drive.normal_load"], float)
    assert first["solvers.use"] == '["lemke"]' and first["status"] == "solved" and first["scene"] == "half-plane-hertz"
    e_star = plane_strain_modulus(210000.0, 0.3)
    for r in rows:
        # The resultant is the swept load; Hertz's a at it is the closed form (a^2 = 4PR/(pi E*)).
        assert r["normal_load"] == pytest.approx(r["drive.normal_load"], rel=1e-12)
        assert r["hertz_a"] == pytest.approx(hertz_2d(r["drive.normal_load"], 460.0, e_star)["a"], rel=1e-12)
        assert r["t_total"] > 0 and r["setup"] in ("built", "reused")
    # The four cases share bodies and mesh: one model, built once.
    assert sorted(r["setup"] for r in rows) == ["built", "reused", "reused", "reused"]
    # A shard keeps every second case.
    assert [r["case"] for r in rollbem.sweep(spec, shard="2/2")] == [1, 3]


def test_sweep_as_frame_uses_pandas_when_there(spec: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    # pandas is not a dependency: a stand-in module records what the DataFrame is made of.
    made: List[Any] = []

    class DataFrame:
        def __init__(self, rows: list, columns: list) -> None:
            made.append((rows, columns))

    monkeypatch.setitem(sys.modules, "pandas", types.SimpleNamespace(DataFrame=DataFrame))
    frame = rollbem.sweep(spec, as_frame=True)
    assert isinstance(frame, DataFrame)
    rows, columns = made[0]
    assert len(rows) == 4 and columns[:2] == ["case", "drive.normal_load"] and all(len(r) == len(columns) for r in rows)


def test_sweep_as_frame_without_pandas_says_so(spec: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setitem(sys.modules, "pandas", None)  # `import pandas` raises ImportError
    with pytest.raises(ImportError, match="pip install pandas"):
        rollbem.sweep(spec, as_frame=True)


def test_a_bad_spec_names_the_case_and_key(tmp_path: Path) -> None:
    p = tmp_path / "bad.toml"
    p.write_text(SPEC.format(base=SCENES / "half-plane-hertz.toml").replace("4000.0", "-4000.0"))
    with pytest.raises(rollbem.InputError, match="drive.normal_load") as e:
        rollbem.sweep(p)
    assert e.value.key == "drive.normal_load"
