//! Box-constrained QP by clarabel: the TANG sub-problem of NORM-TANG (a Tresca box |h| ≤ μf), and the NORM
//! sub-problem when given lower bounds only.
//!
//! ```text
//!   min ½ xᵀ K_s x + cᵀ x   subject to   lo ≤ x ≤ hi,   [aᵀ x = b]
//! ```
//!
//! with `K_s = (K + Kᵀ)/2`. Its KKT conditions are those of the box LCP with the symmetrised matrix: the gradient
//! `s = K_s x + c + ν a` vanishes where lo < x < hi, is ≥ 0 at lo and ≤ 0 at hi; ν is the equality's
//! multiplier. A collocation-BEM flexibility is slightly nonsymmetric, so the interior-point answer solves a
//! slightly different problem; an **active-set polish** then solves the equality system of the *nonsymmetric* K on
//! the detected free set and keeps it if every bound and sign condition holds (else the interior-point answer is
//! kept and `polished = false`). The harness reports the polish's effect.

use super::clarabel_qp::{clarabel_settings, map_status, QpSettings, QpStatus};
use crate::tolerances::{BOX_FREE_FRACTION, BOX_POLISH_ACCEPT};
use clarabel::algebra::CscMatrix;
use clarabel::solver::{
    DefaultSolver, IPSolver,
    SupportedConeT::{NonnegativeConeT, ZeroConeT},
};
use faer::linalg::solvers::Solve;
use faer::Mat;

/// Result of a box QP.
#[derive(Debug, Clone)]
#[non_exhaustive]
pub struct BoxOutcome {
    /// The minimiser (after polish when accepted).
    pub x: Vec<f64>,
    /// Multiplier ν of the equality (gradient `K x + c + ν a`), when one was given.
    pub nu: Option<f64>,
    /// Interior-point iterations.
    pub iterations: u32,
    /// Status.
    pub status: QpStatus,
    /// Whether the polish was accepted.
    pub polished: bool,
}

