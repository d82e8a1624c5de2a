//! The half-space (3D) pipeline: a [`SpaceModel`] is built once from a validated [`SpaceScene`] — the influence
//! kernels of its grid, only those the scene's effects need ([`crate::halfspace::Path`]: the normal kernel alone
//! without friction; the coupling kernels only for a dissimilar pair asked to couple) — and solved into the
//! half-space result document ([`SpaceReport`]) with its checks (`pipeline::space_checks`).
//!
//! ```
//! use rollbem::pipeline::space::SpaceModel;
//! use rollbem::scene::SpaceScene;
//! let scene = SpaceScene::from_toml(
//!     r#"
//! name = "sphere"
//! [wheel]
//! model = "half_space"
//! youngs_modulus = 210000.0
//! poisson_ratio = 0.3
//! [mesh]
//! mx = 21
//! my = 21
//! contact_x = [-1.0, 1.0]
//! contact_y = [-1.0, 1.0]
//! [profile]
//! curvatures = [0.01, 0.01]
//! [drive]
//! normal_load = 100.0
//! "#,
//!     std::path::Path::new("sphere.toml"),
//! )
//! .unwrap();
//! let model = SpaceModel::build(&scene).unwrap();
//! assert!(!model.influence().has_tangential()); // frictionless: the normal kernel only
//! let report = model.solve(&rollbem::cancel::Cancel::never()).unwrap();
//! assert_eq!(report.steps[0].status.name(), "solved");
//! ```

use crate::cancel::Cancel;
use crate::error::{Error, Result};
use crate::halfspace::normal::Drive as NormalDrive;
use crate::halfspace::tangential::TangentialDrive;
use crate::halfspace::{Influence, Path, PathStatus, StepOutcome};
use crate::results::space::{
    state_code, ElementArrays, GridInfo, HertzEllipse, KernelsInfo, NormalDriveDoc, SpaceReferences, SpaceReport,
    SpaceStepResult, SpaceTiming, TangentialDriveDoc, SPACE_SCHEMA_VERSION,
};
use crate::results::EffectNote;
use crate::scene::space::SpaceModelName;
use crate::scene::{SpaceScene, SpaceStatus, SpaceStep};
use std::time::Instant;

/// A half-space scene's influence operators and path, built once.
#[derive(Debug)]
pub struct SpaceModel {
    scene: SpaceScene,
    path: Path,
    build_s: f64,
}

impl SpaceModel {
    /// Build the influence kernels the scene needs.
    ///
    /// # Errors
    /// [`Error::Invalid`] naming `mesh` when the grid's kernels cannot be held (a validated scene is within
    /// [`crate::scene::space::MAX_HALF_SPACE_ELEMENTS`], so this is not expected).
    pub fn build(scene: &SpaceScene) -> Result<SpaceModel> {
        let t = Instant::now();
        let steps = scene.steps().iter().map(|s| s.drive).collect();
        let path = Path::new(
            scene.grid(),
            scene.body(),
            scene.counter(),
            scene.profile().clone(),
            scene.friction(),
            scene.coupling(),
            steps,
        )
        .map_err(|e| Error::Invalid {
            path: scene.origin().to_path_buf(),
            field: "mesh".into(),
            message: e.to_string(),
        })?;
        Ok(SpaceModel { scene: scene.clone(), path, build_s: t.elapsed().as_secs_f64() })
    }

    /// The scene it was built for.
    pub fn scene(&self) -> &SpaceScene {
        &self.scene
    }

    /// The influence operators built ([`Influence::has_tangential`], [`Influence::has_coupling`]).
    pub fn influence(&self) -> &Influence {
        self.path.influence()
    }

    /// Whether the steps alternate the coupled normal and tangential problems.
    pub fn is_coupled(&self) -> bool {
        self.path.is_coupled()
    }

    /// Seconds the build took.
    pub fn build_time(&self) -> f64 {
        self.build_s
    }

    /// Solve every step and check the answers: the result document. A step without a solution is a status in it.
    ///
    /// # Errors
    /// [`Error::Cancelled`] when `cancel` was raised (nothing is produced).
    pub fn solve(&self, cancel: &Cancel) -> Result<SpaceReport> {
        let t = Instant::now();
        let outcomes = self
            .path
            .solve(&self.scene.settings(), cancel)
            .map_err(|e| Error::Numerical { stage: "half-space path", message: e.to_string() })?;
        let solve = t.elapsed().as_secs_f64();
        if cancel.is_cancelled() || outcomes.iter().any(|o| o.status == PathStatus::Cancelled) {
            return Err(Error::Cancelled);
        }
        let steps: Vec<SpaceStepResult> =
            outcomes.iter().zip(self.scene.steps()).map(|(o, s)| step_result(o, s)).collect();
        let mut report = self.document(steps, SpaceTiming { build: self.build_s, solve, total: self.build_s + solve });
        super::space_checks::add_checks(&self.scene, self.is_coupled(), &mut report);
        Ok(report)
    }

