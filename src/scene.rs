//! Scene files: what to simulate (TOML, see `../shared/DESIGN.md` and `reference/scenes/`).
//!
//! A scene is parsed with serde (unknown keys are rejected) and then validated range by range; every error names
//! the file and the dotted key. Units are the user's and must be consistent (e.g. N, mm, MPa): lengths, moduli and
//! loads per unit thickness. Sign conventions of the drive follow `DESIGN.md`: the support moves rigidly relative
//! to the fixed flat by an approach `d_N` (towards the flat, positive compresses), a tangential shift `d_T` (+x) and
//! a rotation `φ` (counter-clockwise, radians); a drive load is the resultant the contact must carry
//! (`normal_load` = P = ∫p dx > 0 compressive).

use crate::error::{Error, Result};
use serde::{Deserialize, Serialize};
use std::path::{Path, PathBuf};

/// Largest number of boundary nodes (collocation points) a scene may have: the dense BEM system (2N)² and its LU
/// then need about 2 GiB.
pub const MAX_NODES: usize = 8000;

/// A whole scene.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Scene {
    /// Short identifier, used in reports.
    pub name: String,
    /// What the scene is and where its numbers come from.
    #[serde(default)]
    pub description: String,
    /// The elastic wheel and its support.
    pub wheel: Wheel,
    /// Boundary-element mesh of the wheel.
    pub mesh: MeshSpec,
    /// Contact law.
    #[serde(default)]
    pub contact: ContactSpec,
    /// How the support is driven: a displacement or a load for each rigid degree of freedom.
    pub drive: Drive,
    /// Optional rolling post-processing (slip velocity, seed eq. 12).
    #[serde(default)]
    pub rolling: Option<Rolling>,
    /// Which solvers to run.
    #[serde(default)]
    pub solvers: SolverSpec,
    /// What the scene expects of its runs.
    #[serde(default)]
    pub checks: Expect,
}

/// Expectations a scene declares about its own outcome (`[checks]`): the status, and tolerances that override
/// the defaults of [`crate::tolerances`] for this scene.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Expect {
    /// The status every solver should end with (default `solved`; e.g. `infeasible` for a load beyond μP).
    #[serde(default = "default_status")]
    pub status: crate::solvers::Status,
    /// Per-solver expected statuses overriding `status` (e.g. `{ pgs = "not_converged" }` where the NORM-TANG
    /// split is known not to converge).
    #[serde(default, skip_serializing_if = "std::collections::BTreeMap::is_empty")]
    pub solver_status: std::collections::BTreeMap<SolverName, crate::solvers::Status>,
    /// Relative tolerance on Hertz's a and p0 (default: 1.5 % constant, 1 % quadratic elements).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub hertz: Option<f64>,
    /// Agreement between solvers, max |Δp|, |Δq| over p_max (default 1e-6).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub agreement: Option<f64>,
    /// Largest solver-independent residual (default: round-off for direct solvers, 100 τ for iterative ones).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub residual: Option<f64>,
    /// Cattaneo–Mindlin stick-zone half-width and centre, in contact elements (default 1).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub cattaneo_elements: Option<f64>,
}

fn default_status() -> crate::solvers::Status {
    crate::solvers::Status::Solved
}

impl Default for Expect {
    fn default() -> Self {
        Expect {
            status: default_status(),
            solver_status: Default::default(),
            hertz: None,
            agreement: None,
            residual: None,
            cattaneo_elements: None,
        }
    }
}

/// The wheel: an elastic disk (or annulus) in plane strain.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Wheel {
    /// Outer radius R (length unit).
    pub radius: f64,
    /// Young's modulus E (stress unit).
    pub youngs_modulus: f64,
    /// Poisson's ratio ν, 0 ≤ ν ≤ 0.5 (plane strain).
    pub poisson_ratio: f64,
    /// How the wheel is held.
    pub support: Support,
}

