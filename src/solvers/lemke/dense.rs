//! The dense reference engine of Lemke's method: the whole m × m basis inverse kept explicitly, in product form.
//!
//! `B⁻¹ = E_t ⋯ E_1 B₀⁻¹`: B₀⁻¹ is an explicit m × m matrix (the identity, not stored, until the first update) and
//! each pivot appends its pivot column to an eta file, so a pivot column costs one product B₀⁻¹ a (one read of
//! B₀⁻¹, m²; a column of B₀⁻¹ for a w entering) plus t eta steps. Every `refactor_every` pivots the eta file is
//! absorbed into B₀⁻¹ by one rank-s product (E_t ⋯ E_1 = I + U S, S the distinct pivot rows): 2 s m² flops at
//! matrix-product speed instead of the t read-write passes of explicit eta updates. The inverse is recomputed
//! from an LU factorisation only when a drift check after an absorption fails: the residual of the basic
//! solution, and a probe ‖B₀⁻¹ (B 1) − 1‖∞ (the constant `DRIFT`); otherwise x gets one step of iterative refinement.
//!
//! The previous version recomputed the inverse from scratch (LU, then the m × m inverse: ≈ 2 m³) every 100
//! pivots and made two read-write passes over it per pivot; at m = 2644 that took 51 s against 31 s for Siconos'
//! lexicographic Lemke on the same pivots (`benches/peer/README.md`). Measured effect: the table in [`super`].
//!
//! Slower than the block-revised engine (`super::block`), kept as an independent implementation that the tests
//! compare against, and selectable by name (`lemke_dense`) with the same retry and ray interpretation as `lemke`
//! ([`super::Lemke`]). Its final solution is a fresh LU solve of the whole basis with one refinement step, computed
//! exactly as before the rework.

use super::{column, prepare, Lemke, LemkeOutcome, LemkeSettings, Scaled, Z0_NEGLIGIBLE};
use crate::cancel::Cancel;
use crate::solvers::{settings_of, Entry, Lcp, SolverId, Termination};
use faer::linalg::matmul::matmul;
use faer::linalg::solvers::Solve;
use faer::{Accum, Mat, MatMut, MatRef, Par};

/// The dense engine's identity.
pub const ID: SolverId = SolverId::new("lemke_dense");

/// Registry entry: Lemke with the dense engine (not part of `all`: run it by name).
pub const ENTRY: Entry = Entry::new::<LemkeSettings>(
    "lemke_dense",
    "Lemke's method, dense reference engine (whole basis inverse); every scene; run by name only",
    false,
    &["pivots"],
    |_, s| {
        let settings = settings_of::<LemkeSettings>(s).copied().unwrap_or_default();
        Box::new(Lemke { id: ID, settings, engine: solve_dense_cancellable })
    },
    super::cost,
);

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Var {
    W(usize),
    Z(usize),
    Z0,
}

/// As the messages name it: `w[i]`, `z[i]` (0-based LCP indices), `z0`.
impl std::fmt::Display for Var {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Var::W(i) => write!(f, "w[{i}]"),
            Var::Z(i) => write!(f, "z[{i}]"),
            Var::Z0 => write!(f, "z0"),
        }
    }
}

/// The explicit inverse is recomputed from scratch when the relative residual ‖q − B x‖∞ / (‖q‖∞ + ‖x‖∞) of the
/// basic solution exceeds `DRIFT`, or when the probe error ‖B₀⁻¹ (B 1) − 1‖∞ exceeds both [`PROBE_LIMIT`] and
/// [`PROBE_GROWTH`] times its value after the last inversion from scratch. (The probe error of a fresh inverse
/// is about κ(B) ε, 1e-12 to 1e-9 on the frictional LCPs: a new inversion only helps when the updates made it
/// grow well beyond that.)
const DRIFT: f64 = 1e-10;

/// See [`DRIFT`].
const PROBE_LIMIT: f64 = 1e-8;

/// See [`DRIFT`].
const PROBE_GROWTH: f64 = 100.0;