    /// The document around the steps (references, effects, kernels).
    fn document(&self, steps: Vec<SpaceStepResult>, timing_s: SpaceTiming) -> SpaceReport {
        let s = &self.scene;
        let g = s.grid();
        let (x0, y0) = g.centre(0, 0);
        let inf = self.influence();
        let last_load = steps.last().map(|st| st.load).filter(|&p| p > 0.0);
        let hertz = match (s.curvatures(), last_load) {
            (Some((a, b)), Some(p)) => {
                crate::theory::Hertz3D::from_load(a, b, s.contact_modulus(), p).map(HertzEllipse::from)
            }
            _ => None,
        };
        let (effects, effect_notes) = effects(s, inf, self.is_coupled());
        SpaceReport {
            schema: SPACE_SCHEMA_VERSION,
            model: SpaceModelName::HalfSpace,
            scene: s.document().clone(),
            grid: GridInfo { mx: g.mx(), my: g.my(), dx: g.dx(), dy: g.dy(), x0, y0 },
            effects,
            effect_notes,
            kernels: KernelsInfo {
                tangential: inf.has_tangential(),
                coupling: inf.has_coupling(),
                coupled: self.is_coupled(),
            },
            references: SpaceReferences { contact_modulus: s.contact_modulus(), dundurs_beta: s.dundurs_beta(), hertz },
            timing_s,
            steps,
            checks: Vec::new(),
            warnings: Vec::new(),
        }
    }
}

/// Build and solve a half-space scene once (Ctrl-C-free: a token that is never raised).
///
/// # Errors
/// As [`SpaceModel::build`].
pub fn run_space_scene(scene: &SpaceScene) -> Result<SpaceReport> {
    SpaceModel::build(scene)?.solve(&Cancel::never())
}

/// One step's document entry.
fn step_result(o: &StepOutcome, s: &SpaceStep) -> SpaceStepResult {
    let normal_drive = match s.drive.normal {
        NormalDrive::Load(p) => NormalDriveDoc::Load(p),
        NormalDrive::Approach(d) => NormalDriveDoc::Approach(d),
    };
    let tangential_drive = match s.drive.tangential {
        TangentialDrive::Force(x, y) => TangentialDriveDoc::Force([x, y]),
        TangentialDrive::Shift(x, y) => TangentialDriveDoc::ShiftIncrement([x, y]),
    };
    let shift = [o.shift.0, o.shift.1];
    SpaceStepResult {
        step: s.step,
        substep: s.substep,
        substeps: s.substeps,
        normal_drive,
        tangential_drive,
        status: SpaceStatus::of(o.status),
        message: o.message.clone(),
        load: o.load,
        approach: o.approach,
        force: [o.force.0, o.force.1],
        shift: shift.iter().all(|v| v.is_finite()).then_some(shift),
        contact: o.counts.0,
        stick: o.counts.1,
        slip: o.counts.2,
        residual_normal: o.residuals.0,
        residual_tangential: o.residuals.1,
        outer_iterations: o.outer_iterations,
        iterations_normal: o.iterations.0,
        iterations_tangential: o.iterations.1,
        elements: ElementArrays {
            pressure: o.pressure.clone(),
            qx: o.qx.clone(),
            qy: o.qy.clone(),
            gap: o.gap.clone(),
            state: o.state.iter().map(|&e| state_code(e)).collect(),
        },
    }
}

/// The effects simulated, and per effect whether it was asked for and why it is (not) simulated.
fn effects(s: &SpaceScene, inf: &Influence, coupled: bool) -> (Vec<String>, Vec<EffectNote>) {
    let mu = s.friction();
    let note = |effect: &str, asked: bool, simulated: bool, why: String| EffectNote {
        effect: effect.into(),
        asked,
        simulated,
        why,
    };
    let mut notes = vec![note(
        "friction",
        mu > 0.0,
        inf.has_tangential(),
        if mu > 0.0 {
            format!("μ = {mu}: the tangential kernels are built and the shift problem solved on Coulomb's disc")
        } else {
            "frictionless (contact.friction = 0): only the normal kernel C_zz is built".into()
        },
    )];
    let why = match (s.coupling(), mu > 0.0, inf.has_coupling()) {
        (false, _, _) => "contact.coupling = false".to_string(),
        (true, false, _) => "frictionless: the shears are zero, nothing couples".to_string(),
        (true, true, false) => format!(
            "the pair's coupling constant is 0 (Dundurs' β = {:.3e}: identical materials), so C_zt vanishes \
             identically and is not built",
            s.dundurs_beta()
        ),
        (true, true, true) => format!("Dundurs' β = {:.4}: normal and tangential problems alternate", s.dundurs_beta()),
    };
    notes.push(note("coupling", s.coupling(), coupled, why));
    let history = s.steps().len() > 1 && mu > 0.0;
    notes.push(note(
        "history",
        s.is_path(),
        history,
        if history {
            "friction with memory: each step starts from the previous step's tractions".into()
        } else {
            "one step, or frictionless: no tangential memory to carry".into()
        },
    ));
    let mut effects = vec!["normal".to_string()];
    effects.extend(notes.iter().filter(|n| n.simulated).map(|n| n.effect.clone()));
    (effects, notes)
}
