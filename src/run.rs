//! The pipeline for one scene: flexibility source → contact problem → every requested solver → post-processing →
//! checks, producing the result document ([`Report`]).
//!
//! Only the effects the scene calls for are simulated: a frictionless scene builds only the normal columns of the
//! flexibility ([`Blocks::Normal`]), a problem of one unknown per contact node (plus two per load-driven rigid
//! degree of freedom) and does no tangential or rolling work; `effects` and `problem_size` in the report show it.

use crate::checks::make_checks;
use crate::diagnostics::{asymmetry, diagnose};
use crate::error::{Error, Result};
use crate::formulation::{ContactProblem, DriveIssue, Lcp, ProblemKind, SlipOperator};
use crate::hertz::Hertz;
use crate::post::{evaluate, RollingPost};
use crate::results::{MeshInfo, References, Report, SolverName, SolverRun, Timing};
use crate::scene::{BodyModel, Dof, RollingMode, Scene};
use crate::solvers::{Outcome, Solver, Status, Work, REGISTRY};
use crate::source::{self, Blocks};
use std::path::Path;
use std::time::Instant;

/// Which flexibility blocks the scene needs: the tangential columns only with friction or rolling.
pub fn blocks_for(scene: &Scene) -> Blocks {
    if scene.contact.friction > 0.0 || scene.rolling.is_some() {
        Blocks::All
    } else {
        Blocks::Normal
    }
}

/// The rolling post-processing a scene asks for.
pub fn rolling_post(scene: &Scene) -> Option<RollingPost> {
    scene.rolling.as_ref().map(|r| match r.mode {
        RollingMode::Steady => RollingPost::Steady,
        RollingMode::Seed => RollingPost::Seed {
            creepage: r.creepage.expect("validated: seed mode has a creepage"),
            direction: r.direction,
        },
        // A history sets the rolled distance per step (crate::history); this is the one-step default.
        RollingMode::Transient => RollingPost::Transient { creepage: r.creepage.unwrap_or(0.0), roll: 0.0 },
    })
}

/// The slip operator of a scene on a flexibility: steady rolling's upwind slip velocity, or the static slip.
pub fn slip_operator(scene: &Scene, flex: &crate::flexibility::Flexibility) -> SlipOperator {
    match &scene.rolling {
        Some(r) if r.mode == RollingMode::Steady => SlipOperator::steady(&flex.x, r.direction),
        _ => SlipOperator::static_slip(),
    }
}

/// Build the scene's contact problem on a flexibility (an unformulable drive is an input error naming the key).
pub fn build_problem<'a>(
    scene: &Scene,
    flex: &'a crate::flexibility::Flexibility,
    path: &Path,
) -> Result<ContactProblem<'a>> {
    ContactProblem::new(flex, scene.law(), scene.drive_dofs(), slip_operator(scene, flex))
        .map_err(|DriveIssue::TangentialLoadWithoutFriction(_)| drive_error(scene, path))
}

/// The input error of a tangential load on a frictionless contact.
pub fn drive_error(scene: &Scene, path: &Path) -> Error {
    let key = if scene.steps.is_empty() { "drive.tangential_load" } else { "steps[].tangential_load" };
    Error::Unsupported {
        path: path.to_path_buf(),
        message: format!(
            "{key}: a frictionless contact carries no tangential load (gross sliding); use a zero tangential load \
             or friction > 0"
        ),
    }
}

/// Build the scene's solvers (`solvers.use`): `all` expands to every solver of the registry's `all` set that
/// applies to the problem; an explicitly named solver that does not apply is an error naming `solvers.use` and the
/// reason; a bad setting is an input error naming its key. Registry order, no duplicates.
pub fn solvers_for(scene: &Scene, problem: &ContactProblem, path: &Path) -> Result<Vec<Box<dyn Solver>>> {
    let invalid = |e: crate::solvers::SettingsError| e.into_error(path);
    let mut out = Vec::new();
    for e in REGISTRY {
        let named = scene.solvers.use_.iter().any(|u| u == e.name);
        let all = e.in_all && scene.solvers.use_.iter().any(|u| u == "all");
        if !named && !all {
            continue;
        }
        let solver = scene.solvers.build(e.name).map_err(invalid)?;
        match solver.applies(problem) {
            Ok(()) => out.push(solver),
            Err(why) if named => {
                return Err(Error::Unsupported {
                    path: path.to_path_buf(),
                    message: format!("solvers.use: {} does not apply to this scene: {why}", e.name),
                })
            }
            Err(_) => {}
        }
    }
    if let Some(u) = scene.solvers.use_.iter().find(|u| *u != "all" && crate::solvers::entry(u).is_none()) {
        return Err(invalid(crate::solvers::SettingsError {
            unknown: true,
            field: "solvers.use".into(),
            message: format!("unknown solver `{u}` (expected one of: all, {})", crate::solvers::names()),
        }));
    }
    Ok(out)
}

