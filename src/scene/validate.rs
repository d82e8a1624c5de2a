//! Validation: a [`SceneDocument`] checked range by range and turned into a [`Scene`] whose parts cannot hold an
//! invalid value. Every error names the file and the dotted key.

use super::document::{CounterBodyTable, DriveTable, MeshTable, SceneDocument};
use super::{
    safe_name, Body, BodyModel, ContactZone, CounterBody, ElementKind, Loading, Material, PathStep, Profile, Rolling,
    RollingMode, Scene, StressQuantity, Support, Wheel, ZoneExtent, MAX_HALF_PLANE_ELEMENTS, MAX_NODES,
    MAX_PATH_RESULT_BYTES, MAX_PATH_SUBSTEPS, MAX_STRESS_POINTS, MIN_CONTACT_ELEMENT_ANGLE, PATH_BYTES_PER_NODE,
};
use crate::error::{Error, Result};
use crate::formulation::{ContactLaw, Dof, ProblemKind};
use crate::solvers::Facts;
use std::path::Path;

/// Validate a document and build the typed scene.
pub(super) fn validate(document: SceneDocument, path: &Path) -> Result<Scene> {
    document.validate(path)?;
    solvers_apply(build(document, path)?)
}

/// Build the typed scene of a document without its range checks (a scene recorded in a result document by a version
/// whose checks it passed: [`Scene::from_record`]); only what the typed parts need is required.
pub(super) fn build(mut document: SceneDocument, path: &Path) -> Result<Scene> {
    let solvers = document.solvers.typed().map_err(|e| e.into_error(path))?;
    super::friction::fill_static_coefficient(&mut document);
    // The scene as parsed: every solver's settings with the defaults filled in.
    document.solvers.settings = solvers.settings.tables();
    let d = &document;
    let w = &d.wheel;
    let wheel = Wheel {
        radius: w.radius,
        material: Material { youngs_modulus: w.youngs_modulus, poisson_ratio: w.poisson_ratio },
    };
    let body = match (w.model, w.support, d.mesh.other_elements) {
        (BodyModel::Bem, Some(support), Some(other_elements)) => {
            Body::Bem { support, element: d.mesh.element, other_elements }
        }
        (BodyModel::HalfPlane, _, _) => Body::HalfPlane {
            datum_depth: w.datum_depth.unwrap_or(w.radius),
            profile: w.profile.unwrap_or(Profile::Circle),
            strip_width: d.mesh.strip_width,
            viscoelastic: super::visco::solid(w.viscoelastic, w.youngs_modulus),
        },
        (BodyModel::Bem, None, _) => {
            return Err(Error::Invalid {
                path: path.to_path_buf(),
                field: "wheel.support".into(),
                message: "a BEM wheel needs a support".into(),
            })
        }
        (BodyModel::Bem, _, None) => {
            return Err(Error::Invalid {
                path: path.to_path_buf(),
                field: "mesh.other_elements".into(),
                message: "a BEM wheel needs other_elements".into(),
            })
        }
    };
    let counter_body = match d.counter_body {
        CounterBodyTable::Rigid => CounterBody::Rigid,
        CounterBodyTable::HalfPlane { youngs_modulus, poisson_ratio, datum_depth, viscoelastic } => {
            CounterBody::HalfPlane {
                material: Material { youngs_modulus, poisson_ratio },
                datum_depth: datum_depth.unwrap_or(w.radius),
                viscoelastic: super::visco::solid(viscoelastic, youngs_modulus),
            }
        }
        CounterBodyTable::Disc { radius, youngs_modulus, poisson_ratio, support, other_elements } => {
            CounterBody::Disc { material: Material { youngs_modulus, poisson_ratio }, radius, support, other_elements }
        }
        CounterBodyTable::Bore {
            radius,
            outer_radius,
            youngs_modulus,
            poisson_ratio,
            other_elements,
            outer_elements,
        } => CounterBody::Bore {
            material: Material { youngs_modulus, poisson_ratio },
            radius,
            outer_radius,
            other_elements,
            outer_elements,
        },
    };
    let rolling = d.rolling.as_ref().map(|r| match r.mode {
        RollingMode::Steady => Rolling::Steady { direction: r.direction, velocity: r.velocity },
        RollingMode::Seed => Rolling::Seed { creepage: r.creepage.unwrap_or(0.0), direction: r.direction },
        RollingMode::Transient => Rolling::Transient { creepage: r.creepage.unwrap_or(0.0), direction: r.direction },
    });
    let loading = if d.steps.is_empty() {
        let mut drive = d.drive.dofs();
        if let (Some(Rolling::Steady { .. }), Some(xi)) = (rolling, d.rolling.as_ref().and_then(|r| r.creepage)) {
            drive.tangential = Dof::Displacement(xi);
        }
        Loading::Drive(drive)
    } else {
        Loading::Path(
            d.steps
                .iter()
                .map(|st| PathStep {
                    end: st.drive().dofs(),
                    substeps: st.substeps.unwrap_or(1),
                    roll: st.roll.unwrap_or(0.0),
                })
                .collect(),
        )
    };
    Ok(Scene {
        origin: path.to_path_buf(),
        wheel,
        body,
        zone: zone_of(&d.mesh),
        counter_body,
        law: ContactLaw { friction: d.contact.friction, coupling: d.contact.coupling },
        loading,
        rolling,
        solvers,
        document,
        recorded: None,
    })
}

