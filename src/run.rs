//! The pipeline for one scene: model → condensation → formulation → every requested solver → post-processing →
//! checks. Produces the JSON document of `DESIGN.md` ([`Report`]).
//!
//! Only the effects the scene calls for are simulated: a frictionless scene condenses only the normal columns of
//! the flexibility ([`Blocks::Normal`]), builds an LCP of one unknown per contact node (plus two per load-driven
//! rigid degree of freedom) and does no tangential or rolling work; `effects` and `problem_size` in the report
//! show it.

use crate::condense::{condense, Blocks, Flexibility, Model};
use crate::error::{Error, Result};
use crate::formulation::{DriveIssue, Frictional, Frictionless, Split, MODE_APPROACH};
use crate::hertz::Hertz;
use crate::post::{evaluate, ContactSummary, Evaluation, NodeResult, Residuals, Resultants, RigidBody};
use crate::scene::{Dof, ElementKind, Scene, SolverName};
use crate::solvers::clarabel_qp::{self, QpStatus};
use crate::solvers::lemke;
use crate::solvers::normtang::{self, Inner};
use crate::solvers::Status;
use crate::tolerances as tol;
use serde::Serialize;
use std::path::Path;
use std::time::Instant;

/// Work counters of a solver run.
#[derive(Debug, Clone, Copy, Default, Serialize)]
pub struct Work {
    /// Lemke pivots.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub pivots: Option<usize>,
    /// Interior-point iterations (clarabel, or the sum over NORM-TANG's QPs).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub iterations: Option<u32>,
    /// Projected Gauss–Seidel sweeps, summed over all inner solves (PGS).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub sweeps: Option<usize>,
    /// NORM-TANG outer iterations.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub outer: Option<usize>,
}

/// Wall-clock time per stage, seconds. Assembly and condensation are shared by all solvers of a scene.
#[derive(Debug, Clone, Copy, Default, Serialize)]
pub struct Timing {
    /// BEM assembly.
    pub assembly: f64,
    /// LU factorisation and solves for the flexibility.
    pub condensation: f64,
    /// Building the LCP / QP.
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
    pub solver: String,
    /// `frictionless` | `displacement` | `loading`.
    pub formulation: String,
    /// Outcome (after the solver-independent residual check).
    pub status: Status,
    /// Detail from the solver or the residual check.
    pub message: String,
    /// Number of complementarity (or QP) unknowns solved.
    pub problem_size: usize,
    /// Work counters.
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
    /// Per contact node (empty unless solved).
    pub nodes: Vec<NodeResult>,
    /// For clarabel: max |p − p_unpolished| / p_max, the effect of solving the symmetrised QP before the
    /// active-set polish with the nonsymmetric flexibility.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub polish_change: Option<f64>,
}

/// Mesh facts.
#[derive(Debug, Clone, Serialize)]
pub struct MeshInfo {
    /// Number of elements.
    pub elements: usize,
    /// Number of nodes (collocation points).
    pub nodes: usize,
    /// Number of contact nodes.
    pub contact_nodes: usize,
    /// Element family.
    pub element: ElementKind,
    /// Size of the rearranged BEM system.
    pub system_size: usize,
    /// Smallest contact element length (user's unit).
    pub contact_element_length: f64,
}

/// Numerical health of the condensation and of the contact flexibility.
#[derive(Debug, Clone, Serialize)]
pub struct Diagnostics {
    /// Largest/smallest |U_ii| of the BEM system's LU (a lower bound of its condition number).
    pub bem_pivot_ratio: f64,
    /// Estimated 1-norm condition number of the rearranged BEM system.
    pub bem_condition: f64,
    /// Estimated 1-norm condition number of the normal flexibility K_NN (nodal forces to gaps).
    pub flexibility_condition: f64,
    /// Same for the tangential block K_TT (null when the tangential problem is not built).
    pub tangential_condition: Option<f64>,
    /// ‖K − Kᵀ‖_F / ‖K‖_F of the normal flexibility in nodal forces (collocation asymmetry).
    pub flexibility_asymmetry: f64,
    /// Warnings when a figure above exceeds its threshold in [`crate::tolerances`].
    pub warnings: Vec<String>,
}

