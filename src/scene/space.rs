//! Half-space scenes: the 3D contact of two elastic half-spaces on a rectangular grid ([`crate::halfspace`]), in
//! the vocabulary of the 2D scenes (`[wheel]`, `[counter_body]`, `[contact]`, `[drive]`, `[[steps]]`, `[solvers]`,
//! `[checks]`) and of CONTACT (MX, MY, the grid's extent, the profile's curvatures A, B or a gap per element).
//!
//! A scene is 3D when its `[wheel]` says `model = "half_space"`; [`AnyScene`] reads either kind. Its keys
//! (README, "Scenes"):
//!
//! ```toml
//! name = "hertz3d-ellipse"
//! [wheel]                      # body 1 (z > 0): the tractions act on it
//! model = "half_space"
//! youngs_modulus = 210000.0
//! poisson_ratio = 0.3
//! [counter_body]               # body 2: kind = "rigid" (default) or "half_space" with its material
//! kind = "half_space"
//! youngs_modulus = 210000.0
//! poisson_ratio = 0.3
//! [mesh]                       # MX × MY rectangles covering contact_x × contact_y
//! mx = 40
//! my = 20
//! contact_x = [-2.0, 2.0]
//! contact_y = [-1.0, 1.0]
//! [profile]                    # h = A x² + B y² (1/length), or gap_file = "gap.csv" (MY rows of MX values)
//! curvatures = [0.0025, 0.01]
//! [contact]
//! friction = 0.0
//! [drive]                      # normal_load | normal_approach; tangential_load | tangential_shift = [x, y]
//! normal_load = 1000.0
//! ```
//!
//! Conventions are CONTACT's (`reference/contact3d/README.md`): z into body 1, pressure p > 0 in compression,
//! tractions and forces **on body 1**, displacements and shifts of body 1 relative to body 2. A step's
//! `tangential_load = [F_x, F_y]` is the total tangential force on body 1 at the step's end; its
//! `tangential_shift = [w_x, w_y]` the rigid shift of body 1 relative to body 2 at the step's end, counted from the
//! path's start (absent: `[0, 0]`, as in 2D where an absent tangential drive holds the shift at 0).

use super::document::ContactTable;
use super::Scene;
use crate::error::{Error, Result};
use crate::halfspace::normal::{Drive as NormalDrive, NormalSettings};
use crate::halfspace::tangential::{TangentialDrive, TangentialSettings};
use crate::halfspace::{ContactGrid, HalfSpace, PathSettings, PathStatus, Profile, Step};
use serde::{Deserialize, Serialize};
use std::path::{Path, PathBuf};

/// Largest grid of a half-space scene (elements, `mx · my`): 2048 × 2048. The FFT kernels of the full problem hold
/// about 400 bytes per element (six kernels on the doubled grid, complex), 1.7 GiB at this size.
pub const MAX_HALF_SPACE_ELEMENTS: usize = 1 << 22;

/// Memory per element of one (sub)step of a half-space path's result (bytes): pressure, two shears, gap (8 B each),
/// a state, with slack for the vectors: 48.
pub const SPACE_BYTES_PER_ELEMENT: usize = 48;

/// A scene of either kind: the 2D wheel (BEM or half-plane) or the 3D pair of half-spaces.
#[derive(Debug, Clone)]
#[allow(clippy::large_enum_variant)]
pub enum AnyScene {
    /// A 2D scene ([`Scene`]).
    Plane(Scene),
    /// A 3D half-space scene ([`SpaceScene`]).
    Space(SpaceScene),
}

impl AnyScene {
    /// Read and validate a scene file of either kind (3D when `[wheel] model = "half_space"`).
    ///
    /// # Errors
    /// As [`Scene::from_file`] and [`SpaceScene::from_toml`]: the key and why.
    pub fn from_file(path: &Path) -> Result<AnyScene> {
        let text = std::fs::read_to_string(path).map_err(|source| Error::Io { path: path.to_path_buf(), source })?;
        AnyScene::from_toml(&text, path)
    }

