//! `rollbem.Report`, `rollbem.Run`, `rollbem.Step`, `rollbem.Residuals`: the result document of a solve
//! ([`rollbem::results::Report`]) read from Python, node results as NumPy arrays.
//!
//! The document stays in Rust (shared by its runs). What it holds is made into Python objects once, when first
//! asked for, and kept: a report's `Run` and `Step` objects, a run's node arrays and its stresses, a path's history
//! arrays. So `run.pressure is run.pressure`, and a loop over `run.pressure[i]` reads one array. The kept NumPy
//! arrays are read-only (their `WRITEABLE` flag cleared; they do not own their memory, so a caller cannot set it
//! back): one caller cannot change what another reads. Dicts (`timing`, `work`, `contact`, ...) are small and
//! made anew on each access, so a caller may change its copy.
//!
//! A run's node arrays are its **answer**: the nodes of a run whose status is `solved`
//! ([`SolverRun::answer_nodes`]), and none (arrays of shape (0,)) for any other status. A run judged
//! `contact_at_zone_edge` or `kinematics_out_of_range` keeps the discrete answer the harness refused as the
//! evidence for its verdict: in the document (`to_dict()["nodes"]`, the JSON), not in the arrays, which would pass
//! it off as an answer. Every figure derived from the nodes (`stick_zone`, `state`, `n_nodes`) follows the same
//! rule, as the library's own tables do.
//!
//! Units are the scene's; signs as in the crate docs ("Conventions"): tractions act on the wheel, pressure p ≥ 0,
//! shear q = t_x (+x); x along the flat, the contact centred at x = 0.

use crate::convert::to_python;
use crate::errors::{solve_error, to_py};
use crate::stresses::PyStresses;
use numpy::{Element, PyArray1, PyArrayMethods};
use pyo3::prelude::*;
use pyo3::sync::PyOnceLock;
use pyo3::types::{PyDict, PyTuple};
use rollbem::formulation::{Dof, Drive};
use rollbem::post::{NodeResult, NodeState};
use rollbem::results::{Report, SolverRun};
use std::collections::BTreeMap;
use std::sync::Arc;

/// The names of the node state codes of [`PyRun::state`], by code.
pub const NODE_STATES: [&str; 4] = ["stick", "slip", "contact", "separated"];

/// The code of a node state (its index in [`NODE_STATES`]).
fn state_code(s: NodeState) -> i8 {
    match s {
        NodeState::Stick => 0,
        NodeState::Slip => 1,
        NodeState::Contact => 2,
        NodeState::Separated => 3,
        // `NodeState` is `#[non_exhaustive]`: a state added after this binding was written.
        _ => -1,
    }
}

/// A NumPy array made read-only: its `WRITEABLE` flag cleared. The arrays the binding keeps are made from Rust
/// vectors and do not own their memory, so NumPy refuses to set the flag back (`ValueError`).
pub fn read_only<'py, T: Element, D: numpy::ndarray::Dimension>(
    array: Bound<'py, numpy::PyArray<T, D>>,
) -> PyResult<Bound<'py, numpy::PyArray<T, D>>> {
    let writable = array.try_readwrite().map_err(|e| pyo3::exceptions::PyRuntimeError::new_err(e.to_string()))?;
    drop(writable.make_nonwriteable());
    Ok(array)
}

/// A read-only float array of `values`.
fn floats(py: Python<'_>, values: Vec<f64>) -> PyResult<Py<PyArray1<f64>>> {
    Ok(read_only(PyArray1::from_vec(py, values))?.unbind())
}

/// The result document of one solve: the scene, mesh facts, numerical health, the references, one run per solver
/// and, for a load path, every substep's runs.
#[pyclass(name = "Report", module = "rollbem", frozen)]
pub struct PyReport {
    /// The document.
    pub inner: Arc<Report>,
    /// The runs as `Run` objects, made once.
    runs: PyOnceLock<Py<PyTuple>>,
    /// The substeps as `Step` objects, made once.
    steps: PyOnceLock<Py<PyTuple>>,
    /// Each solver's path history (`history()`), made once for all solvers.
    histories: PyOnceLock<BTreeMap<String, History>>,
}

/// Where a run sits in its report.
#[derive(Clone, Copy)]
enum At {
    /// `runs[i]`: the run (a load path's at the last step it reached).
    Final(usize),
    /// `steps[s].runs[i]`.
    Step(usize, usize),
}