/// The wheel's support, which moves rigidly with the drive.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case", deny_unknown_fields)]
pub enum Support {
    /// An annulus whose inner circle (radius `radius` < R) is clamped to a rigid axle: the physical wheel.
    Hub {
        /// Hub radius r_h (length unit), 0 < r_h < R.
        radius: f64,
    },
    /// A full disk clamped on an arc of `angle_deg` degrees centred on the top point (the seed's mesh, Fig. 5).
    TopArc {
        /// Angular extent of the clamped arc, degrees, in (0, 180).
        angle_deg: f64,
    },
}

/// Boundary element family.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum ElementKind {
    /// Straight elements, constant displacement and traction, collocation at the midpoint.
    Constant,
    /// Discontinuous quadratic elements on the exact circular arc, collocation at ξ = −2/3, 0, 2/3.
    Quadratic,
}

impl ElementKind {
    /// Name as written in scene files.
    pub fn name(self) -> &'static str {
        match self {
            ElementKind::Constant => "constant",
            ElementKind::Quadratic => "quadratic",
        }
    }
}

/// Mesh of the wheel's boundary.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct MeshSpec {
    /// Element family.
    pub element: ElementKind,
    /// Angular extent (degrees) of the potential contact zone, centred on the bottom point, in (0, 180).
    pub contact_arc_deg: f64,
    /// Number of (uniform) elements on the potential contact arc, ≥ 1.
    pub contact_elements: usize,
    /// Number of elements on the rest of the outer boundary (graded from the contact size), ≥ 3. The hub circle
    /// gets elements in proportion to its circumference.
    pub other_elements: usize,
}

/// Contact law between wheel and flat.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ContactSpec {
    /// Coulomb friction coefficient μ ≥ 0; 0 means frictionless (the normal problem only).
    #[serde(default)]
    pub friction: f64,
    /// Keep the normal–tangential cross flexibilities F_NT, F_TN (true) or drop them (false).
    #[serde(default = "default_true")]
    pub coupling: bool,
}

fn default_true() -> bool {
    true
}

impl Default for ContactSpec {
    fn default() -> Self {
        ContactSpec { friction: 0.0, coupling: true }
    }
}

/// The drive of the support: per rigid degree of freedom, a displacement or a load (not both).
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Drive {
    /// Rigid approach d_N towards the flat (length; positive compresses).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub normal_approach: Option<f64>,
    /// Normal load P = ∫p dx the contact carries (force per unit thickness; positive compressive).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub normal_load: Option<f64>,
    /// Rigid tangential shift d_T of the support (+x, length). Default 0 when no tangential load is given.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub tangential_shift: Option<f64>,
    /// Tangential load Q = ∫q dx the contact carries.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub tangential_load: Option<f64>,
    /// Rigid rotation φ of the support, counter-clockwise, radians. Default 0 when no moment is given.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub rotation: Option<f64>,
    /// Moment M of the contact tractions about the wheel centre (counter-clockwise positive).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub moment: Option<f64>,
}

/// One rigid degree of freedom's drive, after validation.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Dof {
    /// Prescribed rigid displacement (or rotation).
    Displacement(f64),
    /// Prescribed resultant (force or moment); the rigid motion is an unknown.
    Load(f64),
}

impl Drive {
    /// The normal drive (d_N or P).
    pub fn normal(&self) -> Dof {
        match (self.normal_approach, self.normal_load) {
            (_, Some(p)) => Dof::Load(p),
            (Some(d), None) => Dof::Displacement(d),
            (None, None) => Dof::Displacement(0.0),
        }
    }
    /// The tangential drive (d_T or Q).
    pub fn tangential(&self) -> Dof {
        match (self.tangential_shift, self.tangential_load) {
            (_, Some(q)) => Dof::Load(q),
            (d, None) => Dof::Displacement(d.unwrap_or(0.0)),
        }
    }
    /// The rotational drive (φ or M).
    pub fn rotational(&self) -> Dof {
        match (self.rotation, self.moment) {
            (_, Some(m)) => Dof::Load(m),
            (r, None) => Dof::Displacement(r.unwrap_or(0.0)),
        }
    }
}

