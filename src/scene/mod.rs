//! Scenes: what to simulate (TOML, see `DESIGN.md` and `reference/scenes/`).
//!
//! A scene file is parsed with serde into its [`document`] (unknown keys are rejected) and validated range by range
//! into a [`Scene`], whose parts cannot hold an invalid value: its fields are private and its parts are shaped by
//! what they are (a body is a BEM wheel with its support and mesh, or a half-plane with its datum and profile; a
//! scene is driven by one drive or walks a load path; rolling is steady, the seed's or transient, each with its own
//! fields). Every error names the file and the dotted key. To change a scene, edit its document and validate it
//! again ([`Scene::edit`]).
//!
//! Units are the user's and must be consistent (e.g. N, mm, MPa): lengths, moduli and loads per unit thickness.
//! Sign conventions of the drive follow `DESIGN.md`: the support moves rigidly relative to the fixed flat by an
//! approach `d_N` (towards the flat, positive compresses), a tangential shift `d_T` (+x) and a rotation `φ`
//! (counter-clockwise, radians); a drive load is the resultant the contact must carry (`normal_load` = P = ∫p dx > 0
//! compressive).
//!
//! ```
//! use rollbem::scene::{Body, Scene};
//! let text = r#"
//! name = "hertz"
//! [wheel]
//! radius = 460.0
//! youngs_modulus = 210000.0
//! poisson_ratio = 0.3
//! support = { kind = "hub", radius = 100.0 }
//! [mesh]
//! element = "constant"
//! contact_arc_deg = 4.0
//! contact_elements = 40
//! other_elements = 60
//! [drive]
//! normal_load = 1000.0
//! "#;
//! let scene = Scene::from_toml(text, std::path::Path::new("hertz.toml")).unwrap();
//! assert!(matches!(scene.body(), Body::Bem { .. }));
//! // A negative radius is refused, naming the key.
//! let bad = scene.edit(|d| d.wheel.radius = -1.0).unwrap_err();
//! assert!(bad.to_string().contains("wheel.radius"));
//! ```

pub mod document;
mod friction;
pub mod space;
mod space_validate;
mod validate;
mod visco;

use crate::error::{Error, Result};
pub use crate::formulation::{ContactLaw, Dof, Drive};
pub use crate::material::Material;
use crate::solvers::{SolverId, SolverSettings};
use crate::status::Status;
use crate::viscoelastic::{Memory, StandardLinearSolid};
use document::SceneDocument;
use serde::{Deserialize, Serialize};
pub use space::{AnyScene, SpaceDocument, SpaceScene, SpaceStatus, SpaceStep};
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

/// Largest number of boundary nodes (collocation points) a scene may have: the dense BEM system (2N)² and its LU
/// then need about 2 GiB.
pub const MAX_NODES: usize = 8000;

/// Smallest mean angle (radians) a BEM wheel's contact element may subtend. The wheel's polar angles near the
/// contact point, −π/2, are resolved to 2.2e-16 rad; below 1e-10 rad per element the elements' extents carry fewer
/// than six significant digits and the assembled system is not the wheel's (measured: constant elements then end
/// `numerical_error` at 5.8e-11 rad, quadratic ones already at 2.3e-9 rad; a subnormal contact arc tripped the quadratic
/// integrator's own consistency assertion, found by the `scene` fuzz target). Tested in `tests/mesh_precision.rs`.
pub const MIN_CONTACT_ELEMENT_ANGLE: f64 = 1e-10;

/// Most substeps a load path may have in all (`[[steps]]` substeps summed): each is a solve per solver and a row of
/// the result. The same order as a sweep's guard (100 000 cases without `--allow-large`), ten times over: a substep
/// is cheaper than a case (no model to build).
pub const MAX_PATH_SUBSTEPS: usize = 1_000_000;

/// The largest memory a load path's result may need (bytes): it keeps every substep's run with its node values.
pub const MAX_PATH_RESULT_BYTES: u64 = 4 << 30;

/// Memory per contact node of one substep's run in a load path's result (bytes): a node's eleven values and state
/// (`results::NodeResult`, 96 bytes) with the run's vector overhead, rounded up.
pub const PATH_BYTES_PER_NODE: usize = 128;