/// One solver's run: status, resultants, rigid motion, residuals and the per-node results (its answer: none unless
/// solved; see the module docs).
#[pyclass(name = "Run", module = "rollbem", frozen)]
pub struct PyRun {
    report: Arc<Report>,
    at: At,
    /// The node arrays, made on first access.
    arrays: PyOnceLock<NodeArrays>,
    /// The wheel's stresses, made on first access.
    stresses: PyOnceLock<Option<Py<PyStresses>>>,
    /// The counter-body's stresses, made on first access.
    counter_body_stresses: PyOnceLock<Option<Py<PyStresses>>>,
}

/// A run's node arrays (read-only) and state names, made once from its answer nodes.
struct NodeArrays {
    x: Py<PyArray1<f64>>,
    y: Py<PyArray1<f64>>,
    pressure: Py<PyArray1<f64>>,
    shear: Py<PyArray1<f64>>,
    gap: Py<PyArray1<f64>>,
    slip: Py<PyArray1<f64>>,
    u_x: Py<PyArray1<f64>>,
    u_y: Py<PyArray1<f64>>,
    slip_velocity: Py<PyArray1<f64>>,
    state: Py<PyArray1<i8>>,
    state_names: Py<PyTuple>,
}

impl NodeArrays {
    /// The arrays of `nodes`, NaN where a value does not exist.
    fn of(py: Python<'_>, nodes: &[NodeResult]) -> PyResult<NodeArrays> {
        let col = |f: &dyn Fn(&NodeResult) -> f64| floats(py, nodes.iter().map(f).collect());
        let nan = f64::NAN;
        Ok(NodeArrays {
            x: col(&|n| n.x)?,
            y: col(&|n| n.y)?,
            pressure: col(&|n| n.pressure)?,
            shear: col(&|n| n.shear)?,
            gap: col(&|n| n.gap)?,
            slip: col(&|n| n.slip.unwrap_or(nan))?,
            u_x: col(&|n| n.u_x.unwrap_or(nan))?,
            u_y: col(&|n| n.u_y)?,
            slip_velocity: col(&|n| n.slip_velocity.unwrap_or(nan))?,
            state: read_only(PyArray1::from_vec(py, nodes.iter().map(|n| state_code(n.state)).collect()))?.unbind(),
            state_names: PyTuple::new(py, nodes.iter().map(|n| n.state.name()))?.unbind(),
        })
    }
}

/// One substep of a load path: where it is on the path and every solver's run at its end.
#[pyclass(name = "Step", module = "rollbem", frozen)]
pub struct PyStep {
    report: Arc<Report>,
    index: usize,
    /// The runs as `Run` objects, made once.
    runs: PyOnceLock<Py<PyTuple>>,
}

/// Solver-independent residuals of a run's physical conditions, relative (see `rollbem::post::evaluate`).
#[pyclass(name = "Residuals", module = "rollbem", frozen, get_all)]
pub struct PyResiduals {
    /// max |p_i g_i| / (p_max ℓ), ℓ the largest rigid gap over the candidate zone.
    complementarity: f64,
    /// max(0, −min g) / ℓ.
    penetration: f64,
    /// max(0, −min p) / p_max.
    tension: f64,
    /// Coulomb's law: max(0, |q| − μp)/(μ p_max) and the slip terms; `None` without friction.
    friction: Option<f64>,
    /// Worst |resultant − load| / |load| over the load-driven DOFs; `None` when displacement-driven.
    equilibrium: Option<f64>,
    /// The largest of those that apply.
    max: f64,
}

#[pymethods]
impl PyResiduals {
    fn __repr__(&self) -> String {
        let opt = |v: Option<f64>| v.map_or("None".to_string(), |v| format!("{v:.3e}"));
        format!(
            "Residuals(complementarity={:.3e}, penetration={:.3e}, tension={:.3e}, friction={}, equilibrium={}, \
             max={:.3e})",
            self.complementarity,
            self.penetration,
            self.tension,
            opt(self.friction),
            opt(self.equilibrium),
            self.max
        )
    }
}

/// The `KeyError` of a solver the report has no run of.
fn no_run(report: &Report, solver: Option<&str>) -> PyErr {
    let have: Vec<&str> = report.runs.iter().map(|r| r.solver.name()).collect();
    let have = if have.is_empty() { "none".to_string() } else { have.join(", ") };
    let what = match solver {
        Some(name) => format!("no run of solver '{name}' in this report (its runs: {have})"),
        None => "the report has no runs".to_string(),
    };
    pyo3::exceptions::PyKeyError::new_err(what)
}