/// Rolling post-processing (seed eqs. 10–12).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Rolling {
    /// Creepage ξ = (V_A − V_B)/|V| (dimensionless).
    pub creepage: f64,
    /// sgn(V): +1 rolling towards +x, −1 towards −x.
    pub direction: i32,
}

/// A solver name as written in scene files and on the command line: the one registry of rollbem's solvers.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum SolverName {
    /// Every solver valid for the scene.
    All,
    /// Lemke's complementary pivoting on the scene's LCP (every scene).
    Lemke,
    /// The clarabel interior-point solver on the frictionless QP (frictionless scenes, no moment load).
    Clarabel,
    /// NORM-TANG with projected Gauss–Seidel inner sweeps (no moment load).
    Pgs,
    /// NORM-TANG with clarabel QPs as inner solver (no moment load).
    NormtangQp,
}

impl SolverName {
    /// Every solver, in registry order (without `all`).
    pub const SOLVERS: [SolverName; 4] =
        [SolverName::Lemke, SolverName::Clarabel, SolverName::Pgs, SolverName::NormtangQp];

    /// Name as written in scene files and reports.
    pub fn name(self) -> &'static str {
        match self {
            SolverName::All => "all",
            SolverName::Lemke => "lemke",
            SolverName::Clarabel => "clarabel",
            SolverName::Pgs => "pgs",
            SolverName::NormtangQp => "normtang_qp",
        }
    }

    /// Parse a name (as on the command line); the error lists the valid names.
    pub fn parse(s: &str) -> std::result::Result<SolverName, String> {
        std::iter::once(SolverName::All)
            .chain(SolverName::SOLVERS)
            .find(|n| n.name() == s)
            .ok_or_else(|| format!("unknown solver `{s}` (expected one of: all, lemke, clarabel, pgs, normtang_qp)"))
    }
}

/// Which solvers to run, with their settings (`[solvers.lemke]`, `[solvers.clarabel]`, `[solvers.pgs]`,
/// `[solvers.normtang_qp]`; documented defaults when absent).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SolverSpec {
    /// Solver names; `["all"]` runs every solver valid for the scene.
    #[serde(rename = "use", default = "default_use")]
    pub use_: Vec<SolverName>,
    /// Lemke settings.
    #[serde(default)]
    pub lemke: crate::solvers::lemke::LemkeSettings,
    /// clarabel settings (frictionless QP).
    #[serde(default)]
    pub clarabel: crate::solvers::clarabel_qp::QpSettings,
    /// NORM-TANG with PGS settings.
    #[serde(default)]
    pub pgs: crate::solvers::normtang::PgsSettings,
    /// NORM-TANG with clarabel settings.
    #[serde(default)]
    pub normtang_qp: crate::solvers::normtang::NormTangQpSettings,
}

fn default_use() -> Vec<SolverName> {
    vec![SolverName::All]
}

impl Default for SolverSpec {
    fn default() -> Self {
        SolverSpec {
            use_: default_use(),
            lemke: Default::default(),
            clarabel: Default::default(),
            pgs: Default::default(),
            normtang_qp: Default::default(),
        }
    }
}

impl Scene {
    /// Read, parse and validate a scene file.
    pub fn from_file(path: &Path) -> Result<Scene> {
        let text = std::fs::read_to_string(path).map_err(|source| Error::Io { path: path.to_path_buf(), source })?;
        Scene::from_toml(&text, path)
    }

    /// Parse and validate scene text; `path` is used in error messages only.
    pub fn from_toml(text: &str, path: &Path) -> Result<Scene> {
        let scene: Scene = toml::from_str(text)
            .map_err(|e| Error::Parse { path: path.to_path_buf(), message: e.to_string().trim_end().to_string() })?;
        scene.validate(path)?;
        Ok(scene)
    }