/// What a valid scene's parts cannot pose together, refused when it is read rather than when it is run (issue 31):
/// a tangential load on a frictionless contact (the rule the problem is built with, [`ProblemKind::of`]), and a
/// solver named in `solvers.use` that cannot take the scene — its [`crate::solvers::Solver::admits`] of the scene's
/// facts ([`scene_facts`]), the one rule the run applies to each problem through `applies`: clarabel with friction
/// or a moment load, NORM-TANG with a moment load or at the sliding limit, normtang_qp in steady rolling with
/// friction. Errors name the key and why. `all` is not checked: it runs the solvers that apply.
fn solvers_apply(scene: Scene) -> Result<Scene> {
    let invalid =
        |field: String, message: String| Error::Invalid { path: scene.origin().to_path_buf(), field, message };
    let mu = scene.law().friction;
    let drives: Vec<(String, &crate::formulation::Drive)> = match scene.loading() {
        Loading::Drive(d) => vec![("drive.tangential_load".into(), d)],
        Loading::Path(steps) => {
            steps.iter().enumerate().map(|(i, s)| (format!("steps[{i}].tangential_load"), &s.end)).collect()
        }
    };
    for (key, drive) in drives {
        if let Err(crate::formulation::DriveIssue::TangentialLoadWithoutFriction(q)) = ProblemKind::of(mu, drive) {
            let why = format!("{q} on a frictionless contact (contact.friction = 0) has no static solution");
            return Err(invalid(key, format!("{why}: use a zero tangential load or friction > 0")));
        }
    }
    let facts = scene_facts(&scene);
    let set = scene.solvers();
    for id in &set.named {
        if let Some(Err(why)) = id.build(&set.settings).map(|s| s.admits(&facts)) {
            return Err(invalid("solvers.use".into(), format!("{} does not apply to this scene: {why}", id.name())));
        }
    }
    Ok(scene)
}

