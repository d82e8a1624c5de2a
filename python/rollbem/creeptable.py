"""Read creep-force tables (README "Creep-force tables"): the CSV and the ``.npz`` that ``rollbem sweep`` writes for a
spec with ``kind = "creep_table"`` (or :func:`rollbem.creep_table`). NumPy only; no Rust needed to read.

Both readers return a :class:`CreepTable`: the axes ``nu``, ``a_over_b``, ``xi``, ``eta``, ``phi`` (normalised
creepages xi', eta', phi', each strictly increasing), ``forces`` of shape (n_nu, n_ab, n_xi, n_eta, n_phi, 3) holding
Fx/(mu N), Fy/(mu N), Mz/(mu N c) (NaN where the engine gave none), ``status`` of the same shape without the last axis
(0 solved, 1 gross sliding, 2 not converged, 3 refused) and ``coefficients`` (n_nu, n_ab, 3), Kalker's C11, C22, C23
that normalise each ellipse::

    from rollbem import creeptable
    t = creeptable.read_npz("fastsim-usetab.npz")
    fx = t.forces[..., 0]          # Fx/(mu N) on the grid
    t.physical_creepages(0, 2, xi_n=0.3, eta_n=0.0, phi_n=0.0, shear_modulus=82e3, mu=0.3, normal_force=1e4, c=6.0)

The normalisation (Kalker's USETAB): xi = -xi' 3 mu N/(G c^2 C11), eta = -eta' 3 mu N/(G c^2 C22),
phi = -phi' mu N/(G c^3 C23), with c = sqrt(ab); the linear theory reads Fx' = 3 xi', Fy' = 3 eta' + phi'.
"""

from __future__ import annotations

import csv
import os
from dataclasses import dataclass
from typing import Dict, List, Tuple, Union

import numpy as np
import numpy.typing as npt

#: The CSV's columns, in order.
COLUMNS: Tuple[str, ...] = (
    "case", "nu", "a_over_b", "xi_n", "eta_n", "phi_n", "status", "fx_n", "fy_n", "mz_n", "engine", "a", "b", "c11",
    "c22", "c23", "xi", "eta", "phi", "fx", "fy", "mz", "residual", "contact_elements", "slip_elements", "case_digest",
    "message",
)  # fmt: skip

#: Status names by their code in ``CreepTable.status``.
STATUSES: Tuple[str, ...] = ("solved", "gross_sliding", "not_converged", "refused")

#: Columns read as text; every other is a float (NaN where the cell is empty), ``case`` an int.
_TEXT = ("status", "engine", "case_digest", "message")

Path = Union[str, "os.PathLike[str]"]


@dataclass(frozen=True)
class CreepTable:
    """A whole creep table as arrays (module docs)."""

    nu: npt.NDArray[np.float64]
    a_over_b: npt.NDArray[np.float64]
    xi: npt.NDArray[np.float64]
    eta: npt.NDArray[np.float64]
    phi: npt.NDArray[np.float64]
    forces: npt.NDArray[np.float64]
    status: npt.NDArray[np.int8]
    coefficients: npt.NDArray[np.float64]

    @property
    def shape(self) -> Tuple[int, int, int, int, int]:
        """(n_nu, n_ab, n_xi, n_eta, n_phi)."""
        return (len(self.nu), len(self.a_over_b), len(self.xi), len(self.eta), len(self.phi))

    def physical_creepages(
        self,
        inu: int,
        iab: int,
        *,
        xi_n: float,
        eta_n: float,
        phi_n: float,
        shear_modulus: float,
        mu: float,
        normal_force: float,
        c: float,
    ) -> Tuple[float, float, float]:
        """The physical (xi, eta, phi) of normalised creepages on ellipse (inu, iab), CONTACT's signs."""
        c11, c22, c23 = self.coefficients[inu, iab]
        mu_n, g = mu * normal_force, shear_modulus
        return (
            -xi_n * 3.0 * mu_n / (g * c * c * c11),
            -eta_n * 3.0 * mu_n / (g * c * c * c22),
            -phi_n * mu_n / (g * c**3 * c23),
        )


