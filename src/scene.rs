//! Scene files: what to simulate (TOML, see `../shared/DESIGN.md` and `reference/scenes/`).
//!
//! A scene is parsed with serde (unknown keys are rejected) and then validated range by range; every error names
//! the file and the dotted key. Units are the user's and must be consistent (e.g. N, mm, MPa): lengths, moduli and
//! loads per unit thickness. Sign conventions of the drive follow `DESIGN.md`: the support moves rigidly relative
//! to the fixed flat by an approach `d_N` (towards the flat, positive compresses), a tangential shift `d_T` (+x) and
//! a rotation `φ` (counter-clockwise, radians); a drive load is the resultant the contact must carry
//! (`normal_load` = P = ∫p dx > 0 compressive).

use crate::error::{Error, Result};
pub use crate::formulation::Dof;
use crate::formulation::{ContactLaw, Drive as DriveDofs};
use crate::status::Status;
use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

/// Largest number of boundary nodes (collocation points) a scene may have: the dense BEM system (2N)² and its LU
/// then need about 2 GiB.
pub const MAX_NODES: usize = 8000;

/// Largest number of contact elements of a half-plane scene: the four dense influence blocks (4n² doubles) and the
/// frictional LCP ((3n)² doubles) then need about 3.5 GiB.
pub const MAX_HALF_PLANE_ELEMENTS: usize = 6000;

/// A whole scene.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Scene {
    /// Short identifier, used in reports.
    pub name: String,
    /// What the scene is and where its numbers come from.
    #[serde(default)]
    pub description: String,
    /// The scene's units as a label for tables and axes, e.g. `"N, mm, MPa"` (force, length, stress): rollbem is
    /// unit-agnostic (any consistent set works); this only says which set the numbers are in.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub units: Option<String>,
    /// The elastic wheel and its support.
    pub wheel: Wheel,
    /// Boundary-element mesh of the wheel (or the contact grid of the half-plane).
    pub mesh: MeshSpec,
    /// The counter-body: a rigid flat (default) or an elastic half-plane.
    #[serde(default)]
    pub counter_body: CounterBody,
    /// Contact law.
    #[serde(default)]
    pub contact: ContactSpec,
    /// How the support is driven: a displacement or a load for each rigid degree of freedom (one step from rest).
    /// Absent when the scene gives a load path (`[[steps]]`).
    #[serde(default)]
    pub drive: Drive,
    /// A load path: quasi-static steps with memory ([`crate::history`]), instead of `[drive]`.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub steps: Vec<Step>,
    /// Optional rolling: steady-state rolling, or the seed's slip velocity after a static solve.
    #[serde(default)]
    pub rolling: Option<Rolling>,
    /// Which solvers to run.
    #[serde(default)]
    pub solvers: SolverSpec,
    /// What the scene expects of its runs.
    #[serde(default)]
    pub checks: Expect,
    /// Subsurface stresses on a grid below the contact ([`crate::stresses`]); computed only when given.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub stresses: Option<StressSpec>,
}

/// Expectations a scene declares about its own outcome (`[checks]`): the status, and tolerances that override
/// the defaults of [`crate::tolerances`] for this scene.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Expect {
    /// The status every solver should end with (default `solved`; e.g. `infeasible` for a load beyond μP).
    #[serde(default = "default_status")]
    pub status: Status,
    /// Per-solver expected statuses overriding `status` (e.g. `{ pgs = "not_converged" }` where the NORM-TANG
    /// split is known not to converge); keys are registry names ([`crate::solvers::REGISTRY`]).
    #[serde(default, skip_serializing_if = "BTreeMap::is_empty")]
    pub solver_status: BTreeMap<String, Status>,
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
    /// Fewest contact elements across a loaded contact (default
    /// [`crate::tolerances::MIN_CONTACT_ELEMENTS`]; e.g. 1 for a scene about a one-node contact).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub contact_elements: Option<f64>,
}

fn default_status() -> Status {
    Status::Solved
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
            contact_elements: None,
        }
    }
}

/// The wheel: an elastic disk (or annulus) in plane strain, modelled either as itself (BEM, the finite body) or as
/// an elastic half-plane with the wheel's initial gap (the half-space model of Hertz, Cattaneo, Carter and Spence).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Wheel {
    /// Outer radius R (length unit).
    pub radius: f64,
    /// Young's modulus E (stress unit).
    pub youngs_modulus: f64,
    /// Poisson's ratio ν, 0 ≤ ν ≤ 0.5 (plane strain).
    pub poisson_ratio: f64,
    /// Which model of the wheel: `bem` (default, the finite wheel) or `half_plane`.
    #[serde(default)]
    pub model: BodyModel,
    /// How the wheel is held (BEM only; required there, refused for the half-plane).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub support: Option<Support>,
    /// Half-plane only: depth below the contact centre of the datum point whose rigid motion the drive prescribes
    /// (length unit; default R, the depth of the wheel's centre). A half-plane's surface displacement under a line
    /// load is logarithmic, so an approach is defined only against such a datum.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub datum_depth: Option<f64>,
    /// Half-plane only: the initial gap profile, `circle` (default: the wheel's circle, g₀ = R − √(R² − x²)) or
    /// `parabola` (g₀ = x²/(2R), Hertz's geometry and the seed's eq. 5).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub profile: Option<Profile>,
}

impl Wheel {
    /// The support of a (validated) BEM wheel.
    ///
    /// # Panics
    /// If the wheel has no support (a half-plane, or an unvalidated scene).
    pub fn support(&self) -> Support {
        self.support.expect("a BEM wheel has a support (checked by Scene::validate)")
    }

