//! Steady rolling with a falling friction law of the slip velocity (`[contact] friction_law`, [`crate::veldep`]):
//! the one-step solve of such a scene. Only a scene that calls for it comes here (`super::single` asks
//! [`Scene::slip_velocity_friction`]); a Coulomb scene's path has none of it.
//!
//! The pair is uncoupled (checked when the model is built: [`applies`]), so the normal problem does not depend on
//! the tangential one: each requested solver solves the frictionless normal problem on the model's flexibility,
//! and its nodal forces pose [`crate::veldep::SteadyProblem`] (`D K_TT`, the creepage, the speed, the law), solved
//! from both starts ([`crate::veldep::solve_both`]). The run carries the start the scene names
//! (`[contact.friction_law] start`) and reports both ([`crate::veldep::BranchReport`]); a start that did not converge
//! is a status with its residual, never a solution. The run's nodes and resultants are post-processed from the
//! normal forces and the law's tangential forces by [`crate::post::evaluate`] on the frictional steady problem
//! (Coulomb's μ(0)); its node states and its friction residual are then the law's (a slipping node carries
//! `μ(V|s|) p < μ(0) p`, which Coulomb's residual would call stick).

use super::stages::{
    add_stresses, assemble_report, evaluate_outcome, is_half_plane, normal_asymmetry, slip_operator, solve_timed,
    solvers_for, RunContext,
};
use crate::error::{Error, Result};
use crate::formulation::{ContactLaw, ContactProblem, Dof, DofKind, Drive, SlipOperator, Solution};
use crate::post::{evaluate, NodeState, RollingPost};
use crate::results::{ProblemClass, Report, Setup, SolverRun, Timing};
use crate::scene::Scene;
use crate::solvers::Termination;
use crate::source::Built;
use crate::status::Status;
use crate::veldep::{BranchFigures, BranchReport, SceneFriction, Start, SteadyOutcome, SteadyProblem, SteadyStatus};
use std::time::Instant;

/// The law's residual a converged start must reach (relative to max μ(0) f; [`crate::veldep::solve_steady`]).
pub const TOLERANCE: f64 = 1e-10;
/// Active-set iterations per start.
pub const MAX_ITERATIONS: usize = 200;

/// Whether the model of `scene` can carry its falling law: the simulated problem must be uncoupled
/// ([`super::stages::simulated_law`]); refused otherwise, naming `contact.friction_law` (bad input, exit 2).
pub(super) fn applies(scene: &Scene) -> Result<()> {
    if scene.slip_velocity_friction().is_some() && super::stages::simulated_law(scene).coupling {
        return Err(Error::Invalid {
            path: scene.origin().to_path_buf(),
            field: "contact.friction_law".into(),
            message: format!(
                "a falling friction law is solved at the normal problem's pressure, which needs the uncoupled \
                 problem: this pair couples normal and tangential (Dundurs β = {:.4}); set `[contact] coupling = \
                 false` or use one material",
                scene.dundurs_beta()
            ),
        });
    }
    Ok(())
}

/// Solve a one-step steady-rolling scene with a falling law (module docs) on a built flexibility.
pub(super) fn solve(
    scene: &Scene,
    drive: Drive,
    friction: SceneFriction,
    built: &Built,
    setup: Setup,
    cancel: &crate::cancel::Cancel,
) -> Result<Report> {
    let flex = &built.flex;
    let tf = Instant::now();
    let unsupported = |message: String| Error::Unsupported { path: scene.origin().to_path_buf(), message };
    let normal_drive = Drive { tangential: Dof::Displacement(0.0), ..drive };
    let normal = ContactProblem::new(
        flex,
        ContactLaw { friction: 0.0, coupling: false },
        normal_drive,
        SlipOperator::static_slip(),
    )
    .map_err(|e| unsupported(format!("{e} (a flexibility built for another scene?)")))?;
    let frictional = super::stages::build_problem(scene, flex, drive, slip_operator(scene, flex))?;
    let k_tt = flex.k_tt.as_ref().ok_or_else(|| unsupported("the model holds no tangential flexibility".into()))?;
    let slip_matrix = frictional.slip().apply_mat(k_tt);
    let formulation = tf.elapsed().as_secs_f64();
    crate::diagnostics::conditions(flex);
    let asym = normal_asymmetry(&normal, is_half_plane(scene));
    let solvers = solvers_for(scene, &normal)?;
    let stresses = crate::stresses::StressEvaluator::new(scene, built)?;
    let mut runs = Vec::new();
    let mut bounds = Vec::new();
    for solver in &solvers {
        let start = super::Warm::default().start(solver.id(), cancel);
        let (outcome, solve_time) = solve_timed(solver.as_ref(), &normal, start);
        cancel.check()?;
        let normal_solution = outcome.solution.clone().filter(|_| outcome.status == Termination::Solved);
        let (check_bound, refuse) = crate::solvers::residual_bounds(solver.as_ref());
        let ctx = RunContext {
            scene,
            problem: &normal,
            solver: solver.id(),
            timing: Timing::of(&built.timing, formulation, solve_time, setup),
            refuse,
            rolling: None,
        };
        let (mut run, _) = evaluate_outcome(&ctx, outcome);
        if let (Status::Solved, Some(nsol)) = (run.status, normal_solution) {
            let t0 = Instant::now();
            let posed = Posed {
                origin: scene.origin(),
                direction: scene.rolling().map_or(1, |r| r.direction()),
                normal: &normal,
                frictional: &frictional,
                slip_matrix: &slip_matrix,
                friction,
            };
            tangential(&posed, &nsol, &mut run)?;
            let dt = t0.elapsed().as_secs_f64();
            run.timing_s.solve += dt;
            run.timing_s.total += dt;
        }
        add_stresses(&mut run, stresses.as_ref())?;
        runs.push(run);
        bounds.push(check_bound);
    }
    Ok(assemble_report(scene, built, asym, runs, &bounds, Vec::new()))
}

