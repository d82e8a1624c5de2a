//! The result document of a half-space (3D) scene: what `rollbem run --json` writes for a scene with
//! `[wheel] model = "half_space"`, and what `rollbem plot` reads back.
//!
//! A document of its own kind beside the 2D [`super::Report`] (whose layout, schema 3, is unchanged): it says
//! `"model": "half_space"` and carries its own layout version [`SPACE_SCHEMA_VERSION`]. A 2D reader refuses it
//! (it has no `runs`), never reads it wrongly. Keys (all in the scene's units; CONTACT's signs: tractions and forces
//! on body 1, pressure > 0 in compression, shifts of body 1 relative to body 2):
//!
//! - `schema`, `model`, `scene` (the scene document as parsed, defaults filled in), `grid` (MX, MY, DX, DY, the
//!   first element's centre), `effects` and `effect_notes` (as in 2D), `kernels` (which influence kernels were
//!   built: the tangential ones only with friction, the coupling ones only for a dissimilar pair asked to couple),
//!   `references` (E*, Dundurs' β, Hertz's ellipse at the last step's load for a quadratic profile), `timing_s`,
//!   `checks` (the 2D [`Check`] rows), `warnings`;
//! - `steps`: one entry per (sub)step with its drive, `status` (`solved`, `contact_at_grid_edge`, `not_converged`,
//!   `gross_sliding`, `no_contact`), the resultants, the counts, the residuals and iterations, and `elements`: the
//!   per-element arrays in grid order `ix + MX·iy` (a (MY, MX) array in row-major order): `pressure`, `qx`, `qy`,
//!   `gap`, `state` (codes of [`ELEMENT_STATES`]).

use super::{Check, EffectNote};
use crate::halfspace::tangential::ElementState;
use crate::scene::space::{SpaceDocument, SpaceModelName};
use crate::scene::SpaceStatus;
use serde::{Deserialize, Serialize};

/// The layout version of the half-space result document ([`SpaceReport::schema`]): raised when a key changes
/// meaning or is removed.
pub const SPACE_SCHEMA_VERSION: u32 = 1;

/// The element state codes of [`ElementArrays::state`]: 0 exterior (no pressure), 1 stick, 2 slip (a frictionless
/// step's loaded elements are `slip`: nothing holds them tangentially).
pub const ELEMENT_STATES: [&str; 3] = ["exterior", "stick", "slip"];

/// The code of an element state ([`ELEMENT_STATES`]).
pub fn state_code(s: ElementState) -> u8 {
    match s {
        ElementState::Exterior => 0,
        ElementState::Stick => 1,
        _ => 2,
    }
}

/// The grid of the document.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[non_exhaustive]
pub struct GridInfo {
    /// Elements along x.
    pub mx: usize,
    /// Elements along y.
    pub my: usize,
    /// Element side along x (length).
    pub dx: f64,
    /// Element side along y (length).
    pub dy: f64,
    /// Centre of element (0, 0) along x (length).
    pub x0: f64,
    /// Centre of element (0, 0) along y (length).
    pub y0: f64,
}

impl GridInfo {
    /// The centre of element `(ix, iy)`.
    pub fn centre(&self, ix: usize, iy: usize) -> (f64, f64) {
        (self.x0 + ix as f64 * self.dx, self.y0 + iy as f64 * self.dy)
    }

    /// Number of elements.
    pub fn len(&self) -> usize {
        self.mx * self.my
    }

    /// Never: a grid has at least one element.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }
}

/// Which influence kernels the run built (the effects it paid for).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[non_exhaustive]
pub struct KernelsInfo {
    /// The tangential kernels C_xx, C_xy, C_yy (with friction only).
    pub tangential: bool,
    /// The coupling kernels C_zx, C_zy (a dissimilar pair with friction only).
    pub coupling: bool,
    /// Whether the steps alternate the coupled normal and tangential problems.
    pub coupled: bool,
}

