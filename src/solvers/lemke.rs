//! Lemke's complementary pivoting algorithm (seed §5; Cottle, Pang & Stone, *The Linear Complementarity Problem*,
//! §4.4; Murty 1988 ch. 2) for `w = M z + q`, with the covering vector e = (1, …, 1).
//!
//! Implementation notes:
//! - **Scaling.** Rows and columns are equilibrated (Ruiz) before pivoting: `M' = D_r M D_c`, `q' = D_r q`,
//!   `z = D_c z'`, `w = D_r⁻¹ w'`. Positive diagonal scalings preserve complementarity, and they bring the
//!   unknowns to order one whatever the units of the physical problem.
//! - **Revised form.** The inverse of the basis matrix is kept explicitly and updated by one eta (Gauss–Jordan)
//!   step per pivot, O(m²); it is recomputed from an LU factorisation every `refactor_every` pivots, and the final
//!   basic solution is obtained by a fresh LU solve with one step of iterative refinement, so the complementarity
//!   of the answer is exact (every nonbasic variable is zero) and its residual is at round-off level.
//! - **Anti-cycling.** Ties in the minimum-ratio test are broken by the lexicographic rule: among the tied rows
//!   choose the one whose row of `B⁻¹`, divided by the pivot column entry, is lexicographically smallest. Rows of
//!   `B⁻¹` are linearly independent, so no tie survives and no basis repeats: the algorithm is finite on
//!   degenerate problems. When z₀ is among the tied rows it leaves at once (termination).
//! - **Outcome.** `Solved` (z₀ left the basis), `RayTermination` (no blocking row: for a copositive-plus M, as
//!   every LCP rollbem builds, this proves the LCP infeasible), `NotConverged` (pivot limit).

use super::{Lcp, Status};
use faer::linalg::solvers::Solve;
use faer::Mat;

/// Settings of Lemke's algorithm.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct LemkeSettings {
    /// Maximum number of pivots, as a multiple of the problem size m (plus 100). Default 50.
    pub max_pivots_per_unknown: usize,
    /// Pivot-column entries ≤ `pivot_tolerance · ‖column‖∞` cannot block (default 1e-11).
    pub pivot_tolerance: f64,
    /// Ratios within `tie_tolerance` (relative) of the minimum count as tied (default 1e-9).
    pub tie_tolerance: f64,
    /// Recompute the basis inverse from scratch every this many pivots (default 100).
    pub refactor_every: usize,
}

impl Default for LemkeSettings {
    fn default() -> Self {
        LemkeSettings { max_pivots_per_unknown: 50, pivot_tolerance: 1e-11, tie_tolerance: 1e-9, refactor_every: 100 }
    }
}

/// Result of Lemke's algorithm.
#[derive(Debug, Clone)]
pub struct LemkeOutcome {
    /// z (unscaled); on ray termination the last basic point's z (not a solution).
    pub z: Vec<f64>,
    /// w = M z + q (unscaled), recomputed from z.
    pub w: Vec<f64>,
    /// Outcome.
    pub status: Status,
    /// Number of pivots, including the initial z₀ pivot.
    pub pivots: usize,
    /// Human-readable detail (which variable ended it, etc.).
    pub message: String,
}

/// z0 counts as zero below this fraction of its initial value (both engines).
pub(crate) const Z0_NEGLIGIBLE: f64 = 1e-13;

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Var {
    W(usize),
    Z(usize),
    Z0,
}

/// Ruiz equilibration (8 sweeps): returns (D_r, D_c) with max |D_r M D_c| ≈ 1 in every nonzero row and column.
/// Both Lemke engines pivot on `D_r M D_c`; with covering vector e this is Lemke on M with covering vector D_r⁻¹e.
pub fn equilibrate(m: &Mat<f64>) -> (Vec<f64>, Vec<f64>) {
    let n = m.nrows();
    let mut dr = vec![1.0; n];
    let mut dc = vec![1.0; n];
    for _ in 0..8 {
        let mut rmax = vec![0.0_f64; n];
        let mut cmax = vec![0.0_f64; n];
        for j in 0..n {
            for i in 0..n {
                let v = (dr[i] * m[(i, j)] * dc[j]).abs();
                rmax[i] = rmax[i].max(v);
                cmax[j] = cmax[j].max(v);
            }
        }
        for i in 0..n {
            if rmax[i] > 0.0 {
                dr[i] /= rmax[i].sqrt();
            }
            if cmax[i] > 0.0 {
                dc[i] /= cmax[i].sqrt();
            }
        }
    }
    (dr, dc)
}

