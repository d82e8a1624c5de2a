//! Residuals of a solution of an LCP `w = M z + q`, `w ≥ 0`, `z ≥ 0`, `wᵀz = 0`, scaled so that round-off reads as
//! round-off, and a timed solve of an LCP by one of rollbem's Lemke engines (what `rollbem lcp solve` reports).
//!
//! ## The scale
//! Every w-type residual is divided by the **data scale**
//!
//! ```text
//!   s = max(‖q‖∞, ‖M‖∞ ‖z‖∞)        ‖M‖∞ = maxᵢ Σⱼ |Mᵢⱼ|  (the largest absolute row sum)
//! ```
//!
//! Why: wᵢ = Σⱼ Mᵢⱼ zⱼ + qᵢ is a sum of terms bounded by |qᵢ| and Σⱼ |Mᵢⱼ| |zⱼ| ≤ ‖M‖∞ ‖z‖∞, so floating-point
//! evaluation errs by about ε·(‖q‖∞ + ‖M‖∞ ‖z‖∞) ≤ 2ε s (Higham, *Accuracy and Stability of Numerical Algorithms*,
//! §3.1, for inner products). Divided by s, a solution exact to round-off reads as a few ε (≈ 1e-16) however small w
//! is, and a wrong one reads as O(1). The alternatives fail one way or the other:
//! - dividing by max|w| (what `lcp solve` printed before) makes round-off read as 1 when the exact w is zero, as in
//!   every problem whose solution has w = 0 (Siconos' `lcp_deudeu`, `lcp_trivial`, `lcp_CPS_4`: "0.57", "1.0");
//! - dividing by ‖q‖ (Siconos' `lcp_compute_error`, with ‖·‖₂) ignores the size of M z: when z is large because M
//!   is nearly singular, the cancellation in M z + q leaves round-off of order ε ‖M‖ ‖z‖ ≫ ε ‖q‖ (Siconos'
//!   `lcp_tobenna`: z up to 570 with |q| ≤ 1, so an exact Lemke answer shows `lcp_compute_error` ≈ 1e-12 while
//!   its s-scaled residual is ≈ 1e-16). s contains ‖q‖∞, so it is never smaller than Siconos' scale in ∞-norm.
//!
//! z-type quantities are scaled by ‖z‖∞ (the negativity of z), and complementarity by s·‖z‖∞, so all residuals are
//! dimensionless whatever the units of z and w. For comparison with Siconos, [`LcpResiduals::siconos_error`] is
//! Siconos' own measure, ‖z − max(0, z − w)‖₂ / ‖q‖₂ with w = M z + q (divided by 1 when ‖q‖₂ ≤ ε, as Siconos does).

use crate::error::ArgumentError;
use crate::solvers::{Lcp, LcpOutcome, LcpSolver};
use serde::Serialize;
use std::time::Instant;

/// Residuals of (z, w) for an LCP, each dimensionless (see the module docs for the scale).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[non_exhaustive]
pub struct LcpResiduals {
    /// The data scale s = max(‖q‖∞, ‖M‖∞ ‖z‖∞) the w-type residuals are divided by.
    pub scale: f64,
    /// Infeasibility of w: maxᵢ max(0, −wᵢ) / s.
    pub negative_w: f64,
    /// Infeasibility of z: maxᵢ max(0, −zᵢ) / ‖z‖∞ (0 when z = 0).
    pub negative_z: f64,
    /// Complementarity: maxᵢ |wᵢ zᵢ| / (s ‖z‖∞) (0 when z = 0).
    pub complementarity: f64,
    /// Consistency of the given w with z: maxᵢ |wᵢ − (M z + q)ᵢ| / s.
    pub equation: f64,
    /// The largest of the four above.
    pub max: f64,
    /// Siconos' `lcp_compute_error`: ‖z − max(0, z − w)‖₂ / ‖q‖₂ with w = M z + q recomputed from z.
    pub siconos_error: f64,
}