    /// The half-plane's datum depth (default R).
    pub fn datum(&self) -> f64 {
        self.datum_depth.unwrap_or(self.radius)
    }
}

/// The model of the wheel.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum BodyModel {
    /// The finite wheel, by the boundary element method.
    #[default]
    Bem,
    /// An elastic half-plane with the wheel's material and initial gap (closed-form influence coefficients).
    HalfPlane,
}

impl BodyModel {
    /// Name as written in scene files.
    pub fn name(self) -> &'static str {
        match self {
            BodyModel::Bem => "bem",
            BodyModel::HalfPlane => "half_plane",
        }
    }
}

/// The initial gap profile of the half-plane model.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Profile {
    /// The wheel's circle: g₀ = R − √(R² − x²).
    Circle,
    /// Hertz's parabola: g₀ = x²/(2R).
    Parabola,
}

/// The counter-body the wheel meets.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case", deny_unknown_fields)]
pub enum CounterBody {
    /// A rigid flat (the seed's problem).
    #[default]
    Rigid,
    /// An elastic half-plane (e.g. a steel rail under a steel wheel), in plane strain.
    HalfPlane {
        /// Its Young's modulus (stress unit).
        youngs_modulus: f64,
        /// Its Poisson's ratio, 0 ≤ ν ≤ 0.5.
        poisson_ratio: f64,
        /// Depth of its datum point below the contact centre (length unit; default R).
        #[serde(default, skip_serializing_if = "Option::is_none")]
        datum_depth: Option<f64>,
    },
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

/// Mesh of the wheel's boundary (BEM), or the contact grid of the half-plane. The potential contact zone is given
/// by exactly one of `contact_arc_deg` (elements uniform in angle on the arc) and `contact_half_width` (elements
/// uniform in x, so that a grid of N elements of size dx is written directly); both models put their collocation
/// points at the same x for the same keys.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct MeshSpec {
    /// Element family.
    pub element: ElementKind,
    /// Angular extent (degrees) of the potential contact zone, centred on the bottom point, in (0, 180).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub contact_arc_deg: Option<f64>,
    /// Half-width (length unit) of the potential contact zone, 0 < w < R: the zone is −w ≤ x ≤ w.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub contact_half_width: Option<f64>,
    /// Number of elements on the potential contact zone, ≥ 1.
    pub contact_elements: usize,
    /// BEM only: number of elements on the rest of the outer boundary (graded from the contact size), ≥ 4. The hub
    /// circle gets elements in proportion to its circumference.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub other_elements: Option<usize>,
}

impl MeshSpec {
    /// A BEM mesh on a contact arc of `arc_deg` degrees.
    pub fn arc(element: ElementKind, arc_deg: f64, contact_elements: usize, other_elements: usize) -> MeshSpec {
        MeshSpec {
            element,
            contact_arc_deg: Some(arc_deg),
            contact_half_width: None,
            contact_elements,
            other_elements: Some(other_elements),
        }
    }

    /// The potential contact zone's half-width in x for a wheel of radius `radius` (the half chord of the arc).
    pub fn half_width(&self, radius: f64) -> f64 {
        match (self.contact_half_width, self.contact_arc_deg) {
            (Some(w), _) => w,
            (None, Some(a)) => radius * (0.5 * a.to_radians()).sin(),
            (None, None) => 0.0,
        }
    }

    /// The angle (radians) the potential contact zone subtends on a wheel of radius `radius`.
    pub fn arc_rad(&self, radius: f64) -> f64 {
        match (self.contact_arc_deg, self.contact_half_width) {
            (Some(a), _) => a.to_radians(),
            (None, Some(w)) => 2.0 * (w / radius).asin(),
            (None, None) => 0.0,
        }
    }

    /// The (mean) contact element length on a wheel of radius `radius` (user's unit): the arc length over the
    /// number of elements with `contact_arc_deg`, the grid step dx with `contact_half_width`.
    pub fn element_length(&self, radius: f64) -> f64 {
        match self.contact_half_width {
            Some(w) => 2.0 * w / self.contact_elements as f64,
            None => radius * self.arc_rad(radius) / self.contact_elements as f64,
        }
    }

    /// The number of other elements of a (validated) BEM mesh.
    ///
    /// # Panics
    /// If absent (a half-plane grid, or an unvalidated scene).
    pub fn others(&self) -> usize {
        self.other_elements.expect("a BEM mesh has other_elements (checked by Scene::validate)")
    }
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

/// One step of a load path (`[[steps]]`): the drive at the step's end, with the keys of `[drive]` (each rigid DOF a
/// displacement or a load; the normal DOF required, the others 0 when absent), reached in `substeps` equal
/// increments (linear in the prescribed quantity, from its value at the previous step's end), while the contact
/// rolls `roll` (a length) over the body at the scene's creepage (`[rolling] mode = "transient"`).
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Step {
    /// Rigid approach d_N at the step's end.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub normal_approach: Option<f64>,
    /// Normal load P at the step's end.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub normal_load: Option<f64>,
    /// Tangential shift d_T at the step's end.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub tangential_shift: Option<f64>,
    /// Tangential load Q at the step's end.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub tangential_load: Option<f64>,
    /// Rotation φ at the step's end.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub rotation: Option<f64>,
    /// Moment M at the step's end.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub moment: Option<f64>,
    /// Number of equal increments (default 1).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub substeps: Option<usize>,
    /// Distance the contact rolls over the body during the step (length, ≥ 0; default 0).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub roll: Option<f64>,
}

impl Step {
    /// The step's end drive as a `[drive]` table.
    pub fn drive(&self) -> Drive {
        Drive {
            normal_approach: self.normal_approach,
            normal_load: self.normal_load,
            tangential_shift: self.tangential_shift,
            tangential_load: self.tangential_load,
            rotation: self.rotation,
            moment: self.moment,
        }
    }
}

/// Rolling (seed eqs. 6–12): either the steady-rolling problem with the slip velocity as the unknown of Coulomb's
/// law (`mode = "steady"`, [`crate::formulation::slip`]), or the seed's formulation: a static solve, then the slip
/// velocity of eq. 12 computed from it (`mode = "seed"`).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Rolling {
    /// Which formulation (required, so that nobody gets the seed's post-processing by surprise).
    pub mode: RollingMode,
    /// Creepage ξ = (V_A − V_B)/|V|, the rigid slip velocity of the wheel's surface relative to the flat over the
    /// rolling speed (dimensionless; ξ > 0 braking). Steady: prescribe it, or give `[drive] tangential_load`
    /// instead and it is computed. Seed: required.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub creepage: Option<f64>,
    /// The rolling direction: +1 towards +x (the leading edge is at +x), −1 towards −x.
    pub direction: i32,
}

