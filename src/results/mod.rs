//! The result document of one scene run (`DESIGN.md`, "Result files"): the JSON that `rollbem run --json` writes
//! and that other tools, the sweeps, the reports and the regression suite read. Keys are stable: add freely,
//! rename none.

use crate::formulation::{FormulationName, ProblemKind};
use crate::post::{ContactSummary, NodeResult, Residuals, Resultants, RigidBody, RollingResult};
use crate::scene::{BodyModel, ElementKind, Scene};
use crate::solvers::{SolverId, Work};
use crate::status::{Status, Termination, Verdict};
use crate::theory::Hertz2D;
use serde::{Deserialize, Serialize};

mod export;
pub mod render;
pub mod space;
pub mod space_render;

/// The version of the result document's layout ([`Report::schema`]): raised when a key changes meaning or is
/// removed (keys are only ever added within a version).
pub const SCHEMA_VERSION: u32 = 3;

/// The oldest schema [`Report::read`] still reads (schema 2 had clarabel's `polish_change` as a key of each run, which
/// schema 3 keeps among the run's `figures`; it is moved there when read).
pub const OLDEST_READABLE_SCHEMA: u32 = 2;

/// Whether a run's flexibility was built for it or reused from an earlier solve on the same model
/// ([`crate::pipeline::Model`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
#[non_exhaustive]
pub enum Setup {
    /// Built for this solve: its assembly and condensation times were spent here.
    #[default]
    Built,
    /// Reused: the assembly and condensation times are those of the model's one build, not spent again.
    Reused,
}

/// Which contact problem a run solved (how the drive and the friction limit posed it).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
#[non_exhaustive]
pub enum ProblemClass {
    /// μ = 0: the normal problem only.
    Frictionless,
    /// μ > 0: the frictional problem.
    Frictional,
    /// |Q| = μP with both prescribed: every node slips, the normal problem with q = μp sgn Q; shift indeterminate.
    SlidingLimit,
    /// |Q| > μP with both prescribed: no static solution.
    GrossSliding,
}

impl ProblemClass {
    /// The class of a problem.
    pub fn of(kind: &ProblemKind) -> ProblemClass {
        match kind {
            ProblemKind::Frictionless => ProblemClass::Frictionless,
            ProblemKind::Frictional => ProblemClass::Frictional,
            ProblemKind::SlidingLimit { .. } => ProblemClass::SlidingLimit,
            ProblemKind::GrossSliding { .. } => ProblemClass::GrossSliding,
        }
    }
}

impl PartialEq<&str> for FormulationName {
    fn eq(&self, other: &&str) -> bool {
        self.name() == *other
    }
}

/// Wall-clock time per stage, seconds. Assembly and condensation are shared by all solvers of a scene, and by every
/// solve on one model ([`Timing::setup`] says whether they were spent for this run).
#[derive(Debug, Clone, Copy, Default, PartialEq, Serialize, Deserialize)]
#[non_exhaustive]
pub struct Timing {
    /// Flexibility assembly (BEM: H and G).
    pub assembly: f64,
    /// Condensation to the contact flexibility (BEM: LU factorisation and solves).
    pub condensation: f64,
    /// Building the contact problem (LCP / QP).
    pub formulation: f64,
    /// The solver.
    pub solve: f64,
    /// Sum of the above: the cost of this answer from scratch.
    pub total: f64,
    /// Whether the flexibility (assembly, condensation) was built for this run or reused from the model's build.
    #[serde(default)]
    pub setup: Setup,
}

impl Timing {
    /// A run's timing from its source's build time and its own formulation and solve times.
    pub fn of(source: &crate::source::SourceTiming, formulation: f64, solve: f64, setup: Setup) -> Timing {
        Timing {
            assembly: source.assembly,
            condensation: source.condensation,
            formulation,
            solve,
            total: source.assembly + source.condensation + formulation + solve,
            setup,
        }
    }
}