/// Residuals of a candidate solution (z, w) of `lcp` (w as reported by the solver; it is also checked against
/// M z + q). Non-finite entries give non-finite residuals. A z or w of another size than the LCP's is refused,
/// naming it.
pub fn residuals(lcp: &Lcp, z: &[f64], w: &[f64]) -> Result<LcpResiduals, ArgumentError> {
    let n = lcp.size();
    for (name, v) in [("z", z), ("w", w)] {
        if v.len() != n {
            return Err(ArgumentError::new("residuals", name, format!("has {} entries, the LCP {n}", v.len())));
        }
    }
    let inf = |v: &[f64]| v.iter().fold(0.0_f64, |a, x| a.max(x.abs()));
    let m_inf = (0..n).map(|i| (0..n).map(|j| lcp.m[(i, j)].abs()).sum::<f64>()).fold(0.0_f64, f64::max);
    let (q_inf, z_inf) = (inf(&lcp.q), inf(z));
    let scale = q_inf.max(m_inf * z_inf);
    // s = 0 only when q = 0 and M z = 0 term by term: then w = 0 exactly and any nonzero w is wrong whatever its size.
    let s = if scale > 0.0 { scale } else { f64::MIN_POSITIVE };
    let zs = if z_inf > 0.0 { z_inf } else { 1.0 };
    let mz_q = lcp.w_of_sized(z);
    let mut r = LcpResiduals {
        scale,
        negative_w: 0.0,
        negative_z: 0.0,
        complementarity: 0.0,
        equation: 0.0,
        max: 0.0,
        siconos_error: 0.0,
    };
    let nan_max = |a: f64, b: f64| if a.is_nan() || b.is_nan() { f64::NAN } else { a.max(b) };
    let mut natural = 0.0;
    for i in 0..n {
        r.negative_w = nan_max(r.negative_w, (-w[i]).max(0.0) / s);
        r.negative_z = nan_max(r.negative_z, (-z[i]).max(0.0) / zs);
        r.complementarity = nan_max(r.complementarity, (w[i] * z[i]).abs() / (s * zs));
        r.equation = nan_max(r.equation, (w[i] - mz_q[i]).abs() / s);
        let d = z[i] - (z[i] - mz_q[i]).max(0.0);
        natural += d * d;
    }
    let q2 = lcp.q.iter().map(|v| v * v).sum::<f64>().sqrt();
    r.siconos_error = natural.sqrt() / if q2 > f64::EPSILON { q2 } else { 1.0 };
    r.max = [r.negative_w, r.negative_z, r.complementarity, r.equation].into_iter().fold(0.0, nan_max);
    Ok(r)
}

/// A solve of an LCP: the solver's outcome, its residuals and the wall time of the solve.
#[derive(Debug, Clone)]
#[non_exhaustive]
pub struct LcpSolve {
    /// What the solver returned.
    pub outcome: LcpOutcome,
    /// [`residuals`] of the returned (z, w).
    pub residuals: LcpResiduals,
    /// Wall time of the solver call alone, in seconds (not reading the file, not the residuals).
    pub solve_time_s: f64,
}

/// Solve `lcp` with a solver of bare LCPs ([`crate::solvers::Solver::lcp_solver`]), timing the solver call alone,
/// and compute the residuals of its answer. A solver's answer of another size than the LCP's is refused
/// ([`residuals`]).
pub fn solve_timed(lcp: &Lcp, solver: &dyn LcpSolver) -> Result<LcpSolve, ArgumentError> {
    let start = Instant::now();
    let outcome = solver.solve_lcp(lcp);
    let solve_time_s = start.elapsed().as_secs_f64();
    let residuals = residuals(lcp, &outcome.z, &outcome.w)?;
    Ok(LcpSolve { outcome, residuals, solve_time_s })
}

/// Solve `lcp` with a registered solver of bare LCPs by name; `Err` says which names solve LCP files (or what is
/// wrong with a solver's answer, [`solve_timed`]).
pub fn solve_named(lcp: &Lcp, name: &str) -> Result<LcpSolve, String> {
    let lcp_solvers: Vec<Box<dyn crate::solvers::Solver>> = crate::solvers::registry()
        .into_iter()
        .filter_map(|e| e.id.build(&Default::default()))
        .filter(|s| s.lcp_solver().is_some())
        .collect();
    let names: Vec<&str> = lcp_solvers.iter().map(|s| s.name()).collect();
    let bad = || format!("`{name}` does not solve LCP files (expected one of: {})", names.join(", "));
    let solver = lcp_solvers.iter().find(|s| s.name() == name).ok_or_else(bad)?;
    let lcp_solver = solver.lcp_solver().ok_or_else(bad)?;
    solve_timed(lcp, lcp_solver).map_err(|e| format!("`{name}`'s answer: {e}"))
}

