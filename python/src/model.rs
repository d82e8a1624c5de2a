//! `rollbem.Model`: a scene's flexibility built once ([`rollbem::pipeline::Model`]) and solved for one drive, a
//! list of drives (a creep curve, a family of loads) or a load path, each call on a worker thread with the GIL
//! released and Ctrl-C honoured ([`crate::worker`]).

use crate::convert::to_json;
use crate::drive::{with_steps, DriveKeys};
use crate::errors::{solve_error, to_py};
use crate::report::PyReport;
use crate::scene::PyScene;
use crate::worker;
use pyo3::prelude::*;
use pyo3::types::PyDict;
use rollbem::pipeline::{Model, Warm};
use rollbem::results::Report;
use rollbem::scene::document::StepTable;
use rollbem::scene::Scene;
use std::sync::Arc;

/// What one solve is asked to solve, read from Python on the calling thread.
enum Job {
    /// A whole scene (sharing the model's bodies and mesh).
    Scene(Box<Scene>),
    /// The model's scene with another drive.
    Drive(DriveKeys),
    /// The model's scene walking a load path.
    Path(Vec<StepTable>),
}

impl Job {
    /// The scene to solve (validated; on the worker thread).
    fn scene(self, base: &Scene) -> rollbem::Result<Scene> {
        match self {
            Job::Scene(s) => Ok(*s),
            Job::Drive(k) if k.is_empty() => Ok(base.clone()),
            Job::Drive(k) => k.apply(base),
            Job::Path(steps) => with_steps(base, steps),
        }
    }
}

/// A scene's flexibility (the mesh, the BEM system and its condensation, or the half-plane's influence
/// coefficients), built once and solved for as many drives as the caller has.
#[pyclass(name = "Model", module = "rollbem", frozen)]
pub struct PyModel {
    inner: Arc<Model>,
}

/// The `TypeError` of an argument of the wrong kind (`what` says what it must be).
pub fn wrong_type(obj: &Bound<'_, PyAny>, what: &str) -> PyErr {
    let ty = obj.get_type().name().map(|n| n.to_string()).unwrap_or_else(|_| "?".into());
    pyo3::exceptions::PyTypeError::new_err(format!("{what}, not {ty}"))
}

/// A drive argument: a `Scene`, or a mapping of drive keys merged with keyword drive keys. A key given both in the
/// mapping and as a keyword is bad input naming `drive.KEY`; an argument that is neither a `Scene` nor a mapping is
/// a `TypeError`.
fn job_of(
    py: Python<'_>,
    model: &Model,
    item: Option<&Bound<'_, PyAny>>,
    kwargs: Option<&Bound<'_, PyDict>>,
) -> PyResult<Job> {
    let base = model.scene();
    let invalid = |field: String, message: String| {
        to_py(py, rollbem::Error::Invalid { path: base.origin().to_path_buf(), field, message }.into())
    };
    if let Some(item) = item {
        if let Ok(s) = item.cast::<PyScene>() {
            if kwargs.is_some_and(|k| !k.is_empty()) {
                return Err(invalid(
                    "drive".into(),
                    "give a Scene or drive keys, not both (use scene.with_drive(...))".into(),
                ));
            }
            return Ok(Job::Scene(Box::new(s.get().inner.clone())));
        }
    }
    let mut value = match item {
        Some(m) => to_json(m, "drive", base.origin()).map_err(|f| to_py(py, f))?,
        None => serde_json::Value::Object(Default::default()),
    };
    let serde_json::Value::Object(map) = &mut value else {
        return Err(wrong_type(
            item.unwrap_or(&py.None().into_bound(py)),
            "a drive is a Scene or a mapping of drive keys",
        ));
    };
    if let Some(kw) = kwargs {
        for (k, v) in kw.iter() {
            let k = k.extract::<String>()?;
            if map.contains_key(&k) {
                return Err(invalid(
                    format!("drive.{k}"),
                    format!("`{k}` given twice: in the drive mapping and as a keyword argument"),
                ));
            }
            map.insert(k.clone(), to_json(&v, &format!("drive.{k}"), base.origin()).map_err(|f| to_py(py, f))?);
        }
    }
    let keys = DriveKeys::from_json(value, base).map_err(|f| to_py(py, f))?;
    keys.check(base).map_err(|e| to_py(py, e.into()))?;
    Ok(Job::Drive(keys))
}