fn diagnostics(flex: &Flexibility, asymmetry: f64) -> Diagnostics {
    let n = flex.n();
    let cond = |m: &faer::Mat<f64>| {
        let k = faer::Mat::from_fn(n, n, |i, j| m[(i, j)] / flex.weights[j]);
        crate::condition::cond1(&k, &k.partial_piv_lu())
    };
    let flexibility_condition = if n > 0 { cond(&flex.nn) } else { 0.0 };
    let tangential_condition = flex.tt.as_ref().filter(|_| n > 0).map(cond);
    let mut warnings = Vec::new();
    if flex.system_condition.is_nan() || flex.system_condition > tol::BEM_CONDITION_WARN {
        warnings.push(format!(
            "the BEM system is poorly conditioned (κ₁ ≈ {:.2e} > {:.0e}): expect fewer than {} correct digits in F",
            flex.system_condition,
            tol::BEM_CONDITION_WARN,
            (16.0 - flex.system_condition.log10()).max(0.0).floor()
        ));
    }
    for (name, k) in [("normal", Some(flexibility_condition)), ("tangential", tangential_condition)] {
        if let Some(k) = k.filter(|k| k.is_nan() || *k > tol::FLEXIBILITY_CONDITION_WARN) {
            warnings.push(format!(
                "the {name} contact flexibility is poorly conditioned (κ₁ ≈ {k:.2e} > {:.0e})",
                tol::FLEXIBILITY_CONDITION_WARN
            ));
        }
    }
    if let Some(i) = (0..n).find(|&i| flex.nn[(i, i)].is_nan() || flex.nn[(i, i)] <= 0.0) {
        warnings.push(format!(
            "the normal flexibility is not positive definite (non-positive diagonal at contact node {i}): the mesh is \
             too coarse or distorted to represent the wheel; refine other_elements / contact_elements"
        ));
    }
    if asymmetry > tol::ASYMMETRY_WARN {
        warnings.push(format!(
            "the flexibility is far from symmetric (‖K − Kᵀ‖/‖K‖ = {asymmetry:.2e} > {:.0e}): the QP and PGS solvers \
             assume near symmetry; refine the mesh",
            tol::ASYMMETRY_WARN
        ));
    }
    Diagnostics {
        bem_pivot_ratio: flex.pivot_ratio,
        bem_condition: flex.system_condition,
        flexibility_condition,
        tangential_condition,
        flexibility_asymmetry: asymmetry,
        warnings,
    }
}

/// Analytic references that apply to the scene.
#[derive(Debug, Clone, Serialize, Default)]
pub struct References {
    /// Hertz at the run's load (frictionless scenes), from the first solved run's P when displacement-driven.
    pub hertz: Option<Hertz>,
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
    /// error ≤ tolerance.
    pub pass: bool,
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
    /// One entry per solver.
    pub runs: Vec<SolverRun>,
    /// Checks against theory and between solvers.
    pub checks: Vec<Check>,
}

impl Report {
    /// Whether every check passed and every run solved.
    pub fn all_pass(&self) -> bool {
        self.checks.iter().all(|c| c.pass)
    }
}

/// The solvers to run: `all` expands to every solver valid for the scene; an explicitly named solver that does not
/// apply is an error naming `solvers.use` and the reason.
fn resolve_solvers(
    scene: &Scene,
    path: &Path,
    valid: impl Fn(SolverName) -> std::result::Result<(), &'static str>,
) -> Result<Vec<SolverName>> {
    let mut out = Vec::new();
    for &s in &scene.solvers.use_ {
        match s {
            SolverName::All => out.extend(SolverName::SOLVERS.into_iter().filter(|&x| valid(x).is_ok())),
            s => {
                if let Err(why) = valid(s) {
                    return Err(Error::Unsupported {
                        path: path.to_path_buf(),
                        message: format!("solvers.use: {} does not apply to this scene: {why}", s.name()),
                    });
                }
                out.push(s);
            }
        }
    }
    out.sort();
    out.dedup();
    Ok(out)
}

fn asymmetry(k: &faer::Mat<f64>) -> f64 {
    let n = k.nrows();
    let (mut d, mut s) = (0.0, 0.0);
    for j in 0..n {
        for i in 0..n {
            d += (k[(i, j)] - k[(j, i)]).powi(2);
            s += k[(i, j)].powi(2);
        }
    }
    (d / s.max(f64::MIN_POSITIVE)).sqrt() / 2.0_f64.sqrt()
}

/// The formulation chosen for a scene.
enum Problem {
    /// Frictionless: the normal problem only.
    Frictionless(Frictionless),
    /// Frictional LCP (displacement, loading or mixed drive).
    Frictional(Frictional),
    /// |Q| = μP with both prescribed: full slip, normal problem with h = σμf, shift indeterminate.
    SlidingLimit(Frictionless, f64),
    /// |Q| > μP with both prescribed: no static solution (message).
    GrossSliding(String),
}

