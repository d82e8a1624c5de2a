"""Type stubs of the extension module ``rollbem._core`` (re-exported by ``rollbem``).

Units are the scene's own, consistent (N, mm, MPa or N, m, Pa); forces and moments per unit thickness. Signs (the
crate docs, "Conventions"): x horizontal, y up, wheel centre at the origin, the flat at y = -R; tractions act on the
wheel, pressure p = t_y >= 0, shear q = t_x (+x); approach d_N towards the flat (positive compresses), shift d_T
(+x), rotation phi counter-clockwise (radians); loads P > 0 compressive, Q along +x, M counter-clockwise about the
wheel centre; creepage xi dimensionless, xi > 0 braking.

Written below as: [length], [stress] (force per length squared), [force/thickness] (a force per unit thickness, the
scene's force unit over its length unit), [moment/thickness] (force x length per unit thickness), [energy/thickness],
[rad], [-] (dimensionless), [s] (seconds).

Results are made once and kept: a run's node arrays, a report's runs and steps, a path's history arrays and a
stress field's arrays are the same objects on every access, and the NumPy arrays among them are read-only
(``a.flags.writeable`` is False and cannot be set back; ``a.copy()`` is the caller's own). Dicts (``timing``,
``work``, ``contact``, ``mesh``, ...) are made anew on each access.

A run's node arrays hold its answer: every array has one entry per contact node for a run whose ``status`` is
``"solved"`` and shape (0,) for any other status. A run judged ``contact_at_zone_edge`` or
``kinematics_out_of_range`` keeps the answer the harness refused as the evidence for its verdict in
``Run.to_dict()["nodes"]`` (the JSON document), not in the arrays.

Errors: ``rollbem.errors.InputError`` (a ``ValueError``) for bad input, naming the dotted key; Python's own
``OSError`` subclass for a file (``FileNotFoundError``, ``PermissionError``, ``IsADirectoryError``); ``KeyError`` for
a solver or stress quantity a result does not hold; ``TypeError`` for an argument of the wrong kind (a drive that is
not a ``Scene`` or a mapping, a load path that is not a sequence).
"""

from __future__ import annotations

import os
from pathlib import Path
from typing import Any, Callable, Dict, Iterable, List, Mapping, Optional, Sequence, Tuple, Union, final

import numpy as np
import numpy.typing as npt

__version__: str
#: Names of the node state codes of ``Run.state``, by code: 0 stick, 1 slip, 2 contact (frictionless), 3 separated.
NODE_STATES: List[str]
#: The layout version of the result document (``Report.to_dict()["schema"]``).
SCHEMA_VERSION: int
#: Names of the element state codes of ``SpaceStep.state``, by code: 0 exterior, 1 stick, 2 slip.
ELEMENT_STATES: List[str]

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
    "fastsim",
    "creep_table",
    "_rust_creep_curve",
    "_sweep_rows",
    "NODE_STATES",
    "SCHEMA_VERSION",
    "ELEMENT_STATES",
    "__version__",
]