    /// Parse and validate scene text of either kind; `path` names it in errors and anchors a relative `gap_file`.
    ///
    /// # Errors
    /// As [`AnyScene::from_file`].
    pub fn from_toml(text: &str, path: &Path) -> Result<AnyScene> {
        if is_space_text(text) {
            SpaceScene::from_toml(text, path).map(AnyScene::Space)
        } else {
            Scene::from_toml(text, path).map(AnyScene::Plane)
        }
    }

    /// The scene's name (it names output files).
    pub fn name(&self) -> &str {
        match self {
            AnyScene::Plane(s) => s.name(),
            AnyScene::Space(s) => s.name(),
        }
    }
}

/// Whether scene text is a half-space scene (`[wheel] model = "half_space"`); text that is not TOML is not.
pub fn is_space_text(text: &str) -> bool {
    text.parse::<toml::Table>().is_ok_and(|t| is_space_table(&t))
}

/// Whether a parsed scene table is a half-space scene.
pub fn is_space_table(t: &toml::Table) -> bool {
    t.get("wheel").and_then(|w| w.get("model")).and_then(toml::Value::as_str) == Some("half_space")
}

/// The keys of a half-space scene, as a tree: (key, sub-keys; `None` for a value).
type KeyTree = &'static [(&'static str, Option<&'static [&'static str]>)];

/// Every key a half-space scene may have (README, "Scenes").
const SPACE_KEYS: KeyTree = &[
    ("name", None),
    ("description", None),
    ("units", None),
    ("wheel", Some(&["model", "youngs_modulus", "poisson_ratio"])),
    ("counter_body", Some(&["kind", "youngs_modulus", "poisson_ratio"])),
    ("mesh", Some(&["mx", "my", "contact_x", "contact_y"])),
    ("profile", Some(&["curvatures", "gap_file", "gap"])),
    ("contact", Some(&["friction", "coupling"])),
    ("drive", Some(&["normal_approach", "normal_load", "tangential_shift", "tangential_load"])),
    ("steps", Some(&["normal_approach", "normal_load", "tangential_shift", "tangential_load", "substeps"])),
    ("solvers", Some(&["use", "half_space"])),
    ("checks", Some(&["status", "hertz", "cattaneo", "residual"])),
];

/// Keys of the 2D scenes that mean nothing on two half-spaces (named as such when a 3D scene has them).
const PLANE_ONLY_KEYS: &[&str] = &[
    "wheel.radius",
    "wheel.support",
    "wheel.datum_depth",
    "wheel.profile",
    "mesh.element",
    "mesh.contact_arc_deg",
    "mesh.contact_half_width",
    "mesh.contact_elements",
    "mesh.other_elements",
    "mesh.strip_width",
    "counter_body.datum_depth",
    "drive.rotation",
    "drive.moment",
    "steps.rotation",
    "steps.moment",
    "steps.roll",
    "rolling",
    "stresses",
    "checks.solver_status",
    "checks.agreement",
    "checks.cattaneo_elements",
    "checks.contact_elements",
];

/// Keys of the half-space scenes that the 2D scenes do not have (named as such when a 2D scene has them).
const SPACE_ONLY_KEYS: &[&str] =
    &["profile", "mesh.mx", "mesh.my", "mesh.contact_y", "solvers.half_space", "checks.cattaneo", "checks.hertz_3d"];

/// The first key of a 2D scene table that only half-space scenes have (for [`Scene::from_toml`]'s message).
pub(super) fn space_only_key(t: &toml::Table) -> Option<&'static str> {
    SPACE_ONLY_KEYS.iter().copied().find(|k| {
        let mut parts = k.split('.');
        let top = parts.next().unwrap_or_default();
        match (t.get(top), parts.next()) {
            (Some(_), None) => true,
            (Some(toml::Value::Table(sub)), Some(key)) => sub.contains_key(key),
            _ => false,
        }
    })
}