/// Largest number of contact elements of a half-plane scene: the four dense influence blocks (4n² doubles) and the
/// frictional LCP ((3n)² doubles) then need about 3.5 GiB.
pub const MAX_HALF_PLANE_ELEMENTS: usize = 6000;

/// A validated scene: what to simulate. Built only by validation ([`Scene::from_toml`], [`Scene::from_file`],
/// [`Scene::from_document`], [`Scene::edit`]), so every value is in range and every part is complete.
#[derive(Debug, Clone)]
pub struct Scene {
    /// Where the scene came from (its file, or `<scene>`), for the messages of errors found later.
    origin: PathBuf,
    /// The document with the defaults filled in (the scene as parsed: what results and edits start from).
    document: SceneDocument,
    wheel: Wheel,
    body: Body,
    zone: ContactZone,
    counter_body: CounterBody,
    law: ContactLaw,
    loading: Loading,
    rolling: Option<Rolling>,
    solvers: SolverSet,
    /// For a scene read back from a result document that this version's checks refuse
    /// ([`Scene::from_record`]): why. Such a scene describes what was run; it cannot be run again
    /// ([`Scene::runnable`]).
    recorded: Option<String>,
}

/// The wheel's size and material.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Wheel {
    /// Outer radius R (length unit).
    pub radius: f64,
    /// Its material.
    pub material: Material,
}

/// How the wheel is modelled, with what each model needs.
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub enum Body {
    /// The finite wheel by the boundary element method: held by its support, meshed all round.
    Bem {
        /// How the wheel is held.
        support: Support,
        /// Element family.
        element: ElementKind,
        /// Elements on the rest of the outer boundary (≥ 4; the hub circle gets elements in proportion).
        other_elements: usize,
    },
    /// An elastic half-plane with the wheel's material and initial gap (closed-form influence coefficients,
    /// constant elements).
    HalfPlane {
        /// Depth below the contact centre of the datum point whose rigid motion the drive prescribes (length unit).
        datum_depth: f64,
        /// The initial gap profile.
        profile: Profile,
        /// `Some(w)`: the contact is a strip of width w (length unit) on two half-spaces, CONTACT's 2D model
        /// (`[mesh] strip_width`, [`crate::halfplane::HalfPlane::strip`]); `None`: plane strain.
        strip_width: Option<f64>,
        /// A viscoelastic wheel (`[wheel] viscoelastic`, steady rolling only); `None`: elastic.
        viscoelastic: Option<crate::viscoelastic::StandardLinearSolid>,
    },
}

impl Body {
    /// The model's name.
    pub fn model(&self) -> BodyModel {
        match self {
            Body::Bem { .. } => BodyModel::Bem,
            Body::HalfPlane { .. } => BodyModel::HalfPlane,
        }
    }

    /// The element family (the half-plane's strips are constant elements).
    pub fn element(&self) -> ElementKind {
        match self {
            Body::Bem { element, .. } => *element,
            Body::HalfPlane { .. } => ElementKind::Constant,
        }
    }
}

/// The potential contact zone and its elements (both models).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactZone {
    /// Where the zone is.
    pub extent: ZoneExtent,
    /// Number of elements on it (≥ 1).
    pub elements: usize,
}

/// The extent of the potential contact zone: centred on the bottom point, or (half-plane model) a span placed by the
/// user.
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub enum ZoneExtent {
    /// An arc of the wheel of this many degrees, in (0, 180): elements uniform in angle.
    Arc {
        /// The arc's angle, degrees.
        degrees: f64,
    },
    /// −w ≤ x ≤ w (length unit, 0 < w < R): elements uniform in x.
    HalfWidth {
        /// The half-width w.
        half_width: f64,
    },
    /// x_min ≤ x ≤ x_max (length unit, −R < x_min < x_max < R): elements uniform in x (`contact_x`; the half-plane
    /// model only).
    Span {
        /// Left end of the zone.
        x_min: f64,
        /// Right end of the zone.
        x_max: f64,
    },
}

impl ContactZone {
    /// A zone of `elements` elements on an arc of `degrees`.
    pub fn arc(degrees: f64, elements: usize) -> ContactZone {
        ContactZone { extent: ZoneExtent::Arc { degrees }, elements }
    }

