//! The LCPs of the contact problem, in the convention `w = M z + q`, `w ≥ 0`, `z ≥ 0`, `wᵀz = 0` (the seed's eq. 50
//! writes `w − M z = b`: q = b).
//!
//! **Normal problem** (frictionless, displacement-driven: seed eq. 38 with no friction rows): `g = K f + q₀ ≥ 0 ⊥
//! f ≥ 0` with `q₀ = g₀ + Σ r_m ρ_m` over the prescribed rigid motions. **Load-driven** (seed §4.2, eqs. 39–49
//! without friction): every load-driven rigid DOF m (normal load P, moment M) has an unknown rigid displacement
//! ρ_m = u⁺_m − u⁻_m and two slack rows `v±_m` which, being ≥ 0 with opposite signs, enforce equilibrium
//! `a_mᵀ f = L_m`:
//!
//! ```text
//!   g    = K f + Σ_m r_m (u⁺_m − u⁻_m) + q₀        (r_m = the DOF's gap response)
//!   v⁺_m = −s_m (a_mᵀ f − L_m),   v⁻_m = s_m (a_mᵀ f − L_m)
//! ```
//!
//! with `a_P = 1`, `s_P = −1` (the approach mode moves contact nodes by −1 in y) and `a_M = x`, `s_M = +1` (the
//! rotation mode moves them by +x in y). The sign `s_m` is chosen so that `r_m ≈ s_m a_m`: the coupling terms are
//! skew and cancel in `zᵀMz`. The seed's printed eq. 49 puts `G_N` where its transpose belongs and flips signs in
//! the slack rows; the derivation above is ours, and the tests prove it by the residual of the physical
//! conditions (gap, complementarity, equilibrium) rather than of the LCP.
//!
//! **Frictional** ([`frictional_lcp`]): the seed's displacement (eq. 38), loading (eq. 49) or mixed LCP.
//! Friction law (seed eqs. 25–31, a two-sided pyramid in 2D): per contact node, `γ⁺ = μ f − h ≥ 0 ⊥ λ⁺ ≥ 0` and
//! `γ⁻ = μ f + h ≥ 0 ⊥ λ⁻ ≥ 0`, and the slip ([`super::slip`]) is `s = λ⁻ − λ⁺`: friction on the wheel opposes its
//! slip (h = +μf, γ⁺ = 0, goes with s = −λ⁺ ≤ 0). Elimination of the tangential forces (seed eqs. 35–37): with the
//! slip operator `s = D u_T + c` and `u_T = K_TN f + K_TT h + Σ_m r_T,m ρ_m`,
//!
//! ```text
//!   h = S (λ⁻ − λ⁺ − B f − Σ_m t_m ρ_m − c),   S = (D K_TT)⁻¹,  B = D K_TN,  t_m = D r_T,m
//! ```
//!
//! Writing ρ = ρ_D + E ρ_L (given plus load-driven components) makes h, the gap, γ± and the equilibrium residuals
//! affine functions of `x = [f; λ⁺; λ⁻; ρ_L]`; the LCP is assembled from those affine maps:
//!
//! ```text
//!   z = [f; λ⁺; λ⁻; u⁺; u⁻],   w = [g; γ⁺; γ⁻; v⁺; v⁻],   ρ_L = u⁺ − u⁻,
//!   v⁺_m = −s_m (a_Nᵀ f + a_Tᵀ h − L_m),   v⁻_m = s_m (a_Nᵀ f + a_Tᵀ h − L_m).
//! ```
//!
//! With no load-driven DOF this is the seed's eq. 38; with all three it is eq. 49, whose printed matrix has typos
//! (G_N for G_Nᵀ, signs in the slack rows): the blocks here are derived, not copied, and proved by the residuals of
//! the physical conditions. By Betti's theorem `K_NT ≈ K_TNᵀ` and `S ≈ Sᵀ` (static slip), so the f–λ coupling
//! blocks of M are skew and M is copositive (`zᵀMz = Schur-complement and S quadratic forms + μ(λ⁺ + λ⁻)ᵀf ≥ 0`)
//! but not copositive-plus: with f = 0 and λ⁺ = λ⁻ one has zᵀMz = 0 but (M + Mᵀ)z = 2μλ ≠ 0, whatever the slack
//! signs. Any signs give the same solution set — at a solution both slacks vanish — but they change Lemke's path;
//! the defaults ([`super::RigidDof::default_sign`]) are those that solved every case tried, and Lemke retries the
//! other patterns on a ray ([`crate::solvers::lemke`]).