/// The rolling formulation.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum RollingMode {
    /// Steady-state rolling: the slip velocity is the unknown of Coulomb's law.
    Steady,
    /// The seed's formulation: a static solve, then eq. 12.
    Seed,
    /// Transient rolling through a load path (`[[steps]]` with `roll`): each step's slip is the slip increment of the
    /// material, which the contact carries along by the rolled distance ([`crate::history`]).
    Transient,
}

/// Largest number of grid points of `[stresses]` (`points = [nx, nz]`, nx·nz): a million points of a BEM wheel take
/// minutes and the field about 100 MB of JSON.
pub const MAX_STRESS_POINTS: usize = 1_000_000;

/// A quantity of the subsurface stress field ([`crate::stresses`]): x along the surface, z the depth into the wheel,
/// plane strain, tension positive, in the scene's stress unit.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum StressQuantity {
    /// σ_xx, the normal stress along the surface.
    Sxx,
    /// σ_zz, the normal stress along the depth.
    Szz,
    /// τ_xz, the in-plane shear stress.
    Txz,
    /// σ_yy = ν(σ_xx + σ_zz), the out-of-plane normal stress of plane strain.
    Syy,
    /// The in-plane principal shear τ₁ = √(((σ_xx − σ_zz)/2)² + τ_xz²) (Tresca's in-plane measure).
    PrincipalShear,
    /// The von Mises equivalent stress with σ_yy = ν(σ_xx + σ_zz).
    VonMises,
    /// The orthogonal shear τ_xz (the shear on the planes normal and parallel to the surface; the rolling-contact
    /// fatigue measure: its amplitude as the load passes is 2 max|τ_xz|).
    OrthogonalShear,
}

impl StressQuantity {
    /// Every quantity, in the order of the result document and of the CSV columns.
    pub const ALL: [StressQuantity; 7] = [
        StressQuantity::Sxx,
        StressQuantity::Szz,
        StressQuantity::Txz,
        StressQuantity::Syy,
        StressQuantity::PrincipalShear,
        StressQuantity::VonMises,
        StressQuantity::OrthogonalShear,
    ];

    /// Name as written in scene files and results.
    pub fn name(self) -> &'static str {
        match self {
            StressQuantity::Sxx => "sxx",
            StressQuantity::Szz => "szz",
            StressQuantity::Txz => "txz",
            StressQuantity::Syy => "syy",
            StressQuantity::PrincipalShear => "principal_shear",
            StressQuantity::VonMises => "von_mises",
            StressQuantity::OrthogonalShear => "orthogonal_shear",
        }
    }

    /// The quantity of a name, if there is one.
    pub fn from_name(name: &str) -> Option<StressQuantity> {
        StressQuantity::ALL.into_iter().find(|q| q.name() == name)
    }
}

fn all_stress_quantities() -> Vec<String> {
    StressQuantity::ALL.iter().map(|q| q.name().to_string()).collect()
}

/// `[stresses]`: the subsurface stress field of the wheel on a regular grid below the contact ([`crate::stresses`]).
/// The grid's nodes are `x = x[0] + i (x[1] − x[0])/(nx − 1)` and `depth = depth[0] + j (depth[1] − depth[0])/(nz − 1)`;
/// depth z is measured from the flat (the line the undeformed wheel touches at x = 0), positive into the wheel:
/// the point (x, z) is (x, z − R) in the wheel's axes. Lengths in the scene's length unit.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct StressSpec {
    /// `[min, max]` of x along the surface (length unit; for the BEM wheel inside (−R, R)).
    pub x: [f64; 2],
    /// `[min, max]` of the depth z ≥ 0 (length unit; for the BEM wheel below 2R).
    pub depth: [f64; 2],
    /// `[nx, nz]`: grid nodes along x and along depth, each ≥ 2, nx·nz ≤ [`MAX_STRESS_POINTS`].
    pub points: [usize; 2],
    /// Quantities to report (names of [`StressQuantity`]; default all).
    #[serde(default = "all_stress_quantities")]
    pub quantities: Vec<String>,
    /// Name of the scene's length unit, for the axes of `rollbem plot` (a label only; default "length unit").
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub length_unit: Option<String>,
    /// Name of the scene's stress unit, for the colour bars of `rollbem plot` (a label only; default "stress unit").
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub stress_unit: Option<String>,
}

impl StressSpec {
    /// The quantities of a validated spec, in [`StressQuantity::ALL`] order, without repeats.
    pub fn quantities(&self) -> Vec<StressQuantity> {
        StressQuantity::ALL.into_iter().filter(|q| self.quantities.iter().any(|n| n == q.name())).collect()
    }

