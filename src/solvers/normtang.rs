//! NORM-TANG: Kalker's split of the frictional contact problem (Kalker 1990 ch. 2; González & Abascal 2000, the
//! seed's ref. [3]) into a normal problem with the shear fixed (NORM) and a tangential problem with the pressure
//! fixed (TANG, a Tresca box |h| ≤ μf), alternated until the change of the tractions falls under a tolerance.
//!
//! - **NORM** (h fixed): `g = g₀ + R_N ρ + K_NN f + K_NT h ≥ 0 ⊥ f ≥ 0`; with the normal load prescribed the
//!   approach d_N is an unknown tied by Σf = P.
//! - **TANG** (f fixed): slip `s = R_T ρ + K_TN f + K_TT h`, `−μf ≤ h ≤ μf`, with s = 0 where |h| < μf, s ≤ 0 at
//!   h = μf, s ≥ 0 at h = −μf (friction opposes slip); with the tangential load prescribed the shift d_T is an
//!   unknown tied by Σh = Q, and |Q| ≥ μP is gross sliding (`infeasible`).
//!
//! Two inner solvers: **projected Gauss–Seidel** sweeps `x_i ← clamp(x_i − ω r_i / K_ii, lo_i, hi_i)` (ω the
//! relaxation; convergent for symmetric positive definite K, which a collocation flexibility is only nearly), and
//! **clarabel** on the sub-problems as QPs with the symmetric part of K followed by an active-set polish with the
//! nonsymmetric K ([`super::clarabel_qp`], [`super::clarabel_box`]). With PGS a prescribed load is met by a
//! safeguarded root-find on the rigid displacement (the resultant is monotone in it: Illinois regula falsi);
//! clarabel carries the load as an equality constraint whose multiplier is the rigid displacement.
//!
//! The split converges when the coupling is weak (β small, or `coupling = false`, where one NORM and one TANG
//! solve are exact); with strong coupling (ν → 0, high μ) it may not, and says so (`not_converged` with the
//! achieved change). A moment load is not supported by the split (use Lemke's loading formulation).

use super::clarabel_box::solve_box;
use super::clarabel_qp::{solve_frictionless, QpSettings};
use super::Status;
use crate::formulation::{Split, MODE_APPROACH, MODE_ROTATION, MODE_SHIFT};
use crate::scene::Dof;
use serde::{Deserialize, Serialize};

/// Settings of NORM-TANG with projected Gauss–Seidel inner sweeps (`[solvers.pgs]`).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct PgsSettings {
    /// Relative tolerance on the change of (f, h) between outer iterations (inner sweeps and load root-finds are
    /// driven to a tenth of it). Default 1e-10.
    pub tolerance: f64,
    /// Maximum Gauss–Seidel sweeps per inner solve. Default 100 000.
    pub max_sweeps: usize,
    /// Maximum NORM-TANG outer iterations. Default 200.
    pub max_outer: usize,
    /// Over-relaxation ω in (0, 2). Default 1.
    pub relaxation: f64,
}

impl Default for PgsSettings {
    fn default() -> Self {
        PgsSettings { tolerance: 1e-10, max_sweeps: 100_000, max_outer: 200, relaxation: 1.0 }
    }
}

/// Settings of NORM-TANG with clarabel QPs as inner solver (`[solvers.normtang_qp]`).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct NormTangQpSettings {
    /// Relative tolerance on the change of (f, h) between outer iterations. Default 1e-10.
    pub tolerance: f64,
    /// Maximum outer iterations. Default 200.
    pub max_outer: usize,
    /// The QP solver's settings.
    pub qp: QpSettings,
}

impl Default for NormTangQpSettings {
    fn default() -> Self {
        NormTangQpSettings { tolerance: 1e-10, max_outer: 200, qp: QpSettings::default() }
    }
}

/// The inner solver.
#[derive(Debug, Clone)]
pub enum Inner {
    /// Projected Gauss–Seidel.
    Pgs(PgsSettings),
    /// clarabel QPs.
    Qp(NormTangQpSettings),
}

