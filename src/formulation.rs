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
use faer::linalg::solvers::Solve;
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
    /// A prescribed moment, which the NORM-TANG split does not carry.
    MomentLoad,
}

impl Frictionless {
    /// Build the frictionless problem of `scene` from its flexibility.
    pub fn new(scene: &Scene, model: &Model, flex: &Flexibility) -> Result<Frictionless, DriveIssue> {
        Self::build(scene, model, flex, None)
    }

    /// The normal problem at the limit of gross sliding, |Q| = μP with P and Q prescribed: every contact node
    /// slips, `h = σ μ f` (σ = sgn Q), so the tangential forces are eliminated exactly and only the normal problem
    /// remains, with `K = (F_NN + σμ F_NT) W⁻¹` (the cross block only with coupling) and the moment row
    /// `x − σμ y`. The tangential equilibrium Σh = σμP = Q holds by construction; the shift is indeterminate.
    pub fn sliding_limit(scene: &Scene, model: &Model, flex: &Flexibility, sigma: f64) -> Frictionless {
        Self::build(scene, model, flex, Some(sigma)).expect("the tangential drive is not used at the sliding limit")
    }

    fn build(scene: &Scene, model: &Model, flex: &Flexibility, limit: Option<f64>) -> Result<Frictionless, DriveIssue> {
        let n = flex.n();
        let l0 = model.length;
        let e = model.modulus;
        let smu = limit.map(|sg| sg * scene.contact.friction).unwrap_or(0.0);
        let cross = |i: usize, j: usize| match (&flex.nt, limit.is_some() && scene.contact.coupling) {
            (Some(nt), true) => smu * nt[(i, j)],
            _ => 0.0,
        };
        let k = Mat::from_fn(n, n, |i, j| (flex.nn[(i, j)] + cross(i, j)) / flex.weights[j]);
        let mut rigid_given = [0.0; 3];
        let mut loads = Vec::new();
        match scene.drive.tangential() {
            Dof::Displacement(d) => rigid_given[MODE_SHIFT] = d / l0,
            _ if limit.is_some() => {}
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
            Dof::Load(m) => loads.push(LoadDof {
                mode: MODE_ROTATION,
                row: (0..n).map(|i| flex.x[i] - smu * flex.y[i]).collect(),
                sign: 1.0,
                load: m / (e * l0 * l0),
            }),
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

/// Default slack-row signs of the frictional loading LCP, by rigid mode (shift, approach, rotation): see
/// [`Frictional::with_signs`].
pub const DEFAULT_SIGNS: [f64; 3] = [1.0, -1.0, 1.0];

/// One load-driven rigid degree of freedom of the frictional problem: its resultant is
/// `a_Nᵀ f + a_Tᵀ h = L` (f normal, h tangential nodal forces).
#[derive(Debug, Clone)]
pub struct FrictionalLoad {
    /// Rigid mode index (MODE_SHIFT, MODE_APPROACH or MODE_ROTATION).
    pub mode: usize,
    /// Row on the normal forces: 1 for P, 0 for Q, x for M.
    pub row_n: Vec<f64>,
    /// Row on the tangential forces: 0 for P, 1 for Q, −y for M.
    pub row_t: Vec<f64>,
    /// Sign s_m of the slack rows (see [`Frictional::with_signs`]).
    pub sign: f64,
    /// Prescribed resultant (dimensionless).
    pub load: f64,
}

/// The frictional contact problem (seed §4), displacement-, load- or mixed-driven, as one LCP.
///
/// **Friction law** (seed eqs. 25–31, a two-sided pyramid in 2D): per contact node,
/// `γ⁺ = μ f − h ≥ 0 ⊥ λ⁺ ≥ 0` and `γ⁻ = μ f + h ≥ 0 ⊥ λ⁻ ≥ 0`, and the slip of the wheel relative to the flat
/// is `s = u_T = λ⁻ − λ⁺`: friction on the wheel opposes its slip (h = +μf, γ⁺ = 0, goes with s = −λ⁺ ≤ 0).
///
/// **Elimination of the tangential forces** (seed eqs. 35–37): from `u_T = K_TN f + K_TT h + R_T ρ = λ⁻ − λ⁺`,
/// `h = S(λ⁻ − λ⁺ − K_TN f − R_T ρ)` with `S = K_TT⁻¹`. Writing ρ = ρ_D + E ρ_L (given plus load-driven
/// components) makes h, the gap, γ± and the equilibrium residuals affine functions of
/// `x = [f; λ⁺; λ⁻; ρ_L]`; the LCP is assembled from those affine maps:
///
/// ```text
///   z = [f; λ⁺; λ⁻; u⁺; u⁻],   w = [g; γ⁺; γ⁻; v⁺; v⁻],   ρ_L = u⁺ − u⁻,
///   v⁺_m = −s_m (a_Nᵀ f + a_Tᵀ h − L_m),   v⁻_m = s_m (a_Nᵀ f + a_Tᵀ h − L_m).
/// ```
///
/// With no load-driven DOF this is the seed's eq. 38 (rigid-body displacement approach); with all three it is
/// eq. 49 (rigid-body loading approach), whose printed matrix has typos (G_N for G_Nᵀ, signs in the slack rows):
/// the blocks here are derived, not copied, and proved by the residuals of the physical conditions.
/// By Betti's theorem `K_NT ≈ K_TNᵀ` and `S ≈ Sᵀ`, so the f–λ coupling blocks of M are skew and M is copositive
/// (`zᵀMz = Schur-complement and S quadratic forms + μ(λ⁺ + λ⁻)ᵀf ≥ 0`) but not copositive-plus (see
/// [`Frictional::with_signs`]): Lemke's ray on it is not a proof of infeasibility.
#[derive(Debug, Clone)]
pub struct Frictional {
    /// Friction coefficient μ.
    pub mu: f64,
    /// Prescribed rigid motion (shift, approach, rotation); load-driven entries are 0 here.
    pub rigid_given: [f64; 3],
    /// Load-driven DOFs.
    pub loads: Vec<FrictionalLoad>,
    /// h = h_x x + h_0 with x = [f; λ⁺; λ⁻; ρ_L] (n × (3n + L)).
    pub h_x: Mat<f64>,
    /// Constant part of h.
    pub h_0: Vec<f64>,
    /// The LCP, size 3n + 2L.
    pub lcp: Lcp,
}

impl Frictional {
    /// Build the frictional problem. `flex` must hold all four blocks ([`crate::condense::Blocks::All`]);
    /// with `scene.contact.coupling = false` the cross blocks are dropped (K_NT = K_TN = 0).
    pub fn new(scene: &Scene, model: &Model, flex: &Flexibility) -> Frictional {
        Self::with_signs(scene, model, flex, DEFAULT_SIGNS)
    }

    /// Build with chosen slack-row signs `s_m` (indexed by rigid mode: shift, approach, rotation). Any signs give the
    /// same solution set — at a solution both slacks vanish — but they change Lemke's path. No choice makes the
    /// frictional LCP copositive-plus (with f = 0 and λ⁺ = λ⁻ one has zᵀMz = 0 but (M + Mᵀ)z = 2μλ ≠ 0), so
    /// Lemke's success here rests on experience, not on the copositive-plus theorem: the defaults
    /// ([`DEFAULT_SIGNS`]) are those that solved every case tried, and the caller retries the other sign patterns
    /// when Lemke ends on a ray ([`crate::run`]). A ray is then reported as undecided unless a bound proves the drive
    /// infeasible.
    pub fn with_signs(scene: &Scene, model: &Model, flex: &Flexibility, signs: [f64; 3]) -> Frictional {
        let n = flex.n();
        let (l0, e) = (model.length, model.modulus);
        let mu = scene.contact.friction;
        let coupling = scene.contact.coupling;
        let per_force = |m: &Mat<f64>| Mat::from_fn(n, n, |i, j| m[(i, j)] / flex.weights[j]);
        let k_nn = per_force(&flex.nn);
        let k_tt = per_force(flex.tt.as_ref().expect("tangential blocks condensed"));
        let (k_nt, k_tn) = if coupling {
            (per_force(flex.nt.as_ref().expect("F_NT")), per_force(flex.tn.as_ref().expect("F_TN")))
        } else {
            (Mat::zeros(n, n), Mat::zeros(n, n))
        };
        let r_n = &flex.rigid_n;
        let r_t = flex.rigid_t.as_ref().expect("tangential rigid responses");

        let mut rigid_given = [0.0; 3];
        let mut loads = Vec::new();
        let zeros = vec![0.0; n];
        let ones = vec![1.0; n];
        match scene.drive.tangential() {
            Dof::Displacement(d) => rigid_given[MODE_SHIFT] = d / l0,
            Dof::Load(q) => loads.push(FrictionalLoad {
                mode: MODE_SHIFT,
                row_n: zeros.clone(),
                row_t: ones.clone(),
                sign: signs[MODE_SHIFT],
                load: q / (e * l0),
            }),
        }
        match scene.drive.normal() {
            Dof::Displacement(d) => rigid_given[MODE_APPROACH] = d / l0,
            Dof::Load(p) => loads.push(FrictionalLoad {
                mode: MODE_APPROACH,
                row_n: ones.clone(),
                row_t: zeros.clone(),
                sign: signs[MODE_APPROACH],
                load: p / (e * l0),
            }),
        }
        match scene.drive.rotational() {
            Dof::Displacement(phi) => rigid_given[MODE_ROTATION] = phi,
            Dof::Load(m) => loads.push(FrictionalLoad {
                mode: MODE_ROTATION,
                row_n: flex.x.clone(),
                row_t: flex.y.iter().map(|y| -y).collect(),
                sign: signs[MODE_ROTATION],
                load: m / (e * l0 * l0),
            }),
        }
        let nl = loads.len();
        let nx = 3 * n + nl;
        // S = K_TT⁻¹ and the affine map of h.
        let lu = k_tt.partial_piv_lu();
        let s = lu.solve(Mat::<f64>::identity(n, n));
        let sk = &s * &k_tn;
        let sr = &s * r_t;
        let mut h_x = Mat::<f64>::zeros(n, nx);
        let mut h_0 = vec![0.0; n];
        for i in 0..n {
            for j in 0..n {
                h_x[(i, j)] = -sk[(i, j)];
                h_x[(i, n + j)] = -s[(i, j)];
                h_x[(i, 2 * n + j)] = s[(i, j)];
            }
            for (b, ld) in loads.iter().enumerate() {
                h_x[(i, 3 * n + b)] = -sr[(i, ld.mode)];
            }
            h_0[i] = -(0..3).map(|m| sr[(i, m)] * rigid_given[m]).sum::<f64>();
        }
        // g = g0 + R_N (ρ_D + E ρ_L) + K_NN f + K_NT h.
        let knt_h = &k_nt * &h_x;
        let mut g_x = knt_h;
        for i in 0..n {
            for j in 0..n {
                g_x[(i, j)] += k_nn[(i, j)];
            }
            for (b, ld) in loads.iter().enumerate() {
                g_x[(i, 3 * n + b)] += r_n[(i, ld.mode)];
            }
        }
        let g_0: Vec<f64> = (0..n)
            .map(|i| {
                flex.g0[i]
                    + (0..3).map(|m| r_n[(i, m)] * rigid_given[m]).sum::<f64>()
                    + (0..n).map(|j| k_nt[(i, j)] * h_0[j]).sum::<f64>()
            })
            .collect();
        // Equilibrium residuals e_m = a_Nᵀ f + a_Tᵀ h − L_m.
        let mut e_x = Mat::<f64>::zeros(nl, nx);
        let mut e_0 = vec![0.0; nl];
        for (b, ld) in loads.iter().enumerate() {
            for c in 0..nx {
                let mut v: f64 = (0..n).map(|i| ld.row_t[i] * h_x[(i, c)]).sum();
                if c < n {
                    v += ld.row_n[c];
                }
                e_x[(b, c)] = v;
            }
            e_0[b] = (0..n).map(|i| ld.row_t[i] * h_0[i]).sum::<f64>() - ld.load;
        }
        // Assemble the LCP: columns x → z (ρ_L splits into u⁺, u⁻), rows g, γ⁺, γ⁻, v⁺, v⁻.
        let size = 3 * n + 2 * nl;
        let mut m = Mat::<f64>::zeros(size, size);
        let mut q = vec![0.0; size];
        let zcol = |c: usize| -> (usize, Option<usize>) {
            if c < 3 * n {
                (c, None)
            } else {
                let b = c - 3 * n;
                (3 * n + 2 * b, Some(3 * n + 2 * b + 1))
            }
        };
        let mut put_row = |row: usize, coef: &dyn Fn(usize) -> f64, c0: f64, m: &mut Mat<f64>| {
            for c in 0..nx {
                let v = coef(c);
                let (cp, cm) = zcol(c);
                m[(row, cp)] = v;
                if let Some(cm) = cm {
                    m[(row, cm)] = -v;
                }
            }
            q[row] = c0;
        };
        for i in 0..n {
            put_row(i, &|c| g_x[(i, c)], g_0[i], &mut m);
            let fmu = |c: usize| if c == i { mu } else { 0.0 };
            put_row(n + i, &|c| fmu(c) - h_x[(i, c)], -h_0[i], &mut m);
            put_row(2 * n + i, &|c| fmu(c) + h_x[(i, c)], h_0[i], &mut m);
        }
        for (b, ld) in loads.iter().enumerate() {
            let sg = ld.sign;
            put_row(3 * n + 2 * b, &|c| -sg * e_x[(b, c)], -sg * e_0[b], &mut m);
            put_row(3 * n + 2 * b + 1, &|c| sg * e_x[(b, c)], sg * e_0[b], &mut m);
        }
        Frictional { mu, rigid_given, loads, h_x, h_0, lcp: Lcp { m, q } }
    }

    /// Number of contact nodes.
    pub fn n(&self) -> usize {
        self.h_0.len()
    }

    /// Split an LCP solution into normal forces f, tangential forces h and the full rigid motion.
    pub fn unpack(&self, z: &[f64]) -> (Vec<f64>, Vec<f64>, [f64; 3]) {
        let n = self.n();
        let nl = self.loads.len();
        let mut x = z[..3 * n].to_vec();
        let mut rigid = self.rigid_given;
        for (b, ld) in self.loads.iter().enumerate() {
            let r = z[3 * n + 2 * b] - z[3 * n + 2 * b + 1];
            x.push(r);
            rigid[ld.mode] = r;
        }
        let h: Vec<f64> =
            (0..n).map(|i| self.h_0[i] + (0..3 * n + nl).map(|c| self.h_x[(i, c)] * x[c]).sum::<f64>()).collect();
        (z[..n].to_vec(), h, rigid)
    }
}

/// The flexibility split into its normal and tangential blocks, for NORM-TANG ([`crate::solvers::normtang`]):
/// nodal-force matrices (row-major, and K_NN column-major too for the QP inner solver), rigid responses, and the
/// drive in dimensionless units. The cross blocks are zero when `coupling = false`; the tangential blocks are
/// empty for a frictionless scene.
#[derive(Debug, Clone)]
pub struct Split {
    /// Contact nodes.
    pub n: usize,
    /// Friction coefficient.
    pub mu: f64,
    /// Whether K_NT, K_TN are kept.
    pub coupling: bool,
    /// K_NN, row-major.
    pub knn_rows: Vec<f64>,
    /// K_NN, column-major.
    pub knn_cols: Vec<f64>,
    /// K_NT, row-major (empty without friction).
    pub knt_rows: Vec<f64>,
    /// K_TN, row-major.
    pub ktn_rows: Vec<f64>,
    /// K_TT, row-major.
    pub ktt_rows: Vec<f64>,
    /// Initial gaps.
    pub g0: Vec<f64>,
    /// Normal rigid responses per node (shift, approach, rotation).
    pub rn: Vec<[f64; 3]>,
    /// Tangential rigid responses per node (zeros without the tangential blocks).
    pub rt: Vec<[f64; 3]>,
    /// Prescribed rigid motion (load-driven entries 0).
    pub rigid_given: [f64; 3],
    /// Normal drive, dimensionless.
    pub normal: Dof,
    /// Tangential drive, dimensionless.
    pub tangential: Dof,
}

impl Split {
    /// Build the split problem; a moment load is refused ([`DriveIssue::MomentLoad`]).
    pub fn new(scene: &Scene, model: &Model, flex: &Flexibility) -> Result<Split, DriveIssue> {
        let n = flex.n();
        let (l0, e) = (model.length, model.modulus);
        let mu = scene.contact.friction;
        let frictional = mu > 0.0;
        let coupling = scene.contact.coupling && frictional;
        let rows = |m: &Mat<f64>| {
            let mut v = Vec::with_capacity(n * n);
            for i in 0..n {
                for j in 0..n {
                    v.push(m[(i, j)] / flex.weights[j]);
                }
            }
            v
        };
        let knn_rows = rows(&flex.nn);
        let mut knn_cols = vec![0.0; n * n];
        for i in 0..n {
            for j in 0..n {
                knn_cols[i + j * n] = knn_rows[i * n + j];
            }
        }
        let opt =
            |m: &Option<Mat<f64>>| if frictional { m.as_ref().map(&rows).unwrap_or_default() } else { Vec::new() };
        let (knt_rows, ktn_rows, ktt_rows) = (opt(&flex.nt), opt(&flex.tn), opt(&flex.tt));
        let mut rigid_given = [0.0; 3];
        let normal = match scene.drive.normal() {
            Dof::Displacement(d) => {
                rigid_given[MODE_APPROACH] = d / l0;
                Dof::Displacement(d / l0)
            }
            Dof::Load(p) => Dof::Load(p / (e * l0)),
        };
        let tangential = match scene.drive.tangential() {
            Dof::Displacement(d) => {
                rigid_given[MODE_SHIFT] = d / l0;
                Dof::Displacement(d / l0)
            }
            Dof::Load(0.0) if !frictional => Dof::Displacement(0.0),
            Dof::Load(q) if !frictional => return Err(DriveIssue::TangentialLoadWithoutFriction(q)),
            Dof::Load(q) => Dof::Load(q / (e * l0)),
        };
        match scene.drive.rotational() {
            Dof::Displacement(phi) => rigid_given[MODE_ROTATION] = phi,
            Dof::Load(_) => return Err(DriveIssue::MomentLoad),
        }
        let rn = (0..n).map(|i| [flex.rigid_n[(i, 0)], flex.rigid_n[(i, 1)], flex.rigid_n[(i, 2)]]).collect();
        let rt = match &flex.rigid_t {
            Some(r) => (0..n).map(|i| [r[(i, 0)], r[(i, 1)], r[(i, 2)]]).collect(),
            None => vec![[0.0; 3]; n],
        };
        Ok(Split {
            n,
            mu,
            coupling,
            knn_rows,
            knn_cols,
            knt_rows,
            ktn_rows,
            ktt_rows,
            g0: flex.g0.clone(),
            rn,
            rt,
            rigid_given,
            normal,
            tangential,
        })
    }
}
