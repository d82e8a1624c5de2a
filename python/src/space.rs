//! The half-space (3D) scenes from Python: `rollbem.SpaceScene` (a validated [`rollbem::scene::SpaceScene`]),
//! `rollbem.SpaceModel` (its influence kernels, built once: [`rollbem::pipeline::SpaceModel`]) and
//! `rollbem.SpaceReport` / `rollbem.SpaceStep` (the result document, with each step's per-element results as
//! read-only NumPy arrays of shape (MY, MX): row `iy`, column `ix`, as the grid's elements are numbered).

use crate::convert::{to_json, to_python, typed};
use crate::errors::{keyed, to_py, Failure};
use crate::report::read_only;
use crate::worker;
use numpy::ndarray::Array2;
use numpy::PyArray2;
use pyo3::prelude::*;
use pyo3::sync::PyOnceLock;
use rollbem::pipeline::SpaceModel;
use rollbem::results::space::{SpaceReport, SpaceStepResult};
use rollbem::scene::space::SpaceDocument;
use rollbem::scene::{Scene, SpaceScene};
use serde_json::Value;
use std::path::{Path, PathBuf};
use std::sync::Arc;

/// A validated half-space scene (`[wheel] model = "half_space"`): bad input raises `InputError` naming the key.
#[pyclass(name = "SpaceScene", module = "rollbem", frozen)]
#[derive(Clone)]
pub struct PySpaceScene {
    inner: SpaceScene,
}

/// A document from a JSON value, validated.
fn from_json(value: Value, origin: &Path) -> Result<SpaceScene, Failure> {
    let document: SpaceDocument = typed(value, "", origin)?;
    Ok(SpaceScene::from_document(document, origin)?)
}

#[pymethods]
impl PySpaceScene {
    /// Parse and validate half-space scene TOML text; `origin` names it in errors and anchors a relative `gap_file`.
    #[staticmethod]
    #[pyo3(signature = (text, origin = None))]
    fn from_toml(py: Python<'_>, text: &str, origin: Option<PathBuf>) -> PyResult<PySpaceScene> {
        let origin = origin.unwrap_or_else(Scene::code_path);
        SpaceScene::from_toml(text, &origin).map(|inner| PySpaceScene { inner }).map_err(|e| to_py(py, e.into()))
    }

    /// Read, parse and validate a half-space scene file.
    #[staticmethod]
    fn from_file(py: Python<'_>, path: PathBuf) -> PyResult<PySpaceScene> {
        let text = std::fs::read_to_string(&path)
            .map_err(|source| to_py(py, rollbem::Error::Io { path: path.clone(), source }.into()))?;
        PySpaceScene::from_toml(py, &text, Some(path))
    }

    /// A scene from a mapping of its tables (the TOML document as nested dicts).
    #[staticmethod]
    fn from_dict(py: Python<'_>, tables: &Bound<'_, PyAny>) -> PyResult<PySpaceScene> {
        let origin = Scene::code_path();
        let made = to_json(tables, "", &origin).and_then(|v| from_json(v, &origin));
        made.map(|inner| PySpaceScene { inner }).map_err(|f| to_py(py, f))
    }

    /// A changed copy: `changes` maps dotted keys (`"drive.normal_load"`, `"contact.friction"`) to values (`None`
    /// removes a key); validated again.
    fn edit(&self, py: Python<'_>, changes: &Bound<'_, PyAny>) -> PyResult<PySpaceScene> {
        let origin = self.inner.origin().to_path_buf();
        let made = (|| -> Result<SpaceScene, Failure> {
            let Value::Object(changes) = to_json(changes, "", &origin)? else {
                return Err(keyed(&origin, "", "changes are a mapping of dotted keys to values".into()));
            };
            let mut doc = serde_json::to_value(self.inner.document())
                .map_err(|e| keyed(&origin, "", format!("cannot serialise the scene: {e}")))?;
            for (k, v) in changes {
                crate::scene::set_dotted(&mut doc, &k, v, &origin)?;
            }
            from_json(doc, &origin)
        })();
        made.map(|inner| PySpaceScene { inner }).map_err(|f| to_py(py, f))
    }

    /// The scene with the gap given per element: `gap` an array (or nested sequence) of shape (MY, MX), row `iy`
    /// first (length); it replaces `[profile]`.
    fn with_gap(&self, py: Python<'_>, gap: &Bound<'_, PyAny>) -> PyResult<PySpaceScene> {
        let rows: Vec<Vec<f64>> = if let Ok(a) = gap.call_method0("tolist") { a.extract()? } else { gap.extract()? };
        let made = self.inner.edit(|d| {
            d.profile = rollbem::scene::space::ProfileTable { gap: Some(rows), ..Default::default() };
        });
        made.map(|inner| PySpaceScene { inner }).map_err(|e| to_py(py, e.into()))
    }