    /// Check every value's range; the error names the dotted key.
    pub fn validate(&self, path: &Path) -> Result<()> {
        let bad = |field: &str, message: String| Error::Invalid {
            path: path.to_path_buf(),
            field: field.to_string(),
            message,
        };
        let positive = |field: &str, v: f64| -> Result<()> {
            if !v.is_finite() || v <= 0.0 {
                return Err(bad(field, format!("must be a finite number > 0 (got {v})")));
            }
            Ok(())
        };
        let finite = |field: &str, v: f64| -> Result<()> {
            if !v.is_finite() {
                return Err(bad(field, format!("must be a finite number (got {v})")));
            }
            Ok(())
        };
        if self.name.trim().is_empty() {
            return Err(bad("name", "must not be empty".into()));
        }
        let w = &self.wheel;
        positive("wheel.radius", w.radius)?;
        positive("wheel.youngs_modulus", w.youngs_modulus)?;
        let nu = w.poisson_ratio;
        if !nu.is_finite() || !(0.0..=0.5).contains(&nu) {
            return Err(bad("wheel.poisson_ratio", format!("must lie in [0, 0.5] (got {nu})")));
        }
        match w.support {
            Support::Hub { radius } => {
                positive("wheel.support.radius", radius)?;
                if nu == 0.5 {
                    return Err(bad(
                        "wheel.poisson_ratio",
                        "ν = 0.5 with a hub support is degenerate for the displacement BIE: in incompressible plane \
                         strain a uniform radial traction on the clamped hub circle produces no displacement anywhere, \
                         so the hub pressure is undetermined (the BEM system is singular). Use ν ≤ 0.4999, or the \
                         top_arc support (an open clamped arc), for which ν = 0.5 is well posed"
                            .into(),
                    ));
                }
                if radius >= 0.95 * w.radius {
                    return Err(bad(
                        "wheel.support.radius",
                        format!("hub radius {radius} must be below 0.95 × wheel.radius = {}", 0.95 * w.radius),
                    ));
                }
            }
            Support::TopArc { angle_deg } => {
                if !angle_deg.is_finite() || angle_deg <= 0.0 || angle_deg >= 180.0 {
                    return Err(bad(
                        "wheel.support.angle_deg",
                        format!("must lie in (0, 180) degrees (got {angle_deg})"),
                    ));
                }
            }
        }
        let m = &self.mesh;
        if !m.contact_arc_deg.is_finite() || m.contact_arc_deg <= 0.0 || m.contact_arc_deg >= 180.0 {
            return Err(bad(
                "mesh.contact_arc_deg",
                format!("must lie in (0, 180) degrees (got {})", m.contact_arc_deg),
            ));
        }
        if let Support::TopArc { angle_deg } = w.support {
            if m.contact_arc_deg + angle_deg >= 300.0 {
                return Err(bad(
                    "wheel.support.angle_deg",
                    "the clamped top arc and the contact arc overlap or leave no free boundary".into(),
                ));
            }
        }
        if m.contact_elements < 1 {
            return Err(bad("mesh.contact_elements", "must be at least 1".into()));
        }
        if m.other_elements < 4 {
            return Err(bad("mesh.other_elements", format!("must be at least 4 (got {})", m.other_elements)));
        }
        // The dense BEM system holds (2N)² doubles for N nodes (plus its LU copy): bound N so that it fits in a few
        // GiB instead of failing to allocate (an abort, not an error).
        let per = match m.element {
            ElementKind::Constant => 1,
            ElementKind::Quadratic => 3,
        };
        let outer_nodes = m.contact_elements.saturating_add(m.other_elements).saturating_mul(per);
        let hub_nodes = match w.support {
            Support::Hub { radius } => ((outer_nodes as f64) * radius / w.radius).ceil() as usize + 12 * per,
            Support::TopArc { .. } => 0,
        };
        let nodes = outer_nodes.saturating_add(hub_nodes);
        if nodes > MAX_NODES {
            let gib = (2.0 * nodes as f64).powi(2) * 8.0 * 2.0 / (1u64 << 30) as f64;
            return Err(bad(
                "mesh",
                format!(
                    "about {nodes} boundary nodes: the dense BEM system and its LU would need about {gib:.1} GiB; \
                     rollbem allows at most {MAX_NODES} nodes (use fewer elements, or constant elements)"
                ),
            ));
        }
        let mu = self.contact.friction;
        if !mu.is_finite() || mu < 0.0 {
            return Err(bad("contact.friction", format!("must be a finite number ≥ 0 (got {mu})")));
        }
        let d = &self.drive;
        let pairs = [
            ("drive.normal_approach", d.normal_approach, "drive.normal_load", d.normal_load),
            ("drive.tangential_shift", d.tangential_shift, "drive.tangential_load", d.tangential_load),
            ("drive.rotation", d.rotation, "drive.moment", d.moment),
        ];
        for (a, va, b, vb) in pairs {
            if va.is_some() && vb.is_some() {
                return Err(bad(a, format!("give either `{a}` or `{b}`, not both")));
            }
            if let Some(v) = va {
                finite(a, v)?;
            }
            if let Some(v) = vb {
                finite(b, v)?;
            }
        }
        if d.normal_approach.is_none() && d.normal_load.is_none() {
            return Err(bad("drive", "give `normal_approach` or `normal_load`".into()));
        }
        if let Some(p) = d.normal_load {
            positive("drive.normal_load", p)?;
        }
        if let Some(r) = &self.rolling {
            finite("rolling.creepage", r.creepage)?;
            if r.direction != 1 && r.direction != -1 {
                return Err(bad("rolling.direction", format!("must be 1 or -1 (got {})", r.direction)));
            }
        }
        if self.solvers.use_.is_empty() {
            return Err(bad("solvers.use", "must name at least one solver (or \"all\")".into()));
        }
        let sv = &self.solvers;
        let tol = |field: &str, v: f64| -> Result<()> {
            if !v.is_finite() || v <= 0.0 || v >= 1.0 {
                return Err(bad(field, format!("must lie in (0, 1) (got {v})")));
            }
            Ok(())
        };
        let count = |field: &str, v: usize| -> Result<()> {
            if v == 0 {
                return Err(bad(field, "must be at least 1".into()));
            }
            Ok(())
        };
        tol("solvers.lemke.pivot_tolerance", sv.lemke.pivot_tolerance)?;
        tol("solvers.lemke.tie_tolerance", sv.lemke.tie_tolerance)?;
        count("solvers.lemke.max_pivots_per_unknown", sv.lemke.max_pivots_per_unknown)?;
        count("solvers.lemke.refactor_every", sv.lemke.refactor_every)?;
        tol("solvers.clarabel.tolerance", sv.clarabel.tolerance)?;
        count("solvers.clarabel.max_iter", sv.clarabel.max_iter as usize)?;
        tol("solvers.pgs.tolerance", sv.pgs.tolerance)?;
        count("solvers.pgs.max_sweeps", sv.pgs.max_sweeps)?;
        count("solvers.pgs.max_outer", sv.pgs.max_outer)?;
        if !(sv.pgs.relaxation > 0.0 && sv.pgs.relaxation < 2.0) {
            return Err(bad("solvers.pgs.relaxation", format!("must lie in (0, 2) (got {})", sv.pgs.relaxation)));
        }
        tol("solvers.normtang_qp.tolerance", sv.normtang_qp.tolerance)?;
        count("solvers.normtang_qp.max_outer", sv.normtang_qp.max_outer)?;
        tol("solvers.normtang_qp.qp.tolerance", sv.normtang_qp.qp.tolerance)?;
        let ck = &self.checks;
        for (field, v) in [
            ("checks.hertz", ck.hertz),
            ("checks.agreement", ck.agreement),
            ("checks.residual", ck.residual),
            ("checks.cattaneo_elements", ck.cattaneo_elements),
        ] {
            if let Some(v) = v {
                positive(field, v)?;
            }
        }
        Ok(())
    }

    /// Path placeholder for scenes built in code.
    pub fn code_path() -> PathBuf {
        PathBuf::from("<scene>")
    }
}

impl Expect {
    /// The status expected of `solver` (by its registry name).
    pub fn status_for(&self, solver: &str) -> crate::solvers::Status {
        self.solver_status.iter().find(|(k, _)| k.name() == solver).map(|(_, v)| *v).unwrap_or(self.status)
    }
}