/// Refuse any key of `t` outside [`SPACE_KEYS`], naming it (a 2D key as such).
fn check_keys(t: &toml::Table, path: &Path) -> Result<()> {
    // `plain` is the key without indices (`steps.roll`), `named` the one the user wrote (`steps[2].roll`).
    let refuse = |plain: &str, named: String| {
        let message = if PLANE_ONLY_KEYS.contains(&plain) {
            "is a key of the 2D scenes (the BEM and half-plane wheels); a half-space scene (wheel.model = \
             \"half_space\") does not take it: remove it (README, \"Scenes\")"
        } else {
            "unknown key in a half-space scene (wheel.model = \"half_space\"; README, \"Scenes\")"
        };
        Err(Error::Invalid { path: path.to_path_buf(), field: named, message: message.into() })
    };
    for (key, value) in t {
        let Some((_, sub)) = SPACE_KEYS.iter().find(|(k, _)| k == key) else { return refuse(key, key.clone()) };
        let Some(sub) = sub else { continue };
        let tables: Vec<(String, &toml::Table)> = match value {
            toml::Value::Table(tab) => vec![(key.clone(), tab)],
            toml::Value::Array(items) if key == "steps" => items
                .iter()
                .enumerate()
                .filter_map(|(i, v)| v.as_table().map(|tab| (format!("steps[{i}]"), tab)))
                .collect(),
            _ => continue,
        };
        for (prefix, tab) in tables {
            if let Some(k) = tab.keys().find(|k| !sub.contains(&k.as_str())) {
                return refuse(&format!("{key}.{k}"), format!("{prefix}.{k}"));
            }
        }
    }
    Ok(())
}

/// `[wheel]` of a half-space scene: body 1 (`z > 0`), the body the tractions act on.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SpaceBodyTable {
    /// Always `half_space` (what makes the scene 3D).
    pub model: SpaceModelName,
    /// Young's modulus E₁ (stress, finite, > 0).
    pub youngs_modulus: f64,
    /// Poisson's ratio ν₁ ∈ [0, 0.5].
    pub poisson_ratio: f64,
}

/// The body model of a half-space scene (one value: `half_space`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
#[non_exhaustive]
pub enum SpaceModelName {
    /// Two elastic half-spaces (Kalker's discretisation, [`crate::halfspace`]).
    HalfSpace,
}

/// `[counter_body]` of a half-space scene: body 2 (`z < 0`).
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case", deny_unknown_fields)]
#[non_exhaustive]
pub enum SpaceCounterTable {
    /// A rigid body (default).
    #[default]
    Rigid,
    /// An elastic half-space.
    HalfSpace {
        /// Young's modulus E₂ (stress, finite, > 0).
        youngs_modulus: f64,
        /// Poisson's ratio ν₂ ∈ [0, 0.5].
        poisson_ratio: f64,
    },
}

/// `[mesh]` of a half-space scene: `mx × my` rectangles covering `contact_x × contact_y` exactly (element `(ix, iy)`
/// centred at `x_min + (ix + ½)·DX`, `y_min + (iy + ½)·DY`, DX = (x_max − x_min)/mx; CONTACT's XL = x_min).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct GridTable {
    /// Elements along x (MX, ≥ 1).
    pub mx: usize,
    /// Elements along y (MY, ≥ 1).
    pub my: usize,
    /// The grid's extent along x, `[x_min, x_max]` (length).
    pub contact_x: [f64; 2],
    /// The grid's extent along y, `[y_min, y_max]` (length).
    pub contact_y: [f64; 2],
}

