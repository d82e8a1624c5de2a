//! Solvers written in Python, plugged into rollbem's registry at run time ([`register_solver`]): a callable that
//! solves the problem's LCP, `z = solve(M, q)` with `w = M z + q ≥ 0, z ≥ 0, wᵀz = 0` (NumPy arrays, M of shape
//! (m, m)). rollbem builds the LCP (its formulation, with the scene's drive, friction and slip operator), calls the
//! function on the worker thread with the GIL held, unpacks z into the physical unknowns and certifies the answer by
//! its own residuals, as for a built-in solver; scenes name it in `[solvers] use`. What the function raises or
//! returns wrongly (a wrong length, a non-finite value) is the run's `numerical_error`, with the message. A call into
//! Python cannot be interrupted from here: Ctrl-C cancels the run when the function returns.

use pyo3::prelude::*;
use rollbem::formulation::ContactProblem;
use rollbem::solvers::{Entry, Facts, Outcome, Solver, SolverId, Start, Termination, Validate, Work};
use std::sync::Mutex;

/// The registered Python solvers: name → (the callable, whether it takes frictional problems).
static SOLVERS: Mutex<Vec<(&'static str, Py<PyAny>, bool)>> = Mutex::new(Vec::new());

/// A Python solver has no settings table of its own (`[solvers.NAME]` must be empty).
#[derive(Debug, Clone, Copy, Default, PartialEq, serde::Serialize, serde::Deserialize)]
#[serde(deny_unknown_fields)]
struct NoSettings {}

impl Validate for NoSettings {
    fn validate(&self) -> Result<(), (&'static str, String)> {
        Ok(())
    }
}

/// A Python solver, as the registry builds it.
struct PySolver {
    id: SolverId,
}

/// Whether the Python solver of `name` takes frictional problems (`None`: not registered).
fn frictional(name: &str) -> Option<bool> {
    SOLVERS.lock().unwrap_or_else(|e| e.into_inner()).iter().find(|(n, ..)| *n == name).map(|(_, _, f)| *f)
}

impl Solver for PySolver {
    fn id(&self) -> SolverId {
        self.id
    }

    fn admits(&self, facts: &Facts) -> Result<(), String> {
        match frictional(self.id.name()) {
            Some(false) if facts.friction => {
                Err("registered for frictionless problems (register_solver(..., frictional=True) for others)".into())
            }
            _ => Ok(()),
        }
    }

    fn uses_lcp(&self) -> bool {
        true
    }

    fn solve_from(&self, p: &ContactProblem, start: Start) -> Outcome {
        let Some(lcp) = p.lcp() else {
            return Outcome::failed(
                Termination::Infeasible,
                "no static problem (gross sliding)".into(),
                Work::default(),
            );
        };
        let m = lcp.size();
        let call = Python::attach(|py| -> PyResult<Vec<f64>> {
            let f = {
                let solvers = SOLVERS.lock().unwrap_or_else(|e| e.into_inner());
                let Some((_, f, _)) = solvers.iter().find(|(n, ..)| *n == self.id.name()) else {
                    return Err(pyo3::exceptions::PyKeyError::new_err("the solver is no longer registered"));
                };
                f.clone_ref(py)
            };
            let rows: Vec<Vec<f64>> = (0..m).map(|i| (0..m).map(|j| lcp.m()[(i, j)]).collect()).collect();
            let mm = numpy::PyArray2::from_vec2(py, &rows)?;
            let q = numpy::PyArray1::from_vec(py, lcp.q().to_vec());
            f.call1(py, (mm, q))?.extract::<Vec<f64>>(py)
        });
        if start.cancel.is_cancelled() {
            return Outcome::failed(Termination::NotConverged, "cancelled".into(), Work::default());
        }
        let z = match call {
            Ok(z) if z.len() == m && z.iter().all(|v| v.is_finite()) => z,
            Ok(z) => {
                let why =
                    format!("the Python solver returned {} values (the LCP has {m}) or a non-finite one", z.len());
                return Outcome::failed(Termination::NumericalError, why, Work::default());
            }
            Err(e) => {
                let why = format!("the Python solver raised {e}");
                return Outcome::failed(Termination::NumericalError, why, Work::default());
            }
        };
        match p.unpack(&z) {
            Some(s) => Outcome::solved(s, format!("the Python solver returned z ({m} unknowns)"), Work::default()),
            None => Outcome::failed(Termination::NumericalError, "z of another size".into(), Work::default()),
        }
    }
}

/// Register `solve(M, q) -> z`, a solver of the LCP written in Python, under `name` (lowercase letters, digits and
/// `_`; not a name rollbem has): scenes can then name it in `[solvers] use` (as `Scene.edit({"solvers.use": [name,
/// "lemke"]})`), and the model, `run` and `sweep` run it like a built-in solver, certified by the same residuals.
/// `frictional=False` (the default) refuses it for frictional scenes when they are read (the frictional LCPs are
/// not symmetric and have zero diagonals; a simple method will not solve them). Raises `ValueError` for a name
/// taken or not valid, `TypeError` for a `solve` that is not callable.
#[pyfunction]
#[pyo3(signature = (name, solve, *, summary = None, frictional = false))]
pub fn register_solver(
    py: Python<'_>,
    name: String,
    solve: Py<PyAny>,
    summary: Option<String>,
    frictional: bool,
) -> PyResult<()> {
    if !solve.bind(py).is_callable() {
        return Err(pyo3::exceptions::PyTypeError::new_err("solve must be callable: solve(M, q) -> z"));
    }
    // Entries live for the process's life (the registry holds `&'static Entry`).
    let name: &'static str = Box::leak(name.into_boxed_str());
    let summary: &'static str =
        Box::leak(summary.unwrap_or_else(|| "a solver of the LCP written in Python".into()).into_boxed_str());
    let entry: &'static Entry = Box::leak(Box::new(Entry::new::<NoSettings>(
        name,
        summary,
        false,
        &[],
        |id, _| Box::new(PySolver { id }),
        |m| (1e-8 * m * m * m, 8.0 * m * m),
    )));
    rollbem::solvers::register(entry).map_err(pyo3::exceptions::PyValueError::new_err)?;
    SOLVERS.lock().unwrap_or_else(|e| e.into_inner()).push((name, solve, frictional));
    Ok(())
}
