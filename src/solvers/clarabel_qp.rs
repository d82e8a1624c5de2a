//! Frictionless normal-contact solve as a convex QP with the Clarabel interior-point solver,
//! followed by an optional active-set "polish" with the original nonsymmetric flexibility.
//!
//! # Problem
//!
//! Unknowns are the nodal normal forces `f` (N per unit thickness in 2D: pressure × tributary
//! length of contact node `i`; compressive contact force is **positive**). The gap is
//!
//! ```text
//! g = K f + c − d·a
//! ```
//!
//! where `K` (m/N, dense `n×n`, column-major) is the BEM flexibility, `c` (m) the unloaded
//! gap, `a` a weight vector (ones in practice) and `d` (m) the rigid approach, **positive when
//! the bodies are pressed harder together** (it closes the gap). The contact conditions are the
//! LCP `g ≥ 0, f ≥ 0, fᵢ gᵢ = 0`, plus `aᵀ f = P` when the total load `P` (N) is prescribed
//! (then `d` is an unknown); when the load is not prescribed `d` is already folded into `c`.
//!
//! `K` is only nearly symmetric (collocation BEM), so the LCP is not exactly a QP. We solve the
//! symmetrised QP
//!
//! ```text
//! min ½ fᵀ K_s f + cᵀ f   s.t.  f ≥ 0  [, aᵀ f = P],      K_s = (K + Kᵀ)/2
//! ```
//!
//! whose KKT conditions are the LCP with `K_s` in place of `K` (the multiplier of the equality
//! is `d`). The interior-point solution therefore differs from the LCP solution by about the
//! relative asymmetry of `K`. The **polish** then fixes the active set `S` found by the
//! interior-point method and solves the equality system of the *nonsymmetric* `K` on `S`
//! (`K_SS f_S + c_S − d a_S = 0`, `a_Sᵀ f_S = P`), accepting it only if it satisfies every LCP
//! condition; after a successful polish the result agrees with a pivoting (Lemke) solve of the
//! nonsymmetric LCP to round-off.

use std::fmt;
use std::panic::{catch_unwind, AssertUnwindSafe};

use clarabel::algebra::CscMatrix;
use clarabel::solver::{
    DefaultSettingsBuilder, DefaultSolver, IPSolver, SolverStatus,
    SupportedConeT::{NonnegativeConeT, ZeroConeT},
};
use faer::prelude::*;

/// Maximum number of active-set correction rounds tried by the polish (each round drops nodes
/// with a negative force and adds nodes with a negative gap, then re-solves).
const MAX_POLISH_ROUNDS: usize = 4;

/// Clarabel's static KKT regularisation. Its default (1e-8) makes the interior-point method stall
/// ("InsufficientProgress") at the tight tolerances used here once n ≳ 200 (measured on a
/// log-kernel flexibility, n = 200..1000); 1e-12 converges in 15–19 iterations.
const STATIC_REGULARIZATION: f64 = 1e-12;

/// Settings for the interior-point frictionless solve.
///
/// Defaults: `tolerance = 1e-12`, `max_iter = 200`, `polish = true`.
#[derive(Debug, Clone, PartialEq, serde::Serialize, serde::Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct QpSettings {
    /// Relative/absolute tolerance (dimensionless, applied to the internally scaled problem)
    /// passed to Clarabel as `tol_gap_abs`, `tol_gap_rel` and `tol_feas`; also the relative
    /// tolerance on negative gaps when the polish is checked. Default `1e-12` (Clarabel's own
    /// default of `1e-8` is not accurate enough to reproduce the LCP solution).
    pub tolerance: f64,
    /// Maximum number of interior-point iterations. Default `200` (about 20 are typical).
    pub max_iter: u32,
    /// Whether to run the active-set polish with the nonsymmetric `K`. Default `true`.
    pub polish: bool,
}

impl Default for QpSettings {
    fn default() -> Self {
        Self { tolerance: 1e-12, max_iter: 200, polish: true }
    }
}

/// Termination status of [`solve_frictionless`].
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum QpStatus {
    /// Converged to the requested tolerance.
    Solved,
    /// Converged only to Clarabel's reduced tolerances (still usually accurate to ~1e-5
    /// relative; a successful polish makes it exact).
    AlmostSolved,
    /// Iteration or time limit reached; the returned forces are the last iterate.
    MaxIterations,
    /// No feasible force distribution exists (e.g. `P < 0` with `a ≥ 0`, or a nonzero load
    /// on an empty problem), or Clarabel returned an infeasibility certificate.
    Infeasible,
    /// Invalid input (NaN/∞, inconsistent sizes), a Clarabel setup error, a numerical failure
    /// or insufficient progress inside Clarabel; the message says which.
    NumericalError(String),
}

impl crate::solvers::Validate for QpSettings {
    fn validate(&self) -> Result<(), (&'static str, String)> {
        crate::solvers::check_tolerance("tolerance", self.tolerance)?;
        crate::solvers::check_count("max_iter", self.max_iter as usize)
    }
}

/// The one mapping of clarabel's outcome to rollbem's [`crate::status::Termination`] (used by every solver that calls
/// clarabel).
impl From<&QpStatus> for crate::status::Termination {
    fn from(s: &QpStatus) -> Self {
        use crate::status::Termination as Status;
        match s {
            QpStatus::Solved | QpStatus::AlmostSolved => Status::Solved,
            QpStatus::MaxIterations => Status::NotConverged,
            QpStatus::Infeasible => Status::Infeasible,
            QpStatus::NumericalError(_) => Status::NumericalError,
        }
    }
}

