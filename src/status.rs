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
    /// infeasibility and is reported as [`Status::Infeasible`]; the frictional LCPs are not copositive-plus, so a ray
    /// there leaves feasibility undecided and keeps this status.
    RayTermination,
    /// The iteration limit was reached before the tolerance.
    NotConverged,
    /// The problem has no solution (e.g. a load the contact cannot carry).
    Infeasible,
    /// The solver failed numerically, or claimed success with a large independent residual.
    NumericalError,
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
        }
    }
}

impl std::fmt::Display for Status {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.pad(self.name())
    }
}