def read_rows(path: Path) -> Dict[str, Union[npt.NDArray[np.float64], npt.NDArray[np.int64], List[str]]]:
    """A table CSV's columns: ``case`` as int64, the text columns (``status``, ``engine``, ``case_digest``,
    ``message``) as lists of str, every other as float64 with NaN for an empty cell. Raises ``ValueError`` when the
    header is not a creep table's."""
    with open(path, newline="", encoding="utf-8") as f:
        reader = csv.reader(f)
        header = tuple(next(reader, ()))
        if header != COLUMNS:
            raise ValueError(f"{os.fspath(path)}: not a creep table: its header is {list(header)}")
        cells = list(reader)
    out: Dict[str, Union[npt.NDArray[np.float64], npt.NDArray[np.int64], List[str]]] = {}
    for j, name in enumerate(COLUMNS):
        column = [row[j] for row in cells]
        if name == "case":
            out[name] = np.array([int(v) for v in column], dtype=np.int64)
        elif name in _TEXT:
            out[name] = column
        else:
            out[name] = np.array([float(v) if v else np.nan for v in column], dtype=np.float64)
    return out


def read_csv(path: Path) -> CreepTable:
    """A table from its CSV: the axes are the distinct values of the coordinate columns, and every case of their
    product must be there once, at its index (phi' fastest, then eta', xi', a/b, nu); the coefficients come from the
    ``c11``, ``c22``, ``c23`` columns. Raises ``ValueError`` for an incomplete table."""
    rows = read_rows(path)
    axes = [np.unique(np.asarray(rows[k])) for k in ("nu", "a_over_b", "xi_n", "eta_n", "phi_n")]
    shape = tuple(len(a) for a in axes)
    n = int(np.prod(shape))
    case = np.asarray(rows["case"])
    if len(case) != n or not np.array_equal(np.sort(case), np.arange(n)):
        raise ValueError(f"{os.fspath(path)}: {len(case)} rows for a grid of {n} cases: not a complete table")
    order = np.argsort(case)
    coords = [np.asarray(rows[k])[order] for k in ("nu", "a_over_b", "xi_n", "eta_n", "phi_n")]
    grid = np.meshgrid(*axes, indexing="ij")
    if not all(np.array_equal(g.ravel(), c) for g, c in zip(grid, coords)):
        raise ValueError(f"{os.fspath(path)}: a row is not at its place on the grid")
    forces = np.stack([np.asarray(rows[k])[order] for k in ("fx_n", "fy_n", "mz_n")], axis=-1)
    codes = {s: i for i, s in enumerate(STATUSES)}
    status = np.array([codes[s] for s in np.asarray(rows["status"], dtype=object)[order]], dtype=np.int8)
    return CreepTable(
        *axes,
        forces=forces.reshape(shape + (3,)),
        status=status.reshape(shape),
        coefficients=np.stack([np.asarray(rows[k])[order] for k in ("c11", "c22", "c23")], axis=-1).reshape(shape + (3,))[
            :, :, 0, 0, 0, :
        ],
    )


def read_npz(path: Path) -> CreepTable:
    """A table from its ``.npz`` (``numpy.load``). Raises ``ValueError`` when a member is missing or of another
    shape than the axes say."""
    with np.load(path) as z:
        missing = {"forces", "status", "nu", "a_over_b", "xi", "eta", "phi", "coefficients"} - set(z.files)
        if missing:
            raise ValueError(f"{os.fspath(path)}: not a creep table: no {sorted(missing)}")
        t = CreepTable(
            nu=z["nu"], a_over_b=z["a_over_b"], xi=z["xi"], eta=z["eta"], phi=z["phi"],
            forces=z["forces"], status=z["status"], coefficients=z["coefficients"],
        )  # fmt: skip
    if t.forces.shape != t.shape + (3,) or t.status.shape != t.shape or t.coefficients.shape != t.shape[:2] + (3,):
        raise ValueError(f"{os.fspath(path)}: its arrays' shapes do not match its axes {t.shape}")
    return t
