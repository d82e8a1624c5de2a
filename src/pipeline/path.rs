//! Load paths with memory: quasi-static steps (`[[steps]]`), each one contact problem whose tangential unknown is
//! the slip increment since the previous step ([`crate::formulation::slip`], `SlipKind::Increment`), starting from
//! the previous step's state. Friction remembers the path: Spence's stick zone under a growing normal load with
//! coupling, Mindlin–Deresiewicz loops under a cycled tangential load, rolling from rest.
//!
//! **A step** gives the drive at its end (the keys of `[drive]`; the normal DOF required, an absent tangential or
//! rotational DOF held at 0 displacement). With `substeps = m` it is reached in m equal increments, linear in the
//! prescribed quantity from the value that quantity had at the previous step's end (prescribed or solved: a load
//! following a displacement starts from the resultant the displacement produced). The path starts from rest: no
//! load, no rigid motion, no displacement.
//!
//! **Memory.** Each solver walks the whole path with its own state: the total tangential displacement u_T of the
//! contact nodes (rigid motion included) at the previous step's end. A step's slip is s = u_T − u_T,prev; stick ⇔
//! s = 0 and |h| ≤ μf, slip ⇔ h = −μf sgn(s). Separation and re-contact are allowed (the gap condition has no
//! memory). Each solver starts a substep from the previous substep's solution and its own state
//! ([`crate::solvers::Start`]: Lemke from its basis, the active-set method from its sets and factorisations).
//!
//! **Cancellation.** The walk checks the caller's token ([`crate::cancel::Cancel`]) before every substep and every
//! solver checks it at its iterations: a cancelled path returns [`crate::Error::Cancelled`] at once.
//!
//! **Rolling** (`roll = d` > 0, `[rolling] mode = "transient"`): during the step the contact moves over the body by
//! d; node i then holds the material that was at x_i + dir·d at the previous step's end (linear interpolation
//! between nodes; material entering the candidate zone carries no displacement, the steady operator's convention
//! for its leading-edge row), and the rigid creep ξ d adds to the slip. When d is one element of a uniform grid this
//! is exactly the upwind difference of steady rolling: Δs_i = h (ξ + (u_i − u_{i+dir})/h) = h s_i^steady, so a
//! steady state of the path is the steady-rolling solution of the same mesh.
//!
//! **Energy.** The frictional dissipation of a step is Σ −h_i Δs_i with the step's end forces (friction opposes the
//! slip increment, so every term is ≥ 0), in energy per unit thickness; with enough substeps it converges to the
//! path integral.

use super::stages::{
    add_stresses, assemble_report, build_problem, evaluate_outcome, is_half_plane, lcp_time, normal_asymmetry,
    solve_timed, solvers_for, RunContext,
};
use crate::error::Result;
use crate::formulation::{ContactProblem, Dof, Drive, SlipOperator, Solution};
use crate::post::RollingPost;
use crate::results::{Report, Setup, SolverRun, StepEnergy, StepResult, Timing};
use crate::scene::{PathStep, Rolling, Scene};
use crate::solvers::{Solver, Start, Status};
use crate::source::Built;
use std::time::Instant;

/// A solver's state at the end of a step (user's units for the rigid motion and the resultants).
#[derive(Debug, Clone)]
struct PathState {
    /// Total tangential displacement of the contact nodes (dimensionless), rigid motion included.
    u_t: Vec<f64>,
    /// Rigid motion (d_T, d_N, φ).
    rigid: [f64; 3],
    /// Resultants (Q, P, M).
    loads: [f64; 3],
    /// The solution (a warm start for the next step).
    solution: Option<Solution>,
    /// Dissipated energy so far.
    dissipated: f64,
}

/// One substep of the path: the drive at its end and the distance it rolls (user's units).
#[derive(Debug, Clone, Copy)]
struct Substep {
    step: usize,
    substep: usize,
    substeps: usize,
    /// The end drive of the step, per DOF (shift, approach, rotation order: tangential, normal, rotational).
    end: [Dof; 3],
    /// Fraction of the step reached at this substep's end.
    fraction: f64,
    /// Distance rolled in this substep.
    roll: f64,
}