    /// The zone's half-width in x on a wheel of radius `radius` (the half chord of an arc; for a span, the larger
    /// distance of its ends from x = 0).
    pub fn half_width(&self, radius: f64) -> f64 {
        match self.extent {
            ZoneExtent::HalfWidth { half_width } => half_width,
            ZoneExtent::Span { x_min, x_max } => x_min.abs().max(x_max.abs()),
            ZoneExtent::Arc { degrees } => radius * (0.5 * degrees.to_radians()).sin(),
        }
    }

    /// The angle (radians) the zone subtends on a wheel of radius `radius`.
    pub fn arc_rad(&self, radius: f64) -> f64 {
        match self.extent {
            ZoneExtent::Arc { degrees } => degrees.to_radians(),
            ZoneExtent::HalfWidth { half_width } => 2.0 * (half_width / radius).asin(),
            ZoneExtent::Span { x_min, x_max } => (x_max / radius).asin() - (x_min / radius).asin(),
        }
    }

    /// The (mean) contact element length on a wheel of radius `radius` (length unit): the arc length over the
    /// number of elements on an arc, the grid step dx on a half-width.
    pub fn element_length(&self, radius: f64) -> f64 {
        match self.extent {
            ZoneExtent::HalfWidth { half_width } => 2.0 * half_width / self.elements as f64,
            ZoneExtent::Span { x_min, x_max } => (x_max - x_min) / self.elements as f64,
            ZoneExtent::Arc { .. } => radius * self.arc_rad(radius) / self.elements as f64,
        }
    }

    /// The same zone with its lengths divided by `length` (an arc is unchanged).
    pub fn scaled(&self, length: f64) -> ContactZone {
        let extent = match self.extent {
            ZoneExtent::HalfWidth { half_width } => ZoneExtent::HalfWidth { half_width: half_width / length },
            ZoneExtent::Span { x_min, x_max } => ZoneExtent::Span { x_min: x_min / length, x_max: x_max / length },
            arc => arc,
        };
        ContactZone { extent, elements: self.elements }
    }
}

/// The counter-body the wheel meets.
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub enum CounterBody {
    /// A rigid flat (the seed's problem).
    Rigid,
    /// An elastic half-plane (e.g. a steel rail under a steel wheel), in plane strain.
    HalfPlane {
        /// Its material.
        material: Material,
        /// Depth of its datum point below the contact centre (length unit).
        datum_depth: f64,
        /// A viscoelastic counter-body (`[counter_body] viscoelastic`, steady rolling only); `None`: elastic.
        viscoelastic: Option<crate::viscoelastic::StandardLinearSolid>,
    },
    /// A finite elastic disc below the wheel, a BEM body like the wheel (the twin-disc rig,
    /// [`crate::source::two_body`]).
    Disc {
        /// Its material.
        material: Material,
        /// Its radius R₂ (length unit).
        radius: f64,
        /// How it is held: a hub, or a clamped arc centred opposite the contact.
        support: Support,
        /// Elements on its circle beyond the contact zone.
        other_elements: usize,
    },
    /// A plate with a circular bore around the wheel (the pin in a bore), a BEM body ([`crate::source::two_body`]).
    Bore {
        /// Its material.
        material: Material,
        /// The bore's radius R_b ≥ R (clearance R_b − R).
        radius: f64,
        /// The plate's outer radius (its outer circle clamped).
        outer_radius: f64,
        /// Elements on the bore beyond the contact zone.
        other_elements: usize,
        /// Elements on the outer circle.
        outer_elements: usize,
    },
}

impl CounterBody {
    /// Its material (`None` for a rigid flat).
    pub fn material(&self) -> Option<&Material> {
        match self {
            CounterBody::Rigid => None,
            CounterBody::HalfPlane { material, .. }
            | CounterBody::Disc { material, .. }
            | CounterBody::Bore { material, .. } => Some(material),
        }
    }
}

/// How the support is driven.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum Loading {
    /// One step from rest to this drive (`[drive]`). In steady rolling the tangential DOF is the creepage ξ
    /// (`Displacement`) or the tangential load Q (`Load`).
    Drive(Drive),
    /// A load path (`[[steps]]`, [`crate::pipeline`]): at least one step.
    Path(Vec<PathStep>),
}