_Path = Union[str, "os.PathLike[str]"]
_Drive = Mapping[str, float]
_FloatArray = npt.NDArray[np.float64]
_Int8Array = npt.NDArray[np.int8]

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
        """Read, parse and validate a scene file; ``FileNotFoundError`` (an ``OSError``) when it is not there."""
    @staticmethod
    def from_dict(tables: Optional[Mapping[str, Any]] = None, **kwargs: Any) -> Scene:
        """A scene from a mapping of its tables (the TOML document as nested dicts: ``name``, ``wheel``, ``mesh``,
        ``contact``, ``drive``, ``rolling``, ``steps``, ``solvers``, ...), keyword arguments, or both (keywords
        override the mapping's top-level keys). ``TypeError`` when ``tables`` is not a mapping."""
    def edit(self, changes: Mapping[str, Any]) -> Scene:
        """A changed copy: ``changes`` maps dotted keys (``"drive.normal_load"``, ``"contact.friction"``,
        ``"solvers.use"``) to their new values (``None`` removes a key); validated again. ``TypeError`` when
        ``changes`` is not a mapping."""
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
        """The scene with another one-step drive: ``normal_approach`` d_N [length, towards the flat > 0] |
        ``normal_load`` P [force/thickness, compressive > 0], ``tangential_shift`` d_T [length, +x] |
        ``tangential_load`` Q [force/thickness, +x], ``rotation`` phi [rad, counter-clockwise] | ``moment`` M
        [moment/thickness, counter-clockwise about the wheel centre], ``creepage`` xi [-, > 0 braking]. A degree of
        freedom named by one of its keys is replaced (giving ``normal_load`` drops the scene's ``normal_approach``),
        the others are kept; in steady rolling ``creepage`` and ``tangential_load`` replace the scene's other one. A
        load path becomes a one-step scene. Both keys of one degree of freedom (or ``creepage`` and
        ``tangential_load`` in steady rolling) are bad input (``InputError`` naming the first)."""
    def with_creepage(self, creepage: float) -> Scene:
        """The scene at another creepage xi (dimensionless, xi > 0 braking); ``InputError`` naming
        ``rolling.creepage`` for a scene without ``[rolling]``."""
    def with_steps(self, steps: Sequence[Mapping[str, float]]) -> Scene:
        """The scene walking a load path: a sequence of step mappings with the keys of ``[[steps]]`` (the drive keys
        of ``with_drive`` but ``creepage``, at the step's end; ``substeps``, an int >= 1; ``roll`` [length] >= 0).
        ``TypeError`` when ``steps`` is not a sequence."""
    def to_dict(self) -> Dict[str, Any]:
        """The scene as a dict of its tables, defaults filled in."""
    def to_toml(self) -> str:
        """The scene as TOML text (it reads back as the same scene)."""
    @property
    def name(self) -> str:
        """Short identifier (names output files)."""
    @property
    def description(self) -> str:
        """What the scene is and where its numbers come from."""
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
        """Coulomb's mu [-] (0: frictionless)."""
    @property
    def contact_modulus(self) -> float:
        """E* of the pair [stress]: 1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2, the second term 0 for a rigid
        flat."""
    @property
    def dundurs_beta(self) -> float:
        """Dundurs' second parameter beta of the pair in plane strain [-] (``rollbem::material::dundurs_beta``):
        body 1 is the wheel, body 2 the counter-body (a rigid flat has 1/G2 = 0),
        beta = [(1 - 2 nu1)/G1 - (1 - 2 nu2)/G2] / [2 ((1 - nu1)/G1 + (1 - nu2)/G2)]. Swapping the bodies changes
        its sign; an elastic wheel on a rigid flat has beta = (1 - 2 nu)/(2 (1 - nu)) > 0 (2/7 at nu = 0.3); the
        more compliant body as the wheel gives beta > 0; 0 (identical materials) uncouples the normal and tangential
        problems."""
    @property
    def model(self) -> str:
        """``"bem"`` (the finite wheel) or ``"half_plane"``."""
    @property
    def strip_width(self) -> Optional[float]:
        """The width [length] of the strip of half-spaces the contact is posed on (``[mesh] strip_width``, CONTACT's
        2D model), or None in plane strain."""
    @property
    def element(self) -> str:
        """``"constant"`` or ``"quadratic"``."""
    @property
    def rolling(self) -> Optional[str]:
        """``"steady"``, ``"seed"``, ``"transient"``, or ``None``."""
    @property
    def creepage(self) -> Optional[float]:
        """The prescribed creepage xi [-, > 0 braking], or ``None``."""
    @property
    def drive(self) -> Dict[str, float]:
        """The ``[drive]`` table with its keys (``normal_approach`` [length] | ``normal_load`` [force/thickness],
        ``tangential_shift`` [length] | ``tangential_load`` [force/thickness], ``rotation`` [rad] | ``moment``
        [moment/thickness]); empty for a load path."""
    @property
    def steps(self) -> List[Dict[str, Any]]:
        """The ``[[steps]]`` of a load path: the drive keys of ``drive``, ``substeps``, ``roll`` [length] (empty for a
        one-step scene)."""
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
        """The build's time [s]: ``assembly``, ``condensation``."""
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
        model's scene with a drive changed by a mapping or keywords (``model.solve(creepage=1e-3)``), with the keys
        and units of ``Scene.with_drive`` (a ``Step.drive`` is such a mapping). A key given both in the mapping and
        as a keyword, or both keys of one degree of freedom, is bad input (``InputError`` naming ``drive.KEY``); a
        ``drive`` that is neither a ``Scene`` nor a mapping is a ``TypeError``. With ``check=True`` a run that did
        not end with the status the scene expects raises ``SolveError``."""
    def solve_all(self, drives: Iterable[Union[Scene, _Drive]], *, check: bool = False) -> List[Report]:
        """Solve for each drive in order, each from rest, on this one model (a creep curve:
        ``[{"creepage": xi} for xi in xis]``); Ctrl-C stops before the next drive."""
    def solve_path(self, steps: Sequence[Mapping[str, float]], *, check: bool = False) -> Report:
        """Walk a load path (a sequence of ``[[steps]]`` mappings, as ``Scene.with_steps``), friction with memory
        from substep to substep."""

@final
class Residuals:
    """Solver-independent residuals of the physical conditions, each relative [-]."""

    @property
    def complementarity(self) -> float:
        """max |p g| / (p_max l) [-], l the largest rigid gap over the candidate zone."""
    @property
    def penetration(self) -> float:
        """max(0, -min g) / l [-]."""
    @property
    def tension(self) -> float:
        """max(0, -min p) / p_max [-]."""
    @property
    def friction(self) -> Optional[float]:
        """Coulomb's law (cone and slip terms) over mu p_max [-]; ``None`` without friction."""
    @property
    def equilibrium(self) -> Optional[float]:
        """Worst |resultant - load| / |load| of the load-driven DOFs [-]; ``None`` when displacement-driven."""
    @property
    def max(self) -> float:
        """The largest of those that apply [-]."""

