//! Block-revised Lemke engine: the basis is factorised through its z-part only, and updated in product form.
//!
//! The basis of `w − M z − d z₀ = q` (d the covering vector: e for the cold start, see [`super::solve_warm`] for
//! the warm start) holds some w's (columns of I) and some z's (columns −M_{:,j}, or −d for z₀). Let Z be the
//! basic z's (with z₀; "z-type" columns c = M_{:,j} or d), W the rows whose w is basic and R the other rows
//! (|R| = |Z| = k). With `C = M_{R,Z}` (k × k), the basis and its inverse are
//!
//! ```text
//!   B = [ I_W  −M_{W,Z} ]        B⁻¹ = [ I   −M_{W,Z} C⁻¹ ]
//!       [ 0    −C       ],              [ 0   −C⁻¹        ]
//! ```
//!
//! **Factorisation.** At a refactorisation the current basis becomes the *base* B₀: C₀ is factorised by LU with
//! partial pivoting (⅔ k³) and the block M_{W,Z} is copied into a contiguous (m − k) × k matrix. Between
//! refactorisations each pivot appends one eta vector (the pivot column) to an eta file, so that
//! `B⁻¹ = E_t ⋯ E_1 B₀⁻¹`. A pivot column `d = B⁻¹ a` costs one pair of triangular solves with the LU of C₀ (k²),
//! one product with the contiguous M_{W,Z} ((m − k) k) and t eta steps (t m); a w entering on a row of W₀ costs
//! only the eta steps. Nothing of size k² is written per pivot. The base is refactorised every `refactor_every`
//! pivots (default 100), which resets the eta file; the final basic solution comes from a fresh LU solve of the
//! final C with one step of iterative refinement.
//!
//! **Why.** The previous version of this engine kept C⁻¹ explicitly and updated it per pivot (bordering and
//! Sherman–Morrison), which made three passes over the k × k inverse per pivot (the column C⁻¹c_R, the row
//! M_{i,Z}C⁻¹ for the update, the rank-one update itself, read and written) plus a pass over all m rows of the k
//! basic columns of M. On the frictional LCP of 2644 unknowns (k ≈ 1100 at the end) those four passes were
//! 33 % + 14 % + 14 % + 11 % of the run, all memory-bound; the product form reads k² + (m − k) k numbers per pivot
//! instead of 4k² + m k and writes none. Measured effect: see the module docs of [`super`].
//!
//! **Ties** in the ratio test are broken lexicographically: among the tied rows the one whose row of
//! `B⁻¹ B_init` (B_init the starting basis: I for the cold start), divided by the pivot entry, is
//! lexicographically smallest. The comparison proceeds column by column and stops at the first difference; column
//! c of `B⁻¹ B_init` is the pivot column of the variable that was basic at position c in B_init, computed only when
//! a comparison reaches it. For the cold start this is exactly the rule of the dense engine, so both follow the
//! same pivot path on exact data.

use super::{column, LemkeOutcome, LemkeSettings, Scaled, Z0_NEGLIGIBLE};
use crate::cancel::Cancel;
use crate::solvers::Termination;
use faer::linalg::matmul::matmul;
use faer::linalg::solvers::{PartialPivLu, Solve};
use faer::{Accum, Mat, MatMut, MatRef, Par};

/// A variable of the LCP.
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

impl Var {
    /// The complement of a leaving variable: the variable that enters next.
    fn complement(self) -> Var {
        match self {
            Var::W(i) => Var::Z(i),
            Var::Z(i) => Var::W(i),
            Var::Z0 => unreachable!("z0 leaving ends the loop"),
        }
    }
}

const NONE: usize = usize::MAX;

/// A row of `B⁻¹` in the making, for the lexicographic rule: vᵀ = e_iᵀ E_t ⋯ E_1 and, when needed, vᵀ B₀⁻¹.
struct LexRow {
    v: Vec<f64>,
    g: Option<Vec<f64>>,
}