struct Work<'a> {
    sc: &'a Scaled<'a>,
    n: usize,
    basis: Vec<Var>,
    /// B₀⁻¹ (column-major), the inverse of the basis at the last absorption; `None` while B₀ = I.
    binv0: Option<Mat<f64>>,
    /// Eta file since then: pivot rows and pivot columns (flat, n per eta); B⁻¹ = E_t ⋯ E_1 B₀⁻¹.
    eta_rows: Vec<usize>,
    eta_cols: Vec<f64>,
    x: Vec<f64>,
    q: &'a [f64],
    /// Scratch.
    a: Vec<f64>,
    /// Recomputations of the inverse from scratch (drift).
    refactors: usize,
    /// Probe error right after the last inversion from scratch (0 for B₀ = I).
    probe_fresh: f64,
}

impl Work<'_> {
    fn column(&self, v: Var, out: &mut [f64]) {
        match v {
            Var::W(i) => {
                out.fill(0.0);
                out[i] = 1.0;
            }
            Var::Z(j) => self.sc.scaled_column(j, -1.0, out),
            Var::Z0 => out.fill(-1.0),
        }
    }

    /// y ← E_t ⋯ E_1 y.
    fn apply_etas(&self, y: &mut [f64]) {
        let n = self.n;
        for (t, &r) in self.eta_rows.iter().enumerate() {
            let d = &self.eta_cols[t * n..(t + 1) * n];
            let yr = y[r] / d[r];
            if yr != 0.0 {
                for (yi, &di) in y.iter_mut().zip(d) {
                    *yi -= di * yr;
                }
            }
            y[r] = yr;
        }
    }

    /// vᵀ = e_iᵀ E_t ⋯ E_1, as its nonzeros (row, value).
    fn eta_row(&self, i: usize) -> Vec<(usize, f64)> {
        let n = self.n;
        let mut v = vec![0.0; n];
        v[i] = 1.0;
        let mut nz = vec![i];
        let mut listed = vec![false; n];
        listed[i] = true;
        for (t, &r) in self.eta_rows.iter().enumerate().rev() {
            let d = &self.eta_cols[t * n..(t + 1) * n];
            let vd: f64 = nz.iter().map(|&s| v[s] * d[s]).sum();
            v[r] -= (vd - v[r]) / d[r];
            if !listed[r] {
                listed[r] = true;
                nz.push(r);
            }
        }
        nz.sort_unstable();
        nz.into_iter().map(|s| (s, v[s])).collect()
    }

    /// Entry c of the row vᵀ B₀⁻¹.
    fn row_entry(&self, v: &[(usize, f64)], c: usize) -> f64 {
        match &self.binv0 {
            None => v.iter().find(|&&(s, _)| s == c).map(|&(_, x)| x).unwrap_or(0.0),
            Some(b) => {
                let col = column(b, c);
                v.iter().map(|&(s, x)| x * col[s]).sum()
            }
        }
    }

    /// d = B⁻¹ a_v (a_v the column of v).
    fn ftran(&mut self, v: Var, d: &mut [f64]) {
        let n = self.n;
        match (v, &self.binv0) {
            (Var::W(i), Some(b)) => d.copy_from_slice(column(b, i)),
            (_, None) => self.column(v, d),
            (_, Some(_)) => {
                let mut a = std::mem::take(&mut self.a);
                a.resize(n, 0.0);
                self.column(v, &mut a);
                let b = self.binv0.as_ref().expect("B₀⁻¹");
                matmul(
                    MatMut::from_column_major_slice_mut(d, n, 1),
                    Accum::Replace,
                    b,
                    MatRef::from_column_major_slice(&a, n, 1),
                    1.0,
                    Par::Seq,
                );
                self.a = a;
            }
        }
        self.apply_etas(d);
    }

    /// Pivot on row r with pivot column d: x ← E x, one eta appended.
    fn pivot(&mut self, r: usize, d: &[f64], entering: Var) {
        let xr = self.x[r] / d[r];
        for (xi, &di) in self.x.iter_mut().zip(d) {
            *xi -= di * xr;
        }
        self.x[r] = xr;
        self.eta_rows.push(r);
        self.eta_cols.extend_from_slice(d);
        self.basis[r] = entering;
    }

    /// Absorb the eta file into B₀⁻¹: E_t ⋯ E_1 = I + U S with S the rows of the distinct pivot rows, so
    /// B⁻¹ = B₀⁻¹ + U (those rows of B₀⁻¹): one n × s × n product (s ≤ t). Then check the drift with the residual
    /// of the basic solution, refine x with one step, or recompute the inverse from scratch when the residual
    /// exceeds [`DRIFT`]. Returns false if the basis is numerically singular.
    fn absorb(&mut self) -> bool {
        let n = self.n;
        if self.eta_rows.is_empty() {
            return true;
        }
        let mut rows: Vec<usize> = Vec::new();
        let mut seen = vec![false; n];
        for &r in &self.eta_rows {
            if !seen[r] {
                seen[r] = true;
                rows.push(r);
            }
        }
        let s = rows.len();
        let mut u = Mat::<f64>::zeros(n, s);
        let mut y = vec![0.0; n];
        for (c, &r) in rows.iter().enumerate() {
            y.fill(0.0);
            y[r] = 1.0;
            self.apply_etas(&mut y);
            y[r] -= 1.0;
            for (i, &v) in y.iter().enumerate() {
                u[(i, c)] = v;
            }
        }
        match &mut self.binv0 {
            None => {
                let mut b = Mat::<f64>::identity(n, n);
                for (c, &r) in rows.iter().enumerate() {
                    for i in 0..n {
                        b[(i, r)] += u[(i, c)];
                    }
                }
                self.binv0 = Some(b);
            }
            Some(b) => {
                let sel = Mat::from_fn(s, n, |c, j| b[(rows[c], j)]);
                matmul(b.as_mut(), Accum::Add, &u, &sel, 1.0, Par::Seq);
            }
        }
        self.eta_rows.clear();
        self.eta_cols.clear();
        // Drift checks: the residual of the basic solution, res = q − B x, and the inverse on a probe,
        // ‖B₀⁻¹ (B 1) − 1‖∞.
        let mut res = self.q.to_vec();
        let mut bp = vec![0.0; n];
        let mut col = vec![0.0; n];
        for (r, &v) in self.basis.iter().enumerate() {
            let xr = self.x[r];
            self.column(v, &mut col);
            for ((ri, pi), &c) in res.iter_mut().zip(bp.iter_mut()).zip(&col) {
                *ri -= xr * c;
                *pi += c;
            }
        }
        let probe = self.times_binv0(&bp).iter().fold(0.0_f64, |a, v| a.max((v - 1.0).abs()));
        let rmax = res.iter().fold(0.0_f64, |a, v| a.max(v.abs()));
        let xmax = self.x.iter().fold(0.0_f64, |a, v| a.max(v.abs()));
        let qmax = self.q.iter().fold(0.0_f64, |a, v| a.max(v.abs()));
        let accurate = rmax <= DRIFT * (qmax + xmax) && probe <= PROBE_LIMIT.max(PROBE_GROWTH * self.probe_fresh);
        let drift = !accurate; // also on NaN
        if drift {
            self.refactors += 1;
            return self.refactor();
        }
        let dx = self.times_binv0(&res);
        for (xi, d) in self.x.iter_mut().zip(&dx) {
            *xi += d;
        }
        true
    }

    /// B₀⁻¹ v.
    fn times_binv0(&self, v: &[f64]) -> Vec<f64> {
        let n = self.n;
        let Some(b) = &self.binv0 else { return v.to_vec() };
        let mut out = vec![0.0; n];
        matmul(
            MatMut::from_column_major_slice_mut(&mut out, n, 1),
            Accum::Replace,
            b,
            MatRef::from_column_major_slice(v, n, 1),
            1.0,
            Par::Seq,
        );
        out
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

    /// x = B⁻¹ q from a fresh LU factorisation, with one step of iterative refinement; with `inverse`, B₀⁻¹ is
    /// recomputed from the same LU and the eta file emptied. Returns false if B is numerically singular.
    fn solve_basis(&mut self, inverse: bool) -> bool {
        let n = self.n;
        let b = self.basis_matrix();
        let lu = b.partial_piv_lu();
        if inverse {
            let inv = lu.solve(Mat::<f64>::identity(n, n));
            if !inv.col_iter().all(|c| c.iter().all(|v| v.is_finite())) {
                return false;
            }
            self.binv0 = Some(inv);
            self.eta_rows.clear();
            self.eta_cols.clear();
            let bp = Mat::from_fn(n, 1, |i, _| (0..n).map(|c| b[(i, c)]).sum::<f64>());
            let p = self.times_binv0(bp.col(0).try_as_col_major().expect("contiguous").as_slice());
            self.probe_fresh = p.iter().fold(0.0_f64, |a, v| a.max((v - 1.0).abs()));
        }
        let qv = Mat::from_fn(n, 1, |i, _| self.q[i]);
        let mut xs = lu.solve(&qv);
        // One step of iterative refinement.
        let res = Mat::from_fn(n, 1, |i, _| self.q[i] - (0..n).map(|k| b[(i, k)] * xs[(k, 0)]).sum::<f64>());
        let corr = lu.solve(&res);
        for i in 0..n {
            xs[(i, 0)] += corr[(i, 0)];
        }
        if !(0..n).all(|i| xs[(i, 0)].is_finite()) {
            return false;
        }
        for i in 0..n {
            self.x[i] = xs[(i, 0)];
        }
        true
    }

    /// Recompute B₀⁻¹ and x from an LU factorisation of the current basis.
    fn refactor(&mut self) -> bool {
        self.solve_basis(true)
    }
}