@final
class Stresses:
    """A run's subsurface stresses on the ``[stresses]`` grid: plane strain, tension positive, [stress]; depth z
    [length] from the flat into the body (on the loaded surface szz = -p, txz = -q). Fields have shape (nz, nx): row
    j at ``depth[j]``, column i at ``x[i]``; NaN where a point has no value. Every array is made once and read-only.
    """

    @property
    def x(self) -> _FloatArray:
        """x of the columns [length], shape (nx,)."""
    @property
    def depth(self) -> _FloatArray:
        """Depth of the rows [length], shape (nz,)."""
    @property
    def shape(self) -> Tuple[int, int]:
        """(nz, nx)."""
    @property
    def quantities(self) -> List[str]:
        """The quantities computed (``sxx``, ``szz``, ``txz``, ``syy``, ``principal_shear``, ``von_mises``,
        ``orthogonal_shear``)."""
    def __getitem__(self, quantity: str, /) -> npt.NDArray[np.float64]:
        """The field of a quantity [stress], shape (nz, nx), float64; ``KeyError`` for a name that is not a stress
        quantity or a quantity not computed."""
    def __contains__(self, quantity: str, /) -> bool: ...
    @property
    def maxima(self) -> Dict[str, Optional[Dict[str, float]]]:
        """Per quantity its largest |value| (sign kept) [stress] and where: ``{"value", "x", "depth"}`` (x, depth
        [length]); grid and surface points."""
    @property
    def body(self) -> str:
        """``"wheel"``, or ``"counter_body"`` for an elastic counter-body's own field (depth measured into it)."""
    @property
    def surface_x(self) -> _FloatArray:
        """x of the surface points [length] (depth 0, the contact elements' centres), shape (n_surface,)."""
    def surface(self, quantity: str) -> _FloatArray:
        """A quantity at the surface points [stress], shape (n_surface,), float64 (NaN where refused); ``KeyError``
        as for ``st[quantity]``."""
    @property
    def refused(self) -> Dict[str, int]:
        """Refused points per reason (``outside_body``, ``near_boundary``, ``singular``)."""
    @property
    def time_s(self) -> float:
        """Wall-clock time of the evaluation [s]."""