struct Work<'a> {
    m: &'a Mat<f64>,
    n: usize,
    basis: Vec<Var>,
    /// Basis inverse, row-major: binv[r * n + c].
    binv: Vec<f64>,
    x: Vec<f64>,
    q: &'a [f64],
}

impl Work<'_> {
    fn column(&self, v: Var, out: &mut [f64]) {
        match v {
            Var::W(i) => {
                out.fill(0.0);
                out[i] = 1.0;
            }
            Var::Z(j) => {
                for (i, o) in out.iter_mut().enumerate() {
                    *o = -self.m[(i, j)];
                }
            }
            Var::Z0 => out.fill(-1.0),
        }
    }

    /// d = B⁻¹ a.
    fn ftran(&self, a: &[f64], d: &mut [f64]) {
        let n = self.n;
        for (r, dr) in d.iter_mut().enumerate() {
            let row = &self.binv[r * n..(r + 1) * n];
            *dr = row.iter().zip(a).map(|(b, a)| b * a).sum();
        }
    }

    fn pivot(&mut self, r: usize, d: &[f64], entering: Var) {
        let n = self.n;
        let piv = d[r];
        for c in 0..n {
            self.binv[r * n + c] /= piv;
        }
        self.x[r] /= piv;
        let (head, rest) = self.binv.split_at_mut(r * n);
        let (prow, tail) = rest.split_at_mut(n);
        for (i, row) in head.chunks_exact_mut(n).chain(tail.chunks_exact_mut(n)).enumerate() {
            let i = if i < r { i } else { i + 1 };
            let f = d[i];
            if f != 0.0 {
                for (b, p) in row.iter_mut().zip(prow.iter()) {
                    *b -= f * p;
                }
                self.x[i] -= f * self.x[r];
            }
        }
        self.basis[r] = entering;
    }

    fn basis_matrix(&self) -> Mat<f64> {
        let n = self.n;
        let mut b = Mat::<f64>::zeros(n, n);
        let mut col = vec![0.0; n];
        for (c, &v) in self.basis.iter().enumerate() {
            self.column(v, &mut col);
            for (r, &val) in col.iter().enumerate() {
                b[(r, c)] = val;
            }
        }
        b
    }

    /// Recompute B⁻¹ and x = B⁻¹ q from an LU factorisation. Returns false if B is numerically singular.
    fn refactor(&mut self) -> bool {
        let n = self.n;
        let lu = self.basis_matrix().partial_piv_lu();
        let inv = lu.solve(Mat::<f64>::identity(n, n));
        if !inv.col_iter().all(|c| c.iter().all(|v| v.is_finite())) {
            return false;
        }
        for r in 0..n {
            for c in 0..n {
                self.binv[r * n + c] = inv[(r, c)];
            }
        }
        let qv = Mat::from_fn(n, 1, |i, _| self.q[i]);
        let mut xs = lu.solve(&qv);
        // One step of iterative refinement.
        let b = self.basis_matrix();
        let res = Mat::from_fn(n, 1, |i, _| self.q[i] - (0..n).map(|k| b[(i, k)] * xs[(k, 0)]).sum::<f64>());
        let corr = lu.solve(&res);
        for i in 0..n {
            xs[(i, 0)] += corr[(i, 0)];
            self.x[i] = xs[(i, 0)];
        }
        true
    }
}

/// The scaled problem both engines pivot on, and the way back to the user's variables.
pub(crate) struct Scaled<'a> {
    pub(crate) lcp: &'a Lcp,
    pub(crate) m: Mat<f64>,
    pub(crate) q: Vec<f64>,
    pub(crate) dc: Vec<f64>,
    pub(crate) qscale: f64,
}

impl Scaled<'_> {
    /// Unscale z, recompute w = M z + q from the original data, and wrap up.
    pub(crate) fn finish(&self, z_s: Vec<f64>, status: Status, pivots: usize, message: String) -> LemkeOutcome {
        let z: Vec<f64> = z_s.iter().zip(&self.dc).map(|(z, d)| z * d).collect();
        let w = self.lcp.w_of(&z);
        LemkeOutcome { z, w, status, pivots, message }
    }
}