/// One step of a load path: the drive at its end, reached in `substeps` equal increments while the contact rolls
/// `roll` over the body.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PathStep {
    /// The drive at the step's end (user's units; an absent tangential or rotational DOF is held at 0).
    pub end: Drive,
    /// Number of equal increments (≥ 1).
    pub substeps: usize,
    /// Distance the contact rolls over the body during the step (length unit, ≥ 0).
    pub roll: f64,
}

/// Rolling (seed eqs. 6–12), each formulation with its own data. `direction` is +1 for rolling towards +x (the
/// leading edge at +x), −1 towards −x.
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub enum Rolling {
    /// Steady-state rolling: the slip velocity is the unknown of Coulomb's law; the creepage ξ (or the tangential
    /// load Q, and ξ is computed) is the drive's tangential DOF.
    Steady {
        /// ±1.
        direction: i32,
        /// The rolling speed V (length/s), given only with a viscoelastic body or a friction law of the slip
        /// velocity (`[rolling] velocity`).
        velocity: Option<f64>,
    },
    /// The seed's formulation: a static solve, then the slip velocity of eq. 12 at the creepage.
    Seed {
        /// Creepage ξ (dimensionless; ξ > 0 braking).
        creepage: f64,
        /// ±1.
        direction: i32,
    },
    /// Transient rolling along a load path (steps with `roll`).
    Transient {
        /// Creepage ξ (dimensionless).
        creepage: f64,
        /// ±1.
        direction: i32,
    },
}

impl Rolling {
    /// The formulation's name.
    pub fn mode(&self) -> RollingMode {
        match self {
            Rolling::Steady { .. } => RollingMode::Steady,
            Rolling::Seed { .. } => RollingMode::Seed,
            Rolling::Transient { .. } => RollingMode::Transient,
        }
    }

    /// The rolling direction, ±1.
    pub fn direction(&self) -> i32 {
        match *self {
            Rolling::Steady { direction, .. }
            | Rolling::Seed { direction, .. }
            | Rolling::Transient { direction, .. } => direction,
        }
    }
}

/// Which solvers a scene runs, with their typed, validated settings.
#[derive(Debug, Clone, PartialEq)]
pub struct SolverSet {
    /// `use` contains `"all"`: every solver of the registry's `all` set that applies to the problem.
    pub all: bool,
    /// The solvers named explicitly (each must apply), in the order given, without repeats.
    pub named: Vec<SolverId>,
    /// Every solver's settings.
    pub settings: SolverSettings,
}

impl SolverSet {
    /// Whether the set asks for a solver by name.
    pub fn names(&self, id: SolverId) -> bool {
        self.named.contains(&id)
    }
}

/// The model of the wheel.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
#[non_exhaustive]
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
#[non_exhaustive]
pub enum Profile {
    /// The wheel's circle: g₀ = R − √(R² − x²).
    Circle,
    /// Hertz's parabola: g₀ = x²/(2R).
    Parabola,
}

/// The wheel's support, which moves rigidly with the drive.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case", deny_unknown_fields)]
#[non_exhaustive]
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
#[non_exhaustive]
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
/// The rolling formulation.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
#[non_exhaustive]
pub enum RollingMode {
    /// Steady-state rolling: the slip velocity is the unknown of Coulomb's law.
    Steady,
    /// The seed's formulation: a static solve, then eq. 12.
    Seed,
    /// Transient rolling through a load path (`[[steps]]` with `roll`): each step's slip is the slip increment of the
    /// material, which the contact carries along by the rolled distance (`crate::pipeline::path`).
    Transient,
}

impl RollingMode {
    /// Its name as written in scene files (`steady`, `seed`, `transient`).
    pub fn name(self) -> &'static str {
        match self {
            RollingMode::Steady => "steady",
            RollingMode::Seed => "seed",
            RollingMode::Transient => "transient",
        }
    }
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
    /// split is known not to converge); keys are registry names ([`crate::solvers::registry`]).
    #[serde(default, skip_serializing_if = "BTreeMap::is_empty")]
    pub solver_status: BTreeMap<SolverId, Status>,
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

/// The expectations of a scene without `[checks]`.
static DEFAULT_EXPECT: Expect = Expect {
    status: Status::Solved,
    solver_status: BTreeMap::new(),
    hertz: None,
    agreement: None,
    residual: None,
    cattaneo_elements: None,
    contact_elements: None,
};

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
/// Largest number of grid points of `[stresses]` (`points = [nx, nz]`, nx·nz): a million points of a BEM wheel take
/// minutes and the field about 100 MB of JSON.
pub const MAX_STRESS_POINTS: usize = 1_000_000;