use super::ContactProblem;
use crate::error::ArgumentError;
use faer::linalg::solvers::Solve;
use faer::Mat;

/// A linear complementarity problem `w = M z + q`, `w ≥ 0`, `z ≥ 0`, `wᵀz = 0`: M square and q of its size, by
/// construction ([`Lcp::new`]; read-only outside the crate, so every solver can index it).
#[derive(Debug, Clone)]
pub struct Lcp {
    /// The square matrix M (m × m).
    pub(crate) m: Mat<f64>,
    /// The vector q (length m).
    pub(crate) q: Vec<f64>,
}

impl Lcp {
    /// The LCP of M and q; refused, naming the argument, unless M is square and q has its size.
    pub fn new(m: Mat<f64>, q: Vec<f64>) -> Result<Lcp, ArgumentError> {
        if m.nrows() != m.ncols() {
            return Err(ArgumentError::new("Lcp::new", "m", format!("is {}×{}, not square", m.nrows(), m.ncols())));
        }
        if q.len() != m.nrows() {
            return Err(ArgumentError::new("Lcp::new", "q", format!("has {} entries, M {} rows", q.len(), m.nrows())));
        }
        Ok(Lcp { m, q })
    }

    /// The square matrix M (m × m).
    pub fn m(&self) -> &Mat<f64> {
        &self.m
    }

    /// The vector q (length m).
    pub fn q(&self) -> &[f64] {
        &self.q
    }

    /// Problem size m.
    pub fn size(&self) -> usize {
        self.q.len()
    }

    /// `w = M z + q` for a given `z` of the LCP's size (another size is refused).
    pub fn w_of(&self, z: &[f64]) -> Result<Vec<f64>, ArgumentError> {
        if z.len() != self.size() {
            return Err(ArgumentError::new(
                "Lcp::w_of",
                "z",
                format!("has {} entries, the LCP {}", z.len(), self.size()),
            ));
        }
        Ok(self.w_of_sized(z))
    }

    /// [`Lcp::w_of`] for a `z` the caller knows to have the LCP's size.
    pub(crate) fn w_of_sized(&self, z: &[f64]) -> Vec<f64> {
        let m = self.size();
        let mut w = self.q.clone();
        for (j, &zj) in z.iter().enumerate() {
            if zj != 0.0 {
                for (i, wi) in w.iter_mut().enumerate().take(m) {
                    *wi += self.m[(i, j)] * zj;
                }
            }
        }
        w
    }
}

/// The normal problem (frictionless, or the sliding limit): K and q₀. See the module docs.
pub(crate) fn normal_problem(p: &ContactProblem) -> super::NormalProblem {
    let flex = p.flex;
    let n = flex.n();
    let smu = p.limit_factor();
    let k = match (&flex.k_nt, smu != 0.0 && p.law.coupling) {
        (Some(nt), true) => Mat::from_fn(n, n, |i, j| flex.k_nn[(i, j)] + smu * nt[(i, j)]),
        _ => flex.k_nn.clone(),
    };
    let given = p.given();
    let q0: Vec<f64> =
        (0..n).map(|i| flex.g0[i] + p.dofs.iter().zip(&given).map(|(d, v)| d.gap[i] * v).sum::<f64>()).collect();
    super::NormalProblem { k, q0 }
}