    /// Number of grid points nx·nz.
    pub fn n_points(&self) -> usize {
        self.points[0].saturating_mul(self.points[1])
    }
}

/// Range checks of scene values; every error names the file and the dotted key.
struct Checker<'a> {
    path: &'a Path,
}

impl Checker<'_> {
    fn bad(&self, field: &str, message: String) -> Error {
        Error::Invalid { path: self.path.to_path_buf(), field: field.to_string(), message }
    }

    fn positive(&self, field: &str, v: f64) -> Result<()> {
        if !v.is_finite() || v <= 0.0 {
            return Err(self.bad(field, format!("must be a finite number > 0 (got {v})")));
        }
        Ok(())
    }

    fn poisson(&self, field: &str, nu: f64) -> Result<()> {
        if !nu.is_finite() || !(0.0..=0.5).contains(&nu) {
            return Err(self.bad(field, format!("must lie in [0, 0.5] (got {nu})")));
        }
        Ok(())
    }

    /// A key that means nothing for the half-plane model.
    fn meaningless(&self, field: &str) -> Error {
        self.bad(
            field,
            "means nothing for wheel.model = \"half_plane\" (an unbounded body has no support, no other boundary \
             and no rotation about a centre): remove it"
                .into(),
        )
    }

    fn finite(&self, field: &str, v: f64) -> Result<()> {
        if !v.is_finite() {
            return Err(self.bad(field, format!("must be a finite number (got {v})")));
        }
        Ok(())
    }
}

/// Which solvers to run (`[solvers] use = [...]`, registry names or `"all"`), with their settings tables
/// (`[solvers.NAME]`, validated by each solver: [`crate::solvers::Validate`]). After [`Scene::from_toml`] (or
/// [`SolverSpec::default`]) `settings` holds every registered solver's settings with the defaults filled in.
#[derive(Debug, Clone, PartialEq)]
pub struct SolverSpec {
    /// Solver names; `["all"]` runs every solver of the registry's `all` set that applies to the scene.
    pub use_: Vec<String>,
    /// Settings table per registered solver name.
    pub settings: BTreeMap<String, toml::Value>,
}

impl Default for SolverSpec {
    fn default() -> Self {
        let mut s = SolverSpec { use_: vec!["all".into()], settings: BTreeMap::new() };
        s.normalize().expect("default settings are valid");
        s
    }
}

impl SolverSpec {
    /// Solvers by name (`"all"` included).
    pub fn using(names: &[&str]) -> SolverSpec {
        SolverSpec { use_: names.iter().map(|s| s.to_string()).collect(), ..SolverSpec::default() }
    }

    /// Set one setting of one solver (e.g. `set("pgs", "max_outer", 1)`, or a dotted key into a nested table:
    /// `set("normtang_qp", "qp.max_iter", 50)`); checked when the solver is built.
    pub fn set(&mut self, solver: &str, key: &str, value: impl Into<toml::Value>) {
        let mut t = self.settings.entry(solver.to_string()).or_insert_with(|| toml::Value::Table(Default::default()));
        let parts: Vec<&str> = key.split('.').collect();
        for p in &parts[..parts.len() - 1] {
            let toml::Value::Table(tab) = t else { return };
            t = tab.entry(p.to_string()).or_insert_with(|| toml::Value::Table(Default::default()));
        }
        if let toml::Value::Table(tab) = t {
            tab.insert(parts[parts.len() - 1].to_string(), value.into());
        }
    }

    /// One setting of one solver (a dotted key reaches into nested tables), if present.
    pub fn get(&self, solver: &str, key: &str) -> Option<&toml::Value> {
        let mut v = self.settings.get(solver)?;
        for p in key.split('.') {
            v = v.as_table()?.get(p)?;
        }
        Some(v)
    }

    /// Build a registered solver with this spec's settings (an input error names the key).
    pub fn build(
        &self,
        name: &str,
    ) -> std::result::Result<Box<dyn crate::solvers::Solver>, crate::solvers::SettingsError> {
        crate::solvers::build(name, self.settings.get(name))
    }

    /// Check the names and every settings table, and fill in the defaults of every registered solver.
    pub fn normalize(&mut self) -> std::result::Result<(), crate::solvers::SettingsError> {
        use crate::solvers::{SettingsError, REGISTRY};
        if self.use_.is_empty() {
            return Err(SettingsError {
                field: "solvers.use".into(),
                message: "must name at least one solver (or \"all\")".into(),
                unknown: false,
            });
        }
        for name in &self.use_ {
            if name != "all" && crate::solvers::entry(name).is_none() {
                return Err(SettingsError {
                    field: "solvers.use".into(),
                    message: format!("unknown solver `{name}` (expected one of: all, {})", crate::solvers::names()),
                    unknown: true,
                });
            }
        }
        if let Some(k) = self.settings.keys().find(|k| crate::solvers::entry(k).is_none()) {
            return Err(SettingsError {
                field: format!("solvers.{k}"),
                message: format!("unknown solver settings table (solvers are: {})", crate::solvers::names()),
                unknown: true,
            });
        }
        let mut settings = BTreeMap::new();
        for e in REGISTRY {
            let solver = (e.build)(self.settings.get(e.name))?;
            settings.insert(e.name.to_string(), solver.settings());
        }
        self.settings = settings;
        Ok(())
    }
}

