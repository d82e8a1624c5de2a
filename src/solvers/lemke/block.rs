//! Block-revised Lemke engine: only the part of the basis made of z-columns is factorised.
//!
//! The basis of `w − M z − e z₀ = q` holds some w's (columns of I) and some z's (columns −M_{:,j}, or −e for z₀).
//! Let Z be the basic z's (with z₀; "z-type" columns c = M_{:,j} or e), W the rows whose w is basic and R the
//! other rows (|R| = |Z| = k). With `C = M_{R,Z}` (k × k), the basis and its inverse are
//!
//! ```text
//!   B = [ I_W  −M_{W,Z} ]        B⁻¹ = [ I   −M_{W,Z} C⁻¹ ]
//!       [ 0    −C       ],              [ 0   −C⁻¹        ]
//! ```
//!
//! so a pivot column `d = B⁻¹ a` costs one k × k product and one pass over the k basic columns of M, instead of an
//! m × m product, and C⁻¹ changes by one of four O(k²) updates per pivot: a row and a column added (a w leaves,
//! a z enters), a column replaced (z for z), a row replaced (w for w), a row and a column removed (a z leaves, a w
//! enters). C⁻¹ is recomputed from an LU factorisation every `max(refactor_every, k)` pivots (amortised O(k²)) and
//! the final basic solution comes from a fresh LU solve with one step of iterative refinement.
//!
//! Ties in the ratio test are broken lexicographically with rows of B⁻¹ (formed only for the tied candidates),
//! exactly as in the dense engine, so both follow the same pivot path on exact data.

use super::{LemkeOutcome, LemkeSettings, Scaled, Z0_NEGLIGIBLE};
use crate::solvers::Status;
use faer::linalg::solvers::Solve;
use faer::Mat;

/// A basic z-type variable.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Zv {
    Z(usize),
    Z0,
}

/// A variable of the LCP.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Var {
    W(usize),
    Z(Zv),
}

struct Engine<'a> {
    m: &'a Mat<f64>,
    q: &'a [f64],
    n: usize,
    /// w_i basic?
    wbasic: Vec<bool>,
    /// Value of basic w_i.
    xw: Vec<f64>,
    /// Basic z-type variables, by position p.
    zcols: Vec<Zv>,
    /// Their values.
    xz: Vec<f64>,
    /// Rows of R, by position q.
    rrows: Vec<usize>,
    /// Position of row i in R.
    rpos: Vec<usize>,
    /// C⁻¹ (Z positions × R positions), row stride `cap`.
    cinv: Vec<f64>,
    cap: usize,
}

const NONE: usize = usize::MAX;

impl<'a> Engine<'a> {
    fn k(&self) -> usize {
        self.zcols.len()
    }

    /// Entry i of the z-type column c (M_{:,j}, or e for z₀).
    #[inline]
    fn mc(&self, v: Zv, i: usize) -> f64 {
        match v {
            Zv::Z(j) => self.m[(i, j)],
            Zv::Z0 => 1.0,
        }
    }

    #[inline]
    fn ci(&self, p: usize, q: usize) -> f64 {
        self.cinv[p * self.cap + q]
    }

    /// t = Σ_p y_p c(zcols[p]) over all rows.
    fn combine(&self, y: &[f64], t: &mut [f64]) {
        t.fill(0.0);
        for (p, &yp) in y.iter().enumerate() {
            if yp == 0.0 {
                continue;
            }
            match self.zcols[p] {
                Zv::Z(j) => {
                    let col = self.m.col(j);
                    for (ti, &mij) in t.iter_mut().zip(col.iter()) {
                        *ti += yp * mij;
                    }
                }
                Zv::Z0 => t.iter_mut().for_each(|ti| *ti += yp),
            }
        }
    }