/// A quantity of the subsurface stress field ([`crate::stresses`]): x along the surface, z the depth into the wheel,
/// plane strain, tension positive, in the scene's stress unit.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
#[non_exhaustive]
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

impl Scene {
    /// Read, parse and validate a scene file.
    pub fn from_file(path: &Path) -> Result<Scene> {
        let text = std::fs::read_to_string(path).map_err(|source| Error::Io { path: path.to_path_buf(), source })?;
        Scene::from_toml(&text, path)
    }

    /// Parse and validate scene text; `path` is used in error messages only.
    pub fn from_toml(text: &str, path: &Path) -> Result<Scene> {
        let document: SceneDocument = toml::from_str(text).map_err(|e| {
            // A half-space scene, or a 2D scene with a key only half-space scenes have: name it.
            let table = text.parse::<toml::Table>().ok();
            if table.as_ref().is_some_and(space::is_space_table) {
                return Error::Invalid {
                    path: path.to_path_buf(),
                    field: "wheel.model".into(),
                    message: "\"half_space\" is a 3D scene: read it with `scene::AnyScene` or `SpaceScene` (`rollbem \
                              run`, `check` and `plot` take both kinds; sweeps take 2D scenes only, for now)"
                        .into(),
                };
            }
            if let Some(key) = table.as_ref().and_then(space::space_only_key) {
                return Error::Invalid {
                    path: path.to_path_buf(),
                    field: key.into(),
                    message: "is a key of the half-space (3D) scenes (wheel.model = \"half_space\"); this 2D scene \
                              does not take it (README, \"Scenes\")"
                        .into(),
                };
            }
            Error::Parse { path: path.to_path_buf(), message: e.to_string().trim_end().to_string() }
        })?;
        Scene::from_document(document, path)
    }

    /// Validate a document; `path` is used in error messages only. The solvers' settings come back with their
    /// defaults filled in.
    pub fn from_document(document: SceneDocument, path: &Path) -> Result<Scene> {
        validate::validate(document, path)
    }

    /// A changed copy: `change` edits the document, which is validated again (errors name the scene's origin). A
    /// scene read back as recorded and not runnable ([`Scene::runnable`]) is refused: its document may have lost what
    /// this version could not read, and an edit must not make it look runnable.
    pub fn edit(&self, change: impl FnOnce(&mut SceneDocument)) -> Result<Scene> {
        self.runnable()?;
        let mut d = self.document.clone();
        change(&mut d);
        Scene::from_document(d, &self.origin)
    }

    /// The same scene with another one-step drive (user's units; in steady rolling the tangential DOF is the
    /// creepage ξ as a `Displacement`, or the tangential load Q). Validated like a scene file; a load path becomes a
    /// one-step drive.
    pub fn with_drive(&self, drive: Drive) -> Result<Scene> {
        let steady = matches!(self.rolling, Some(Rolling::Steady { .. }));
        self.edit(|d| {
            d.steps.clear();
            let split = |dof: Dof| match dof {
                Dof::Displacement(v) => (Some(v), None),
                Dof::Load(v) => (None, Some(v)),
            };
            let (normal_approach, normal_load) = split(drive.normal);
            let (mut tangential_shift, tangential_load) = split(drive.tangential);
            let (rotation, moment) = split(drive.rotational);
            if let (true, Some(r)) = (steady, d.rolling.as_mut()) {
                r.creepage = tangential_shift.take();
            }
            d.drive = document::DriveTable {
                normal_approach,
                normal_load,
                tangential_shift,
                tangential_load,
                rotation: if steady { None } else { rotation },
                moment,
            };
        })
    }

    /// The same scene at another creepage ξ (steady, seed or transient rolling; an error without `[rolling]`). In
    /// steady rolling a prescribed tangential load is replaced by the creepage.
    pub fn with_creepage(&self, creepage: f64) -> Result<Scene> {
        self.edit(|d| {
            if let Some(r) = d.rolling.as_mut() {
                r.creepage = Some(creepage);
                if r.mode == RollingMode::Steady {
                    d.drive.tangential_load = None;
                }
            }
        })
        .and_then(|s| match s.rolling {
            Some(_) => Ok(s),
            None => Err(Error::Invalid {
                path: self.origin.clone(),
                field: "rolling.creepage".into(),
                message: "the scene does not roll (no `[rolling]`): a creepage means nothing".into(),
            }),
        })
    }