/// One solver's run on the scene.
#[derive(Debug, Clone, Serialize, Deserialize)]
#[non_exhaustive]
pub struct SolverRun {
    /// Solver name.
    pub solver: SolverId,
    /// `frictionless` | `displacement` | `loading`.
    pub formulation: FormulationName,
    /// Which contact problem the drive posed (e.g. `sliding_limit`).
    pub problem: ProblemClass,
    /// The harness's conclusion (after the solver-independent residual check and the model-range checks): what a
    /// user acts on.
    pub status: Status,
    /// How the solver itself ended.
    pub termination: Termination,
    /// The solver's own message.
    pub message: String,
    /// Why `status` is not simply the solver's `termination` (null when it is).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub verdict: Option<Verdict>,
    /// Number of complementarity (or QP) unknowns solved.
    pub problem_size: usize,
    /// Work counters (named: pivots, sweeps, iterations, outer, ...).
    pub work: Work,
    /// Time per stage.
    pub timing_s: Timing,
    /// Solver-independent residuals (null unless a solution was produced).
    pub residuals: Option<Residuals>,
    /// Resultants of the contact tractions (null unless solved).
    pub resultants: Option<Resultants>,
    /// Rigid motion of the support (null unless solved).
    pub rigid_body: Option<RigidBody>,
    /// Contact figures (null unless solved).
    pub contact: Option<ContactSummary>,
    /// Rolling figures: creepage (prescribed or computed) and Coulomb-law inconsistencies of the slip velocities
    /// (null without rolling, or unless solved).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub rolling: Option<RollingResult>,
    /// Per contact node: empty unless solved, or judged `contact_at_zone_edge` / `kinematics_out_of_range` (then the
    /// discrete answer that was judged, kept as the evidence for the verdict; such a run has no resultants, contact
    /// summary or residuals).
    pub nodes: Vec<NodeResult>,
    /// The solver's own figures of the run, by name ([`crate::solvers::Figures`]); clarabel's `polish_change` is
    /// max |p − p_unpolished| / p_max, the effect of solving the symmetrised QP before the active-set polish with the
    /// nonsymmetric flexibility. Empty for most solvers.
    #[serde(default, skip_serializing_if = "crate::solvers::Figures::is_empty")]
    pub figures: crate::solvers::Figures,
    /// A step of a load path: the frictional energy dissipated in the step and since the start.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub history: Option<StepEnergy>,
    /// Subsurface stresses (only with `[stresses]`, for a solved run; a load path's at the end of each step):
    /// [`crate::stresses`].
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub stresses: Option<crate::stresses::StressResult>,
    /// The elastic counter-body's subsurface stresses from the same tractions (with `[stresses]` and
    /// `[counter_body] kind = "half_plane"`; depth measured into the counter-body): [`crate::stresses`].
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub counter_body_stresses: Option<crate::stresses::StressResult>,
    /// With a falling friction law of the slip velocity (`[contact] friction_law`): the steady problem solved from
    /// both starts, which one the run carries, and whether they are two solutions ([`crate::veldep::BranchReport`]).
    /// Absent for Coulomb.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub branches: Option<crate::veldep::BranchReport>,
}

impl SolverRun {
    /// What to tell a user about the run: the verdict's explanation (when the harness overrode the solver), then
    /// the solver's message.
    pub fn explanation(&self) -> String {
        match &self.verdict {
            Some(v) if self.message.is_empty() => v.message.clone(),
            Some(v) => format!("{}; {}: {}", v.message, self.solver, self.message),
            None => self.message.clone(),
        }
    }

    /// The nodes of the answer: the run's nodes when it solved, none otherwise (a run judged
    /// `contact_at_zone_edge` or `kinematics_out_of_range` keeps its nodes as evidence, not as an answer). Every
    /// figure derived from the nodes (stick edges, node counts) reads them through this.
    pub fn answer_nodes(&self) -> &[crate::post::NodeResult] {
        if self.status == crate::solvers::Status::Solved {
            &self.nodes
        } else {
            &[]
        }
    }
}

/// The frictional dissipation of a load step (energy per unit thickness, user's units): Σ −h_i Δs_i with the
/// step's end forces (backward Euler; converges with the substeps).
#[derive(Debug, Clone, Copy, Serialize, Deserialize)]
#[non_exhaustive]
pub struct StepEnergy {
    /// Dissipated in this (sub)step.
    pub dissipated: f64,
    /// Dissipated since the start of the path.
    pub dissipated_total: f64,
}

/// One (sub)step of a load path: where it is on the path and every solver's run at its end.
#[derive(Debug, Clone, Serialize, Deserialize)]
#[non_exhaustive]
pub struct StepResult {
    /// Step index (from 0, as in `[[steps]]`).
    pub step: usize,
    /// Substep (1 ..= substeps).
    pub substep: usize,
    /// Number of substeps of the step.
    pub substeps: usize,
    /// Distance rolled since the start of the path (user's length unit).
    pub rolled: f64,
    /// The drive at the substep's end (user's units): per DOF `{"Displacement": v}` or `{"Load": v}`.
    pub drive: crate::formulation::Drive,
    /// Every solver's run at the substep's end (a solver whose path broke earlier has none).
    pub runs: Vec<SolverRun>,
}