/// A solver's answer in the formulation's dimensionless unknowns.
struct Solution {
    /// Normal nodal forces.
    f: Vec<f64>,
    /// Tangential nodal forces (None when the tangential problem was not built).
    h: Option<Vec<f64>>,
    /// Rigid motion (shift, approach, rotation).
    rigid: [f64; 3],
    /// False when the shift is indeterminate (sliding limit).
    shift_known: bool,
}

/// The LCP that `run_scene` hands to Lemke for this scene (for `rollbem lcp export`): frictionless, frictional
/// (displacement, loading or mixed) or the sliding-limit problem. A scene beyond gross sliding has no LCP.
pub fn scene_lcp(scene: &Scene, path: &Path) -> Result<crate::solvers::Lcp> {
    let model = Model::new(scene);
    let (flex, _) = condense(&model, blocks_for(scene))?;
    match build_problem(scene, &model, &flex, path)? {
        Problem::Frictionless(p) | Problem::SlidingLimit(p, _) => Ok(p.lcp),
        Problem::GrossSliding(msg) => {
            Err(Error::Unsupported { path: path.to_path_buf(), message: format!("no static problem to export: {msg}") })
        }
        Problem::Frictional(p) => {
            // The LCP Lemke actually solves: with the slack signs of the attempt that succeeded.
            let (solved_by, _) = lemke_frictional(scene, &model, &flex, &p);
            Ok(solved_by.unwrap_or(p).lcp)
        }
    }
}

/// Which flexibility blocks the scene needs: the tangential columns only with friction or rolling.
fn blocks_for(scene: &Scene) -> Blocks {
    if scene.contact.friction > 0.0 || scene.rolling.is_some() {
        Blocks::All
    } else {
        Blocks::Normal
    }
}

/// Choose and build the scene's formulation (shared by `run_scene` and `scene_lcp`).
fn build_problem(scene: &Scene, model: &Model, flex: &Flexibility, path: &Path) -> Result<Problem> {
    let mu = scene.contact.friction;
    if mu == 0.0 {
        return Ok(Problem::Frictionless(Frictionless::new(scene, model, flex).map_err(|issue| {
            Error::Unsupported {
                path: path.to_path_buf(),
                message: match issue {
                    DriveIssue::TangentialLoadWithoutFriction(q) => format!(
                        "drive.tangential_load = {q}: a frictionless contact carries no tangential load (gross \
                         sliding); use tangential_load = 0 or friction > 0"
                    ),
                    DriveIssue::MomentLoad => "a prescribed moment is not carried by this formulation".into(),
                },
            }
        })?));
    }
    Ok(match (scene.drive.normal(), scene.drive.tangential()) {
        (Dof::Load(p), Dof::Load(q)) if q.abs() > mu * p * (1.0 + SLIDING_LIMIT_BAND) => {
            Problem::GrossSliding(format!(
                "gross sliding: the tangential load |Q| = {:.6e} exceeds the friction limit μP = {:.6e} (μ = {mu}, \
             P = {p:.6e}); no static solution exists",
                q.abs(),
                mu * p
            ))
        }
        (Dof::Load(p), Dof::Load(q)) if q.abs() >= mu * p * (1.0 - SLIDING_LIMIT_BAND) => {
            Problem::SlidingLimit(Frictionless::sliding_limit(scene, model, flex, q.signum()), q.signum())
        }
        _ => Problem::Frictional(Frictional::new(scene, model, flex)),
    })
}

/// Relative band around |Q| = μP treated as the sliding limit.
const SLIDING_LIMIT_BAND: f64 = 1e-9;