@final
class Run:
    """One solver's run. Node arrays (``x`` ... ``state``) are float64 (``state`` int8) of shape (n_nodes,), made
    once and read-only: one entry per contact node for a solved run, shape (0,) for any other status (a
    ``contact_at_zone_edge`` or ``kinematics_out_of_range`` run keeps its refused answer in ``to_dict()["nodes"]``
    only). Resultants and rigid motion are ``None`` unless solved."""

    @property
    def solver(self) -> str:
        """The solver's registry name (``lemke``, ``active_set``, ``clarabel``, ``pgs``, ``normtang_qp``)."""
    @property
    def status(self) -> str:
        """``solved``, ``infeasible``, ``ray_termination``, ``not_converged``, ``numerical_error``,
        ``contact_at_zone_edge`` or ``kinematics_out_of_range``: the harness's conclusion."""
    @property
    def solved(self) -> bool:
        """Whether ``status`` is ``solved``: whether the run has an answer (node arrays, resultants, rigid motion)."""
    @property
    def termination(self) -> str:
        """How the solver itself ended, before the harness checked its answer."""
    @property
    def verdict(self) -> Optional[Dict[str, str]]:
        """Why ``status`` differs from ``termination`` (``reason``, ``message``), or ``None``."""
    @property
    def explanation(self) -> str:
        """What to tell a user about the run (the verdict's explanation, then the solver's message)."""
    @property
    def formulation(self) -> str:
        """``frictionless``, ``displacement`` or ``loading``."""
    @property
    def problem_size(self) -> int:
        """Number of complementarity (or QP) unknowns."""
    @property
    def work(self) -> Dict[str, int]:
        """The solver's counters (pivots, iterations, sweeps, ...)."""
    @property
    def timing(self) -> Dict[str, Any]:
        """Times [s]: ``assembly``, ``condensation``, ``formulation``, ``solve``, ``total``; ``setup`` is
        ``"built"`` or ``"reused"``."""
    @property
    def residuals(self) -> Optional[Residuals]:
        """The residuals, or ``None`` unless a solution was produced."""
    @property
    def residual(self) -> Optional[float]:
        """The largest residual [-]."""
    @property
    def normal_load(self) -> Optional[float]:
        """Resultant P = int p dx of the tractions on the wheel [force/thickness], compressive > 0."""
    @property
    def tangential_load(self) -> Optional[float]:
        """Resultant Q = int q dx [force/thickness], +x."""
    @property
    def moment(self) -> Optional[float]:
        """Moment M about the wheel centre [moment/thickness], counter-clockwise."""
    @property
    def normal_approach(self) -> Optional[float]:
        """The support's approach d_N [length], towards the flat > 0."""
    @property
    def tangential_shift(self) -> Optional[float]:
        """The support's shift d_T [length], +x; ``None`` when indeterminate (|Q| = mu P)."""
    @property
    def rotation(self) -> Optional[float]:
        """The support's rotation phi [rad], counter-clockwise."""
    @property
    def creepage(self) -> Optional[float]:
        """The creepage xi [-, > 0 braking], prescribed or computed from a prescribed Q."""
    @property
    def contact(self) -> Optional[Dict[str, Any]]:
        """Contact figures: ``x_min``, ``x_max``, ``half_width``, ``fit_half_width``, ``stick_x_min``,
        ``stick_x_max`` [length]; ``peak_pressure``, ``fit_peak_pressure`` [stress]; node counts."""
    @property
    def stick_zone(self) -> Optional[Tuple[float, float]]:
        """The stick zone's edges (left, right) [length], each midway between the outermost sticking node and its
        neighbour; ``None`` without friction, when nothing sticks, or for a run not solved."""
    @property
    def n_nodes(self) -> int:
        """Entries of each node array: the contact nodes of a solved run, 0 for any other status."""
    @property
    def x(self) -> _FloatArray:
        """x of each contact node (undeformed) [length]."""
    @property
    def y(self) -> _FloatArray:
        """y of each contact node (undeformed) [length]; the flat is y = -R."""
    @property
    def pressure(self) -> _FloatArray:
        """p = t_y >= 0 on the wheel [stress]."""
    @property
    def shear(self) -> _FloatArray:
        """q = t_x on the wheel [stress], +x; 0 without friction."""
    @property
    def gap(self) -> _FloatArray:
        """g = g0 + u_y to the flat [length]; 0 in contact."""
    @property
    def slip(self) -> _FloatArray:
        """Slip of the wheel relative to the flat [length], +x; NaN where separated or not computed."""
    @property
    def u_x(self) -> _FloatArray:
        """u_x with the rigid motion [length], +x; NaN when the tangential problem was not built."""
    @property
    def u_y(self) -> _FloatArray:
        """u_y with the rigid motion [length], +y."""
    @property
    def slip_velocity(self) -> _FloatArray:
        """Slip velocity relative to the rolling speed [-] (seed eq. 12); NaN without ``[rolling]``."""
    @property
    def state(self) -> npt.NDArray[np.int8]:
        """State codes, int8: 0 stick, 1 slip, 2 contact (frictionless), 3 separated; ``NODE_STATES[code]`` names
        them."""
    @property
    def state_names(self) -> Tuple[str, ...]:
        """The state of each node by name (``"stick"``, ``"slip"``, ``"contact"``, ``"separated"``)."""
    @property
    def stresses(self) -> Optional[Stresses]:
        """With ``[stresses]``, for a solved run."""
    @property
    def counter_body_stresses(self) -> Optional[Stresses]:
        """The elastic counter-body's own field (``[counter_body] kind = "half_plane"`` or ``"disc"`` with
        ``[stresses]``; depth measured into it)."""
    def raise_for_status(self) -> None:
        """Raise ``SolveError`` unless the run ended with the status its scene expects."""
    def to_dict(self) -> Dict[str, Any]:
        """The run's entry of the JSON document (``nodes`` holds a refused answer's evidence)."""

