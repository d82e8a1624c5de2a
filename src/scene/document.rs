//! The scene file as written: the TOML document's tables, every optional key an `Option` (what deserialises).
//! [`crate::scene::Scene`] is the validated form; edit a scene through this document
//! ([`crate::scene::Scene::edit`]) and it is validated again.

use super::{BodyModel, ElementKind, Expect, Profile, RollingMode, SolverSet, StressSpec, Support};
use crate::formulation::{Dof, Drive};
use crate::solvers::{SettingsError, SolverId, SolverSettings};
use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;

/// A whole scene file, as written (before validation: every optional key an `Option`).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SceneDocument {
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
    pub wheel: WheelTable,
    /// Boundary-element mesh of the wheel (or the contact grid of the half-plane).
    pub mesh: MeshTable,
    /// The counter-body: a rigid flat (default) or an elastic half-plane.
    #[serde(default)]
    pub counter_body: CounterBodyTable,
    /// Contact law.
    #[serde(default)]
    pub contact: ContactTable,
    /// How the support is driven: a displacement or a load for each rigid degree of freedom (one step from rest).
    /// Absent when the scene gives a load path (`[[steps]]`).
    #[serde(default)]
    pub drive: DriveTable,
    /// A load path: quasi-static steps with memory (`crate::pipeline::path`), instead of `[drive]`.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub steps: Vec<StepTable>,
    /// Optional rolling: steady-state rolling, or the seed's slip velocity after a static solve.
    #[serde(default)]
    pub rolling: Option<RollingTable>,
    /// Which solvers to run.
    #[serde(default)]
    pub solvers: SolversTable,
    /// What the scene expects of its runs.
    /// Absent: the defaults of [`Expect`], and `rollbem run` does not exit on a failed check.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub checks: Option<Expect>,
    /// Subsurface stresses on a grid below the contact ([`crate::stresses`]); computed only when given.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub stresses: Option<StressSpec>,
}
/// `[wheel]`: the elastic disk (or annulus) in plane strain, modelled either as itself (BEM, the finite body) or as an
/// elastic half-plane with the wheel's initial gap (the half-space model of Hertz, Cattaneo, Carter and Spence).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct WheelTable {
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
    /// Half-plane only, steady rolling only: the wheel as a viscoelastic standard linear solid
    /// ([`crate::viscoelastic`]) whose glassy modulus is `youngs_modulus`. Absent (the default): elastic.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub viscoelastic: Option<ViscoelasticTable>,
}

/// `viscoelastic = { ... }` of `[wheel]` or `[counter_body]`: a standard linear solid ([`crate::viscoelastic`]) in
/// exactly one of its two documented parameter sets: CONTACT's `compliance_ratio` (FG = (E_g − E_r)/E_r ≥ 0) and
/// `creep_time` (TC = τ_C ≥ 0, s), or the stress-relaxation form `relaxed_modulus` (E_r, 0 < E_r ≤ the body's
/// `youngs_modulus` = E_g) and `relaxation_time` (τ_E ≥ 0, s).
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ViscoelasticTable {
    /// FG = C_v/C_g = (E_g − E_r)/E_r ≥ 0 (dimensionless).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub compliance_ratio: Option<f64>,
    /// TC = τ_C ≥ 0, the creep relaxation time (s).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub creep_time: Option<f64>,
    /// E_r, the relaxed (rubbery) Young's modulus (stress unit).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub relaxed_modulus: Option<f64>,
    /// τ_E ≥ 0, the stress relaxation time (s).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub relaxation_time: Option<f64>,
}