/// (check bound, refusal bound) of a scene's solver by name, with the scene's settings
/// ([`crate::solvers::residual_bounds`]).
///
/// # Panics
/// If the solver is not registered or its settings are invalid (a validated scene's are not).
pub fn residual_bounds(scene: &Scene, solver: &str) -> (f64, f64) {
    let s = scene.solvers.build(solver).expect("a registered solver with valid settings");
    crate::solvers::residual_bounds(s.as_ref())
}

/// The LCP that Lemke solves for a scene (for `rollbem lcp export`): frictionless, frictional (displacement,
/// loading or mixed, with the slack signs of the attempt that succeeded) or the sliding-limit problem. A scene
/// beyond gross sliding has no LCP.
pub fn scene_lcp(scene: &Scene, path: &Path) -> Result<Lcp> {
    let built = source::build(scene, blocks_for(scene))?;
    let problem = build_problem(scene, &built.flex, path)?;
    let settings =
        crate::solvers::parse_settings("lemke", scene.solvers.settings.get("lemke")).map_err(|e| e.into_error(path))?;
    let lemke = crate::solvers::lemke::Lemke { name: "lemke", settings, engine: crate::solvers::lemke::solve };
    lemke.solved_lcp(&problem).ok_or_else(|| match &problem.kind {
        ProblemKind::GrossSliding { message } => {
            Error::Unsupported { path: path.to_path_buf(), message: format!("no static problem to export: {message}") }
        }
        _ => unreachable!("every other problem has an LCP"),
    })
}

/// The effects a scene simulates.
pub fn effects(scene: &Scene) -> Vec<String> {
    let mut effects = vec!["normal".to_string()];
    if scene.contact.friction > 0.0 {
        effects.push("friction".into());
        if scene.contact.coupling {
            effects.push("coupling".into());
        }
    }
    if scene.rolling.is_some() {
        effects.push("rolling".into());
    }
    if scene.counter_body != crate::scene::CounterBody::Rigid {
        effects.push("counter_body".into());
    }
    if !scene.steps.is_empty() {
        effects.push("history".into());
    }
    if scene.stresses.is_some() {
        effects.push("stresses".into());
    }
    effects
}

/// Run a validated scene (one step from rest, or a load path: [`crate::history`]). `path` is used in error
/// messages.
pub fn run_scene(scene: &Scene, path: &Path) -> Result<Report> {
    if !scene.steps.is_empty() {
        return crate::history::run_history(scene, path);
    }
    let built = source::build(scene, blocks_for(scene))?;
    let flex = &built.flex;
    let tf = Instant::now();
    let problem = build_problem(scene, flex, path)?;
    let formulation_time = tf.elapsed().as_secs_f64();
    let problem_size = problem.lcp_size();
    let solvers = solvers_for(scene, &problem, path)?;
    let rolling = rolling_post(scene);
    let stresses = crate::stresses::StressEvaluator::new(scene, &built, path)?;
    let mut runs = Vec::new();
    let mut bounds = Vec::new();
    for solver in &solvers {
        let (outcome, solve_time) = solve_timed(solver.as_ref(), &problem);
        let formulation = formulation_time + lcp_time(solver.as_ref(), &problem);
        let timing = Timing {
            assembly: built.timing.assembly,
            condensation: built.timing.condensation,
            formulation,
            solve: solve_time,
            total: built.timing.assembly + built.timing.condensation + formulation + solve_time,
        };
        let (check_bound, refuse_bound) = crate::solvers::residual_bounds(solver.as_ref());
        let (mut run, _) =
            evaluate_outcome(scene, &problem, solver.name(), problem_size, outcome, timing, refuse_bound, rolling);
        add_stresses(&mut run, stresses.as_ref());
        runs.push(run);
        bounds.push(check_bound);
    }
    Ok(assemble_report(
        scene,
        &built,
        normal_asymmetry(&problem, scene.wheel.model == BodyModel::HalfPlane),
        runs,
        &bounds,
        Vec::new(),
    ))
}