/// Every substep of a path, in order.
fn substeps(steps: &[PathStep]) -> Vec<Substep> {
    let mut out = Vec::new();
    for (k, st) in steps.iter().enumerate() {
        let (d, m) = (st.end, st.substeps);
        for j in 1..=m {
            out.push(Substep {
                step: k,
                substep: j,
                substeps: m,
                end: [d.tangential, d.normal, d.rotational],
                fraction: j as f64 / m as f64,
                roll: st.roll / m as f64,
            });
        }
    }
    out
}

/// The drive at a substep's end: each DOF linear in its prescribed quantity from the value it had at the step's
/// start (`start`, the state at the previous step's end).
fn drive_at(sub: &Substep, start: &PathState) -> Drive {
    let dof = |k: usize| match sub.end[k] {
        Dof::Displacement(v) => Dof::Displacement(start.rigid[k] + (v - start.rigid[k]) * sub.fraction),
        Dof::Load(v) => Dof::Load(start.loads[k] + (v - start.loads[k]) * sub.fraction),
    };
    Drive { tangential: dof(0), normal: dof(1), rotational: dof(2) }
}

/// The slip offset of a substep: −(the material's u_T at the previous step's end) + ξ d, the material at node i being
/// the one that was at x_i + dir·d (linear interpolation; none beyond the candidate zone). Dimensionless.
fn offset(x: &[f64], u_prev: &[f64], roll: f64, creepage: f64, direction: i32) -> Vec<f64> {
    let n = x.len();
    x.iter()
        .map(|&xi| {
            let at = xi + direction as f64 * roll;
            let u = if roll == 0.0 {
                None
            } else {
                (0..n.saturating_sub(1)).find(|&k| x[k] <= at && at <= x[k + 1]).map(|k| {
                    let t = (at - x[k]) / (x[k + 1] - x[k]);
                    (1.0 - t) * u_prev[k] + t * u_prev[k + 1]
                })
            };
            // Without rolling, node i holds its own material (its index is that of xi).
            let u = match u {
                Some(u) => u,
                None if roll == 0.0 => x.iter().position(|v| *v == xi).map_or(0.0, |i| u_prev[i]),
                None => 0.0,
            };
            -u + creepage * roll
        })
        .collect()
}

/// Walk a load path with every requested solver, on a built flexibility; `setup` says whether the flexibility was
/// built for this walk.
pub(super) fn solve(
    scene: &Scene,
    steps: &[PathStep],
    built: &Built,
    setup: Setup,
    cancel: &crate::cancel::Cancel,
) -> Result<Report> {
    let flex = &built.flex;
    let n = flex.n();
    let l0 = flex.scales.length;
    let (creepage, direction) = match scene.rolling() {
        Some(Rolling::Transient { creepage, direction }) => (*creepage, *direction),
        _ => (0.0, 1),
    };
    let subs = substeps(steps);
    let rest = PathState { u_t: vec![0.0; n], rigid: [0.0; 3], loads: [0.0; 3], solution: None, dissipated: 0.0 };
    // The problem of a substep: the slip increment from the previous substep's state `st`, the drive interpolated
    // from the step's start `start`.
    let problem_at = |sub: &Substep, st: &PathState, start: &PathState| -> Result<ContactProblem<'_>> {
        let slip = SlipOperator::increment(offset(&flex.x, &st.u_t, sub.roll / l0, creepage, direction));
        build_problem(scene, flex, drive_at(sub, start), slip)
    };
    let first = problem_at(&subs[0], &rest, &rest)?;
    let solvers = solvers_for(scene, &first)?;
    let asym = normal_asymmetry(&first, is_half_plane(scene));
    let mut steps: Vec<StepResult> = Vec::with_capacity(subs.len());
    let mut rolled = 0.0;
    for sub in &subs {
        rolled += sub.roll;
        steps.push(StepResult {
            step: sub.step,
            substep: sub.substep,
            substeps: sub.substeps,
            rolled,
            drive: drive_at(sub, &rest),
            runs: Vec::new(),
        });
    }
    let mut finals = Vec::new();
    let mut bounds = Vec::new();
    let stresses = crate::stresses::StressEvaluator::new(scene, built)?;
    for solver in &solvers {
        let ctx = PathContext { source_time: &built.timing, setup, scene, stresses: stresses.as_ref(), cancel };
        let (last, bound) = walk(solver.as_ref(), &subs, &rest, &problem_at, &ctx, &mut steps)?;
        finals.push(last);
        bounds.push(bound);
    }
    Ok(assemble_report(scene, built, asym, finals, &bounds, steps))
}

