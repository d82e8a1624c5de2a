"""Shared fixtures of the rollbem Python tests: the repository's reference scenes and the CLI binary."""

from __future__ import annotations

import math
import os
import shutil
from pathlib import Path
from typing import Dict

import pytest

import rollbem

#: The repository root (python/tests/ is two levels below it).
REPO = Path(__file__).resolve().parents[2]
SCENES = REPO / "reference" / "scenes"


def scene(name: str, **changes: object) -> rollbem.Scene:
    """A reference scene by file stem, with dotted-key changes (``solvers__use`` stands for ``solvers.use``)."""
    s = rollbem.Scene.from_file(SCENES / f"{name}.toml")
    if changes:
        s = s.edit({k.replace("__", "."): v for k, v in changes.items()})
    return s


def hertz_2d(load: float, radius: float, e_star: float) -> Dict[str, float]:
    """2D Hertz (Johnson §4.3), computed here: a^2 = 4PR/(pi E*), p0 = 2P/(pi a)."""
    a = math.sqrt(4.0 * load * radius / (math.pi * e_star))
    return {"a": a, "p0": 2.0 * load / (math.pi * a)}


def plane_strain_modulus(e: float, nu: float) -> float:
    """E/(1 - nu^2): a body's share of the contact modulus, 1/E* = sum (1 - nu_i^2)/E_i (a rigid flat adds 0)."""
    return e / (1.0 - nu * nu)


@pytest.fixture(scope="session")
def cli() -> str:
    """The rollbem command-line binary (ROLLBEM_CLI, else target/release/rollbem under CARGO_TARGET_DIR or the
    repository). In CI (CI set) a missing binary fails the test instead of skipping it."""
    candidates = [os.environ.get("ROLLBEM_CLI", "")]
    target = os.environ.get("CARGO_TARGET_DIR")
    if target:
        candidates.append(str(Path(target) / "release" / "rollbem"))
    candidates.append(str(REPO / "target" / "release" / "rollbem"))
    candidates.append(shutil.which("rollbem") or "")
    for c in candidates:
        if c and Path(c).is_file() and os.access(c, os.X_OK):
            return c
    if os.environ.get("CI"):
        pytest.fail("the rollbem CLI binary was not found (set ROLLBEM_CLI)")
    pytest.skip("the rollbem CLI binary was not found (set ROLLBEM_CLI)")
    raise AssertionError("unreachable")


def pytest_report_header(config: pytest.Config) -> str:
    """Which rollbem the tests import (CI: the wheel installed in a fresh environment, not the sources)."""
    return f"rollbem {rollbem.__version__} from {Path(rollbem._core.__file__).parent}"