impl Serialize for SolverSpec {
    fn serialize<S: serde::Serializer>(&self, s: S) -> std::result::Result<S::Ok, S::Error> {
        use serde::ser::SerializeMap;
        let mut m = s.serialize_map(Some(1 + self.settings.len()))?;
        m.serialize_entry("use", &self.use_)?;
        // Registry order first (as reported), then anything else.
        for e in crate::solvers::REGISTRY {
            if let Some(v) = self.settings.get(e.name) {
                m.serialize_entry(e.name, v)?;
            }
        }
        for (k, v) in self.settings.iter().filter(|(k, _)| crate::solvers::entry(k).is_none()) {
            m.serialize_entry(k, v)?;
        }
        m.end()
    }
}

impl<'de> Deserialize<'de> for SolverSpec {
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> std::result::Result<Self, D::Error> {
        #[derive(Deserialize)]
        struct Raw {
            #[serde(rename = "use", default = "default_use")]
            use_: Vec<String>,
            #[serde(flatten)]
            settings: BTreeMap<String, toml::Value>,
        }
        let raw = Raw::deserialize(d)?;
        Ok(SolverSpec { use_: raw.use_, settings: raw.settings })
    }
}

fn default_use() -> Vec<String> {
    vec!["all".into()]
}

impl Scene {
    /// Read, parse and validate a scene file.
    pub fn from_file(path: &Path) -> Result<Scene> {
        let text = std::fs::read_to_string(path).map_err(|source| Error::Io { path: path.to_path_buf(), source })?;
        Scene::from_toml(&text, path)
    }

    /// Parse and validate scene text; `path` is used in error messages only. The solvers' settings come back with
    /// their defaults filled in.
    pub fn from_toml(text: &str, path: &Path) -> Result<Scene> {
        let mut scene: Scene = toml::from_str(text)
            .map_err(|e| Error::Parse { path: path.to_path_buf(), message: e.to_string().trim_end().to_string() })?;
        scene.validate(path)?;
        scene.solvers.normalize().map_err(|e| e.into_error(path))?;
        Ok(scene)
    }

    /// The drive of the three rigid degrees of freedom (user's units).
    pub fn drive_dofs(&self) -> DriveDofs {
        let tangential = match &self.rolling {
            Some(Rolling { mode: RollingMode::Steady, creepage: Some(xi), .. }) => Dof::Displacement(*xi),
            _ => self.drive.tangential(),
        };
        DriveDofs { normal: self.drive.normal(), tangential, rotational: self.drive.rotational() }
    }

    /// The plane-strain contact modulus of the pair, E* with 1/E* = (1 − ν₁²)/E₁ + (1 − ν₂²)/E₂ (the second term
    /// absent for a rigid counter-body), as Hertz's theory uses it.
    pub fn contact_modulus(&self) -> f64 {
        let w = &self.wheel;
        let mut c = (1.0 - w.poisson_ratio * w.poisson_ratio) / w.youngs_modulus;
        if let CounterBody::HalfPlane { youngs_modulus, poisson_ratio, .. } = self.counter_body {
            c += (1.0 - poisson_ratio * poisson_ratio) / youngs_modulus;
        }
        1.0 / c
    }

    /// Dundurs' β of the pair (wheel against counter-body; a rigid counter-body has G₂ → ∞):
    /// β = [(1 − 2ν₁)/G₁ − (1 − 2ν₂)/G₂] / [2((1 − ν₁)/G₁ + (1 − ν₂)/G₂)]. β = 0 decouples the normal and tangential
    /// problems of two half-planes.
    pub fn dundurs_beta(&self) -> f64 {
        let w = &self.wheel;
        let g = |e: f64, nu: f64| e / (2.0 * (1.0 + nu));
        let (a1, b1) = ((1.0 - 2.0 * w.poisson_ratio), (1.0 - w.poisson_ratio));
        let g1 = g(w.youngs_modulus, w.poisson_ratio);
        let (num2, den2) = match self.counter_body {
            CounterBody::Rigid => (0.0, 0.0),
            CounterBody::HalfPlane { youngs_modulus, poisson_ratio, .. } => {
                let g2 = g(youngs_modulus, poisson_ratio);
                ((1.0 - 2.0 * poisson_ratio) / g2, (1.0 - poisson_ratio) / g2)
            }
        };
        (a1 / g1 - num2) / (2.0 * (b1 / g1 + den2))
    }

    /// The contact law.
    pub fn law(&self) -> ContactLaw {
        ContactLaw { friction: self.contact.friction, coupling: self.contact.coupling }
    }

    /// Check every value's range; the error names the dotted key.
    pub fn validate(&self, path: &Path) -> Result<()> {
        let c = Checker { path };
        if let Err(why) = safe_name(&self.name) {
            return Err(c.bad("name", why));
        }
        self.validate_wheel(&c)?;
        self.validate_mesh(&c)?;
        self.validate_counter_body(&c)?;
        let mu = self.contact.friction;
        if !mu.is_finite() || mu < 0.0 {
            return Err(c.bad("contact.friction", format!("must be a finite number ≥ 0 (got {mu})")));
        }
        self.validate_drive(&c)?;
        self.validate_stresses(&c)?;
        self.solvers.clone().normalize().map_err(|e| e.into_error(path))?;
        if let Some(k) = self.checks.solver_status.keys().find(|k| crate::solvers::entry(k).is_none()) {
            return Err(Error::Parse {
                path: path.to_path_buf(),
                message: format!("checks.solver_status.{k}: unknown solver (solvers are: {})", crate::solvers::names()),
            });
        }
        let ck = &self.checks;
        for (field, v) in [
            ("checks.hertz", ck.hertz),
            ("checks.agreement", ck.agreement),
            ("checks.residual", ck.residual),
            ("checks.cattaneo_elements", ck.cattaneo_elements),
            ("checks.contact_elements", ck.contact_elements),
        ] {
            if let Some(v) = v {
                c.positive(field, v)?;
            }
        }
        Ok(())
    }

