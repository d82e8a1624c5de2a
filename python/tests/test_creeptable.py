"""Creep-force tables and FASTSIM from Python (README "Creep-force tables"): ``rollbem.fastsim`` against the command
line and against Kalker's linear theory, ``rollbem.creep_table`` and the NumPy readers of ``rollbem.creeptable``: the
CSV and the ``.npz`` read back to the same table, bit for bit, equal to direct ``rollbem.fastsim`` calls."""

from __future__ import annotations

import json
import subprocess
from pathlib import Path

import numpy as np
import pytest

import rollbem
from rollbem import creeptable

SPEC = """kind = "creep_table"
name = "py-table"
engine = "fastsim"
[contact]
shear_modulus = 82000.0
friction = 0.3
normal_force = 10000.0
size = 6.0
[grid]
mx = 40
my = 30
[axes]
nu = [0.25, 0.28]
a_over_b = [0.5, 1.0, 3.0]
xi = [0.0, 0.2, 0.7]
eta = [-0.2, 0.0, 0.4]
phi = [-0.5, 0.0, 0.5]
"""


@pytest.fixture()
def table(tmp_path: Path) -> Path:
    spec = tmp_path / "py-table.toml"
    spec.write_text(SPEC)
    out = tmp_path / "py-table.csv"
    done = rollbem.creep_table(spec, out)
    assert done["total"] == done["cases"] == done["ran"] == 162
    assert done["npz"] == str(out.with_suffix(".npz"))
    return out


def test_csv_and_npz_read_back_to_the_same_table(table: Path) -> None:
    # Expected: the two files hold the same numbers (the CSV's are shortest round-trip decimals: the same bits).
    a, b = creeptable.read_csv(table), creeptable.read_npz(table.with_suffix(".npz"))
    assert a.shape == b.shape == (2, 3, 3, 3, 3)
    for name in ("nu", "a_over_b", "xi", "eta", "phi", "coefficients"):
        np.testing.assert_array_equal(getattr(a, name), getattr(b, name))
    assert a.forces.tobytes() == b.forces.tobytes()
    np.testing.assert_array_equal(a.status, b.status)
    np.testing.assert_array_equal(b.xi, [0.0, 0.2, 0.7])


def test_entries_equal_direct_fastsim_calls(table: Path) -> None:
    # Expected: each entry is rollbem.fastsim on the physical case built here from the documented normalisation
    # (a = c sqrt(a/b), b = c/sqrt(a/b); the creepages from CreepTable.physical_creepages), Fx' = fx/(mu N),
    # Mz' = mz/(mu N c): the same library code, so equal to the last bit.
    t = creeptable.read_npz(table.with_suffix(".npz"))
    g, mu, n, c = 82000.0, 0.3, 10000.0, 6.0
    for idx in [(0, 0, 0, 0, 0), (1, 2, 2, 2, 2), (0, 1, 1, 0, 2), (1, 0, 2, 1, 0)]:
        inu, iab, ixi, ieta, iphi = idx
        r = t.a_over_b[iab]
        xi, eta, phi = t.physical_creepages(
            inu, iab, xi_n=t.xi[ixi], eta_n=t.eta[ieta], phi_n=t.phi[iphi], shear_modulus=g, mu=mu,
            normal_force=n, c=c,
        )  # fmt: skip
        f = rollbem.fastsim(
            a=c * np.sqrt(r), b=c / np.sqrt(r), shear_modulus=g, nu=t.nu[inu], mu=mu, normal_force=n,
            xi=xi, eta=eta, phi=phi, mx=40, my=30,
        )  # fmt: skip
        assert t.forces[idx].tolist() == [f["fx"] / (mu * n), f["fy"] / (mu * n), f["mz"] / (mu * n * c)], idx


def test_rows_keep_the_physical_columns(table: Path) -> None:
    rows = creeptable.read_rows(table)
    assert list(rows["case"]) == list(range(162))
    assert set(rows["status"]) <= {"solved", "gross_sliding"}
    np.testing.assert_array_equal(np.asarray(rows["fx"]) / (0.3 * 10000.0), rows["fx_n"])


def test_fastsim_matches_the_cli_and_the_linear_theory(cli: str) -> None:
    # Expected: the CLI's JSON (the same library call) to the last bit; at a vanishing creepage Kalker's linear
    # theory Fx = -G c^2 C11 xi with C11 = 4.12 (Table E.3, a/b = 1, nu = 1/4) within 1e-3.
    args = dict(a=6.0, b=6.0, shear_modulus=80000.0, nu=0.25, mu=0.3, normal_force=10000.0, xi=1e-7)
    f = rollbem.fastsim(**args, elements=True)
    cmd = [cli, "fastsim", "--json", "-", "--quiet"]
    for k, v in args.items():
        cmd += [f"--{k.replace('_', '-')}", repr(v)]
    doc = json.loads(subprocess.run(cmd, check=True, capture_output=True, text=True).stdout)
    assert (doc["fx"], doc["fy"], doc["mz"], doc["n_slip"]) == (f["fx"], f["fy"], f["mz"], f["n_slip"])
    linear = -80000.0 * 36.0 * 4.12 * 1e-7
    assert abs(f["fx"] - linear) < 1e-3 * abs(linear)
    assert f["x"].shape == f["state"].shape == (10000,)
    assert f["state"].dtype == np.int8 and set(np.unique(f["state"])) <= {1, 2}


def test_bad_input_names_the_argument(tmp_path: Path) -> None:
    base = dict(a=6.0, b=6.0, shear_modulus=80000.0, nu=0.25, mu=0.3, normal_force=10000.0)
    for key, value in [("normal_force", -1.0), ("nu", 0.7), ("bound", "flat"), ("mx", 0)]:
        with pytest.raises(rollbem.InputError) as e:
            rollbem.fastsim(**{**base, key: value})
        assert e.value.key == key, e.value
    spec = tmp_path / "bad.toml"
    spec.write_text(SPEC.replace("a_over_b = [0.5, 1.0, 3.0]", "a_over_b = [0.5, 30.0]"))
    with pytest.raises(rollbem.InputError) as e:
        rollbem.creep_table(spec, tmp_path / "bad.csv")
    assert e.value.key == "axes.a_over_b[1]"
    assert not (tmp_path / "bad.csv").exists()
    with pytest.raises(ValueError):
        creeptable.read_csv(spec)