/// Result of NORM-TANG.
#[derive(Debug, Clone)]
pub struct Outcome {
    /// Normal nodal forces (dimensionless).
    pub f: Vec<f64>,
    /// Tangential nodal forces (None for a frictionless scene).
    pub h: Option<Vec<f64>>,
    /// Rigid motion (shift, approach, rotation).
    pub rigid: [f64; 3],
    /// Outcome.
    pub status: Status,
    /// Detail.
    pub message: String,
    /// Total Gauss–Seidel sweeps (PGS inner).
    pub sweeps: usize,
    /// Outer NORM-TANG iterations.
    pub outer: usize,
    /// Total interior-point iterations (QP inner).
    pub qp_iterations: u32,
}

/// Why an inner solve failed.
struct Failure(Status, String);

/// Projected Gauss–Seidel on `r = q + K x`, `lo ≤ x ≤ hi` (box LCP). `k` row-major. Returns sweeps used and
/// whether the largest update fell under `tol · max|x|`.
#[allow(clippy::too_many_arguments)]
pub fn pgs_box(
    k: &[f64],
    n: usize,
    q: &[f64],
    lo: &[f64],
    hi: &[f64],
    x: &mut [f64],
    omega: f64,
    tol: f64,
    max_sweeps: usize,
) -> (usize, bool) {
    for i in 0..n {
        x[i] = x[i].clamp(lo[i], hi[i]);
    }
    for sweep in 1..=max_sweeps {
        let mut change = 0.0_f64;
        let mut scale = 0.0_f64;
        for i in 0..n {
            let row = &k[i * n..(i + 1) * n];
            let r = q[i] + row.iter().zip(x.iter()).map(|(a, b)| a * b).sum::<f64>();
            let new = (x[i] - omega * r / row[i]).clamp(lo[i], hi[i]);
            change = change.max((new - x[i]).abs());
            x[i] = new;
            scale = scale.max(new.abs());
        }
        if change <= tol * scale || scale == 0.0 && change == 0.0 {
            return (sweep, true);
        }
    }
    (max_sweeps, false)
}

/// Gauss–Seidel needs a positive diagonal; a collocation flexibility on a very coarse or distorted mesh can lack
/// one (it is only nearly symmetric positive definite).
fn check_diagonal(k: &[f64], n: usize, which: &str) -> Result<(), Failure> {
    match (0..n).find(|&i| k[i * n + i].is_nan() || k[i * n + i] <= 0.0) {
        Some(i) => Err(Failure(
            Status::NumericalError,
            format!(
                "the {which} flexibility has a non-positive diagonal entry at contact node {i} ({:e}): it is not \
                 positive definite, so projected Gauss–Seidel cannot run (refine the mesh, or use lemke)",
                k[i * n + i]
            ),
        )),
        None => Ok(()),
    }
}

/// Find d with S(d) = target for a monotone S (increasing when `increasing`), starting at `d0` with a first
/// step `step`: bracket by doubling, then Illinois regula falsi. `eval` returns S(d) or a failure.
fn root<F: FnMut(f64) -> Result<f64, Failure>>(
    mut eval: F,
    target: f64,
    d0: f64,
    step: f64,
    increasing: bool,
    tol: f64,
) -> Result<f64, Failure> {
    let sgn = if increasing { 1.0 } else { -1.0 };
    let g = |s: f64| sgn * (s - target);
    let mut eval = move |d: f64| -> Result<f64, Failure> {
        let v = eval(d)?;
        if v.is_finite() {
            Ok(v)
        } else {
            Err(Failure(Status::NumericalError, format!("the resultant is not finite at rigid displacement {d:e}")))
        }
    };
    let (mut a, mut ga) = (d0, g(eval(d0)?));
    if ga.abs() <= tol {
        return Ok(a);
    }
    let dir = if ga < 0.0 { 1.0 } else { -1.0 };
    let mut h = step.abs().max(f64::MIN_POSITIVE);
    let (mut b, mut gb);
    let mut tries = 0;
    loop {
        b = a + dir * h;
        gb = g(eval(b)?);
        if gb.abs() <= tol {
            return Ok(b);
        }
        if gb.signum() != ga.signum() {
            break;
        }
        a = b;
        ga = gb;
        h *= 2.0;
        tries += 1;
        if tries > 200 {
            return Err(Failure(Status::NotConverged, "could not bracket the prescribed load".into()));
        }
    }
    let mut side = 0;
    for _ in 0..200 {
        let c = (a * gb - b * ga) / (gb - ga);
        let gc = g(eval(c)?);
        if gc.abs() <= tol || (b - a).abs() <= 1e-15 * (a.abs() + b.abs()) {
            return Ok(c);
        }
        if gc.signum() == gb.signum() {
            b = c;
            gb = gc;
            if side == -1 {
                ga *= 0.5;
            }
            side = -1;
        } else {
            a = c;
            ga = gc;
            if side == 1 {
                gb *= 0.5;
            }
            side = 1;
        }
    }
    Err(Failure(Status::NotConverged, "the load root-find did not converge".into()))
}