    /// Path placeholder for scenes built in code.
    pub fn code_path() -> PathBuf {
        PathBuf::from("<scene>")
    }

    /// The same scene with another origin (what its later errors name, e.g. `spec.toml [case 3]`).
    pub fn relabel(mut self, origin: impl Into<PathBuf>) -> Scene {
        self.origin = origin.into();
        self
    }

    /// A scene as recorded in a result document: validated as [`Scene::from_document`] does when it passes this
    /// version's checks; otherwise (a document written before a check was tightened) built without them, keeping
    /// what the document says was run, and marked: [`Scene::runnable`] then says why it cannot be run again. Keys
    /// this version does not know are the caller's to drop ([`crate::results::Report::read`] does).
    ///
    /// # Errors
    /// When even the typed parts cannot be built (a BEM wheel without a support, unknown solver settings).
    pub fn from_record(document: SceneDocument, path: &Path) -> Result<Scene> {
        match validate::validate(document.clone(), path) {
            Ok(scene) => Ok(scene),
            Err(refusal) => {
                // Solvers this process does not have (a document of a program with a solver plugged in): the scene
                // as recorded without them.
                let mut known = document;
                let unknown: Vec<String> = known
                    .solvers
                    .use_
                    .iter()
                    .chain(known.solvers.settings.keys())
                    .filter(|n| *n != "all" && crate::solvers::SolverId::from_name(n).is_none())
                    .cloned()
                    .collect();
                known.solvers.use_.retain(|n| !unknown.contains(n));
                known.solvers.settings.retain(|n, _| !unknown.contains(n));
                if known.solvers.use_.is_empty() {
                    known.solvers.use_ = vec!["all".into()];
                }
                // Settings tables this version refuses (a key added later, a range tightened): the defaults.
                let mut dropped = Vec::new();
                known.solvers.settings.retain(|n, table| {
                    let keep = crate::solvers::entry(n).is_some_and(|e| (e.parse)(n, Some(table)).is_ok());
                    if !keep {
                        dropped.push(format!("solvers.{n}"));
                    }
                    keep
                });
                let mut scene = validate::build(known, path)?;
                let mut why = refusal.to_string();
                if !dropped.is_empty() {
                    why = format!(
                        "{why}; settings this version refuses were read as the defaults: {}",
                        dropped.join(", ")
                    );
                }
                scene.recorded = Some(why);
                Ok(scene)
            }
        }
    }

    /// Mark a scene read back from a result document as not runnable, saying why (keys it had that this version
    /// ignores); the reasons accumulate.
    pub(crate) fn mark_recorded(&mut self, why: String) {
        self.recorded = Some(match self.recorded.take() {
            Some(before) => format!("{before}; {why}"),
            None => why,
        });
    }

    /// `Err` naming why, for a scene read back from a result document that this version's checks refuse
    /// ([`Scene::from_record`]); `Ok` for every scene made by validation.
    ///
    /// # Errors
    /// [`Error::Invalid`] with the check that refused it.
    pub fn runnable(&self) -> Result<()> {
        match &self.recorded {
            None => Ok(()),
            Some(why) => Err(Error::Invalid {
                path: self.origin.clone(),
                field: "scene".into(),
                message: format!("recorded in a result document, refused by this version's checks: {why}"),
            }),
        }
    }

    /// Where the scene came from: its file, or `<scene>` for one built in code.
    pub fn origin(&self) -> &Path {
        &self.origin
    }

    /// The scene as parsed, with the defaults filled in.
    pub fn document(&self) -> &SceneDocument {
        &self.document
    }

    /// Short identifier, used in reports and output file names.
    pub fn name(&self) -> &str {
        &self.document.name
    }

    /// What the scene is and where its numbers come from.
    pub fn description(&self) -> &str {
        &self.document.description
    }

    /// The scene's units label (e.g. `"N, mm, MPa"`), if it declares one.
    pub fn units(&self) -> Option<&str> {
        self.document.units.as_deref()
    }

