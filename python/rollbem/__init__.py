"""rollbem from Python: 2D frictional contact of an elastic wheel on a flat (BEM + LCP solvers).

A :class:`Scene` says what to simulate (TOML text, a file, or dicts); a :class:`Model` is its flexibility, built once
and solved for one drive, a list of drives (a creep curve) or a load path; a :class:`Report` holds the result
document, with each solver's :class:`Run` and its node results as NumPy arrays::

    import rollbem
    scene = rollbem.Scene.from_file("reference/scenes/carter-steady-rolling.toml")
    model = rollbem.Model(scene)                                   # built once
    reports = model.solve_all([{"creepage": xi} for xi in (1e-4, 2e-4, 4e-4)])
    q = [r.run().tangential_load for r in reports]                 # floats
    x, p = reports[0].run().x, reports[0].run().pressure           # NumPy arrays

Conventions (the crate docs, "Conventions"): per unit thickness, plane strain (or, with ``[mesh] strip_width``, a
strip of half-spaces of that width, CONTACT's 2D model); x horizontal, y up, the wheel centre
at the origin, the flat at y = -R. Tractions act on the wheel: pressure p = t_y >= 0, shear q = t_x (+x). The
support moves rigidly by an approach d_N (``normal_approach``, towards the flat, positive compresses), a shift d_T
(``tangential_shift``, +x) and a rotation phi (``rotation``, counter-clockwise, radians); a load is the resultant the
contact carries (``normal_load`` P > 0 compressive, ``tangential_load`` Q along +x, ``moment`` M counter-clockwise
about the wheel centre). The creepage xi is dimensionless, xi > 0 braking. Units are the scene's own, consistent
(N, mm, MPa or N, m, Pa).

Results are made once and kept (``run.pressure is run.pressure``); their NumPy arrays are read-only. A run's node
arrays hold its answer: empty (shape (0,)) for a run whose status is not ``solved``, the refused answer of a
``contact_at_zone_edge`` or ``kinematics_out_of_range`` run staying in ``run.to_dict()["nodes"]`` as evidence.
Drives use a scene's ``[drive]`` keys everywhere (``Scene.drive``, ``Step.drive``, ``Model.solve``).

Errors are exceptions of :mod:`rollbem.errors`: bad input raises :class:`InputError` (a ``ValueError``) naming the
key (a drive key given twice included); a run that did not solve is a status in the report, or :class:`SolveError`
when asked (``check=True``). Where Python has a class of its own it is raised: ``FileNotFoundError`` (and the other
``OSError`` subclasses) for a file, ``KeyError`` for a solver or quantity a result does not hold, ``TypeError`` for
an argument of the wrong kind.
Half-space (3D) scenes (``[wheel] model = "half_space"``): :class:`SpaceScene`, :class:`SpaceModel` (only the
kernels the effects need), :class:`SpaceReport` with each :class:`SpaceStep`'s per-element arrays of shape (MY, MX)
(``pressure``, ``px``, ``py``, ``gap``, ``state``); CONTACT's signs: tractions on body 1, pressure > 0 in compression.

Solves release the GIL and run on a worker thread; Ctrl-C raises ``KeyboardInterrupt`` within about 20 ms (a list
of drives stops before its next drive; a single solve in progress finishes in the background, its result dropped).
"""

from __future__ import annotations

import os
from typing import Any, Dict, List, Literal, Optional, Union, overload

from ._core import (
    ELEMENT_STATES,
    NODE_STATES,
    SCHEMA_VERSION,
    Model,
    Report,
    Residuals,
    Run,
    Scene,
    SpaceModel,
    SpaceReport,
    SpaceScene,
    SpaceStep,
    Step,
    Stresses,
    __version__,
    creep_table,
    fastsim,
    register_solver,
    run,
    run3d,
)
from ._core import _sweep_rows
from . import creeptable
from .errors import InputError, InternalError, NumericalError, OutputError, RollbemError, SolveError

__all__ = [
    "Scene",
    "Model",
    "Report",
    "Run",
    "Step",
    "Residuals",
    "Stresses",
    "SpaceScene",
    "SpaceModel",
    "SpaceReport",
    "SpaceStep",
    "run",
    "run3d",
    "register_solver",
    "sweep",
    "fastsim",
    "creep_table",
    "creeptable",
    "NODE_STATES",
    "ELEMENT_STATES",
    "SCHEMA_VERSION",
    "RollbemError",
    "InputError",
    "OutputError",
    "NumericalError",
    "SolveError",
    "InternalError",
    "__version__",
]


@overload
def sweep(
    spec: Union[str, "os.PathLike[str]"], *, shard: Optional[str] = None, as_frame: "Literal[False]" = False
) -> List[Dict[str, Any]]: ...


@overload
def sweep(spec: Union[str, "os.PathLike[str]"], *, shard: Optional[str] = None, as_frame: "Literal[True]") -> Any: ...


def sweep(
    spec: Union[str, "os.PathLike[str]"],
    *,
    shard: Optional[str] = None,
    as_frame: bool = False,
) -> Any:
    """Run a sweep spec (``reference/sweeps/*.toml``; the README's "Sweeps") and return its rows.

    One row per (case, solver run), sorted by case then solver, with the columns of the sweep CSV (``rollbem sweep
    --out``): ``case``, the swept keys, ``scene``, ``solver``, ``status``, the work counters, the resultants and
    fits, the errors against theory, the rigid motion, the timings (seconds) and ``message``. Values are ints,
    floats or strings, ``None`` where a cell does not apply; lengths, loads and stresses in the scene's units.

    Args:
        spec: the spec file (its ``base`` scene is relative to it).
        shard: ``"k/n"`` to run only the cases with ``index % n == k - 1``.
        as_frame: return a ``pandas.DataFrame`` (typed ``Any``: pandas must be installed, and it is not a dependency
            of rollbem).

    Raises:
        InputError: a spec, base scene or case that does not validate (naming the key), or a bad ``shard``.
        ImportError: ``as_frame=True`` without pandas.
    """
    if as_frame:
        try:
            import pandas as pd  # type: ignore[import-untyped, unused-ignore]
        except ImportError as e:
            raise ImportError("rollbem.sweep(as_frame=True) needs pandas: pip install pandas") from e
    columns, rows = _sweep_rows(os.fspath(spec), shard)
    if as_frame:
        return pd.DataFrame(rows, columns=columns)
    return [dict(zip(columns, r)) for r in rows]