/// Hertz's ellipse ([`crate::theory::Hertz3D`]) as written in the document.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[non_exhaustive]
pub struct HertzEllipse {
    /// Semi-axis along x (length).
    pub a_x: f64,
    /// Semi-axis along y (length).
    pub a_y: f64,
    /// Peak pressure (stress).
    pub p0: f64,
    /// Approach (length).
    pub approach: f64,
    /// The load it is for (force).
    pub load: f64,
}

impl From<crate::theory::Hertz3D> for HertzEllipse {
    fn from(h: crate::theory::Hertz3D) -> Self {
        HertzEllipse { a_x: h.a_x, a_y: h.a_y, p0: h.p0, approach: h.approach, load: h.load }
    }
}

/// Analytic references of the scene.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[non_exhaustive]
pub struct SpaceReferences {
    /// The pair's contact modulus E* (stress).
    pub contact_modulus: f64,
    /// Dundurs' β of the pair (body 1 first).
    pub dundurs_beta: f64,
    /// Hertz at the last step's load (a quadratic profile with contact; null otherwise).
    pub hertz: Option<HertzEllipse>,
}

/// Wall-clock seconds.
#[derive(Debug, Clone, Copy, Default, PartialEq, Serialize, Deserialize)]
#[non_exhaustive]
pub struct SpaceTiming {
    /// Building the influence kernels (FFT of the grid's kernels).
    pub build: f64,
    /// Solving every step.
    pub solve: f64,
    /// The sum.
    pub total: f64,
}

/// A step's normal drive as written.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
#[non_exhaustive]
pub enum NormalDriveDoc {
    /// The normal load P (force).
    Load(f64),
    /// The approach (length).
    Approach(f64),
}

/// A step's tangential drive as the solver took it.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
#[non_exhaustive]
pub enum TangentialDriveDoc {
    /// The total force on body 1 at the step's end (force).
    Force([f64; 2]),
    /// The shift increment of body 1 relative to body 2 in the step (length).
    ShiftIncrement([f64; 2]),
}

/// The per-element arrays of a step, grid order `ix + MX·iy`.
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
#[non_exhaustive]
pub struct ElementArrays {
    /// Pressure p (stress, ≥ 0).
    pub pressure: Vec<f64>,
    /// Shear q_x on body 1 (stress).
    pub qx: Vec<f64>,
    /// Shear q_y on body 1 (stress).
    pub qy: Vec<f64>,
    /// The deformed gap (length).
    pub gap: Vec<f64>,
    /// State codes ([`ELEMENT_STATES`]).
    pub state: Vec<u8>,
}

/// One (sub)step's outcome.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[non_exhaustive]
pub struct SpaceStepResult {
    /// Index of the `[[steps]]` entry (0 for `[drive]`).
    pub step: usize,
    /// Substep, 1 ..= substeps.
    pub substep: usize,
    /// Substeps of the step.
    pub substeps: usize,
    /// The normal drive.
    pub normal_drive: NormalDriveDoc,
    /// The tangential drive.
    pub tangential_drive: TangentialDriveDoc,
    /// The step's status.
    pub status: SpaceStatus,
    /// What it means (one sentence).
    pub message: String,
    /// The normal force P = A Σ p (force).
    pub load: f64,
    /// The approach (length).
    pub approach: f64,
    /// The tangential force on body 1, [F_x, F_y] (force).
    pub force: [f64; 2],
    /// The rigid shift of body 1 relative to body 2 from the path's start (length; null once a step slid grossly).
    pub shift: Option<[f64; 2]>,
    /// Elements in contact.
    pub contact: usize,
    /// Elements in stick.
    pub stick: usize,
    /// Elements in slip.
    pub slip: usize,
    /// The normal solver's residual (relative).
    pub residual_normal: f64,
    /// The tangential solver's residual (relative; 0 without friction).
    pub residual_tangential: f64,
    /// Alternations of the coupled step (1 without coupling).
    pub outer_iterations: usize,
    /// Normal solver iterations (summed over the alternations).
    pub iterations_normal: usize,
    /// Tangential solver iterations.
    pub iterations_tangential: usize,
    /// The per-element arrays.
    pub elements: ElementArrays,
}

