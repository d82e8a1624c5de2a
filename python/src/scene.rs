//! `rollbem.Scene`: a validated scene ([`rollbem::scene::Scene`]) made from TOML text, a file or Python mappings,
//! changed by dotted keys or by a drive, and read back as a dict or TOML.

use crate::convert::{to_json, to_python, toml_document, typed};
use crate::drive::{path_of, with_steps, DriveKeys};
use crate::errors::{keyed, to_py, Failure};
use pyo3::prelude::*;
use pyo3::types::PyDict;
use rollbem::scene::document::SceneDocument;
use rollbem::scene::Scene;
use serde_json::Value;
use std::path::{Path, PathBuf};

/// A validated scene: what to simulate. Made only by validation, so every value is in range and every part is
/// complete; bad input raises `InputError` naming the key.
#[pyclass(name = "Scene", module = "rollbem", frozen, eq)]
#[derive(Clone, PartialEq)]
pub struct PyScene {
    /// The scene.
    pub inner: Scene,
}

/// The origin of a scene made in Python (what its errors name).
fn code_origin() -> PathBuf {
    Scene::code_path()
}

/// A scene from a JSON object of the whole document.
fn from_json(value: Value, origin: &Path) -> Result<Scene, Failure> {
    let document: SceneDocument = typed(value, "", origin)?;
    Ok(Scene::from_document(document, origin)?)
}

/// Set a dotted key (`drive.normal_load`, `solvers.use`) in a JSON document; `Null` removes it.
pub(crate) fn set_dotted(doc: &mut Value, key: &str, value: Value, origin: &Path) -> Result<(), Failure> {
    let parts: Vec<&str> = key.split('.').collect();
    if parts.iter().any(|p| p.is_empty()) {
        return Err(keyed(origin, key, "not a dotted key (e.g. `drive.normal_load`)".into()));
    }
    let mut at = doc;
    for (i, p) in parts[..parts.len() - 1].iter().enumerate() {
        let Value::Object(map) = at else {
            return Err(keyed(origin, key, format!("`{}` is not a table", parts[..i].join("."))));
        };
        at = map.entry(p.to_string()).or_insert_with(|| Value::Object(Default::default()));
    }
    let Value::Object(map) = at else {
        return Err(keyed(origin, key, format!("`{}` is not a table", parts[..parts.len() - 1].join("."))));
    };
    let last = parts[parts.len() - 1].to_string();
    if value.is_null() {
        map.remove(&last);
    } else {
        map.insert(last, value);
    }
    Ok(())
}

impl PyScene {
    /// Wrap a scene.
    pub fn new(inner: Scene) -> PyScene {
        PyScene { inner }
    }
}

#[pymethods]
impl PyScene {
    /// Parse and validate scene TOML text (the format of `reference/scenes/*.toml`); `origin` names it in errors.
    #[staticmethod]
    #[pyo3(signature = (text, origin = None))]
    fn from_toml(py: Python<'_>, text: &str, origin: Option<PathBuf>) -> PyResult<PyScene> {
        let origin = origin.unwrap_or_else(code_origin);
        let scene = toml_document(text, &origin).and_then(|d| Ok(Scene::from_document(d, &origin)?));
        scene.map(PyScene::new).map_err(|f| to_py(py, f))
    }

    /// Read, parse and validate a scene file; a file that is not there raises `FileNotFoundError` (Python's
    /// `OSError` of the system's error), one that is not UTF-8 text `InputError`.
    #[staticmethod]
    fn from_file(py: Python<'_>, path: PathBuf) -> PyResult<PyScene> {
        let text = std::fs::read_to_string(&path)
            .map_err(|source| to_py(py, rollbem::Error::Io { path: path.clone(), source }.into()))?;
        PyScene::from_toml(py, &text, Some(path))
    }