    fn validate_wheel(&self, c: &Checker) -> Result<()> {
        let w = &self.wheel;
        c.positive("wheel.radius", w.radius)?;
        c.positive("wheel.youngs_modulus", w.youngs_modulus)?;
        c.poisson("wheel.poisson_ratio", w.poisson_ratio)?;
        let nu = w.poisson_ratio;
        let support = match (w.model, w.support) {
            (BodyModel::Bem, Some(s)) => s,
            (BodyModel::Bem, None) => {
                return Err(c.bad("wheel.support", "missing: the BEM wheel needs a support (hub or top_arc)".into()))
            }
            (BodyModel::HalfPlane, Some(_)) => return Err(c.meaningless("wheel.support")),
            (BodyModel::HalfPlane, None) => {
                if let Some(d) = w.datum_depth {
                    c.positive("wheel.datum_depth", d)?;
                }
                return Ok(());
            }
        };
        if w.datum_depth.is_some() {
            return Err(c.bad(
                "wheel.datum_depth",
                "only for model = \"half_plane\": the BEM wheel's rigid motion is that of its support".into(),
            ));
        }
        if w.profile.is_some_and(|p| p != Profile::Circle) {
            return Err(c.bad("wheel.profile", "only for model = \"half_plane\": the BEM wheel is a circle".into()));
        }
        match support {
            Support::Hub { radius } => {
                c.positive("wheel.support.radius", radius)?;
                if nu == 0.5 {
                    return Err(c.bad(
                        "wheel.poisson_ratio",
                        "ν = 0.5 with a hub support is degenerate for the displacement BIE: in incompressible plane \
                         strain a uniform radial traction on the clamped hub circle produces no displacement anywhere, \
                         so the hub pressure is undetermined (the BEM system is singular). Use ν ≤ 0.4999, or the \
                         top_arc support (an open clamped arc), for which ν = 0.5 is well posed"
                            .into(),
                    ));
                }
                if radius >= 0.95 * w.radius {
                    return Err(c.bad(
                        "wheel.support.radius",
                        format!("hub radius {radius} must be below 0.95 × wheel.radius = {}", 0.95 * w.radius),
                    ));
                }
            }
            Support::TopArc { angle_deg } => {
                if !angle_deg.is_finite() || angle_deg <= 0.0 || angle_deg >= 180.0 {
                    return Err(
                        c.bad("wheel.support.angle_deg", format!("must lie in (0, 180) degrees (got {angle_deg})"))
                    );
                }
            }
        }
        Ok(())
    }

    fn validate_stresses(&self, c: &Checker) -> Result<()> {
        let Some(st) = &self.stresses else { return Ok(()) };
        let r = self.wheel.radius;
        let bem = self.wheel.model == BodyModel::Bem;
        for (key, [lo, hi]) in [("stresses.x", st.x), ("stresses.depth", st.depth)] {
            c.finite(key, lo)?;
            c.finite(key, hi)?;
            if lo >= hi {
                return Err(c.bad(key, format!("[min, max] must have min < max (got [{lo}, {hi}])")));
            }
        }
        if st.depth[0] < 0.0 {
            return Err(c.bad(
                "stresses.depth",
                format!("depths are measured into the wheel from the flat and must be ≥ 0 (got {})", st.depth[0]),
            ));
        }
        if bem && (st.x[0] <= -r || st.x[1] >= r) {
            return Err(c.bad(
                "stresses.x",
                format!("the grid must lie inside the wheel: −R < x < R = {r} (got [{}, {}])", st.x[0], st.x[1]),
            ));
        }
        if bem && st.depth[1] >= 2.0 * r {
            return Err(c.bad(
                "stresses.depth",
                format!("the grid must lie inside the wheel: depth < 2R = {} (got {})", 2.0 * r, st.depth[1]),
            ));
        }
        let [nx, nz] = st.points;
        if nx < 2 || nz < 2 {
            return Err(c.bad("stresses.points", format!("[nx, nz] must both be at least 2 (got [{nx}, {nz}])")));
        }
        if nx.checked_mul(nz).is_none_or(|n| n > MAX_STRESS_POINTS) {
            return Err(c.bad(
                "stresses.points",
                format!("{nx} × {nz} points: rollbem allows at most {MAX_STRESS_POINTS} (nx·nz)"),
            ));
        }
        if st.quantities.is_empty() {
            return Err(c.bad("stresses.quantities", "must name at least one quantity (or leave it out: all)".into()));
        }
        if let Some(q) = st.quantities.iter().find(|q| StressQuantity::from_name(q).is_none()) {
            let names: Vec<&str> = StressQuantity::ALL.iter().map(|q| q.name()).collect();
            return Err(c.bad(
                "stresses.quantities",
                format!("unknown quantity `{q}` (expected one of: {})", names.join(", ")),
            ));
        }
        Ok(())
    }

    fn validate_counter_body(&self, c: &Checker) -> Result<()> {
        if let CounterBody::HalfPlane { youngs_modulus, poisson_ratio, datum_depth } = self.counter_body {
            c.positive("counter_body.youngs_modulus", youngs_modulus)?;
            c.poisson("counter_body.poisson_ratio", poisson_ratio)?;
            if let Some(d) = datum_depth {
                c.positive("counter_body.datum_depth", d)?;
            }
            if self.mesh.element == ElementKind::Quadratic {
                return Err(c.bad(
                    "mesh.element",
                    "an elastic counter-body needs constant elements: its influence coefficients are those of \
                     uniform-traction strips"
                        .into(),
                ));
            }
        }
        Ok(())
    }