/// The base basis B₀ of the product form, in block form.
struct Base {
    /// Rows whose w is basic in B₀ (W₀), ascending.
    wrows: Vec<usize>,
    /// Basic z-type variables of B₀ by position p; position p sits in slot `rrows[p]`.
    zvars: Vec<Var>,
    /// Rows of R₀ by position, ascending.
    rrows: Vec<usize>,
    /// Position of row i in R₀, or NONE (i ∈ W₀).
    rpos: Vec<usize>,
    /// Position of z_j in Z₀ (index n: z₀), or NONE.
    zpos: Vec<usize>,
    /// LU of C₀ = M_{R₀,Z₀} (None when k = 0).
    lu: Option<PartialPivLu<f64>>,
    /// M_{W₀,Z₀}, contiguous ((m − k) × k).
    mw: Mat<f64>,
}

struct Engine<'a> {
    sc: &'a Scaled<'a>,
    q: &'a [f64],
    n: usize,
    /// The covering vector d (z₀'s column is −d).
    cover: Vec<f64>,
    /// Basic variable of each slot (basis position).
    slot_var: Vec<Var>,
    /// Slot of basic w_i / z_j / z₀, or NONE.
    w_slot: Vec<usize>,
    z_slot: Vec<usize>,
    z0_slot: usize,
    /// Basic values, by slot.
    x: Vec<f64>,
    base: Base,
    /// Eta file since the last refactorisation: pivot slots and pivot columns (flat, n per eta).
    eta_slots: Vec<usize>,
    eta_cols: Vec<f64>,
    /// The starting basis, by slot (columns of the lexicographic order).
    init_var: Vec<Var>,
    /// The basic z-type variables and the rows of R in the order the previous version of this engine kept them
    /// (a z entering by bordering is appended, a z or row replacement keeps the position, a removal swaps the
    /// last one in): the final solve factorises C in this order, so that the answer is the previous engine's to
    /// the bit.
    ord_z: Vec<Var>,
    ord_r: Vec<usize>,
    /// Scratch.
    yz: Vec<f64>,
    tw: Vec<f64>,
}

impl<'a> Engine<'a> {
    fn new(sc: &'a Scaled<'a>, cover: Vec<f64>) -> Self {
        let q = &sc.q[..];
        let n = q.len();
        Engine {
            sc,
            q,
            n,
            cover,
            slot_var: (0..n).map(Var::W).collect(),
            w_slot: (0..n).collect(),
            z_slot: vec![NONE; n],
            z0_slot: NONE,
            x: q.to_vec(),
            base: Base {
                wrows: (0..n).collect(),
                zvars: Vec::new(),
                rrows: Vec::new(),
                rpos: vec![NONE; n],
                zpos: vec![NONE; n + 1],
                lu: None,
                mw: Mat::zeros(n, 0),
            },
            eta_slots: Vec::new(),
            eta_cols: Vec::new(),
            init_var: (0..n).map(Var::W).collect(),
            ord_z: Vec::new(),
            ord_r: Vec::new(),
            yz: Vec::new(),
            tw: Vec::new(),
        }
    }

    /// Entry i of the z-type column c of v (M_{:,j}, or d for z₀).
    #[inline]
    fn zc(&self, v: Var, i: usize) -> f64 {
        match v {
            Var::Z(j) => self.sc.entry(i, j),
            Var::Z0 => self.cover[i],
            Var::W(_) => unreachable!("not a z-type variable"),
        }
    }

    fn set_slot(&mut self, v: Var, s: usize) {
        match v {
            Var::W(i) => self.w_slot[i] = s,
            Var::Z(j) => self.z_slot[j] = s,
            Var::Z0 => self.z0_slot = s,
        }
    }

