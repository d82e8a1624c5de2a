//! A solver written outside rollbem and plugged in at run time: projected Gauss–Seidel on the problem's LCP
//! (`w = M z + q ≥ 0, z ≥ 0, wᵀz = 0`), `z_i ← max(0, z_i − (M z + q)_i / M_ii)` sweep after sweep. It needs a
//! positive diagonal and converges for a symmetric positive definite M, so it admits frictionless scenes only (the
//! frictionless LCP's M is K_NN, nearly symmetric positive definite; a load-driven one borders it with the
//! equilibrium rows, whose zero diagonal it refuses as a numerical error).
//!
//! This file is the whole solver: settings, the `Solver` impl and its registry `Entry`. Adding it to a program
//! takes one line, `rollbem::solvers::register(&lcp_pgs::ENTRY)` (tests/solver_plugin.rs,
//! examples/cli_with_plugin.rs). It is not part of the library.

use rollbem::formulation::ContactProblem;
use rollbem::solvers::{settings_of, Entry, Facts, Outcome, Solver, SolverId, Start, Termination, Validate, Work};
use serde::{Deserialize, Serialize};

/// `[solvers.lcp_pgs]`.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct LcpPgsSettings {
    /// Stop when the largest update of a sweep is below `tolerance · max z`. Default 1e-12.
    pub tolerance: f64,
    /// Sweeps before giving up (`not_converged`). Default 200 000.
    pub max_sweeps: usize,
}

impl Default for LcpPgsSettings {
    fn default() -> Self {
        LcpPgsSettings { tolerance: 1e-12, max_sweeps: 200_000 }
    }
}

impl Validate for LcpPgsSettings {
    fn validate(&self) -> Result<(), (&'static str, String)> {
        rollbem::solvers::check_tolerance("tolerance", self.tolerance)?;
        rollbem::solvers::check_count("max_sweeps", self.max_sweeps)
    }

    fn tolerance(&self) -> Option<f64> {
        Some(self.tolerance)
    }
}

/// The solver.
pub struct LcpPgs {
    id: SolverId,
    settings: LcpPgsSettings,
}

/// Its registry entry: the one line a program adds is `register(&ENTRY)`.
pub static ENTRY: Entry = Entry::new::<LcpPgsSettings>(
    "lcp_pgs",
    "projected Gauss–Seidel on the LCP (a plug-in from tests/plugin); frictionless",
    false,
    &["sweeps"],
    |id, s| Box::new(LcpPgs { id, settings: settings_of::<LcpPgsSettings>(s).copied().unwrap_or_default() }),
    |m| (1e-8 * m * m * m, 8.0 * m * m),
);

impl Solver for LcpPgs {
    fn id(&self) -> SolverId {
        self.id
    }

    fn admits(&self, facts: &Facts) -> Result<(), String> {
        if facts.friction {
            Err("projected Gauss–Seidel on the LCP needs a positive diagonal: frictionless scenes only".into())
        } else {
            Ok(())
        }
    }

    fn uses_lcp(&self) -> bool {
        true
    }

    fn tolerance(&self) -> Option<f64> {
        Some(self.settings.tolerance)
    }

    fn solve_from(&self, p: &ContactProblem, start: Start) -> Outcome {
        let Some(lcp) = p.lcp() else {
            return Outcome::failed(
                Termination::Infeasible,
                "no static problem (gross sliding)".into(),
                Work::default(),
            );
        };
        let (mat, q, m) = (lcp.m(), lcp.q(), lcp.size());
        if (0..m).any(|i| mat[(i, i)].is_nan() || mat[(i, i)] <= 0.0) {
            let why = "the LCP's diagonal is not positive (a load-driven DOF's equilibrium row)".to_string();
            return Outcome::failed(Termination::NumericalError, why, Work::default());
        }
        let mut z = vec![0.0; m];
        for sweep in 1..=self.settings.max_sweeps {
            if start.cancel.is_cancelled() {
                return Outcome::failed(
                    Termination::NotConverged,
                    format!("cancelled at sweep {sweep}"),
                    Work::default(),
                );
            }
            let (mut change, mut scale) = (0.0_f64, 0.0_f64);
            for i in 0..m {
                let w: f64 = q[i] + (0..m).map(|j| mat[(i, j)] * z[j]).sum::<f64>();
                let new: f64 = (z[i] - w / mat[(i, i)]).max(0.0);
                change = change.max((new - z[i]).abs());
                z[i] = new;
                scale = scale.max(new);
            }
            if change <= self.settings.tolerance * scale {
                let work = Work::one("sweeps", sweep as u64);
                return match p.unpack(&z) {
                    Some(solution) => Outcome::solved(solution, format!("converged in {sweep} sweeps"), work),
                    None => Outcome::failed(Termination::NumericalError, "z of another size".into(), work),
                };
            }
        }
        let n = self.settings.max_sweeps as u64;
        Outcome::failed(Termination::NotConverged, format!("no convergence in {n} sweeps"), Work::one("sweeps", n))
    }
}