/// The index of the run of `solver` (the first run when `None`) in `report.runs`.
fn run_index(report: &Report, solver: Option<&str>) -> PyResult<usize> {
    let i = match solver {
        None => (!report.runs.is_empty()).then_some(0),
        Some(name) => report.runs.iter().position(|r| r.solver.name() == name),
    };
    i.ok_or_else(|| no_run(report, solver))
}

impl PyReport {
    /// Wrap a document.
    pub fn new(inner: Report) -> PyReport {
        PyReport {
            inner: Arc::new(inner),
            runs: PyOnceLock::new(),
            steps: PyOnceLock::new(),
            histories: PyOnceLock::new(),
        }
    }

    /// The `Run` objects, made on first access.
    fn run_objects<'py>(&self, py: Python<'py>) -> PyResult<&Bound<'py, PyTuple>> {
        let made = self.runs.get_or_try_init(py, || -> PyResult<Py<PyTuple>> {
            let runs = (0..self.inner.runs.len())
                .map(|i| Py::new(py, PyRun::new(self.inner.clone(), At::Final(i))))
                .collect::<PyResult<Vec<_>>>()?;
            Ok(PyTuple::new(py, runs)?.unbind())
        })?;
        Ok(made.bind(py))
    }
}

/// A load path's history for one solver: one column per quantity, one entry per substep that solver reached.
struct History {
    /// The float and integer columns (read-only arrays), by name.
    columns: Vec<(&'static str, Py<PyAny>)>,
    /// `status` per substep.
    status: Py<PyTuple>,
}

impl History {
    /// The history of `solver` in `report`.
    fn of(py: Python<'_>, report: &Report, solver: &str) -> PyResult<History> {
        use rollbem::results::StepResult;
        let rows: Vec<(&StepResult, &SolverRun)> = report
            .steps
            .iter()
            .filter_map(|st| st.runs.iter().find(|r| r.solver.name() == solver).map(|r| (st, r)))
            .collect();
        let nan = f64::NAN;
        let col = |f: &dyn Fn(&StepResult, &SolverRun) -> f64| -> PyResult<Py<PyAny>> {
            Ok(floats(py, rows.iter().map(|(s, r)| f(s, r)).collect())?.into_any())
        };
        let ints = |f: &dyn Fn(&StepResult) -> usize| -> PyResult<Py<PyAny>> {
            let v: Vec<i64> = rows.iter().map(|(s, _)| f(s) as i64).collect();
            Ok(read_only(PyArray1::from_vec(py, v))?.into_any().unbind())
        };
        let columns = vec![
            ("step", ints(&|s| s.step)?),
            ("substep", ints(&|s| s.substep)?),
            ("rolled", col(&|s, _| s.rolled)?),
            ("normal_load", col(&|_, r| r.resultants.map_or(nan, |f| f.normal))?),
            ("tangential_load", col(&|_, r| r.resultants.map_or(nan, |f| f.tangential))?),
            ("moment", col(&|_, r| r.resultants.map_or(nan, |f| f.moment))?),
            ("normal_approach", col(&|_, r| r.rigid_body.map_or(nan, |b| b.normal))?),
            ("tangential_shift", col(&|_, r| r.rigid_body.and_then(|b| b.tangential).unwrap_or(nan))?),
            ("rotation", col(&|_, r| r.rigid_body.map_or(nan, |b| b.rotation))?),
            ("creepage", col(&|_, r| r.rolling.and_then(|x| x.creepage).unwrap_or(nan))?),
            ("dissipated", col(&|_, r| r.history.map_or(nan, |h| h.dissipated))?),
            ("dissipated_total", col(&|_, r| r.history.map_or(nan, |h| h.dissipated_total))?),
        ];
        let status = PyTuple::new(py, rows.iter().map(|(_, r)| r.status.name()))?.unbind();
        Ok(History { columns, status })
    }
}

/// A drive as a scene's `[drive]` table gives it: per degree of freedom the key that names what is prescribed
/// (`normal_approach` or `normal_load`, `tangential_shift` or `tangential_load`, `rotation` or `moment`) and its
/// value, in the scene's units; a tangential or rotational DOF held at zero displacement is left out, as a scene
/// leaves it out (an absent key means zero displacement there, and a half-plane has no rotation to name).
fn drive_dict<'py>(py: Python<'py>, drive: &Drive) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    match drive.normal {
        Dof::Displacement(v) => d.set_item("normal_approach", v)?,
        Dof::Load(v) => d.set_item("normal_load", v)?,
    }
    for (dof, displacement, load) in
        [(drive.tangential, "tangential_shift", "tangential_load"), (drive.rotational, "rotation", "moment")]
    {
        match dof {
            Dof::Displacement(0.0) => {}
            Dof::Displacement(v) => d.set_item(displacement, v)?,
            Dof::Load(v) => d.set_item(load, v)?,
        }
    }
    Ok(d)
}