/// Reports as Python objects; with `check`, the `SolveError` of the first one whose runs did not all end as the
/// scene expects.
fn finish(py: Python<'_>, reports: Vec<Report>, check: bool) -> PyResult<Vec<Py<PyReport>>> {
    let mut out = Vec::with_capacity(reports.len());
    for r in reports {
        let obj = Bound::new(py, PyReport::new(r))?;
        if check {
            if let Some(e) = solve_error(py, obj.as_any(), &obj.get().inner) {
                return Err(e);
            }
        }
        out.push(obj.unbind());
    }
    Ok(out)
}

#[pymethods]
impl PyModel {
    /// Build the flexibility of `scene` (its drive, friction, rolling and solvers may change later; its bodies,
    /// mesh and candidate zone may not). Raises `NumericalError` for a singular BEM system.
    #[new]
    fn new(py: Python<'_>, scene: &PyScene) -> PyResult<PyModel> {
        let scene = scene.inner.clone();
        let model = worker::run(py, move |_| Ok(Model::build(&scene)?))?;
        Ok(PyModel { inner: Arc::new(model) })
    }

    /// The scene the model was built for.
    #[getter]
    fn scene(&self) -> PyScene {
        PyScene::new(self.inner.scene().clone())
    }

    /// How many solves the model has done.
    #[getter]
    fn solves(&self) -> usize {
        self.inner.solves()
    }

    /// Seconds the build took: `{"assembly": ..., "condensation": ...}`.
    #[getter]
    fn build_time(&self) -> std::collections::BTreeMap<&'static str, f64> {
        let t = self.inner.timing();
        [("assembly", t.assembly), ("condensation", t.condensation)].into_iter().collect()
    }

    /// Whether `scene` can be solved on this model (the same bodies, mesh and candidate zone, and the blocks it
    /// needs); `solve` raises `InputError` naming the part that differs otherwise.
    fn accepts(&self, scene: &PyScene) -> bool {
        self.inner.accepts(&scene.inner).is_ok()
    }

    /// Solve once. `drive` is `None` (the model's scene as built), a `Scene` sharing the model's bodies and mesh,
    /// or a mapping of drive keys; keyword drive keys may be given instead (`model.solve(creepage=1e-3)`). Drive
    /// keys: `normal_approach` | `normal_load`, `tangential_shift` | `tangential_load`, `rotation` | `moment`, and
    /// `creepage`; each changes that degree of freedom of the scene's drive and keeps the others (units and signs
    /// of the scene file: d_N, d_T lengths, P, Q force per unit thickness, φ radians, M moment per unit thickness,
    /// ξ dimensionless). A key given both in the mapping and as a keyword, or both keys of one degree of freedom
    /// (or `creepage` with `tangential_load` in steady rolling), is an `InputError` naming `drive.KEY`; a `drive`
    /// that is neither `None`, a `Scene` nor a mapping is a `TypeError`. With `check=True` a run that did not end
    /// with the status the scene expects raises `SolveError` (with the report attached); otherwise the status is in
    /// the report.
    #[pyo3(signature = (drive = None, *, check = false, **drive_keys))]
    fn solve(
        &self,
        py: Python<'_>,
        drive: Option<&Bound<'_, PyAny>>,
        check: bool,
        drive_keys: Option<&Bound<'_, PyDict>>,
    ) -> PyResult<Py<PyReport>> {
        let job = job_of(py, &self.inner, drive, drive_keys)?;
        let model = self.inner.clone();
        let report = worker::run(py, move |cancel| {
            let scene = job.scene(model.scene())?;
            Ok(model.solve_with(&scene, &mut Warm::default(), cancel)?)
        })?;
        Ok(finish(py, vec![report], check)?.remove(0))
    }

    /// Solve for each of `drives` in order, each from rest, on this one model (a creep curve:
    /// `[{"creepage": xi} for xi in xis]`; a family of loads: `[{"normal_load": p} for p in ps]`; or scenes). One
    /// call: the flexibility is not built again, and Ctrl-C stops before the next drive. Returns one report per
    /// drive. `check` as for `solve`.
    #[pyo3(signature = (drives, *, check = false))]
    fn solve_all(&self, py: Python<'_>, drives: &Bound<'_, PyAny>, check: bool) -> PyResult<Vec<Py<PyReport>>> {
        let mut jobs = Vec::new();
        for item in drives.try_iter()? {
            jobs.push(job_of(py, &self.inner, Some(&item?), None)?);
        }
        self.inner.check_result_count(jobs.len()).map_err(|e| to_py(py, e.into()))?;
        let model = self.inner.clone();
        let reports = worker::run(py, move |cancel| {
            let mut out = Vec::with_capacity(jobs.len());
            // Each drive starts from the previous one's solutions (the answers do not depend on it; the work does).
            let mut warm = Warm::default();
            for job in jobs {
                let scene = job.scene(model.scene())?;
                out.push(model.solve_with(&scene, &mut warm, cancel)?);
            }
            Ok(out)
        })?;
        finish(py, reports, check)
    }

    /// Walk a load path on this model: `steps` is a sequence of mappings with the keys of `[[steps]]` (drive keys,
    /// `substeps`, `roll`; `TypeError` for anything but a sequence), friction with memory from substep to substep. The report's `steps` hold every substep
    /// and `history()` gives them as arrays. `check` as for `solve`.
    #[pyo3(signature = (steps, *, check = false))]
    fn solve_path(&self, py: Python<'_>, steps: &Bound<'_, PyAny>, check: bool) -> PyResult<Py<PyReport>> {
        let base = self.inner.scene();
        let steps = crate::drive::path_of(py, steps, base)?;
        let model = self.inner.clone();
        let report = worker::run(py, move |cancel| {
            let scene = Job::Path(steps).scene(model.scene())?;
            Ok(model.solve_with(&scene, &mut Warm::default(), cancel)?)
        })?;
        Ok(finish(py, vec![report], check)?.remove(0))
    }

    fn __repr__(&self) -> String {
        let t = self.inner.timing();
        format!(
            "<rollbem.Model of {:?}: built in {:.3} s, {} solves>",
            self.inner.scene().name(),
            t.assembly + t.condensation,
            self.inner.solves()
        )
    }
}