/// The LCP of the normal problem. See the module docs.
pub(crate) fn normal_lcp(p: &ContactProblem, np: &super::NormalProblem) -> Lcp {
    let n = p.n();
    let smu = p.limit_factor();
    let (k, q0) = (&np.k, &np.q0);
    // Every DOF of `load_dofs` is load-driven.
    let loads: Vec<(&super::RigidDof, f64, f64)> =
        p.load_dofs().filter_map(|d| d.drive.load().map(|l| (d, d.default_sign(), l))).collect();
    let size = n + 2 * loads.len();
    let mut m = Mat::<f64>::zeros(size, size);
    let mut q = vec![0.0; size];
    for j in 0..n {
        for i in 0..n {
            m[(i, j)] = k[(i, j)];
        }
    }
    q[..n].copy_from_slice(q0);
    for (b, (d, sign, load)) in loads.iter().enumerate() {
        let (cp, cm) = (n + 2 * b, n + 2 * b + 1);
        for i in 0..n {
            let r = d.gap[i];
            // The resultant of h = σμ f adds σμ row_t to the row on f (the sliding limit's moment row x − σμy).
            let row = d.row_n[i] + smu * d.row_t[i];
            m[(i, cp)] = r;
            m[(i, cm)] = -r;
            m[(cp, i)] = -sign * row;
            m[(cm, i)] = sign * row;
        }
        q[cp] = sign * load;
        q[cm] = -sign * load;
    }
    Lcp { m, q }
}

/// The affine map of the tangential nodal forces of the frictional LCP: `h = h_0 + h_x x`, `x = [f; λ⁺; λ⁻; ρ_L]`.
#[derive(Debug, Clone)]
#[non_exhaustive]
pub struct TangentialMap {
    /// n × (3n + L).
    pub h_x: Mat<f64>,
    /// Constant part.
    pub h_0: Vec<f64>,
}

impl TangentialMap {
    /// h for the first 3n LCP unknowns `[f; λ⁺; λ⁻]` and the load-driven rigid displacements ρ_L.
    pub fn h(&self, z3n: &[f64], rho_l: &[f64]) -> Vec<f64> {
        let n = self.h_0.len();
        let x: Vec<f64> = z3n.iter().chain(rho_l).copied().collect();
        (0..n).map(|i| self.h_0[i] + (0..x.len()).map(|c| self.h_x[(i, c)] * x[c]).sum::<f64>()).collect()
    }
}

/// The frictional LCP with the tangential forces eliminated, and their affine map.
#[derive(Debug, Clone)]
#[non_exhaustive]
pub struct Frictional {
    /// The LCP, size 3n + 2L.
    pub lcp: Lcp,
    /// h as an affine map of the unknowns.
    pub map: TangentialMap,
}