    /// The scene's name.
    #[getter]
    fn name(&self) -> String {
        self.inner.name().to_string()
    }

    /// The grid's shape (MY, MX): the shape of every per-element array.
    #[getter]
    fn shape(&self) -> (usize, usize) {
        (self.inner.grid().my(), self.inner.grid().mx())
    }

    /// Coulomb's μ.
    #[getter]
    fn friction(&self) -> f64 {
        self.inner.friction()
    }

    /// Dundurs' β of the pair (body 1 first).
    #[getter]
    fn dundurs_beta(&self) -> f64 {
        self.inner.dundurs_beta()
    }

    /// The document as nested dicts (defaults filled in).
    fn to_dict<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        to_python(py, self.inner.document())
    }

    fn __repr__(&self) -> String {
        let g = self.inner.grid();
        format!("SpaceScene({:?}, {} × {} elements, μ = {})", self.inner.name(), g.mx(), g.my(), self.inner.friction())
    }
}

/// A half-space scene's influence kernels, built once (only those its effects need).
#[pyclass(name = "SpaceModel", module = "rollbem", frozen)]
pub struct PySpaceModel {
    inner: Arc<SpaceModel>,
}

#[pymethods]
impl PySpaceModel {
    /// Build the kernels of `scene`.
    #[new]
    fn new(py: Python<'_>, scene: &PySpaceScene) -> PyResult<PySpaceModel> {
        let scene = scene.inner.clone();
        let model = worker::run(py, move |_| Ok(SpaceModel::build(&scene)?))?;
        Ok(PySpaceModel { inner: Arc::new(model) })
    }

    /// Whether the tangential kernels were built (with friction only).
    #[getter]
    fn has_tangential(&self) -> bool {
        self.inner.influence().has_tangential()
    }

    /// Whether the coupling kernels were built (a dissimilar pair with friction asked to couple).
    #[getter]
    fn has_coupling(&self) -> bool {
        self.inner.influence().has_coupling()
    }

    /// Solve every step: the result document (a step without a solution is a status in it). Ctrl-C cancels.
    fn solve(&self, py: Python<'_>) -> PyResult<PySpaceReport> {
        let model = Arc::clone(&self.inner);
        let report = worker::run(py, move |cancel| Ok(model.solve(cancel)?))?;
        Ok(PySpaceReport::new(report))
    }
}

/// The result document of a half-space scene.
#[pyclass(name = "SpaceReport", module = "rollbem", frozen)]
pub struct PySpaceReport {
    inner: Arc<SpaceReport>,
    steps: PyOnceLock<Vec<Py<PySpaceStep>>>,
}

impl PySpaceReport {
    fn new(report: SpaceReport) -> PySpaceReport {
        PySpaceReport { inner: Arc::new(report), steps: PyOnceLock::new() }
    }
}

#[pymethods]
impl PySpaceReport {
    /// Every (sub)step, in order (a tuple).
    #[getter]
    fn steps<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, pyo3::types::PyTuple>> {
        let steps = self.steps.get_or_try_init(py, || -> PyResult<_> {
            (0..self.inner.steps.len())
                .map(|i| {
                    Py::new(py, PySpaceStep { report: Arc::clone(&self.inner), index: i, arrays: PyOnceLock::new() })
                })
                .collect()
        })?;
        pyo3::types::PyTuple::new(py, steps.iter().map(|s| s.clone_ref(py)))
    }

    /// The checks, as dicts (name, measured, reference, error, tolerance, pass, kind, note).
    #[getter]
    fn checks<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        to_python(py, &self.inner.checks)
    }

    /// Whether every check passed.
    #[getter]
    fn all_pass(&self) -> bool {
        self.inner.all_pass()
    }

    /// Hertz's ellipse at the last step's load (`a_x`, `a_y`, `p0`, `approach`, `load`), or None.
    #[getter]
    fn hertz<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        to_python(py, &self.inner.references.hertz)
    }

    /// The element centres' x (length), shape (MY, MX).
    #[getter]
    fn x<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray2<f64>>> {
        let g = self.inner.grid;
        grid_array(py, (g.my, g.mx), (0..g.len()).map(|i| g.centre(i % g.mx, i / g.mx).0).collect())
    }

    /// The element centres' y (length), shape (MY, MX).
    #[getter]
    fn y<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray2<f64>>> {
        let g = self.inner.grid;
        grid_array(py, (g.my, g.mx), (0..g.len()).map(|i| g.centre(i % g.mx, i / g.mx).1).collect())
    }

    /// The whole document as dicts, as `rollbem run --json` writes it.
    fn to_dict<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        to_python(py, &*self.inner)
    }

    /// The document as JSON text.
    fn to_json(&self) -> PyResult<String> {
        serde_json::to_string_pretty(&*self.inner)
            .map_err(|e| pyo3::exceptions::PyRuntimeError::new_err(format!("cannot serialise: {e}")))
    }
}

