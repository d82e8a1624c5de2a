//! The slip operator: how the tangential kinematics of a formulation turns the tangential surface displacement
//! u_T (of the wheel relative to the counter-body, rigid motion included) into the slip s that Coulomb's law acts
//! on:
//!
//! ```text
//!   s = D u_T + c
//! ```
//!
//! with a matrix D (the identity when `None`) and an offset c (zero when `None`). Coulomb's law per contact node:
//! stick ⇔ s = 0 and |h| ≤ μf; slip ⇔ h = −μf·sgn(s) (friction on the wheel opposes the slip).
//!
//! - **Static** (the seed's problem, §4): s = u_T, the tangential displacement relative to the flat (it includes
//!   the rigid shift δ_T through the shift mode's response): D = I, c = 0.
//! - **Steady rolling** (Kalker 1990 §2; González & Abascal 2000, the seed's ref. \[3\]): s is the dimensionless
//!   slip velocity of the wheel's surface relative to the flat, `s = ξ − dir · ∂u_T/∂x` (dir = ±1 the rolling
//!   direction), discretised upwind: the difference taken towards the leading edge, where material enters,
//!   `s_i = ξ + (u_T,i − u_T,up(i)) / |x_up(i) − x_i|` with up(i) = i + 1 rolling towards +x and i − 1 towards
//!   −x. The creepage ξ is the problem's tangential DOF ([`super::DofKind::Creepage`]), so D holds the difference
//!   only. At the leading-edge node there is no upstream node in the candidate zone; its row takes u_up = 0, which
//!   keeps D invertible and matters for nothing physical there, since a well-posed candidate zone leaves that node
//!   separated (h = 0 whatever its slip).
//!
//!   **Sign.** In the contact frame of a wheel rolling towards +x, material moves towards −x at the rolling speed
//!   V: a surface point's slip velocity relative to the flat is V(ξ − ∂u_x/∂x). The seed's eq. 10–12 write
//!   `ξ + sgn(V)(u_T,x)` with V the velocity of the material through the contact, which is −dir: the same thing.
//!   Read with sgn(V) = the rolling direction, eq. 12 would make the slip decrease with the node's own shear
//!   (D K_TT with a negative diagonal: friction assisting its own slip, several solutions); the sign here makes it
//!   increase, and Carter's theory confirms it: the stick zone comes out at the leading edge (`tests/rolling.rs`).
//!   ξ > 0 is braking (the wheel's surface slower than the ground): the slip is positive and the friction on the
//!   wheel, q = −μp, negative.
//! - **Load step** (quasi-static history, `crate::pipeline::path`): s = Δu_T = u_T − u_T,prev, the slip increment since the
//!   previous step: D = I, c = −u_T,prev (material-tracked: when the contact rolls by d during the step, node i
//!   holds the material that was at x_i + dir·d, and the rigid creep ξ d adds to c). Coulomb's law on the increment
//!   is the incremental law of Mindlin–Deresiewicz and Spence: friction remembers the path.
//!
//! The LCP builder ([`super::lcp`]), NORM-TANG ([`crate::solvers::normtang`]) and the solver-independent residuals
//! ([`crate::post`]) all take the slip from here, so a new kinematics (steady rolling s = ξ + D u_T, a load step
//! s = Δu_T) is a new operator, not a new builder.

use faer::Mat;

/// Which kinematics the operator describes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub enum SlipKind {
    /// s = u_T: static contact (seed §4).
    Static,
    /// s = ξ + D u_T: steady rolling in direction `direction` (±1), the upwind difference D.
    Steady {
        /// The rolling direction, +1 towards +x.
        direction: i32,
    },
    /// s = u_T + c: the slip increment of a load step, c = −(the material's tangential displacement at the previous
    /// step's end) + ξ d (the rigid creep over a rolled distance d).
    Increment,
}

