"""Type stubs of the extension module ``rollbem._core`` (re-exported by ``rollbem``).

Units are the scene's own, consistent (N, mm, MPa or N, m, Pa); forces and moments per unit thickness. Signs (the
crate docs, "Conventions"): x horizontal, y up, wheel centre at the origin, the flat at y = -R; tractions act on the
wheel, pressure p = t_y >= 0, shear q = t_x (+x); approach d_N towards the flat (positive compresses), shift d_T
(+x), rotation phi counter-clockwise (radians); loads P > 0 compressive, Q along +x, M counter-clockwise about the
wheel centre; creepage xi dimensionless, xi > 0 braking.
"""

from __future__ import annotations

import os
from pathlib import Path
from typing import Any, Dict, Iterable, List, Mapping, Optional, Sequence, Tuple, Union, final

import numpy as np
import numpy.typing as npt

__version__: str
#: Names of the node state codes of ``Run.state``, by code: 0 stick, 1 slip, 2 contact (frictionless), 3 separated.
NODE_STATES: List[str]
#: The layout version of the result document (``Report.to_dict()["schema"]``).
SCHEMA_VERSION: int

__all__ = [
    "Scene",
    "Model",
    "Report",
    "Run",
    "Step",
    "Residuals",
    "Stresses",
    "run",
    "_rust_creep_curve",
    "_sweep_rows",
    "NODE_STATES",
    "SCHEMA_VERSION",
    "__version__",
]

_Path = Union[str, "os.PathLike[str]"]
_Drive = Mapping[str, float]
_FloatArray = npt.NDArray[np.float64]

@final
class Scene:
    """A validated scene: what to simulate. Made only by validation, so every value is in range and every part is
    complete; bad input raises ``InputError`` naming the key. Immutable: ``edit``, ``with_drive``,
    ``with_creepage`` and ``with_steps`` return changed copies."""

    @staticmethod
    def from_toml(text: str, origin: Optional[_Path] = None) -> Scene:
        """Parse and validate scene TOML text (the format of ``reference/scenes/*.toml``); ``origin`` names it in
        errors (default ``"<scene>"``)."""
    @staticmethod
    def from_file(path: _Path) -> Scene:
        """Read, parse and validate a scene file."""
    @staticmethod
    def from_dict(tables: Optional[Mapping[str, Any]] = None, **kwargs: Any) -> Scene:
        """A scene from a mapping of its tables (the TOML document as nested dicts: ``name``, ``wheel``, ``mesh``,
        ``contact``, ``drive``, ``rolling``, ``steps``, ``solvers``, ...), keyword arguments, or both (keywords
        override the mapping's top-level keys)."""
    def edit(self, changes: Mapping[str, Any]) -> Scene:
        """A changed copy: ``changes`` maps dotted keys (``"drive.normal_load"``, ``"contact.friction"``,
        ``"solvers.use"``) to their new values (``None`` removes a key); validated again."""
    def with_drive(
        self,
        *,
        normal_approach: Optional[float] = ...,
        normal_load: Optional[float] = ...,
        tangential_shift: Optional[float] = ...,
        tangential_load: Optional[float] = ...,
        rotation: Optional[float] = ...,
        moment: Optional[float] = ...,
        creepage: Optional[float] = ...,
    ) -> Scene:
        """The scene with another one-step drive. A degree of freedom named by one of its keys is replaced (giving
        ``normal_load`` drops ``normal_approach``), the others are kept; in steady rolling ``creepage`` and
        ``tangential_load`` replace each other. A load path becomes a one-step scene."""
    def with_creepage(self, creepage: float) -> Scene:
        """The scene at another creepage xi (dimensionless, xi > 0 braking); ``InputError`` naming
        ``rolling.creepage`` for a scene without ``[rolling]``."""
    def with_steps(self, steps: Sequence[Mapping[str, float]]) -> Scene:
        """The scene walking a load path: step mappings with the keys of ``[[steps]]`` (the drive keys, ``substeps``,
        ``roll``)."""
    def to_dict(self) -> Dict[str, Any]:
        """The scene as a dict of its tables, defaults filled in."""
    def to_toml(self) -> str:
        """The scene as TOML text (it reads back as the same scene)."""
    @property
    def name(self) -> str:
        """Short identifier (names output files)."""
    @property
    def description(self) -> str: ...
    @property
    def units(self) -> Optional[str]:
        """The units label (e.g. ``"N, mm, MPa"``), or ``None``."""
    @property
    def origin(self) -> Path:
        """Its file, or ``Path("<scene>")``."""
    @property
    def radius(self) -> float:
        """The wheel's radius R (length unit)."""
    @property
    def friction(self) -> float:
        """Coulomb's mu (0: frictionless)."""
    @property
    def contact_modulus(self) -> float:
        """E* of the pair (stress unit): 1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2, the second term 0 for a rigid
        flat."""
    @property
    def dundurs_beta(self) -> float:
        """Dundurs' beta of the pair (0: normal and tangential problems uncouple)."""
    @property
    def model(self) -> str:
        """``"bem"`` (the finite wheel) or ``"half_plane"``."""
    @property
    def strip_width(self) -> float | None:
        """The width of the strip of half-spaces the contact is posed on (``[mesh] strip_width``, CONTACT's 2D model;
        length unit), or None in plane strain."""
    @property
    def element(self) -> str:
        """``"constant"`` or ``"quadratic"``."""
    @property
    def rolling(self) -> Optional[str]:
        """``"steady"``, ``"seed"``, ``"transient"``, or ``None``."""
    @property
    def creepage(self) -> Optional[float]:
        """The prescribed creepage xi, or ``None``."""
    @property
    def drive(self) -> Dict[str, float]:
        """The ``[drive]`` table (empty for a load path)."""
    @property
    def steps(self) -> List[Dict[str, Any]]:
        """The ``[[steps]]`` of a load path (empty for a one-step scene)."""
    @property
    def solvers(self) -> List[str]:
        """``[solvers] use``."""
    def __eq__(self, other: object, /) -> bool: ...