/// Evaluate a solved run's subsurface stresses when the scene asks for them (`[stresses]`).
pub fn add_stresses(run: &mut SolverRun, stresses: Option<&crate::stresses::StressEvaluator>) {
    if let (Some(ev), Status::Solved) = (stresses, run.status) {
        run.stresses = Some(ev.evaluate(&run.nodes));
    }
}

/// The time to build the problem's LCP if the solver uses it (built once, before the solve: see
/// [`solve_timed`]), else 0.
pub fn lcp_time(solver: &dyn Solver, problem: &ContactProblem) -> f64 {
    if solver.uses_lcp() {
        problem.lcp_build_time().unwrap_or(0.0)
    } else {
        0.0
    }
}

/// Solve a problem with a solver, timed (the solve only: the LCP a solver uses is built before the clock starts);
/// a problem beyond gross sliding is `infeasible` without a solve.
pub fn solve_timed(solver: &dyn Solver, problem: &ContactProblem) -> (Outcome, f64) {
    if solver.uses_lcp() && !matches!(problem.kind, ProblemKind::GrossSliding { .. }) {
        let _stage = crate::progress::stage(|| format!("building the LCP ({} unknowns)", problem.lcp_size()));
        problem.lcp();
    }
    let _stage = crate::progress::stage(|| format!("{}: solving ({} unknowns)", solver.name(), problem.lcp_size()));
    let t0 = Instant::now();
    let outcome = match &problem.kind {
        ProblemKind::GrossSliding { message } => Outcome {
            solution: None,
            status: Status::Infeasible,
            message: message.clone(),
            work: Work::default(),
            polish_change: None,
        },
        _ => solver.solve(problem),
    };
    (outcome, t0.elapsed().as_secs_f64())
}

/// The asymmetry of the normal flexibility K_NN: the collocation asymmetry the mesh controls, whatever problem is
/// solved (at the sliding limit the normal problem's matrix K_NN + σμK_NT is nonsymmetric by friction, not by the
/// mesh; beyond it no problem is solved, and the flexibility's health is still reported).
///
/// On the half-plane model (`half_plane`) the displacements are relative to a datum point below the contact, which
/// adds a rank-one column term u cᵀ to K_NN (u the approach's gap vector: every node moves by the datum's motion
/// under the load at node j, c_j). It is physics, not a mesh error, and under load control the approach absorbs it
/// (K_NN p and (K_NN + u cᵀ) p differ by the uniform (cᵀp)u). So when the normal load is prescribed, the asymmetry is
/// measured on the part that matters, P K_NN P with P = I − ûûᵀ the projector orthogonal to the approach's gap
/// vector (P u cᵀ P = 0); with the approach prescribed the full K_NN is measured and the warning says what it is
/// ([`crate::diagnostics::diagnose`]).
pub fn normal_asymmetry(problem: &ContactProblem, half_plane: bool) -> f64 {
    let k = &problem.flex.k_nn;
    let load_driven = matches!(problem.drive.normal, crate::formulation::Dof::Load(_));
    let approach = problem.flex.mode(crate::flexibility::ModeKind::Approach);
    match (half_plane && load_driven, approach) {
        (true, Some(m)) => asymmetry(&project_out(k, &m.normal)),
        _ => asymmetry(k),
    }
}

/// P K P with P = I − ûûᵀ, û = u/|u| (K unchanged when u = 0).
fn project_out(k: &faer::Mat<f64>, u: &[f64]) -> faer::Mat<f64> {
    let n = k.nrows();
    let norm = u.iter().map(|v| v * v).sum::<f64>().sqrt();
    if norm == 0.0 || u.len() != n {
        return k.clone();
    }
    let uh: Vec<f64> = u.iter().map(|v| v / norm).collect();
    // K P = K − (K û) ûᵀ, then P (K P) = K P − û (ûᵀ K P).
    let ku: Vec<f64> = (0..n).map(|i| (0..n).map(|j| k[(i, j)] * uh[j]).sum()).collect();
    let kp = faer::Mat::from_fn(n, n, |i, j| k[(i, j)] - ku[i] * uh[j]);
    let ukp: Vec<f64> = (0..n).map(|j| (0..n).map(|i| uh[i] * kp[(i, j)]).sum()).collect();
    faer::Mat::from_fn(n, n, |i, j| kp[(i, j)] - uh[i] * ukp[j])
}