/// The counter-body the wheel meets.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case", deny_unknown_fields)]
#[non_exhaustive]
pub enum CounterBodyTable {
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
        /// Steady rolling only: the counter-body as a viscoelastic standard linear solid (as `[wheel]
        /// viscoelastic`; its glassy modulus is this `youngs_modulus`).
        #[serde(default, skip_serializing_if = "Option::is_none")]
        viscoelastic: Option<ViscoelasticTable>,
    },
    /// A finite elastic disc below the wheel (the twin-disc rig), a BEM body like the wheel: BEM wheel only.
    Disc {
        /// Its radius R₂ (length unit).
        radius: f64,
        /// Its Young's modulus (stress unit).
        youngs_modulus: f64,
        /// Its Poisson's ratio, 0 ≤ ν ≤ 0.5.
        poisson_ratio: f64,
        /// How it is held: `{ kind = "hub", radius }` or `{ kind = "top_arc", angle_deg }` (the arc centred
        /// opposite the contact).
        support: Support,
        /// Elements on its circle beyond the contact zone (≥ 4).
        other_elements: usize,
    },
    /// A plate with a circular bore around the wheel (the pin in a bore), its outer circle clamped: BEM wheel only.
    Bore {
        /// The bore's radius R_b ≥ the wheel's radius (clearance R_b − R, zero allowed).
        radius: f64,
        /// The plate's outer radius (> R_b).
        outer_radius: f64,
        /// Its Young's modulus (stress unit).
        youngs_modulus: f64,
        /// Its Poisson's ratio, 0 ≤ ν ≤ 0.5.
        poisson_ratio: f64,
        /// Elements on the bore beyond the contact zone (≥ 4).
        other_elements: usize,
        /// Elements on the outer circle (≥ 8).
        outer_elements: usize,
    },
}

/// `[mesh]`: the boundary-element mesh of the wheel, or the contact grid of the half-plane. The potential contact
/// zone is given by exactly one of `contact_arc_deg` (elements uniform in angle on the arc), `contact_half_width`
/// (elements uniform in x on −w ≤ x ≤ w, so that a grid of N elements of size dx is written directly) and, on the
/// half-plane model only, `contact_x = [x_min, x_max]` (elements uniform in x on a span the user places, e.g. a
/// CONTACT grid that is not centred on x = 0); both models put their collocation points at the same x for the same
/// keys.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct MeshTable {
    /// Element family.
    pub element: ElementKind,
    /// Angular extent (degrees) of the potential contact zone, centred on the bottom point, in (0, 180).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub contact_arc_deg: Option<f64>,
    /// Half-width (length unit) of the potential contact zone, 0 < w < R: the zone is −w ≤ x ≤ w.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub contact_half_width: Option<f64>,
    /// Half-plane model only: the potential contact zone x_min ≤ x ≤ x_max (length unit, −R < x_min < x_max < R),
    /// elements uniform in x. x is measured from the point of first contact (the profile's lowest point).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub contact_x: Option<[f64; 2]>,
    /// Number of elements on the potential contact zone, ≥ 1.
    pub contact_elements: usize,
    /// Half-plane model only: the contact as a strip of this width (length unit, positive) across the rolling
    /// direction on two elastic half-SPACES, one row of rectangular elements (element length × strip_width), the
    /// displacements at the strip's centre line: CONTACT's model of its 2D cases (its `MY = 1`, `DY`), so that a
    /// CONTACT input is posed exactly. Without it (the default) the bodies are in plane strain. Loads stay per unit
    /// of width (a CONTACT force FN is FN/DY here). The displacements of a strip vanish far away, so there is no
    /// datum (`datum_depth` is refused with it), and its interior fields are 3D (`[stresses]` is refused).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub strip_width: Option<f64>,
    /// BEM only: number of elements on the rest of the outer boundary (graded from the contact size), ≥ 4. The hub
    /// circle gets elements in proportion to its circumference.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub other_elements: Option<usize>,
}

/// Contact law between wheel and flat.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ContactTable {
    /// Coulomb friction coefficient μ ≥ 0; 0 means frictionless (the normal problem only).
    #[serde(default)]
    pub friction: f64,
    /// Keep the normal–tangential cross flexibilities F_NT, F_TN (true) or drop them (false).
    #[serde(default = "default_true")]
    pub coupling: bool,
    /// A friction law of the slip velocity ([`crate::veldep`], CONTACT's L = 2, 3, 4) instead of Coulomb's constant
    /// `friction`, which is then the law's static coefficient μ(0) (leave it out, or give that value). Absent (the
    /// default): Coulomb.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub friction_law: Option<FrictionLawTable>,
}