/// Run a validated scene. `path` is used in error messages.
pub fn run_scene(scene: &Scene, path: &Path) -> Result<Report> {
    let mu = scene.contact.friction;
    let frictional = mu > 0.0;
    let mut effects = vec!["normal".to_string()];
    if frictional {
        effects.push("friction".into());
        if scene.contact.coupling {
            effects.push("coupling".into());
        }
    }
    if scene.rolling.is_some() {
        effects.push("rolling".into());
    }
    // Only what the scene calls for: the tangential columns of F are condensed only with friction or rolling.
    let model = Model::new(scene);
    let (flex, bem_t) = condense(&model, blocks_for(scene))?;

    let tf = Instant::now();
    let problem = build_problem(scene, &model, &flex, path)?;
    let formulation_time = tf.elapsed().as_secs_f64();
    let moment_load = matches!(scene.drive.rotational(), Dof::Load(_));
    let (formulation, problem_size, asym) = match &problem {
        Problem::Frictionless(p) => ("frictionless", p.lcp.size(), asymmetry(&p.k)),
        Problem::SlidingLimit(p, _) => ("loading", p.lcp.size(), asymmetry(&p.k)),
        Problem::Frictional(p) => {
            let name = if p.loads.is_empty() { "displacement" } else { "loading" };
            let k = faer::Mat::from_fn(flex.n(), flex.n(), |i, j| flex.nn[(i, j)] / flex.weights[j]);
            (name, p.lcp.size(), asymmetry(&k))
        }
        Problem::GrossSliding(_) => ("loading", 0, 0.0),
    };
    let valid = |s: SolverName| -> std::result::Result<(), &'static str> {
        match s {
            SolverName::Lemke | SolverName::All => Ok(()),
            SolverName::Clarabel => match &problem {
                Problem::Frictionless(_) if !moment_load => Ok(()),
                Problem::Frictionless(_) => {
                    Err("the frictionless QP takes at most the normal load; this scene prescribes a moment")
                }
                _ => Err("it solves the frictionless QP; with friction use normtang_qp (NORM-TANG with clarabel QPs)"),
            },
            SolverName::Pgs | SolverName::NormtangQp => {
                if moment_load {
                    Err("the NORM-TANG split does not carry a prescribed moment (use lemke)")
                } else if matches!(problem, Problem::SlidingLimit(..)) {
                    Err("at the sliding limit |Q| = μP the problem is solved as full slip by lemke")
                } else {
                    Ok(())
                }
            }
        }
    };
    let solvers = resolve_solvers(scene, path, valid)?;
    let mut split: Option<Split> = None;

    let mut runs = Vec::new();
    for s in solvers {
        let t0 = Instant::now();
        let mut polish_change = None;
        let (status, message, work, sol): (Status, String, Work, Option<Solution>) = match (&problem, s) {
            (Problem::GrossSliding(msg), _) => (Status::Infeasible, msg.clone(), Work::default(), None),
            (Problem::Frictionless(p), SolverName::Lemke) | (Problem::SlidingLimit(p, _), SolverName::Lemke) => {
                let out = lemke::solve(&p.lcp, &scene.solvers.lemke);
                let (f, rigid) = p.unpack(&out.z);
                let limit = matches!(problem, Problem::SlidingLimit(..));
                let h = match &problem {
                    Problem::SlidingLimit(_, sigma) => Some(f.iter().map(|v| sigma * mu * v).collect()),
                    _ => None,
                };
                let msg = if limit {
                    format!(
                        "sliding limit |Q| = μP: every contact node slips (q = μp sgn Q); the tangential shift is \
                             indeterminate (reported null); {}",
                        out.message
                    )
                } else {
                    out.message
                };
                let (status, msg) = classify_ray(out.status, msg, scene, &model, &flex);
                (
                    status,
                    msg,
                    Work { pivots: Some(out.pivots), ..Default::default() },
                    Some(Solution { f, h, rigid, shift_known: !limit }),
                )
            }
            (Problem::Frictional(p), SolverName::Lemke) => {
                let (solved_by, out) = lemke_frictional(scene, &model, &flex, p);
                let (f, h, rigid) = solved_by.as_ref().unwrap_or(p).unpack(&out.z);
                let (status, msg) = classify_ray(out.status, out.message, scene, &model, &flex);
                (
                    status,
                    msg,
                    Work { pivots: Some(out.pivots), ..Default::default() },
                    Some(Solution { f, h: Some(h), rigid, shift_known: true }),
                )
            }
            (Problem::Frictionless(p), SolverName::Clarabel) => {
                let n = p.n();
                let kcol: Vec<f64> = (0..n * n).map(|idx| p.k[(idx % n, idx / n)]).collect();
                let ones = vec![1.0; n];
                let load = p.loads.first().map(|l| (ones.as_slice(), l.load));
                let out = clarabel_qp::solve_frictionless(&kcol, n, &p.q0, load, &scene.solvers.clarabel);
                let mut rigid = p.rigid_given;
                if let Some(d) = out.approach {
                    rigid[MODE_APPROACH] = d;
                }
                let pmax = out.f.iter().zip(&flex.weights).fold(0.0_f64, |a, (f, w)| a.max(f / w));
                polish_change = Some(
                    out.f
                        .iter()
                        .zip(&out.f_unpolished)
                        .zip(&flex.weights)
                        .fold(0.0_f64, |a, ((f, g), w)| a.max((f - g).abs() / w))
                        / pmax.max(f64::MIN_POSITIVE),
                );
                let (status, msg) = match &out.status {
                    QpStatus::Solved | QpStatus::AlmostSolved => (Status::Solved, format!("{}", out.status)),
                    QpStatus::MaxIterations => (Status::NotConverged, format!("{}", out.status)),
                    QpStatus::Infeasible => (Status::Infeasible, format!("{}", out.status)),
                    QpStatus::NumericalError(m) => (Status::NumericalError, m.clone()),
                };
                let msg =
                    format!("{msg}; active-set polish {}", if out.polished { "accepted" } else { "not accepted" });
                (
                    status,
                    msg,
                    Work { iterations: Some(out.iterations), ..Default::default() },
                    Some(Solution { f: out.f, h: None, rigid, shift_known: true }),
                )
            }
            (Problem::Frictionless(_) | Problem::Frictional(_), SolverName::Pgs | SolverName::NormtangQp) => {
                if split.is_none() {
                    split = Some(Split::new(scene, &model, &flex).map_err(|_| Error::Unsupported {
                        path: path.to_path_buf(),
                        message: "the NORM-TANG split does not carry a prescribed moment".into(),
                    })?);
                }
                let sp = split.as_ref().expect("built above");
                let inner = match s {
                    SolverName::Pgs => Inner::Pgs(scene.solvers.pgs),
                    _ => Inner::Qp(scene.solvers.normtang_qp.clone()),
                };
                let out = normtang::solve(sp, &inner);
                let work = match inner {
                    Inner::Pgs(_) => Work { sweeps: Some(out.sweeps), outer: Some(out.outer), ..Default::default() },
                    Inner::Qp(_) => {
                        Work { iterations: Some(out.qp_iterations), outer: Some(out.outer), ..Default::default() }
                    }
                };
                let sol = Solution { f: out.f, h: out.h, rigid: out.rigid, shift_known: true };
                (out.status, out.message, work, Some(sol))
            }
            (_, other) => unreachable!("{other:?} was filtered by resolve_solvers"),
        };
        let solve_time = t0.elapsed().as_secs_f64();
        let timing = Timing {
            assembly: bem_t.assembly,
            condensation: bem_t.condensation,
            formulation: formulation_time,
            solve: solve_time,
            total: bem_t.assembly + bem_t.condensation + formulation_time + solve_time,
        };
        runs.push(finish_run(
            scene,
            &model,
            &flex,
            s,
            formulation,
            problem_size,
            status,
            message,
            work,
            sol,
            timing,
            polish_change,
        ));
    }

    let hertz = if frictional { None } else { reference_hertz(scene, &runs) };
    let checks = make_checks(scene, &model, &runs, hertz.as_ref());
    let mesh = &model.mesh;
    Ok(Report {
        scene: scene.clone(),
        effects,
        mesh: MeshInfo {
            elements: mesh.elements.len(),
            nodes: mesh.n_nodes(),
            contact_nodes: flex.n(),
            element: mesh.kind,
            system_size: flex.system_size,
            contact_element_length: scene.wheel.radius * scene.mesh.contact_arc_deg.to_radians()
                / scene.mesh.contact_elements as f64,
        },
        diagnostics: diagnostics(&flex, asym),
        references: References { hertz },
        runs,
        checks,
    })
}