    /// A scene from a mapping of its tables (the TOML document as nested dicts), keyword arguments, or both
    /// (keywords override the mapping's top-level keys). `TypeError` when `tables` is not a mapping.
    #[staticmethod]
    #[pyo3(signature = (tables = None, **kwargs))]
    fn from_dict(
        py: Python<'_>,
        tables: Option<&Bound<'_, PyAny>>,
        kwargs: Option<&Bound<'_, PyDict>>,
    ) -> PyResult<PyScene> {
        let origin = code_origin();
        let mut map = match tables {
            Some(t) => match to_json(t, "", &origin).map_err(|f| to_py(py, f))? {
                Value::Object(map) => map,
                _ => return Err(crate::model::wrong_type(t, "a scene is a mapping of its tables")),
            },
            None => Default::default(),
        };
        let made = (|| -> Result<Scene, Failure> {
            if let Some(kw) = kwargs {
                for (k, v) in kw.iter() {
                    let k = k.extract::<String>().map_err(|e| keyed(&origin, "", e.to_string()))?;
                    map.insert(k.clone(), to_json(&v, &k, &origin)?);
                }
            }
            from_json(Value::Object(map), &origin)
        })();
        made.map(PyScene::new).map_err(|f| to_py(py, f))
    }

    /// A changed copy: `changes` maps dotted keys (`"drive.normal_load"`, `"contact.friction"`, `"solvers.use"`) to
    /// their new values (`None` removes a key); validated again. `TypeError` when `changes` is not a mapping.
    fn edit(&self, py: Python<'_>, changes: &Bound<'_, PyAny>) -> PyResult<PyScene> {
        let origin = self.inner.origin().to_path_buf();
        let Value::Object(changes) = to_json(changes, "", &origin).map_err(|f| to_py(py, f))? else {
            return Err(crate::model::wrong_type(changes, "changes are a mapping of dotted keys to values"));
        };
        let made = (|| -> Result<Scene, Failure> {
            let mut doc = serde_json::to_value(self.inner.document())
                .map_err(|e| keyed(&origin, "", format!("cannot serialise the scene: {e}")))?;
            for (k, v) in changes {
                set_dotted(&mut doc, &k, v, &origin)?;
            }
            from_json(doc, &origin)
        })();
        made.map(PyScene::new).map_err(|f| to_py(py, f))
    }

    /// The scene with another one-step drive: the keys of `[drive]` (`normal_approach` | `normal_load`,
    /// `tangential_shift` | `tangential_load`, `rotation` | `moment`) and `creepage`. A degree of freedom named by
    /// one of its keys is replaced, the others kept; in steady rolling `creepage` and `tangential_load` replace each
    /// other. Units are the scene's; signs as in the scene file. Both keys of one degree of freedom (or `creepage`
    /// with `tangential_load` in steady rolling) are an `InputError` naming the first.
    #[pyo3(signature = (**drive))]
    fn with_drive(&self, py: Python<'_>, drive: Option<&Bound<'_, PyDict>>) -> PyResult<PyScene> {
        let keys = match drive {
            Some(d) => to_json(d.as_any(), "drive", self.inner.origin())
                .and_then(|v| DriveKeys::from_json(v, &self.inner))
                .map_err(|f| to_py(py, f))?,
            None => DriveKeys::default(),
        };
        keys.apply(&self.inner).map(PyScene::new).map_err(|e| to_py(py, e.into()))
    }

    /// The scene at another creepage ξ (dimensionless; ξ > 0 braking); an `InputError` naming `rolling.creepage` for
    /// a scene without `[rolling]`.
    fn with_creepage(&self, py: Python<'_>, creepage: f64) -> PyResult<PyScene> {
        self.inner.with_creepage(creepage).map(PyScene::new).map_err(|e| to_py(py, e.into()))
    }

    /// The scene walking a load path: a sequence of step mappings with the keys of `[[steps]]` (the drive keys,
    /// `substeps`, `roll`); `TypeError` for anything but a sequence.
    fn with_steps(&self, py: Python<'_>, steps: &Bound<'_, PyAny>) -> PyResult<PyScene> {
        let steps = path_of(py, steps, &self.inner)?;
        with_steps(&self.inner, steps).map(PyScene::new).map_err(|e| to_py(py, e.into()))
    }