/// `[contact.friction_law]` (or `friction_law = { ... }` in `[contact]`): CONTACT's falling friction laws of the
/// absolute slip velocity `s_a` (length/s; [`crate::veldep`] has the formulas). Each term is `[coefficient, s_h]`:
/// the coefficient ≥ 0 (dimensionless) and, when it is not 0, its half-value slip velocity `s_h > 0` (length/s,
/// CONTACT's SABSH1, SABSH2). A law whose terms are both 0 is Coulomb's `μ = kinetic` and is solved as Coulomb.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct FrictionLawTable {
    /// `linear` (L = 2), `rational` (L = 3) or `exponential` (L = 4).
    pub kind: FrictionLawKind,
    /// The kinetic coefficient μ_kin = μ(∞) > 0 (FKIN).
    pub kinetic: f64,
    /// The first term `[coefficient, s_h]` (FLIN1/FRAT1/FEXP1, SABSH1).
    pub first: [f64; 2],
    /// The second term (FLIN2/FRAT2/FEXP2, SABSH2); default `[0, 0]` (off).
    #[serde(default)]
    pub second: [f64; 2],
    /// Where the iteration starts whose solution the runs carry: `below` (every node sticking, CONTACT's INISLP > 0;
    /// the default) or `above` (every node sliding at μ_kin, INISLP < 0). Both starts are always solved and
    /// reported ([`crate::veldep::BranchReport`]).
    #[serde(default)]
    pub start: crate::veldep::Start,
    /// CONTACT's friction memory (`{ distance, min_velocity }`: MEMDST d_c > 0 in length, MEM_S0 s_0 ≥ 0 in
    /// length/s; [`crate::veldep::Memory`]); absent: none (the coefficient follows the slip velocity at once).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub memory: Option<FrictionMemoryTable>,
}

/// `memory = { distance, min_velocity }` of `[contact.friction_law]`: CONTACT's MEMDST and MEM_S0.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct FrictionMemoryTable {
    /// d_c, the memory distance (length, > 0).
    pub distance: f64,
    /// s_0, the least slip velocity of the relaxation (length/s, ≥ 0).
    pub min_velocity: f64,
}

/// The family of a [`FrictionLawTable`].
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum FrictionLawKind {
    /// `μ_kin + c1 max(0, 1 − s/(2 s1)) + c2 max(0, 1 − s/(2 s2))`.
    Linear,
    /// `μ_kin + c1/(1 + s/s1) + c2/(1 + (s/s2)²)`.
    Rational,
    /// `μ_kin + c1 exp(−ln2 s/s1) + c2 exp(−ln2 s/s2)`.
    Exponential,
}

impl FrictionLawTable {
    /// The law it writes ([`crate::veldep::FrictionLaw`]; not checked).
    pub fn law(&self) -> crate::veldep::FrictionLaw {
        use crate::veldep::FrictionLaw as L;
        let (kinetic, first, second) = (self.kinetic, (self.first[0], self.first[1]), (self.second[0], self.second[1]));
        match self.kind {
            FrictionLawKind::Linear => L::Linear { kinetic, first, second },
            FrictionLawKind::Rational => L::Rational { kinetic, first, second },
            FrictionLawKind::Exponential => L::Exponential { kinetic, first, second },
        }
    }

    /// Whether the law is a constant (both terms' coefficients 0): Coulomb's `μ = kinetic` (memory then changes
    /// nothing: the coefficient relaxes towards the constant it starts from).
    pub fn is_constant(&self) -> bool {
        self.first[0] == 0.0 && self.second[0] == 0.0
    }
}

fn default_true() -> bool {
    true
}

impl Default for ContactTable {
    fn default() -> Self {
        ContactTable { friction: 0.0, coupling: true, friction_law: None }
    }
}