/// (check bound, refusal bound) on a run's largest residual: direct solvers are held to round-off, an iterative
/// solver to [`tol::ITERATIVE_RESIDUAL_FACTOR`] times its requested tolerance.
pub fn residual_bounds(scene: &Scene, solver: &str) -> (f64, f64) {
    let t = match solver {
        "pgs" => scene.solvers.pgs.tolerance,
        "normtang_qp" => scene.solvers.normtang_qp.tolerance,
        _ => 0.0,
    };
    let f = tol::ITERATIVE_RESIDUAL_FACTOR * t;
    (tol::RESIDUAL_DIRECT.max(f), tol::RESIDUAL_REFUSE.max(f))
}

/// Lemke on the frictional LCP with the default slack signs and, on a ray, with every other sign pattern of the
/// load-driven DOFs (the same solution set; see [`Frictional::with_signs`]). Returns the problem that was solved
/// (when a retry solved it) and the outcome, with the pivots of all attempts summed.
pub fn lemke_frictional(
    scene: &Scene,
    model: &Model,
    flex: &Flexibility,
    p: &Frictional,
) -> (Option<Frictional>, lemke::LemkeOutcome) {
    let mut out = lemke::solve(&p.lcp, &scene.solvers.lemke);
    let loads = p.loads.len();
    if out.status != Status::RayTermination || loads == 0 {
        return (None, out);
    }
    let mut pivots = out.pivots;
    for pattern in 1..(1usize << loads) {
        let mut signs = crate::formulation::DEFAULT_SIGNS;
        for (b, ld) in p.loads.iter().enumerate() {
            if pattern & (1 << b) != 0 {
                signs[ld.mode] = -ld.sign;
            }
        }
        let alt = Frictional::with_signs(scene, model, flex, signs);
        let o = lemke::solve(&alt.lcp, &scene.solvers.lemke);
        pivots += o.pivots;
        if o.status == Status::Solved {
            let msg =
                format!("{} (solved with flipped slack signs, attempt {} of {})", o.message, pattern + 1, 1 << loads);
            return (Some(alt), lemke::LemkeOutcome { pivots, message: msg, ..o });
        }
    }
    out.pivots = pivots;
    out.message = format!("{} ({} slack-sign patterns tried)", out.message, 1 << loads);
    (None, out)
}