/// A matrix with at most two entries per row: the diagonal and one more (the upstream node of steady rolling). An
/// n-node D takes 3n words instead of n² (5.7 MB at 841 nodes).
#[derive(Debug, Clone, PartialEq)]
pub struct TwoDiagonal {
    /// D_ii.
    pub diag: Vec<f64>,
    /// The other entry of row i: its column and value (`None`: the row has the diagonal only).
    pub off: Vec<Option<(usize, f64)>>,
}

impl TwoDiagonal {
    /// Its size n.
    pub fn n(&self) -> usize {
        self.diag.len()
    }

    /// D as a dense n × n matrix (for tests and small problems).
    pub fn to_dense(&self) -> Mat<f64> {
        let mut d = Mat::<f64>::zeros(self.n(), self.n());
        for i in 0..self.n() {
            d[(i, i)] = self.diag[i];
            if let Some((u, v)) = self.off[i] {
                d[(i, u)] = v;
            }
        }
        d
    }

    /// D v.
    pub fn apply(&self, v: &[f64]) -> Vec<f64> {
        (0..self.n()).map(|i| self.diag[i] * v[i] + self.off[i].map_or(0.0, |(u, du)| du * v[u])).collect()
    }

    /// Entry (i, j) of D M for a matrix M with n rows (two products).
    pub fn entry(&self, m: &Mat<f64>, i: usize, j: usize) -> f64 {
        self.diag[i] * m[(i, j)] + self.off[i].map_or(0.0, |(u, du)| du * m[(u, j)])
    }
}

/// The slip operator s = D u_T + c (see the module docs).
#[derive(Debug, Clone, PartialEq)]
pub struct SlipOperator {
    /// Which kinematics.
    pub kind: SlipKind,
    /// D (n × n, two-diagonal); `None` is the identity.
    pub d: Option<TwoDiagonal>,
    /// c (length n); `None` is zero.
    pub offset: Option<Vec<f64>>,
}

impl SlipOperator {
    /// The static slip s = u_T.
    pub fn static_slip() -> SlipOperator {
        SlipOperator { kind: SlipKind::Static, d: None, offset: None }
    }

    /// The steady-rolling slip velocity on contact nodes at `x` (increasing), rolling in direction `direction`
    /// (±1): D is the upwind difference of the module docs; the creepage is the problem's tangential DOF.
    pub fn steady(x: &[f64], direction: i32) -> SlipOperator {
        SlipOperator { kind: SlipKind::Steady { direction }, d: Some(upwind(x, direction)), offset: None }
    }

    /// The slip increment of a load step: s = u_T + c with c = `offset` (see the module docs).
    pub fn increment(offset: Vec<f64>) -> SlipOperator {
        SlipOperator { kind: SlipKind::Increment, d: None, offset: Some(offset) }
    }

    /// The same kinematics on every `stride`-th node of a grid whose kept x are `x_coarse` (see
    /// [`crate::flexibility::Flexibility::coarse`]).
    pub fn coarse(&self, stride: usize, x_coarse: &[f64]) -> SlipOperator {
        match self.kind {
            SlipKind::Static => SlipOperator::static_slip(),
            SlipKind::Steady { direction } => SlipOperator::steady(x_coarse, direction),
            SlipKind::Increment => SlipOperator::increment(
                self.offset.as_ref().map_or_else(Vec::new, |c| c.iter().step_by(stride.max(1)).copied().collect()),
            ),
        }
    }

    /// Whether this is the steady-rolling operator (whose tangential DOF is the creepage).
    pub fn is_steady(&self) -> bool {
        matches!(self.kind, SlipKind::Steady { .. })
    }

    /// The bits of D (its two diagonals and their positions), for telling whether two operators have the same D
    /// exactly (the identity: one word). O(n).
    pub fn d_bits(&self) -> Vec<u64> {
        match &self.d {
            None => vec![0],
            Some(d) => (0..d.n())
                .flat_map(|i| {
                    let (u, du) = d.off[i].map_or((u64::MAX, 0.0), |(u, du)| (u as u64, du));
                    [d.diag[i].to_bits(), u, du.to_bits()]
                })
                .collect(),
        }
    }