/// The drive of the support: per rigid degree of freedom, a displacement or a load (not both).
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct DriveTable {
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

impl DriveTable {
    /// The drive of the three rigid degrees of freedom (user's units; an absent tangential or rotational DOF is held
    /// at zero displacement).
    pub fn dofs(&self) -> Drive {
        Drive { normal: self.normal(), tangential: self.tangential(), rotational: self.rotational() }
    }

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
pub struct StepTable {
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

impl StepTable {
    /// The step's end drive as a `[drive]` table.
    pub fn drive(&self) -> DriveTable {
        DriveTable {
            normal_approach: self.normal_approach,
            normal_load: self.normal_load,
            tangential_shift: self.tangential_shift,
            tangential_load: self.tangential_load,
            rotation: self.rotation,
            moment: self.moment,
        }
    }
}

/// `[rolling]` (seed eqs. 6–12): either the steady-rolling problem with the slip velocity as the unknown of Coulomb's
/// law (`mode = "steady"`, [`crate::formulation::slip`]), or the seed's formulation: a static solve, then the slip
/// velocity of eq. 12 computed from it (`mode = "seed"`).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RollingTable {
    /// Which formulation (required, so that nobody gets the seed's post-processing by surprise).
    pub mode: RollingMode,
    /// Creepage ξ = (V_A − V_B)/|V|, the rigid slip velocity of the wheel's surface relative to the flat over the
    /// rolling speed (dimensionless; ξ > 0 braking). Steady: prescribe it, or give `[drive] tangential_load`
    /// instead and it is computed. Seed: required.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub creepage: Option<f64>,
    /// The rolling direction: +1 towards +x (the leading edge is at +x), −1 towards −x.
    pub direction: i32,
    /// The rolling speed V (length unit per second, > 0): steady rolling of a viscoelastic body, whose relaxation
    /// distance is V·τ_C, or with a falling friction law (`[contact] friction_law`), whose absolute slip velocity
    /// is V·|s|. Required there, refused without either.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub velocity: Option<f64>,
}

/// `[solvers]`: which solvers to run (`use = [...]`, registry names or `"all"`), with their settings tables
/// (`[solvers.NAME]`, as written; validated into [`crate::solvers::SolverSettings`] when the scene is read).
#[derive(Debug, Clone, PartialEq)]
pub struct SolversTable {
    /// Solver names; `["all"]` runs every solver of the registry's `all` set that applies to the scene.
    pub use_: Vec<String>,
    /// Settings table per registered solver name.
    pub settings: BTreeMap<String, toml::Value>,
}

impl Default for SolversTable {
    fn default() -> Self {
        SolversTable { use_: vec!["all".into()], settings: BTreeMap::new() }
    }
}

impl SolversTable {
    /// Solvers by name (`"all"` included).
    pub fn using(names: &[&str]) -> SolversTable {
        SolversTable { use_: names.iter().map(|s| s.to_string()).collect(), ..SolversTable::default() }
    }

    /// Set one setting of one solver (e.g. `set("pgs", "max_outer", 1)`, or a dotted key into a nested table:
    /// `set("normtang_qp", "qp.max_iter", 50)`); checked when the scene is validated.
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

    /// The typed set: the names checked, every settings table parsed and validated (no solver is built).
    pub fn typed(&self) -> std::result::Result<SolverSet, SettingsError> {
        if self.use_.is_empty() {
            return Err(SettingsError {
                field: "solvers.use".into(),
                message: "must name at least one solver (or \"all\")".into(),
                unknown: false,
            });
        }
        let mut named = Vec::new();
        let mut all = false;
        for name in &self.use_ {
            match (name.as_str(), SolverId::from_name(name)) {
                ("all", _) => all = true,
                (_, Some(id)) => {
                    if !named.contains(&id) {
                        named.push(id)
                    }
                }
                (_, None) => {
                    return Err(SettingsError {
                        field: "solvers.use".into(),
                        message: format!("unknown solver `{name}` (expected one of: all, {})", crate::solvers::names()),
                        unknown: true,
                    })
                }
            }
        }
        Ok(SolverSet { all, named, settings: SolverSettings::from_tables(&self.settings)? })
    }
}

impl Serialize for SolversTable {
    fn serialize<S: serde::Serializer>(&self, s: S) -> std::result::Result<S::Ok, S::Error> {
        use serde::ser::SerializeMap;
        let mut m = s.serialize_map(Some(1 + self.settings.len()))?;
        m.serialize_entry("use", &self.use_)?;
        // Registry order first (as reported), then anything else.
        for e in crate::solvers::registry() {
            if let Some(v) = self.settings.get(e.name()) {
                m.serialize_entry(e.name(), v)?;
            }
        }
        for (k, v) in self.settings.iter().filter(|(k, _)| crate::solvers::entry(k).is_none()) {
            m.serialize_entry(k, v)?;
        }
        m.end()
    }
}

impl<'de> Deserialize<'de> for SolversTable {
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> std::result::Result<Self, D::Error> {
        #[derive(Deserialize)]
        struct Raw {
            #[serde(rename = "use", default = "default_use")]
            use_: Vec<String>,
            #[serde(flatten)]
            settings: BTreeMap<String, toml::Value>,
        }
        let raw = Raw::deserialize(d)?;
        Ok(SolversTable { use_: raw.use_, settings: raw.settings })
    }
}

fn default_use() -> Vec<String> {
    vec!["all".into()]
}