/// A read-only (MY, MX) array of grid values.
fn grid_array<T: numpy::Element>(py: Python<'_>, shape: (usize, usize), v: Vec<T>) -> PyResult<Bound<'_, PyArray2<T>>> {
    let a = Array2::from_shape_vec(shape, v)
        .map_err(|e| pyo3::exceptions::PyRuntimeError::new_err(format!("grid array of the wrong size: {e}")))?;
    read_only(PyArray2::from_owned_array(py, a))
}

/// One (sub)step of a half-space result.
#[pyclass(name = "SpaceStep", module = "rollbem", frozen)]
pub struct PySpaceStep {
    report: Arc<SpaceReport>,
    index: usize,
    arrays: PyOnceLock<[Py<PyAny>; 5]>,
}

impl PySpaceStep {
    fn step(&self) -> &SpaceStepResult {
        &self.report.steps[self.index]
    }

    /// The five arrays (pressure, qx, qy, gap, state), made once.
    fn array(&self, py: Python<'_>, k: usize) -> PyResult<Py<PyAny>> {
        let arrays = self.arrays.get_or_try_init(py, || -> PyResult<_> {
            let (g, e) = (self.report.grid, &self.step().elements);
            let shape = (g.my, g.mx);
            let f = |v: &Vec<f64>| grid_array(py, shape, v.clone()).map(|a| a.into_any().unbind());
            let state: Vec<i8> = e.state.iter().map(|&s| s as i8).collect();
            Ok([f(&e.pressure)?, f(&e.qx)?, f(&e.qy)?, f(&e.gap)?, grid_array(py, shape, state)?.into_any().unbind()])
        })?;
        Ok(arrays[k].clone_ref(py))
    }
}

#[pymethods]
impl PySpaceStep {
    /// `[[steps]]` index (0 for `[drive]`).
    #[getter]
    fn index(&self) -> usize {
        self.step().step
    }

    /// Substep, 1 ..= substeps.
    #[getter]
    fn substep(&self) -> usize {
        self.step().substep
    }

    /// The status: `solved`, `contact_at_grid_edge`, `not_converged`, `gross_sliding`, `no_contact`.
    #[getter]
    fn status(&self) -> &'static str {
        self.step().status.name()
    }

    /// What the status means.
    #[getter]
    fn message(&self) -> String {
        self.step().message.clone()
    }

    /// The normal load P (force).
    #[getter]
    fn load(&self) -> f64 {
        self.step().load
    }

    /// The approach (length).
    #[getter]
    fn approach(&self) -> f64 {
        self.step().approach
    }

    /// The tangential force (F_x, F_y) on body 1 (force).
    #[getter]
    fn force(&self) -> (f64, f64) {
        (self.step().force[0], self.step().force[1])
    }

    /// The shift (w_x, w_y) of body 1 relative to body 2 from the path's start (length), None after gross sliding.
    #[getter]
    fn shift(&self) -> Option<(f64, f64)> {
        self.step().shift.map(|w| (w[0], w[1]))
    }

    /// Elements in contact, in stick, in slip.
    #[getter]
    fn counts(&self) -> (usize, usize, usize) {
        (self.step().contact, self.step().stick, self.step().slip)
    }

    /// Pressure p per element (stress), shape (MY, MX), read-only.
    #[getter]
    fn pressure(&self, py: Python<'_>) -> PyResult<Py<PyAny>> {
        self.array(py, 0)
    }

    /// Shear q_x on body 1 per element (stress), shape (MY, MX).
    #[getter(px)]
    fn shear_x(&self, py: Python<'_>) -> PyResult<Py<PyAny>> {
        self.array(py, 1)
    }

    /// Shear q_y on body 1 per element (stress), shape (MY, MX).
    #[getter(py)]
    fn shear_y(&self, py: Python<'_>) -> PyResult<Py<PyAny>> {
        self.array(py, 2)
    }

    /// The deformed gap per element (length), shape (MY, MX).
    #[getter]
    fn gap(&self, py: Python<'_>) -> PyResult<Py<PyAny>> {
        self.array(py, 3)
    }

    /// State codes per element (int8: 0 exterior, 1 stick, 2 slip; `rollbem.ELEMENT_STATES`), shape (MY, MX).
    #[getter]
    fn state(&self, py: Python<'_>) -> PyResult<Py<PyAny>> {
        self.array(py, 4)
    }
}

/// `rollbem.run3d(scene)`: build and solve a half-space scene once.
#[pyfunction]
pub fn run3d(py: Python<'_>, scene: &PySpaceScene) -> PyResult<PySpaceReport> {
    let scene = scene.inner.clone();
    let report = worker::run(py, move |cancel| Ok(SpaceModel::build(&scene)?.solve(cancel)?))?;
    Ok(PySpaceReport::new(report))
}