#[pymethods]
impl PyReport {
    /// Read a result document (`rollbem run --json FILE`); one of another schema is refused (`InputError`), a file
    /// that is not there raises `FileNotFoundError`.
    #[staticmethod]
    fn read(py: Python<'_>, path: std::path::PathBuf) -> PyResult<PyReport> {
        Report::read(&path).map(PyReport::new).map_err(|e| to_py(py, e.into()))
    }

    /// Parse a result document's JSON text.
    #[staticmethod]
    fn from_json(py: Python<'_>, text: &str) -> PyResult<PyReport> {
        Report::from_json(text, std::path::Path::new("<json>")).map(PyReport::new).map_err(|e| to_py(py, e.into()))
    }

    /// One run per solver (for a load path: its run at the last step it reached), as a tuple made once: the same
    /// `Run` objects on every access.
    #[getter]
    fn runs(&self, py: Python<'_>) -> PyResult<Py<PyTuple>> {
        Ok(self.run_objects(py)?.clone().unbind())
    }

    /// The run of `solver` (a registry name such as `"lemke"`), or the first run when `solver` is `None`; `KeyError`
    /// when the report has no run of that solver.
    #[pyo3(signature = (solver = None))]
    fn run(&self, py: Python<'_>, solver: Option<&str>) -> PyResult<Py<PyAny>> {
        let i = run_index(&self.inner, solver)?;
        Ok(self.run_objects(py)?.get_item(i)?.unbind())
    }

    /// A load path's substeps (empty for a one-step scene), as a tuple made once.
    #[getter]
    fn steps(&self, py: Python<'_>) -> PyResult<Py<PyTuple>> {
        let made = self.steps.get_or_try_init(py, || -> PyResult<Py<PyTuple>> {
            let steps = (0..self.inner.steps.len())
                .map(|index| Py::new(py, PyStep { report: self.inner.clone(), index, runs: PyOnceLock::new() }))
                .collect::<PyResult<Vec<_>>>()?;
            Ok(PyTuple::new(py, steps)?.unbind())
        })?;
        Ok(made.clone_ref(py))
    }

    /// The scene as solved.
    #[getter]
    fn scene(&self) -> crate::scene::PyScene {
        crate::scene::PyScene::new(self.inner.scene.clone())
    }

    /// Whether every run ended with the status the scene expects (`solved` unless its `[checks] status` says
    /// otherwise).
    #[getter]
    fn ok(&self) -> bool {
        !rollbem::exit::unexpected_status(&self.inner)
    }

    /// Raise `SolveError` unless every run ended with the status the scene expects (the CLI's exit code 5).
    fn raise_for_status(slf: &Bound<'_, Self>) -> PyResult<()> {
        match solve_error(slf.py(), slf.as_any(), &slf.get().inner) {
            Some(e) => Err(e),
            None => Ok(()),
        }
    }