@final
class Step:
    """One substep of a load path."""

    @property
    def step(self) -> int:
        """Step index, from 0 as in ``[[steps]]``."""
    @property
    def substep(self) -> int:
        """Substep, 1 ..= ``substeps``."""
    @property
    def substeps(self) -> int:
        """Number of substeps of the step."""
    @property
    def rolled(self) -> float:
        """Distance rolled since the start [length]."""
    @property
    def drive(self) -> Dict[str, float]:
        """The drive at the substep's end with the keys of a scene's ``[drive]``: ``normal_approach`` [length] |
        ``normal_load`` [force/thickness], ``tangential_shift`` [length] | ``tangential_load`` [force/thickness],
        ``rotation`` [rad] | ``moment`` [moment/thickness]; a tangential or rotational DOF held at zero
        displacement is left out, as in a scene. ``Model.solve`` and ``Scene.with_drive`` accept it."""
    @property
    def runs(self) -> Tuple[Run, ...]:
        """Every solver's run at the substep's end."""

@final
class Report:
    """The result document of one solve (``rollbem run --json``)."""

    @staticmethod
    def read(path: _Path) -> Report:
        """Read a result document; another schema is refused (``InputError``); ``FileNotFoundError`` when it is not
        there."""
    @staticmethod
    def from_json(text: str) -> Report:
        """Parse a result document's JSON text."""
    @property
    def runs(self) -> Tuple[Run, ...]:
        """One run per solver (a load path's at the last step it reached)."""
    def run(self, solver: Optional[str] = None) -> Run:
        """The run of ``solver``, or the first; ``KeyError`` when there is none."""
    @property
    def steps(self) -> Tuple[Step, ...]:
        """A load path's substeps (empty for a one-step scene)."""
    @property
    def scene(self) -> Scene:
        """The scene as solved."""
    @property
    def ok(self) -> bool:
        """Whether every run ended with the status the scene expects."""
    def raise_for_status(self) -> None:
        """Raise ``SolveError`` unless ``ok``."""
    @property
    def hertz(self) -> Optional[Dict[str, float]]:
        """Hertz at the run's load (frictionless scenes): ``half_width`` a [length], ``peak_pressure`` p0 [stress],
        ``load`` P [force/thickness]."""
    @property
    def dundurs_beta(self) -> float:
        """Dundurs' beta of the pair [-], body 1 the wheel (as ``Scene.dundurs_beta``: > 0 for an elastic wheel on
        a rigid flat, sign flips when the bodies swap)."""
    @property
    def checks(self) -> List[Dict[str, Any]]:
        """The checks against theory and between solvers (``name``, ``measured``, ``reference``, ``error``,
        ``tolerance``, ``pass``, ``kind``, ``note``)."""
    @property
    def all_pass(self) -> bool:
        """Whether every check passed."""
    @property
    def warnings(self) -> List[str]:
        """Run-level warnings."""
    @property
    def mesh(self) -> Dict[str, Any]:
        """Mesh facts (``model``, ``elements``, ``nodes``, ``contact_nodes``, ``element``, ``system_size``,
        ``contact_element_length`` [length])."""
    @property
    def diagnostics(self) -> Dict[str, Any]:
        """Numerical health (condition estimates, flexibility asymmetry, warnings)."""
    def history(self, solver: Optional[str] = None) -> Dict[str, Any]:
        """A load path per substep, as read-only arrays (the same arrays on every call, in a new dict):
        ``step``, ``substep`` (int64), ``rolled`` [length], ``normal_load``, ``tangential_load``
        [force/thickness], ``moment`` [moment/thickness], ``normal_approach``, ``tangential_shift`` [length],
        ``rotation`` [rad], ``creepage`` [-], ``dissipated``, ``dissipated_total`` [energy/thickness] (NaN where a
        substep did not solve), and ``status`` (tuple of str). ``KeyError`` for a solver the report has no run of;
        empty arrays for a one-step report."""
    def to_dict(self) -> Dict[str, Any]:
        """The whole document, as ``rollbem run --json`` writes it."""
    def to_json(self, indent: Optional[int] = None) -> str:
        """The document as JSON text (``indent`` spaces, or compact)."""
    def __len__(self) -> int: ...