    /// Pivot column of an entering variable: (d_W over all rows — meaningful on W —, d_Z over positions).
    fn column(&self, e: Var, dw: &mut [f64], dz: &mut Vec<f64>) {
        let k = self.k();
        dz.clear();
        match e {
            Var::Z(v) => {
                let cr: Vec<f64> = self.rrows.iter().map(|&i| self.mc(v, i)).collect();
                for p in 0..k {
                    let row = &self.cinv[p * self.cap..p * self.cap + k];
                    dz.push(row.iter().zip(&cr).map(|(a, b)| a * b).sum());
                }
                self.combine(dz, dw);
                for (i, d) in dw.iter_mut().enumerate() {
                    *d -= self.mc(v, i);
                }
            }
            Var::W(j) => {
                let q0 = self.rpos[j];
                for p in 0..k {
                    dz.push(-self.ci(p, q0));
                }
                self.combine(dz, dw);
            }
        }
    }

    /// u = M_{i,Z} C⁻¹ (a row over R positions).
    fn row_times_cinv(&self, i: usize) -> Vec<f64> {
        let k = self.k();
        let mut u = vec![0.0; k];
        for p in 0..k {
            let r = self.mc(self.zcols[p], i);
            if r != 0.0 {
                let row = &self.cinv[p * self.cap..p * self.cap + k];
                for (uq, &c) in u.iter_mut().zip(row) {
                    *uq += r * c;
                }
            }
        }
        u
    }

    /// Row of B⁻¹ of a basic variable, as a vector over the original rows.
    fn binv_row(&self, v: Var) -> Vec<f64> {
        let mut out = vec![0.0; self.n];
        match v {
            Var::W(i) => {
                out[i] = 1.0;
                for (q, uq) in self.row_times_cinv(i).into_iter().enumerate() {
                    out[self.rrows[q]] = -uq;
                }
            }
            Var::Z(zv) => {
                let p = self.zcols.iter().position(|&c| c == zv).expect("basic z");
                for q in 0..self.k() {
                    out[self.rrows[q]] = -self.ci(p, q);
                }
            }
        }
        out
    }

    fn rank1(&mut self, a: &[f64], b: &[f64], scale: f64) {
        let k = self.k();
        for p in 0..k {
            let f = a[p] * scale;
            if f != 0.0 {
                let row = &mut self.cinv[p * self.cap..p * self.cap + k];
                for (c, &bq) in row.iter_mut().zip(b) {
                    *c += f * bq;
                }
            }
        }
    }

