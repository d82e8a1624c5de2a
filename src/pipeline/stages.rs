//! The stages every solve shares, one function each: which flexibility blocks a scene needs, its contact problem,
//! its solvers, a timed solve, the harness's verdict on an outcome, and the result document. The one-step solve
//! (`super::single`) and the load path (`super::path`) are built from these; neither calls the other.

use crate::checks::{make_checks, ModelReference};
use crate::diagnostics::{asymmetry, diagnose};
use crate::error::{Error, Result};
use crate::formulation::{ContactLaw, ContactProblem, Drive, DriveIssue, ProblemKind, SlipOperator};
use crate::post::{evaluate, Evaluation, RollingPost};
use crate::results::{EffectNote, MeshInfo, ProblemClass, References, Report, SolverRun, Timing};
use crate::scene::{BodyModel, CounterBody, Dof, Rolling, Scene};
use crate::solvers::{Outcome, Solver, SolverId, Start, Termination, Work};
use crate::source::{Blocks, Built};
use crate::status::{Status, Verdict, VerdictReason};
use crate::theory::Hertz2D;
use std::time::Instant;

/// The contact law the pipeline simulates: the scene's ([`Scene::law`]), without normal–tangential coupling where the
/// pair's cross flexibilities vanish identically (`crate::source::half_plane::cross_blocks_vanish`: two half-planes
/// of one material and datum depth, or a strip pair with Dundurs' β = 0). The coupled path would then build two more
/// n × n blocks and iterate the normal and tangential problems jointly for the same answer; the uncoupled path solves
/// the normal problem once and the stick–slip problem at fixed pressure. The run's `effect_notes` say so.
pub fn simulated_law(scene: &Scene) -> ContactLaw {
    let mut law = scene.law();
    law.coupling = law.coupling && !crate::source::half_plane::cross_blocks_vanish(scene);
    law
}

/// Which flexibility blocks the scene needs: the tangential columns only with friction or rolling, the coupling
/// blocks only when coupling is simulated as well ([`simulated_law`]).
pub fn blocks_for(scene: &Scene) -> Blocks {
    if scene.friction() <= 0.0 && scene.rolling().is_none() {
        Blocks::Normal
    } else if simulated_law(scene).coupling {
        Blocks::All
    } else {
        Blocks::Uncoupled
    }
}

/// The rolling post-processing a one-step scene asks for.
pub fn rolling_post(scene: &Scene) -> Option<RollingPost> {
    scene.rolling().map(|r| match *r {
        Rolling::Steady { .. } => RollingPost::Steady,
        Rolling::Seed { creepage, direction } => RollingPost::Seed { creepage, direction },
        // A load path sets the rolled distance per step (super::path); this is the one-step default.
        Rolling::Transient { creepage, .. } => RollingPost::Transient { creepage, roll: 0.0 },
    })
}

/// The slip operator of a scene on a flexibility: steady rolling's upwind slip velocity, or the static slip.
pub fn slip_operator(scene: &Scene, flex: &crate::flexibility::Flexibility) -> SlipOperator {
    match scene.rolling() {
        // The flat's upwind operator; with two finite bodies plus the turning of the pair's frame.
        Some(Rolling::Steady { direction, .. }) => crate::source::two_body::steady_slip(flex, *direction),
        _ => SlipOperator::static_slip(),
    }
}

/// Build the contact problem of a drive on a flexibility (an unformulable drive is an input error naming the key).
pub fn build_problem<'a>(
    scene: &Scene,
    flex: &'a crate::flexibility::Flexibility,
    drive: Drive,
    slip: SlipOperator,
) -> Result<ContactProblem<'a>> {
    ContactProblem::new(flex, simulated_law(scene), drive, slip).map_err(|e| match e {
        DriveIssue::TangentialLoadWithoutFriction(_) => drive_error(scene),
        other => Error::Unsupported {
            path: scene.origin().to_path_buf(),
            message: format!("{other} (a flexibility built for another scene?)"),
        },
    })
}

/// The contact problem of a one-step scene on a flexibility (its drive and slip operator); a load path has none
/// (an error saying so).
pub fn scene_problem<'a>(scene: &Scene, flex: &'a crate::flexibility::Flexibility) -> Result<ContactProblem<'a>> {
    let Some(drive) = scene.drive() else {
        return Err(Error::Unsupported {
            path: scene.origin().to_path_buf(),
            message: "steps: a load path poses one problem per substep, not one".into(),
        });
    };
    build_problem(scene, flex, *drive, slip_operator(scene, flex))
}

