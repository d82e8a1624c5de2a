//! The result document of one scene run (`DESIGN.md`, "Result files"): the JSON that `rollbem run --json` writes
//! and that other tools, the sweeps, the reports and the regression suite read. Keys are stable: add freely,
//! rename none.

use crate::formulation::FormulationName;
use crate::hertz::Hertz;
use crate::post::{ContactSummary, NodeResult, Residuals, Resultants, RigidBody, RollingResult};
use crate::scene::{BodyModel, ElementKind, Scene};
use crate::solvers::Work;
use crate::status::Status;
use serde::Serialize;

/// A solver's registry name ([`crate::solvers::REGISTRY`]), as written in results.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize)]
#[serde(transparent)]
pub struct SolverName(pub &'static str);

impl std::fmt::Display for SolverName {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.pad(self.0)
    }
}

impl PartialEq<str> for SolverName {
    fn eq(&self, other: &str) -> bool {
        self.0 == other
    }
}

impl PartialEq<&str> for SolverName {
    fn eq(&self, other: &&str) -> bool {
        self.0 == *other
    }
}

impl PartialEq<&str> for FormulationName {
    fn eq(&self, other: &&str) -> bool {
        self.name() == *other
    }
}

/// Wall-clock time per stage, seconds. Assembly and condensation are shared by all solvers of a scene.
#[derive(Debug, Clone, Copy, Default, Serialize)]
pub struct Timing {
    /// Flexibility assembly (BEM: H and G).
    pub assembly: f64,
    /// Condensation to the contact flexibility (BEM: LU factorisation and solves).
    pub condensation: f64,
    /// Building the contact problem (LCP / QP).
    pub formulation: f64,
    /// The solver.
    pub solve: f64,
    /// Sum of the above.
    pub total: f64,
}

/// One solver's run on the scene.
#[derive(Debug, Clone, Serialize)]
pub struct SolverRun {
    /// Solver name.
    pub solver: SolverName,
    /// `frictionless` | `displacement` | `loading`.
    pub formulation: FormulationName,
    /// Outcome (after the solver-independent residual check).
    pub status: Status,
    /// Detail from the solver or the residual check.
    pub message: String,
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
    #[serde(skip_serializing_if = "Option::is_none")]
    pub rolling: Option<RollingResult>,
    /// Per contact node: empty unless solved, or judged `contact_at_zone_edge` / `kinematics_out_of_range` (then the
    /// discrete answer that was judged, kept as the evidence for the verdict; such a run has no resultants, contact
    /// summary or residuals).
    pub nodes: Vec<NodeResult>,
    /// For clarabel: max |p − p_unpolished| / p_max, the effect of solving the symmetrised QP before the
    /// active-set polish with the nonsymmetric flexibility.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub polish_change: Option<f64>,
    /// A step of a load path: the frictional energy dissipated in the step and since the start.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub history: Option<StepEnergy>,
    /// Subsurface stresses (only with `[stresses]`, for a solved run; a load path's at the end of each step):
    /// [`crate::stresses`].
    #[serde(skip_serializing_if = "Option::is_none")]
    pub stresses: Option<crate::stresses::StressResult>,
}

impl SolverRun {
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
#[derive(Debug, Clone, Copy, Serialize)]
pub struct StepEnergy {
    /// Dissipated in this (sub)step.
    pub dissipated: f64,
    /// Dissipated since the start of the path.
    pub dissipated_total: f64,
}

/// One (sub)step of a load path: where it is on the path and every solver's run at its end.
#[derive(Debug, Clone, Serialize)]
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
#[derive(Debug, Clone, Serialize)]
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
#[derive(Debug, Clone, Serialize)]
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
#[derive(Debug, Clone, Serialize)]
pub struct References {
    /// Hertz at the run's load (frictionless scenes), from the first solved run's P when displacement-driven, with
    /// the pair's contact modulus E*.
    pub hertz: Option<Hertz>,
    /// Dundurs' β of the pair (wheel against counter-body; a rigid flat has G → ∞): the normal–tangential coupling
    /// of two half-planes vanishes with it.
    pub dundurs_beta: f64,
}

/// What a check compares.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum CheckKind {
    /// A measured figure against a reference within a tolerance (the numbers mean what they say).
    Figure,
    /// A verdict without a figure (a status against the expected one, a reference that could not be evaluated):
    /// `measured`, `reference` and `tolerance` are 0/1 placeholders and `note` says what was found.
    Verdict,
    /// A reference that does not apply to this scene or run (it passes; `note` says why it does not apply).
    NotApplicable,
}

/// One check: a measured figure against a reference.
#[derive(Debug, Clone, Serialize)]
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
    /// Whether this is a figure, a verdict or a reference that does not apply.
    pub kind: CheckKind,
    /// What was found, for a verdict or a reference that could not be evaluated or does not apply; what to do about
    /// a failed figure where there is advice (null otherwise).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub note: Option<String>,
}

/// The JSON document of one scene run (`DESIGN.md`, "Result files").
#[derive(Debug, Clone, Serialize)]
pub struct Report {
    /// The scene as parsed, with defaults filled in.
    pub scene: Scene,
    /// Effects simulated.
    pub effects: Vec<String>,
    /// Mesh facts.
    pub mesh: MeshInfo,
    /// Numerical health.
    pub diagnostics: Diagnostics,
    /// Analytic references.
    pub references: References,
    /// One entry per solver (for a load path: its run at the last step it reached).
    pub runs: Vec<SolverRun>,
    /// A load path's steps (empty for a one-step scene).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub steps: Vec<StepResult>,
    /// Checks against theory and between solvers.
    pub checks: Vec<Check>,
}

impl Report {
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

    /// The nodal table as CSV (`rollbem run --csv`): one row per contact node and solver run that has nodes (a run
    /// that did not solve has none, except the evidence kept by a run judged `contact_at_zone_edge` or
    /// `kinematics_out_of_range`: the `status` column tells them apart), with the keys of `runs[].nodes[]` in the user's units; empty cells where a
    /// value is null (u_x without the tangential problem, the slip of a separated node, the slip velocity without
    /// rolling).
    pub fn nodes_csv(&self) -> String {
        let mut w = csv::Writer::from_writer(Vec::new());
        let head = [
            "solver",
            "status",
            "node",
            "x",
            "y",
            "pressure",
            "shear",
            "u_x",
            "u_y",
            "gap",
            "slip",
            "state",
            "slip_velocity",
        ];
        w.write_record(head).expect("CSV into memory");
        let opt = |v: Option<f64>| v.map(|v| format!("{v:e}")).unwrap_or_default();
        for run in &self.runs {
            for (i, n) in run.nodes.iter().enumerate() {
                let state = serde_json::to_value(n.state).expect("a state serialises");
                w.write_record([
                    run.solver.0.to_string(),
                    run.status.name().to_string(),
                    i.to_string(),
                    format!("{:e}", n.x),
                    format!("{:e}", n.y),
                    format!("{:e}", n.pressure),
                    format!("{:e}", n.shear),
                    opt(n.u_x),
                    format!("{:e}", n.u_y),
                    format!("{:e}", n.gap),
                    opt(n.slip),
                    state.as_str().unwrap_or_default().to_string(),
                    opt(n.slip_velocity),
                ])
                .expect("CSV into memory");
            }
        }
        String::from_utf8(w.into_inner().expect("CSV into memory")).expect("CSV of UTF-8 cells is UTF-8")
    }
}
