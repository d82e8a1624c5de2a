//! Contact solvers. A solver consumes a formulation (plain data: an [`Lcp`] or a QP) and returns a solution and a
//! [`Status`]. Non-convergence, ray termination and infeasibility are outcomes, never panics.

pub mod clarabel_box;
pub mod clarabel_qp;
pub mod lemke;
pub mod lemke_block;
pub mod normtang;

use faer::Mat;
use serde::Serialize;

/// A linear complementarity problem in the convention `w = M z + q`, `w ≥ 0`, `z ≥ 0`, `wᵀz = 0`
/// (the seed's eq. 50 writes `w − M z = b`: `q = b`).
#[derive(Debug, Clone)]
pub struct Lcp {
    /// The square matrix M (m × m).
    pub m: Mat<f64>,
    /// The vector q (length m).
    pub q: Vec<f64>,
}

impl Lcp {
    /// Problem size m.
    pub fn size(&self) -> usize {
        self.q.len()
    }

    /// `w = M z + q` for a given `z`.
    pub fn w_of(&self, z: &[f64]) -> Vec<f64> {
        let m = self.size();
        let mut w = self.q.clone();
        for (j, &zj) in z.iter().enumerate() {
            if zj != 0.0 {
                for (i, wi) in w.iter_mut().enumerate().take(m) {
                    *wi += self.m[(i, j)] * zj;
                }
            }
        }
        w
    }
}

/// Outcome of a solver run.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, serde::Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Status {
    /// A solution was found and its solver-independent residuals are small.
    Solved,
    /// Lemke's algorithm ended on a secondary ray: the LCP has no solution (for the problems rollbem builds, which
    /// are copositive-plus, this proves infeasibility).
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
        f.write_str(self.name())
    }
}