/// Solve the box QP. `k` column-major n×n. Never panics; bad data gives `NumericalError`.
pub fn solve_box(
    k: &[f64],
    n: usize,
    c: &[f64],
    lo: &[f64],
    hi: &[f64],
    eq: Option<(&[f64], f64)>,
    s: &QpSettings,
) -> BoxOutcome {
    let fail = |st: QpStatus| BoxOutcome { x: vec![0.0; n], nu: None, iterations: 0, status: st, polished: false };
    if let Err(out) = check_box_input(k, n, c, lo, hi, eq) {
        return out;
    }
    // Scaling: x = α x̂, objective / γ with γ = scale of the gradient.
    let kmax = k.iter().fold(0.0_f64, |m, v| m.max(v.abs())).max(f64::MIN_POSITIVE);
    let bmax = lo.iter().chain(hi).fold(0.0_f64, |m, v| m.max(v.abs()));
    let alpha = if bmax > 0.0 { bmax } else { 1.0 };
    let gamma = (kmax * alpha).max(c.iter().fold(0.0_f64, |m, v| m.max(v.abs()))).max(f64::MIN_POSITIVE);
    let mut colptr = vec![0];
    let (mut rowval, mut nzval) = (Vec::new(), Vec::new());
    for j in 0..n {
        for i in 0..=j {
            rowval.push(i);
            nzval.push(0.5 * (k[i + j * n] + k[j + i * n]) * alpha * alpha / gamma);
        }
        colptr.push(rowval.len());
    }
    let p = CscMatrix::new(n, n, colptr, rowval, nzval);
    let q: Vec<f64> = c.iter().map(|v| v * alpha / gamma).collect();
    // Rows: [a^T] (zero cone), then x ≤ hi (I x + s = hi), then −x ≤ −lo.
    let ne = usize::from(eq.is_some());
    let m = ne + 2 * n;
    let mut colptr = vec![0];
    let (mut rowval, mut nzval) = (Vec::new(), Vec::new());
    let amax = eq.map_or(1.0, |(a, _)| a.iter().fold(0.0_f64, |m, v| m.max(v.abs())).max(f64::MIN_POSITIVE));
    for j in 0..n {
        if let Some((a, _)) = eq {
            rowval.push(0);
            nzval.push(a[j] / amax);
        }
        rowval.push(ne + j);
        nzval.push(1.0);
        rowval.push(ne + n + j);
        nzval.push(-1.0);
        colptr.push(rowval.len());
    }
    let amat = CscMatrix::new(m, n, colptr, rowval, nzval);
    let mut b = vec![0.0; m];
    if let Some((_, rhs)) = eq {
        b[0] = rhs / (alpha * amax);
    }
    for i in 0..n {
        b[ne + i] = hi[i] / alpha;
        b[ne + n + i] = -lo[i] / alpha;
    }
    let mut cones = Vec::new();
    if ne == 1 {
        cones.push(ZeroConeT(1));
    }
    cones.push(NonnegativeConeT(2 * n));
    let settings = match clarabel_settings(s) {
        Ok(st) => st,
        Err(e) => return fail(QpStatus::NumericalError(e)),
    };
    let run = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
        let mut solver = DefaultSolver::new(&p, &q, &amat, &b, &cones, settings).map_err(|e| format!("{e}"))?;
        solver.solve();
        let sol = &solver.solution;
        Ok::<_, String>((sol.x.clone(), sol.z.clone(), sol.status, sol.iterations))
    }));
    let (x, z, st, iterations) = match run {
        Ok(Ok(r)) => r,
        Ok(Err(m)) => return fail(QpStatus::NumericalError(format!("clarabel setup: {m}"))),
        Err(_) => return fail(QpStatus::NumericalError("clarabel panicked".into())),
    };
    let status = map_status(st);
    let xs: Vec<f64> = (0..n).map(|i| (alpha * x[i]).clamp(lo[i], hi[i])).collect();
    // KKT: K x + c + Aᵀ z = 0 with A's equality row a/amax: ν = z_eq · γ / (α amax) in the unscaled gradient.
    let nu = eq.map(|_| z[0] * gamma / (alpha * amax));
    let mut out = BoxOutcome { x: xs, nu, iterations, status, polished: false };
    if s.polish && out.status.is_solved() {
        polish_rounds(k, n, c, lo, hi, eq, &mut out);
    }
    out
}

/// Check the inputs of [`solve_box`]; `Err` carries the outcome to return (bad data, a provably infeasible box or
/// equality, or the trivial `n = 0` solution).
fn check_box_input(
    k: &[f64],
    n: usize,
    c: &[f64],
    lo: &[f64],
    hi: &[f64],
    eq: Option<(&[f64], f64)>,
) -> Result<(), BoxOutcome> {
    let fail = |st: QpStatus| Err(BoxOutcome { x: vec![0.0; n], nu: None, iterations: 0, status: st, polished: false });
    if k.len() != n * n || c.len() != n || lo.len() != n || hi.len() != n || eq.is_some_and(|(a, _)| a.len() != n) {
        return fail(QpStatus::NumericalError("inconsistent sizes".into()));
    }
    let finite = k.iter().chain(c).chain(lo).chain(hi).all(|v| v.is_finite())
        && eq.is_none_or(|(a, b)| b.is_finite() && a.iter().all(|v| v.is_finite()));
    if !finite {
        return fail(QpStatus::NumericalError("non-finite entry in the box QP".into()));
    }
    if (0..n).any(|i| lo[i] > hi[i]) {
        return fail(QpStatus::Infeasible);
    }
    if let Some((a, b)) = eq {
        let (mut mn, mut mx) = (0.0, 0.0);
        for i in 0..n {
            mn += (a[i] * lo[i]).min(a[i] * hi[i]);
            mx += (a[i] * lo[i]).max(a[i] * hi[i]);
        }
        if b < mn || b > mx {
            return fail(QpStatus::Infeasible);
        }
    }
    if n == 0 {
        return Err(BoxOutcome {
            x: vec![],
            nu: eq.map(|_| 0.0),
            iterations: 0,
            status: QpStatus::Solved,
            polished: false,
        });
    }
    Ok(())
}