/// The input error of a tangential load on a frictionless contact.
pub fn drive_error(scene: &Scene) -> Error {
    let key = if scene.steps().is_empty() { "drive.tangential_load" } else { "steps[].tangential_load" };
    Error::Unsupported {
        path: scene.origin().to_path_buf(),
        message: format!(
            "{key}: a frictionless contact carries no tangential load (gross sliding); use a zero tangential load \
             or friction > 0"
        ),
    }
}

/// Build the scene's solvers (`solvers.use`): `all` expands to every solver of the registry's `all` set that
/// applies to the problem; an explicitly named solver that does not apply is an error naming `solvers.use` and the
/// reason. Registry order, no duplicates. The settings were validated with the scene, so building cannot fail.
pub fn solvers_for(scene: &Scene, problem: &ContactProblem) -> Result<Vec<Box<dyn Solver>>> {
    let set = scene.solvers();
    let mut out = Vec::new();
    for e in crate::solvers::registry() {
        let named = set.names(e.id);
        if !(named || set.all && e.in_all) {
            continue;
        }
        let Some(solver) = e.id.build(&set.settings) else { continue };
        match solver.applies(problem) {
            Ok(()) => out.push(solver),
            Err(why) if named => {
                return Err(Error::Unsupported {
                    path: scene.origin().to_path_buf(),
                    message: format!("solvers.use: {} does not apply to this scene: {why}", e.name()),
                })
            }
            Err(_) => {}
        }
    }
    if out.is_empty() {
        return Err(Error::Unsupported {
            path: scene.origin().to_path_buf(),
            message: "solvers.use: no requested solver applies to this scene".into(),
        });
    }
    Ok(out)
}

/// (check bound, refusal bound) of a scene's solver, with the scene's settings
/// ([`crate::solvers::residual_bounds`]).
pub fn residual_bounds(scene: &Scene, solver: SolverId) -> (f64, f64) {
    match solver.build(&scene.solvers().settings) {
        Some(s) => crate::solvers::residual_bounds(s.as_ref()),
        None => (crate::tolerances::RESIDUAL_DIRECT, crate::tolerances::RESIDUAL_REFUSE),
    }
}

/// The effects a scene simulates (names, in a fixed order: `normal`, `friction`, `coupling`, `rolling`,
/// `counter_body`, `history`, `stresses`) and, for each effect beyond the normal problem, whether it is simulated and
/// why ([`EffectNote`]): what the scene asks for and what the physics needs.
pub fn effects(scene: &Scene) -> (Vec<String>, Vec<EffectNote>) {
    let mut notes = Vec::new();
    let mut note = |effect: &str, asked: bool, simulated: bool, why: String| {
        notes.push(EffectNote { effect: effect.into(), asked, simulated, why });
    };
    let mu = scene.friction();
    note(
        "friction",
        mu > 0.0,
        mu > 0.0,
        match (mu > 0.0, scene.rolling().is_some()) {
            (true, _) => format!("Coulomb friction, μ = {mu}"),
            (false, false) => "frictionless (μ = 0): the normal problem only, no tangential flexibility built".into(),
            (false, true) => "frictionless (μ = 0): no shear; the tangential flexibility is built for the rolling \
                              slip velocity"
                .into(),
        },
    );
    let blocks = blocks_for(scene);
    let asked = scene.law().coupling;
    let why = match (blocks, asked) {
        (Blocks::Normal, _) => "no tangential problem (frictionless, no rolling)".to_string(),
        (Blocks::All, _) => {
            format!("normal–tangential cross flexibilities kept (Dundurs β = {:.6})", scene.dundurs_beta())
        }
        (_, false) => "`[contact] coupling = false`: the cross flexibilities are dropped".into(),
        (_, true) => format!(
            "the pair's cross flexibilities vanish identically ({}): the uncoupled path gives the same answer, \
             without building them",
            if scene.strip_width().is_some() {
                "a strip pair with Dundurs β = 0"
            } else {
                "two half-planes of one material and datum depth, Dundurs β = 0"
            }
        ),
    };
    note("coupling", asked && blocks != Blocks::Normal, blocks == Blocks::All, why);
    let rolling = scene.rolling().map(|r| format!("{:?} rolling", r.mode()).to_lowercase());
    note("rolling", rolling.is_some(), rolling.is_some(), rolling.unwrap_or_else(|| "static (no `[rolling]`)".into()));
    let elastic = *scene.counter_body() != CounterBody::Rigid;
    let what = match scene.counter_body() {
        CounterBody::Rigid => "a rigid flat",
        CounterBody::Disc { .. } => "a finite elastic counter-disc (BEM)",
        CounterBody::Bore { .. } => "a plate with a bore (BEM)",
        _ => "an elastic half-plane counter-body",
    };
    note("counter_body", elastic, elastic, what.into());
    let steps = scene.steps().len();
    let what = if steps > 0 { format!("a load path of {steps} steps") } else { "one step from rest".into() };
    note("history", steps > 0, steps > 0, what);
    let stress = scene.stresses().map(|s| format!("subsurface stresses on {} points", s.n_points()));
    note("stresses", stress.is_some(), stress.is_some(), stress.unwrap_or_else(|| "no `[stresses]` table".into()));
    let mut names = vec!["normal".to_string()];
    names.extend(notes.iter().filter(|n| n.simulated).map(|n| n.effect.clone()));
    (names, notes)
}