/// Build a scene's model and solve the scene once (what `rollbem run` does for a scene). `check` as for
/// `Model.solve`.
#[pyfunction]
#[pyo3(signature = (scene, *, check = false))]
pub fn run(py: Python<'_>, scene: &PyScene, check: bool) -> PyResult<Py<PyReport>> {
    let scene = scene.inner.clone();
    let report =
        worker::run(py, move |cancel| Ok(Model::build(&scene)?.solve_with(&scene, &mut Warm::default(), cancel)?))?;
    Ok(finish(py, vec![report], check)?.remove(0))
}

/// The benchmark's reference: the same creep curve through the Rust API alone (no Python between the solves):
/// build the model of `scene`, solve it at each creepage, and return (seconds, Q of the first run per creepage,
/// NaN where not solved). On the calling thread, or with `on_worker` on a worker thread of [`worker`] (where the
/// binding's solves run). `python/benches/creep_curve.py` times the Python API against it.
#[pyfunction]
#[pyo3(signature = (scene, creepages, on_worker = false))]
pub fn _rust_creep_curve(
    py: Python<'_>,
    scene: &PyScene,
    creepages: Vec<f64>,
    on_worker: bool,
) -> PyResult<(f64, Vec<f64>)> {
    let scene = scene.inner.clone();
    let curve = move || -> rollbem::Result<(f64, Vec<f64>)> {
        let start = std::time::Instant::now();
        let model = Model::build(&scene)?;
        let mut q = Vec::with_capacity(creepages.len());
        for xi in creepages {
            let report = model.solve(&scene.with_creepage(xi)?)?;
            q.push(report.runs[0].resultants.map_or(f64::NAN, |f| f.tangential));
        }
        Ok((start.elapsed().as_secs_f64(), q))
    };
    if on_worker {
        worker::run(py, move |_| Ok(curve()?))
    } else {
        py.detach(curve).map_err(|e| to_py(py, e.into()))
    }
}
