//! One step from rest to the scene's drive (`[drive]`): the contact problem on the model's flexibility, every
//! requested solver, the harness's verdict on each, and the result document.
//!
//! Only the effects the scene calls for are simulated: a frictionless scene's model holds only the normal columns of
//! the flexibility ([`crate::source::Blocks::Normal`]), its problem one unknown per contact node (plus two per
//! load-driven rigid degree of freedom) and no tangential or rolling work; `effects` and `problem_size` in the
//! report show it.

use super::stages::{
    add_stresses, assemble_report, build_problem, is_half_plane, lcp_time, normal_asymmetry, rolling_post,
    slip_operator, solve_timed, solvers_for, RunContext,
};
use crate::error::Result;
use crate::formulation::{Drive, Lcp, ProblemKind};
use crate::results::{Report, Setup, Timing};
use crate::scene::Scene;
use crate::source::Built;
use std::time::Instant;

/// Solve a one-step scene on a built flexibility; `setup` says whether the flexibility was built for this solve.
pub(super) fn solve(
    scene: &Scene,
    drive: Drive,
    built: &Built,
    setup: Setup,
    warm: &mut super::Warm,
    cancel: &crate::cancel::Cancel,
) -> Result<Report> {
    if let Some(friction) = scene.slip_velocity_friction() {
        return super::veldep::solve(scene, drive, friction, built, setup, cancel);
    }
    let flex = &built.flex;
    let tf = Instant::now();
    let problem = build_problem(scene, flex, drive, slip_operator(scene, flex))?;
    let formulation_time = tf.elapsed().as_secs_f64();
    // The flexibility's health figures (computed once per flexibility, with n × n transients) before any solver:
    // on a clean heap they do not add to the peak memory (see `diagnostics::conditions`).
    crate::diagnostics::conditions(flex);
    let asym = normal_asymmetry(&problem, is_half_plane(scene));
    let solvers = solvers_for(scene, &problem)?;
    let stresses = crate::stresses::StressEvaluator::new(scene, built)?;
    let mut runs = Vec::new();
    let mut bounds = Vec::new();
    for solver in &solvers {
        let start = warm.start(solver.id(), cancel);
        let (mut outcome, solve_time) = solve_timed(solver.as_ref(), &problem, start);
        cancel.check()?;
        let certified_start = outcome.status == crate::solvers::Termination::Solved;
        warm.set(solver.id(), outcome.solution.clone().filter(|_| certified_start), outcome.state.take());
        let formulation = formulation_time + lcp_time(solver.as_ref(), &problem);
        let (check_bound, refuse) = crate::solvers::residual_bounds(solver.as_ref());
        let ctx = RunContext {
            scene,
            problem: &problem,
            solver: solver.id(),
            timing: Timing::of(&built.timing, formulation, solve_time, setup),
            refuse,
            rolling: rolling_post(scene),
        };
        let (mut run, _) = super::stages::evaluate_outcome(&ctx, outcome);
        add_stresses(&mut run, stresses.as_ref())?;
        runs.push(run);
        bounds.push(check_bound);
    }
    Ok(assemble_report(scene, built, asym, runs, &bounds, Vec::new()))
}

/// The LCP that Lemke solves for a one-step scene on a built flexibility (for `rollbem lcp export`): frictionless,
/// frictional (displacement, loading or mixed, with the slack signs of the attempt that succeeded) or the
/// sliding-limit problem. A scene beyond gross sliding has no LCP (an error saying why).
pub(super) fn lcp(scene: &Scene, drive: Drive, built: &Built) -> Result<Lcp> {
    let problem = build_problem(scene, &built.flex, drive, slip_operator(scene, &built.flex))?;
    let lemke = crate::solvers::lemke::Lemke {
        id: crate::solvers::lemke::ID,
        settings: scene
            .solvers()
            .settings
            .get(crate::solvers::lemke::ID)
            .and_then(crate::solvers::settings_of::<crate::solvers::lemke::LemkeSettings>)
            .copied()
            .unwrap_or_default(),
        engine: crate::solvers::lemke::solve_cancellable,
    };
    match (&problem.kind, lemke.solved_lcp(&problem)) {
        (_, Some(lcp)) => Ok(lcp),
        (ProblemKind::GrossSliding { message }, None) => Err(crate::error::Error::Unsupported {
            path: scene.origin().to_path_buf(),
            message: format!("no static problem to export: {message}"),
        }),
        (_, None) => Err(crate::error::Error::Unsupported {
            path: scene.origin().to_path_buf(),
            message: "no static problem to export".into(),
        }),
    }
}