    /// Hertz at the run's load (frictionless scenes), as a dict (`half_width` a, length; `peak_pressure` p0,
    /// stress; `load` P, force per unit thickness), or `None`.
    #[getter]
    fn hertz<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        to_python(py, &self.inner.references.hertz)
    }

    /// Dundurs' β of the pair, as the document's references give it: body 1 the wheel, body 2 the counter-body (a
    /// rigid flat has 1/G₂ = 0); β = [(1 − 2ν₁)/G₁ − (1 − 2ν₂)/G₂] / [2((1 − ν₁)/G₁ + (1 − ν₂)/G₂)],
    /// dimensionless. Swapping the bodies changes its sign; an elastic wheel on a rigid flat has
    /// β = (1 − 2ν)/(2(1 − ν)) > 0; 0 uncouples the normal and tangential problems.
    #[getter]
    fn dundurs_beta(&self) -> f64 {
        self.inner.references.dundurs_beta
    }

    /// The checks against theory and between solvers, as dicts (`name`, `measured`, `reference`, `error`,
    /// `tolerance`, `pass`, `kind`, `note`).
    #[getter]
    fn checks<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        to_python(py, &self.inner.checks)
    }

    /// Whether every check passed.
    #[getter]
    fn all_pass(&self) -> bool {
        self.inner.all_pass()
    }

    /// Run-level warnings.
    #[getter]
    fn warnings(&self) -> Vec<String> {
        self.inner.warnings.clone()
    }

    /// Mesh facts as a dict (`model`, `elements`, `nodes`, `contact_nodes`, `element`, `system_size`,
    /// `contact_element_length` in the length unit).
    #[getter]
    fn mesh<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        to_python(py, &self.inner.mesh)
    }

    /// Numerical health as a dict (condition estimates, flexibility asymmetry, warnings).
    #[getter]
    fn diagnostics<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        to_python(py, &self.inner.diagnostics)
    }

    /// A load path's history for one solver (the first run's when `None`; `KeyError`, as `run`, for a solver the
    /// report has no run of): a new dict of arrays made once per report (read-only, the same arrays on every
    /// call), one entry per substep that solver reached: `step`, `substep` (int64), `rolled` (distance rolled,
    /// length), the resultants `normal_load`, `tangential_load` (force per unit thickness), `moment` (force × length
    /// per unit thickness), the rigid motion `normal_approach`, `tangential_shift` (length), `rotation` (radians),
    /// the `creepage` (dimensionless), `dissipated` and `dissipated_total` (frictional energy per unit thickness),
    /// NaN where a value does not exist (a substep whose run did not solve); and `status`, a tuple of str. A
    /// one-step report has no substeps: every array is empty.
    #[pyo3(signature = (solver = None))]
    fn history<'py>(&self, py: Python<'py>, solver: Option<&str>) -> PyResult<Bound<'py, PyDict>> {
        let name = self.inner.runs[run_index(&self.inner, solver)?].solver.name();
        let all = self.histories.get_or_try_init(py, || -> PyResult<BTreeMap<String, History>> {
            let mut all = BTreeMap::new();
            for r in &self.inner.runs {
                let solver = r.solver.name();
                all.insert(solver.to_string(), History::of(py, &self.inner, solver)?);
            }
            Ok(all)
        })?;
        let h = all.get(name).ok_or_else(|| no_run(&self.inner, Some(name)))?;
        let out = PyDict::new(py);
        for (k, v) in &h.columns {
            out.set_item(*k, v.bind(py))?;
        }
        out.set_item("status", h.status.bind(py))?;
        Ok(out)
    }

    /// The whole document as a dict: exactly the JSON `rollbem run --json` writes.
    fn to_dict<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        to_python(py, &*self.inner)
    }

    /// The document as JSON text (`indent` spaces, or compact).
    #[pyo3(signature = (indent = None))]
    fn to_json(&self, indent: Option<usize>) -> PyResult<String> {
        let err = |e: serde_json::Error| pyo3::exceptions::PyRuntimeError::new_err(e.to_string());
        match indent {
            None => serde_json::to_string(&*self.inner).map_err(err),
            Some(n) => {
                let pad = vec![b' '; n];
                let mut out = Vec::new();
                let fmt = serde_json::ser::PrettyFormatter::with_indent(&pad);
                let mut ser = serde_json::Serializer::with_formatter(&mut out, fmt);
                serde::Serialize::serialize(&*self.inner, &mut ser).map_err(err)?;
                Ok(String::from_utf8_lossy(&out).into_owned())
            }
        }
    }

    fn __len__(&self) -> usize {
        self.inner.runs.len()
    }

    fn __repr__(&self) -> String {
        let runs: Vec<String> = self.inner.runs.iter().map(|r| format!("{} {}", r.solver, r.status)).collect();
        format!("<rollbem.Report {:?}: {}>", self.inner.scene.name(), runs.join(", "))
    }
}

impl PyRun {
    fn new(report: Arc<Report>, at: At) -> PyRun {
        PyRun {
            report,
            at,
            arrays: PyOnceLock::new(),
            stresses: PyOnceLock::new(),
            counter_body_stresses: PyOnceLock::new(),
        }
    }

    fn get(&self) -> &SolverRun {
        match self.at {
            At::Final(i) => &self.report.runs[i],
            At::Step(s, i) => &self.report.steps[s].runs[i],
        }
    }

    /// The node arrays of the answer (module docs), made on first access.
    fn arrays(&self, py: Python<'_>) -> PyResult<&NodeArrays> {
        self.arrays.get_or_try_init(py, || NodeArrays::of(py, self.get().answer_nodes()))
    }
}