/// The problems a run's tangential part is posed on.
struct Posed<'a, 'p> {
    origin: &'a std::path::Path,
    direction: i32,
    normal: &'a ContactProblem<'p>,
    frictional: &'a ContactProblem<'p>,
    slip_matrix: &'a faer::Mat<f64>,
    friction: SceneFriction,
}

/// Solve the law from both starts at the normal solution's forces and make `run` (the normal problem's, solved)
/// the carried start's answer, with both starts' figures.
fn tangential(posed: &Posed, nsol: &Solution, run: &mut SolverRun) -> Result<()> {
    let fp = posed.frictional;
    let flex = fp.flex();
    let Some(k) = fp.dofs().iter().position(|d| d.kind == DofKind::Creepage) else {
        // A validated falling-law scene prescribes its creepage (scene::friction); say so if one does not.
        return Err(Error::Unsupported {
            path: posed.origin.to_path_buf(),
            message: "rolling.creepage: a falling friction law needs the creepage prescribed".into(),
        });
    };
    let xi = fp.given()[k];
    let p = SteadyProblem {
        slip_matrix: posed.slip_matrix,
        normal: &nsol.f,
        creepage: xi,
        offset: None,
        velocity: posed.friction.velocity,
        law: posed.friction.law,
    };
    // Memory: the material moves one element per Δt = Δx/V (a uniform grid: the mean spacing), leading edge first.
    let memory = posed.friction.memory.map(|(distance, min_velocity)| {
        let n = flex.x.len();
        let element = match n {
            0 | 1 => flex.weights.first().copied().unwrap_or(1.0) * flex.scales.length,
            _ => (flex.x[n - 1] - flex.x[0]).abs() / (n - 1) as f64 * flex.scales.length,
        };
        crate::veldep::Memory { distance, min_velocity, element, direction: posed.direction }
    });
    let both = crate::veldep::solve_both_with(&p, memory, TOLERANCE, MAX_ITERATIONS).map_err(Error::from)?;
    let force = flex.scales.modulus * flex.scales.length;
    let report = BranchReport {
        carried: posed.friction.start,
        below: BranchFigures::of(&both.below, force),
        above: BranchFigures::of(&both.above, force),
        distinct: both.distinct,
    };
    run.branches = Some(report);
    run.formulation = fp.formulation();
    run.problem = ProblemClass::Frictional;
    let carried = match posed.friction.start {
        Start::Below => &both.below,
        Start::Above => &both.above,
    };
    let SteadyStatus::Converged { residual, .. } = carried.status else {
        run.status = Status::NotConverged;
        run.termination = Termination::NotConverged;
        run.verdict = None;
        run.message = report.describe();
        run.residuals = None;
        run.resultants = None;
        run.rigid_body = None;
        run.contact = None;
        run.rolling = None;
        run.nodes = Vec::new();
        return Ok(());
    };
    let rigid = fp
        .dofs()
        .iter()
        .map(|d| if d.kind == DofKind::Creepage { xi } else { posed.normal.rigid_value(nsol, d.kind) })
        .collect();
    let sol = Solution { f: nsol.f.clone(), h: Some(carried.tangential.clone()), rigid, tangential_known: true };
    let mut ev = evaluate(fp, &sol, Some(RollingPost::Steady)).map_err(Error::from)?;
    law_states(&mut ev, carried);
    ev.residuals.friction = Some(residual);
    run.residuals = Some(ev.residuals);
    run.resultants = Some(ev.resultants);
    run.rigid_body = Some(ev.rigid_body);
    run.contact = Some(ev.contact);
    run.rolling = ev.rolling;
    run.nodes = ev.nodes;
    Ok(())
}

/// The law's node states (stick where it found `s = 0`, else slip; separated as evaluated) and the counts and
/// stick zone that follow; the rolling figures' counts are recounted with these states (a sticking node whose slip
/// velocity exceeds [`crate::tolerances::STATE_MARGIN`] of its scale, a slipping node whose shear does not oppose
/// it).
fn law_states(ev: &mut crate::post::Evaluation, o: &SteadyOutcome) {
    for (n, &stick) in ev.nodes.iter_mut().zip(&o.stick) {
        if n.state != NodeState::Separated {
            n.state = if stick { NodeState::Stick } else { NodeState::Slip };
        }
    }
    let sticking: Vec<f64> = ev.nodes.iter().filter(|n| n.state == NodeState::Stick).map(|n| n.x).collect();
    ev.contact.nodes_stick = sticking.len();
    ev.contact.nodes_slip = ev.nodes.iter().filter(|n| n.state == NodeState::Slip).count();
    ev.contact.stick_x_min = sticking.iter().copied().reduce(f64::min);
    ev.contact.stick_x_max = sticking.iter().copied().reduce(f64::max);
    if let Some(r) = ev.rolling.as_mut() {
        let margin = crate::tolerances::STATE_MARGIN * r.slip_velocity_scale;
        let count = |state: NodeState, bad: &dyn Fn(f64, f64) -> bool| {
            ev.nodes.iter().filter(|n| n.state == state && bad(n.shear, n.slip_velocity.unwrap_or(0.0))).count()
        };
        r.stick_nodes_moving = count(NodeState::Stick, &|_, s| s.abs() > margin);
        r.slip_nodes_not_opposed = count(NodeState::Slip, &|q, s| q * s > 0.0 && s.abs() > margin);
    }
}