/// Interpret Lemke's secondary ray. A ray proves infeasibility only for a copositive-plus M, which the frictional
/// LCPs are not (see [`Frictional::with_signs`]); so `infeasible` is reported only when it is proven, with the bound
/// that is violated:
/// - |Q| > μP with both prescribed (Coulomb: |Σh| ≤ μΣf);
/// - a prescribed moment beyond `|M| ≤ P·max|x| + μP·max|y + R| + R·|Q|` (with |Q| ≤ μP when Q is not prescribed),
///   which every static solution obeys since M = Σ(x f − y h) and Σh = Q;
/// - a frictionless LCP (copositive-plus: the ray is the proof).
///
/// Otherwise the status stays `ray_termination` and the message says that feasibility is undecided.
fn classify_ray(status: Status, message: String, scene: &Scene, model: &Model, flex: &Flexibility) -> (Status, String) {
    if status != Status::RayTermination {
        return (status, message);
    }
    let mu = scene.contact.friction;
    let r = scene.wheel.radius;
    let l0 = model.length;
    let xmax = flex.x.iter().fold(0.0_f64, |m, v| m.max(v.abs())) * l0;
    let ymax = flex.y.iter().fold(0.0_f64, |m, v| m.max((v * l0 + r).abs()));
    let (normal, tangential, rotational) = (scene.drive.normal(), scene.drive.tangential(), scene.drive.rotational());
    if let (Dof::Load(q), Dof::Load(p)) = (tangential, normal) {
        if q.abs() > mu * p {
            return (
                Status::Infeasible,
                format!("infeasible: |Q| = {:.6e} exceeds μP = {:.6e} (Lemke: {message})", q.abs(), mu * p),
            );
        }
    }
    if let (Dof::Load(m), Dof::Load(p)) = (rotational, normal) {
        let qterm = match tangential {
            Dof::Load(q) => q.abs(),
            Dof::Displacement(_) => mu * p,
        };
        let bound = p * xmax + mu * p * ymax + r * qterm;
        if m.abs() > bound {
            return (
                Status::Infeasible,
                format!(
                    "infeasible: the moment |M| = {:.6e} exceeds what any static state can carry, \
                     P·max|x| + μP·max|y + R| + R·|Q| = {bound:.6e} (the pressure centre would have to leave the \
                     candidate zone, |x| ≤ {xmax:.4e}: overturning) (Lemke: {message})",
                    m.abs()
                ),
            );
        }
    }
    // The frictionless LCP is copositive-plus (K nearly SPD, skew rigid-motion coupling): its ray is a proof. The
    // frictional LCPs are not copositive-plus (Frictional::with_signs), and a displacement-driven contact always has
    // a static solution, so their ray is a solver failure, not a diagnosis.
    if mu == 0.0 {
        return (
            Status::Infeasible,
            format!("infeasible: the LCP has no solution (Lemke's ray on a copositive-plus LCP: {message})"),
        );
    }
    (
        Status::RayTermination,
        format!(
            "Lemke ended on a secondary ray with every choice of slack signs; the frictional LCP is not copositive-plus, \
             so this does not prove that no static solution exists ({message})"
        ),
    )
}