/// Validate and equilibrate; `Err` carries the outcome when there is nothing to pivot (bad data, or q ≥ 0).
pub(crate) fn prepare(lcp: &Lcp) -> Result<Scaled<'_>, LemkeOutcome> {
    let n = lcp.size();
    let fail = |msg: String| LemkeOutcome {
        z: vec![0.0; n],
        w: lcp.q.clone(),
        status: Status::NumericalError,
        pivots: 0,
        message: msg,
    };
    if lcp.m.nrows() != n || lcp.m.ncols() != n {
        return Err(fail(format!("M is {}×{} but q has {} entries", lcp.m.nrows(), lcp.m.ncols(), n)));
    }
    if !lcp.q.iter().all(|v| v.is_finite()) || !lcp.m.col_iter().all(|c| c.iter().all(|v| v.is_finite())) {
        return Err(fail("M or q has a non-finite entry (NaN or infinity)".into()));
    }
    let (dr, dc) = equilibrate(&lcp.m);
    let m = Mat::from_fn(n, n, |i, j| dr[i] * lcp.m[(i, j)] * dc[j]);
    let q: Vec<f64> = (0..n).map(|i| dr[i] * lcp.q[i]).collect();
    let qscale = q.iter().fold(0.0_f64, |a, v| a.max(v.abs()));
    let sc = Scaled { lcp, m, q, dc, qscale };
    if sc.q.iter().all(|&v| v >= 0.0) {
        return Err(sc.finish(vec![0.0; n], Status::Solved, 0, "q ≥ 0: z = 0 is the solution".into()));
    }
    Ok(sc)
}

/// Solve `w = M z + q ⊥ z ≥ 0` by Lemke's method: the block-revised engine ([`super::lemke_block`]), which works
/// on the k × k block of the basis that involves z-columns only.
pub fn solve(lcp: &Lcp, settings: &LemkeSettings) -> LemkeOutcome {
    match prepare(lcp) {
        Ok(sc) => super::lemke_block::run(&sc, settings),
        Err(out) => out,
    }
}

/// Reference engine: the whole m × m basis inverse kept explicitly and updated by an eta step per pivot, O(m²)
/// per pivot and O(m³) per refactorisation. Slower than [`solve`], kept as an independent implementation that the
/// tests compare against.
pub fn solve_dense(lcp: &Lcp, settings: &LemkeSettings) -> LemkeOutcome {
    let sc = match prepare(lcp) {
        Ok(sc) => sc,
        Err(out) => return out,
    };
    let n = lcp.size();
    let (ms, qs, qscale) = (&sc.m, &sc.q, sc.qscale);
    let fail = |msg: String, pivots| LemkeOutcome {
        z: vec![0.0; n],
        w: lcp.q.clone(),
        status: Status::NumericalError,
        pivots,
        message: msg,
    };
    let finish =
        |z_s: Vec<f64>, status: Status, pivots: usize, message: String| sc.finish(z_s, status, pivots, message);
    let mut wk = Work {
        m: ms,
        n,
        basis: (0..n).map(Var::W).collect(),
        binv: {
            let mut b = vec![0.0; n * n];
            for i in 0..n {
                b[i * n + i] = 1.0;
            }
            b
        },
        x: qs.clone(),
        q: qs,
    };
    // Initial pivot: z0 enters, the row of the most negative q leaves (ties: the lexicographic choice with
    // B = I is the largest index).
    let mut r0 = 0;
    for i in 0..n {
        if qs[i] <= qs[r0] {
            r0 = i;
        }
    }
    let mut col = vec![0.0; n];
    let mut d = vec![0.0; n];
    wk.column(Var::Z0, &mut col);
    wk.ftran(&col, &mut d);
    let mut leaving = wk.basis[r0];
    let z0_start = wk.x[r0] / d[r0];
    wk.pivot(r0, &d, Var::Z0);
    let mut pivots = 1;
    let max_pivots = settings.max_pivots_per_unknown.saturating_mul(n).saturating_add(100);
    let mut since_refactor = 0;
    loop {
        let entering = match leaving {
            Var::W(i) => Var::Z(i),
            Var::Z(i) => Var::W(i),
            Var::Z0 => unreachable!("z0 leaving ends the loop"),
        };
        wk.column(entering, &mut col);
        wk.ftran(&col, &mut d);
        let dmax = d.iter().fold(0.0_f64, |a, v| a.max(v.abs()));
        let tol = settings.pivot_tolerance * dmax.max(1e-300);
        // Minimum ratio over blocking rows.
        let mut theta = f64::INFINITY;
        for i in 0..n {
            if d[i] > tol {
                theta = theta.min(wk.x[i].max(0.0) / d[i]);
            }
        }
        let z0_row = wk.basis.iter().position(|&v| v == Var::Z0);
        let z0_value = z0_row.map(|r| wk.x[r]).unwrap_or(0.0);
        if !theta.is_finite() {
            if z0_value <= Z0_NEGLIGIBLE * z0_start {
                // z0 already zero to round-off: the current point is complementary (see the block engine).
                if !wk.refactor() {
                    return fail("the final basis is numerically singular".into(), pivots);
                }
                let z = extract_z(&wk);
                return finish(z, Status::Solved, pivots, format!("z0 reached zero after {pivots} pivots"));
            }
            let z = extract_z(&wk);
            return finish(
                z,
                Status::RayTermination,
                pivots,
                format!("secondary ray: entering {entering:?} is unblocked after {pivots} pivots"),
            );
        }
        let tie = settings.tie_tolerance * (theta.abs() + settings.tie_tolerance * qscale.max(1.0));
        let tied: Vec<usize> = (0..n).filter(|&i| d[i] > tol && wk.x[i].max(0.0) / d[i] <= theta + tie).collect();
        let z0_drops = z0_row.is_some_and(|r| d[r] > tol && z0_value - theta * d[r] <= Z0_NEGLIGIBLE * z0_start);
        let r = if let Some(&rz) = tied.iter().find(|&&i| wk.basis[i] == Var::Z0) {
            rz
        } else if z0_drops {
            z0_row.expect("z0 basic")
        } else {
            let mut best = tied[0];
            for &i in &tied[1..] {
                // Lexicographic comparison of B⁻¹ rows scaled by 1/d.
                for c in 0..n {
                    let a = wk.binv[i * n + c] / d[i];
                    let b = wk.binv[best * n + c] / d[best];
                    if (a - b).abs() > 1e-14 * (a.abs() + b.abs()) {
                        if a < b {
                            best = i;
                        }
                        break;
                    }
                }
            }
            best
        };
        leaving = wk.basis[r];
        wk.pivot(r, &d, entering);
        pivots += 1;
        since_refactor += 1;
        if leaving == Var::Z0 {
            if !wk.refactor() {
                return fail("the final basis is numerically singular".into(), pivots);
            }
            let z = extract_z(&wk);
            return finish(z, Status::Solved, pivots, format!("z0 left the basis after {pivots} pivots"));
        }
        if pivots >= max_pivots {
            let z = extract_z(&wk);
            return finish(z, Status::NotConverged, pivots, format!("pivot limit {max_pivots} reached"));
        }
        if since_refactor >= settings.refactor_every {
            since_refactor = 0;
            if !wk.refactor() {
                return fail(format!("the basis became numerically singular after {pivots} pivots"), pivots);
            }
        }
    }
}