/// Build the frictional LCP with slack signs `signs` (one per load-driven DOF, in [`ContactProblem::load_dofs`]
/// order); with `coupling = false` the cross blocks are dropped (K_NT = K_TN = 0). See the module docs. `None`
/// unless the problem is frictional ([`super::ProblemKind::Frictional`]: [`ContactProblem::new`] then checked that
/// the flexibility holds the blocks it needs) and `signs` has one sign per load-driven DOF.
pub fn frictional_lcp(p: &ContactProblem, signs: &[f64]) -> Option<Frictional> {
    if p.kind != super::ProblemKind::Frictional || signs.len() != p.load_dofs().count() {
        return None;
    }
    let flex = p.flex;
    let n = flex.n();
    let k_nt = match (&flex.k_nt, p.law.coupling) {
        (Some(k), true) => k.clone(),
        _ => Mat::zeros(n, n),
    };
    let nd = p.dofs.len();
    let r_n = Mat::from_fn(n, nd, |i, m| p.dofs[m].gap[i]);
    let given = p.given();
    let loads = load_rows(p, signs);
    let map = tangential_map(p, &loads, &given);
    let (g_x, g_0) = gap_map(p, &k_nt, &r_n, &map, &loads, &given);
    let (e_x, e_0) = equilibrium_map(&loads, &map);
    let nx = 3 * n + loads.len();
    // Rows g, γ⁺ = μ f − h, γ⁻ = μ f + h, then v⁺, v⁻ = ∓σ e for each load-driven DOF.
    let mu = p.law.friction;
    let mut rows: Vec<(Vec<f64>, f64)> = Vec::with_capacity(3 * n + 2 * loads.len());
    for i in 0..n {
        rows.push(((0..nx).map(|c| g_x[(i, c)]).collect(), g_0[i]));
    }
    let fmu = |i: usize, c: usize| if c == i { mu } else { 0.0 };
    for i in 0..n {
        rows.push(((0..nx).map(|c| fmu(i, c) - map.h_x[(i, c)]).collect(), -map.h_0[i]));
    }
    for i in 0..n {
        rows.push(((0..nx).map(|c| fmu(i, c) + map.h_x[(i, c)]).collect(), map.h_0[i]));
    }
    for (b, ld) in loads.iter().enumerate() {
        let sg = ld.sign;
        rows.push(((0..nx).map(|c| -sg * e_x[(b, c)]).collect(), -sg * e_0[b]));
        rows.push(((0..nx).map(|c| sg * e_x[(b, c)]).collect(), sg * e_0[b]));
    }
    Some(Frictional { lcp: assemble_split_columns(n, &rows), map })
}

/// A load-driven rigid DOF as the frictional LCP uses it.
struct LoadRow<'r> {
    /// Index of the DOF in [`ContactProblem::dofs`].
    dof: usize,
    /// Its equilibrium row on the normal forces f.
    row_n: &'r [f64],
    /// Its equilibrium row on the tangential forces h.
    row_t: &'r [f64],
    /// Slack sign σ of its rigid displacement.
    sign: f64,
    /// The prescribed load.
    load: f64,
}

/// The load-driven DOFs of `p`, in [`ContactProblem::load_dofs`] order, with their slack signs `signs`.
fn load_rows<'r>(p: &'r ContactProblem, signs: &[f64]) -> Vec<LoadRow<'r>> {
    p.dofs
        .iter()
        .enumerate()
        .filter(|(_, d)| p.is_unknown(d))
        .zip(signs)
        // An unknown DOF is load-driven.
        .filter_map(|((k, d), &s)| {
            let l = d.drive.load()?;
            Some(LoadRow { dof: k, row_n: d.row_n.as_slice(), row_t: d.row_t.as_slice(), sign: s, load: l })
        })
        .collect()
}