impl QpStatus {
    /// `true` for [`QpStatus::Solved`] and [`QpStatus::AlmostSolved`].
    pub fn is_solved(&self) -> bool {
        matches!(self, QpStatus::Solved | QpStatus::AlmostSolved)
    }
}

impl fmt::Display for QpStatus {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            QpStatus::Solved => write!(f, "solved"),
            QpStatus::AlmostSolved => write!(f, "almost solved (reduced accuracy)"),
            QpStatus::MaxIterations => write!(f, "iteration/time limit reached"),
            QpStatus::Infeasible => write!(f, "infeasible"),
            QpStatus::NumericalError(msg) => write!(f, "numerical error: {msg}"),
        }
    }
}

/// Outcome of [`solve_frictionless`].
#[derive(Debug, Clone)]
#[non_exhaustive]
pub struct QpOutcome {
    /// Nodal normal forces (N, ≥ 0, compressive positive), length `n`: the polished solution
    /// if the polish was accepted, otherwise the interior-point solution.
    pub f: Vec<f64>,
    /// Rigid approach `d` (m, positive pressing harder) when the load is prescribed: from the
    /// polish if accepted, otherwise from the multiplier of the load equality. `None` in the
    /// displacement-driven case.
    pub approach: Option<f64>,
    /// Number of interior-point iterations.
    pub iterations: u32,
    /// Termination status (of the interior-point solve, or of the input validation).
    pub status: QpStatus,
    /// Whether the active-set polish was run and accepted.
    pub polished: bool,
    /// The raw interior-point solution (N), before polishing (equal to `f` if not polished).
    pub f_unpolished: Vec<f64>,
}

impl QpOutcome {
    fn failed(n: usize, status: QpStatus) -> Self {
        Self { f: vec![0.0; n], approach: None, iterations: 0, status, polished: false, f_unpolished: vec![0.0; n] }
    }
}

/// Solve the frictionless contact problem `g = K f + c − d·a ≥ 0, f ≥ 0, f ⊥ g [, aᵀ f = P]`
/// with Clarabel (symmetrised `K`) and, if `s.polish`, an active-set polish with the original
/// nonsymmetric `K`.
///
/// * `k`: flexibility `K` (m/N), column-major `n×n`: `k[i + j*n] = K_ij` = gap change at node
///   `i` per unit force at node `j`. Should be (nearly) symmetric positive definite.
/// * `c`: unloaded gap (m), length `n` (negative entries = initial interpenetration).
/// * `load`: `None` for the displacement-driven case (the approach is already in `c`), or
///   `Some((a, P))` with the weights `a` (length `n`, ones in practice) and the total load
///   `P = aᵀ f` (N); then the approach `d` is returned in [`QpOutcome::approach`].
///
/// Never panics: invalid input, setup errors and solver failures are reported in
/// [`QpOutcome::status`] (with zero forces when nothing could be computed). `n = 0` gives
/// `Solved` with empty vectors unless a nonzero load is prescribed (`Infeasible`).
pub fn solve_frictionless(k: &[f64], n: usize, c: &[f64], load: Option<(&[f64], f64)>, s: &QpSettings) -> QpOutcome {
    solve_frictionless_cancellable(k, n, c, load, s, &crate::cancel::Cancel::never())
}

