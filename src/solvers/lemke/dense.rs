//! The dense reference engine of Lemke's method: the whole m × m basis inverse kept explicitly and updated by an
//! eta step per pivot, O(m²) per pivot and O(m³) per refactorisation. Slower than the block-revised engine
//! ([`super::block`]), kept as an independent implementation that the tests compare against, and selectable
//! by name (`lemke_dense`) with the same retry and ray interpretation as `lemke` ([`super::Lemke`]).

use super::{prepare, Lemke, LemkeOutcome, LemkeSettings, Z0_NEGLIGIBLE};
use crate::solvers::{Entry, Lcp, Status};
use faer::linalg::solvers::Solve;
use faer::Mat;

/// Registry entry: Lemke with the dense engine (not part of `all`: run it by name).
pub const ENTRY: Entry = Entry {
    name: "lemke_dense",
    summary: "Lemke's method, dense reference engine (whole basis inverse); every scene; run by name only",
    in_all: false,
    counters: &["pivots"],
    build: |raw| {
        let settings = crate::solvers::parse_settings("lemke_dense", raw)?;
        Ok(Box::new(Lemke { name: "lemke_dense", settings, engine: solve_dense }))
    },
};

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Var {
    W(usize),
    Z(usize),
    Z0,
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

/// Reference engine: the whole m × m basis inverse kept explicitly and updated by an eta step per pivot, O(m²)
/// per pivot and O(m³) per refactorisation. Slower than [`super::solve`], kept as an independent implementation that the
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
        let Some(r) = leaving_row(&wk, &d, settings, qscale, z0_start) else {
            let z0_value = wk.basis.iter().position(|&v| v == Var::Z0).map(|r| wk.x[r]).unwrap_or(0.0);
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

/// The minimum-ratio test for the pivot column d, ties broken lexicographically by rows of B⁻¹ divided by the pivot
/// entry, z₀ leaving whenever it is tied or this step brings it to a negligible value. `None` when unblocked.
fn leaving_row(wk: &Work, d: &[f64], settings: &LemkeSettings, qscale: f64, z0_start: f64) -> Option<usize> {
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