/// Mesh facts.
#[derive(Debug, Clone, Serialize, Deserialize)]
#[non_exhaustive]
pub struct MeshInfo {
    /// The wheel's model: `bem` (the finite wheel) or `half_plane`.
    pub model: BodyModel,
    /// Number of elements.
    pub elements: usize,
    /// Number of nodes (collocation points).
    pub nodes: usize,
    /// Number of contact nodes.
    pub contact_nodes: usize,
    /// Element family.
    pub element: ElementKind,
    /// Size of the rearranged BEM system (null without one).
    pub system_size: Option<usize>,
    /// Smallest contact element length (user's unit).
    pub contact_element_length: f64,
}

/// Numerical health of the flexibility source and of the contact flexibility.
#[derive(Debug, Clone, Serialize, Deserialize)]
#[non_exhaustive]
pub struct Diagnostics {
    /// Largest/smallest |U_ii| of the BEM system's LU (a lower bound of its condition number; null without BEM).
    pub bem_pivot_ratio: Option<f64>,
    /// Estimated 1-norm condition number of the rearranged BEM system (null without BEM).
    pub bem_condition: Option<f64>,
    /// Estimated 1-norm condition number of the normal flexibility K_NN (nodal forces to gaps).
    pub flexibility_condition: f64,
    /// Same for the tangential block K_TT (null when the tangential problem is not built).
    pub tangential_condition: Option<f64>,
    /// ‖K − Kᵀ‖_F / ‖K‖_F of the normal flexibility in nodal forces (collocation asymmetry).
    pub flexibility_asymmetry: f64,
    /// Warnings when a figure above exceeds its threshold in [`crate::tolerances`].
    pub warnings: Vec<String>,
}

/// Analytic references that apply to the scene.
#[derive(Debug, Clone, Serialize, Deserialize)]
#[non_exhaustive]
pub struct References {
    /// Hertz at the run's load (frictionless scenes in plane strain: none on a strip of half-spaces), from the first
    /// solved run's P when displacement-driven, with the pair's contact modulus E*.
    pub hertz: Option<Hertz2D>,
    /// Dundurs' β of the pair (wheel against counter-body; a rigid flat has G → ∞): the normal–tangential coupling
    /// of two half-planes vanishes with it.
    pub dundurs_beta: f64,
}

/// What a check compares.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
#[non_exhaustive]
pub enum CheckKind {
    /// A measured figure against a reference within a tolerance (the numbers mean what they say).
    Figure,
    /// A verdict without a figure (a status against the expected one, a reference that could not be evaluated):
    /// `measured`, `reference` and `tolerance` are 0/1 placeholders and `note` says what was found.
    Verdict,
    /// A reference that does not apply to this scene or run (it passes; `note` says why it does not apply).
    NotApplicable,
    /// A theory used outside the conditions it assumes (a half-space theory on the finite wheel): no verdict, the
    /// measured difference from the theory (`error`, in the quantity's unit) with the **model error** beside it
    /// (`model_error`: the same loads on the model the theory assumes, computed by rollbem, subtracted) and its
    /// uncertainty. It passes: refining the mesh converges the difference to the model error, it does not fail it.
    ModelComparison,
}

/// One check: a measured figure against a reference.
#[derive(Debug, Clone, Serialize, Deserialize)]
#[non_exhaustive]
pub struct Check {
    /// What is checked.
    pub name: String,
    /// Measured value.
    pub measured: f64,
    /// Reference value (theory, or the peer solver).
    pub reference: f64,
    /// Error (relative unless the name says otherwise).
    pub error: f64,
    /// Tolerance (from [`crate::tolerances`]).
    pub tolerance: f64,
    /// error ≤ tolerance (for a verdict: the verdict; a reference that does not apply passes).
    pub pass: bool,
    /// Whether this is a figure, a verdict, a reference that does not apply or a model comparison.
    pub kind: CheckKind,
    /// For a model comparison: measured minus the same figure on the model the theory assumes (e.g. the finite wheel
    /// minus the half-plane pair at the same loads and mesh), in the quantity's unit.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub model_error: Option<f64>,
    /// For a model comparison: the uncertainty of `model_error` (e.g. one contact element length for a stick-zone
    /// edge located on the nodes).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub uncertainty: Option<f64>,
    /// What was found, for a verdict or a reference that could not be evaluated or does not apply; what to do about
    /// a failed figure where there is advice (null otherwise).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub note: Option<String>,
}