/// [`solve_frictionless`], stopping at the interior-point iteration after `cancel` is raised (clarabel's
/// termination callback; the status is then a numerical error naming the callback).
pub fn solve_frictionless_cancellable(
    k: &[f64],
    n: usize,
    c: &[f64],
    load: Option<(&[f64], f64)>,
    s: &QpSettings,
    cancel: &crate::cancel::Cancel,
) -> QpOutcome {
    if let Err(out) = validate_input(k, n, c, load, s) {
        return out;
    }
    // ---- scaling: f = alpha * f_hat, g = gamma * g_hat, d = gamma / amax * d_hat ---------
    let kscale = positive_or(k.iter().fold(0.0_f64, |m, v| m.max(v.abs())), 1.0);
    let cscale = c.iter().fold(0.0_f64, |m, v| m.max(v.abs()));
    let amax = load.map_or(1.0, |(a, _)| positive_or(a.iter().fold(0.0_f64, |m, v| m.max(v.abs())), 1.0));
    let (alpha, gamma) = match load {
        Some((a, p)) if p != 0.0 => {
            // average force if the load were spread over all nodes; gap scale from c or from
            // the displacement that the whole load would cause.
            let asum: f64 = a.iter().map(|v| v.abs()).sum();
            let alpha = p.abs() / asum;
            let gamma = positive_or(cscale.max(kscale * p.abs() / amax), kscale * alpha);
            (alpha, gamma)
        }
        _ => {
            let gamma = positive_or(cscale, kscale);
            (gamma / kscale, gamma)
        }
    };
    let (p_mat, q, a_mat, b, cones) = clarabel_data(k, n, c, load, alpha, gamma, amax);

    let settings = match clarabel_settings(s) {
        Ok(st) => st,
        Err(e) => return QpOutcome::failed(n, QpStatus::NumericalError(e)),
    };

    // Clarabel should not panic on valid finite data; guard anyway so callers never see one.
    let run = catch_unwind(AssertUnwindSafe(|| {
        let mut solver =
            DefaultSolver::new(&p_mat, &q, &a_mat, &b, &cones, settings).map_err(|e| format!("clarabel setup: {e}"))?;
        let cancel = cancel.clone();
        solver.set_termination_callback(move |_| cancel.is_cancelled());
        solver.solve();
        let sol = &solver.solution;
        Ok::<_, String>((sol.x.clone(), sol.z.clone(), sol.status, sol.iterations))
    }));
    let (x, z, cl_status, iterations) = match run {
        Ok(Ok(r)) => r,
        Ok(Err(msg)) => return QpOutcome::failed(n, QpStatus::NumericalError(msg)),
        Err(_) => return QpOutcome::failed(n, QpStatus::NumericalError("clarabel panicked".into())),
    };

    let status = map_status(cl_status);

    // Unscale. f >= 0 is enforced only up to the interior-point tolerance: clip round-off.
    let f_unpolished: Vec<f64> = x.iter().map(|&v| alpha * v.max(0.0)).collect();
    // KKT: K_s f + c + a z_eq - z_nn = 0 with z_nn = g  =>  d = -z_eq (scaled).
    let d_ipm = load.map(|_| -gamma * z[n] / amax);

    let mut out =
        QpOutcome { f: f_unpolished.clone(), approach: d_ipm, iterations, status, polished: false, f_unpolished };
    if matches!(out.status, QpStatus::Infeasible) {
        out.approach = None;
    }

    if s.polish && out.status.is_solved() && x.iter().all(|v| v.is_finite()) {
        // Initial active set from strict complementarity of the scaled iterate:
        // f_hat_i * g_hat_i ≈ mu, active where the force dominates the gap.
        let active: Vec<bool> = (0..n).map(|i| x[i] > z[i]).collect();
        let scaled = Scaled { k, n, c, load, alpha, gamma, amax };
        if let Some((f, d)) = polish(&scaled, active, s.tolerance) {
            out.f = f;
            if load.is_some() {
                out.approach = Some(d);
            }
            out.polished = true;
        }
    }
    out
}

/// Check the inputs of [`solve_frictionless`]; `Err` carries the outcome to return (including the trivial
/// `n = 0` solution and a provably infeasible load).
fn validate_input(
    k: &[f64],
    n: usize,
    c: &[f64],
    load: Option<(&[f64], f64)>,
    s: &QpSettings,
) -> Result<(), QpOutcome> {
    let nn = match n.checked_mul(n) {
        Some(v) => v,
        None => return Err(QpOutcome::failed(0, QpStatus::NumericalError("n*n overflows".into()))),
    };
    if k.len() != nn || c.len() != n {
        return Err(QpOutcome::failed(
            n.min(c.len()),
            QpStatus::NumericalError(format!(
                "inconsistent sizes: n = {n}, k.len() = {}, c.len() = {}",
                k.len(),
                c.len()
            )),
        ));
    }
    if let Some((a, _)) = load {
        if a.len() != n {
            return Err(QpOutcome::failed(n, QpStatus::NumericalError(format!("a.len() = {} but n = {n}", a.len()))));
        }
    }
    let all_finite = k.iter().chain(c.iter()).all(|v| v.is_finite())
        && load.is_none_or(|(a, p)| p.is_finite() && a.iter().all(|v| v.is_finite()));
    if !all_finite {
        return Err(QpOutcome::failed(
            n,
            QpStatus::NumericalError("non-finite (NaN/inf) entry in K, c, a or P".into()),
        ));
    }
    if !(s.tolerance.is_finite() && s.tolerance > 0.0) {
        return Err(QpOutcome::failed(n, QpStatus::NumericalError(format!("invalid tolerance {}", s.tolerance))));
    }
    if let Some((a, p)) = load {
        // {f ≥ 0, aᵀf = P} is nonempty iff P = 0 or some a_i has the sign of P.
        let feasible = p == 0.0 || a.iter().any(|&ai| ai * p > 0.0);
        if !feasible {
            return Err(QpOutcome::failed(n, QpStatus::Infeasible));
        }
    }
    if n == 0 {
        return Err(QpOutcome::failed(0, QpStatus::Solved));
    }
    Ok(())
}