    /// Entry (i, j) of D M for a matrix M with n rows (two products: D is two-diagonal).
    pub fn entry(&self, m: &Mat<f64>, i: usize, j: usize) -> f64 {
        match &self.d {
            None => m[(i, j)],
            Some(d) => d.entry(m, i, j),
        }
    }

    /// D v (a copy of v when D is the identity); O(n), D being two-diagonal.
    pub fn apply(&self, v: &[f64]) -> Vec<f64> {
        match &self.d {
            None => v.to_vec(),
            Some(d) => d.apply(v),
        }
    }

    /// D M for a matrix M with n rows (a copy when D is the identity); O(n²), D being two-diagonal (a dense product
    /// cost 2n³: 1.2 GFLOP per solve on an 841-node grid).
    pub fn apply_mat(&self, m: &Mat<f64>) -> Mat<f64> {
        match &self.d {
            None => m.clone(),
            Some(d) => Mat::from_fn(m.nrows(), m.ncols(), |i, j| d.entry(m, i, j)),
        }
    }

    /// The slip s = D u_T + c of a tangential displacement u_T.
    pub fn slip(&self, u_t: &[f64]) -> Vec<f64> {
        let mut s = self.apply(u_t);
        if let Some(c) = &self.offset {
            for (si, ci) in s.iter_mut().zip(c) {
                *si += ci;
            }
        }
        s
    }
}

/// The upwind difference of steady rolling (module docs): row i is `(e_i − e_up(i)) / |x_up(i) − x_i|`, the
/// leading-edge node's row `e_i / h` with the spacing of its downstream neighbour.
pub fn upwind(x: &[f64], direction: i32) -> TwoDiagonal {
    let n = x.len();
    let mut d = TwoDiagonal { diag: vec![0.0; n], off: vec![None; n] };
    for i in 0..n {
        let up = if direction >= 0 { (i + 1 < n).then_some(i + 1) } else { i.checked_sub(1) };
        match up {
            Some(u) => {
                let h = (x[u] - x[i]).abs();
                d.diag[i] = 1.0 / h;
                d.off[i] = Some((u, -1.0 / h));
            }
            None => {
                let down = if direction >= 0 { i.checked_sub(1) } else { (i + 1 < n).then_some(i + 1) };
                let h = down.map_or(1.0, |k| (x[k] - x[i]).abs());
                d.diag[i] = 1.0 / h;
            }
        }
    }
    d
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The two-diagonal products against the dense product with the same D (an independent computation: faer's
    /// matrix product), both rolling directions, on a non-uniform grid.
    #[test]
    fn sparse_products_match_the_dense_ones() {
        let x: Vec<f64> = (0..9).map(|i| (i as f64).powf(1.3) * 0.1 - 0.4).collect();
        let m = Mat::<f64>::from_fn(9, 5, |i, j| ((i * 7 + j * 3) % 11) as f64 - 4.5 + 0.1 * i as f64);
        let v: Vec<f64> = (0..9).map(|i| (i as f64 * 0.7).sin()).collect();
        for direction in [1, -1] {
            let op = SlipOperator::steady(&x, direction);
            let dense_d = op.d.as_ref().unwrap().to_dense();
            let dense_m = &dense_d * &m;
            let sparse_m = op.apply_mat(&m);
            for i in 0..9 {
                for j in 0..5 {
                    assert!((dense_m[(i, j)] - sparse_m[(i, j)]).abs() <= 1e-13 * dense_m[(i, j)].abs().max(1.0));
                }
            }
            let dense_v: Vec<f64> = (0..9).map(|i| (0..9).map(|j| dense_d[(i, j)] * v[j]).sum()).collect();
            for (a, b) in dense_v.iter().zip(op.apply(&v)) {
                assert!((a - b).abs() <= 1e-13 * a.abs().max(1.0));
            }
        }
    }
}
