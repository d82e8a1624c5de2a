//! `rollbem.Report`, `rollbem.Run`, `rollbem.Step`, `rollbem.Residuals`: the result document of a solve
//! ([`rollbem::results::Report`]) read from Python, node results as NumPy arrays.
//!
//! The document stays in Rust (shared by its runs); arrays and dicts are made when asked for, a new one each time.
//! Units are the scene's; signs as in the crate docs ("Conventions"): tractions act on the wheel, pressure p ≥ 0,
//! shear q = t_x (+x); x along the flat, the contact centred at x = 0.

use crate::convert::to_python;
use crate::errors::{solve_error, to_py};
use crate::stresses::PyStresses;
use numpy::PyArray1;
use pyo3::prelude::*;
use pyo3::types::PyDict;
use rollbem::post::{NodeResult, NodeState};
use rollbem::results::{Report, SolverRun};
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
    }
}

/// The result document of one solve: the scene, mesh facts, numerical health, the references, one run per solver
/// and, for a load path, every substep's runs.
#[pyclass(name = "Report", module = "rollbem", frozen)]
pub struct PyReport {
    /// The document.
    pub inner: Arc<Report>,
}

/// Where a run sits in its report.
#[derive(Clone, Copy)]
enum At {
    /// `runs[i]`: the run (a load path's at the last step it reached).
    Final(usize),
    /// `steps[s].runs[i]`.
    Step(usize, usize),
}

/// One solver's run: status, resultants, rigid motion, residuals and the per-node results.
#[pyclass(name = "Run", module = "rollbem", frozen)]
pub struct PyRun {
    report: Arc<Report>,
    at: At,
}

/// One substep of a load path: where it is on the path and every solver's run at its end.
#[pyclass(name = "Step", module = "rollbem", frozen)]
pub struct PyStep {
    report: Arc<Report>,
    index: usize,
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

impl PyReport {
    /// Wrap a document.
    pub fn new(inner: Report) -> PyReport {
        PyReport { inner: Arc::new(inner) }
    }

    fn run_at(&self, at: At) -> PyRun {
        PyRun { report: self.inner.clone(), at }
    }
}

/// A float array of the nodes.
fn column<'py>(py: Python<'py>, nodes: &[NodeResult], f: impl Fn(&NodeResult) -> f64) -> Bound<'py, PyArray1<f64>> {
    PyArray1::from_vec(py, nodes.iter().map(f).collect())
}

#[pymethods]
impl PyReport {
    /// Read a result document (`rollbem run --json FILE`); one of another schema is refused (`InputError`).
    #[staticmethod]
    fn read(py: Python<'_>, path: std::path::PathBuf) -> PyResult<PyReport> {
        Report::read(&path).map(PyReport::new).map_err(|e| to_py(py, e.into()))
    }

    /// Parse a result document's JSON text.
    #[staticmethod]
    fn from_json(py: Python<'_>, text: &str) -> PyResult<PyReport> {
        Report::from_json(text, std::path::Path::new("<json>")).map(PyReport::new).map_err(|e| to_py(py, e.into()))
    }

    /// One run per solver (for a load path: its run at the last step it reached).
    #[getter]
    fn runs(&self) -> Vec<PyRun> {
        (0..self.inner.runs.len()).map(|i| self.run_at(At::Final(i))).collect()
    }

    /// The run of `solver` (a registry name such as `"lemke"`), or the first run when `solver` is `None`; `KeyError`
    /// when the report has no run of that solver.
    #[pyo3(signature = (solver = None))]
    fn run(&self, solver: Option<&str>) -> PyResult<PyRun> {
        let i = match solver {
            None if !self.inner.runs.is_empty() => Some(0),
            None => None,
            Some(name) => self.inner.runs.iter().position(|r| r.solver.name() == name),
        };
        i.map(|i| self.run_at(At::Final(i))).ok_or_else(|| {
            let have: Vec<&str> = self.inner.runs.iter().map(|r| r.solver.name()).collect();
            pyo3::exceptions::PyKeyError::new_err(format!("no run of {solver:?} (runs: {})", have.join(", ")))
        })
    }

    /// A load path's substeps (empty for a one-step scene).
    #[getter]
    fn steps(&self) -> Vec<PyStep> {
        (0..self.inner.steps.len()).map(|index| PyStep { report: self.inner.clone(), index }).collect()
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

    /// Hertz at the run's load (frictionless scenes), as a dict (`half_width` a, `peak_pressure` p0, `load` P), or
    /// `None`.
    #[getter]
    fn hertz<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        to_python(py, &self.inner.references.hertz)
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
    /// `contact_element_length`).
    #[getter]
    fn mesh<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        to_python(py, &self.inner.mesh)
    }