/// Clarabel's data for the scaled QP: P (upper triangle of K_s α/γ), q, A = [−I; âᵀ], b = [0; P̂], cones.
#[allow(clippy::type_complexity)]
fn clarabel_data(
    k: &[f64],
    n: usize,
    c: &[f64],
    load: Option<(&[f64], f64)>,
    alpha: f64,
    gamma: f64,
    amax: f64,
) -> (CscMatrix<f64>, Vec<f64>, CscMatrix<f64>, Vec<f64>, Vec<clarabel::solver::SupportedConeT<f64>>) {
    let kf = alpha / gamma; // scaled flexibility factor
                            // P: upper triangle of K_s * alpha/gamma, column by column.
    let mut colptr = Vec::with_capacity(n + 1);
    let mut rowval = Vec::with_capacity(n * (n + 1) / 2);
    let mut nzval = Vec::with_capacity(n * (n + 1) / 2);
    colptr.push(0);
    for j in 0..n {
        for i in 0..=j {
            rowval.push(i);
            nzval.push(0.5 * (k[i + j * n] + k[j + i * n]) * kf);
        }
        colptr.push(rowval.len());
    }
    let p_mat = CscMatrix::new(n, n, colptr, rowval, nzval);
    let q: Vec<f64> = c.iter().map(|v| v / gamma).collect();

    // A = [-I; a_hat^T], b = [0; P_hat], cones = [Nonneg(n), Zero(1)].
    let m = n + usize::from(load.is_some());
    let mut colptr = Vec::with_capacity(n + 1);
    let mut rowval = Vec::with_capacity(2 * n);
    let mut nzval = Vec::with_capacity(2 * n);
    colptr.push(0);
    for j in 0..n {
        rowval.push(j);
        nzval.push(-1.0);
        if let Some((a, _)) = load {
            rowval.push(n);
            nzval.push(a[j] / amax);
        }
        colptr.push(rowval.len());
    }
    let a_mat = CscMatrix::new(m, n, colptr, rowval, nzval);
    let mut b = vec![0.0; m];
    let mut cones = vec![NonnegativeConeT(n)];
    if let Some((_, p)) = load {
        b[n] = p / (alpha * amax);
        cones.push(ZeroConeT(1));
    }
    (p_mat, q, a_mat, b, cones)
}

fn positive_or(v: f64, fallback: f64) -> f64 {
    if v > 0.0 && v.is_finite() {
        v
    } else {
        fallback
    }
}

/// Problem data and the scale factors (f = alpha f_hat, g = gamma g_hat, d = gamma/amax d_hat).
struct Scaled<'a> {
    k: &'a [f64],
    n: usize,
    c: &'a [f64],
    load: Option<(&'a [f64], f64)>,
    alpha: f64,
    gamma: f64,
    amax: f64,
}

/// Active-set polish with the nonsymmetric K. Returns the unscaled `(f, d)` (d = 0 when not
/// load-driven) if an active set satisfying all LCP conditions is reached within
/// `MAX_POLISH_ROUNDS` corrections of the initial guess.
fn polish(p: &Scaled<'_>, mut active: Vec<bool>, tol: f64) -> Option<(Vec<f64>, f64)> {
    let n = p.n;
    // Negative gaps down to -gap_tol (scaled) are accepted as round-off.
    let gap_tol = tol.max(16.0 * f64::EPSILON);
    for _ in 0..MAX_POLISH_ROUNDS {
        let was_active = active.clone();
        let idx: Vec<usize> = (0..n).filter(|&i| active[i]).collect();
        let (f_hat, d_hat) = solve_active(p, &idx)?;
        // Scaled gap on all nodes: g_hat = (alpha/gamma) K f_hat + c/gamma - d_hat a/amax.
        let kf = p.alpha / p.gamma;
        let mut g_hat: Vec<f64> = (0..n).map(|i| p.c[i] / p.gamma).collect();
        if let Some((a, _)) = p.load {
            for (gi, ai) in g_hat.iter_mut().zip(a) {
                *gi -= d_hat * ai / p.amax;
            }
        }
        for (jj, &j) in idx.iter().enumerate() {
            let col = &p.k[j * n..(j + 1) * n];
            let fj = kf * f_hat[jj];
            for (gi, kij) in g_hat.iter_mut().zip(col) {
                *gi += kij * fj;
            }
        }
        let mut changed = false;
        for (jj, &j) in idx.iter().enumerate() {
            if f_hat[jj] < 0.0 {
                active[j] = false;
                changed = true;
            }
        }
        for i in 0..n {
            if !was_active[i] && g_hat[i] < -gap_tol {
                active[i] = true;
                changed = true;
            }
        }
        if !changed {
            let mut f = vec![0.0; n];
            for (jj, &j) in idx.iter().enumerate() {
                f[j] = p.alpha * f_hat[jj];
            }
            return Some((f, p.gamma * d_hat / p.amax));
        }
    }
    None
}

/// Solve the scaled equality system on the active set `idx`:
/// `(alpha/gamma) K_SS f_hat − d_hat a_S/amax = −c_S/gamma` and, when load-driven,
/// `(a_S/amax)ᵀ f_hat = P/(alpha amax)`. Dense LU with one step of iterative refinement.
/// Returns `None` if the system is singular or the solution is not finite.
fn solve_active(p: &Scaled<'_>, idx: &[usize]) -> Option<(Vec<f64>, f64)> {
    let n = p.n;
    let ms = idx.len();
    let kf = p.alpha / p.gamma;
    let dim = ms + usize::from(p.load.is_some());
    if dim == 0 {
        return Some((Vec::new(), 0.0));
    }
    let entry = |r: usize, col: usize| -> f64 {
        match (r < ms, col < ms) {
            (true, true) => kf * p.k[idx[r] + idx[col] * n],
            (true, false) => p.load.map_or(0.0, |(a, _)| -a[idx[r]] / p.amax),
            (false, true) => p.load.map_or(0.0, |(a, _)| a[idx[col]] / p.amax),
            (false, false) => 0.0,
        }
    };
    let mat = Mat::from_fn(dim, dim, entry);
    let rhs = Mat::from_fn(dim, 1, |r, _| {
        if r < ms {
            -p.c[idx[r]] / p.gamma
        } else {
            p.load.map_or(0.0, |(_, pl)| pl / (p.alpha * p.amax))
        }
    });
    let lu = mat.partial_piv_lu();
    let mut sol = lu.solve(&rhs);
    // One step of iterative refinement: sol += LU⁻¹ (rhs − M sol).
    let resid = &rhs - &mat * &sol;
    let corr = lu.solve(&resid);
    sol += &corr;
    let v: Vec<f64> = (0..dim).map(|r| sol[(r, 0)]).collect();
    if !v.iter().all(|x| x.is_finite()) {
        return None;
    }
    // Reject a (near-)singular system: the residual must be at round-off level.
    let resid = &rhs - &mat * &sol;
    let rnorm = (0..dim).fold(0.0_f64, |m, r| m.max(resid[(r, 0)].abs()));
    let bnorm = (0..dim).fold(1.0_f64, |m, r| m.max(rhs[(r, 0)].abs()));
    if rnorm.is_nan() || rnorm > 1e-8 * bnorm {
        return None;
    }
    let d_hat = if p.load.is_some() { v[ms] } else { 0.0 };
    Some((v[..ms].to_vec(), d_hat))
}