/// The active-set polish of a box-QP answer with the nonsymmetric K: the free set of the symmetrised problem can
/// differ from the nonsymmetric one's near the transition, so it is corrected for a few rounds (pin overshooting
/// free nodes, release bound nodes pushed the wrong way) until a polished answer is accepted.
fn polish_rounds(
    k: &[f64],
    n: usize,
    c: &[f64],
    lo: &[f64],
    hi: &[f64],
    eq: Option<(&[f64], f64)>,
    out: &mut BoxOutcome,
) {
    let width = |i: usize| (hi[i] - lo[i]).max(f64::MIN_POSITIVE);
    let free: Vec<bool> = (0..n)
        .map(|i| out.x[i] - lo[i] > BOX_FREE_FRACTION * width(i) && hi[i] - out.x[i] > BOX_FREE_FRACTION * width(i))
        .collect();
    // The free set of the symmetrised problem can differ from the nonsymmetric one's near the transition:
    // correct it for a few rounds (pin overshooting free nodes, release bound nodes pushed the wrong way).
    let mut free = free;
    let mut x0 = out.x.clone();
    for _ in 0..20 {
        match polish(k, n, c, lo, hi, eq, &x0, &free) {
            Ok((xp, nup)) => {
                out.x = xp;
                out.nu = nup;
                out.polished = true;
                break;
            }
            Err(Some((pin, release))) => {
                for (i, bound) in pin {
                    free[i] = false;
                    x0[i] = bound;
                }
                for i in release {
                    free[i] = true;
                }
            }
            Err(None) => break,
        }
    }
}

/// Solve the nonsymmetric equality system on the free set and accept it if it is a box-LCP solution.
#[allow(clippy::too_many_arguments)]
fn polish(
    k: &[f64],
    n: usize,
    c: &[f64],
    lo: &[f64],
    hi: &[f64],
    eq: Option<(&[f64], f64)>,
    x0: &[f64],
    free: &[bool],
) -> Result<(Vec<f64>, Option<f64>), Option<Fix>> {
    let idx: Vec<usize> = (0..n).filter(|&i| free[i]).collect();
    // Bound variables stay where the interior point put them (snapped to the nearer bound).
    let mut x: Vec<f64> = (0..n)
        .map(|i| {
            if free[i] {
                0.0
            } else if x0[i] - lo[i] < hi[i] - x0[i] {
                lo[i]
            } else {
                hi[i]
            }
        })
        .collect();
    let nf = idx.len();
    let ne = usize::from(eq.is_some());
    let dim = nf + ne;
    let mut nu = None;
    if dim > 0 {
        let mut a = Mat::<f64>::zeros(dim, dim);
        let mut r = Mat::<f64>::zeros(dim, 1);
        for (ri, &i) in idx.iter().enumerate() {
            for (cj, &j) in idx.iter().enumerate() {
                a[(ri, cj)] = k[i + j * n];
            }
            r[(ri, 0)] = -c[i] - (0..n).filter(|&j| !free[j]).map(|j| k[i + j * n] * x[j]).sum::<f64>();
            if let Some((av, _)) = eq {
                a[(ri, nf)] = av[i];
            }
        }
        if let Some((av, b)) = eq {
            for (cj, &j) in idx.iter().enumerate() {
                a[(nf, cj)] = av[j];
            }
            r[(nf, 0)] = b - (0..n).filter(|&j| !free[j]).map(|j| av[j] * x[j]).sum::<f64>();
        }
        let sol = a.partial_piv_lu().solve(&r);
        if !(0..dim).all(|i| sol[(i, 0)].is_finite()) {
            return Err(None);
        }
        for (ri, &i) in idx.iter().enumerate() {
            x[i] = sol[(ri, 0)];
        }
        if ne == 1 {
            nu = Some(sol[(nf, 0)]);
        }
    }
    // Accept only a box-LCP solution of the nonsymmetric problem.
    let scale = lo.iter().chain(hi).fold(0.0_f64, |m, v| m.max(v.abs())).max(f64::MIN_POSITIVE);
    let kmax = k.iter().fold(0.0_f64, |m, v| m.max(v.abs()));
    let gscale = (kmax * scale).max(c.iter().fold(0.0_f64, |m, v| m.max(v.abs()))).max(f64::MIN_POSITIVE);
    let tol = BOX_POLISH_ACCEPT;
    let (mut pin, mut release) = (Vec::new(), Vec::new());
    for i in 0..n {
        if free[i] {
            if x[i] < lo[i] - tol * scale {
                pin.push((i, lo[i]));
            } else if x[i] > hi[i] + tol * scale {
                pin.push((i, hi[i]));
            }
            continue;
        }
        let g: f64 =
            c[i] + (0..n).map(|j| k[i + j * n] * x[j]).sum::<f64>() + nu.unwrap_or(0.0) * eq.map_or(0.0, |(a, _)| a[i]);
        let at_lo = x[i] == lo[i] && lo[i] < hi[i];
        let at_hi = x[i] == hi[i] && lo[i] < hi[i];
        if (at_lo && g < -tol * gscale) || (at_hi && g > tol * gscale) {
            release.push(i);
        }
    }
    if pin.is_empty() && release.is_empty() {
        Ok((x, nu))
    } else {
        Err(Some((pin, release)))
    }
}