/// Whether an effect is simulated, and why ([`Report::effect_notes`]).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[non_exhaustive]
pub struct EffectNote {
    /// The effect: `friction`, `coupling`, `rolling`, `counter_body`, `history` or `stresses`.
    pub effect: String,
    /// Whether the scene asks for it (a key it sets, or a default it leaves, e.g. `coupling = true`).
    pub asked: bool,
    /// Whether the run simulates it (builds and solves what it needs).
    pub simulated: bool,
    /// Why: what the scene says and what the physics needs.
    pub why: String,
}

/// The JSON document of one scene run (`DESIGN.md`, "Result files").
#[derive(Debug, Clone, Serialize, Deserialize)]
#[non_exhaustive]
pub struct Report {
    /// The layout version of this document ([`SCHEMA_VERSION`]).
    pub schema: u32,
    /// The scene as parsed, with defaults filled in. Read back ([`Report::read`]) it is the scene as recorded
    /// ([`Scene::from_record`]): keys this version does not know are dropped, and a scene this version's checks
    /// refuse (or one with dropped keys) is kept as written and marked not runnable ([`Scene::runnable`]).
    #[serde(deserialize_with = "recorded_scene")]
    pub scene: Scene,
    /// Effects simulated.
    pub effects: Vec<String>,
    /// Each effect beyond the normal problem: asked for or not, simulated or not, and why (e.g. coupling asked for
    /// but not simulated because the pair's cross flexibilities vanish). Empty in documents written before it.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub effect_notes: Vec<EffectNote>,
    /// Mesh facts.
    pub mesh: MeshInfo,
    /// Numerical health.
    pub diagnostics: Diagnostics,
    /// Analytic references.
    pub references: References,
    /// One entry per solver (for a load path: its run at the last step it reached).
    pub runs: Vec<SolverRun>,
    /// A load path's steps (empty for a one-step scene).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub steps: Vec<StepResult>,
    /// Checks against theory and between solvers.
    pub checks: Vec<Check>,
    /// Run-level warnings: a contact with too few elements across it (a failed check in `check`, a warning in
    /// `run`), one line per distinct finding with the solvers it concerns.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub warnings: Vec<String>,
}

impl Report {
    /// Read a result document (`rollbem run --json`) of this layout ([`SCHEMA_VERSION`]) or an older one this version
    /// still reads ([`OLDEST_READABLE_SCHEMA`]). Keys it does not know are ignored (a schema only ever adds keys); the
    /// embedded scene is read as recorded ([`Scene::from_record`]). A document of a newer schema, or of none (written
    /// before the schema was recorded), is refused with a message saying so, never read wrongly.
    pub fn read(path: &std::path::Path) -> crate::Result<Report> {
        let text =
            std::fs::read_to_string(path).map_err(|source| crate::Error::Io { path: path.to_path_buf(), source })?;
        Report::from_json(&text, path)
    }

    /// Parse a result document's text (`path` names it in messages); see [`Report::read`].
    pub fn from_json(text: &str, path: &std::path::Path) -> crate::Result<Report> {
        let bad = |message: String| crate::Error::Parse { path: path.to_path_buf(), message };
        let mut value: serde_json::Value = serde_json::from_str(text).map_err(|e| bad(format!("not JSON: {e}")))?;
        if space::is_space_value(&value) {
            return Err(bad(
                "a half-space (3D) result document: read it with `results::space::SpaceReport::read` (`rollbem plot` \
                 reads both kinds)"
                    .into(),
            ));
        }
        if value.get("runs").is_none() {
            return Err(bad("not a rollbem result document: no `runs` array".into()));
        }
        match value.get("schema").and_then(serde_json::Value::as_u64) {
            Some(v) if (u64::from(OLDEST_READABLE_SCHEMA)..=u64::from(SCHEMA_VERSION)).contains(&v) => {
                if v < 3 {
                    migrate_polish_change(&mut value);
                }
            }
            Some(v) => {
                return Err(bad(format!(
                    "result document of schema {v}; this rollbem reads schemas {OLDEST_READABLE_SCHEMA} to \
                     {SCHEMA_VERSION}: read it with the rollbem that wrote it, or rerun the scene"
                )))
            }
            None => {
                return Err(bad(format!(
                    "result document without a schema version (written by an older rollbem); this rollbem reads \
                     schemas {OLDEST_READABLE_SCHEMA} to {SCHEMA_VERSION}: rerun the scene"
                )))
            }
        }
        serde_json::from_value(value).map_err(|e| bad(format!("not a result document of schema {SCHEMA_VERSION}: {e}")))
    }

    /// Whether every check passed.
    pub fn all_pass(&self) -> bool {
        self.checks.iter().all(|c| c.pass)
    }