#[allow(clippy::too_many_arguments)]
fn finish_run(
    scene: &Scene,
    model: &Model,
    flex: &Flexibility,
    solver: SolverName,
    formulation: &str,
    problem_size: usize,
    mut status: Status,
    mut message: String,
    work: Work,
    sol: Option<Solution>,
    timing: Timing,
    polish_change: Option<f64>,
) -> SolverRun {
    let ev: Option<Evaluation> = match (&sol, status) {
        (Some(x), Status::Solved) => Some(evaluate(scene, model, flex, &x.f, x.h.as_deref(), x.rigid, x.shift_known)),
        _ => None,
    };
    if let Some(ev) = &ev {
        let worst = ev.residuals.max();
        let refuse = residual_bounds(scene, solver.name()).1;
        if worst.is_nan() || worst > refuse {
            status = Status::NumericalError;
            message = format!(
                "solver reported success but the independent residual is {worst:.3e} > {refuse:.0e}; {message}"
            );
        }
    }
    let ev = ev.filter(|_| status == Status::Solved);
    SolverRun {
        solver: solver.name().into(),
        formulation: formulation.into(),
        status,
        message,
        problem_size,
        work,
        timing_s: timing,
        residuals: ev.as_ref().map(|e| e.residuals),
        resultants: ev.as_ref().map(|e| e.resultants),
        rigid_body: ev.as_ref().map(|e| e.rigid_body),
        contact: ev.as_ref().map(|e| e.contact.clone()),
        nodes: ev.map(|e| e.nodes).unwrap_or_default(),
        polish_change,
    }
}

/// Hertz at the scene's load, or at the first solved run's load when the approach is prescribed.
fn reference_hertz(scene: &Scene, runs: &[SolverRun]) -> Option<Hertz> {
    let w = &scene.wheel;
    let p = match scene.drive.normal() {
        Dof::Load(p) => Some(p),
        Dof::Displacement(_) => runs.iter().find_map(|r| r.resultants.map(|x| x.normal)),
    }?;
    (p > 0.0).then(|| Hertz::new(w.radius, w.youngs_modulus, w.poisson_ratio, p))
}

fn check(name: String, measured: f64, reference: f64, tolerance: f64) -> Check {
    let error = if reference != 0.0 { (measured - reference).abs() / reference.abs() } else { measured.abs() };
    Check { name, measured, reference, error, tolerance, pass: error <= tolerance }
}