impl LcpSolve {
    /// What `rollbem lcp solve` prints: the status, the work, the residuals and the solver's message.
    pub fn summary(&self, size: usize) -> String {
        let (out, r) = (&self.outcome, &self.residuals);
        format!(
            "status {}  {}  size {size}  solve time {:.3e} s\n\
             residuals (relative to s = max(‖q‖∞, ‖M‖∞‖z‖∞) = {:.3e}): max(0, −w)/s {:.1e}, max(0, −z)/‖z‖∞ {:.1e}, \
             max|w z|/(s ‖z‖∞) {:.1e}, max|w − (Mz + q)|/s {:.1e}; Siconos' lcp_compute_error {:.1e}\n{}\n",
            out.termination,
            out.work.long(),
            self.solve_time_s,
            r.scale,
            r.negative_w,
            r.negative_z,
            r.complementarity,
            r.equation,
            r.siconos_error,
            out.message
        )
    }

    /// The JSON document of `rollbem lcp solve --json`: solver, status, work counters (`pivots` for Lemke), message,
    /// solve time, z, w and the residuals.
    pub fn document(&self, solver: &str) -> String {
        let out = &self.outcome;
        let mut doc = serde_json::json!({
            "solver": solver, "status": out.termination, "message": out.message,
            "solve_time_s": self.solve_time_s, "z": out.z, "w": out.w, "residuals": self.residuals,
        });
        for (k, v) in &out.work.0 {
            doc[k.as_str()] = serde_json::json!(v);
        }
        // A JSON value's pretty text (what `serde_json::to_string_pretty` writes: two-space indent).
        format!("{doc:#}")
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::solvers::Termination;
    use faer::Mat;

    fn lcp(rows: &[&[f64]], q: &[f64]) -> Lcp {
        let n = q.len();
        Lcp { m: Mat::from_fn(n, n, |i, j| rows[i][j]), q: q.to_vec() }
    }

    /// Siconos' `lcp_deudeu.dat`: M = [[2, 1], [1, 2]], q = (−5, −6); by hand z = M⁻¹(−q) = (4/3, 7/3), w = 0.
    fn deudeu() -> Lcp {
        lcp(&[&[2.0, 1.0], &[1.0, 2.0]], &[-5.0, -6.0])
    }

    #[test]
    fn round_off_reads_as_round_off() {
        // The exact solution is z = (4/3, 7/3), w = 0 (by hand); rollbem's Lemke returns it to round-off, with a w
        // that is round-off but not zero (the old max|w| scaling printed this answer as 0.57 and 1.0).
        let p = deudeu();
        let lemke = crate::solvers::build("lemke").unwrap();
        let solved = solve_timed(&p, lemke.lcp_solver().unwrap()).unwrap();
        let (z, w) = (&solved.outcome.z, &solved.outcome.w);
        assert_eq!(solved.outcome.termination, Termination::Solved);
        assert!((z[0] - 4.0 / 3.0).abs() < 1e-15 && (z[1] - 7.0 / 3.0).abs() < 1e-15, "z = {z:?}");
        assert!(w.iter().any(|&v| v != 0.0) && w.iter().all(|v| v.abs() < 1e-14), "w = {w:?}");
        let r = solved.residuals;
        assert_eq!(r, residuals(&p, z, w).unwrap());
        // s = max(‖q‖∞ = 6, ‖M‖∞ ‖z‖∞ = 3 · 7/3 = 7) = 7 (by hand).
        assert!((r.scale - 7.0).abs() < 1e-14);
        assert!(r.max < 4.0 * f64::EPSILON && r.siconos_error < 4.0 * f64::EPSILON, "{r:?}");
        assert!(solved.solve_time_s >= 0.0 && solved.solve_time_s.is_finite());
    }

    #[test]
    fn wrong_solutions_read_as_order_one() {
        let p = deudeu();
        // z = 0 is feasible but w = q = (−5, −6): max(0, −w)/s = 6/6 = 1 (s = ‖q‖∞ = 6 as z = 0).
        let r = residuals(&p, &[0.0, 0.0], &p.q).unwrap();
        assert!((r.negative_w - 1.0).abs() < 1e-15 && r.max == r.negative_w, "{r:?}");
        // z = (3, 0): w = (1, −3), w₁ z₁ = 3 ≠ 0 and w₂ < 0. s = max(6, 3 · 3) = 9; complementarity 3/(9·3) = 1/9,
        // negative w 3/9 = 1/3.
        let z = [3.0, 0.0];
        let r = residuals(&p, &z, &p.w_of(&z).unwrap()).unwrap();
        assert!((r.negative_w - 1.0 / 3.0).abs() < 1e-15 && (r.complementarity - 1.0 / 9.0).abs() < 1e-15, "{r:?}");
        // A w that does not match z, and a negative z.
        // (w₁ z₁ = 4/3, s ‖z‖∞ = 7 · 7/3: complementarity 4/49; |w − (M z + q)| = 1: equation 1/7.)
        let r = residuals(&p, &[4.0 / 3.0, 7.0 / 3.0], &[1.0, 0.0]).unwrap();
        assert!((r.equation - 1.0 / 7.0).abs() < 1e-14 && (r.complementarity - 4.0 / 49.0).abs() < 1e-14, "{r:?}");
        let r = residuals(&p, &[-1.0, 2.0], &p.w_of(&[-1.0, 2.0]).unwrap()).unwrap();
        assert!((r.negative_z - 0.5).abs() < 1e-15, "{r:?}");
        // Non-finite input is reported, not hidden.
        assert!(residuals(&p, &[f64::NAN, 0.0], &[0.0, 0.0]).unwrap().max.is_nan());
    }

    #[test]
    fn large_z_from_a_nearly_singular_m_is_judged_on_its_own_scale() {
        // M = [[1, −1], [−1, 1 + δ]] (positive definite, det δ = 1e−8), q = (−1, 1 − 1e6 δ). Solved by hand: w = 0
        // gives z₁ − z₂ = 1 and δ (z₂ − 1e6) = 0, so z = (1e6 + 1, 1e6) with ‖q‖ ≈ 1. The terms of M z + q are ≈ 1e6,
        // so an answer exact to round-off has w ≈ ε·1e6: the data scale s ≈ 2e6 reads it as ≈ 1e−16, Siconos'
        // ‖q‖ scaling as ≈ 1e−10 (observed with this Lemke answer: 5.8e−17 against 8.3e−11).
        let d = 1e-8;
        let p = lcp(&[&[1.0, -1.0], &[-1.0, 1.0 + d]], &[-1.0, 1.0 - d * 1e6]);
        let dense = crate::solvers::build("lemke_dense").unwrap();
        let out = solve_timed(&p, dense.lcp_solver().unwrap()).unwrap();
        assert_eq!(out.outcome.termination, Termination::Solved, "{}", out.outcome.message);
        // z itself is only as accurate as the conditioning (κ ≈ 4e8) allows.
        assert!((out.outcome.z[1] - 1e6).abs() < 1e-6 * 1e6, "z = {:?}", out.outcome.z);
        let r = out.residuals;
        assert!(r.scale > 1e6 && r.max < 1e-15, "{r:?}");
        assert!(r.siconos_error > 1e-12, "the ‖q‖ scaling overstates this round-off: {r:?}");
    }

    #[test]
    fn only_solvers_of_bare_lcps_solve_files() {
        let p = deudeu();
        for name in ["lemke", "lemke_dense"] {
            let s = crate::solvers::build(name).unwrap();
            let solved = solve_timed(&p, s.lcp_solver().expect("a solver of bare LCPs")).unwrap();
            assert_eq!(solved.outcome.termination, Termination::Solved, "{name}");
        }
        for name in ["pgs", "active_set", "clarabel", "normtang_qp"] {
            assert!(crate::solvers::build(name).unwrap().lcp_solver().is_none(), "{name}");
        }
    }
}