/// The tangential forces eliminated from the slip `s = D u_T + c = λ⁻ − λ⁺` (module docs):
/// `h = S (λ⁻ − λ⁺ − B f − Σ_m t_m ρ_m − c)` with `S = (D K_TT)⁻¹`, `B = D K_TN` (zero without coupling), as an
/// affine map of `x = [f; λ⁺; λ⁻; ρ_L]`; the displacement-driven part of ρ (`given`) goes into the constant.
fn tangential_map(p: &ContactProblem, loads: &[LoadRow<'_>], given: &[f64]) -> TangentialMap {
    let flex = p.flex;
    let n = flex.n();
    let a = p.slip.apply_mat(flex.k_tt.as_ref().expect("tangential blocks condensed"));
    let b = if p.law.coupling { p.slip.apply_mat(flex.k_tn.as_ref().expect("K_TN")) } else { Mat::zeros(n, n) };
    let nd = p.dofs.len();
    let r_t = Mat::from_fn(n, nd, |i, m| p.dofs[m].slip.as_ref().expect("tangential rigid responses")[i]);
    let nx = 3 * n + loads.len();
    // S = (D K_TT)⁻¹ and the affine map of h.
    let lu = a.partial_piv_lu();
    let s = lu.solve(Mat::<f64>::identity(n, n));
    let sk = &s * &b;
    let sr = &s * &r_t;
    let sc: Option<Vec<f64>> =
        p.slip.offset.as_ref().map(|c| (0..n).map(|i| (0..n).map(|j| s[(i, j)] * c[j]).sum()).collect());
    let mut h_x = Mat::<f64>::zeros(n, nx);
    let mut h_0 = vec![0.0; n];
    for i in 0..n {
        for j in 0..n {
            h_x[(i, j)] = -sk[(i, j)];
            h_x[(i, n + j)] = -s[(i, j)];
            h_x[(i, 2 * n + j)] = s[(i, j)];
        }
        for (b, ld) in loads.iter().enumerate() {
            h_x[(i, 3 * n + b)] = -sr[(i, ld.dof)];
        }
        h_0[i] = -(0..nd).map(|m| sr[(i, m)] * given[m]).sum::<f64>();
        if let Some(sc) = &sc {
            h_0[i] -= sc[i];
        }
    }
    TangentialMap { h_x, h_0 }
}

/// The gap as an affine map `g = g_x x + g_0` of the unknowns: g = g0 + R_N (ρ_D + E ρ_L) + K_NN f + K_NT h.
fn gap_map(
    p: &ContactProblem,
    k_nt: &Mat<f64>,
    r_n: &Mat<f64>,
    map: &TangentialMap,
    loads: &[LoadRow<'_>],
    given: &[f64],
) -> (Mat<f64>, Vec<f64>) {
    let flex = p.flex;
    let (n, nd) = (flex.n(), p.dofs.len());
    let k_nn = &flex.k_nn;
    let mut g_x = k_nt * &map.h_x;
    for i in 0..n {
        for j in 0..n {
            g_x[(i, j)] += k_nn[(i, j)];
        }
        for (b, ld) in loads.iter().enumerate() {
            g_x[(i, 3 * n + b)] += r_n[(i, ld.dof)];
        }
    }
    let g_0: Vec<f64> = (0..n)
        .map(|i| {
            flex.g0[i]
                + (0..nd).map(|m| r_n[(i, m)] * given[m]).sum::<f64>()
                + (0..n).map(|j| k_nt[(i, j)] * map.h_0[j]).sum::<f64>()
        })
        .collect();
    (g_x, g_0)
}

/// The equilibrium residuals of the load-driven DOFs as an affine map `e = e_x x + e_0` of the unknowns:
/// e_m = a_Nᵀ f + a_Tᵀ h − L_m.
fn equilibrium_map(loads: &[LoadRow<'_>], map: &TangentialMap) -> (Mat<f64>, Vec<f64>) {
    let n = map.h_0.len();
    let (nl, nx) = (loads.len(), map.h_x.ncols());
    let mut e_x = Mat::<f64>::zeros(nl, nx);
    let mut e_0 = vec![0.0; nl];
    for (b, ld) in loads.iter().enumerate() {
        for c in 0..nx {
            let mut v: f64 = (0..n).map(|i| ld.row_t[i] * map.h_x[(i, c)]).sum();
            if c < n {
                v += ld.row_n[c];
            }
            e_x[(b, c)] = v;
        }
        e_0[b] = (0..n).map(|i| ld.row_t[i] * map.h_0[i]).sum::<f64>() - ld.load;
    }
    (e_x, e_0)
}

/// The LCP of the rows `(coefficients on x, constant)`: the columns of x become columns of z, the first 3n one to
/// one, each load-driven ρ_L split into u⁺ − u⁻ (two columns, the second with the opposite sign).
fn assemble_split_columns(n: usize, rows: &[(Vec<f64>, f64)]) -> Lcp {
    let size = rows.len();
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
    for (row, (coef, c0)) in rows.iter().enumerate() {
        for (c, &v) in coef.iter().enumerate() {
            let (cp, cm) = zcol(c);
            m[(row, cp)] = v;
            if let Some(cm) = cm {
                m[(row, cm)] = -v;
            }
        }
        q[row] = *c0;
    }
    Lcp { m, q }
}