    /// Move every stress field too large to be written inline ([`crate::stresses::MAX_INLINE_POINTS`]) to a CSV file
    /// beside the result document `json`: each such run then names its file (`stresses.csv`, a name in `json`'s
    /// folder: `STEM.SOLVER.stresses.csv`, `STEM.stepK-S.SOLVER.stresses.csv` for a load path's steps). Returns the
    /// files to write (path, text); writing them is the caller's.
    pub fn spill_stress_fields(&mut self, json: &std::path::Path) -> Vec<(std::path::PathBuf, String)> {
        let stem = json.file_stem().map(|s| s.to_string_lossy().into_owned()).unwrap_or_else(|| "result".into());
        let dir = json.parent().map(|p| p.to_path_buf()).unwrap_or_default();
        let mut out = Vec::new();
        let mut spill = |run: &mut SolverRun, tag: String| {
            if let Some(s) = run.stresses.as_mut() {
                let file = format!("{stem}.{tag}{}.stresses.csv", run.solver);
                if let Some(text) = s.spill(&file) {
                    out.push((dir.join(&file), text));
                }
            }
        };
        for run in &mut self.runs {
            spill(run, String::new());
        }
        for st in &mut self.steps {
            for run in &mut st.runs {
                spill(run, format!("step{}-{}.", st.step, st.substep));
            }
        }
        out
    }
}

/// Schema 2 → 3: each run's `polish_change` key becomes its `figures.polish_change`.
fn migrate_polish_change(value: &mut serde_json::Value) {
    let mut move_it = |run: &mut serde_json::Value| {
        let Some(obj) = run.as_object_mut() else { return };
        if let Some(v) = obj.remove("polish_change") {
            let figures = obj.entry("figures").or_insert_with(|| serde_json::json!({}));
            if let Some(f) = figures.as_object_mut() {
                f.insert("polish_change".into(), v);
            }
        }
    };
    if let Some(runs) = value.get_mut("runs").and_then(|r| r.as_array_mut()) {
        runs.iter_mut().for_each(&mut move_it);
    }
    if let Some(steps) = value.get_mut("steps").and_then(|s| s.as_array_mut()) {
        for step in steps {
            if let Some(runs) = step.get_mut("runs").and_then(|r| r.as_array_mut()) {
                runs.iter_mut().for_each(&mut move_it);
            }
        }
    }
}

/// The scene of a result document, as recorded ([`Scene::from_record`]): keys this version does not know are dropped
/// (their dotted paths then mark the scene not runnable, since what they asked for is not simulated here).
fn recorded_scene<'de, D: serde::Deserializer<'de>>(d: D) -> std::result::Result<Scene, D::Error> {
    use serde::de::Error as _;
    let mut value = serde_json::Value::deserialize(d)?;
    let mut dropped = Vec::new();
    let document = loop {
        match serde_path_to_error::deserialize::<_, crate::scene::document::SceneDocument>(value.clone()) {
            Ok(doc) => break doc,
            Err(e) => {
                let message = e.inner().to_string();
                let Some(field) = message.strip_prefix("unknown field `").and_then(|m| m.split('`').next()) else {
                    return Err(D::Error::custom(format!("scene: {}: {message}", e.path())));
                };
                let mut segments: Vec<String> = e.path().iter().map(|s| s.to_string()).collect();
                // The path may end with the unknown key itself.
                if segments.last().is_some_and(|l| l == field) {
                    segments.pop();
                }
                if dropped.len() >= 100 || !remove_key(&mut value, &segments, field) {
                    return Err(D::Error::custom(format!("scene: {}: {message}", e.path())));
                }
                let mut at = segments.clone();
                at.push(field.to_string());
                dropped.push(at.join(".").replace(".[", "["));
            }
        }
    };
    let mut scene = Scene::from_record(document, &Scene::code_path()).map_err(D::Error::custom)?;
    if !dropped.is_empty() {
        scene.mark_recorded(format!("keys this version does not know were ignored: {}", dropped.join(", ")));
    }
    Ok(scene)
}

/// Remove `field` from the object at `path` (serde_path_to_error's segments: keys, and `[i]` for sequence indices)
/// inside `value`; whether it was there.
fn remove_key(value: &mut serde_json::Value, path: &[String], field: &str) -> bool {
    let mut at = value;
    for seg in path {
        let next = match seg.strip_prefix('[').and_then(|s| s.strip_suffix(']')).and_then(|i| i.parse::<usize>().ok()) {
            Some(i) => at.get_mut(i),
            None => at.get_mut(seg.as_str()),
        };
        match next {
            Some(v) => at = v,
            None => return false,
        }
    }
    at.as_object_mut().is_some_and(|o| o.remove(field).is_some())
}