    /// The scene as a dict of its tables, defaults filled in (what a result document holds as `scene`).
    fn to_dict<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        to_python(py, self.inner.document())
    }

    /// The scene as TOML text (it reads back as the same scene).
    fn to_toml(&self) -> PyResult<String> {
        toml::to_string(self.inner.document())
            .map_err(|e| pyo3::exceptions::PyRuntimeError::new_err(format!("cannot write the scene as TOML: {e}")))
    }

    /// Short identifier (names output files).
    #[getter]
    fn name(&self) -> String {
        self.inner.name().to_string()
    }

    /// What the scene is and where its numbers come from.
    #[getter]
    fn description(&self) -> String {
        self.inner.description().to_string()
    }

    /// The units label (e.g. `"N, mm, MPa"`), or `None`.
    #[getter]
    fn units(&self) -> Option<String> {
        self.inner.units().map(str::to_string)
    }

    /// Where the scene came from: its file, or `<scene>`.
    #[getter]
    fn origin(&self) -> PathBuf {
        self.inner.origin().to_path_buf()
    }

    /// The wheel's radius R (length unit).
    #[getter]
    fn radius(&self) -> f64 {
        self.inner.radius()
    }

    /// Coulomb's μ (0: frictionless).
    #[getter]
    fn friction(&self) -> f64 {
        self.inner.friction()
    }

    /// The plane-strain contact modulus of the pair, E* (stress unit): 1/E* = (1 − ν₁²)/E₁ + (1 − ν₂²)/E₂, the
    /// second term zero for a rigid flat.
    #[getter]
    fn contact_modulus(&self) -> f64 {
        self.inner.contact_modulus()
    }

    /// Dundurs' second parameter β of the pair in plane strain (dimensionless; `rollbem::material::dundurs_beta`):
    /// body 1 the wheel, body 2 the counter-body (a rigid flat has 1/G₂ = 0),
    /// β = [(1 − 2ν₁)/G₁ − (1 − 2ν₂)/G₂] / [2((1 − ν₁)/G₁ + (1 − ν₂)/G₂)]. Swapping the bodies changes its sign;
    /// an elastic wheel on a rigid flat has β = (1 − 2ν)/(2(1 − ν)) > 0; the more compliant body as the wheel gives
    /// β > 0; 0 (identical materials, or an incompressible wheel on a rigid flat) uncouples the normal and
    /// tangential problems.
    #[getter]
    fn dundurs_beta(&self) -> f64 {
        self.inner.dundurs_beta()
    }

    /// The wheel's model: `"bem"` or `"half_plane"`.
    #[getter]
    fn model(&self) -> &'static str {
        self.inner.model().name()
    }

    /// The width of the strip of half-spaces the contact is posed on (`[mesh] strip_width`, CONTACT's 2D model;
    /// length unit), or `None` in plane strain.
    #[getter]
    fn strip_width(&self) -> Option<f64> {
        self.inner.strip_width()
    }

    /// The element family: `"constant"` or `"quadratic"`.
    #[getter]
    fn element(&self) -> &'static str {
        self.inner.element().name()
    }

    /// The rolling formulation (`"steady"`, `"seed"`, `"transient"`), or `None` for a scene that does not roll.
    #[getter]
    fn rolling(&self) -> Option<&'static str> {
        self.inner.rolling().map(|r| r.mode().name())
    }

    /// The prescribed creepage ξ (dimensionless, ξ > 0 braking), or `None`.
    #[getter]
    fn creepage(&self) -> Option<f64> {
        self.inner.creepage()
    }

    /// The `[drive]` table as a dict with its keys (`normal_approach` | `normal_load`, `tangential_shift` |
    /// `tangential_load`, `rotation` | `moment`; the scene's units), empty for a load path.
    #[getter]
    fn drive<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        to_python(py, &self.inner.document().drive)
    }

    /// The `[[steps]]` of a load path as a list of dicts with the keys of `[drive]`, `substeps` and `roll` (empty for
    /// a one-step scene).
    #[getter]
    fn steps<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        to_python(py, &self.inner.document().steps)
    }

    /// The solvers the scene asks for (`[solvers] use`).
    #[getter]
    fn solvers(&self) -> Vec<String> {
        self.inner.document().solvers.use_.clone()
    }

    fn __repr__(&self) -> String {
        format!(
            "<rollbem.Scene {:?} ({}, {})>",
            self.inner.name(),
            self.inner.model().name(),
            self.inner.origin().display()
        )
    }
}