/// `[profile]`: the initial separation of the surfaces, exactly one of three forms.
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ProfileTable {
    /// `[A, B]`: h = A x² + B y² (1/length, both > 0; A = 1/(2R_x) summed over the bodies): Hertz's geometry.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub curvatures: Option<[f64; 2]>,
    /// A CSV file (relative to the scene file's folder) of MY rows of MX gaps (length), row iy = 0 first (y = y_min);
    /// `#` starts a comment line.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub gap_file: Option<PathBuf>,
    /// The gaps inline: MY arrays of MX values (length), row iy = 0 first (what Python's arrays give).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub gap: Option<Vec<Vec<f64>>>,
}

/// `[drive]` of a half-space scene, or one `[[steps]]` entry (with `substeps`).
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SpaceDriveTable {
    /// The approach d (length) at the end.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub normal_approach: Option<f64>,
    /// The normal load P = ∫p dA (force, > 0) at the end.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub normal_load: Option<f64>,
    /// The rigid shift `[w_x, w_y]` of body 1 relative to body 2 at the end, from the path's start (length).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub tangential_shift: Option<[f64; 2]>,
    /// The tangential force `[F_x, F_y]` on body 1 at the end (force).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub tangential_load: Option<[f64; 2]>,
    /// `[[steps]]` only: equal increments to the step's end (default 1).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub substeps: Option<usize>,
}

/// `[solvers]` of a half-space scene: `use` (`["all"]` or `["half_space"]`: the one 3D solver, the path of
/// [`crate::halfspace::Path`]) and its settings table `[solvers.half_space]`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SpaceSolversTable {
    /// Solver names: `all` or `half_space`.
    #[serde(rename = "use", default = "default_use")]
    pub use_: Vec<String>,
    /// The settings of the half-space path solver (defaults: [`PathSettings::default`]).
    #[serde(default)]
    pub half_space: HalfSpaceSettingsTable,
}

impl Default for SpaceSolversTable {
    fn default() -> Self {
        SpaceSolversTable { use_: default_use(), half_space: HalfSpaceSettingsTable::default() }
    }
}

fn default_use() -> Vec<String> {
    vec!["all".into()]
}

/// `[solvers.half_space]`: the settings of [`crate::halfspace::Path::solve`] (absent keys: its defaults).
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct HalfSpaceSettingsTable {
    /// The normal solver's relative pressure change to stop at, in (0, 1) (default 1e-10).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub normal_tolerance: Option<f64>,
    /// The normal solver's iteration limit (≥ 1; default 10 000).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub normal_max_iterations: Option<usize>,
    /// The tangential solver's shear change (relative to max μp) to stop at, in (0, 1) (default 1e-10).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub tangential_tolerance: Option<f64>,
    /// The tangential solver's iteration limit (≥ 1; default 100 000).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub tangential_max_iterations: Option<usize>,
    /// The normal solver: `"preconditioned_cg"` (the default) or `"polonsky_keer"`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub normal_method: Option<crate::halfspace::normal::NormalMethod>,
    /// The tangential solver: `"conjugate_gradient"` (the default) or `"fista"`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub tangential_method: Option<crate::halfspace::tangential::TangentialMethod>,
    /// The coupled alternation's tolerance, in (0, 1) (default 1e-9).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub outer_tolerance: Option<f64>,
    /// The coupled alternation's limit per step (≥ 1; default 100).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub max_outer: Option<usize>,
    /// The largest inner residual a solved step may have, in (0, 1) (default 1e-7).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub residual: Option<f64>,
}

impl HalfSpaceSettingsTable {
    /// The path settings: the given keys over the defaults.
    pub fn settings(&self) -> PathSettings {
        let d = PathSettings::default();
        PathSettings {
            normal: NormalSettings::new(
                self.normal_tolerance.unwrap_or(d.normal.tolerance),
                self.normal_max_iterations.unwrap_or(d.normal.max_iterations),
            )
            .with_method(self.normal_method.unwrap_or(d.normal.method)),
            tangential: TangentialSettings::new(
                self.tangential_tolerance.unwrap_or(d.tangential.tolerance),
                self.tangential_max_iterations.unwrap_or(d.tangential.max_iterations),
            )
            .with_method(self.tangential_method.unwrap_or(d.tangential.method)),
            outer_tolerance: self.outer_tolerance.unwrap_or(d.outer_tolerance),
            max_outer: self.max_outer.unwrap_or(d.max_outer),
            residual: self.residual.unwrap_or(d.residual),
        }
    }
}