    /// Numerical health as a dict (condition estimates, flexibility asymmetry, warnings).
    #[getter]
    fn diagnostics<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        to_python(py, &self.inner.diagnostics)
    }

    /// A load path's history for one solver (the first run's when `None`): a dict of arrays, one entry per substep
    /// that solver reached: `step`, `substep`, `rolled` (distance rolled), the resultants `normal_load`,
    /// `tangential_load`, `moment`, the rigid motion `normal_approach`, `tangential_shift`, `rotation`, the
    /// `creepage`, `dissipated` and `dissipated_total` (frictional energy per unit thickness), NaN where a value
    /// does not exist (a run that did not solve); and `status`, a list of str.
    #[pyo3(signature = (solver = None))]
    fn history<'py>(&self, py: Python<'py>, solver: Option<&str>) -> PyResult<Bound<'py, PyDict>> {
        let want = match solver {
            Some(s) => s.to_string(),
            None => self.inner.runs.first().map(|r| r.solver.name().to_string()).unwrap_or_default(),
        };
        let mut rows: Vec<(&rollbem::results::StepResult, &SolverRun)> = Vec::new();
        for st in &self.inner.steps {
            if let Some(r) = st.runs.iter().find(|r| r.solver.name() == want) {
                rows.push((st, r));
            }
        }
        let out = PyDict::new(py);
        let nan = f64::NAN;
        let col = |f: &dyn Fn(&rollbem::results::StepResult, &SolverRun) -> f64| -> Vec<f64> {
            rows.iter().map(|(s, r)| f(s, r)).collect()
        };
        let ints = |f: &dyn Fn(&rollbem::results::StepResult) -> usize| -> Vec<i64> {
            rows.iter().map(|(s, _)| f(s) as i64).collect()
        };
        out.set_item("step", PyArray1::from_vec(py, ints(&|s| s.step)))?;
        out.set_item("substep", PyArray1::from_vec(py, ints(&|s| s.substep)))?;
        out.set_item("rolled", PyArray1::from_vec(py, col(&|s, _| s.rolled)))?;
        out.set_item("normal_load", PyArray1::from_vec(py, col(&|_, r| r.resultants.map_or(nan, |f| f.normal))))?;
        out.set_item(
            "tangential_load",
            PyArray1::from_vec(py, col(&|_, r| r.resultants.map_or(nan, |f| f.tangential))),
        )?;
        out.set_item("moment", PyArray1::from_vec(py, col(&|_, r| r.resultants.map_or(nan, |f| f.moment))))?;
        out.set_item("normal_approach", PyArray1::from_vec(py, col(&|_, r| r.rigid_body.map_or(nan, |b| b.normal))))?;
        out.set_item(
            "tangential_shift",
            PyArray1::from_vec(py, col(&|_, r| r.rigid_body.and_then(|b| b.tangential).unwrap_or(nan))),
        )?;
        out.set_item("rotation", PyArray1::from_vec(py, col(&|_, r| r.rigid_body.map_or(nan, |b| b.rotation))))?;
        out.set_item(
            "creepage",
            PyArray1::from_vec(py, col(&|_, r| r.rolling.and_then(|x| x.creepage).unwrap_or(nan))),
        )?;
        out.set_item("dissipated", PyArray1::from_vec(py, col(&|_, r| r.history.map_or(nan, |h| h.dissipated))))?;
        out.set_item(
            "dissipated_total",
            PyArray1::from_vec(py, col(&|_, r| r.history.map_or(nan, |h| h.dissipated_total))),
        )?;
        out.set_item("status", rows.iter().map(|(_, r)| r.status.name()).collect::<Vec<_>>())?;
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
    fn get(&self) -> &SolverRun {
        match self.at {
            At::Final(i) => &self.report.runs[i],
            At::Step(s, i) => &self.report.steps[s].runs[i],
        }
    }
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

    /// Whether the status is `solved`.
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

    /// Resultant Q = ∫q dx (+x); `None` unless solved.
    #[getter]
    fn tangential_load(&self) -> Option<f64> {
        self.get().resultants.map(|f| f.tangential)
    }

    /// Moment M = Σ (x f_y − y f_x) of the tractions about the wheel centre (counter-clockwise); `None` unless
    /// solved.
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

    /// Contact figures as a dict (`x_min`, `x_max`, `half_width`, `peak_pressure`, `fit_half_width`,
    /// `fit_peak_pressure`, `stick_x_min`, `stick_x_max`, node counts, ...), or `None` unless solved.
    #[getter]
    fn contact<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        to_python(py, &self.get().contact)
    }

    /// The stick zone's edges (x of the outermost sticking nodes), or `None` (no friction, or nothing sticks).
    #[getter]
    fn stick_zone(&self) -> Option<(f64, f64)> {
        let r = self.get();
        if r.problem == rollbem::results::ProblemClass::Frictionless {
            return None;
        }
        rollbem::post::stick_edges(r.answer_nodes())
    }

    /// Number of contact nodes in the arrays below (0 for a run without an answer).
    #[getter]
    fn n_nodes(&self) -> usize {
        self.get().nodes.len()
    }

    /// x of each contact node (undeformed; length unit), shape (n,), float64.
    #[getter]
    fn x<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        column(py, &self.get().nodes, |n| n.x)
    }

    /// y of each contact node (undeformed; the flat is y = −R).
    #[getter]
    fn y<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        column(py, &self.get().nodes, |n| n.y)
    }

    /// Pressure p = t_y ≥ 0 on the wheel at each node (stress unit).
    #[getter]
    fn pressure<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        column(py, &self.get().nodes, |n| n.pressure)
    }

    /// Shear q = t_x on the wheel at each node (stress unit, +x; 0 without friction).
    #[getter]
    fn shear<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        column(py, &self.get().nodes, |n| n.shear)
    }

    /// Gap g = g₀ + u_y to the flat at each node (length; 0 in contact).
    #[getter]
    fn gap<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        column(py, &self.get().nodes, |n| n.gap)
    }

    /// Slip of the wheel relative to the flat at each node (length, +x; NaN where separated or not computed).
    #[getter]
    fn slip<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        column(py, &self.get().nodes, |n| n.slip.unwrap_or(f64::NAN))
    }

    /// Displacement u_x at each node, rigid motion included (length; NaN when the tangential problem was not
    /// built).
    #[getter]
    fn u_x<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        column(py, &self.get().nodes, |n| n.u_x.unwrap_or(f64::NAN))
    }

    /// Displacement u_y at each node, rigid motion included (length, +y).
    #[getter]
    fn u_y<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        column(py, &self.get().nodes, |n| n.u_y)
    }

    /// Slip velocity at each node (seed eq. 12; dimensionless, relative to the rolling speed; NaN without
    /// `[rolling]` or where not computed).
    #[getter]
    fn slip_velocity<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        column(py, &self.get().nodes, |n| n.slip_velocity.unwrap_or(f64::NAN))
    }

    /// Node state codes, int8: 0 stick, 1 slip, 2 contact (frictionless), 3 separated (`rollbem.NODE_STATES[code]`
    /// is the name).
    #[getter]
    fn state<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<i8>> {
        PyArray1::from_vec(py, self.get().nodes.iter().map(|n| state_code(n.state)).collect())
    }

    /// Node state names (`"stick"`, `"slip"`, `"contact"`, `"separated"`).
    #[getter]
    fn state_names(&self) -> Vec<&'static str> {
        self.get().nodes.iter().map(|n| NODE_STATES[state_code(n.state) as usize]).collect()
    }

    /// The subsurface stresses (only with `[stresses]`, for a solved run), or `None`.
    #[getter]
    fn stresses(&self) -> Option<PyStresses> {
        self.get().stresses.clone().map(PyStresses::new)
    }

    /// The elastic counter-body's own subsurface stresses from the same tractions (with `[stresses]` and
    /// `[counter_body] kind = "half_plane"`, depth measured into the counter-body), or `None`.
    #[getter]
    fn counter_body_stresses(&self) -> Option<PyStresses> {
        self.get().counter_body_stresses.clone().map(PyStresses::new)
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

    /// The run as a dict: exactly its entry in the JSON document.
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

    /// The drive at the substep's end, as in the JSON document (per DOF `{"Displacement": v}` or `{"Load": v}`).
    #[getter]
    fn drive<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        to_python(py, &self.report.steps[self.index].drive)
    }

    /// Every solver's run at the substep's end.
    #[getter]
    fn runs(&self) -> Vec<PyRun> {
        (0..self.report.steps[self.index].runs.len())
            .map(|i| PyRun { report: self.report.clone(), at: At::Step(self.index, i) })
            .collect()
    }

    fn __repr__(&self) -> String {
        let s = &self.report.steps[self.index];
        format!("<rollbem.Step {} {}/{}>", s.step, s.substep, s.substeps)
    }
}