/// The result document of a scene from its runs (and a load path's steps): references, checks, mesh facts and
/// health. `bounds[k]` is run k's residual check bound.
pub fn assemble_report(
    scene: &Scene,
    built: &source::Built,
    asym: f64,
    runs: Vec<SolverRun>,
    bounds: &[f64],
    steps: Vec<crate::results::StepResult>,
) -> Report {
    let flex = &built.flex;
    let hertz = if scene.contact.friction > 0.0 { None } else { reference_hertz(scene, &runs) };
    let checks =
        make_checks(scene, built.info.element, built.info.contact_element_length, &runs, bounds, hertz.as_ref());
    Report {
        scene: scene.clone(),
        effects: effects(scene),
        mesh: MeshInfo {
            model: scene.wheel.model,
            elements: built.info.elements,
            nodes: built.info.nodes,
            contact_nodes: flex.n(),
            element: built.info.element,
            system_size: built.info.system_size,
            contact_element_length: built.info.contact_element_length,
        },
        diagnostics: diagnose(flex, &built.info, asym),
        references: References { hertz, dundurs_beta: scene.dundurs_beta() },
        runs,
        checks,
        steps,
    }
}

/// Post-process a solver's outcome as `run_scene` does — evaluate a claimed solution by the solver-independent
/// residuals and refuse it above `refuse` (`numerical_error`); judge an accepted one by the range of the model
/// ([`crate::validity::judge`]: linearised kinematics, candidate zone); decide a failed load-driven solve exactly
/// ([`crate::validity::decide`]) — returning also the evaluation of an accepted solution (a load path carries its
/// state on).
#[allow(clippy::too_many_arguments)]
pub fn evaluate_outcome(
    scene: &Scene,
    problem: &ContactProblem,
    solver: &'static str,
    problem_size: usize,
    outcome: Outcome,
    timing: Timing,
    refuse: f64,
    rolling: Option<RollingPost>,
) -> (SolverRun, Option<crate::post::Evaluation>) {
    let Outcome { solution, mut status, mut message, work, polish_change } = outcome;
    let ev = match (&solution, status) {
        (Some(sol), Status::Solved) => Some(evaluate(problem, sol, rolling)),
        _ => None,
    };
    if let Some(ev) = &ev {
        let worst = ev.residuals.max();
        if worst.is_nan() || worst > refuse {
            status = Status::NumericalError;
            message = format!(
                "solver reported success but the independent residual is {worst:.3e} > {refuse:.0e}; {message}"
            );
        }
    }
    if let (Some(ev), Status::Solved) = (&ev, status) {
        if let Some((judged, why)) = crate::validity::judge(scene, problem, ev) {
            status = judged;
            message = format!("{why}; {solver}: {message}");
        }
    }
    if let Some((decided, why)) = crate::validity::decide(problem, solver, status, &message) {
        status = decided;
        message = why;
    }
    // A run judged `contact_at_zone_edge` or `kinematics_out_of_range` keeps its nodal values (and only those:
    // no resultants, contact summary or residuals, so no check, comparison or metric treats it as an answer): they
    // are the evidence for the verdict (the pressure at the zone's edge, the collapsed contact) that the user
    // needs to see in the JSON, `run --csv` and `rollbem plot`.
    let flagged_nodes = match (&ev, status) {
        (Some(e), Status::ContactAtZoneEdge | Status::KinematicsOutOfRange) => e.nodes.clone(),
        _ => Vec::new(),
    };
    let ev = ev.filter(|_| status == Status::Solved);
    let run = SolverRun {
        solver: SolverName(solver),
        formulation: problem.formulation(),
        status,
        message,
        problem_size,
        work,
        timing_s: timing,
        residuals: ev.as_ref().map(|e| e.residuals),
        resultants: ev.as_ref().map(|e| e.resultants),
        rigid_body: ev.as_ref().map(|e| e.rigid_body),
        contact: ev.as_ref().map(|e| e.contact.clone()),
        rolling: ev.as_ref().and_then(|e| e.rolling),
        nodes: ev.as_ref().map(|e| e.nodes.clone()).unwrap_or(flagged_nodes),
        polish_change,
        history: None,
        stresses: None,
    };
    (run, ev)
}

/// Hertz at the scene's load, or at the first solved run's load when the approach is prescribed.
fn reference_hertz(scene: &Scene, runs: &[SolverRun]) -> Option<Hertz> {
    let p = match scene.drive.normal() {
        Dof::Load(p) => Some(p),
        Dof::Displacement(_) => runs.iter().find_map(|r| r.resultants.map(|x| x.normal)),
    }?;
    (p > 0.0).then(|| Hertz::with_modulus(scene.wheel.radius, scene.contact_modulus(), p))
}