/// A kept array, as the getter returns it.
fn kept<T>(py: Python<'_>, a: &Py<T>) -> Py<T> {
    a.clone_ref(py)
}

#[pymethods]
impl PyRun {
    /// The solver's registry name.
    #[getter]
    fn solver(&self) -> &'static str {
        self.get().solver.name()
    }

    /// The harness's conclusion (`solved`, `infeasible`, `ray_termination`, `not_converged`, `numerical_error`,
    /// `contact_at_zone_edge`, `kinematics_out_of_range`): what to act on.
    #[getter]
    fn status(&self) -> &'static str {
        self.get().status.name()
    }

    /// Whether the status is `solved`: whether the run has an answer (node arrays, resultants, rigid motion).
    #[getter]
    fn solved(&self) -> bool {
        self.get().status == rollbem::status::Status::Solved
    }

    /// How the solver itself ended (before the harness checked its answer).
    #[getter]
    fn termination(&self) -> &'static str {
        self.get().termination.name()
    }

    /// Why `status` is not simply `termination`: a dict (`reason`, `message`), or `None` when it is.
    #[getter]
    fn verdict<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        to_python(py, &self.get().verdict)
    }

    /// What to tell a user about the run (the verdict's explanation, then the solver's message).
    #[getter]
    fn explanation(&self) -> String {
        self.get().explanation()
    }

    /// The formulation solved: `frictionless`, `displacement` or `loading`.
    #[getter]
    fn formulation(&self) -> &'static str {
        self.get().formulation.name()
    }

    /// Number of complementarity (or QP) unknowns.
    #[getter]
    fn problem_size(&self) -> usize {
        self.get().problem_size
    }

    /// The solver's work counters by name (pivots, iterations, sweeps, ...).
    #[getter]
    fn work<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let d = PyDict::new(py);
        for (k, v) in &self.get().work.0 {
            d.set_item(k, v)?;
        }
        Ok(d)
    }

    /// Seconds per stage: `assembly`, `condensation` (the model's one build), `formulation`, `solve`, `total`; and
    /// `setup`: `"built"` when the flexibility was built for this run, `"reused"` otherwise.
    #[getter]
    fn timing<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        to_python(py, &self.get().timing_s)
    }

    /// The residuals (`None` unless a solution was produced).
    #[getter]
    fn residuals(&self) -> Option<PyResiduals> {
        self.get().residuals.map(|r| PyResiduals {
            complementarity: r.complementarity,
            penetration: r.penetration,
            tension: r.tension,
            friction: r.friction,
            equilibrium: r.equilibrium,
            max: r.max(),
        })
    }

    /// The largest residual (`None` unless a solution was produced).
    #[getter]
    fn residual(&self) -> Option<f64> {
        self.get().residuals.map(|r| r.max())
    }

    /// Resultant P = ∫p dx of the contact tractions on the wheel (force per unit thickness, compressive > 0);
    /// `None` unless solved.
    #[getter]
    fn normal_load(&self) -> Option<f64> {
        self.get().resultants.map(|f| f.normal)
    }

    /// Resultant Q = ∫q dx of the tractions on the wheel (force per unit thickness, +x); `None` unless solved.
    #[getter]
    fn tangential_load(&self) -> Option<f64> {
        self.get().resultants.map(|f| f.tangential)
    }

    /// Moment M = Σ (x f_y − y f_x) of the tractions about the wheel centre (force × length per unit thickness,
    /// counter-clockwise); `None` unless solved.
    #[getter]
    fn moment(&self) -> Option<f64> {
        self.get().resultants.map(|f| f.moment)
    }

    /// The support's approach d_N towards the flat (length, positive compresses); `None` unless solved.
    #[getter]
    fn normal_approach(&self) -> Option<f64> {
        self.get().rigid_body.map(|b| b.normal)
    }

    /// The support's tangential shift d_T (+x, length); `None` unless solved, or indeterminate (at the sliding
    /// limit |Q| = μP).
    #[getter]
    fn tangential_shift(&self) -> Option<f64> {
        self.get().rigid_body.and_then(|b| b.tangential)
    }

    /// The support's rotation φ (radians, counter-clockwise); `None` unless solved.
    #[getter]
    fn rotation(&self) -> Option<f64> {
        self.get().rigid_body.map(|b| b.rotation)
    }

    /// The creepage ξ, prescribed or computed from a prescribed Q (dimensionless, ξ > 0 braking); `None` without
    /// rolling or unless solved.
    #[getter]
    fn creepage(&self) -> Option<f64> {
        self.get().rolling.and_then(|r| r.creepage)
    }

    /// Contact figures as a dict (`x_min`, `x_max`, `half_width`, `fit_half_width`, `stick_x_min`, `stick_x_max`
    /// in the length unit; `peak_pressure`, `fit_peak_pressure` in the stress unit; node counts, ...), or `None`
    /// unless solved.
    #[getter]
    fn contact<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        to_python(py, &self.get().contact)
    }

    /// The stick zone's edges (left, right; length unit), each midway between the outermost sticking node and its
    /// neighbour, or `None`: no friction, nothing sticks, or no answer (a run not solved).
    #[getter]
    fn stick_zone(&self) -> Option<(f64, f64)> {
        let r = self.get();
        if r.problem == rollbem::results::ProblemClass::Frictionless {
            return None;
        }
        rollbem::post::stick_edges(r.answer_nodes())
    }

    /// Number of contact nodes in the node arrays: the mesh's contact nodes for a solved run, 0 for any other status.
    #[getter]
    fn n_nodes(&self) -> usize {
        self.get().answer_nodes().len()
    }

    /// x of each contact node (undeformed; length unit), shape (n_nodes,), float64, read-only.
    #[getter]
    fn x(&self, py: Python<'_>) -> PyResult<Py<PyArray1<f64>>> {
        Ok(kept(py, &self.arrays(py)?.x))
    }

    /// y of each contact node (undeformed; length unit; the flat is y = −R).
    #[getter]
    fn y(&self, py: Python<'_>) -> PyResult<Py<PyArray1<f64>>> {
        Ok(kept(py, &self.arrays(py)?.y))
    }

    /// Pressure p = t_y ≥ 0 on the wheel at each node (stress unit).
    #[getter]
    fn pressure(&self, py: Python<'_>) -> PyResult<Py<PyArray1<f64>>> {
        Ok(kept(py, &self.arrays(py)?.pressure))
    }

    /// Shear q = t_x on the wheel at each node (stress unit, +x; 0 without friction).
    #[getter]
    fn shear(&self, py: Python<'_>) -> PyResult<Py<PyArray1<f64>>> {
        Ok(kept(py, &self.arrays(py)?.shear))
    }

    /// Gap g = g₀ + u_y to the flat at each node (length; 0 in contact).
    #[getter]
    fn gap(&self, py: Python<'_>) -> PyResult<Py<PyArray1<f64>>> {
        Ok(kept(py, &self.arrays(py)?.gap))
    }

    /// Slip of the wheel relative to the flat at each node (length, +x; NaN where separated or not computed).
    #[getter]
    fn slip(&self, py: Python<'_>) -> PyResult<Py<PyArray1<f64>>> {
        Ok(kept(py, &self.arrays(py)?.slip))
    }

    /// Displacement u_x at each node, rigid motion included (length, +x; NaN when the tangential problem was not
    /// built).
    #[getter]
    fn u_x(&self, py: Python<'_>) -> PyResult<Py<PyArray1<f64>>> {
        Ok(kept(py, &self.arrays(py)?.u_x))
    }

    /// Displacement u_y at each node, rigid motion included (length, +y).
    #[getter]
    fn u_y(&self, py: Python<'_>) -> PyResult<Py<PyArray1<f64>>> {
        Ok(kept(py, &self.arrays(py)?.u_y))
    }

    /// Slip velocity at each node (seed eq. 12; dimensionless, relative to the rolling speed; NaN without
    /// `[rolling]` or where not computed).
    #[getter]
    fn slip_velocity(&self, py: Python<'_>) -> PyResult<Py<PyArray1<f64>>> {
        Ok(kept(py, &self.arrays(py)?.slip_velocity))
    }

    /// Node state codes, int8, read-only: 0 stick, 1 slip, 2 contact (frictionless), 3 separated
    /// (`rollbem.NODE_STATES[code]` is the name).
    #[getter]
    fn state(&self, py: Python<'_>) -> PyResult<Py<PyArray1<i8>>> {
        Ok(kept(py, &self.arrays(py)?.state))
    }

    /// Node state names (`"stick"`, `"slip"`, `"contact"`, `"separated"`), a tuple made once.
    #[getter]
    fn state_names(&self, py: Python<'_>) -> PyResult<Py<PyTuple>> {
        Ok(kept(py, &self.arrays(py)?.state_names))
    }

    /// The subsurface stresses (only with `[stresses]`, for a solved run), or `None`; the same object on every
    /// access.
    #[getter]
    fn stresses(&self, py: Python<'_>) -> PyResult<Option<Py<PyStresses>>> {
        let made = self.stresses.get_or_try_init(py, || -> PyResult<_> {
            self.get().stresses.clone().map(|s| Py::new(py, PyStresses::new(s))).transpose()
        })?;
        Ok(made.as_ref().map(|s| s.clone_ref(py)))
    }

    /// The elastic counter-body's own subsurface stresses from the same tractions (with `[stresses]` and
    /// `[counter_body] kind = "half_plane"`, depth measured into the counter-body), or `None`.
    #[getter]
    fn counter_body_stresses(&self, py: Python<'_>) -> PyResult<Option<Py<PyStresses>>> {
        let made = self.counter_body_stresses.get_or_try_init(py, || -> PyResult<_> {
            self.get().counter_body_stresses.clone().map(|s| Py::new(py, PyStresses::new(s))).transpose()
        })?;
        Ok(made.as_ref().map(|s| s.clone_ref(py)))
    }

    /// Raise `SolveError` unless the run ended with the status its scene expects (`solved` unless declared).
    fn raise_for_status(&self, py: Python<'_>) -> PyResult<()> {
        let run = self.get();
        let expected = self.report.scene.expect().status_for(run.solver);
        if run.status == expected {
            return Ok(());
        }
        let cls = py.import("rollbem.errors")?.getattr("SolveError")?;
        let kw = PyDict::new(py);
        kw.set_item("status", run.status.name())?;
        kw.set_item("solver", run.solver.name())?;
        kw.set_item("explanation", run.explanation())?;
        let message = format!("{} ended {} (expected {expected}): {}", run.solver, run.status, run.explanation());
        Err(PyErr::from_value(cls.call((message,), Some(&kw))?))
    }

    /// The run as a dict: exactly its entry in the JSON document (for a run judged `contact_at_zone_edge` or
    /// `kinematics_out_of_range`, `nodes` holds the refused answer, the verdict's evidence).
    fn to_dict<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        to_python(py, self.get())
    }

    fn __repr__(&self) -> String {
        let r = self.get();
        match r.resultants {
            Some(f) => format!("<rollbem.Run {} {}: P={:e} Q={:e}>", r.solver, r.status, f.normal, f.tangential),
            None => format!("<rollbem.Run {} {}>", r.solver, r.status),
        }
    }
}