    /// Apply a pivot: `leave` leaves, `enter` enters with value `theta`; dw/dz its pivot column.
    fn pivot(&mut self, leave: Var, enter: Var, theta: f64, dw: &[f64], dz: &[f64]) {
        let k = self.k();
        // Values of the variables that stay basic.
        for i in 0..self.n {
            if self.wbasic[i] {
                self.xw[i] -= theta * dw[i];
            }
        }
        for p in 0..k {
            self.xz[p] -= theta * dz[p];
        }
        let cap = self.cap;
        match (leave, enter) {
            (Var::W(i), Var::Z(v)) => {
                // Border C with row i and column v: s = c_i − M_{i,Z} C⁻¹ c_R = −d_W[i].
                let s = -dw[i];
                let u = self.row_times_cinv(i);
                self.rank1(dz, &u, 1.0 / s);
                for p in 0..k {
                    self.cinv[p * cap + k] = -dz[p] / s;
                }
                for q in 0..k {
                    self.cinv[k * cap + q] = -u[q] / s;
                }
                self.cinv[k * cap + k] = 1.0 / s;
                self.wbasic[i] = false;
                self.rpos[i] = k;
                self.rrows.push(i);
                self.zcols.push(v);
                self.xz.push(theta);
            }
            (Var::Z(lv), Var::Z(v)) => {
                // Column replacement at p0: eta step with y = C⁻¹ c_R = d_Z.
                let p0 = self.zcols.iter().position(|&c| c == lv).expect("basic z");
                let piv = dz[p0];
                let prow: Vec<f64> = self.cinv[p0 * cap..p0 * cap + k].iter().map(|c| c / piv).collect();
                for p in 0..k {
                    let f = if p == p0 { 0.0 } else { dz[p] };
                    let row = &mut self.cinv[p * cap..p * cap + k];
                    if p == p0 {
                        row.copy_from_slice(&prow);
                    } else if f != 0.0 {
                        for (c, &b) in row.iter_mut().zip(&prow) {
                            *c -= f * b;
                        }
                    }
                }
                self.zcols[p0] = v;
                self.xz[p0] = theta;
            }
            (Var::W(i), Var::W(j)) => {
                // Row replacement at q0 = pos(j): C' = C + e_q0 (M_{i,Z} − M_{j,Z}).
                let q0 = self.rpos[j];
                let g: Vec<f64> = (0..k).map(|p| self.ci(p, q0)).collect();
                let mut h = self.row_times_cinv(i);
                h[q0] -= 1.0;
                let denom = 1.0 + h[q0];
                self.rank1(&g, &h, -1.0 / denom);
                self.rrows[q0] = i;
                self.rpos[i] = q0;
                self.rpos[j] = NONE;
                self.wbasic[i] = false;
                self.wbasic[j] = true;
                self.xw[j] = theta;
            }
            (Var::Z(lv), Var::W(j)) => {
                // Remove Z position p0 and R position q0.
                let p0 = self.zcols.iter().position(|&c| c == lv).expect("basic z");
                let q0 = self.rpos[j];
                let piv = self.ci(p0, q0);
                let col: Vec<f64> = (0..k).map(|p| self.ci(p, q0)).collect();
                let row: Vec<f64> = self.cinv[p0 * cap..p0 * cap + k].to_vec();
                self.rank1(&col, &row, -1.0 / piv);
                // Swap-remove row p0 (Z side) and column q0 (R side).
                let last = k - 1;
                if p0 != last {
                    for q in 0..k {
                        self.cinv[p0 * cap + q] = self.cinv[last * cap + q];
                    }
                }
                if q0 != last {
                    for p in 0..k {
                        self.cinv[p * cap + q0] = self.cinv[p * cap + last];
                    }
                }
                self.zcols.swap_remove(p0);
                self.xz.swap_remove(p0);
                let moved = self.rrows[last];
                self.rrows.swap_remove(q0);
                if q0 != last {
                    self.rpos[moved] = q0;
                }
                self.rpos[j] = NONE;
                self.wbasic[j] = true;
                self.xw[j] = theta;
            }
        }
    }

    /// C = M_{R,Z} as a k × k matrix (R positions × Z positions).
    fn c_matrix(&self) -> Mat<f64> {
        let k = self.k();
        Mat::from_fn(k, k, |q, p| self.mc(self.zcols[p], self.rrows[q]))
    }

    /// Recompute C⁻¹ and the basic values from an LU factorisation (x_Z = −C⁻¹ q_R refined once,
    /// x_W = q_W + M_{W,Z} x_Z). Returns false if C is numerically singular.
    fn refactor(&mut self, keep_inverse: bool) -> bool {
        let k = self.k();
        let c = self.c_matrix();
        let lu = c.partial_piv_lu();
        let qr = Mat::from_fn(k, 1, |q, _| -self.q[self.rrows[q]]);
        let mut x = lu.solve(&qr);
        let res = Mat::from_fn(k, 1, |q, _| qr[(q, 0)] - (0..k).map(|p| c[(q, p)] * x[(p, 0)]).sum::<f64>());
        let corr = lu.solve(&res);
        for p in 0..k {
            x[(p, 0)] += corr[(p, 0)];
        }
        if !(0..k).all(|p| x[(p, 0)].is_finite()) {
            return false;
        }
        if keep_inverse {
            let inv = lu.solve(Mat::<f64>::identity(k, k));
            if !inv.col_iter().all(|col| col.iter().all(|v| v.is_finite())) {
                return false;
            }
            for p in 0..k {
                for q in 0..k {
                    self.cinv[p * self.cap + q] = inv[(p, q)];
                }
            }
        }
        for p in 0..k {
            self.xz[p] = x[(p, 0)];
        }
        let mut t = vec![0.0; self.n];
        self.combine(&self.xz.clone(), &mut t);
        for i in 0..self.n {
            if self.wbasic[i] {
                self.xw[i] = self.q[i] + t[i];
            }
        }
        true
    }