fn extract_z(wk: &Work) -> Vec<f64> {
    let mut z = vec![0.0; wk.n];
    for (r, v) in wk.basis.iter().enumerate() {
        if let Var::Z(j) = *v {
            z[j] = wk.x[r].max(0.0);
        }
    }
    z
}

#[cfg(test)]
mod tests {
    use super::*;

    fn lcp(m: &[&[f64]], q: &[f64]) -> Lcp {
        let n = q.len();
        Lcp { m: Mat::from_fn(n, n, |i, j| m[i][j]), q: q.to_vec() }
    }

    #[test]
    fn solves_a_p_matrix_problem_known_by_hand() {
        // M = [[2,1],[1,2]], q = [-5,-6]: both positive, z = M⁻¹(−q) = (4/3, 7/3), w = 0 (solved by hand).
        let p = lcp(&[&[2.0, 1.0], &[1.0, 2.0]], &[-5.0, -6.0]);
        let out = solve(&p, &LemkeSettings::default());
        assert_eq!(out.status, Status::Solved);
        assert!((out.z[0] - 4.0 / 3.0).abs() < 1e-14 && (out.z[1] - 7.0 / 3.0).abs() < 1e-14);
    }

    #[test]
    fn detects_infeasibility_by_ray_termination() {
        // w1 = 0·z − 1 ≥ 0 is impossible whatever z (by inspection): Lemke must end on a secondary ray.
        let p = lcp(&[&[0.0, 0.0], &[0.0, 1.0]], &[-1.0, 1.0]);
        let out = solve(&p, &LemkeSettings::default());
        assert_eq!(out.status, Status::RayTermination);
    }

    #[test]
    fn degenerate_ties_terminate() {
        // Fully degenerate: every q equal, M with repeated columns (ties in every ratio test). The solution is
        // checked against the LCP conditions themselves.
        let p = lcp(&[&[1.0, 1.0, 1.0], &[1.0, 1.0, 1.0], &[1.0, 1.0, 2.0]], &[-1.0, -1.0, -1.0]);
        let out = solve(&p, &LemkeSettings::default());
        assert_eq!(out.status, Status::Solved, "{}", out.message);
        for i in 0..3 {
            assert!(out.w[i] >= -1e-14 && out.z[i] >= 0.0 && (out.w[i] * out.z[i]).abs() < 1e-14);
        }
    }
}