/// What a walk along the path needs of the scene beyond its problems.
struct PathContext<'s> {
    source_time: &'s crate::source::SourceTiming,
    /// Whether the flexibility was built for this walk (its time is then counted on the first substep).
    setup: Setup,
    scene: &'s Scene,
    /// The stress evaluation, when the scene asks for it (at the end of each step).
    stresses: Option<&'s crate::stresses::StressEvaluator<'s>>,
    /// The caller's cancellation token.
    cancel: &'s crate::cancel::Cancel,
}

/// One solver along the whole path; returns its last run and its residual check bound.
fn walk<'a>(
    solver: &dyn Solver,
    subs: &[Substep],
    rest: &PathState,
    problem_at: &dyn Fn(&Substep, &PathState, &PathState) -> Result<ContactProblem<'a>>,
    ctx: &PathContext,
    steps: &mut [StepResult],
) -> Result<(SolverRun, f64)> {
    let (source_time, scene) = (ctx.source_time, ctx.scene);
    let (check, refuse) = crate::solvers::residual_bounds(solver);
    let mut state = rest.clone();
    // The state at the start of the current step: its substeps interpolate from there.
    let mut step_start = rest.clone();
    let mut last = None;
    // The solver's own state after the last substep (its warm start for the next one).
    let mut own = None;
    for (k, sub) in subs.iter().enumerate() {
        ctx.cancel.check()?;
        if sub.substep == 1 {
            step_start = state.clone();
        }
        let tf = Instant::now();
        let problem = problem_at(sub, &state, &step_start)?;
        let formulation = tf.elapsed().as_secs_f64();
        steps[k].drive = problem.drive;
        let start = Start { solution: state.solution.clone(), state: own.take(), cancel: ctx.cancel.clone() };
        let (mut outcome, solve) = solve_timed(solver, &problem, start);
        ctx.cancel.check()?;
        own = outcome.state.take();
        let formulation = formulation + lcp_time(solver, &problem);
        // The flexibility's setup is counted once, on the path's first substep.
        let timing = if k == 0 {
            Timing::of(source_time, formulation, solve, ctx.setup)
        } else {
            Timing::of(&Default::default(), formulation, solve, Setup::Reused)
        };
        let rolling = match scene.rolling() {
            Some(Rolling::Transient { creepage, .. }) => {
                Some(RollingPost::Transient { creepage: *creepage, roll: sub.roll / problem.flex.scales.length })
            }
            _ => None,
        };
        let solution = outcome.solution.clone();
        let run_ctx = RunContext { scene, problem: &problem, solver: solver.id(), timing, refuse, rolling };
        let (mut run, ev) = evaluate_outcome(&run_ctx, outcome);
        let solved = run.status == Status::Solved;
        if let (true, Some(ev), Some(sol)) = (solved, ev, solution) {
            let sc = problem.flex.scales;
            let step_energy = match (&sol.h, &ev.slip) {
                (Some(h), Some(s)) => {
                    -h.iter().zip(s).map(|(h, s)| h * s).sum::<f64>() * sc.modulus * sc.length * sc.length
                }
                _ => 0.0,
            };
            state.dissipated += step_energy;
            run.history = Some(StepEnergy { dissipated: step_energy, dissipated_total: state.dissipated });
            let rb = ev.rigid_body;
            state.rigid = [rb.tangential.unwrap_or(state.rigid[0]), rb.normal, rb.rotation];
            state.loads = [ev.resultants.tangential, ev.resultants.normal, ev.resultants.moment];
            state.u_t = ev.u_t.clone().unwrap_or_else(|| vec![0.0; problem.n()]);
            state.solution = Some(sol);
            if sub.substep == sub.substeps {
                add_stresses(&mut run, ctx.stresses)?;
            }
        }
        steps[k].runs.push(run.clone());
        last = Some(run);
        if !solved {
            break;
        }
    }
    match last {
        Some(run) => Ok((run, check)),
        None => unreachable!("a validated path has at least one substep"),
    }
}