@final
class Model:
    """A scene's flexibility (mesh, BEM system and its condensation, or the half-plane's influence coefficients),
    built once and solved for many drives. Every solve releases the GIL and honours Ctrl-C."""

    def __new__(cls, scene: Scene) -> Model:
        """Build the flexibility of ``scene``. Raises ``NumericalError`` for a singular BEM system."""
    @property
    def scene(self) -> Scene:
        """The scene the model was built for."""
    @property
    def solves(self) -> int:
        """How many solves the model has done."""
    @property
    def build_time(self) -> Dict[str, float]:
        """Seconds of the build: ``assembly``, ``condensation``."""
    def accepts(self, scene: Scene) -> bool:
        """Whether ``scene`` shares the model's bodies, mesh and candidate zone (and needs no other blocks)."""
    def solve(
        self,
        drive: Union[None, Scene, _Drive] = None,
        *,
        check: bool = False,
        normal_approach: float = ...,
        normal_load: float = ...,
        tangential_shift: float = ...,
        tangential_load: float = ...,
        rotation: float = ...,
        moment: float = ...,
        creepage: float = ...,
    ) -> Report:
        """Solve once: the model's scene (``drive=None``), another ``Scene`` on the same bodies and mesh, or the
        model's scene with a drive changed by a mapping or keywords (``model.solve(creepage=1e-3)``). With
        ``check=True`` a run that did not end with the status the scene expects raises ``SolveError``."""
    def solve_all(self, drives: Iterable[Union[Scene, _Drive]], *, check: bool = False) -> List[Report]:
        """Solve for each drive in order, each from rest, on this one model (a creep curve:
        ``[{"creepage": xi} for xi in xis]``); Ctrl-C stops before the next drive."""
    def solve_path(self, steps: Sequence[Mapping[str, float]], *, check: bool = False) -> Report:
        """Walk a load path (``[[steps]]`` mappings: drive keys, ``substeps``, ``roll``), friction with memory."""

@final
class Residuals:
    """Solver-independent residuals of the physical conditions, relative."""

    @property
    def complementarity(self) -> float:
        """max |p g| / (p_max l), l the largest rigid gap over the candidate zone."""
    @property
    def penetration(self) -> float:
        """max(0, -min g) / l."""
    @property
    def tension(self) -> float:
        """max(0, -min p) / p_max."""
    @property
    def friction(self) -> Optional[float]:
        """Coulomb's law (cone and slip terms) over mu p_max; ``None`` without friction."""
    @property
    def equilibrium(self) -> Optional[float]:
        """Worst |resultant - load| / |load| of the load-driven DOFs; ``None`` when displacement-driven."""
    @property
    def max(self) -> float:
        """The largest of those that apply."""