/// Evaluate a solved run's subsurface stresses when the scene asks for them (`[stresses]`). A run of another model
/// than the evaluator's (other contact nodes) is refused ([`crate::stresses::StressEvaluator::evaluate`]).
pub fn add_stresses(run: &mut SolverRun, stresses: Option<&crate::stresses::StressEvaluator>) -> Result<()> {
    if let (Some(ev), Status::Solved) = (stresses, run.status) {
        run.stresses = Some(ev.evaluate(&run.nodes)?);
        run.counter_body_stresses = ev.evaluate_counter_body(&run.nodes)?;
    }
    Ok(())
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

/// Solve a problem with a solver from a start, timed (the solve only: the LCP a solver uses is built before the clock
/// starts); a problem beyond gross sliding is `infeasible` without a solve.
pub fn solve_timed(solver: &dyn Solver, problem: &ContactProblem, start: Start) -> (Outcome, f64) {
    if solver.uses_lcp() && !matches!(problem.kind, ProblemKind::GrossSliding { .. }) {
        let _stage = crate::progress::stage(|| format!("building the LCP ({} unknowns)", problem.lcp_size()));
        problem.lcp();
    }
    let _stage = crate::progress::stage(|| format!("{}: solving ({} unknowns)", solver.name(), problem.lcp_size()));
    let t0 = Instant::now();
    let outcome = match &problem.kind {
        ProblemKind::GrossSliding { message } => {
            Outcome::failed(Termination::Infeasible, message.clone(), Work::default())
        }
        _ => solver.solve_from(problem, start),
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
/// (`crate::diagnostics::diagnose`).
pub fn normal_asymmetry(problem: &ContactProblem, half_plane: bool) -> f64 {
    let k = &problem.flex.k_nn;
    let load_driven = matches!(problem.drive.normal, Dof::Load(_));
    let approach = problem.flex.mode(crate::flexibility::ModeKind::Approach);
    match (half_plane && load_driven, approach) {
        (true, Some(m)) => problem.flex.derived.asymmetry(true, || asymmetry(&project_out(k, &m.normal))),
        _ => problem.flex.derived.asymmetry(false, || asymmetry(k)),
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
    built: &Built,
    asym: f64,
    runs: Vec<SolverRun>,
    bounds: &[f64],
    steps: Vec<crate::results::StepResult>,
) -> Report {
    let flex = &built.flex;
    let hertz = if crate::references::hertz_applies(scene) { reference_hertz(scene, &runs) } else { None };
    let (element, length) = (built.info.element, built.info.contact_element_length);
    // A finite wheel compared with a half-space theory: the same loads on the half-plane counterpart give the model
    // error beside the comparison (`checks::ModelReference`).
    let counterpart = crate::references::half_space_counterpart(scene).and_then(|s| s.ok());
    let counterpart_report = counterpart.as_ref().and_then(|s| super::run_scene(s).ok());
    let model = counterpart
        .as_ref()
        .map(|s| ModelReference { scene: s, run: counterpart_report.as_ref().and_then(|r| r.runs.first()) });
    let checks = make_checks(scene, element, length, &runs, bounds, hertz.as_ref(), model.as_ref());
    let warnings = crate::checks::run_warnings(scene, element, length, &runs);
    let (effects, effect_notes) = effects(scene);
    Report {
        schema: crate::results::SCHEMA_VERSION,
        scene: scene.clone(),
        effects,
        effect_notes,
        mesh: MeshInfo {
            model: scene.model(),
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
        warnings,
    }
}

/// What a run's post-processing needs beside the outcome: the scene, the problem, the solver, its timing and the
/// bound above which a claimed solution is refused.
pub struct RunContext<'a, 'p> {
    /// The scene.
    pub scene: &'a Scene,
    /// The problem solved.
    pub problem: &'a ContactProblem<'p>,
    /// Which solver.
    pub solver: SolverId,
    /// Time per stage.
    pub timing: Timing,
    /// Refusal bound of the largest solver-independent residual.
    pub refuse: f64,
    /// The rolling post-processing.
    pub rolling: Option<RollingPost>,
}

/// Post-process a solver's outcome — evaluate a claimed solution by the solver-independent residuals and refuse
/// it above the refusal bound (`numerical_error`); judge an accepted one by the range of the model
/// (`crate::validity::judge`: linearised kinematics, candidate zone); decide a failed load-driven solve exactly
/// (`crate::validity::decide`) — returning also the evaluation of an accepted solution (a load path carries its
/// state on). The solver's termination and message are kept as they are; the harness's conclusion is the run's
/// `status`, with a [`Verdict`] when it is not simply the termination.
pub fn evaluate_outcome(ctx: &RunContext, outcome: Outcome) -> (SolverRun, Option<Evaluation>) {
    let RunContext { scene, problem, solver, .. } = *ctx;
    let Outcome { solution, status: termination, message, work, figures, state: _ } = outcome;
    let mut status = Status::from(termination);
    let mut verdict = None;
    let ev = match (&solution, termination) {
        (Some(sol), Termination::Solved) => match evaluate(problem, sol, ctx.rolling) {
            Ok(ev) => Some(ev),
            Err(e) => {
                // A solver (a plug-in's, say) that claims a solution of another shape than the problem's.
                status = Status::NumericalError;
                verdict = Some(Verdict {
                    reason: VerdictReason::ResidualTooLarge,
                    message: format!("the solver reported success but its solution cannot be evaluated: {e}"),
                });
                None
            }
        },
        _ => None,
    };
    if let Some(ev) = &ev {
        let worst = ev.residuals.max();
        if let Some(what) = ev.first_non_finite() {
            status = Status::NumericalError;
            verdict = Some(Verdict {
                reason: VerdictReason::ResidualTooLarge,
                message: format!(
                    "the solver reported success but {what}: its residuals cannot be evaluated (the scene's numbers \
                     may be outside double precision, e.g. loads or lengths extreme against the moduli)"
                ),
            });
        } else if worst.is_nan() || worst > ctx.refuse {
            status = Status::NumericalError;
            verdict = Some(Verdict {
                reason: VerdictReason::ResidualTooLarge,
                message: format!(
                    "the solver reported success but the independent residual is {worst:.3e} > {:.0e}",
                    ctx.refuse
                ),
            });
        }
    }
    if let (Some(ev), Status::Solved) = (&ev, status) {
        if let Some((judged, reason, why)) = crate::validity::judge(scene, problem, ev) {
            status = judged;
            verdict = Some(Verdict { reason, message: why });
        }
    }
    if let Some((decided, why)) = crate::validity::decide(problem, solver, status) {
        status = decided;
        verdict = Some(Verdict { reason: VerdictReason::Admissibility, message: why });
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
        solver,
        formulation: problem.formulation(),
        problem: ProblemClass::of(&problem.kind),
        status,
        termination,
        message,
        verdict,
        problem_size: problem.lcp_size(),
        work,
        timing_s: ctx.timing,
        residuals: ev.as_ref().map(|e| e.residuals),
        resultants: ev.as_ref().map(|e| e.resultants),
        rigid_body: ev.as_ref().map(|e| e.rigid_body),
        contact: ev.as_ref().map(|e| e.contact.clone()),
        rolling: ev.as_ref().and_then(|e| e.rolling),
        nodes: ev.as_ref().map(|e| e.nodes.clone()).unwrap_or(flagged_nodes),
        figures,
        history: None,
        stresses: None,
        counter_body_stresses: None,
        branches: None,
    };
    (run, ev)
}

/// Hertz at the scene's load, or at the first solved run's load when the approach is prescribed (and for a load
/// path, whose runs are at its end).
fn reference_hertz(scene: &Scene, runs: &[SolverRun]) -> Option<Hertz2D> {
    let p = match scene.drive().map(|d| d.normal) {
        Some(Dof::Load(p)) => Some(p),
        _ => runs.iter().find_map(|r| r.resultants.map(|x| x.normal)),
    }?;
    (p > 0.0).then(|| crate::references::hertz_at(scene, p))
}

/// Whether the scene's wheel is the half-plane model.
pub fn is_half_plane(scene: &Scene) -> bool {
    scene.model() == BodyModel::HalfPlane
}