def run(scene: Scene, *, check: bool = False) -> Report:
    """Build the scene's model and solve the scene once (``rollbem run``)."""

def register_solver(
    name: str,
    solve: Callable[[npt.NDArray[np.float64], npt.NDArray[np.float64]], Sequence[float]],
    *,
    summary: Optional[str] = None,
    frictional: bool = False,
) -> None:
    """Register ``solve(M, q) -> z``, a solver of the LCP ``w = M z + q >= 0, z >= 0, w.z = 0`` written in Python
    (M of shape (m, m), dimensionless, the scene's formulation), under ``name``: scenes then name it in
    ``solvers.use`` and every run of it is certified by rollbem's residuals. ``frictional=False`` refuses it for
    frictional scenes. ``ValueError`` for a name taken or not valid, ``TypeError`` for ``solve`` not callable."""

def _rust_creep_curve(scene: Scene, creepages: Sequence[float], on_worker: bool = False) -> Tuple[float, List[float]]:
    """Benchmark reference: the same creep curve through the Rust API alone: (time [s], Q per creepage
    [force/thickness])."""

def _sweep_rows(spec: str, shard: Optional[str] = None) -> Tuple[List[str], List[List[Any]]]:
    """The sweep CSV's columns and rows of typed cells (``rollbem.sweep``); a sweep of 3D half-space scenes has its
    own columns (``mx``, ``my``, the contact/stick/slip counts, the errors against Hertz's ellipse and
    Cattaneo-Mindlin; README "Sweeps")."""