/// Active-set corrections: free variables to pin at a bound, bound variables to release.
type Fix = (Vec<(usize, f64)>, Vec<usize>);

#[cfg(test)]
mod tests {
    use super::*;

    /// Reference by brute force: every assignment of {lo, free, hi} for n ≤ 5, keeping the one whose free
    /// system's solution satisfies the box-LCP conditions (solved with the same nonsymmetric K).
    fn enumerate(k: &[f64], n: usize, c: &[f64], lo: &[f64], hi: &[f64]) -> Vec<f64> {
        for code in 0..3usize.pow(n as u32) {
            let st: Vec<usize> = (0..n).map(|i| (code / 3usize.pow(i as u32)) % 3).collect();
            let free: Vec<bool> = st.iter().map(|&s| s == 1).collect();
            let x0: Vec<f64> = (0..n).map(|i| if st[i] == 0 { lo[i] } else { hi[i] }).collect();
            if let Ok((x, _)) = polish(k, n, c, lo, hi, None, &x0, &free) {
                return x;
            }
        }
        panic!("no solution");
    }

    #[test]
    fn matches_enumeration_on_a_small_nonsymmetric_box_problem() {
        let n = 5;
        let k: Vec<f64> = (0..n * n)
            .map(|idx| {
                let (i, j): (usize, usize) = (idx % n, idx / n);
                if i == j {
                    4.0
                } else if i.abs_diff(j) == 1 {
                    -1.0 + 0.01 * (i as f64 - j as f64)
                } else {
                    0.0
                }
            })
            .collect();
        let c = [-3.0, 2.0, -0.5, 4.0, -6.0];
        let lo = [-0.5, -0.2, -1.0, -0.1, 0.0];
        let hi = [0.5, 0.2, 1.0, 0.1, 1.0];
        let out = solve_box(&k, n, &c, &lo, &hi, None, &QpSettings::default());
        assert!(out.status.is_solved() && out.polished);
        let reference = enumerate(&k, n, &c, &lo, &hi);
        for i in 0..n {
            assert!((out.x[i] - reference[i]).abs() < 1e-12, "{i}: {} vs {}", out.x[i], reference[i]);
        }
    }

    #[test]
    fn infeasible_equality_and_nan_are_statuses() {
        let k = [1.0];
        let out = solve_box(&k, 1, &[0.0], &[-1.0], &[1.0], Some((&[1.0], 3.0)), &QpSettings::default());
        assert!(matches!(out.status, QpStatus::Infeasible));
        let out = solve_box(&k, 1, &[f64::NAN], &[-1.0], &[1.0], None, &QpSettings::default());
        assert!(matches!(out.status, QpStatus::NumericalError(_)));
    }
}