/// Reference engine: the whole m × m basis inverse kept explicitly and updated by an eta step per pivot, O(m²)
/// per pivot and O(m³) per refactorisation. Slower than [`super::solve`], kept as an independent implementation that the
/// tests compare against.
pub fn solve_dense(lcp: &Lcp, settings: &LemkeSettings) -> LemkeOutcome {
    solve_dense_cancellable(lcp, settings, &Cancel::never())
}

/// [`solve_dense`], stopping (`not_converged`) at the first pivot after `cancel` is raised.
pub fn solve_dense_cancellable(lcp: &Lcp, settings: &LemkeSettings, cancel: &Cancel) -> LemkeOutcome {
    let sc = match prepare(lcp) {
        Ok(sc) => sc,
        Err(out) => return out,
    };
    let n = lcp.size();
    let (qs, qscale) = (&sc.q, sc.qscale);
    let fail = |msg: String, pivots| LemkeOutcome {
        z: vec![0.0; n],
        w: lcp.q.clone(),
        status: Termination::NumericalError,
        pivots,
        message: msg,
    };
    let finish =
        |z_s: Vec<f64>, status: Termination, pivots: usize, message: String| sc.finish(z_s, status, pivots, message);
    let mut wk = Work {
        sc: &sc,
        n,
        basis: (0..n).map(Var::W).collect(),
        binv0: None,
        eta_rows: Vec::new(),
        eta_cols: Vec::new(),
        x: qs.clone(),
        q: qs,
        a: Vec::new(),
        refactors: 0,
        probe_fresh: 0.0,
    };
    // Initial pivot: z0 enters, the row of the most negative q leaves (ties: the lexicographic choice with
    // B = I is the largest index).
    let mut r0 = 0;
    for i in 0..n {
        if qs[i] <= qs[r0] {
            r0 = i;
        }
    }
    let mut d = vec![0.0; n];
    wk.ftran(Var::Z0, &mut d);
    let mut leaving = wk.basis[r0];
    let z0_start = wk.x[r0] / d[r0];
    wk.pivot(r0, &d, Var::Z0);
    let mut pivots = 1;
    let max_pivots = settings.max_pivots_per_unknown.saturating_mul(n).saturating_add(100);
    loop {
        let entering = match leaving {
            Var::W(i) => Var::Z(i),
            Var::Z(i) => Var::W(i),
            Var::Z0 => unreachable!("z0 leaving ends the loop"),
        };
        wk.ftran(entering, &mut d);
        let Some(r) = leaving_row(&mut wk, &d, settings, qscale, z0_start) else {
            let z0_value = wk.basis.iter().position(|&v| v == Var::Z0).map(|r| wk.x[r]).unwrap_or(0.0);
            if z0_value <= Z0_NEGLIGIBLE * z0_start {
                // z0 already zero to round-off: the current point is complementary (see the block engine).
                if !wk.solve_basis(false) {
                    return fail("the final basis is numerically singular".into(), pivots);
                }
                let z = extract_z(&wk);
                return finish(z, Termination::Solved, pivots, format!("z0 reached zero after {pivots} pivots"));
            }
            let z = extract_z(&wk);
            return finish(
                z,
                Termination::RayTermination,
                pivots,
                format!("secondary ray: entering {entering} is unblocked after {pivots} pivots"),
            );
        };
        leaving = wk.basis[r];
        wk.pivot(r, &d, entering);
        pivots += 1;
        if leaving == Var::Z0 {
            if !wk.solve_basis(false) {
                return fail("the final basis is numerically singular".into(), pivots);
            }
            let z = extract_z(&wk);
            return finish(z, Termination::Solved, pivots, format!("z0 left the basis after {pivots} pivots"));
        }
        if pivots >= max_pivots {
            let z = extract_z(&wk);
            return finish(z, Termination::NotConverged, pivots, format!("pivot limit {max_pivots} reached"));
        }
        if cancel.is_cancelled() {
            let z = extract_z(&wk);
            return finish(z, Termination::NotConverged, pivots, format!("cancelled after {pivots} pivots"));
        }
        if wk.eta_rows.len() >= settings.refactor_every && !wk.absorb() {
            return fail(format!("the basis became numerically singular after {pivots} pivots"), pivots);
        }
    }
}