    /// The minimum-ratio test for the pivot column (dw, dz), with ties broken lexicographically by rows of B⁻¹
    /// divided by the pivot entry, and z₀ leaving whenever it is tied or this step brings it to a negligible value.
    /// `None` when the entering column is unblocked.
    fn leaving(&self, dw: &[f64], dz: &[f64], settings: &LemkeSettings, qscale: f64, z0_start: f64) -> Option<Var> {
        let (e, n) = (self, self.n);
        let dmax = (0..n)
            .filter(|&i| e.wbasic[i])
            .map(|i| dw[i].abs())
            .chain(dz.iter().map(|d| d.abs()))
            .fold(0.0_f64, f64::max);
        let tol = settings.pivot_tolerance * dmax.max(1e-300);
        let mut theta = f64::INFINITY;
        for i in 0..n {
            if e.wbasic[i] && dw[i] > tol {
                theta = theta.min(e.xw[i].max(0.0) / dw[i]);
            }
        }
        for p in 0..e.k() {
            if dz[p] > tol {
                theta = theta.min(e.xz[p].max(0.0) / dz[p]);
            }
        }
        if !theta.is_finite() {
            return None;
        }
        let z0_pos = e.zcols.iter().position(|&c| c == Zv::Z0);
        let z0_value = z0_pos.map(|p| e.xz[p]).unwrap_or(0.0);
        let tie = settings.tie_tolerance * (theta.abs() + settings.tie_tolerance * qscale.max(1.0));
        let mut tied: Vec<(Var, f64)> = Vec::new();
        for i in 0..n {
            if e.wbasic[i] && dw[i] > tol && e.xw[i].max(0.0) / dw[i] <= theta + tie {
                tied.push((Var::W(i), dw[i]));
            }
        }
        for p in 0..e.k() {
            if dz[p] > tol && e.xz[p].max(0.0) / dz[p] <= theta + tie {
                tied.push((Var::Z(e.zcols[p]), dz[p]));
            }
        }
        // z0 leaves whenever it is tied, or whenever this step would bring it to a negligible value (a tie the
        // relative band misses when θ ≈ 0).
        let z0_drops = z0_pos.is_some_and(|p| dz[p] > tol && z0_value - theta * dz[p] <= Z0_NEGLIGIBLE * z0_start);
        Some(if let Some(&(v, _)) = tied.iter().find(|(v, _)| *v == Var::Z(Zv::Z0)) {
            v
        } else if z0_drops {
            Var::Z(Zv::Z0)
        } else if tied.len() == 1 {
            tied[0].0
        } else {
            // Lexicographic rule on rows of B⁻¹ divided by the pivot entry.
            let rows: Vec<Vec<f64>> =
                tied.iter().map(|&(v, d)| e.binv_row(v).iter().map(|x| x / d).collect()).collect();
            let mut best = 0;
            for t in 1..tied.len() {
                for c in 0..n {
                    let (a, b) = (rows[t][c], rows[best][c]);
                    if (a - b).abs() > 1e-14 * (a.abs() + b.abs()) {
                        if a < b {
                            best = t;
                        }
                        break;
                    }
                }
            }
            tied[best].0
        })
    }

    fn z_vector(&self) -> Vec<f64> {
        let mut z = vec![0.0; self.n];
        for (p, &v) in self.zcols.iter().enumerate() {
            if let Zv::Z(j) = v {
                z[j] = self.xz[p].max(0.0);
            }
        }
        z
    }
}