@final
class SpaceScene:
    """A validated half-space (3D) scene (``[wheel] model = "half_space"``; README "Scenes"): two elastic
    half-spaces on an MX x MY grid. CONTACT's signs: tractions and forces on body 1, pressure > 0 in compression,
    shifts of body 1 relative to body 2. Bad input raises ``InputError`` naming the key."""

    @staticmethod
    def from_toml(text: str, origin: Optional[_Path] = None) -> SpaceScene:
        """Parse and validate scene text; ``origin`` names it in errors and anchors a relative ``gap_file``."""
    @staticmethod
    def from_file(path: _Path) -> SpaceScene:
        """Read, parse and validate a half-space scene file."""
    @staticmethod
    def from_dict(tables: Mapping[str, Any]) -> SpaceScene:
        """A scene from its tables as nested dicts."""
    def edit(self, changes: Mapping[str, Any]) -> SpaceScene:
        """A changed copy: dotted keys to values (``None`` removes a key); validated again."""
    def with_gap(self, gap: Union[_FloatArray, Sequence[Sequence[float]]]) -> SpaceScene:
        """The scene with one gap [length] per element, shape (MY, MX), row iy first; it replaces ``[profile]``."""
    @property
    def name(self) -> str: ...
    @property
    def shape(self) -> Tuple[int, int]:
        """(MY, MX): the shape of every per-element array."""
    @property
    def friction(self) -> float:
        """Coulomb's mu [-]."""
    @property
    def dundurs_beta(self) -> float:
        """Dundurs' beta of the pair, body 1 first [-]."""
    def to_dict(self) -> Dict[str, Any]:
        """The document as nested dicts (defaults filled in)."""

@final
class SpaceModel:
    """A half-space scene's influence kernels, built once: only those its effects need."""

    def __new__(cls, scene: SpaceScene) -> SpaceModel:
        """Build the kernels of ``scene``."""
    @property
    def has_tangential(self) -> bool:
        """Whether the tangential kernels were built (friction only)."""
    @property
    def has_coupling(self) -> bool:
        """Whether the coupling kernels were built (a dissimilar pair with friction asked to couple)."""
    def solve(self) -> SpaceReport:
        """Solve every step (a step without a solution is a status in the report)."""

@final
class SpaceStep:
    """One (sub)step of a half-space result. Arrays have shape (MY, MX), are read-only and made once."""

    @property
    def index(self) -> int:
        """The ``[[steps]]`` index (0 for ``[drive]``)."""
    @property
    def substep(self) -> int: ...
    @property
    def status(self) -> str:
        """``solved``, ``contact_at_grid_edge``, ``not_converged``, ``gross_sliding`` or ``no_contact``."""
    @property
    def message(self) -> str: ...
    @property
    def load(self) -> float:
        """The normal load P [force]."""
    @property
    def approach(self) -> float:
        """The approach [length]."""
    @property
    def force(self) -> Tuple[float, float]:
        """The tangential force (F_x, F_y) on body 1 [force]."""
    @property
    def shift(self) -> Optional[Tuple[float, float]]:
        """The shift of body 1 relative to body 2 from the path's start [length]; None after gross sliding."""
    @property
    def counts(self) -> Tuple[int, int, int]:
        """Elements in contact, in stick, in slip."""
    @property
    def pressure(self) -> _FloatArray:
        """Pressure p [stress], shape (MY, MX)."""
    @property
    def px(self) -> _FloatArray:
        """Shear q_x on body 1 [stress], shape (MY, MX)."""
    @property
    def py(self) -> _FloatArray:
        """Shear q_y on body 1 [stress], shape (MY, MX)."""
    @property
    def gap(self) -> _FloatArray:
        """The deformed gap [length], shape (MY, MX)."""
    @property
    def state(self) -> _Int8Array:
        """State codes (``ELEMENT_STATES``), shape (MY, MX)."""