/// The minimum-ratio test for the pivot column d, ties broken lexicographically by rows of B⁻¹ divided by the pivot
/// entry, z₀ leaving whenever it is tied or this step brings it to a negligible value. `None` when unblocked.
fn leaving_row(wk: &mut Work, d: &[f64], settings: &LemkeSettings, qscale: f64, z0_start: f64) -> Option<usize> {
    let n = wk.n;
    let dmax = d.iter().fold(0.0_f64, |a, v| a.max(v.abs()));
    let tol = settings.pivot_tolerance * dmax.max(1e-300);
    // Minimum ratio over blocking rows.
    let mut theta = f64::INFINITY;
    for i in 0..n {
        if d[i] > tol {
            theta = theta.min(wk.x[i].max(0.0) / d[i]);
        }
    }
    if !theta.is_finite() {
        return None;
    }
    let z0_row = wk.basis.iter().position(|&v| v == Var::Z0);
    let z0_value = z0_row.map(|r| wk.x[r]).unwrap_or(0.0);
    let tie = settings.tie_tolerance * (theta.abs() + settings.tie_tolerance * qscale.max(1.0));
    let tied: Vec<usize> = (0..n).filter(|&i| d[i] > tol && wk.x[i].max(0.0) / d[i] <= theta + tie).collect();
    let z0_drops = z0_row.is_some_and(|r| d[r] > tol && z0_value - theta * d[r] <= Z0_NEGLIGIBLE * z0_start);
    Some(if let Some(&rz) = tied.iter().find(|&&i| wk.basis[i] == Var::Z0) {
        rz
    } else if z0_drops {
        z0_row.expect("z0 basic")
    } else {
        // Lexicographic comparison of B⁻¹ rows scaled by 1/d. Row i of B⁻¹ is vᵀ B₀⁻¹ with vᵀ = e_iᵀ E_t ⋯ E_1,
        // which has at most t + 1 nonzeros: entry c is Σ_s v_s B₀⁻¹[s, c], formed only when a comparison reaches it.
        let rows: Vec<Vec<(usize, f64)>> = tied.iter().map(|&i| wk.eta_row(i)).collect();
        let mut best = 0;
        for t in 1..tied.len() {
            for c in 0..n {
                let a = wk.row_entry(&rows[t], c) / d[tied[t]];
                let b = wk.row_entry(&rows[best], c) / d[tied[best]];
                if (a - b).abs() > 1e-14 * (a.abs() + b.abs()) {
                    if a < b {
                        best = t;
                    }
                    break;
                }
            }
        }
        tied[best]
    })
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