/// The status of a half-space step as scenes and documents name it ([`PathStatus`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
#[non_exhaustive]
pub enum SpaceStatus {
    /// Solved (every condition of [`crate::halfspace::path`]'s "What `Solved` means").
    Solved,
    /// The contact reaches the grid's edge (the 2D `contact_at_zone_edge`): enlarge the grid.
    ContactAtGridEdge,
    /// An inner solver or the coupling did not converge, or a residual is above the limit.
    NotConverged,
    /// The tangential force is at or above μP (the 2D `infeasible` of a load beyond the friction limit).
    GrossSliding,
    /// The prescribed approach gives no contact.
    NoContact,
    /// Cancelled by the caller.
    Cancelled,
}

impl SpaceStatus {
    /// The status of a path step.
    pub fn of(s: PathStatus) -> SpaceStatus {
        match s {
            PathStatus::Solved => SpaceStatus::Solved,
            PathStatus::ContactAtGridEdge => SpaceStatus::ContactAtGridEdge,
            PathStatus::NotConverged => SpaceStatus::NotConverged,
            PathStatus::GrossSliding => SpaceStatus::GrossSliding,
            PathStatus::NoContact => SpaceStatus::NoContact,
            _ => SpaceStatus::Cancelled,
        }
    }

    /// The name in scenes, tables and JSON.
    pub fn name(self) -> &'static str {
        match self {
            SpaceStatus::Solved => "solved",
            SpaceStatus::ContactAtGridEdge => "contact_at_grid_edge",
            SpaceStatus::NotConverged => "not_converged",
            SpaceStatus::GrossSliding => "gross_sliding",
            SpaceStatus::NoContact => "no_contact",
            SpaceStatus::Cancelled => "cancelled",
        }
    }
}

impl std::fmt::Display for SpaceStatus {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.name())
    }
}

/// `[checks]` of a half-space scene: the expected status of every step and tolerances overriding the defaults of
/// [`crate::pipeline::space`].
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SpaceChecks {
    /// The status every step should end with (default `solved`).
    #[serde(default = "default_space_status")]
    pub status: SpaceStatus,
    /// Relative tolerance on Hertz's semi-axes, peak pressure and approach.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub hertz: Option<f64>,
    /// Relative tolerance of the Cattaneo–Mindlin figures (stick radius, force or shift).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub cattaneo: Option<f64>,
    /// Largest inner residual of a solved step.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub residual: Option<f64>,
}

fn default_space_status() -> SpaceStatus {
    SpaceStatus::Solved
}

impl Default for SpaceChecks {
    fn default() -> Self {
        SpaceChecks { status: SpaceStatus::Solved, hertz: None, cattaneo: None, residual: None }
    }
}

/// A half-space scene file as written (before validation).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SpaceDocument {
    /// Short identifier (names the output files).
    pub name: String,
    /// What the scene is and where its numbers come from.
    #[serde(default)]
    pub description: String,
    /// The units as a label (e.g. `"N, mm, MPa"`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub units: Option<String>,
    /// Body 1.
    pub wheel: SpaceBodyTable,
    /// Body 2.
    #[serde(default)]
    pub counter_body: SpaceCounterTable,
    /// The grid.
    pub mesh: GridTable,
    /// The initial separation.
    pub profile: ProfileTable,
    /// Friction μ and coupling (as in 2D: coupling simulated only for a dissimilar pair).
    #[serde(default)]
    pub contact: ContactTable,
    /// One step from rest (absent with `[[steps]]`).
    #[serde(default)]
    pub drive: SpaceDriveTable,
    /// A load path.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub steps: Vec<SpaceDriveTable>,
    /// The solver and its settings.
    #[serde(default)]
    pub solvers: SpaceSolversTable,
    /// Expectations.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub checks: Option<SpaceChecks>,
}

