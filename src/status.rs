//! How a contact solve ended, in two parts kept apart:
//!
//! - [`Termination`]: what the **solver** says of its own run (solved, a secondary ray, the iteration limit, a
//!   proven infeasibility, a numerical failure). Every solver returns one; nothing else writes it.
//! - [`Status`] with its [`Verdict`]: what the **harness** concludes about the physical problem after checking
//!   the answer independently of the solver ([`crate::post`] residuals, `crate::validity`): it adopts the
//!   termination, or overrides it with a reason (a `solved` claim refused on its residuals, an answer cut off by
//!   the candidate zone, a ray that the equilibrium LP proves to be infeasibility).

use serde::{Deserialize, Serialize};

/// How a solver ended its own run (before the harness checks the answer).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
#[non_exhaustive]
pub enum Termination {
    /// The solver claims a solution (the harness still checks it).
    Solved,
    /// Lemke's algorithm ended on a secondary ray (no conclusion by itself for the frictional LCPs).
    RayTermination,
    /// The iteration limit was reached before the tolerance.
    NotConverged,
    /// The solver proved that the problem has no solution.
    Infeasible,
    /// The solver failed numerically (a singular system, non-finite values).
    NumericalError,
}

impl Termination {
    /// Name used in reports and JSON.
    pub fn name(self) -> &'static str {
        Status::from(self).name()
    }
}

impl std::fmt::Display for Termination {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.pad(self.name())
    }
}

impl From<Termination> for Status {
    fn from(t: Termination) -> Status {
        match t {
            Termination::Solved => Status::Solved,
            Termination::RayTermination => Status::RayTermination,
            Termination::NotConverged => Status::NotConverged,
            Termination::Infeasible => Status::Infeasible,
            Termination::NumericalError => Status::NumericalError,
        }
    }
}

/// Why the harness's [`Status`] of a run is not simply the solver's [`Termination`].
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
#[non_exhaustive]
pub enum VerdictReason {
    /// The solver claimed a solution whose solver-independent residual is above the refusal bound, or cannot be
    /// evaluated because the solution has a non-finite value (→ `numerical_error`).
    ResidualTooLarge,
    /// The answer's contact reaches the edge of the candidate zone (→ `contact_at_zone_edge`).
    ZoneEdge,
    /// The answer uses the linearised kinematics far outside their range (→ `kinematics_out_of_range`).
    Kinematics,
    /// A failed load-driven solve decided exactly by the static-admissibility LP: no admissible contact forces
    /// (→ `infeasible`) or admissible forces exist (the failure stays the solver's, with the certificate).
    Admissibility,
}

/// The harness's conclusion about one run: the final [`Status`], and when it differs from the solver's termination
/// (or qualifies it), the reason and the explanation.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[non_exhaustive]
pub struct Verdict {
    /// Why the harness's status is not the solver's own.
    pub reason: VerdictReason,
    /// The explanation, with the numbers.
    pub message: String,
}

/// The status of a run as the harness concludes it (after the solver-independent residual check of
/// [`crate::post`] and the model-range checks of `crate::validity`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
#[non_exhaustive]
pub enum Status {
    /// A solution was found and its solver-independent residuals are small.
    Solved,
    /// Lemke's algorithm ended on a secondary ray. For a copositive-plus LCP (the frictionless ones) this proves
    /// infeasibility and is reported as [`Status::Infeasible`]; the frictional LCPs are not copositive-plus, so on a
    /// load-driven one the equilibrium LP decides (`crate::validity::decide`): no admissible contact forces →
    /// `infeasible` with the certificate; admissible forces exist → this status, the elastic problem undecided
    /// (Lemke's failure, not a diagnosis).
    RayTermination,
    /// The iteration limit was reached before the tolerance.
    NotConverged,
    /// The problem has no solution (e.g. a load the contact cannot carry).
    Infeasible,
    /// The solver failed numerically, or claimed success with a large independent residual.
    NumericalError,
    /// The solution's contact reaches the edge of the candidate zone (its outermost node is loaded): the contact is
    /// cut off by the mesh, not by the physics, and its pressures are not the wheel's. The message says how wide the
    /// zone must be (`crate::validity`).
    ContactAtZoneEdge,
    /// The solution uses the linearised (small-rotation) kinematics far outside their range: the wheel's rigid
    /// rotation φ moves its contact points by φR, more than [`crate::tolerances::ROTATION_ARC_MAX`] contact
    /// half-widths, so the gaps and the lever arms of the moment equilibrium are not the wheel's. Typical of a wheel
    /// free to turn (moment prescribed) under a tangential load (`crate::validity`).
    KinematicsOutOfRange,
}

impl Status {
    /// Name used in reports and JSON.
    pub fn name(self) -> &'static str {
        match self {
            Status::Solved => "solved",
            Status::RayTermination => "ray_termination",
            Status::NotConverged => "not_converged",
            Status::Infeasible => "infeasible",
            Status::NumericalError => "numerical_error",
            Status::ContactAtZoneEdge => "contact_at_zone_edge",
            Status::KinematicsOutOfRange => "kinematics_out_of_range",
        }
    }

    /// Every status: `solved`, then the failures of the solve, then the answers that are not the wheel's.
    pub const ALL: [Status; 7] = [
        Status::Solved,
        Status::Infeasible,
        Status::RayTermination,
        Status::NotConverged,
        Status::NumericalError,
        Status::ContactAtZoneEdge,
        Status::KinematicsOutOfRange,
    ];

    /// The process exit code of a command whose verdict is this status when nothing else was declared (`rollbem lcp
    /// solve`; `rollbem check` against the default expectation `solved`): 0 for `solved`, 1 for every other status
    /// (no answer, or an answer that is not the wheel's). A scene that declares another expected status
    /// (`[checks] status`) turns it into a passing check instead.
    pub fn exit_code(self) -> i32 {
        match self {
            Status::Solved => 0,
            _ => 1,
        }
    }
}

impl std::fmt::Display for Status {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.pad(self.name())
    }
}
