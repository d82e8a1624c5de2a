//! The outcome of a contact solve: one status for every solver and formulation (after the solver-independent
//! residual check of [`crate::post`]).

use serde::{Deserialize, Serialize};

/// Outcome of a solver run.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Status {
    /// A solution was found and its solver-independent residuals are small.
    Solved,
    /// Lemke's algorithm ended on a secondary ray. For a copositive-plus LCP (the frictionless ones) this proves
    /// infeasibility and is reported as [`Status::Infeasible`]; the frictional LCPs are not copositive-plus, so on a
    /// load-driven one the equilibrium LP decides ([`crate::validity::decide`]): no admissible contact forces →
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
    /// zone must be ([`crate::validity`]).
    ContactAtZoneEdge,
    /// The solution uses the linearised (small-rotation) kinematics far outside their range: the wheel's rigid
    /// rotation φ moves its contact points by φR, more than [`crate::tolerances::ROTATION_ARC_MAX`] contact
    /// half-widths, so the gaps and the lever arms of the moment equilibrium are not the wheel's. Typical of a wheel
    /// free to turn (moment prescribed) under a tangential load ([`crate::validity`]).
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