/// clarabel's status as a [`QpStatus`] (shared by the QP wrappers).
pub(crate) fn map_status(st: SolverStatus) -> QpStatus {
    match st {
        SolverStatus::Solved => QpStatus::Solved,
        SolverStatus::AlmostSolved => QpStatus::AlmostSolved,
        SolverStatus::MaxIterations | SolverStatus::MaxTime => QpStatus::MaxIterations,
        SolverStatus::PrimalInfeasible
        | SolverStatus::DualInfeasible
        | SolverStatus::AlmostPrimalInfeasible
        | SolverStatus::AlmostDualInfeasible => QpStatus::Infeasible,
        other => QpStatus::NumericalError(format!("clarabel status {other:?}")),
    }
}

/// clarabel settings for verification-grade answers (shared by the QP wrappers): tolerances from `s`, quiet, and
/// the static regularisation that avoids stalls on log-kernel flexibilities (see [`STATIC_REGULARIZATION`]).
pub(crate) fn clarabel_settings(s: &QpSettings) -> Result<clarabel::solver::DefaultSettings<f64>, String> {
    DefaultSettingsBuilder::default()
        .verbose(false)
        .max_iter(s.max_iter)
        .tol_gap_abs(s.tolerance)
        .tol_gap_rel(s.tolerance)
        .tol_feas(s.tolerance)
        .tol_ktratio(1e-10)
        .static_regularization_constant(STATIC_REGULARIZATION)
        .build()
        .map_err(|e| format!("clarabel settings: {e}"))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Gap `g = K f + c − d a` for column-major `k`.
    fn gap(k: &[f64], n: usize, c: &[f64], a: Option<&[f64]>, d: f64, f: &[f64]) -> Vec<f64> {
        (0..n)
            .map(|i| {
                let kf: f64 = (0..n).map(|j| k[i + j * n] * f[j]).sum();
                kf + c[i] - a.map_or(0.0, |a| d * a[i])
            })
            .collect()
    }

    /// Max violation of the LCP conditions, relative to the scales `fs` (forces) and `gs`
    /// (gaps): negative forces, negative gaps and complementarity |f_i g_i|/(fs gs).
    fn lcp_violation(f: &[f64], g: &[f64], fs: f64, gs: f64) -> f64 {
        f.iter().zip(g).fold(0.0_f64, |m, (&fi, &gi)| {
            m.max((-fi / fs).max(0.0)).max((-gi / gs).max(0.0)).max((fi * gi).abs() / (fs * gs))
        })
    }

    /// Independent dense solver (Gaussian elimination with partial pivoting), row-major `m`.
    fn gauss(mut m: Vec<Vec<f64>>, mut b: Vec<f64>) -> Option<Vec<f64>> {
        let n = b.len();
        for col in 0..n {
            let piv = (col..n).max_by(|&x, &y| m[x][col].abs().total_cmp(&m[y][col].abs()))?;
            if m[piv][col].abs() < 1e-300 {
                return None;
            }
            m.swap(col, piv);
            b.swap(col, piv);
            let pivot_row = m[col].clone();
            for r in col + 1..n {
                let fac = m[r][col] / pivot_row[col];
                for (mrc, prc) in m[r][col..].iter_mut().zip(&pivot_row[col..]) {
                    *mrc -= fac * prc;
                }
                b[r] -= fac * b[col];
            }
        }
        let mut x = vec![0.0; n];
        for r in (0..n).rev() {
            let s: f64 = (r + 1..n).map(|cc| m[r][cc] * x[cc]).sum();
            x[r] = (b[r] - s) / m[r][r];
        }
        Some(x)
    }

    /// Brute-force LCP solution: try every active set S, solve the equality system of the
    /// (nonsymmetric) K on S, keep the sets that satisfy f ≥ 0, g ≥ 0. Returns all solutions
    /// as (f, d) (d = 0 when not load-driven).
    fn enumerate(k: &[f64], n: usize, c: &[f64], load: Option<(&[f64], f64)>) -> Vec<(Vec<f64>, f64)> {
        let mut sols = Vec::new();
        for mask in 0u32..(1 << n) {
            let idx: Vec<usize> = (0..n).filter(|&i| mask & (1 << i) != 0).collect();
            let ms = idx.len();
            let dim = ms + usize::from(load.is_some());
            let mut m = vec![vec![0.0; dim]; dim];
            let mut b = vec![0.0; dim];
            for (r, &i) in idx.iter().enumerate() {
                for (cc, &j) in idx.iter().enumerate() {
                    m[r][cc] = k[i + j * n];
                }
                b[r] = -c[i];
                if let Some((a, _)) = load {
                    m[r][ms] = -a[i];
                    m[ms][r] = a[i];
                }
            }
            if let Some((_, p)) = load {
                b[ms] = p;
            }
            let Some(x) = gauss(m, b) else { continue };
            let mut f = vec![0.0; n];
            for (r, &i) in idx.iter().enumerate() {
                f[i] = x[r];
            }
            let d = if load.is_some() { x[ms] } else { 0.0 };
            let g = gap(k, n, c, load.map(|l| l.0), d, &f);
            if f.iter().all(|&v| v >= -1e-13) && g.iter().all(|&v| v >= -1e-13) {
                sols.push((f, d));
            }
        }
        sols
    }

    fn max_abs(v: &[f64]) -> f64 {
        v.iter().fold(0.0_f64, |m, x| m.max(x.abs()))
    }

    fn max_diff(a: &[f64], b: &[f64]) -> f64 {
        a.iter().zip(b).fold(0.0_f64, |m, (x, y)| m.max((x - y).abs()))
    }

    /// K = tridiag(−1, 4, −1) plus an antisymmetric perturbation eps·(i − j)/n (column-major).
    /// Its symmetric part is positive definite, hence K is a P-matrix and the LCP has a unique
    /// solution.
    fn tridiag_k(n: usize, eps: f64) -> Vec<f64> {
        let mut k = vec![0.0; n * n];
        for j in 0..n {
            for i in 0..n {
                let mut v = match i.abs_diff(j) {
                    0 => 4.0,
                    1 => -1.0,
                    _ => 0.0,
                };
                v += eps * (i as f64 - j as f64) / n as f64;
                k[i + j * n] = v;
            }
        }
        k
    }

    #[test]
    fn small_displacement_driven_matches_enumeration() {
        // Expected values: brute-force enumeration of all 2^5 active sets (`enumerate`).
        let n = 5;
        let k = tridiag_k(n, 0.02);
        let c = [0.5, -1.0, -2.0, -0.5, 1.0];
        let sols = enumerate(&k, n, &c, None);
        assert_eq!(sols.len(), 1, "P-matrix LCP must have a unique solution");
        let f_ref = &sols[0].0;
        let out = solve_frictionless(&k, n, &c, None, &QpSettings::default());
        assert_eq!(out.status, QpStatus::Solved);
        assert!(out.polished);
        assert!(out.approach.is_none());
        let fs = max_abs(f_ref);
        let err = max_diff(&out.f, f_ref) / fs;
        let err_unpol = max_diff(&out.f_unpolished, f_ref) / fs;
        eprintln!("disp n=5: iters {}, |f-f_enum|/|f| polished {err:.2e}, unpolished {err_unpol:.2e}", out.iterations);
        assert!(err < 1e-13, "polished vs enumeration: {err:e}");
        // Unpolished solves the symmetrised problem: differs by about the asymmetry (2e-2/5).
        assert!(err_unpol < 1e-2, "unpolished vs enumeration: {err_unpol:e}");

        // Same problem in realistic BEM units (K ~ 1e-4 m/N, c ~ 1e-3 m): f scales by 10.
        let ks: Vec<f64> = k.iter().map(|v| v * 1e-4).collect();
        let cs: Vec<f64> = c.iter().map(|v| v * 1e-3).collect();
        let out_s = solve_frictionless(&ks, n, &cs, None, &QpSettings::default());
        assert!(out_s.polished);
        let f_ref_s: Vec<f64> = f_ref.iter().map(|v| v * 10.0).collect();
        let err_s = max_diff(&out_s.f, &f_ref_s) / (10.0 * fs);
        eprintln!("disp n=5 rescaled: rel err {err_s:.2e}");
        assert!(err_s < 1e-13, "rescaled: {err_s:e}");
    }

    #[test]
    fn small_load_driven_matches_enumeration() {
        // Expected values: brute-force enumeration of all 2^5 active sets with the load
        // equality appended (`enumerate` with Some((a, P))).
        let n = 5;
        let k = tridiag_k(n, 0.02);
        // Parabolic unloaded gap (rigid punch profile), all nonnegative: contact only through
        // the approach d.
        let c = [2.0, 0.5, 0.0, 0.5, 2.0];
        let a = [1.0; 5];
        for p in [0.3, 1.0, 4.0] {
            let sols = enumerate(&k, n, &c, Some((&a, p)));
            assert_eq!(sols.len(), 1);
            let (f_ref, d_ref) = (&sols[0].0, sols[0].1);
            let out = solve_frictionless(&k, n, &c, Some((&a, p)), &QpSettings::default());
            assert_eq!(out.status, QpStatus::Solved);
            assert!(out.polished);
            let d = out.approach.expect("approach");
            let err = max_diff(&out.f, f_ref) / max_abs(f_ref);
            let err_d = (d - d_ref).abs() / d_ref.abs();
            // IPM approach (from the equality multiplier) before polishing:
            let unpol =
                solve_frictionless(&k, n, &c, Some((&a, p)), &QpSettings { polish: false, ..QpSettings::default() });
            let d_ipm = unpol.approach.expect("approach");
            let err_unpol = max_diff(&unpol.f, f_ref) / max_abs(f_ref);
            eprintln!(
                "load P={p}: iters {}, d_enum {d_ref:.6}, rel err f {err:.2e}, d {err_d:.2e}; \
                 unpolished f {err_unpol:.2e}, d_ipm {d_ipm:.6}",
                out.iterations
            );
            assert!(err < 1e-13, "f: {err:e}");
            assert!(err_d < 1e-13, "d: {err_d:e}");
            // d > 0 (pressing harder), and the multiplier sign convention is right.
            assert!(d_ipm > 0.0 && (d_ipm - d_ref).abs() / d_ref < 1e-2);
            assert!(err_unpol < 1e-2);
            let total: f64 = out.f.iter().sum();
            assert!((total - p).abs() < 1e-13 * p);
        }
    }

    #[test]
    fn symmetric_k_unpolished_already_exact() {
        // Expected values: enumeration; with symmetric K the QP *is* the LCP, so the raw
        // interior-point solution must agree to about the IPM tolerance.
        let n = 5;
        let k = tridiag_k(n, 0.0);
        let c = [0.5, -1.0, -2.0, -0.5, 1.0];
        let f_ref = enumerate(&k, n, &c, None).remove(0).0;
        let out = solve_frictionless(&k, n, &c, None, &QpSettings::default());
        let err = max_diff(&out.f_unpolished, &f_ref) / max_abs(&f_ref);
        eprintln!("symmetric: unpolished rel err {err:.2e}");
        assert!(err < 1e-9, "{err:e}");
    }

    /// BEM-like problem: K_ij = h·exp(−|x_i − x_j|/l) (a positive-definite kernel) times
    /// (1 + eps·(x_i − x_j)) for a relative asymmetry ~eps; unloaded gap profile x²/(2R)
    /// (returned without any approach).
    fn bem_like(n: usize, eps: f64) -> (Vec<f64>, Vec<f64>) {
        let h = 2.0 / n as f64;
        let x: Vec<f64> = (0..n).map(|i| -1.0 + h * (i as f64 + 0.5)).collect();
        let mut k = vec![0.0; n * n];
        for j in 0..n {
            for i in 0..n {
                let r = (x[i] - x[j]).abs();
                k[i + j * n] = 1e-4 * h * (-r / 0.5).exp() * (1.0 + eps * (x[i] - x[j]));
            }
        }
        let profile: Vec<f64> = x.iter().map(|xi| xi * xi / 2.0 * 1e-2).collect();
        (k, profile)
    }

    #[test]
    fn polish_effect_is_about_the_asymmetry() {
        // Expected: the unpolished IPM solves the symmetrised problem, so it differs from the
        // nonsymmetric LCP solution by O(asymmetry); the polished one satisfies the
        // nonsymmetric LCP to round-off (checked directly: f ≥ 0, g ≥ 0, f⊥g). Then the
        // load-driven solve with P = Σf of the displacement-driven solve (approach d0) must
        // return the same forces and d = d0 (uniqueness of the P-matrix LCP solution).
        let n = 60;
        let d0 = 1e-3;
        for eps in [1e-3, 1e-2] {
            let (k, profile) = bem_like(n, eps);
            let asym = {
                let mut num = 0.0_f64;
                let mut den = 0.0_f64;
                for j in 0..n {
                    for i in 0..n {
                        num += (k[i + j * n] - k[j + i * n]).powi(2);
                        den += k[i + j * n].powi(2);
                    }
                }
                (num / den).sqrt()
            };
            let c: Vec<f64> = profile.iter().map(|v| v - d0).collect();
            let disp = solve_frictionless(&k, n, &c, None, &QpSettings::default());
            let p_total: f64 = disp.f.iter().sum();
            let a = vec![1.0; n];
            let load = solve_frictionless(&k, n, &profile, Some((&a, p_total)), &QpSettings::default());
            for (name, out, cc, ld) in [("disp", &disp, &c, None), ("load", &load, &profile, Some(a.as_slice()))] {
                assert!(out.status.is_solved(), "{}", out.status);
                assert!(out.polished, "polish rejected (eps {eps}, {name})");
                let d = out.approach.unwrap_or(0.0);
                let fs = max_abs(&out.f);
                let gs = max_abs(&c);
                let g = gap(&k, n, cc, ld, d, &out.f);
                let viol = lcp_violation(&out.f, &g, fs, gs);
                let g_un = gap(&k, n, cc, ld, d, &out.f_unpolished);
                let viol_un = lcp_violation(&out.f_unpolished, &g_un, fs, gs);
                let diff = max_diff(&out.f, &out.f_unpolished) / fs;
                let ncontact = out.f.iter().filter(|&&v| v > 0.0).count();
                eprintln!(
                    "n={n} eps={eps:.0e} (|K-K^T|/|K| = {asym:.2e}) {name}: iters {}, \
                     contact nodes {ncontact}, |f_pol - f_ipm|/|f| = {diff:.2e}, \
                     nonsym LCP violation polished {viol:.2e}, unpolished {viol_un:.2e}",
                    out.iterations
                );
                assert!(viol < 1e-12, "polished LCP violation {viol:e}");
                assert!(diff > 0.1 * asym && diff < 10.0 * asym, "diff {diff:e}");
            }
            let d = load.approach.expect("approach");
            let fdiff = max_diff(&load.f, &disp.f) / max_abs(&disp.f);
            eprintln!(
                "  load-driven with P = {p_total:.4e}: d = {d:.15e} (d0 = {d0:e}), |f_load - f_disp|/|f| = {fdiff:.2e}"
            );
            assert!((d - d0).abs() < 1e-12 * d0);
            assert!(fdiff < 1e-12);
            assert!((load.f.iter().sum::<f64>() - p_total).abs() < 1e-13 * p_total);
        }
    }

    #[test]
    fn polish_corrects_a_wrong_active_set() {
        // Expected: enumeration result; `polish` is started from a deliberately wrong active
        // set (one node too many and one missing) and must reach the true one.
        let n = 5;
        let k = tridiag_k(n, 0.02);
        let c = [0.5, -1.0, -2.0, -0.5, 1.0];
        let f_ref = enumerate(&k, n, &c, None).remove(0).0;
        let truth: Vec<bool> = f_ref.iter().map(|&v| v > 0.0).collect();
        let mut wrong = truth.clone();
        wrong[0] = !wrong[0];
        wrong[2] = !wrong[2];
        let scaled = Scaled { k: &k, n, c: &c, load: None, alpha: 0.5, gamma: 2.0, amax: 1.0 };
        let (f, _) = polish(&scaled, wrong, 1e-12).expect("polish converges");
        assert!(max_diff(&f, &f_ref) < 1e-14 * max_abs(&f_ref));
    }

    #[test]
    fn nan_and_bad_input_do_not_panic() {
        // Expected: documented error statuses (no panic).
        let n = 3;
        let mut k = tridiag_k(n, 0.0);
        let c = [-1.0, -1.0, -1.0];
        k[4] = f64::NAN;
        let out = solve_frictionless(&k, n, &c, None, &QpSettings::default());
        assert!(matches!(out.status, QpStatus::NumericalError(_)), "{}", out.status);
        assert_eq!(out.f.len(), n);

        let k = tridiag_k(n, 0.0);
        let c_nan = [-1.0, f64::NAN, -1.0];
        let out = solve_frictionless(&k, n, &c_nan, None, &QpSettings::default());
        assert!(matches!(out.status, QpStatus::NumericalError(_)));

        let a = [1.0; 3];
        let out = solve_frictionless(&k, n, &c, Some((&a, f64::NAN)), &QpSettings::default());
        assert!(matches!(out.status, QpStatus::NumericalError(_)));

        // Size mismatch.
        let out = solve_frictionless(&k[..8], n, &c, None, &QpSettings::default());
        assert!(matches!(out.status, QpStatus::NumericalError(_)));

        // Negative load with a ≥ 0: infeasible.
        let out = solve_frictionless(&k, n, &c, Some((&a, -1.0)), &QpSettings::default());
        assert_eq!(out.status, QpStatus::Infeasible);

        // Empty problem.
        let out = solve_frictionless(&[], 0, &[], Some((&[], 1.0)), &QpSettings::default());
        assert_eq!(out.status, QpStatus::Infeasible);
        let out = solve_frictionless(&[], 0, &[], None, &QpSettings::default());
        assert_eq!(out.status, QpStatus::Solved);
        assert!(out.f.is_empty());

        // Bad tolerance.
        let bad = QpSettings { tolerance: f64::NAN, ..QpSettings::default() };
        let out = solve_frictionless(&k, n, &c, None, &bad);
        assert!(matches!(out.status, QpStatus::NumericalError(_)));
        assert!(!out.status.to_string().is_empty());
    }

    #[test]
    fn no_contact_gives_zero_forces() {
        // Expected: c > 0 everywhere and no load => f = 0 exactly (trivial LCP solution).
        let n = 4;
        let k = tridiag_k(n, 0.01);
        let c = [1.0, 2.0, 0.5, 3.0];
        let out = solve_frictionless(&k, n, &c, None, &QpSettings::default());
        assert!(out.status.is_solved());
        assert!(out.polished);
        assert!(out.f.iter().all(|&v| v == 0.0));
    }

    #[test]
    fn settings_serde_defaults() {
        // Expected: the documented defaults.
        let s = QpSettings::default();
        assert_eq!((s.tolerance, s.max_iter, s.polish), (1e-12, 200, true));
    }

    #[test]
    #[ignore = "timing only: cargo test -- --ignored --nocapture"]
    fn timing_n200() {
        let n = 200;
        let (k, profile) = bem_like(n, 5e-3);
        let c: Vec<f64> = profile.iter().map(|v| v - 1e-3).collect();
        let a = vec![1.0; n];
        for (cc, load) in [(&c, None), (&profile, Some((a.as_slice(), 5e-3)))] {
            let t = std::time::Instant::now();
            let reps = 5;
            let mut out = None;
            for _ in 0..reps {
                out = Some(solve_frictionless(&k, n, cc, load, &QpSettings::default()));
            }
            let out = out.expect("ran");
            eprintln!(
                "n=200 load={}: {:.1} ms/solve, iters {}, status {}, polished {}",
                load.is_some(),
                t.elapsed().as_secs_f64() * 1e3 / reps as f64,
                out.iterations,
                out.status,
                out.polished
            );
        }
    }
}