/// Solve the split problem.
pub fn solve(p: &Split, inner: &Inner) -> Outcome {
    let n = p.n;
    let mut f = vec![0.0; n];
    let mut h = vec![0.0; n];
    let mut rigid = p.rigid_given;
    let mut sweeps = 0usize;
    let mut qp_iterations = 0u32;
    let (tolerance, max_outer) = match inner {
        Inner::Pgs(s) => (s.tolerance, s.max_outer),
        Inner::Qp(s) => (s.tolerance, s.max_outer),
    };
    let frictional = p.mu > 0.0;
    let mut outer = 0;
    let mut change = f64::INFINITY;
    let result = loop {
        outer += 1;
        let (f_prev, h_prev) = (f.clone(), h.clone());
        if let Err(Failure(st, msg)) = norm(p, inner, &h, &mut f, &mut rigid, &mut sweeps, &mut qp_iterations) {
            break Err(Failure(st, format!("NORM, outer iteration {outer}: {msg}")));
        }
        if frictional {
            if let Err(Failure(st, msg)) = tang(p, inner, &f, &mut h, &mut rigid, &mut sweeps, &mut qp_iterations) {
                break Err(Failure(st, format!("TANG, outer iteration {outer}: {msg}")));
            }
        }
        let scale = f.iter().fold(0.0_f64, |m, v| m.max(v.abs())).max(f64::MIN_POSITIVE);
        change =
            f.iter().zip(&f_prev).chain(h.iter().zip(&h_prev)).fold(0.0_f64, |m, (a, b)| m.max((a - b).abs())) / scale;
        if !frictional || change <= tolerance || f.iter().all(|&v| v == 0.0) {
            break Ok(());
        }
        if outer >= max_outer {
            break Err(Failure(
                Status::NotConverged,
                format!(
                    "NORM-TANG did not converge in {max_outer} outer iterations: last change {change:.3e} > {tolerance:.0e} \
                     (strong normal–tangential coupling?)"
                ),
            ));
        }
    };
    let (status, message) = match result {
        Ok(()) => (
            Status::Solved,
            format!(
                "converged in {outer} outer iteration(s), last change {:.3e}",
                if change.is_finite() { change } else { 0.0 }
            ),
        ),
        Err(Failure(st, msg)) => (st, msg),
    };
    Outcome { f, h: frictional.then_some(h), rigid, status, message, sweeps, outer, qp_iterations }
}