@final
class SpaceReport:
    """The result document of a half-space scene (``rollbem run --json`` of a 3D scene)."""

    @property
    def steps(self) -> Tuple[SpaceStep, ...]: ...
    @property
    def checks(self) -> List[Dict[str, Any]]: ...
    @property
    def all_pass(self) -> bool: ...
    @property
    def hertz(self) -> Optional[Dict[str, float]]:
        """Hertz's ellipse at the last step's load (a_x, a_y [length], p0 [stress], approach [length], load)."""
    @property
    def x(self) -> _FloatArray:
        """The element centres' x [length], shape (MY, MX) (made on each access)."""
    @property
    def y(self) -> _FloatArray:
        """The element centres' y [length], shape (MY, MX) (made on each access)."""
    def to_dict(self) -> Dict[str, Any]:
        """The whole document, as ``rollbem run --json`` writes it."""
    def to_json(self) -> str: ...

def run3d(scene: SpaceScene) -> SpaceReport:
    """Build and solve a half-space scene once."""


def fastsim(
    *,
    a: float,
    b: float,
    shear_modulus: float,
    nu: float,
    mu: float,
    normal_force: float,
    xi: float = 0.0,
    eta: float = 0.0,
    phi: float = 0.0,
    flexibility: str = "weighted",
    bound: str = "parabolic",
    direction: str = "+x",
    mx: int = 100,
    my: int = 100,
    contact_grid: Optional[float] = None,
    elements: bool = False,
) -> Dict[str, Any]:
    """One steady-rolling case of an elliptic contact by FASTSIM (Kalker's simplified theory), CONTACT's conventions:
    semi-axes ``a`` (rolling direction x) and ``b``, combined modulus of rigidity ``shear_modulus`` G and Poisson
    ratio ``nu``, friction ``mu``, normal force ``normal_force`` (units consistent, e.g. mm, N, N/mm^2); creepages
    ``xi``, ``eta`` (dimensionless) and spin ``phi`` (rad/length) of body 1 relative to body 2 (rigid slip
    (xi - phi*y, eta + phi*x)); forces on body 1, so xi > 0 gives fx < 0. ``flexibility``: weighted (Kalker's
    original), three or blended (CONTACT's M = 3); ``bound``: parabolic (Kalker's) or elliptic (Hertz);
    ``direction``: "+x" or "-x"; ``my`` strips of ``mx`` elements, or CONTACT's rectangle of mx x my elements over
    [-s a, s a] x [-s b, s b] with ``contact_grid=s``.

    Returns a dict: the inputs, ``fx``, ``fy`` (force), ``mz`` (force*length), ``fn_discrete``, ``n_contact``,
    ``n_adhesion``, ``n_slip``, ``flexibilities`` [L1, L2, L3], ``coefficients`` [C11, C22, C23]; with
    ``elements=True`` also float64 arrays ``x``, ``y``, ``pn``, ``px``, ``py`` and int8 ``state`` (0 exterior, 1
    adhesion, 2 slip), x fastest. Raises :class:`InputError` naming the argument (``key``)."""

def creep_table(
    spec: Union[str, "os.PathLike[str]"],
    out: Union[str, "os.PathLike[str]"],
    *,
    shard: Optional[str] = None,
    resume: bool = False,
    allow_large: bool = False,
) -> Dict[str, Any]:
    """Run a creep-table spec (``kind = "creep_table"``; README "Creep-force tables") into the CSV ``out`` (and the
    ``.npz`` beside it for a whole table), as ``rollbem sweep SPEC --out OUT`` does; ``shard="k/n"`` runs one shard,
    ``resume=True`` goes on from its journal. Returns ``total``, ``cases``, ``ran``, ``resumed``, ``statuses`` (a dict
    of counts) and ``npz`` (its path, or None). Read the table with :mod:`rollbem.creeptable`."""