    fn validate_mesh(&self, c: &Checker) -> Result<()> {
        let w = &self.wheel;
        let m = &self.mesh;
        match (m.contact_arc_deg, m.contact_half_width) {
            (Some(_), Some(_)) => {
                return Err(c.bad(
                    "mesh.contact_arc_deg",
                    "give either `mesh.contact_arc_deg` or `mesh.contact_half_width`, not both".into(),
                ))
            }
            (None, None) => {
                return Err(
                    c.bad("mesh", "give `contact_arc_deg` or `contact_half_width` (the potential contact zone)".into())
                )
            }
            (Some(a), None) => {
                if !a.is_finite() || a <= 0.0 || a >= 180.0 {
                    return Err(c.bad("mesh.contact_arc_deg", format!("must lie in (0, 180) degrees (got {a})")));
                }
            }
            (None, Some(hw)) => {
                if !hw.is_finite() || hw <= 0.0 || hw >= w.radius {
                    return Err(c.bad(
                        "mesh.contact_half_width",
                        format!("must lie in (0, wheel.radius = {}) (got {hw})", w.radius),
                    ));
                }
            }
        }
        if m.contact_elements < 1 {
            return Err(c.bad("mesh.contact_elements", "must be at least 1".into()));
        }
        if w.model == BodyModel::HalfPlane {
            if m.other_elements.is_some() {
                return Err(c.meaningless("mesh.other_elements"));
            }
            if m.element != ElementKind::Constant {
                return Err(c.bad(
                    "mesh.element",
                    "the half-plane has closed-form influence coefficients for uniform-traction (constant) elements \
                     only"
                        .into(),
                ));
            }
            if m.contact_elements > MAX_HALF_PLANE_ELEMENTS {
                return Err(c.bad(
                    "mesh.contact_elements",
                    format!(
                        "{} elements: the dense influence blocks and the frictional LCP would not fit in memory; \
                         rollbem allows at most {MAX_HALF_PLANE_ELEMENTS} on the half-plane",
                        m.contact_elements
                    ),
                ));
            }
            return Ok(());
        }
        let Some(other) = m.other_elements else {
            return Err(c.bad("mesh.other_elements", "missing: the BEM wheel's mesh needs it (≥ 4)".into()));
        };
        let arc = m.arc_rad(w.radius).to_degrees();
        if let Support::TopArc { angle_deg } = w.support() {
            if arc + angle_deg >= 300.0 {
                return Err(c.bad(
                    "wheel.support.angle_deg",
                    "the clamped top arc and the contact arc overlap or leave no free boundary".into(),
                ));
            }
        }
        if other < 4 {
            return Err(c.bad("mesh.other_elements", format!("must be at least 4 (got {other})")));
        }
        // The dense BEM system holds (2N)² doubles for N nodes (plus its LU copy): bound N so that it fits in a few
        // GiB instead of failing to allocate (an abort, not an error).
        let per = match m.element {
            ElementKind::Constant => 1,
            ElementKind::Quadratic => 3,
        };
        let outer_nodes = m.contact_elements.saturating_add(other).saturating_mul(per);
        let hub_nodes = match w.support() {
            Support::Hub { radius } => ((outer_nodes as f64) * radius / w.radius).ceil() as usize + 12 * per,
            Support::TopArc { .. } => 0,
        };
        let nodes = outer_nodes.saturating_add(hub_nodes);
        if nodes > MAX_NODES {
            let gib = (2.0 * nodes as f64).powi(2) * 8.0 * 2.0 / (1u64 << 30) as f64;
            return Err(c.bad(
                "mesh",
                format!(
                    "about {nodes} boundary nodes: the dense BEM system and its LU would need about {gib:.1} GiB; \
                     rollbem allows at most {MAX_NODES} nodes (use fewer elements, or constant elements)"
                ),
            ));
        }
        Ok(())
    }

    /// Check one drive table (`[drive]`, or a step's keys) under the key prefix `prefix` (e.g. `drive` or
    /// `steps[2]`).
    fn check_drive(&self, c: &Checker, prefix: &str, d: &Drive) -> Result<()> {
        let key = |k: &str| format!("{prefix}.{k}");
        let pairs = [
            ("normal_approach", d.normal_approach, "normal_load", d.normal_load),
            ("tangential_shift", d.tangential_shift, "tangential_load", d.tangential_load),
            ("rotation", d.rotation, "moment", d.moment),
        ];
        for (a, va, b, vb) in pairs {
            if va.is_some() && vb.is_some() {
                return Err(c.bad(&key(a), format!("give either `{}` or `{}`, not both", key(a), key(b))));
            }
            if let Some(v) = va {
                c.finite(&key(a), v)?;
            }
            if let Some(v) = vb {
                c.finite(&key(b), v)?;
            }
        }
        if d.normal_approach.is_none() && d.normal_load.is_none() {
            return Err(c.bad(prefix, "give `normal_approach` or `normal_load`".into()));
        }
        if let Some(p) = d.normal_load {
            c.positive(&key("normal_load"), p)?;
        }
        if self.wheel.model == BodyModel::HalfPlane {
            if d.rotation.is_some() {
                return Err(c.meaningless(&key("rotation")));
            }
            if d.moment.is_some() {
                return Err(c.meaningless(&key("moment")));
            }
        }
        Ok(())
    }