@final
class Stresses:
    """A run's subsurface stresses on the ``[stresses]`` grid: plane strain, tension positive, the scene's stress
    unit; depth z from the flat into the wheel. Fields have shape (nz, nx): row j at ``depth[j]``, column i at
    ``x[i]``; NaN where a point has no value."""

    @property
    def x(self) -> _FloatArray:
        """x of the columns (length unit), shape (nx,)."""
    @property
    def depth(self) -> _FloatArray:
        """Depth of the rows (length unit), shape (nz,)."""
    @property
    def shape(self) -> Tuple[int, int]:
        """(nz, nx)."""
    @property
    def quantities(self) -> List[str]:
        """The quantities computed (``sxx``, ``szz``, ``txz``, ``syy``, ``principal_shear``, ``von_mises``,
        ``orthogonal_shear``)."""
    def __getitem__(self, quantity: str, /) -> npt.NDArray[np.float64]:
        """The field of a quantity, shape (nz, nx), float64."""
    def __contains__(self, quantity: str, /) -> bool: ...
    @property
    def maxima(self) -> Dict[str, Optional[Dict[str, float]]]:
        """Per quantity its largest |value| (sign kept) and where: ``{"value", "x", "depth"}``; grid and surface
        points."""
    @property
    def body(self) -> str:
        """``"wheel"``, or ``"counter_body"`` for an elastic counter-body's own field (depth measured into it)."""
    @property
    def surface_x(self) -> _FloatArray:
        """x of the surface points (depth 0, the contact elements' centres), shape (n_surface,)."""
    def surface(self, quantity: str, /) -> _FloatArray:
        """A quantity at the surface points, shape (n_surface,), float64 (NaN where refused)."""
    @property
    def refused(self) -> Dict[str, int]:
        """Refused points per reason."""
    @property
    def time_s(self) -> float: ...

@final
class Run:
    """One solver's run. Node arrays are float64 of shape (n_nodes,), new on each access, empty when the run has no
    answer (or holding the judged answer of a ``contact_at_zone_edge`` / ``kinematics_out_of_range`` run)."""

    @property
    def solver(self) -> str: ...
    @property
    def status(self) -> str:
        """``solved``, ``infeasible``, ``ray_termination``, ``not_converged``, ``numerical_error``,
        ``contact_at_zone_edge`` or ``kinematics_out_of_range``: the harness's conclusion."""
    @property
    def solved(self) -> bool: ...
    @property
    def termination(self) -> str:
        """How the solver itself ended, before the harness checked its answer."""
    @property
    def verdict(self) -> Optional[Dict[str, str]]:
        """Why ``status`` differs from ``termination`` (``reason``, ``message``), or ``None``."""
    @property
    def explanation(self) -> str: ...
    @property
    def formulation(self) -> str:
        """``frictionless``, ``displacement`` or ``loading``."""
    @property
    def problem_size(self) -> int: ...
    @property
    def work(self) -> Dict[str, int]:
        """The solver's counters (pivots, iterations, sweeps, ...)."""
    @property
    def timing(self) -> Dict[str, Any]:
        """Seconds: ``assembly``, ``condensation``, ``formulation``, ``solve``, ``total``; ``setup`` is ``"built"``
        or ``"reused"``."""
    @property
    def residuals(self) -> Optional[Residuals]: ...
    @property
    def residual(self) -> Optional[float]:
        """The largest residual."""
    @property
    def normal_load(self) -> Optional[float]:
        """Resultant P of the tractions on the wheel (compressive > 0)."""
    @property
    def tangential_load(self) -> Optional[float]:
        """Resultant Q (+x)."""
    @property
    def moment(self) -> Optional[float]:
        """Moment M about the wheel centre (counter-clockwise)."""
    @property
    def normal_approach(self) -> Optional[float]:
        """The support's approach d_N (towards the flat > 0)."""
    @property
    def tangential_shift(self) -> Optional[float]:
        """The support's shift d_T (+x); ``None`` when indeterminate (|Q| = mu P)."""
    @property
    def rotation(self) -> Optional[float]:
        """The support's rotation phi (counter-clockwise, radians)."""
    @property
    def creepage(self) -> Optional[float]:
        """The creepage xi, prescribed or computed from a prescribed Q."""
    @property
    def contact(self) -> Optional[Dict[str, Any]]:
        """Contact figures: ``x_min``, ``x_max``, ``half_width``, ``peak_pressure``, fits, stick zone, counts."""
    @property
    def stick_zone(self) -> Optional[Tuple[float, float]]:
        """x of the outermost sticking nodes, or ``None``."""
    @property
    def n_nodes(self) -> int: ...
    @property
    def x(self) -> _FloatArray:
        """x of each contact node (undeformed)."""
    @property
    def y(self) -> _FloatArray:
        """y of each contact node (undeformed; the flat is y = -R)."""
    @property
    def pressure(self) -> _FloatArray:
        """p = t_y >= 0 on the wheel."""
    @property
    def shear(self) -> _FloatArray:
        """q = t_x on the wheel (+x)."""
    @property
    def gap(self) -> _FloatArray:
        """g = g0 + u_y (0 in contact)."""
    @property
    def slip(self) -> _FloatArray:
        """Slip of the wheel relative to the flat (+x); NaN where separated or not computed."""
    @property
    def u_x(self) -> _FloatArray:
        """u_x with the rigid motion; NaN when the tangential problem was not built."""
    @property
    def u_y(self) -> _FloatArray:
        """u_y with the rigid motion (+y)."""
    @property
    def slip_velocity(self) -> _FloatArray:
        """Slip velocity (seed eq. 12; dimensionless); NaN without ``[rolling]``."""
    @property
    def state(self) -> npt.NDArray[np.int8]:
        """State codes, int8: ``NODE_STATES[code]`` names them."""
    @property
    def state_names(self) -> List[str]: ...
    @property
    def stresses(self) -> Optional[Stresses]:
        """With ``[stresses]``, for a solved run."""
    @property
    def counter_body_stresses(self) -> Optional[Stresses]:
        """The elastic counter-body's own field (``[counter_body] kind = "half_plane"`` with ``[stresses]``)."""
    def raise_for_status(self) -> None:
        """Raise ``SolveError`` unless the run ended with the status its scene expects."""
    def to_dict(self) -> Dict[str, Any]:
        """The run's entry of the JSON document."""