/// The JSON document of one half-space scene run (module docs).
#[derive(Debug, Clone, Serialize, Deserialize)]
#[non_exhaustive]
pub struct SpaceReport {
    /// [`SPACE_SCHEMA_VERSION`].
    pub schema: u32,
    /// `half_space`: what makes the document 3D.
    pub model: SpaceModelName,
    /// The scene as parsed.
    pub scene: SpaceDocument,
    /// The grid.
    pub grid: GridInfo,
    /// Effects simulated (`normal`, `friction`, `coupling`, `history`).
    pub effects: Vec<String>,
    /// Per effect: asked, simulated, why.
    pub effect_notes: Vec<EffectNote>,
    /// The influence kernels built.
    pub kernels: KernelsInfo,
    /// Analytic references.
    pub references: SpaceReferences,
    /// Wall-clock times.
    pub timing_s: SpaceTiming,
    /// Every (sub)step in order (a path stops after a step that slid grossly or did not converge).
    pub steps: Vec<SpaceStepResult>,
    /// Checks against theory and the scene's expectations.
    pub checks: Vec<Check>,
    /// Run-level warnings.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub warnings: Vec<String>,
}

impl SpaceReport {
    /// Read a half-space result document.
    ///
    /// # Errors
    /// [`crate::Error::Io`] when the file cannot be read; [`crate::Error::Parse`] for another kind of document or
    /// another schema.
    pub fn read(path: &std::path::Path) -> crate::Result<SpaceReport> {
        let text =
            std::fs::read_to_string(path).map_err(|source| crate::Error::Io { path: path.to_path_buf(), source })?;
        SpaceReport::from_json(&text, path)
    }

    /// Parse a half-space result document's text (`path` names it in messages).
    ///
    /// # Errors
    /// As [`SpaceReport::read`].
    pub fn from_json(text: &str, path: &std::path::Path) -> crate::Result<SpaceReport> {
        let bad = |message: String| crate::Error::Parse { path: path.to_path_buf(), message };
        let value: serde_json::Value = serde_json::from_str(text).map_err(|e| bad(format!("not JSON: {e}")))?;
        if !is_space_value(&value) {
            return Err(bad("not a half-space result document (no `\"model\": \"half_space\"`)".into()));
        }
        match value.get("schema").and_then(serde_json::Value::as_u64) {
            Some(v) if v == u64::from(SPACE_SCHEMA_VERSION) => {}
            other => {
                return Err(bad(format!(
                    "half-space result document of schema {other:?}; this rollbem reads schema \
                     {SPACE_SCHEMA_VERSION}: rerun the scene"
                )))
            }
        }
        serde_json::from_value(value).map_err(|e| bad(format!("not a half-space result document: {e}")))
    }

    /// The final (sub)step of each `[[steps]]` entry (or the one of `[drive]`).
    pub fn step_ends(&self) -> impl Iterator<Item = &SpaceStepResult> {
        self.steps.iter().filter(|s| s.substep == s.substeps)
    }

    /// Whether every check passed.
    pub fn all_pass(&self) -> bool {
        self.checks.iter().all(|c| c.pass)
    }

    /// Whether a step ended with a status other than the scene's expected one (`solved` unless declared).
    pub fn unexpected_status(&self) -> bool {
        let expected = self.scene.checks.unwrap_or_default().status;
        self.steps.iter().any(|s| s.status != expected)
    }
}

/// Whether a JSON value is a half-space result document.
pub fn is_space_value(value: &serde_json::Value) -> bool {
    value.get("model").and_then(serde_json::Value::as_str) == Some("half_space")
}