fn norm(
    p: &Split,
    inner: &Inner,
    h: &[f64],
    f: &mut Vec<f64>,
    rigid: &mut [f64; 3],
    sweeps: &mut usize,
    qp_iterations: &mut u32,
) -> Result<(), Failure> {
    let n = p.n;
    // q without the approach term.
    let q0: Vec<f64> = (0..n)
        .map(|i| {
            p.g0[i]
                + p.rn[i][MODE_SHIFT] * rigid[MODE_SHIFT]
                + p.rn[i][MODE_ROTATION] * rigid[MODE_ROTATION]
                + if p.coupling { (0..n).map(|j| p.knt_rows[i * n + j] * h[j]).sum::<f64>() } else { 0.0 }
        })
        .collect();
    let c: Vec<f64> = (0..n).map(|i| p.rn[i][MODE_APPROACH]).collect();
    let lo = vec![0.0; n];
    let hi = vec![f64::INFINITY; n];
    match inner {
        Inner::Pgs(s) => {
            check_diagonal(&p.knn_rows, n, "normal")?;
            let mut solve_at = |d: f64, f: &mut Vec<f64>| -> Result<f64, Failure> {
                let q: Vec<f64> = (0..n).map(|i| q0[i] + c[i] * d).collect();
                let (sw, ok) = pgs_box(&p.knn_rows, n, &q, &lo, &hi, f, s.relaxation, 0.1 * s.tolerance, s.max_sweeps);
                *sweeps += sw;
                if !ok {
                    return Err(Failure(
                        Status::NotConverged,
                        format!("projected Gauss–Seidel did not converge in {} sweeps", s.max_sweeps),
                    ));
                }
                Ok(f.iter().sum())
            };
            match p.normal {
                Dof::Displacement(_) => {
                    solve_at(rigid[MODE_APPROACH], f)?;
                }
                Dof::Load(pl) => {
                    let kmax = (0..n).map(|i| p.knn_rows[i * n + i]).fold(0.0_f64, f64::max);
                    // First touch: the smallest approach that closes a gap.
                    let first = (0..n).map(|i| q0[i] / -c[i]).fold(f64::INFINITY, f64::min);
                    let d0 = if f.iter().any(|&v| v > 0.0) { rigid[MODE_APPROACH] } else { first };
                    let d = root(|d| solve_at(d, f), pl, d0, pl * kmax, true, 0.1 * s.tolerance * pl)?;
                    solve_at(d, f)?;
                    rigid[MODE_APPROACH] = d;
                }
            }
        }
        Inner::Qp(s) => {
            let q: Vec<f64> = match p.normal {
                Dof::Displacement(_) => (0..n).map(|i| q0[i] + c[i] * rigid[MODE_APPROACH]).collect(),
                Dof::Load(_) => q0.clone(),
            };
            let ones = vec![1.0; n];
            let load = match p.normal {
                Dof::Load(pl) => Some((ones.as_slice(), pl)),
                Dof::Displacement(_) => None,
            };
            let out = solve_frictionless(&p.knn_cols, n, &q, load, &s.qp);
            *qp_iterations += out.iterations;
            if !out.status.is_solved() {
                return Err(Failure(Status::NumericalError, format!("clarabel: {}", out.status)));
            }
            *f = out.f;
            if let Some(d) = out.approach {
                rigid[MODE_APPROACH] = d;
            }
        }
    }
    Ok(())
}