    /// The wheel's size and material.
    pub fn wheel(&self) -> &Wheel {
        &self.wheel
    }

    /// The wheel's radius R (length unit).
    pub fn radius(&self) -> f64 {
        self.wheel.radius
    }

    /// How the wheel is modelled.
    pub fn body(&self) -> &Body {
        &self.body
    }

    /// The width of the strip of half-spaces the contact is posed on (`[mesh] strip_width`, CONTACT's 2D model;
    /// length unit), `None` in plane strain.
    pub fn strip_width(&self) -> Option<f64> {
        match self.body {
            Body::HalfPlane { strip_width, .. } => strip_width,
            Body::Bem { .. } => None,
        }
    }

    /// The viscoelastic solids of the wheel and the counter-body (`[wheel] viscoelastic`, `[counter_body]
    /// viscoelastic`); `(None, None)` for elastic bodies.
    pub fn viscoelastic(&self) -> (Option<StandardLinearSolid>, Option<StandardLinearSolid>) {
        let wheel = match self.body {
            Body::HalfPlane { viscoelastic, .. } => viscoelastic,
            Body::Bem { .. } => None,
        };
        let counter = match self.counter_body {
            CounterBody::HalfPlane { viscoelastic, .. } => viscoelastic,
            CounterBody::Rigid | CounterBody::Disc { .. } | CounterBody::Bore { .. } => None,
        };
        (wheel, counter)
    }

    /// Whether a body is viscoelastic (then the scene rolls steadily at `[rolling] velocity`).
    pub fn is_viscoelastic(&self) -> bool {
        let (w, c) = self.viscoelastic();
        w.is_some() || c.is_some()
    }

    /// The steady-rolling memories ([`crate::viscoelastic::Memory`]) of the wheel and the counter-body, lengths in
    /// wheel diameters (the models' unit); `None` for an elastic body.
    pub fn viscoelastic_memories(&self) -> (Option<Memory>, Option<Memory>) {
        let (w, c) = self.viscoelastic();
        let (velocity, direction) = match self.rolling {
            Some(Rolling::Steady { direction, velocity }) => (velocity.unwrap_or(0.0), direction),
            _ => (0.0, 1),
        };
        let l0 = 2.0 * self.radius();
        let memory = |s: Option<StandardLinearSolid>| s.map(|s| s.memory(velocity, direction, l0));
        (memory(w), memory(c))
    }

    /// The wheel's model.
    pub fn model(&self) -> BodyModel {
        self.body.model()
    }

    /// The element family.
    pub fn element(&self) -> ElementKind {
        self.body.element()
    }

    /// The potential contact zone.
    pub fn zone(&self) -> &ContactZone {
        &self.zone
    }

    /// The BEM wheel's support, element family and other elements (`None` for the half-plane).
    pub fn bem_wheel(&self) -> Option<(Support, ElementKind, usize)> {
        match self.body {
            Body::Bem { support, element, other_elements } => Some((support, element, other_elements)),
            Body::HalfPlane { .. } => None,
        }
    }

    /// The counter-body.
    pub fn counter_body(&self) -> &CounterBody {
        &self.counter_body
    }

    /// The contact law (friction and coupling).
    pub fn law(&self) -> ContactLaw {
        self.law
    }

    /// Coulomb's μ (0: frictionless, the normal problem only); with a friction law of the slip velocity its static
    /// coefficient μ(0) ([`Scene::slip_velocity_friction`]).
    pub fn friction(&self) -> f64 {
        self.law.friction
    }

    /// The friction law of the slip velocity the scene calls for (`[contact] friction_law` that is not constant,
    /// with `[rolling] velocity`), or `None`: Coulomb (the default, and a constant law, which is Coulomb's
    /// `μ = kinetic` and solved as such). Derived from the document on each call; a Coulomb scene never builds one.
    pub fn slip_velocity_friction(&self) -> Option<crate::veldep::SceneFriction> {
        let t = self.document.contact.friction_law.filter(|t| !t.is_constant())?;
        let velocity = self.document.rolling.as_ref().and_then(|r| r.velocity)?;
        let memory = t.memory.map(|m| (m.distance, m.min_velocity));
        Some(crate::veldep::SceneFriction { law: t.law(), velocity, start: t.start, memory })
    }