    /// y = B₀⁻¹ a_v (by slot of B₀), a_v the column of v in `w − M z − d z₀ = q`.
    fn base_ftran(&mut self, v: Var, y: &mut [f64]) {
        let k = self.base.zvars.len();
        let mut yz = std::mem::take(&mut self.yz);
        yz.clear();
        match v {
            Var::W(i) if self.base.rpos[i] == NONE => {
                y.fill(0.0);
                y[i] = 1.0;
                self.yz = yz;
                return;
            }
            Var::W(i) => {
                // y_Z = −C⁻¹ e_q, y_W = M_{W,Z} y_Z.
                yz.resize(k, 0.0);
                yz[self.base.rpos[i]] = -1.0;
            }
            _ => {
                // y_Z = C⁻¹ c_R, y_W = M_{W,Z} y_Z − c_W.
                yz.extend(self.base.rrows.iter().map(|&r| self.zc(v, r)));
            }
        }
        if let Some(lu) = &self.base.lu {
            lu.solve_in_place(MatMut::from_column_major_slice_mut(&mut yz, k, 1));
        }
        let nw = self.base.wrows.len();
        let mut tw = std::mem::take(&mut self.tw);
        tw.resize(nw, 0.0);
        matmul(
            MatMut::from_column_major_slice_mut(&mut tw, nw, 1),
            Accum::Replace,
            self.base.mw.as_ref(),
            MatRef::from_column_major_slice(&yz, k, 1),
            1.0,
            Par::Seq,
        );
        for (p, &r) in self.base.rrows.iter().enumerate() {
            y[r] = yz[p];
        }
        match v {
            Var::W(_) => {
                for (a, &r) in self.base.wrows.iter().enumerate() {
                    y[r] = tw[a];
                }
            }
            _ => {
                for (a, &r) in self.base.wrows.iter().enumerate() {
                    y[r] = tw[a] - self.zc(v, r);
                }
            }
        }
        self.yz = yz;
        self.tw = tw;
    }

