//! Transient rolling with a friction law of the slip velocity over many time steps (CONTACT's T = 2 cases in
//! sequence, e.g. `veldep_fric.inp`'s cases 4 to 53): each step is [`super::transient_step`]'s problem posed on the
//! previous step's tangential forces and solved by [`super::solve_steady`] from the step's start. The first step
//! starts from given forces (a steady state, or rest).
//!
//! A step that does not converge ends the run: it is reported with its status and residual
//! ([`TransientStatus::Stopped`]), never taken as the state the next step starts from, and no step after it is
//! computed.
//!
//! No friction memory here ([`super::Memory`] is steady rolling's): CONTACT carries each material point's
//! coefficient from one time step to the next, which this driver does not yet do.

use super::{solve_steady, transient_step, FrictionLaw, Start, SteadyOutcome, SteadyProblem, SteadyStatus};
use crate::error::ArgumentError;
use faer::Mat;

/// The time-stepping problem (dimensionless as [`SteadyProblem`]): the flexibility, the pressure, the creepage, the
/// speed and the law, and the distance rolled per step.
#[derive(Clone, Debug)]
pub struct TransientProblem<'a> {
    /// `K_TT`: tangential displacement per unit tangential nodal force (n × n).
    pub k_tt: &'a Mat<f64>,
    /// Normal nodal forces `f_i ≥ 0` (the same at every step: the uncoupled problem).
    pub normal: &'a [f64],
    /// The creepage ξ of every step (ξ > 0 braking).
    pub creepage: f64,
    /// The rolling speed V (length/s).
    pub velocity: f64,
    /// The law.
    pub law: FrictionLaw,
    /// The distance rolled per step Δq (dimensionless; the element length on [`transient_step`]'s uniform grid).
    pub dq: f64,
    /// The rolling direction ±1.
    pub direction: i32,
}

/// How a run of steps ended.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum TransientStatus {
    /// Every step converged.
    Completed,
    /// Step `step` (0-based) did not converge: the run stops there (its outcome is the last one, NOT a solution).
    Stopped {
        /// The step that did not converge.
        step: usize,
        /// Its law residual at the end.
        residual: f64,
    },
}

/// The steps of a run, in order (the last one is the failed step when [`TransientRun::status`] is `Stopped`).
#[derive(Clone, Debug)]
pub struct TransientRun {
    /// Every step computed.
    pub steps: Vec<SteadyOutcome>,
    /// Completed, or where it stopped.
    pub status: TransientStatus,
}

/// Roll `starts.len()` time steps from the tangential forces `h0` (e.g. a steady solution), step k started from
/// `starts[k]` (CONTACT's INISLP per case), each solved to `tolerance` within `max_iterations`
/// ([`solve_steady`]). Refused as [`transient_step`] and [`solve_steady`], or when `h0` is not of n entries.
pub fn roll(
    p: &TransientProblem,
    h0: &[f64],
    starts: &[Start],
    tolerance: f64,
    max_iterations: usize,
) -> Result<TransientRun, ArgumentError> {
    let n = p.normal.len();
    if h0.len() != n {
        return Err(ArgumentError::new("veldep::transient::roll", "h0", format!("must have {n} entries")));
    }
    let mut previous = h0.to_vec();
    let mut steps = Vec::with_capacity(starts.len());
    for (k, &start) in starts.iter().enumerate() {
        let (m, offset) = transient_step(p.k_tt, &previous, p.dq, p.direction)?;
        let step = SteadyProblem {
            slip_matrix: &m,
            normal: p.normal,
            creepage: p.creepage,
            offset: Some(&offset),
            velocity: p.velocity,
            law: p.law,
        };
        let out = solve_steady(&step, start, tolerance, max_iterations)?;
        if let SteadyStatus::NotConverged { residual, .. } = out.status {
            steps.push(out);
            return Ok(TransientRun { steps, status: TransientStatus::Stopped { step: k, residual } });
        }
        previous.clone_from(&out.tangential);
        steps.push(out);
    }
    Ok(TransientRun { steps, status: TransientStatus::Completed })
}