/// One (sub)step of a half-space scene's path.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SpaceStep {
    /// Index of the `[[steps]]` entry (0 for `[drive]`).
    pub step: usize,
    /// Substep, 1 ..= substeps.
    pub substep: usize,
    /// Substeps of the step.
    pub substeps: usize,
    /// The drives of the substep (the tangential one as [`crate::halfspace::Path`] takes it: a shift increment or a
    /// total force).
    pub drive: Step,
}

/// A validated half-space scene: every value in range, the grid, profile and steps typed for
/// [`crate::halfspace::Path`]. Built only by validation ([`SpaceScene::from_toml`], [`SpaceScene::from_document`],
/// [`SpaceScene::edit`]).
#[derive(Debug, Clone)]
pub struct SpaceScene {
    origin: PathBuf,
    document: SpaceDocument,
    body: HalfSpace,
    counter: HalfSpace,
    grid: ContactGrid,
    profile: Profile,
    steps: Vec<SpaceStep>,
    settings: PathSettings,
}

impl SpaceScene {
    /// Read and validate a half-space scene file.
    ///
    /// # Errors
    /// As [`SpaceScene::from_toml`].
    pub fn from_file(path: &Path) -> Result<SpaceScene> {
        let text = std::fs::read_to_string(path).map_err(|source| Error::Io { path: path.to_path_buf(), source })?;
        SpaceScene::from_toml(&text, path)
    }

    /// Parse and validate half-space scene text (`path` names it in errors and anchors a relative `gap_file`).
    ///
    /// # Errors
    /// [`Error::Parse`] for text that is not TOML or a value of the wrong type; [`Error::Invalid`] naming the key for
    /// an unknown or 2D-only key, a value out of range, a grid too large, a gap file that cannot be read or has the
    /// wrong shape.
    pub fn from_toml(text: &str, path: &Path) -> Result<SpaceScene> {
        let parse = |message: String| Error::Parse { path: path.to_path_buf(), message };
        let table: toml::Table = text.parse().map_err(|e: toml::de::Error| parse(e.to_string().trim_end().into()))?;
        check_keys(&table, path)?;
        let document: SpaceDocument = toml::from_str(text).map_err(|e| parse(e.to_string().trim_end().to_string()))?;
        SpaceScene::from_document(document, path)
    }

    /// A changed copy: `change` edits the document, which is validated again.
    ///
    /// # Errors
    /// As [`SpaceScene::from_document`].
    pub fn edit(&self, change: impl FnOnce(&mut SpaceDocument)) -> Result<SpaceScene> {
        let mut d = self.document.clone();
        change(&mut d);
        SpaceScene::from_document(d, &self.origin)
    }

    /// Assemble a validated scene (for the validation module).
    #[allow(clippy::too_many_arguments)]
    pub(super) fn assemble(
        origin: PathBuf,
        document: SpaceDocument,
        (body, counter): (HalfSpace, HalfSpace),
        grid: ContactGrid,
        profile: Profile,
        steps: Vec<SpaceStep>,
        settings: PathSettings,
    ) -> SpaceScene {
        SpaceScene { origin, document, body, counter, grid, profile, steps, settings }
    }

    /// Where the scene came from.
    pub fn origin(&self) -> &Path {
        &self.origin
    }

    /// The document as parsed, with the defaults filled in.
    pub fn document(&self) -> &SpaceDocument {
        &self.document
    }

    /// Short identifier.
    pub fn name(&self) -> &str {
        &self.document.name
    }

    /// What the scene is.
    pub fn description(&self) -> &str {
        &self.document.description
    }

