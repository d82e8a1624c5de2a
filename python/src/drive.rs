//! Drives and load paths given from Python as mappings, applied to a scene.
//!
//! A drive mapping has the keys of a scene's `[drive]` table (`normal_approach` | `normal_load`, `tangential_shift`
//! | `tangential_load`, `rotation` | `moment`) and `creepage` (`[rolling] creepage`). It **changes** the scene's
//! one-step drive: a degree of freedom named by either of its keys is replaced (giving `normal_load` drops the
//! scene's `normal_approach`), the others are kept. In steady rolling the creepage and the tangential load are the
//! two ways to drive the tangential degree of freedom: giving one drops the other (as
//! [`rollbem::scene::Scene::with_creepage`] does). A load path's scene becomes a one-step scene. The result is
//! validated like a scene file.
//!
//! One mapping names each degree of freedom once: both keys of a pair (`normal_approach` and `normal_load`, ...),
//! or `creepage` with `tangential_load` in steady rolling, are bad input naming the first key of the pair
//! ([`DriveKeys::check`]), as a scene file's `[drive]` is; nothing is resolved silently. (A key given both in a
//! mapping and as a keyword is refused where they are merged, `crate::model`.)
//!
//! A load path is a list of step mappings with the keys of `[[steps]]` (the drive keys, `substeps`, `roll`); it
//! replaces the scene's drive or path.

use crate::convert::{to_json, typed};
use crate::errors::{to_py, Failure};
use pyo3::prelude::*;
use rollbem::error::Error;
use rollbem::scene::document::StepTable;
use rollbem::scene::{RollingMode, Scene};
use serde::Deserialize;
use serde_json::Value;

/// The keys of a drive mapping (module docs); each `None` when not given.
#[derive(Debug, Clone, Copy, Default, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct DriveKeys {
    /// Rigid approach d_N towards the flat (length; positive compresses).
    pub normal_approach: Option<f64>,
    /// Normal load P = ∫p dx (force per unit thickness; positive compressive).
    pub normal_load: Option<f64>,
    /// Tangential shift d_T of the support (+x, length).
    pub tangential_shift: Option<f64>,
    /// Tangential load Q = ∫q dx.
    pub tangential_load: Option<f64>,
    /// Rotation φ of the support (counter-clockwise, radians).
    pub rotation: Option<f64>,
    /// Moment M about the wheel centre (counter-clockwise).
    pub moment: Option<f64>,
    /// Creepage ξ (dimensionless, ξ > 0 braking), for a rolling scene.
    pub creepage: Option<f64>,
}

impl DriveKeys {
    /// The keys of a JSON object (errors name `drive.KEY`).
    pub fn from_json(value: Value, scene: &Scene) -> Result<DriveKeys, Failure> {
        typed(value, "drive", scene.origin())
    }

    /// Refuse a mapping that drives a degree of freedom twice (module docs): an `Invalid` error naming
    /// `drive.KEY`, the first key of the pair.
    pub fn check(&self, scene: &Scene) -> rollbem::Result<()> {
        let k = self;
        let pairs = [
            ("normal_approach", k.normal_approach, "normal_load", k.normal_load),
            ("tangential_shift", k.tangential_shift, "tangential_load", k.tangential_load),
            ("rotation", k.rotation, "moment", k.moment),
        ];
        let twice = |a: &str, b: &str, why: &str| Error::Invalid {
            path: scene.origin().to_path_buf(),
            field: format!("drive.{a}"),
            message: format!("give either `{a}` or `{b}`, not both ({why})"),
        };
        for (a, va, b, vb) in pairs {
            if va.is_some() && vb.is_some() {
                return Err(twice(a, b, "each drives the same degree of freedom"));
            }
        }
        let steady = scene.document().rolling.as_ref().is_some_and(|r| r.mode == RollingMode::Steady);
        if steady && k.creepage.is_some() && k.tangential_load.is_some() {
            return Err(twice(
                "creepage",
                "tangential_load",
                "in steady rolling each drives the tangential degree of freedom",
            ));
        }
        Ok(())
    }

    /// Whether no key is given.
    pub fn is_empty(&self) -> bool {
        *self == DriveKeys::default()
    }

    /// The scene with this drive (module docs).
    pub fn apply(&self, scene: &Scene) -> rollbem::Result<Scene> {
        self.check(scene)?;
        if self.creepage.is_some() && scene.rolling().is_none() {
            return Err(Error::Invalid {
                path: scene.origin().to_path_buf(),
                field: "rolling.creepage".into(),
                message: "the scene does not roll (no `[rolling]`): a creepage means nothing".into(),
            });
        }
        let k = *self;
        scene.edit(|d| {
            d.steps.clear();
            if k.normal_approach.is_some() || k.normal_load.is_some() {
                d.drive.normal_approach = k.normal_approach;
                d.drive.normal_load = k.normal_load;
            }
            if k.tangential_shift.is_some() || k.tangential_load.is_some() {
                d.drive.tangential_shift = k.tangential_shift;
                d.drive.tangential_load = k.tangential_load;
            }
            if k.rotation.is_some() || k.moment.is_some() {
                d.drive.rotation = k.rotation;
                d.drive.moment = k.moment;
            }
            if let Some(r) = d.rolling.as_mut() {
                let steady = r.mode == RollingMode::Steady;
                match (k.creepage, k.tangential_load) {
                    (Some(xi), _) => {
                        r.creepage = Some(xi);
                        if steady {
                            d.drive.tangential_load = None;
                        }
                    }
                    (None, Some(_)) if steady => r.creepage = None,
                    _ => {}
                }
            }
        })
    }
}

/// A load path given from Python: a sequence (not a string or a mapping) of step mappings, as step tables (errors
/// name `steps[i].KEY`); an argument that is not a sequence is a `TypeError`.
pub fn path_of(py: Python<'_>, steps: &Bound<'_, PyAny>, scene: &Scene) -> PyResult<Vec<StepTable>> {
    let value = to_json(steps, "steps", scene.origin()).map_err(|f| to_py(py, f))?;
    if !value.is_array() {
        return Err(crate::model::wrong_type(steps, "a load path is a sequence of step mappings"));
    }
    typed(value, "steps", scene.origin()).map_err(|f| to_py(py, f))
}

/// The scene walking the load path `steps` (validated like a scene file; at least one step).
pub fn with_steps(scene: &Scene, steps: Vec<StepTable>) -> rollbem::Result<Scene> {
    if steps.is_empty() {
        return Err(Error::Invalid {
            path: scene.origin().to_path_buf(),
            field: "steps".into(),
            message: "a load path needs at least one step".into(),
        });
    }
    scene.edit(|d| {
        d.drive = Default::default();
        d.steps = steps;
    })
}