/// Run the block-revised engine on a prepared (scaled, q ≱ 0) problem.
pub(crate) fn run(sc: &Scaled, settings: &LemkeSettings) -> LemkeOutcome {
    let n = sc.q.len();
    let cap = n + 1;
    let mut e = Engine {
        m: &sc.m,
        q: &sc.q,
        n,
        wbasic: vec![true; n],
        xw: sc.q.clone(),
        zcols: Vec::new(),
        xz: Vec::new(),
        rrows: Vec::new(),
        rpos: vec![NONE; n],
        cinv: vec![0.0; cap * cap],
        cap,
    };
    let fail = |msg: String, pivots: usize| LemkeOutcome {
        z: vec![0.0; n],
        w: sc.lcp.q.clone(),
        status: Status::NumericalError,
        pivots,
        message: msg,
    };
    // Initial pivot: z0 enters, the most negative q leaves (ties: the largest index, the lexicographic choice
    // with B = I, as in the dense engine).
    let mut r0 = 0;
    for i in 0..n {
        if sc.q[i] <= sc.q[r0] {
            r0 = i;
        }
    }
    let mut dw = vec![0.0; n];
    let mut dz = Vec::new();
    e.column(Var::Z(Zv::Z0), &mut dw, &mut dz);
    let theta0 = e.xw[r0] / dw[r0];
    let z0_start = theta0;
    e.pivot(Var::W(r0), Var::Z(Zv::Z0), theta0, &dw, &dz);
    let mut leaving = Var::W(r0);
    let mut pivots = 1;
    let max_pivots = settings.max_pivots_per_unknown.saturating_mul(n).saturating_add(100);
    let mut since_refactor = 0;
    loop {
        let entering = match leaving {
            Var::W(i) => Var::Z(Zv::Z(i)),
            Var::Z(Zv::Z(i)) => Var::W(i),
            Var::Z(Zv::Z0) => unreachable!("z0 leaving ends the loop"),
        };
        e.column(entering, &mut dw, &mut dz);
        let Some(leave) = e.leaving(&dw, &dz, settings, sc.qscale, z0_start) else {
            let z0_value = e.zcols.iter().position(|&c| c == Zv::Z0).map(|p| e.xz[p]).unwrap_or(0.0);
            if z0_value <= Z0_NEGLIGIBLE * z0_start {
                // z0 is already zero to round-off: the current basic point is complementary (a degenerate last step
                // left z0 basic at value ~0). Accept it; the caller's residual check is the judge.
                if !e.refactor(false) {
                    return fail("the final basis is numerically singular".into(), pivots);
                }
                return sc.finish(
                    e.z_vector(),
                    Status::Solved,
                    pivots,
                    format!("z0 reached zero after {pivots} pivots"),
                );
            }
            return sc.finish(
                e.z_vector(),
                Status::RayTermination,
                pivots,
                format!("secondary ray: entering {entering:?} is unblocked after {pivots} pivots"),
            );
        };
        let piv = match leave {
            Var::W(i) => dw[i],
            Var::Z(v) => dz[e.zcols.iter().position(|&c| c == v).expect("basic")],
        };
        let step = match leave {
            Var::W(i) => e.xw[i].max(0.0),
            Var::Z(v) => e.xz[e.zcols.iter().position(|&c| c == v).expect("basic")].max(0.0),
        } / piv;
        e.pivot(leave, entering, step, &dw, &dz);
        leaving = leave;
        pivots += 1;
        since_refactor += 1;
        if leaving == Var::Z(Zv::Z0) {
            if !e.refactor(false) {
                return fail("the final basis is numerically singular".into(), pivots);
            }
            return sc.finish(e.z_vector(), Status::Solved, pivots, format!("z0 left the basis after {pivots} pivots"));
        }
        if pivots >= max_pivots {
            return sc.finish(e.z_vector(), Status::NotConverged, pivots, format!("pivot limit {max_pivots} reached"));
        }
        if since_refactor >= settings.refactor_every.max(e.k()) {
            since_refactor = 0;
            if !e.refactor(true) {
                return fail(format!("the basis became numerically singular after {pivots} pivots"), pivots);
            }
        }
    }
}