    /// How the support is driven.
    pub fn loading(&self) -> &Loading {
        &self.loading
    }

    /// The one-step drive (`None` for a load path).
    pub fn drive(&self) -> Option<&Drive> {
        match &self.loading {
            Loading::Drive(d) => Some(d),
            Loading::Path(_) => None,
        }
    }

    /// The steps of a load path (empty for a one-step drive).
    pub fn steps(&self) -> &[PathStep] {
        match &self.loading {
            Loading::Drive(_) => &[],
            Loading::Path(s) => s,
        }
    }

    /// Rolling, if the scene rolls.
    pub fn rolling(&self) -> Option<&Rolling> {
        self.rolling.as_ref()
    }

    /// The prescribed creepage ξ, if any (steady rolling at a given ξ, the seed's, or transient rolling).
    pub fn creepage(&self) -> Option<f64> {
        match (self.rolling?, &self.loading) {
            (Rolling::Steady { .. }, Loading::Drive(d)) => match d.tangential {
                Dof::Displacement(xi) => Some(xi),
                Dof::Load(_) => None,
            },
            (Rolling::Steady { .. }, Loading::Path(_)) => None,
            (Rolling::Seed { creepage, .. } | Rolling::Transient { creepage, .. }, _) => Some(creepage),
        }
    }

    /// The solvers to run and their settings.
    pub fn solvers(&self) -> &SolverSet {
        &self.solvers
    }

    /// What the scene expects of its runs (`[checks]`).
    pub fn expect(&self) -> &Expect {
        self.document.checks.as_ref().unwrap_or(&DEFAULT_EXPECT)
    }

    /// Whether the scene declares expectations of its own (a `[checks]` table): `rollbem run` then exits on a failed
    /// check ([`crate::exit`]).
    pub fn declares_checks(&self) -> bool {
        self.document.checks.is_some()
    }

    /// The subsurface stress grid, when the scene asks for stresses.
    pub fn stresses(&self) -> Option<&StressSpec> {
        self.document.stresses.as_ref()
    }

    /// The effective radius R* of the contact, 1/R* = 1/R + 1/R₂: the wheel's radius on a flat, R R₂/(R + R₂) on a
    /// counter-disc, R R_b/(R_b − R) in a bore (∞ at zero clearance): the radius of Hertz's and Carter's theories.
    pub fn contact_radius(&self) -> f64 {
        let r = self.wheel.radius;
        match self.counter_body {
            CounterBody::Disc { radius, .. } => r * radius / (r + radius),
            CounterBody::Bore { radius, .. } => r * radius / (radius - r),
            _ => r,
        }
    }

    /// The plane-strain contact modulus of the pair, E* ([`crate::material::contact_modulus`]).
    pub fn contact_modulus(&self) -> f64 {
        crate::material::contact_modulus(&self.wheel.material, &self.counter_material())
    }

    /// Dundurs' β of the pair ([`crate::material::dundurs_beta`]; a rigid counter-body has G₂ → ∞).
    pub fn dundurs_beta(&self) -> f64 {
        crate::material::dundurs_beta(&self.wheel.material, &self.counter_material())
    }

    /// The counter-body's material (a rigid flat is [`Material::rigid`]).
    fn counter_material(&self) -> Material {
        self.counter_body.material().copied().unwrap_or_else(Material::rigid)
    }
}

/// Two scenes are equal when their documents are (wherever they came from).
impl PartialEq for Scene {
    fn eq(&self, other: &Scene) -> bool {
        self.document == other.document
    }
}

impl Serialize for Scene {
    fn serialize<S: serde::Serializer>(&self, s: S) -> std::result::Result<S::Ok, S::Error> {
        self.document.serialize(s)
    }
}

impl<'de> Deserialize<'de> for Scene {
    /// A scene deserialises only if it validates (the error says which key is wrong).
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> std::result::Result<Self, D::Error> {
        let document = SceneDocument::deserialize(d)?;
        Scene::from_document(document, &Scene::code_path()).map_err(serde::de::Error::custom)
    }
}

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
    unique_output_names(scenes.into_iter().map(|(p, s)| (p, s.name())))
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
    /// The status expected of `solver`.
    pub fn status_for(&self, solver: SolverId) -> Status {
        self.solver_status.get(&solver).copied().unwrap_or(self.status)
    }
}