    /// The units label, if declared.
    pub fn units(&self) -> Option<&str> {
        self.document.units.as_deref()
    }

    /// Body 1 (the tractions act on it).
    pub fn body(&self) -> HalfSpace {
        self.body
    }

    /// Body 2 (rigid: infinite modulus).
    pub fn counter(&self) -> HalfSpace {
        self.counter
    }

    /// The grid.
    pub fn grid(&self) -> ContactGrid {
        self.grid
    }

    /// The initial separation.
    pub fn profile(&self) -> &Profile {
        &self.profile
    }

    /// The quadratic profile's curvatures (A, B), `None` for a gap per element.
    pub fn curvatures(&self) -> Option<(f64, f64)> {
        match self.profile {
            Profile::Quadratic { a, b } => Some((a, b)),
            _ => None,
        }
    }

    /// Coulomb's μ (0: frictionless, only the normal problem is built and solved).
    pub fn friction(&self) -> f64 {
        self.document.contact.friction
    }

    /// Whether the scene asks for the normal–tangential coupling (simulated only for a dissimilar pair).
    pub fn coupling(&self) -> bool {
        self.document.contact.coupling
    }

    /// The (sub)steps in order.
    pub fn steps(&self) -> &[SpaceStep] {
        &self.steps
    }

    /// Whether the scene is a load path (`[[steps]]`) rather than one `[drive]`.
    pub fn is_path(&self) -> bool {
        !self.document.steps.is_empty()
    }

    /// The solver's settings.
    pub fn settings(&self) -> PathSettings {
        self.settings
    }

    /// The expectations (`[checks]`, defaults without one).
    pub fn expect(&self) -> SpaceChecks {
        self.document.checks.unwrap_or_default()
    }

    /// Whether the scene declares `[checks]` (`rollbem run` then exits on a failed check).
    pub fn declares_checks(&self) -> bool {
        self.document.checks.is_some()
    }

    /// The pair's contact modulus E*, `1/E* = (1 − ν₁²)/E₁ + (1 − ν₂²)/E₂` (a rigid body contributes 0).
    pub fn contact_modulus(&self) -> f64 {
        let c = |h: HalfSpace| {
            if h.youngs_modulus().is_infinite() {
                0.0
            } else {
                (1.0 - h.poisson_ratio().powi(2)) / h.youngs_modulus()
            }
        };
        1.0 / (c(self.body) + c(self.counter))
    }

    /// Dundurs' β of the pair, body 1 first ([`crate::material::dundurs_beta`]): the coupling vanishes with it.
    pub fn dundurs_beta(&self) -> f64 {
        let m = |h: HalfSpace| crate::material::Material {
            youngs_modulus: h.youngs_modulus(),
            poisson_ratio: h.poisson_ratio(),
        };
        crate::material::dundurs_beta(&m(self.body), &m(self.counter))
    }

    /// The normal drive of a substep as the library takes it.
    pub fn normal_drive(drive: &SpaceDriveTable) -> Option<NormalDrive> {
        match (drive.normal_load, drive.normal_approach) {
            (Some(p), _) => Some(NormalDrive::Load(p)),
            (None, Some(d)) => Some(NormalDrive::Approach(d)),
            (None, None) => None,
        }
    }

    /// The tangential drive of a table: a total force, or the total shift (absent: shift `[0, 0]`).
    pub fn tangential_total(drive: &SpaceDriveTable) -> TangentialDrive {
        match (drive.tangential_load, drive.tangential_shift) {
            (Some([x, y]), _) => TangentialDrive::Force(x, y),
            (None, Some([x, y])) => TangentialDrive::Shift(x, y),
            (None, None) => TangentialDrive::Shift(0.0, 0.0),
        }
    }
}

impl PartialEq for SpaceScene {
    fn eq(&self, other: &SpaceScene) -> bool {
        self.document == other.document
    }
}