/// What a scene says of the problems it poses ([`crate::solvers::Facts`]): friction, a moment load at any step, steady
/// rolling, and the sliding limit of a one-step drive (by the rule the problem is built with,
/// [`ProblemKind::of`], on the drive in the scene's units: it depends on ratios of loads only).
fn scene_facts(scene: &Scene) -> Facts {
    let mu = scene.law().friction;
    let drives: Vec<&crate::formulation::Drive> = match scene.loading() {
        Loading::Drive(d) => vec![d],
        Loading::Path(steps) => steps.iter().map(|s| &s.end).collect(),
    };
    Facts {
        friction: mu > 0.0,
        moment_load: drives.iter().any(|d| matches!(d.rotational, Dof::Load(_))),
        steady_rolling: matches!(scene.rolling(), Some(Rolling::Steady { .. })),
        sliding_limit: match scene.loading() {
            Loading::Drive(d) => matches!(ProblemKind::of(mu, d), Ok(ProblemKind::SlidingLimit { .. })),
            Loading::Path(_) => false,
        },
    }
}

/// The contact zone of a mesh table (a validated one has exactly one of the two extents).
fn zone_of(m: &MeshTable) -> ContactZone {
    let extent = match (m.contact_half_width, m.contact_x, m.contact_arc_deg) {
        (Some(half_width), _, _) => ZoneExtent::HalfWidth { half_width },
        (None, Some([x_min, x_max]), _) => ZoneExtent::Span { x_min, x_max },
        (None, None, degrees) => ZoneExtent::Arc { degrees: degrees.unwrap_or(0.0) },
    };
    ContactZone { extent, elements: m.contact_elements }
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

    /// A length `v` (already checked finite and > 0) that the models divide by the wheel's diameter `2R` (their
    /// length unit): the ratio must be a finite, normal double, or the kernels would see 0 or ∞ for it.
    fn scaled_length(&self, field: &str, v: f64, radius: f64) -> Result<()> {
        let ratio = v / (2.0 * radius);
        if !ratio.is_normal() {
            return Err(self.bad(
                field,
                format!(
                    "{v:e} is {ratio:.1e} wheel diameters (2 × wheel.radius = {:e}); rollbem computes in units of \
                     the diameter, and this ratio is not a normal double (it would be 0 or ∞ in the kernels)",
                    2.0 * radius
                ),
            ));
        }
        Ok(())
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
impl SceneDocument {
    /// Check every value's range; the error names the dotted key.
    fn validate(&self, path: &Path) -> Result<()> {
        let c = Checker { path };
        if let Err(why) = safe_name(&self.name) {
            return Err(c.bad("name", why));
        }
        self.validate_wheel(&c)?;
        self.validate_mesh(&c)?;
        self.validate_counter_body(&c)?;
        self.validate_viscoelastic(path)?;
        self.validate_friction_law(path)?;
        let mu = self.contact.friction;
        if !mu.is_finite() || mu < 0.0 {
            return Err(c.bad("contact.friction", format!("must be a finite number ≥ 0 (got {mu})")));
        }
        self.validate_drive(&c)?;
        self.validate_stresses(&c)?;
        let ck = self.checks.clone().unwrap_or_default();
        if let Some(id) = ck.solver_status.keys().find(|id| id.entry().is_none()) {
            return Err(c.bad(
                "checks.solver_status",
                format!("unknown solver `{id}` (solvers are: {})", crate::solvers::names()),
            ));
        }
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
        if !(2.0 * w.radius).is_finite() {
            return Err(c.bad(
                "wheel.radius",
                format!(
                    "{:e} is too large: rollbem computes in units of the wheel's diameter 2R, which must be a finite \
                     double (R ≤ {:.1e})",
                    w.radius,
                    f64::MAX / 2.0
                ),
            ));
        }
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
                    c.scaled_length("wheel.datum_depth", d, w.radius)?;
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
                c.scaled_length("wheel.support.radius", radius, w.radius)?;
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
        self.validate_finite_counter(c)?;
        if let CounterBodyTable::HalfPlane { youngs_modulus, poisson_ratio, datum_depth, .. } = self.counter_body {
            c.positive("counter_body.youngs_modulus", youngs_modulus)?;
            c.poisson("counter_body.poisson_ratio", poisson_ratio)?;
            if let Some(d) = datum_depth {
                c.positive("counter_body.datum_depth", d)?;
                c.scaled_length("counter_body.datum_depth", d, self.wheel.radius)?;
            }
            let ratio = youngs_modulus / self.wheel.youngs_modulus;
            if !ratio.is_normal() {
                return Err(c.bad(
                    "counter_body.youngs_modulus",
                    format!(
                        "{youngs_modulus:e} is {ratio:.1e} × wheel.youngs_modulus; rollbem computes in units of the \
                         wheel's modulus, and this ratio is not a normal double (it would be 0 or ∞ in the kernels)"
                    ),
                ));
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

    /// A second finite body (`kind = "disc"` or `"bore"`, [`crate::source::two_body`]): a BEM wheel's, its values in
    /// range, its zone on the wheel's rays, no interior stresses in a bore, no rolling in a bore.
    fn validate_finite_counter(&self, c: &Checker) -> Result<()> {
        let (radius, e, nu, other, kind) = match self.counter_body {
            CounterBodyTable::Disc { radius, youngs_modulus, poisson_ratio, other_elements, .. } => {
                (radius, youngs_modulus, poisson_ratio, other_elements, "disc")
            }
            CounterBodyTable::Bore { radius, youngs_modulus, poisson_ratio, other_elements, .. } => {
                (radius, youngs_modulus, poisson_ratio, other_elements, "bore")
            }
            _ => return Ok(()),
        };
        let r = self.wheel.radius;
        if self.wheel.model != BodyModel::Bem {
            return Err(c.bad(
                "counter_body.kind",
                format!(
                    "a {kind} is a finite BEM body: it meets a BEM wheel (wheel.model = \"bem\"), not a half-plane"
                ),
            ));
        }
        c.positive("counter_body.radius", radius)?;
        c.scaled_length("counter_body.radius", radius, r)?;
        c.positive("counter_body.youngs_modulus", e)?;
        c.poisson("counter_body.poisson_ratio", nu)?;
        if !(e / self.wheel.youngs_modulus).is_normal() {
            return Err(c.bad(
                "counter_body.youngs_modulus",
                format!("{e:e}: its ratio to the wheel's is not a normal double"),
            ));
        }
        if other < 4 {
            return Err(c.bad("counter_body.other_elements", format!("must be at least 4, got {other}")));
        }
        let per = if self.mesh.element == ElementKind::Quadratic { 3 } else { 1 };
        if (self.mesh.contact_elements.saturating_add(other)).saturating_mul(per) > MAX_NODES {
            return Err(
                c.bad("counter_body.other_elements", format!("more than the {MAX_NODES} nodes a BEM body may have"))
            );
        }
        if self.stresses.is_some() && kind == "bore" {
            return Err(c.bad(
                "stresses",
                "interior stresses are computed for a counter-disc, not for a bore (its plate's field is not \
                 implemented)"
                    .to_string(),
            ));
        }
        self.validate_counter_geometry(c, radius, nu)
    }

    /// The second body's geometry against the wheel's zone, and its support ([`Self::validate_finite_counter`]).
    fn validate_counter_geometry(&self, c: &Checker, radius: f64, nu: f64) -> Result<()> {
        let r = self.wheel.radius;
        // The zone's half-angle on the wheel.
        let half = match (self.mesh.contact_arc_deg, self.mesh.contact_half_width) {
            (Some(deg), _) => 0.5 * deg.to_radians(),
            (None, Some(w)) => (w / r).clamp(-1.0, 1.0).asin(),
            _ => 0.0,
        };
        match self.counter_body {
            CounterBodyTable::Disc { support, .. } => {
                if half.sin() >= 0.99 * radius / (r + radius) {
                    return Err(c.bad(
                        "mesh.contact_arc_deg",
                        format!(
                            "the wheel's contact zone reaches beyond the counter-disc of radius {radius}: narrow it"
                        ),
                    ));
                }
                match support {
                    Support::Hub { radius: rh } if !(rh > 0.0 && rh < radius) => Err(c.bad(
                        "counter_body.support.radius",
                        format!("a hub's radius must lie in (0, counter_body.radius = {radius}), got {rh}"),
                    )),
                    Support::Hub { .. } if nu == 0.5 => Err(c.bad(
                        "counter_body.poisson_ratio",
                        "ν = 0.5 with a hub support is degenerate (the hub pressure is undetermined)".into(),
                    )),
                    Support::TopArc { angle_deg } if !(angle_deg > 0.0 && angle_deg < 180.0) => Err(c.bad(
                        "counter_body.support.angle_deg",
                        format!("a clamped arc must lie in (0, 180) degrees, got {angle_deg}"),
                    )),
                    _ => Ok(()),
                }
            }
            CounterBodyTable::Bore { outer_radius, outer_elements, .. } => {
                if radius < r {
                    return Err(c.bad(
                        "counter_body.radius",
                        format!("a bore's radius must be at least the wheel's (the pin's) {r}, got {radius}"),
                    ));
                }
                if !(outer_radius > radius && outer_radius.is_finite()) {
                    return Err(c.bad(
                        "counter_body.outer_radius",
                        format!("must be finite and beyond the bore's radius {radius}, got {outer_radius}"),
                    ));
                }
                c.scaled_length("counter_body.outer_radius", outer_radius, r)?;
                if outer_elements < 8 {
                    return Err(
                        c.bad("counter_body.outer_elements", format!("must be at least 8, got {outer_elements}"))
                    );
                }
                if nu == 0.5 {
                    return Err(c.bad(
                        "counter_body.poisson_ratio",
                        "ν = 0.5 with the plate's outer circle clamped is degenerate (its pressure is undetermined)"
                            .into(),
                    ));
                }
                if self.rolling.is_some() {
                    return Err(c.bad("rolling", "rolling in a bore is not modelled (a twin disc rolls)".into()));
                }
                Ok(())
            }
            _ => Ok(()),
        }
    }

    /// The candidate zone: exactly one of `contact_arc_deg`, `contact_half_width`, `contact_x`, in range.
    fn validate_zone(&self, c: &Checker) -> Result<()> {
        let w = &self.wheel;
        let m = &self.mesh;
        let given: Vec<&str> = [
            ("contact_arc_deg", m.contact_arc_deg.is_some()),
            ("contact_half_width", m.contact_half_width.is_some()),
            ("contact_x", m.contact_x.is_some()),
        ]
        .iter()
        .filter(|(_, g)| *g)
        .map(|(k, _)| *k)
        .collect();
        match given.as_slice() {
            [] => {
                return Err(c.bad(
                    "mesh",
                    "give `contact_arc_deg`, `contact_half_width` or `contact_x` (the potential contact zone)".into(),
                ))
            }
            [_] => {}
            [first, ..] => {
                return Err(c.bad(
                    &format!("mesh.{first}"),
                    format!("give one of `mesh.{}`, not several", given.join("`, `mesh.")),
                ))
            }
        }
        if let Some(a) = m.contact_arc_deg {
            if !a.is_finite() || a <= 0.0 || a >= 180.0 {
                return Err(c.bad("mesh.contact_arc_deg", format!("must lie in (0, 180) degrees (got {a})")));
            }
        }
        if let Some(hw) = m.contact_half_width {
            if !hw.is_finite() || hw <= 0.0 || hw >= w.radius {
                return Err(c.bad(
                    "mesh.contact_half_width",
                    format!("must lie in (0, wheel.radius = {}) (got {hw})", w.radius),
                ));
            }
        }
        if let Some([x_min, x_max]) = m.contact_x {
            let r = w.radius;
            if !(x_min.is_finite() && x_max.is_finite() && -r < x_min && x_min < x_max && x_max < r) {
                return Err(c.bad(
                    "mesh.contact_x",
                    format!("must be [x_min, x_max] with −R < x_min < x_max < R = {r} (got [{x_min}, {x_max}])"),
                ));
            }
            if w.model != BodyModel::HalfPlane {
                return Err(c.bad(
                    "mesh.contact_x",
                    "a zone placed off-centre is for the half-plane model (`wheel.model = \"half_plane\"`); the BEM \
                     wheel's zone is centred: use `contact_half_width` or `contact_arc_deg`"
                        .into(),
                ));
            }
        }
        Ok(())
    }

    /// `[mesh] strip_width` (half-plane model): positive and finite; no datum and no interior stresses with it.
    fn validate_strip(&self, c: &Checker) -> Result<()> {
        let Some(width) = self.mesh.strip_width else { return Ok(()) };
        c.positive("mesh.strip_width", width)?;
        let dx = zone_of(&self.mesh).element_length(self.wheel.radius);
        let ratio = width / dx;
        if !(1e-8..=1e12).contains(&ratio) || !(width / (2.0 * self.wheel.radius)).is_normal() {
            return Err(c.bad(
                "mesh.strip_width",
                format!(
                    "{width:e} is {ratio:.1e} element lengths ({dx:e}); rollbem takes 1e-8 to 1e12 of them (wider is \
                     plane strain to round-off: leave strip_width out)"
                ),
            ));
        }
        let no_datum = "means nothing on a strip of half-spaces (`mesh.strip_width`): its displacements vanish far \
                        away, there is no datum: remove it";
        if self.wheel.datum_depth.is_some() {
            return Err(c.bad("wheel.datum_depth", no_datum.into()));
        }
        if let CounterBodyTable::HalfPlane { datum_depth: Some(_), .. } = self.counter_body {
            return Err(c.bad("counter_body.datum_depth", no_datum.into()));
        }
        if self.stresses.is_some() {
            return Err(c.bad(
                "stresses",
                "rollbem's subsurface stresses are plane strain; under a strip of half-spaces (`mesh.strip_width`) \
                 the field is 3D: remove `[stresses]` or `strip_width`"
                    .into(),
            ));
        }
        Ok(())
    }

    /// `[mesh]` of the half-plane model (after the zone and the element count): constant elements, each a normal
    /// double wide in units of 2R, the strip, and the size bound.
    fn validate_half_plane_mesh(&self, c: &Checker) -> Result<()> {
        let w = &self.wheel;
        let m = &self.mesh;
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
        // The grid is built in units of the diameter: each element's width must stay a normal double there.
        let dx = zone_of(m).element_length(w.radius);
        if !(dx / (2.0 * w.radius)).is_normal() {
            let key = match (m.contact_x, m.contact_half_width) {
                (Some(_), _) => "mesh.contact_x",
                (None, Some(_)) => "mesh.contact_half_width",
                (None, None) => "mesh.contact_arc_deg",
            };
            return Err(c.bad(
                key,
                format!(
                    "the {} contact elements are {dx:e} wide each, {:.1e} wheel diameters; rollbem computes in \
                     units of the diameter, and this ratio is not a normal double (it would be 0 in the kernels): \
                     widen the zone or use fewer contact_elements",
                    m.contact_elements,
                    dx / (2.0 * w.radius)
                ),
            ));
        }
        self.validate_strip(c)?;
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
        Ok(())
    }

    fn validate_mesh(&self, c: &Checker) -> Result<()> {
        let w = &self.wheel;
        let m = &self.mesh;
        self.validate_zone(c)?;
        if m.contact_elements < 1 {
            return Err(c.bad("mesh.contact_elements", "must be at least 1".into()));
        }
        if w.model == BodyModel::HalfPlane {
            return self.validate_half_plane_mesh(c);
        }
        if m.strip_width.is_some() {
            return Err(c.bad(
                "mesh.strip_width",
                "a strip of half-spaces is a model of the half-plane wheel (`wheel.model = \"half_plane\"`); the BEM \
                 wheel is in plane strain"
                    .into(),
            ));
        }
        let Some(other) = m.other_elements else {
            return Err(c.bad("mesh.other_elements", "missing: the BEM wheel's mesh needs it (≥ 4)".into()));
        };
        let arc = zone_of(m).arc_rad(w.radius).to_degrees();
        let per_element = zone_of(m).arc_rad(w.radius) / m.contact_elements as f64;
        if per_element.is_nan() || per_element < MIN_CONTACT_ELEMENT_ANGLE {
            let key = if m.contact_arc_deg.is_some() { "mesh.contact_arc_deg" } else { "mesh.contact_half_width" };
            return Err(c.bad(
                key,
                format!(
                    "the {} contact elements subtend {per_element:.1e} rad each; the wheel's angles are resolved to \
                     2.2e-16 rad, and below {MIN_CONTACT_ELEMENT_ANGLE:.0e} rad per element its geometry is not \
                     represented in double precision: widen the zone or use fewer contact_elements",
                    m.contact_elements
                ),
            ));
        }
        if let Some(Support::TopArc { angle_deg }) = w.support {
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
        let hub_nodes = match w.support.unwrap_or(Support::TopArc { angle_deg: 0.0 }) {
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
    fn check_drive(&self, c: &Checker, prefix: &str, d: &DriveTable) -> Result<()> {
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
        if self.drive != DriveTable::default() {
            return Err(c.bad(
                "steps",
                "give either `[drive]` (one step from rest) or `[[steps]]` (a load path), not both".into(),
            ));
        }
        let mut rolls = false;
        let mut substeps = 0u128;
        for (k, st) in self.steps.iter().enumerate() {
            let prefix = format!("steps[{k}]");
            self.check_drive(c, &prefix, &st.drive())?;
            if st.substeps == Some(0) {
                return Err(c.bad(&format!("{prefix}.substeps"), "must be at least 1".into()));
            }
            substeps += st.substeps.unwrap_or(1) as u128;
            self.check_path_size(c, k, substeps)?;
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

    /// The size guard of a load path, checked at each step `k` on the `substeps` up to it (so the message names the
    /// step where the path grows too large): a path's result holds every substep's run, so its memory is estimated
    /// as substeps × solvers × contact nodes × [`PATH_BYTES_PER_NODE`] and refused above [`MAX_PATH_RESULT_BYTES`],
    /// and more than [`MAX_PATH_SUBSTEPS`] substeps are refused whatever the mesh — before anything is allocated.
    fn check_path_size(&self, c: &Checker, k: usize, substeps: u128) -> Result<()> {
        let nodes =
            self.mesh.contact_elements as u128 * if self.mesh.element == ElementKind::Quadratic { 3 } else { 1 };
        let all = self.solvers.use_.iter().any(|u| u == "all");
        let solvers = if all { crate::solvers::registry().len() } else { self.solvers.use_.len().max(1) } as u128;
        let bytes = substeps * solvers * nodes * PATH_BYTES_PER_NODE as u128;
        let key = format!("steps[{k}].substeps");
        if substeps > MAX_PATH_SUBSTEPS as u128 {
            return Err(c.bad(
                &key,
                format!(
                    "the path has {substeps} substeps by this step; at most {MAX_PATH_SUBSTEPS} are allowed (each is a \
                     solve per solver and a row of the result)"
                ),
            ));
        }
        if bytes > MAX_PATH_RESULT_BYTES as u128 {
            return Err(c.bad(
                &key,
                format!(
                    "the path's result would hold about {:.1} GiB ({substeps} substeps × {solvers} solver(s) × {nodes} \
                     contact nodes, every substep's run kept); at most {:.0} GiB: use fewer substeps, solvers or \
                     elements",
                    bytes as f64 / (1u64 << 30) as f64,
                    MAX_PATH_RESULT_BYTES as f64 / (1u64 << 30) as f64
                ),
            ));
        }
        Ok(())
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
}
