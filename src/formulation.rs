//! Contact formulations built from the flexibility: plain data consumed by the solvers.
//!
//! **Unknowns are nodal forces**, `f_i = w_i p_i` (tributary length × pressure), not tractions. The matrix that
//! maps nodal forces to displacements, `K = F_NN W⁻¹`, is symmetric up to the collocation error of the BEM
//! (Betti's reciprocity), so (i) the frictionless problem is the LCP of an almost symmetric positive definite
//! matrix and the symmetric part defines the QP solved by clarabel, and (ii) in the load-driven LCP the columns of
//! the rigid motion and the rows of equilibrium cancel in `zᵀMz`, which makes M copositive-plus: Lemke then either
//! solves the problem or proves it infeasible (Cottle–Pang–Stone, Thm. 4.4.13). This is how rollbem resolves the
//! seed's ambiguous equilibrium matrices G_N (eq. 39): with nodal forces they are the rows `1ᵀ` (P) and `xᵀ` (M).
//!
//! **Frictionless, displacement-driven** (seed eq. 38 with no friction rows): `g = K f + q₀ ≥ 0 ⊥ f ≥ 0` with
//! `q₀ = g₀ + R_N ρ` (ρ the prescribed rigid motion).
//!
//! **Frictionless, load-driven** (seed §4.2, eqs. 39–49 without friction): every load-driven rigid degree of
//! freedom m (normal load P, moment M) has an unknown rigid displacement ρ_m = u⁺_m − u⁻_m and two slack rows
//! `v±_m` which, being ≥ 0 with opposite signs, enforce equilibrium `a_mᵀ f = L_m`:
//!
//! ```text
//!   g    = K f + Σ_m r_m (u⁺_m − u⁻_m) + q₀        (r_m = R_N's column of mode m)
//!   v⁺_m = −s_m (a_mᵀ f − L_m),   v⁻_m = s_m (a_mᵀ f − L_m)
//! ```
//!
//! with `a_P = 1`, `s_P = −1` (the approach mode moves contact nodes by −1 in y) and `a_M = x`, `s_M = +1` (the
//! rotation mode moves them by +x in y). The sign `s_m` is chosen so that `r_m ≈ s_m a_m`: the coupling terms are
//! skew and cancel in `zᵀMz`. The seed's printed eq. 49 puts `G_N` where its transpose belongs and flips signs in
//! the slack rows; the derivation above is ours, and the tests prove it by the residual of the physical
//! conditions (gap, complementarity, equilibrium) rather than of the LCP.
//!
//! All quantities are dimensionless ([`crate::condense::Model`]): lengths / L0, forces / (E·L0), moments /
//! (E·L0²).

use crate::condense::{Flexibility, Model};
use crate::scene::{Dof, Scene};
use crate::solvers::Lcp;
use faer::Mat;

/// Index of the rigid modes in [`Flexibility::rigid_n`].
pub const MODE_SHIFT: usize = 0;
/// Approach mode.
pub const MODE_APPROACH: usize = 1;
/// Rotation mode.
pub const MODE_ROTATION: usize = 2;

/// One load-driven rigid degree of freedom.
#[derive(Debug, Clone)]
pub struct LoadDof {
    /// Rigid mode index (MODE_APPROACH or MODE_ROTATION).
    pub mode: usize,
    /// Equilibrium row a_m (resultant = a_mᵀ f).
    pub row: Vec<f64>,
    /// Sign s_m with r_m ≈ s_m a_m.
    pub sign: f64,
    /// Prescribed resultant L_m (dimensionless).
    pub load: f64,
}

/// The frictionless contact problem, ready for any solver.
#[derive(Debug, Clone)]
pub struct Frictionless {
    /// K = F_NN W⁻¹: gap change per unit nodal force (n × n).
    pub k: Mat<f64>,
    /// q₀ = g₀ + R_N ρ over the displacement-driven modes.
    pub q0: Vec<f64>,
    /// Prescribed rigid motion (shift, approach, rotation); entries of load-driven modes are 0 here.
    pub rigid_given: [f64; 3],
    /// Load-driven degrees of freedom (empty for a displacement-driven problem).
    pub loads: Vec<LoadDof>,
    /// The LCP (size n, or n + 2·loads).
    pub lcp: Lcp,
}

/// Why a scene's drive cannot be formulated as a frictionless problem.
#[derive(Debug, Clone, PartialEq)]
pub enum DriveIssue {
    /// A nonzero tangential load with no friction: no static solution.
    TangentialLoadWithoutFriction(f64),
}

impl Frictionless {
    /// Build the frictionless problem of `scene` from its flexibility.
    pub fn new(scene: &Scene, model: &Model, flex: &Flexibility) -> Result<Frictionless, DriveIssue> {
        let n = flex.n();
        let l0 = model.length;
        let e = model.modulus;
        let k = Mat::from_fn(n, n, |i, j| flex.nn[(i, j)] / flex.weights[j]);
        let mut rigid_given = [0.0; 3];
        let mut loads = Vec::new();
        match scene.drive.tangential() {
            Dof::Displacement(d) => rigid_given[MODE_SHIFT] = d / l0,
            Dof::Load(0.0) => {}
            Dof::Load(q) => return Err(DriveIssue::TangentialLoadWithoutFriction(q)),
        }
        match scene.drive.normal() {
            Dof::Displacement(d) => rigid_given[MODE_APPROACH] = d / l0,
            Dof::Load(p) => {
                loads.push(LoadDof { mode: MODE_APPROACH, row: vec![1.0; n], sign: -1.0, load: p / (e * l0) })
            }
        }
        match scene.drive.rotational() {
            Dof::Displacement(phi) => rigid_given[MODE_ROTATION] = phi,
            Dof::Load(m) => {
                loads.push(LoadDof { mode: MODE_ROTATION, row: flex.x.clone(), sign: 1.0, load: m / (e * l0 * l0) })
            }
        }
        let q0: Vec<f64> =
            (0..n).map(|i| flex.g0[i] + (0..3).map(|m| flex.rigid_n[(i, m)] * rigid_given[m]).sum::<f64>()).collect();
        let size = n + 2 * loads.len();
        let mut m = Mat::<f64>::zeros(size, size);
        let mut q = vec![0.0; size];
        for j in 0..n {
            for i in 0..n {
                m[(i, j)] = k[(i, j)];
            }
        }
        q[..n].copy_from_slice(&q0);
        for (b, ld) in loads.iter().enumerate() {
            let (cp, cm) = (n + 2 * b, n + 2 * b + 1);
            for i in 0..n {
                let r = flex.rigid_n[(i, ld.mode)];
                m[(i, cp)] = r;
                m[(i, cm)] = -r;
                m[(cp, i)] = -ld.sign * ld.row[i];
                m[(cm, i)] = ld.sign * ld.row[i];
            }
            q[cp] = ld.sign * ld.load;
            q[cm] = -ld.sign * ld.load;
        }
        Ok(Frictionless { k, q0, rigid_given, loads, lcp: Lcp { m, q } })
    }

    /// Number of contact nodes.
    pub fn n(&self) -> usize {
        self.q0.len()
    }

    /// Split an LCP solution z into nodal forces and the full rigid motion (given + solved).
    pub fn unpack(&self, z: &[f64]) -> (Vec<f64>, [f64; 3]) {
        let n = self.n();
        let mut rigid = self.rigid_given;
        for (b, ld) in self.loads.iter().enumerate() {
            rigid[ld.mode] = z[n + 2 * b] - z[n + 2 * b + 1];
        }
        (z[..n].to_vec(), rigid)
    }
}