fn tang(
    p: &Split,
    inner: &Inner,
    f: &[f64],
    h: &mut [f64],
    rigid: &mut [f64; 3],
    sweeps: &mut usize,
    qp_iterations: &mut u32,
) -> Result<(), Failure> {
    let n = p.n;
    let mu = p.mu;
    let q0: Vec<f64> = (0..n)
        .map(|i| {
            p.rt[i][MODE_APPROACH] * rigid[MODE_APPROACH]
                + p.rt[i][MODE_ROTATION] * rigid[MODE_ROTATION]
                + if p.coupling { (0..n).map(|j| p.ktn_rows[i * n + j] * f[j]).sum::<f64>() } else { 0.0 }
        })
        .collect();
    let c: Vec<f64> = (0..n).map(|i| p.rt[i][MODE_SHIFT]).collect();
    let lo: Vec<f64> = f.iter().map(|&v| -mu * v.max(0.0)).collect();
    let hi: Vec<f64> = f.iter().map(|&v| mu * v.max(0.0)).collect();
    let psum: f64 = f.iter().sum();
    if let Dof::Load(ql) = p.tangential {
        if ql.abs() >= mu * psum {
            return Err(Failure(
                Status::Infeasible,
                format!(
                    "gross sliding: the tangential load |Q| exceeds the friction limit μP (|Q|/(μP) = {:.6})",
                    ql.abs() / (mu * psum)
                ),
            ));
        }
    }
    // Nodes out of contact carry no shear: drop them from the sub-problem.
    let act: Vec<usize> = (0..n).filter(|&i| hi[i] > 0.0).collect();
    let na = act.len();
    for i in 0..n {
        if hi[i] == 0.0 {
            h[i] = 0.0;
        }
    }
    let sub = |m: &[f64]| -> Vec<f64> {
        let mut out = Vec::with_capacity(na * na);
        for &i in &act {
            for &j in &act {
                out.push(m[i * n + j]);
            }
        }
        out
    };
    let ktt_rows = sub(&p.ktt_rows);
    let pick = |v: &[f64]| act.iter().map(|&i| v[i]).collect::<Vec<f64>>();
    let (lo_a, hi_a, q0_a, c_a) = (pick(&lo), pick(&hi), pick(&q0), pick(&c));
    let mut x = pick(h);
    match inner {
        Inner::Pgs(s) => {
            check_diagonal(&ktt_rows, na, "tangential")?;
            let mut solve_at = |d: f64, x: &mut Vec<f64>| -> Result<f64, Failure> {
                let q: Vec<f64> = (0..na).map(|i| q0_a[i] + c_a[i] * d).collect();
                let (sw, ok) =
                    pgs_box(&ktt_rows, na, &q, &lo_a, &hi_a, x, s.relaxation, 0.1 * s.tolerance, s.max_sweeps);
                *sweeps += sw;
                if !ok {
                    return Err(Failure(
                        Status::NotConverged,
                        format!("projected Gauss–Seidel did not converge in {} sweeps", s.max_sweeps),
                    ));
                }
                Ok(x.iter().sum())
            };
            match p.tangential {
                Dof::Displacement(_) => {
                    solve_at(rigid[MODE_SHIFT], &mut x)?;
                }
                Dof::Load(ql) => {
                    let kmax = (0..na).map(|i| ktt_rows[i * na + i]).fold(0.0_f64, f64::max);
                    let step = (mu * psum * kmax).max(f64::MIN_POSITIVE);
                    let tol = 0.1 * s.tolerance * mu * psum;
                    let d = root(|d| solve_at(d, &mut x), ql, rigid[MODE_SHIFT], step, false, tol)?;
                    solve_at(d, &mut x)?;
                    rigid[MODE_SHIFT] = d;
                }
            }
        }
        Inner::Qp(s) => {
            let q: Vec<f64> = match p.tangential {
                Dof::Displacement(_) => (0..na).map(|i| q0_a[i] + c_a[i] * rigid[MODE_SHIFT]).collect(),
                Dof::Load(_) => q0_a.clone(),
            };
            let mut cols = vec![0.0; na * na];
            for i in 0..na {
                for j in 0..na {
                    cols[i + j * na] = ktt_rows[i * na + j];
                }
            }
            let ones = vec![1.0; na];
            let eq = match p.tangential {
                Dof::Load(ql) => Some((ones.as_slice(), ql)),
                Dof::Displacement(_) => None,
            };
            let out = solve_box(&cols, na, &q, &lo_a, &hi_a, eq, &s.qp);
            *qp_iterations += out.iterations;
            if !out.status.is_solved() {
                return Err(Failure(Status::NumericalError, format!("clarabel (TANG): {}", out.status)));
            }
            x = out.x;
            if let Some(nu) = out.nu {
                // Gradient K h + q + ν·1 with the shift column ≈ 1: ν is the shift.
                rigid[MODE_SHIFT] = nu;
            }
        }
    }
    for (a, &i) in act.iter().enumerate() {
        h[i] = x[a];
    }
    Ok(())
}