    /// Apply the eta file to y (by slot): y ← E_t ⋯ E_1 y.
    fn apply_etas(&self, y: &mut [f64]) {
        let n = self.n;
        for (t, &r) in self.eta_slots.iter().enumerate() {
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

    /// Pivot column d = B⁻¹ a_v, by slot.
    fn ftran(&mut self, v: Var, y: &mut [f64]) {
        self.base_ftran(v, y);
        self.apply_etas(y);
    }

    /// Pivot: the variable in slot r leaves, `enter` enters with value theta; d its pivot column.
    fn pivot(&mut self, r: usize, enter: Var, theta: f64, d: &[f64]) {
        for (xi, &di) in self.x.iter_mut().zip(d) {
            *xi -= theta * di;
        }
        self.x[r] = theta;
        self.eta_slots.push(r);
        self.eta_cols.extend_from_slice(d);
        let leave = self.slot_var[r];
        self.track_order(leave, enter);
        self.set_slot(leave, NONE);
        self.set_slot(enter, r);
        self.slot_var[r] = enter;
    }

    /// The complementary basis with z_i basic for `set[i]` (in slot i) and w_i for the others; it is also the
    /// starting basis of the lexicographic rule.
    fn set_complementary_basis(&mut self, set: &[bool]) {
        for (i, &g) in set.iter().enumerate() {
            if g {
                self.slot_var[i] = Var::Z(i);
                self.z_slot[i] = i;
                self.w_slot[i] = NONE;
            }
        }
        self.init_var = self.slot_var.clone();
        self.ord_z = (0..set.len()).filter(|&i| set[i]).map(Var::Z).collect();
        self.ord_r = (0..set.len()).filter(|&i| set[i]).collect();
    }

    /// Update `ord_z` / `ord_r` for a pivot (see their docs).
    fn track_order(&mut self, leave: Var, enter: Var) {
        let zpos = |o: &[Var], v: Var| o.iter().position(|&u| u == v).expect("basic z");
        match (leave, enter) {
            (Var::W(i), Var::W(j)) => {
                let q0 = self.ord_r.iter().position(|&r| r == j).expect("row of R");
                self.ord_r[q0] = i;
            }
            (Var::W(i), v) => {
                self.ord_z.push(v);
                self.ord_r.push(i);
            }
            (lv, Var::W(j)) => {
                let p0 = zpos(&self.ord_z, lv);
                let q0 = self.ord_r.iter().position(|&r| r == j).expect("row of R");
                self.ord_z.swap_remove(p0);
                self.ord_r.swap_remove(q0);
            }
            (lv, v) => {
                let p0 = zpos(&self.ord_z, lv);
                self.ord_z[p0] = v;
            }
        }
    }

    /// The final basic z's: x_Z = −C⁻¹ q_R from a fresh LU factorisation of C (in the order `ord_z` × `ord_r`) with
    /// one step of iterative refinement, written to the z slots. False if C is numerically singular.
    fn final_solve(&mut self) -> bool {
        let k = self.ord_z.len();
        let c = Mat::from_fn(k, k, |q, p| self.zc(self.ord_z[p], self.ord_r[q]));
        let lu = c.partial_piv_lu();
        let qr = Mat::from_fn(k, 1, |q, _| -self.q[self.ord_r[q]]);
        let mut x = lu.solve(&qr);
        let res = Mat::from_fn(k, 1, |q, _| qr[(q, 0)] - (0..k).map(|p| c[(q, p)] * x[(p, 0)]).sum::<f64>());
        let corr = lu.solve(&res);
        for p in 0..k {
            x[(p, 0)] += corr[(p, 0)];
        }
        if !(0..k).all(|p| x[(p, 0)].is_finite()) {
            return false;
        }
        for p in 0..k {
            let s = match self.ord_z[p] {
                Var::Z(j) => self.z_slot[j],
                _ => self.z0_slot,
            };
            self.x[s] = x[(p, 0)];
        }
        true
    }

    /// Make the current basis the base: LU of C, the contiguous M_{W,Z}, slots renumbered (w_i in slot i, the z at
    /// position p in slot `R[p]`), basic values recomputed (x_Z = −C⁻¹ q_R refined once, x_W = q_W + M_{W,Z} x_Z) and
    /// the eta file emptied. False if C is numerically singular.
    fn refactor(&mut self) -> bool {
        let n = self.n;
        let mut zvars: Vec<Var> = Vec::new();
        let mut wrows = Vec::new();
        let mut rpos = vec![NONE; n];
        let mut rrows = Vec::new();
        for s in 0..n {
            if !matches!(self.slot_var[s], Var::W(_)) {
                zvars.push(self.slot_var[s]);
            }
            if self.w_slot[s] == NONE {
                rpos[s] = rrows.len();
                rrows.push(s);
            } else {
                wrows.push(s);
            }
        }
        let k = zvars.len();
        debug_assert_eq!(k, rrows.len());
        let c = Mat::from_fn(k, k, |q, p| self.zc(zvars[p], rrows[q]));
        let lu = (k > 0).then(|| c.partial_piv_lu());
        let qr = Mat::from_fn(k, 1, |q, _| -self.q[rrows[q]]);
        let mut xz = qr.clone();
        if let Some(lu) = &lu {
            lu.solve_in_place(&mut xz);
            let mut res = Mat::from_fn(k, 1, |q, _| qr[(q, 0)]);
            matmul(&mut res, Accum::Add, &c, &xz, -1.0, Par::Seq);
            lu.solve_in_place(&mut res);
            xz += &res;
        }
        if !(0..k).all(|p| xz[(p, 0)].is_finite()) {
            // Keep the factorisation for the diagnosis ([`weak_columns`]); the engine is not used further.
            let zpos = vec![NONE; n + 1];
            self.base = Base { wrows, zvars, rrows, rpos, zpos, lu, mw: Mat::zeros(0, 0) };
            return false;
        }
        // Renumber the slots.
        for s in 0..n {
            self.slot_var[s] = Var::W(s);
        }
        self.w_slot.iter_mut().for_each(|v| *v = NONE);
        for &i in &wrows {
            self.w_slot[i] = i;
        }
        for (p, &v) in zvars.iter().enumerate() {
            let r = rrows[p];
            self.slot_var[r] = v;
            self.set_slot(v, r);
            self.x[r] = xz[(p, 0)];
        }
        self.eta_slots.clear();
        self.eta_cols.clear();
        let nw = wrows.len();
        let mut mw = std::mem::replace(&mut self.base.mw, Mat::zeros(0, 0));
        mw.resize_with(nw, k, |_, _| 0.0);
        for (p, &v) in zvars.iter().enumerate() {
            let col = mw.col_mut(p).try_as_col_major_mut().expect("contiguous").as_slice_mut();
            match v {
                Var::Z(j) => {
                    let (mj, dr, dcj) = (column(&self.sc.lcp.m, j), &self.sc.dr, self.sc.dc[j]);
                    for (o, &i) in col.iter_mut().zip(&wrows) {
                        *o = dr[i] * mj[i] * dcj;
                    }
                }
                _ => {
                    for (o, &i) in col.iter_mut().zip(&wrows) {
                        *o = self.cover[i];
                    }
                }
            }
        }
        let mut xw = Mat::<f64>::zeros(nw, 1);
        matmul(&mut xw, Accum::Replace, &mw, &xz, 1.0, Par::Seq);
        for (a, &i) in wrows.iter().enumerate() {
            self.x[i] = self.q[i] + xw[(a, 0)];
        }
        let mut zpos = vec![NONE; n + 1];
        for (p, &v) in zvars.iter().enumerate() {
            zpos[match v {
                Var::Z(j) => j,
                _ => n,
            }] = p;
        }
        self.base = Base { wrows, zvars, rrows, rpos, zpos, lu, mw };
        true
    }

    /// The minimum-ratio test for the pivot column d (by slot), with ties broken lexicographically (rows of
    /// `B⁻¹ B_init` divided by the pivot entry), and z₀ leaving whenever it is tied or this step brings it to a
    /// negligible value. `None` when the entering column is unblocked.
    fn leaving(&mut self, d: &[f64], settings: &LemkeSettings, qscale: f64, z0_start: f64) -> Option<usize> {
        let n = self.n;
        let dmax = d.iter().fold(0.0_f64, |a, v| a.max(v.abs()));
        let tol = settings.pivot_tolerance * dmax.max(1e-300);
        let x = &self.x;
        let mut theta = f64::INFINITY;
        for i in 0..n {
            if d[i] > tol {
                theta = theta.min(x[i].max(0.0) / d[i]);
            }
        }
        if !theta.is_finite() {
            return None;
        }
        let z0_row = (self.z0_slot != NONE).then_some(self.z0_slot);
        let z0_value = z0_row.map(|r| x[r]).unwrap_or(0.0);
        let tie = settings.tie_tolerance * (theta.abs() + settings.tie_tolerance * qscale.max(1.0));
        let tied: Vec<usize> = (0..n).filter(|&i| d[i] > tol && x[i].max(0.0) / d[i] <= theta + tie).collect();
        let z0_drops = z0_row.is_some_and(|r| d[r] > tol && z0_value - theta * d[r] <= Z0_NEGLIGIBLE * z0_start);
        Some(if let Some(&rz) = tied.iter().find(|&&i| Some(i) == z0_row) {
            rz
        } else if z0_drops {
            z0_row.expect("z0 basic")
        } else if tied.len() == 1 {
            tied[0]
        } else {
            self.lexmin(&tied, d)
        })
    }

    /// Lexicographic minimum of the rows `B⁻¹ B_init` / d over the tied slots.
    ///
    /// Row i of B⁻¹ is `vᵀ B₀⁻¹` with `vᵀ = e_iᵀ E_t ⋯ E_1` (the eta file applied from the right: O(t n)). Column c
    /// of B_init is the column of `init_var[c]`; when that variable is basic in B₀ (in base slot s), B₀⁻¹ maps
    /// its column to e_s and the entry is just v_s. Otherwise the whole row `vᵀ B₀⁻¹` is formed once (a product
    /// with M_{W,Z}ᵀ and a transposed solve with the LU of C₀) and dotted with the column.
    fn lexmin(&mut self, tied: &[usize], d: &[f64]) -> usize {
        let n = self.n;
        let mut rows: Vec<LexRow> = tied.iter().map(|&i| LexRow { v: self.eta_row(i), g: None }).collect();
        let mut best = 0;
        for t in 1..tied.len() {
            for c in 0..n {
                let a = self.lex_entry(&mut rows[t], c) / d[tied[t]];
                let b = self.lex_entry(&mut rows[best], c) / d[tied[best]];
                if (a - b).abs() > 1e-14 * (a.abs() + b.abs()) {
                    if a < b {
                        best = t;
                    }
                    break;
                }
            }
        }
        tied[best]
    }

    /// vᵀ = e_iᵀ E_t ⋯ E_1 (by slot).
    fn eta_row(&self, i: usize) -> Vec<f64> {
        let n = self.n;
        let mut v = vec![0.0; n];
        v[i] = 1.0;
        for (t, &r) in self.eta_slots.iter().enumerate().rev() {
            let d = &self.eta_cols[t * n..(t + 1) * n];
            let vd: f64 = v.iter().zip(d).map(|(a, b)| a * b).sum();
            v[r] -= (vd - v[r]) / d[r];
        }
        v
    }

    /// Entry c of the row `vᵀ B₀⁻¹ B_init`.
    fn lex_entry(&self, row: &mut LexRow, c: usize) -> f64 {
        let var = self.init_var[c];
        if let Some(s) = self.base_slot(var) {
            return row.v[s];
        }
        let g = row.g.get_or_insert_with(|| self.base_btran(&row.v));
        match var {
            Var::W(i) => g[i],
            Var::Z(j) => -(0..self.n).map(|i| g[i] * self.sc.entry(i, j)).sum::<f64>(),
            Var::Z0 => unreachable!("z0 is never in the starting basis"),
        }
    }

    /// Slot of v in the base B₀, if v is basic there.
    fn base_slot(&self, v: Var) -> Option<usize> {
        match v {
            Var::W(i) => (self.base.rpos[i] == NONE).then_some(i),
            Var::Z(j) => Some(self.base.zpos[j]).filter(|&p| p != NONE).map(|p| self.base.rrows[p]),
            Var::Z0 => Some(self.base.zpos[self.n]).filter(|&p| p != NONE).map(|p| self.base.rrows[p]),
        }
    }

    /// gᵀ = vᵀ B₀⁻¹ (v by slot of B₀, g by row): g_W = v_W, g_R = −C₀⁻ᵀ (M_{W,Z}ᵀ v_W + v_Z).
    fn base_btran(&self, v: &[f64]) -> Vec<f64> {
        let k = self.base.zvars.len();
        let nw = self.base.wrows.len();
        let mut g = vec![0.0; self.n];
        let vw: Vec<f64> = self.base.wrows.iter().map(|&r| v[r]).collect();
        let mut h: Vec<f64> = self.base.rrows.iter().map(|&r| v[r]).collect();
        matmul(
            MatMut::from_column_major_slice_mut(&mut h, k, 1),
            Accum::Add,
            self.base.mw.transpose(),
            MatRef::from_column_major_slice(&vw, nw, 1),
            1.0,
            Par::Seq,
        );
        if let Some(lu) = &self.base.lu {
            lu.solve_transpose_in_place(MatMut::from_column_major_slice_mut(&mut h, k, 1));
        }
        for (a, &r) in self.base.wrows.iter().enumerate() {
            g[r] = vw[a];
        }
        for (q, &r) in self.base.rrows.iter().enumerate() {
            g[r] = -h[q];
        }
        g
    }

    fn z_vector(&self) -> Vec<f64> {
        let mut z = vec![0.0; self.n];
        for (j, &s) in self.z_slot.iter().enumerate() {
            if s != NONE {
                z[j] = self.x[s].max(0.0);
            }
        }
        z
    }

    fn z0_value(&self) -> f64 {
        if self.z0_slot == NONE {
            0.0
        } else {
            self.x[self.z0_slot]
        }
    }
}

fn numerical_failure(sc: &Scaled, msg: String, pivots: usize) -> LemkeOutcome {
    LemkeOutcome {
        z: vec![0.0; sc.q.len()],
        w: sc.lcp.q.clone(),
        status: Termination::NumericalError,
        pivots,
        message: msg,
    }
}

/// The initial pivot (z₀ enters) and Lemke's loop from the engine's current complementary basis, whose basic
/// values x are not all ≥ 0, and whose covering vector makes z₀'s pivot column −e (d = B e).
fn lemke_loop(e: &mut Engine, sc: &Scaled, settings: &LemkeSettings, cancel: &Cancel) -> LemkeOutcome {
    let n = e.n;
    let mut d = vec![0.0; n];
    e.ftran(Var::Z0, &mut d);
    // Initial pivot: the slot with the largest −x/(−d) leaves (ties: the largest slot, the lexicographic choice
    // with respect to the starting basis).
    let mut r0 = NONE;
    let mut best = f64::NEG_INFINITY;
    for s in 0..n {
        if d[s] < 0.0 {
            let ratio = e.x[s] / d[s];
            if ratio >= best {
                best = ratio;
                r0 = s;
            }
        }
    }
    if r0 == NONE {
        return numerical_failure(sc, "the pivot column of z0 has no negative entry".into(), 0);
    }
    let theta0 = e.x[r0] / d[r0];
    let z0_start = theta0;
    let mut leaving = e.slot_var[r0];
    e.pivot(r0, Var::Z0, theta0, &d);
    let mut pivots = 1;
    let max_pivots = settings.max_pivots_per_unknown.saturating_mul(n).saturating_add(100);
    loop {
        let entering = leaving.complement();
        e.ftran(entering, &mut d);
        let Some(r) = e.leaving(&d, settings, sc.qscale, z0_start) else {
            if e.z0_value() <= Z0_NEGLIGIBLE * z0_start {
                // z0 is already zero to round-off: the current basic point is complementary (a degenerate last step
                // left z0 basic at value ~0). Accept it; the caller's residual check is the judge.
                if !e.final_solve() {
                    return numerical_failure(sc, "the final basis is numerically singular".into(), pivots);
                }
                return sc.finish(
                    e.z_vector(),
                    Termination::Solved,
                    pivots,
                    format!("z0 reached zero after {pivots} pivots"),
                );
            }
            return sc.finish(
                e.z_vector(),
                Termination::RayTermination,
                pivots,
                format!("secondary ray: entering {entering} is unblocked after {pivots} pivots"),
            );
        };
        let step = e.x[r].max(0.0) / d[r];
        leaving = e.slot_var[r];
        e.pivot(r, entering, step, &d);
        pivots += 1;
        if leaving == Var::Z0 {
            if !e.final_solve() {
                return numerical_failure(sc, "the final basis is numerically singular".into(), pivots);
            }
            return sc.finish(
                e.z_vector(),
                Termination::Solved,
                pivots,
                format!("z0 left the basis after {pivots} pivots"),
            );
        }
        if pivots >= max_pivots {
            return sc.finish(
                e.z_vector(),
                Termination::NotConverged,
                pivots,
                format!("pivot limit {max_pivots} reached"),
            );
        }
        if cancel.is_cancelled() {
            return sc.finish(
                e.z_vector(),
                Termination::NotConverged,
                pivots,
                format!("cancelled after {pivots} pivots"),
            );
        }
        if e.eta_slots.len() >= settings.refactor_every.max(e.base.zvars.len() / 4) && !e.refactor() {
            return numerical_failure(
                sc,
                format!("the basis became numerically singular after {pivots} pivots"),
                pivots,
            );
        }
    }
}

/// Run the block-revised engine on a prepared (scaled, q ≱ 0) problem: the cold start (covering vector e, initial
/// basis I).
pub(crate) fn run(sc: &Scaled, settings: &LemkeSettings, cancel: &Cancel) -> LemkeOutcome {
    let n = sc.q.len();
    let mut e = Engine::new(sc, vec![1.0; n]);
    lemke_loop(&mut e, sc, settings, cancel)
}

/// Why a warm start was abandoned, and the pivots it spent.
pub(crate) struct WarmFailure {
    pub(crate) reason: String,
    pub(crate) pivots: usize,
}

/// Run the block-revised engine from the complementary basis with z_i basic for `guess[i]` (a prepared problem).
///
/// The guessed basis B_g is factorised once (its C is M_{G,G}) and x̄ = B_g⁻¹ q computed. If x̄ ≥ 0 (to round-off)
/// it is the solution, found with no pivot. Otherwise the covering vector is d = B_g d̄ with d̄_s = 1 on the slots
/// where x̄_s < 0 and 0 elsewhere, so that z₀ enters with pivot column −d̄ and only has to repair the infeasible
/// rows; this is Lemke's method on the principal pivotal transform of the LCP with respect to G, with covering
/// vector d̄ ≥ 0 (Cottle, Pang & Stone §4.4 on general covering vectors), and the lexicographic rule is taken with
/// respect to B_g, so its anti-cycling argument carries over. `Err` when the guessed basis is singular or the
/// warm-started path does not end with z₀ leaving (the caller then starts cold).
pub(crate) fn run_warm(
    sc: &Scaled,
    settings: &LemkeSettings,
    guess: &[bool],
    cancel: &Cancel,
) -> Result<LemkeOutcome, WarmFailure> {
    let n = sc.q.len();
    let fail = |reason: String, pivots| Err(WarmFailure { reason, pivots });
    if guess.len() != n {
        return fail(format!("the guess has {} entries for {n} unknowns", guess.len()), 0);
    }
    let (mut e, dropped) = match guessed_basis(sc, guess) {
        Ok(r) => r,
        Err(reason) => return fail(reason, 0),
    };
    let xmax = e.x.iter().fold(0.0_f64, |a, v| a.max(v.abs()));
    let feas_tol = 1e-12 * xmax.max(sc.qscale);
    if e.x.iter().all(|&v| v >= -feas_tol) {
        let repair = if dropped > 0 {
            format!(" ({dropped} guessed z's dropped to make it nonsingular)")
        } else {
            String::new()
        };
        let message = format!("the guessed basis{repair} is feasible: solved with no pivot");
        return Ok(sc.finish(e.z_vector(), Termination::Solved, 0, message));
    }
    // Covering vector d = B_g e (row space): z₀'s pivot column is −e, as in the cold start of the transformed LCP.
    let mut cover = vec![0.0; n];
    let mut col = vec![0.0; n];
    for s in 0..n {
        match e.slot_var[s] {
            Var::W(i) => cover[i] += 1.0,
            Var::Z(j) => {
                sc.scaled_column(j, 1.0, &mut col);
                for (c, &mij) in cover.iter_mut().zip(&col) {
                    *c -= mij;
                }
            }
            Var::Z0 => unreachable!("z0 is not basic yet"),
        }
    }
    e.cover = cover;
    let nguess = guess.iter().filter(|&&g| g).count();
    let ninfeasible = e.x.iter().filter(|&&v| v < -feas_tol).count();
    let out = lemke_loop(&mut e, sc, settings, cancel);
    if out.status == Termination::Solved {
        let repair = if dropped > 0 { format!(" ({dropped} dropped to make it nonsingular)") } else { String::new() };
        let message = format!(
            "{} (warm start from {nguess} guessed basic z's{repair}, {ninfeasible} basic values infeasible)",
            out.message
        );
        Ok(LemkeOutcome { message, ..out })
    } else {
        fail(format!("the warm-started path ended {:?}: {}", out.status, out.message), out.pivots)
    }
}

/// The engine on the guessed complementary basis, factorised, and the number of guessed z's dropped to make it
/// nonsingular: while C = M'_{G,G} is numerically singular, the guessed z's whose column of C has a negligible
/// pivot in its LU are dropped ([`weak_columns`]), at most [`MAX_REPAIRS`] times.
fn guessed_basis<'a>(sc: &'a Scaled<'a>, guess: &[bool]) -> Result<(Engine<'a>, usize), String> {
    let n = sc.q.len();
    let mut set = guess.to_vec();
    let mut dropped = 0;
    for round in 0..=MAX_REPAIRS {
        let mut e = Engine::new(sc, vec![0.0; n]);
        e.set_complementary_basis(&set);
        if e.refactor() && well_conditioned(&e.base) {
            return Ok((e, dropped));
        }
        let weak = weak_columns(&e.base);
        if weak.is_empty() {
            break;
        }
        for v in weak {
            if let Var::Z(j) = v {
                set[j] = false;
                dropped += 1;
            }
        }
        if round == MAX_REPAIRS {
            break;
        }
    }
    Err(format!("the guessed basis is numerically singular (still after dropping {dropped} guessed z's)"))
}

/// Rounds of repair of a singular guessed basis (see [`guessed_basis`]).
const MAX_REPAIRS: usize = 8;

/// The basic z's of the base whose pivot in the LU of C is negligible (|U_jj| ≤ 1e-10 max |U_ii|, or not finite).
/// The frictional LCPs have pairs of columns that differ only in sign (λ⁺ᵢ and λ⁻ᵢ, u⁺ and u⁻ enter only through
/// their differences), so a guess holding both of a pair is singular: this finds the later one of the pair.
fn weak_columns(base: &Base) -> Vec<Var> {
    let Some(lu) = &base.lu else { return Vec::new() };
    let u = lu.U();
    let hi = (0..u.nrows()).map(|i| u[(i, i)].abs()).filter(|v| v.is_finite()).fold(0.0_f64, f64::max);
    let strong = |v: f64| v.abs() > 1e-10 * hi; // false for NaN
    (0..u.nrows()).filter(|&i| !strong(u[(i, i)])).map(|i| base.zvars[i]).collect()
}

/// The LU of the base is not numerically singular: min |U_ii| / max |U_ii| above 1e-13.
fn well_conditioned(base: &Base) -> bool {
    let Some(lu) = &base.lu else { return true };
    let u = lu.U();
    let (mut lo, mut hi) = (f64::INFINITY, 0.0_f64);
    for i in 0..u.nrows() {
        let v = u[(i, i)].abs();
        lo = lo.min(v);
        hi = hi.max(v);
    }
    lo > 1e-13 * hi
}