fn make_checks(scene: &Scene, model: &Model, runs: &[SolverRun], hertz: Option<&Hertz>) -> Vec<Check> {
    let mut out = Vec::new();
    for r in runs {
        let expected = scene.checks.status_for(&r.solver);
        let ok = r.status == expected;
        out.push(Check {
            name: format!("{}: status {} (expected {})", r.solver, r.status, expected),
            measured: if ok { 0.0 } else { 1.0 },
            reference: 0.0,
            error: if ok { 0.0 } else { 1.0 },
            tolerance: 0.0,
            pass: ok,
        });
        let (Some(res), Some(resultants), Some(contact)) = (&r.residuals, &r.resultants, &r.contact) else {
            continue;
        };
        let bound = scene.checks.residual.unwrap_or(residual_bounds(scene, &r.solver).0);
        out.push(Check {
            name: format!("{}: largest residual (absolute)", r.solver),
            measured: res.max(),
            reference: 0.0,
            error: res.max(),
            tolerance: bound,
            pass: res.max() <= bound,
        });
        if let Dof::Load(p) = scene.drive.normal() {
            out.push(check(
                format!("{}: resultant P = normal_load", r.solver),
                resultants.normal,
                p,
                tol::LOAD_RESULTANT,
            ));
        }
        if let Some(h) = hertz {
            let hmesh =
                scene.wheel.radius * scene.mesh.contact_arc_deg.to_radians() / scene.mesh.contact_elements as f64;
            let across = 2.0 * h.half_width / hmesh;
            let applies =
                across >= tol::HERTZ_MIN_ELEMENTS && h.half_width / scene.wheel.radius <= tol::HERTZ_MAX_A_OVER_R;
            let t = scene.checks.hertz.unwrap_or(match model.mesh.kind {
                ElementKind::Constant => tol::HERTZ_CONSTANT,
                ElementKind::Quadratic => tol::HERTZ_QUADRATIC,
            });
            if applies {
                if let (Some(a), Some(p0)) = (contact.fit_half_width, contact.fit_peak_pressure) {
                    out.push(check(format!("{}: Hertz half-width a (fit)", r.solver), a, h.half_width, t));
                    out.push(check(format!("{}: Hertz peak pressure p0 (fit)", r.solver), p0, h.peak_pressure, t));
                }
            }
        }
    }
    // Cattaneo–Mindlin where it applies.
    if crate::references::cattaneo_applies(scene) {
        let t = scene.checks.cattaneo_elements.unwrap_or(tol::CATTANEO_ELEMENTS);
        for r in runs.iter().filter(|r| r.contact.is_some()) {
            let m = crate::references::metrics(scene, r);
            if let (Some(c), Some(ce), Some(err), Some(centre)) =
                (m.cm_c_over_a, m.cm_c_over_a_exact, m.cm_c_err_elements, m.cm_centre_elements)
            {
                out.push(Check {
                    name: format!("{}: Cattaneo–Mindlin c/a (error in elements)", r.solver),
                    measured: c,
                    reference: ce,
                    error: err.abs(),
                    tolerance: t,
                    pass: err.abs() <= t,
                });
                out.push(Check {
                    name: format!("{}: Cattaneo–Mindlin stick-zone centre (elements)", r.solver),
                    measured: centre,
                    reference: 0.0,
                    error: centre.abs(),
                    tolerance: t,
                    pass: centre.abs() <= t,
                });
            } else {
                out.push(Check {
                    name: format!("{}: Cattaneo–Mindlin stick zone exists", r.solver),
                    measured: 0.0,
                    reference: 1.0,
                    error: 1.0,
                    tolerance: 0.0,
                    pass: false,
                });
            }
        }
    }
    // Solvers against each other: pressures and shears relative to the peak pressure.
    let solved: Vec<&SolverRun> = runs.iter().filter(|r| r.contact.is_some()).collect();
    for i in 0..solved.len() {
        for j in i + 1..solved.len() {
            let (a, b) = (solved[i], solved[j]);
            let p0 = a.contact.as_ref().map(|c| c.pressure_scale).unwrap_or(0.0).max(f64::MIN_POSITIVE);
            let d = a
                .nodes
                .iter()
                .zip(&b.nodes)
                .fold(0.0_f64, |m, (x, y)| m.max((x.pressure - y.pressure).abs()).max((x.shear - y.shear).abs()))
                / p0;
            let t = scene.checks.agreement.unwrap_or(tol::SOLVER_AGREEMENT);
            out.push(Check {
                name: format!("{} vs {}: max |Δp|, |Δq| / p_max", a.solver, b.solver),
                measured: d,
                reference: 0.0,
                error: d,
                tolerance: t,
                pass: d <= t,
            });
            // Active sets: nodes both solvers call decisively but differently.
            let mu = scene.contact.friction;
            let decisive = |n: &NodeResult| {
                let pm = p0 * tol::STATE_MARGIN;
                (n.pressure <= 0.0 || n.pressure > pm) && (n.shear.abs() - mu * n.pressure).abs() > mu * pm
            };
            let mismatched =
                a.nodes.iter().zip(&b.nodes).filter(|(x, y)| x.state != y.state && decisive(x) && decisive(y)).count();
            out.push(Check {
                name: format!("{} vs {}: nodes in different states (stick/slip/separated)", a.solver, b.solver),
                measured: mismatched as f64,
                reference: 0.0,
                error: mismatched as f64,
                tolerance: 0.0,
                pass: mismatched == 0,
            });
        }
    }
    out
}

/// Write `text` to `path` atomically (temporary file in the same folder, then rename): nothing half-written.
pub fn write_atomic(path: &Path, text: &str) -> Result<()> {
    let dir = path.parent().filter(|p| !p.as_os_str().is_empty()).unwrap_or(Path::new("."));
    let name = path.file_name().map(|n| n.to_string_lossy().into_owned()).unwrap_or_else(|| "out".into());
    let tmp = dir.join(format!(".{name}.tmp-{}", std::process::id()));
    std::fs::write(&tmp, text).map_err(|source| Error::Write { path: path.to_path_buf(), source })?;
    std::fs::rename(&tmp, path).map_err(|source| {
        let _ = std::fs::remove_file(&tmp);
        Error::Write { path: path.to_path_buf(), source }
    })
}