@final
class Step:
    """One substep of a load path."""

    @property
    def step(self) -> int: ...
    @property
    def substep(self) -> int: ...
    @property
    def substeps(self) -> int: ...
    @property
    def rolled(self) -> float:
        """Distance rolled since the start (length unit)."""
    @property
    def drive(self) -> Dict[str, Dict[str, float]]:
        """Per DOF ``{"Displacement": v}`` or ``{"Load": v}``."""
    @property
    def runs(self) -> List[Run]: ...

@final
class Report:
    """The result document of one solve (``rollbem run --json``)."""

    @staticmethod
    def read(path: _Path) -> Report:
        """Read a result document; another schema is refused (``InputError``)."""
    @staticmethod
    def from_json(text: str) -> Report: ...
    @property
    def runs(self) -> List[Run]:
        """One run per solver (a load path's at the last step it reached)."""
    def run(self, solver: Optional[str] = None) -> Run:
        """The run of ``solver``, or the first; ``KeyError`` when there is none."""
    @property
    def steps(self) -> List[Step]: ...
    @property
    def scene(self) -> Scene: ...
    @property
    def ok(self) -> bool:
        """Whether every run ended with the status the scene expects."""
    def raise_for_status(self) -> None:
        """Raise ``SolveError`` unless ``ok``."""
    @property
    def hertz(self) -> Optional[Dict[str, float]]:
        """Hertz at the run's load (frictionless scenes): ``half_width``, ``peak_pressure``, ``load``."""
    @property
    def checks(self) -> List[Dict[str, Any]]: ...
    @property
    def all_pass(self) -> bool: ...
    @property
    def warnings(self) -> List[str]: ...
    @property
    def mesh(self) -> Dict[str, Any]: ...
    @property
    def diagnostics(self) -> Dict[str, Any]: ...
    def history(self, solver: Optional[str] = None) -> Dict[str, Any]:
        """A load path per substep, as arrays: ``step``, ``substep``, ``rolled``, ``normal_load``,
        ``tangential_load``, ``moment``, ``normal_approach``, ``tangential_shift``, ``rotation``, ``creepage``,
        ``dissipated``, ``dissipated_total`` (NaN where absent), and ``status`` (list of str)."""
    def to_dict(self) -> Dict[str, Any]:
        """The whole document, as ``rollbem run --json`` writes it."""
    def to_json(self, indent: Optional[int] = None) -> str: ...
    def __len__(self) -> int: ...

def run(scene: Scene, *, check: bool = False) -> Report:
    """Build the scene's model and solve the scene once (``rollbem run``)."""

def _rust_creep_curve(scene: Scene, creepages: Sequence[float], on_worker: bool = False) -> Tuple[float, List[float]]:
    """Benchmark reference: the same creep curve through the Rust API alone: (seconds, Q per creepage)."""

def _sweep_rows(spec: str, shard: Optional[str] = None) -> Tuple[List[str], List[List[Any]]]: ...