    fn validate_steps(&self, c: &Checker) -> Result<()> {
        if self.drive != Drive::default() {
            return Err(c.bad(
                "steps",
                "give either `[drive]` (one step from rest) or `[[steps]]` (a load path), not both".into(),
            ));
        }
        let mut rolls = false;
        for (k, st) in self.steps.iter().enumerate() {
            let prefix = format!("steps[{k}]");
            self.check_drive(c, &prefix, &st.drive())?;
            if st.substeps == Some(0) {
                return Err(c.bad(&format!("{prefix}.substeps"), "must be at least 1".into()));
            }
            if let Some(r) = st.roll {
                if !r.is_finite() || r < 0.0 {
                    return Err(c.bad(&format!("{prefix}.roll"), format!("must be a finite length ≥ 0 (got {r})")));
                }
                rolls |= r > 0.0;
            }
        }
        match &self.rolling {
            Some(r) if r.mode != RollingMode::Transient => Err(c.bad(
                "rolling.mode",
                "a load path rolls with mode = \"transient\" (steady and seed are one-step formulations)".into(),
            )),
            Some(r) if r.creepage.is_none() => {
                Err(c.bad("rolling.creepage", "missing: transient rolling rolls at the scene's creepage".into()))
            }
            None if rolls => Err(c.bad(
                "rolling",
                "a step rolls (`roll` > 0): give `[rolling] mode = \"transient\"` with the creepage and direction"
                    .into(),
            )),
            _ => Ok(()),
        }
    }

    fn validate_drive(&self, c: &Checker) -> Result<()> {
        if let Some(r) = &self.rolling {
            if let Some(xi) = r.creepage {
                c.finite("rolling.creepage", xi)?;
            }
            if r.direction != 1 && r.direction != -1 {
                return Err(c.bad("rolling.direction", format!("must be 1 or -1 (got {})", r.direction)));
            }
        }
        if !self.steps.is_empty() {
            return self.validate_steps(c);
        }
        let d = &self.drive;
        self.check_drive(c, "drive", d)?;
        if let Some(r) = &self.rolling {
            match r.mode {
                RollingMode::Transient => {
                    return Err(
                        c.bad("rolling.mode", "transient rolling needs a load path (`[[steps]]` with `roll`)".into())
                    )
                }
                RollingMode::Seed if r.creepage.is_none() => {
                    return Err(c.bad("rolling.creepage", "missing: the seed's eq. 12 needs the creepage".into()))
                }
                RollingMode::Seed => {}
                RollingMode::Steady => {
                    match (r.creepage, d.tangential_load) {
                        (Some(_), Some(_)) => {
                            return Err(c.bad(
                                "rolling.creepage",
                                "give either `rolling.creepage` (the tangential force is computed) or \
                                 `drive.tangential_load` (the creepage is computed), not both"
                                    .into(),
                            ))
                        }
                        (None, None) => {
                            return Err(c.bad(
                                "rolling.creepage",
                                "steady rolling needs `rolling.creepage` or `drive.tangential_load`".into(),
                            ))
                        }
                        _ => {}
                    }
                    let steady = "means nothing in steady rolling (mode = \"steady\"): the wheel turns \
                                  continuously, its tangential motion is the creepage";
                    for (key, given) in [
                        ("drive.tangential_shift", d.tangential_shift.is_some()),
                        ("drive.rotation", d.rotation.is_some()),
                        ("drive.moment", d.moment.is_some()),
                    ] {
                        if given {
                            return Err(c.bad(key, steady.into()));
                        }
                    }
                }
            }
        }
        Ok(())
    }

    /// Path placeholder for scenes built in code.
    pub fn code_path() -> PathBuf {
        PathBuf::from("<scene>")
    }
}

/// Whether a scene name is a safe file name: it names output files (`NAME.json` in `run --out-dir` and in
/// `report`), so it must stay inside the folder it is written to. Letters, digits, `-`, `_`, `.` and `+`, not
/// starting with `.`, at most 100 characters.
pub fn safe_name(name: &str) -> std::result::Result<(), String> {
    let ok = |ch: char| ch.is_ascii_alphanumeric() || matches!(ch, '-' | '_' | '.' | '+');
    if name.is_empty() {
        return Err("must not be empty".into());
    }
    if let Some(ch) = name.chars().find(|&ch| !ok(ch)) {
        return Err(format!(
            "`{name}` names the output files (NAME.json) and may contain only letters, digits, `-`, `_`, `.` and `+` \
             (found {ch:?})"
        ));
    }
    if name.starts_with('.') {
        return Err(format!("`{name}` names the output files (NAME.json) and must not start with `.`"));
    }
    if name.len() > 100 {
        return Err(format!("`{name}` is longer than 100 characters (it names the output files)"));
    }
    Ok(())
}

/// Refuse two scenes of one command with the same name (their outputs, NAME.json, would overwrite each other):
/// `scenes` are (file, scene) pairs; the error names both files and the key `name`.
pub fn unique_names<'a>(scenes: impl IntoIterator<Item = (&'a Path, &'a Scene)>) -> Result<()> {
    unique_output_names(scenes.into_iter().map(|(p, s)| (p, s.name.as_str())))
}

/// Refuse two inputs of one command (scenes, sweep specs) with the same `name`, which names their output files:
/// `items` are (file, name) pairs; the error names both files and the key `name`.
pub fn unique_output_names<'a>(items: impl IntoIterator<Item = (&'a Path, &'a str)>) -> Result<()> {
    let mut seen: std::collections::BTreeMap<&str, &Path> = std::collections::BTreeMap::new();
    for (path, name) in items {
        if let Some(first) = seen.insert(name, path) {
            return Err(Error::Invalid {
                path: path.to_path_buf(),
                field: "name".into(),
                message: format!(
                    "`{name}` is also the name of {}: names must be unique within a command (they name the output \
                     files)",
                    first.display()
                ),
            });
        }
    }
    Ok(())
}

impl Expect {
    /// The status expected of `solver` (by its registry name).
    pub fn status_for(&self, solver: &str) -> Status {
        self.solver_status.get(solver).copied().unwrap_or(self.status)
    }
}