#[pymethods]
impl PyStep {
    /// Step index (from 0, as in `[[steps]]`).
    #[getter]
    fn step(&self) -> usize {
        self.report.steps[self.index].step
    }

    /// Substep (1 ..= substeps).
    #[getter]
    fn substep(&self) -> usize {
        self.report.steps[self.index].substep
    }

    /// Number of substeps of the step.
    #[getter]
    fn substeps(&self) -> usize {
        self.report.steps[self.index].substeps
    }

    /// Distance rolled since the start of the path (length unit).
    #[getter]
    fn rolled(&self) -> f64 {
        self.report.steps[self.index].rolled
    }

    /// The drive at the substep's end with the keys of a scene's `[drive]`: per degree of freedom the one that names
    /// what is prescribed there (`normal_approach` or `normal_load`, `tangential_shift` or `tangential_load`,
    /// `rotation` or `moment`), in the scene's units; a tangential or rotational DOF held at zero displacement is
    /// left out, as in a scene file. A drive mapping `Model.solve` and `Scene.with_drive` accept.
    #[getter]
    fn drive<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        drive_dict(py, &self.report.steps[self.index].drive)
    }

    /// Every solver's run at the substep's end, as a tuple made once.
    #[getter]
    fn runs(&self, py: Python<'_>) -> PyResult<Py<PyTuple>> {
        let made = self.runs.get_or_try_init(py, || -> PyResult<Py<PyTuple>> {
            let runs = (0..self.report.steps[self.index].runs.len())
                .map(|i| Py::new(py, PyRun::new(self.report.clone(), At::Step(self.index, i))))
                .collect::<PyResult<Vec<_>>>()?;
            Ok(PyTuple::new(py, runs)?.unbind())
        })?;
        Ok(made.clone_ref(py))
    }

    fn __repr__(&self) -> String {
        let s = &self.report.steps[self.index];
        format!("<rollbem.Step {} {}/{}>", s.step, s.substep, s.substeps)
    }
}
