//! # Dense formulations on small grids: the 3D normal and shift problems by Lemke and clarabel
//!
//! The cross-checks of the scalable solvers ([`super::normal`] and the tangential solver to come): each problem is
//! written out with the dense influence matrices of a small grid ([`Influence::dense`], at most
//! [`super::DENSE_LIMIT`] elements) and handed to a general-purpose solver — Lemke's method
//! ([`crate::solvers::lemke`]) for the linear complementarity problems, clarabel's interior-point method for the
//! convex programs (a QP with the non-negative cone for the normal problem, second-order cones for the Coulomb
//! disc). Nothing here is fast: Lemke costs O(m²) per pivot on an `m`-row LCP and clarabel factorises a dense KKT
//! system. What it gives is a second, independent answer on the same discretisation.
//!
//! Signs are [`super::kernel`]'s: `z` into body 1, pressure `p > 0` in compression, shears `q_x`, `q_y` on body 1
//! along `+x`, `+y`, displacements of body 1 relative to body 2 (slip along `x`, `y`; the gap change along `z`,
//! positive when the surfaces move apart). Elements are indexed `i = ix + MX·iy`; `A = DX·DY` is one element's
//! area. Pressures and shears in stress units, gaps, approaches, shifts and slips in length units, forces in
//! stress × length².
//!
//! ## 1. The normal problem, frictionless
//!
//! With `h_i` the initial separation of the surfaces at the centre of element `i` (length; any sign, negative where
//! they would interpenetrate), `d` the approach of the bodies (length, positive pressing them together) and `C` the
//! dense `C_zz` (gap change per unit pressure, symmetric positive definite):
//!
//! ```text
//! g = h − d·1 + C p,      p ≥ 0,   g ≥ 0,   pᵀ g = 0          (every element)
//! ```
//!
//! either with `d` prescribed ([`NormalDrive::Approach`]) or with the load `P = A Σ p` prescribed
//! ([`NormalDrive::Load`], `d` unknown). Two formulations:
//!
//! - **Lemke** ([`DenseNormal::lemke`]). Approach prescribed: the LCP `w = C p + (h − d) ⊥ p`. Load prescribed: the
//!   load row is added with the approach as its complementary variable, shifted to be non-negative,
//!   `d' = d − min h`:
//!
//!   ```text
//!   z = (p, d'),   w = [ C  −1 ] z + [ h − min h ] ,     i.e.  w_p = g,   w_d = Σ p − P/A.
//!                      [ 1ᵀ  0 ]     [  −P/A     ]
//!   ```
//!
//!   The matrix is positive semi-definite (C positive definite, the border skew), so Lemke either solves the LCP or
//!   proves it infeasible. For `P > 0` a solution has `d' > 0` (at `d' = 0` the right-hand side `h − min h ≥ 0`
//!   gives `p = 0`, which leaves `w_d = −P/A < 0`), hence `Σ p = P/A`; and `d ≥ min h` holds at any solution
//!   with contact (a contacting element has `d = h_i + (Cp)_i ≥ h_i`), so the shift loses nothing. `P = 0` gives
//!   `p = 0`, `d = min h` (touching); `P < 0` has no solution ([`DenseStatus::Infeasible`]).
//! - **clarabel's QP** ([`DenseNormal::clarabel`], through [`crate::solvers::clarabel_qp::solve_frictionless`]):
//!   `min ½ pᵀCp + (h − d)ᵀp` over `p ≥ 0` (approach prescribed), or `min ½ pᵀCp + hᵀp` over `p ≥ 0`,
//!   `Σ p = P/A` (load prescribed), whose KKT conditions are the LCP above; the multiplier of the equality is the
//!   approach. The active-set polish of that solver then makes the answer exact on its active set.
//!
//! ## 2. The shift problem: the tangential problem at given pressure
//!
//! Kalker's "shift" (quasi-static, one load step): the pressure `p` is given (e.g. from 1.) and held; the elements
//! in contact are `S = {i : p_i > 0}`. With `q′` the shears of the previous state (zero for the first step) and
//! `w = (w_x, w_y)` the rigid shift of body 1 relative to body 2 during the step (length), the slip of element `i`
//! during the step is
//!
//! ```text
//! s_i = w + [C_tt (q − q′)]_i          (2-vectors; C_tt the 2 × 2-block operator of C_xx, C_xy = C_yx, C_yy)
//! ```
//!
//! and Coulomb's law on the disc `D_i = {|q_i| ≤ μ p_i}` holds at every `i ∈ S`:
//!
//! ```text
//! |q_i| ≤ μ p_i,     |q_i| < μ p_i ⇒ s_i = 0,     s_i ≠ 0 ⇒ q_i = −μ p_i s_i/|s_i|
//! ```
//!
//! (the friction on body 1 opposes its slip). Outside `S` the shears vanish and no slip is defined (reported 0).
//! Either `w` is prescribed ([`ShiftDrive::Shift`]) or the total force `F = A Σ q` on body 1
//! ([`ShiftDrive::Force`], `w` unknown).
//!
//! **Coupling.** The normal–tangential coupling `C_tz`, `C_zt` is left out (Kalker's β = 0). For identical materials
//! it vanishes identically. For a dissimilar pair, at a pressure held during the step the coupling term of the slip,
//! `C_tz (p − p′)`, vanishes too; what is neglected is the effect of the shears on the pressure (`C_zt q`) and the
//! shears the normal loading itself induces (Spence's problem). The dense tangential blocks are those of the
//! [`Influence`] (which must hold [`super::Kernels::Full`]); its coupling kernels, if any, are not used.
//!
//! ### 2a. The disc exactly, by clarabel with second-order cones ([`DenseShift::disc`])
//!
//! The shift problem is the optimality system of the convex program
//!
//! ```text
//! min  ½ (q − q′)ᵀ C_tt (q − q′) + wᵀ Σ_{i∈S} q_i     over   q_i ∈ D_i  (i ∈ S),   q_i = 0  (i ∉ S)
//! ```
//!
//! whose gradient is `w + C_tt (q − q′) = s`: stationarity reads `s_i ∈ −N_{D_i}(q_i)` (the normal cone), which is
//! exactly the law above. Each disc is the second-order cone `(μ p_i, q_x,i, q_y,i) ∈ SOC(3)`. With the force
//! prescribed, `w` is dropped from the objective and the equality `A Σ q = F` added; if `λ` is its multiplier in
//! `L = f(q) + λᵀ(Σ q − F/A)`, stationarity is `C_tt (q − q′) + λ = s`, so the shift is `w = λ`. In clarabel's form
//! (`min ½xᵀPx + cᵀx`, `Ax + s = b`, `s ∈ K`, dual `z`, `Px + c + Aᵀz = 0`) with the scaled unknowns
//! `x = q/σ` (`σ = μ max p`), `P = C_tt/κ` (`κ` the largest diagonal entry of `C_tt` on `S`), the equality rows
//! `Σ x = F/(Aσ)` and the cone rows `s = (μp_i/σ, x_i)`: `w = σκ z_eq` and the slip is `s_i = σκ z_i` (the dual's
//! last two components in the cone of element `i`). Tested: the `w` so found, prescribed, gives back `F` and the
//! same shears (test `disc_optimality_and_the_force_multiplier_is_the_shift`). The slip reported is recomputed from
//! the primal, `s = w + C_tt(q − q′)`, not read from the dual.
//!
//! ### 2b. The pyramid with k facets, by Lemke ([`DenseShift::pyramid`])
//!
//! The disc is replaced by the regular polygon INSCRIBED in it: vertices `μ p_i e_m`, `e_m = (cos θ_m, sin θ_m)`,
//! `θ_m = 2πm/k` (a vertex on `±x`, and on `±y` when 4 divides k). Inscribed, so that every admissible traction is
//! also admissible for the disc (the pyramid never transmits more than Coulomb allows) and the vertex formulation
//! below needs no scaling; its facets lie at `μ p_i cos(π/k)` from the centre, so the traction bound is low by at
//! most the factor `1 − cos(π/k) ≈ π²/(2k²)`, where the friction direction falls mid-facet; a slipping element's
//! traction sits at a vertex (or on a facet), so its direction is off by up to `π/k` ("Measured" below). With
//! `q_i = Σ_m β_im e_m` (`β ≥ 0`) and the slip magnitude `γ_i` (Stewart–Trinkle's polyhedral law; Klarbring's
//! for the static case):
//!
//! ```text
//! e_mᵀ s_i + γ_i ≥ 0  ⊥  β_im ≥ 0,        μ p_i − Σ_m β_im ≥ 0  ⊥  γ_i ≥ 0
//! ```
//!
//! A slipping element (`γ_i > 0`) lies on the polygon's boundary and its friction uses the vertices most opposed to
//! its slip; a sticking one has `e_mᵀ s_i ≥ −γ_i = 0` for all m, i.e. `s_i = 0` (k ≥ 3 directions span the plane).
//! With `s = w + C_tt E β − C_tt q′` (E the block-diagonal matrix of the e_m) the LCP in `z = (β, γ)` has the
//! matrix `[[Eᵀ C_tt E, Γ], [−Γᵀ, 0]]` (Γ sums the facets of one element), positive semi-definite. With the force
//! prescribed the shift is free, `w = u⁺ − u⁻`, `u± ≥ 0`, complementary to `±(F/A − Σ q) ≥ 0`: four more rows and
//! columns, borders skew, so the matrix stays positive semi-definite and Lemke's ray proves that no admissible
//! tractions carry F (outside μP times the polygon: [`DenseStatus::GrossSliding`]). The LCP has
//! `(k + 1)·|S| (+ 4)` rows, dense: at most [`PYRAMID_LCP_LIMIT`].
//!
//! ### What is reported ([`ShiftSolution`])
//!
//! The shears and the slips per element, the shift and the total force, the stick set (`i ∈ S` with the traction
//! strictly inside its friction set: `|q_i| < (1 − τ) μ p_i` for the disc, inside the polygon shrunk by `1 − τ` for
//! the pyramid, τ = [`STICK_TOLERANCE`]), and the residual of the DISC law whatever the formulation:
//!
//! ```text
//! r = max_{i∈S} |q_i − Π_{D_i}(q_i − s_i/c₀)| / (μ max p)
//! ```
//!
//! (`Π_D` the projection on the disc, `c₀` the largest diagonal entry of `C_tt`, the slip of an element per unit
//! shear: the fixed-point form of Coulomb's law, zero exactly when the law holds; in traction units relative to
//! `μ max p`). For the pyramid it measures how far its answer is from the disc law.
//!
//! ## Measured (the tests in `dense/tests.rs`; release build, 2 shared cores; times are wall clock of one run)
//!
//! Steel pair (`E = 210 000` MPa both, no coupling), `P = 1 000` N, `μ = 0.3`, grids `m × m` over ±1.2 semi-axes.
//!
//! **Normal, against Hertz** (Johnson §4.2; ν = 0.3; relative errors; the semi-axes from the pressure's second
//! moments, `⟨x²⟩ = a²/5`; "L2" the pressure's relative L2 error at the centres):
//!
//! | case | grid (across) | p0 | approach | a | b | p L2 | Lemke pivots, s |
//! |---|---|---|---|---|---|---|---|
//! | circle | 15² (12.5) | 1.6e-3 | 6.4e-4 | 2.2e-3 | 2.2e-3 | 2.1e-2 | 131, 0.003 |
//! | circle | 25² (20.8) | 2.7e-4 | 5.3e-4 | 2.9e-4 | 2.9e-4 | 1.8e-2 | 351, 0.02 |
//! | B/A = 3 (a/b = 2.07) | 15² | 1.6e-3 | 6.2e-4 | 2.1e-3 | 2.3e-3 | 2.1e-2 | 131, 0.003 |
//! | B/A = 3 | 25² | 2.5e-4 | 5.3e-4 | 2.2e-4 | 3.4e-4 | 1.7e-2 | 351, 0.02 |
//!
//! (at 35² = 1 225 elements, 29 across, a one-off run: p0 1.3e-4, approach 2.7e-4, a 1.9e-4.) Lemke and clarabel
//! (10 iterations, polished) agree to 1e-13 of p0; clarabel's dense QP takes 0.02 s at 225 elements, 0.3 s at 625
//! and 2 s at 1 225, Lemke 0.003, 0.02 and 0.25 s.
//!
//! **Cattaneo–Mindlin** (ν = 0, `Q = 0.5 μP`, the disc): stick radius (from the stick set's area) 2.4e-2 and
//! 1.5e-2, traction max-norm 6.9e-2 and 4.6e-2 of μp0 (the slope of the traction is singular at r = c: first order
//! at best), traction L2 6.1e-2 and 4.2e-2, the shift against Mindlin's 2.8e-3 and 1.1e-4, at 15² and 25²;
//! clarabel 9–11 iterations, 0.06 and 0.4 s. Unloading to `0.2 μP` from `0.6 μP` against Mindlin–Deresiewicz:
//! traction max 1.2e-1 and 6.7e-2, L2 1.8e-1 and 9.8e-2 (of a smaller traction); two loading steps equal one to
//! 2e-11 μp0.
//!
//! **The pyramid against the disc** (11², ν = 0.3, 69 elements in contact, force `0.6 μP` at 30°; relative to μP,
//! μp0, μp0 and the disc's shift):
//!
//! | k | LCP rows | force | traction max | disc residual | shift (force-driven) | pivots (shift / force), s |
//! |---:|---:|---:|---:|---:|---:|---|
//! | 4 | 345 | 3.7e-2 | 1.7e-1 | 1.9e-1 | 9.0e-2 | 175 / 197, 0.01 |
//! | 8 | 621 | 9.8e-3 | 7.4e-2 | 8.1e-2 | 1.8e-2 | 169 / 183, 0.02 |
//! | 16 | 1 173 | 2.9e-3 | 3.7e-2 | 4.0e-2 | 5.1e-3 | 175 / 323, 0.06 |
//! | 32 | 2 277 | 2.3e-4 | 2.2e-2 | 2.1e-2 | 4.7e-4 | 169 / 519, 0.16–0.19 |
//!
//! Fitted orders in k: force −2.4, shift −2.5 (the set's error `1 − cos(π/k) ~ k⁻²`), tractions and disc residual
//! −1.0: a vertex traction's direction is quantised to `π/k`, so the per-element answer converges at first order
//! only, while the totals, averaged over the patch, converge at second. The disc by clarabel on the same problem:
//! 10 iterations, 0.04 s, disc residual 2e-7, force exact to 1e-12. To reach 1e-3 of μP in the total force the
//! pyramid needs k = 32 here (k = 16: 2.9e-3); the disc gets there in fewer seconds on this grid. Lemke's pivots
//! hardly grow with k when the shift is prescribed (169–175), but each pivot costs O(rows²) on the dense matrix,
//! and the rows grow as `(k + 1)|S|`: the pyramid tests stay at 69 elements in contact for that reason.

use super::{ContactGrid, Influence};
use crate::error::ArgumentError;
use crate::formulation::Lcp;
use crate::solvers::clarabel_qp::{self, QpSettings, QpStatus};
use crate::solvers::lemke::{self, LemkeSettings};
use crate::status::Termination;
use clarabel::algebra::CscMatrix;
use clarabel::solver::{
    DefaultSolver, IPSolver, SolverStatus,
    SupportedConeT::{self, SecondOrderConeT, ZeroConeT},
};
use faer::Mat;
use std::f64::consts::PI;
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::time::Instant;

/// Relative margin τ of the stick set: an element in contact sticks when its traction lies inside its friction set
/// shrunk by the factor `1 − τ` (`|q| < (1 − τ) μ p` for the disc). 1e-6: an interior-point answer approaches the
/// boundary of a disc only to its tolerance (module docs, "What is reported").
pub const STICK_TOLERANCE: f64 = 1e-6;

/// The largest pyramid LCP ([`DenseShift::pyramid`]) formed: 16 384 rows, a dense matrix of 2 GiB.
pub const PYRAMID_LCP_LIMIT: usize = 16_384;

/// How a dense solve ended.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub enum DenseStatus {
    /// Solved to the solver's tolerance (Lemke: exactly, up to round-off).
    Solved,
    /// The normal problem has no solution: a negative (tensile) load prescribed.
    Infeasible,
    /// The prescribed tangential force exceeds what the friction set carries (`|F| > μP` for the disc; outside
    /// `μP` times the inscribed polygon for the pyramid): the bodies slide as a whole, no finite shift exists.
    GrossSliding,
    /// The solver's iteration or pivot limit was reached; the answer is its last iterate.
    NotConverged,
    /// The solver failed numerically (or ended where its theory says it cannot); the message says how.
    NumericalError,
}

impl DenseStatus {
    /// The name used in messages and reports.
    pub fn name(self) -> &'static str {
        match self {
            DenseStatus::Solved => "solved",
            DenseStatus::Infeasible => "infeasible",
            DenseStatus::GrossSliding => "gross_sliding",
            DenseStatus::NotConverged => "not_converged",
            DenseStatus::NumericalError => "numerical_error",
        }
    }

    /// Whether the answer is a solution.
    pub fn is_solved(self) -> bool {
        self == DenseStatus::Solved
    }
}

/// The harness's terminations: gross sliding is an infeasible problem.
impl From<DenseStatus> for Termination {
    fn from(s: DenseStatus) -> Termination {
        match s {
            DenseStatus::Solved => Termination::Solved,
            DenseStatus::Infeasible | DenseStatus::GrossSliding => Termination::Infeasible,
            DenseStatus::NotConverged => Termination::NotConverged,
            DenseStatus::NumericalError => Termination::NumericalError,
        }
    }
}

/// Settings of the second-order-cone solve ([`DenseShift::disc`]).
#[derive(Clone, Copy, Debug, PartialEq)]
#[non_exhaustive]
pub struct ConeSettings {
    /// clarabel's gap and feasibility tolerances (dimensionless, on the scaled problem). Default 1e-12 (1e-10 left a
    /// disc residual of 1e-6 on the 11 × 11 test grid; 1e-12 converges in 9–11 iterations there, 2e-7).
    pub tolerance: f64,
    /// Interior-point iteration limit. Default 200.
    pub max_iter: u32,
}

impl Default for ConeSettings {
    fn default() -> ConeSettings {
        ConeSettings { tolerance: 1e-12, max_iter: 200 }
    }
}

impl ConeSettings {
    /// Settings with the tolerance `tolerance` (finite, in `(0, 0.1]`) and the limit `max_iter` (≥ 1).
    ///
    /// # Errors
    /// An [`ArgumentError`] naming the argument out of range.
    pub fn new(tolerance: f64, max_iter: u32) -> Result<ConeSettings, ArgumentError> {
        if !(tolerance > 0.0 && tolerance <= 0.1) {
            return Err(ArgumentError::new(
                "ConeSettings::new",
                "tolerance",
                format!("must be in (0, 0.1], got {tolerance}"),
            ));
        }
        if max_iter == 0 {
            return Err(ArgumentError::new("ConeSettings::new", "max_iter", "must be at least 1, got 0"));
        }
        Ok(ConeSettings { tolerance, max_iter })
    }
}

// ---------------------------------------------------------------------------------------------------------------
// 1. The normal problem
// ---------------------------------------------------------------------------------------------------------------

/// What drives the normal problem.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum NormalDrive {
    /// The approach `d` (length, positive pressing the bodies together) prescribed.
    Approach(f64),
    /// The load `P = A Σ p` (force, positive in compression) prescribed; the approach is an unknown.
    Load(f64),
}

/// The frictionless normal problem of a small grid with its dense `C_zz` (module docs, section 1).
#[derive(Clone, Debug)]
pub struct DenseNormal {
    grid: ContactGrid,
    czz: Vec<f64>,
    h: Vec<f64>,
}

/// The answer to a dense normal problem.
#[derive(Clone, Debug)]
#[non_exhaustive]
pub struct NormalSolution {
    /// Pressure per element (stress, ≥ 0, compression positive), grid order.
    pub pressure: Vec<f64>,
    /// Gap per element `h − d + C_zz p` (length, ≥ 0), grid order.
    pub gap: Vec<f64>,
    /// The approach `d` (length; prescribed or found).
    pub approach: f64,
    /// The load `A Σ p` (force; prescribed or found).
    pub load: f64,
    /// Elements carrying pressure (`p > 0`).
    pub contact: Vec<bool>,
    /// Residual of the contact conditions: the largest of `max_i |min(p_i/p̄, g_i/ḡ)|` (`p̄ = max p`, `ḡ` the largest
    /// `|C_zz p|`: negative values, violated complementarity) and, with the load prescribed, `|A Σ p − P|/P`.
    pub residual: f64,
    /// How the solve ended.
    pub status: DenseStatus,
    /// Lemke's pivots or clarabel's interior-point iterations.
    pub iterations: usize,
    /// Wall-clock time of the solve proper (s), building the dense problem included.
    pub seconds: f64,
    /// The solver's own words.
    pub message: String,
}

impl DenseNormal {
    /// The normal problem of `influence`'s grid (at most [`super::DENSE_LIMIT`] elements) with the initial
    /// separation `separation` (length, one finite value per element, grid order; e.g. `A x² + B y²` by
    /// [`ContactGrid::sample`]).
    ///
    /// # Errors
    /// An [`ArgumentError`] when the grid is too large for a dense matrix or the separation is not one finite value
    /// per element.
    pub fn new(influence: &Influence, separation: &[f64]) -> Result<DenseNormal, ArgumentError> {
        let grid = *influence.grid();
        check_field("DenseNormal::new", "separation", separation, grid.len())?;
        let czz = influence.dense(|c| c.zz)?;
        Ok(DenseNormal { grid, czz, h: separation.to_vec() })
    }

    /// The grid.
    pub fn grid(&self) -> &ContactGrid {
        &self.grid
    }

    /// The gap `h − d + C_zz p` (length) of the pressure `pressure` (stress, one per element) at the approach
    /// `approach` (length).
    ///
    /// # Errors
    /// An [`ArgumentError`] when the pressure is not one finite value per element or the approach is not finite.
    pub fn gap(&self, pressure: &[f64], approach: f64) -> Result<Vec<f64>, ArgumentError> {
        check_field("DenseNormal::gap", "pressure", pressure, self.grid.len())?;
        check_finite("DenseNormal::gap", "approach", approach)?;
        Ok(self.gap_of(pressure, approach))
    }

    fn gap_of(&self, p: &[f64], d: f64) -> Vec<f64> {
        let n = self.grid.len();
        (0..n).map(|i| self.h[i] - d + dot(&self.czz[i * n..(i + 1) * n], p)).collect()
    }

    /// Solve by Lemke's method (module docs, section 1: the LCP, bordered by the load row when the load is
    /// prescribed).
    ///
    /// # Errors
    /// An [`ArgumentError`] when the drive's value is not finite. A negative load is [`DenseStatus::Infeasible`].
    pub fn lemke(&self, drive: NormalDrive, settings: &LemkeSettings) -> Result<NormalSolution, ArgumentError> {
        let start = Instant::now();
        check_drive("DenseNormal::lemke", drive)?;
        let n = self.grid.len();
        let hmin = self.h.iter().fold(f64::INFINITY, |m, &v| m.min(v));
        let (lcp, offset) = match drive {
            NormalDrive::Approach(d) => {
                let m = Mat::from_fn(n, n, |i, j| self.czz[i * n + j]);
                (Lcp::new(m, self.h.iter().map(|h| h - d).collect()), 0.0)
            }
            NormalDrive::Load(load) if load < 0.0 => {
                let msg = format!("a tensile load P = {load} has no compressive solution");
                return Ok(self.finish(vec![0.0; n], hmin, drive, DenseStatus::Infeasible, 0, start, msg));
            }
            NormalDrive::Load(load) => {
                let m = Mat::from_fn(n + 1, n + 1, |i, j| match (i < n, j < n) {
                    (true, true) => self.czz[i * n + j],
                    (true, false) => -1.0,
                    (false, true) => 1.0,
                    (false, false) => 0.0,
                });
                let mut q: Vec<f64> = self.h.iter().map(|h| h - hmin).collect();
                q.push(-load / self.grid.area());
                (Lcp::new(m, q), hmin)
            }
        };
        let out = lemke::solve(&lcp?, settings);
        let status = match out.status {
            Termination::Solved => DenseStatus::Solved,
            Termination::NotConverged => DenseStatus::NotConverged,
            // A positive semi-definite LCP ends on a ray only when it is infeasible, which a load ≥ 0 is not.
            _ => DenseStatus::NumericalError,
        };
        let approach = match drive {
            NormalDrive::Approach(d) => d,
            NormalDrive::Load(_) => offset + out.z[n],
        };
        let p = out.z[..n].iter().map(|v| v.max(0.0)).collect();
        let msg = format!("Lemke: {}", out.message);
        Ok(self.finish(p, approach, drive, status, out.pivots, start, msg))
    }

    /// Solve by clarabel's interior-point method on the QP (module docs, section 1), with the active-set polish of
    /// [`clarabel_qp::solve_frictionless`] when `settings.polish`.
    ///
    /// # Errors
    /// An [`ArgumentError`] when the drive's value is not finite. A negative load is [`DenseStatus::Infeasible`].
    pub fn clarabel(&self, drive: NormalDrive, settings: &QpSettings) -> Result<NormalSolution, ArgumentError> {
        let start = Instant::now();
        check_drive("DenseNormal::clarabel", drive)?;
        let n = self.grid.len();
        let ones = vec![1.0; n];
        let out = match drive {
            NormalDrive::Approach(d) => {
                let c: Vec<f64> = self.h.iter().map(|h| h - d).collect();
                clarabel_qp::solve_frictionless(&self.czz, n, &c, None, settings)
            }
            NormalDrive::Load(load) => {
                let per_area = load / self.grid.area();
                clarabel_qp::solve_frictionless(&self.czz, n, &self.h, Some((&ones, per_area)), settings)
            }
        };
        let status = match &out.status {
            QpStatus::Solved | QpStatus::AlmostSolved => DenseStatus::Solved,
            QpStatus::MaxIterations => DenseStatus::NotConverged,
            QpStatus::Infeasible => DenseStatus::Infeasible,
            _ => DenseStatus::NumericalError,
        };
        let approach = match drive {
            NormalDrive::Approach(d) => d,
            NormalDrive::Load(_) => out.approach.unwrap_or(f64::NAN),
        };
        let msg = format!("clarabel: {} (polished: {})", out.status, out.polished);
        Ok(self.finish(out.f, approach, drive, status, out.iterations as usize, start, msg))
    }

    /// The solution record of the pressure `p` at the approach `d`, with its residual.
    #[allow(clippy::too_many_arguments)]
    fn finish(
        &self,
        p: Vec<f64>,
        d: f64,
        drive: NormalDrive,
        status: DenseStatus,
        iterations: usize,
        start: Instant,
        message: String,
    ) -> NormalSolution {
        let gap = self.gap_of(&p, d);
        let load = self.grid.area() * p.iter().sum::<f64>();
        let pbar = positive_or(p.iter().fold(0.0_f64, |m, v| m.max(v.abs())), 1.0);
        let gbar = positive_or(gap.iter().zip(&self.h).fold(0.0_f64, |m, (g, h)| m.max((g - h + d).abs())), 1.0);
        let mut residual = p.iter().zip(&gap).fold(0.0_f64, |m, (pi, gi)| m.max((pi / pbar).min(gi / gbar).abs()));
        if let NormalDrive::Load(target) = drive {
            if target > 0.0 {
                residual = residual.max((load - target).abs() / target);
            }
        }
        let contact = p.iter().map(|&v| v > 0.0).collect();
        let seconds = start.elapsed().as_secs_f64();
        NormalSolution { pressure: p, gap, approach: d, load, contact, residual, status, iterations, seconds, message }
    }
}

// ---------------------------------------------------------------------------------------------------------------
// 2. The shift problem
// ---------------------------------------------------------------------------------------------------------------

/// What drives the shift problem.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum ShiftDrive {
    /// The rigid shift `w = (w_x, w_y)` of body 1 relative to body 2 during the step (length) prescribed.
    Shift([f64; 2]),
    /// The total tangential force `F = A Σ q` on body 1 (force, along `+x`, `+y`) prescribed; the shift is an
    /// unknown.
    Force([f64; 2]),
}

/// The shift problem of a small grid at a given pressure (module docs, section 2): the dense `C_tt` on the elements
/// in contact, the pressure, the friction coefficient and the previous shears.
#[derive(Clone, Debug)]
pub struct DenseShift {
    grid: ContactGrid,
    mu: f64,
    pressure: Vec<f64>,
    /// The elements in contact (`p > 0`), ascending.
    active: Vec<usize>,
    /// `C_tt` on the elements in contact, row-major `2|S| × 2|S|`, unknowns interleaved `(q_x, q_y)` per element.
    ctt: Vec<f64>,
    /// `[C_tt q′]` on the elements in contact, interleaved.
    memory: Vec<f64>,
    /// The largest diagonal entry of `ctt` (slip per unit shear), 1 when nothing is in contact.
    c0: f64,
}

/// The answer to a dense shift problem.
#[derive(Clone, Debug)]
#[non_exhaustive]
pub struct ShiftSolution {
    /// Shear `q_x` per element (stress, on body 1 along `+x`), grid order; 0 out of contact.
    pub qx: Vec<f64>,
    /// Shear `q_y` per element (stress, along `+y`).
    pub qy: Vec<f64>,
    /// Slip `s_x` during the step per element (length, body 1 relative to body 2), `w + [C_tt(q − q′)]_x`; 0 out of
    /// contact.
    pub sx: Vec<f64>,
    /// Slip `s_y` during the step per element (length).
    pub sy: Vec<f64>,
    /// The shift `w` (length; prescribed or found).
    pub shift: [f64; 2],
    /// The total force `A Σ q` on body 1 (force).
    pub force: [f64; 2],
    /// Elements in contact whose traction lies strictly inside the friction set (by [`STICK_TOLERANCE`]).
    pub stick: Vec<bool>,
    /// The residual of the DISC law `max |q − Π_D(q − s/c₀)|/(μ max p)` (module docs), whatever the formulation.
    pub disc_residual: f64,
    /// How the solve ended.
    pub status: DenseStatus,
    /// clarabel's interior-point iterations or Lemke's pivots.
    pub iterations: usize,
    /// Wall-clock time (s) of building and solving the problem.
    pub seconds: f64,
    /// The solver's own words.
    pub message: String,
}

/// A raw answer on the contact set before it is spread over the grid.
struct Raw {
    q: Vec<f64>,
    shift: [f64; 2],
    status: DenseStatus,
    iterations: usize,
    message: String,
}

impl DenseShift {
    /// The shift problem of `influence` (built with [`super::Kernels::Full`], at most [`super::DENSE_LIMIT`]
    /// elements) at the pressure `pressure` (stress, ≥ 0, one per element), the friction coefficient `mu` (> 0,
    /// finite) and the previous shears `previous = (q′_x, q′_y)` (stress, one per element; `None`: zero).
    ///
    /// # Errors
    /// An [`ArgumentError`] naming the argument: no tangential kernels, a grid too large, a pressure negative or not
    /// finite, `mu` out of range, previous shears of the wrong length or not finite.
    pub fn new(
        influence: &Influence,
        pressure: &[f64],
        mu: f64,
        previous: Option<(&[f64], &[f64])>,
    ) -> Result<DenseShift, ArgumentError> {
        const F: &str = "DenseShift::new";
        let grid = *influence.grid();
        let n = grid.len();
        if !influence.has_tangential() {
            return Err(ArgumentError::new(F, "influence", "built with Kernels::Normal: no tangential kernels"));
        }
        check_field(F, "pressure", pressure, n)?;
        if let Some(v) = pressure.iter().find(|v| **v < 0.0) {
            return Err(ArgumentError::new(F, "pressure", format!("must be ≥ 0 everywhere, got {v}")));
        }
        if !(mu > 0.0 && mu.is_finite()) {
            return Err(ArgumentError::new(
                F,
                "mu",
                format!("(friction coefficient) must be finite and > 0, got {mu}"),
            ));
        }
        if let Some((px, py)) = previous {
            check_field(F, "previous", px, n)?;
            check_field(F, "previous", py, n)?;
        }
        let [xx, xy, yy] = [influence.dense(|c| c.xx)?, influence.dense(|c| c.xy)?, influence.dense(|c| c.yy)?];
        let active: Vec<usize> = (0..n).filter(|&i| pressure[i] > 0.0).collect();
        let ns = active.len();
        let block = |i: usize, j: usize| [[xx[i * n + j], xy[i * n + j]], [xy[i * n + j], yy[i * n + j]]];
        let mut ctt = vec![0.0; 4 * ns * ns];
        for (a, &i) in active.iter().enumerate() {
            for (b, &j) in active.iter().enumerate() {
                let c = block(i, j);
                for (r, row) in c.iter().enumerate() {
                    for (s, v) in row.iter().enumerate() {
                        ctt[(2 * a + r) * 2 * ns + 2 * b + s] = *v;
                    }
                }
            }
        }
        let mut memory = vec![0.0; 2 * ns];
        if let Some((px, py)) = previous {
            for (a, &i) in active.iter().enumerate() {
                let row = |m: &[f64], v: &[f64]| dot(&m[i * n..(i + 1) * n], v);
                memory[2 * a] = row(&xx, px) + row(&xy, py);
                memory[2 * a + 1] = row(&xy, px) + row(&yy, py);
            }
        }
        let c0 = positive_or((0..2 * ns).fold(0.0_f64, |m, r| m.max(ctt[r * 2 * ns + r])), 1.0);
        Ok(DenseShift { grid, mu, pressure: pressure.to_vec(), active, ctt, memory, c0 })
    }

    /// The grid.
    pub fn grid(&self) -> &ContactGrid {
        &self.grid
    }

    /// The elements in contact (`p > 0`), ascending grid indices.
    pub fn contact(&self) -> &[usize] {
        &self.active
    }

    /// The normal load `P = A Σ p` (force) of the given pressure.
    pub fn load(&self) -> f64 {
        self.grid.area() * self.pressure.iter().sum::<f64>()
    }

    /// The disc exactly, by clarabel with one second-order cone per element in contact (module docs, 2a).
    ///
    /// # Errors
    /// An [`ArgumentError`] when the drive's values are not finite. A force above `μP` is
    /// [`DenseStatus::GrossSliding`].
    pub fn disc(&self, drive: ShiftDrive, settings: &ConeSettings) -> Result<ShiftSolution, ArgumentError> {
        let start = Instant::now();
        check_shift_drive("DenseShift::disc", drive)?;
        let raw = match drive {
            ShiftDrive::Force(f) if norm(f) > self.mu * self.load() => gross(f, self.mu * self.load(), "the disc"),
            _ if self.active.is_empty() => self.nothing_in_contact(drive),
            _ => self.disc_solve(drive, settings),
        };
        Ok(self.finish(raw, None, start))
    }

    /// The pyramid of `facets` facets (the inscribed regular polygon; 3 ≤ `facets` ≤ 1024) as an LCP solved by
    /// Lemke (module docs, 2b).
    ///
    /// # Errors
    /// An [`ArgumentError`] when `facets` is out of range, the drive's values are not finite or the LCP would have
    /// more than [`PYRAMID_LCP_LIMIT`] rows. A force outside `μP` times the polygon is
    /// [`DenseStatus::GrossSliding`].
    pub fn pyramid(
        &self,
        facets: usize,
        drive: ShiftDrive,
        settings: &LemkeSettings,
    ) -> Result<ShiftSolution, ArgumentError> {
        const F: &str = "DenseShift::pyramid";
        let start = Instant::now();
        if !(3..=1024).contains(&facets) {
            return Err(ArgumentError::new(F, "facets", format!("must be 3 ..= 1024, got {facets}")));
        }
        check_shift_drive(F, drive)?;
        let rows = (facets + 1) * self.active.len() + if matches!(drive, ShiftDrive::Force(_)) { 4 } else { 0 };
        if rows > PYRAMID_LCP_LIMIT {
            let msg = format!("{rows} LCP rows ({} elements in contact) exceed {PYRAMID_LCP_LIMIT}", self.active.len());
            return Err(ArgumentError::new(F, "facets", msg));
        }
        let raw = match drive {
            ShiftDrive::Force(f) if polygon_gauge(f, self.mu * self.load(), facets) > 1.0 => {
                gross(f, self.mu * self.load(), &format!("the {facets}-gon"))
            }
            _ if self.active.is_empty() => self.nothing_in_contact(drive),
            _ => self.pyramid_solve(facets, drive, settings),
        };
        Ok(self.finish(raw, Some(facets), start))
    }

    /// No element in contact: no shear; a zero force leaves the shift undetermined (reported 0).
    fn nothing_in_contact(&self, drive: ShiftDrive) -> Raw {
        let (shift, message) = match drive {
            ShiftDrive::Shift(w) => (w, "no element in contact: no shear".to_string()),
            ShiftDrive::Force(_) => ([0.0; 2], "no element in contact: zero force, the shift is undetermined".into()),
        };
        Raw { q: Vec::new(), shift, status: DenseStatus::Solved, iterations: 0, message }
    }

    /// `C_tt q − [C_tt q′] + w` on the contact set, interleaved.
    fn slip_of(&self, q: &[f64], w: [f64; 2]) -> Vec<f64> {
        let m = 2 * self.active.len();
        (0..m).map(|r| dot(&self.ctt[r * m..(r + 1) * m], q) - self.memory[r] + w[r % 2]).collect()
    }

    /// Clarabel's data and solve for the disc (module docs, 2a).
    fn disc_solve(&self, drive: ShiftDrive, settings: &ConeSettings) -> Raw {
        let ns = self.active.len();
        let m = 2 * ns;
        let pmax = self.active.iter().fold(0.0_f64, |a, &i| a.max(self.pressure[i]));
        let (sigma, kappa) = (self.mu * pmax, self.c0);
        // P: the upper triangle of C_tt/κ, column by column.
        let (mut colptr, mut rowval, mut nzval) = (vec![0], Vec::new(), Vec::new());
        for j in 0..m {
            for i in 0..=j {
                rowval.push(i);
                nzval.push(self.ctt[i * m + j] / kappa);
            }
            colptr.push(rowval.len());
        }
        let p_mat = CscMatrix::new(m, m, colptr, rowval, nzval);
        let w = if let ShiftDrive::Shift(w) = drive { w } else { [0.0; 2] };
        let c: Vec<f64> = (0..m).map(|r| (w[r % 2] - self.memory[r]) / (sigma * kappa)).collect();
        let force = if let ShiftDrive::Force(f) = drive { Some(f) } else { None };
        let rows = 3 * ns + if force.is_some() { 2 } else { 0 };
        let (mut colptr, mut rowval, mut nzval) = (vec![0], Vec::new(), Vec::new());
        for j in 0..m {
            rowval.push(3 * (j / 2) + 1 + j % 2);
            nzval.push(-1.0);
            if force.is_some() {
                rowval.push(3 * ns + j % 2);
                nzval.push(1.0);
            }
            colptr.push(rowval.len());
        }
        let a_mat = CscMatrix::new(rows, m, colptr, rowval, nzval);
        let mut b = vec![0.0; rows];
        for (a, &i) in self.active.iter().enumerate() {
            b[3 * a] = self.mu * self.pressure[i] / sigma;
        }
        let mut cones: Vec<SupportedConeT<f64>> = vec![SecondOrderConeT(3); ns];
        if let Some(f) = force {
            b[3 * ns] = f[0] / (self.grid.area() * sigma);
            b[3 * ns + 1] = f[1] / (self.grid.area() * sigma);
            cones.push(ZeroConeT(2));
        }
        let (x, z, status, iterations) = match run_clarabel(&p_mat, &c, &a_mat, &b, &cones, settings) {
            Ok(r) => r,
            Err(message) => {
                return Raw { q: vec![0.0; m], shift: w, status: DenseStatus::NumericalError, iterations: 0, message }
            }
        };
        let shift = if force.is_some() { [sigma * kappa * z[3 * ns], sigma * kappa * z[3 * ns + 1]] } else { w };
        let (status, message) = match status {
            SolverStatus::Solved | SolverStatus::AlmostSolved => (DenseStatus::Solved, format!("clarabel: {status:?}")),
            SolverStatus::MaxIterations | SolverStatus::MaxTime => (DenseStatus::NotConverged, format!("{status:?}")),
            SolverStatus::PrimalInfeasible | SolverStatus::AlmostPrimalInfeasible if force.is_some() => {
                (DenseStatus::GrossSliding, format!("clarabel: {status:?} (no admissible shears carry F)"))
            }
            other => (DenseStatus::NumericalError, format!("clarabel: {other:?}")),
        };
        Raw { q: x.iter().map(|v| sigma * v).collect(), shift, status, iterations: iterations as usize, message }
    }

    /// The pyramid LCP (module docs, 2b) solved by Lemke.
    fn pyramid_solve(&self, k: usize, drive: ShiftDrive, settings: &LemkeSettings) -> Raw {
        let ns = self.active.len();
        let m2 = 2 * ns;
        let nb = k * ns;
        let free = matches!(drive, ShiftDrive::Force(_));
        let size = nb + ns + if free { 4 } else { 0 };
        let e: Vec<[f64; 2]> = (0..k).map(|j| vertex(j, k)).collect();
        // (C_tt E) column by column: the slip of element rows per unit β_jl.
        let ce = Mat::from_fn(m2, nb, |r, col| {
            let (jb, l) = (col / k, col % k);
            self.ctt[r * m2 + 2 * jb] * e[l][0] + self.ctt[r * m2 + 2 * jb + 1] * e[l][1]
        });
        let area = self.grid.area();
        let entry = |row: usize, col: usize| -> f64 {
            if row < nb {
                let (i, mm) = (row / k, row % k);
                if col < nb {
                    e[mm][0] * ce[(2 * i, col)] + e[mm][1] * ce[(2 * i + 1, col)]
                } else if col < nb + ns {
                    f64::from(col - nb == i)
                } else {
                    let c = (col - nb - ns) % 2;
                    if col - nb - ns < 2 {
                        e[mm][c]
                    } else {
                        -e[mm][c]
                    }
                }
            } else if row < nb + ns {
                if col < nb && col / k == row - nb {
                    -1.0
                } else {
                    0.0
                }
            } else if col < nb {
                let c = (row - nb - ns) % 2;
                let sign = if row - nb - ns < 2 { -1.0 } else { 1.0 };
                sign * e[col % k][c]
            } else {
                0.0
            }
        };
        let mat = Mat::from_fn(size, size, entry);
        let w = if let ShiftDrive::Shift(w) = drive { w } else { [0.0; 2] };
        let mut q = vec![0.0; size];
        for (row, qr) in q.iter_mut().enumerate().take(nb) {
            let (i, mm) = (row / k, row % k);
            *qr = e[mm][0] * (w[0] - self.memory[2 * i]) + e[mm][1] * (w[1] - self.memory[2 * i + 1]);
        }
        for (a, &i) in self.active.iter().enumerate() {
            q[nb + a] = self.mu * self.pressure[i];
        }
        if let ShiftDrive::Force(f) = drive {
            for c in 0..2 {
                q[nb + ns + c] = f[c] / area;
                q[nb + ns + 2 + c] = -f[c] / area;
            }
        }
        let lcp = match Lcp::new(mat, q) {
            Ok(l) => l,
            Err(e) => {
                return Raw {
                    q: vec![0.0; m2],
                    shift: w,
                    status: DenseStatus::NumericalError,
                    iterations: 0,
                    message: e.to_string(),
                }
            }
        };
        let out = lemke::solve(&lcp, settings);
        let mut qs = vec![0.0; m2];
        for i in 0..ns {
            for (mm, ev) in e.iter().enumerate() {
                let beta = out.z[i * k + mm].max(0.0);
                qs[2 * i] += beta * ev[0];
                qs[2 * i + 1] += beta * ev[1];
            }
        }
        let shift = if free { [out.z[size - 4] - out.z[size - 2], out.z[size - 3] - out.z[size - 1]] } else { w };
        let status = match out.status {
            Termination::Solved => DenseStatus::Solved,
            Termination::NotConverged => DenseStatus::NotConverged,
            // Positive semi-definite: a ray proves that no admissible shears carry F.
            Termination::RayTermination if free => DenseStatus::GrossSliding,
            _ => DenseStatus::NumericalError,
        };
        Raw { q: qs, shift, status, iterations: out.pivots, message: format!("Lemke ({size} rows): {}", out.message) }
    }

    /// Spread a raw answer over the grid: slips, force, stick set (the disc's, or the `facets`-gon's), residual.
    fn finish(&self, raw: Raw, facets: Option<usize>, start: Instant) -> ShiftSolution {
        let n = self.grid.len();
        let (mut qx, mut qy, mut sx, mut sy) = (vec![0.0; n], vec![0.0; n], vec![0.0; n], vec![0.0; n]);
        let mut stick = vec![false; n];
        let q = if raw.q.len() == 2 * self.active.len() { raw.q } else { vec![0.0; 2 * self.active.len()] };
        let s = self.slip_of(&q, raw.shift);
        let pmax = self.active.iter().fold(0.0_f64, |a, &i| a.max(self.pressure[i]));
        let scale = positive_or(self.mu * pmax, 1.0);
        let mut residual = 0.0_f64;
        for (a, &i) in self.active.iter().enumerate() {
            let (qi, si) = ([q[2 * a], q[2 * a + 1]], [s[2 * a], s[2 * a + 1]]);
            (qx[i], qy[i], sx[i], sy[i]) = (qi[0], qi[1], si[0], si[1]);
            let bound = self.mu * self.pressure[i];
            let gauge = match facets {
                None => norm(qi) / bound,
                Some(k) => polygon_gauge(qi, bound, k),
            };
            stick[i] = gauge < 1.0 - STICK_TOLERANCE;
            let r = super::tangential::disc_law_residual((qi[0], qi[1]), (si[0], si[1]), bound, self.c0);
            residual = residual.max(r / scale);
        }
        let area = self.grid.area();
        let force = [area * qx.iter().sum::<f64>(), area * qy.iter().sum::<f64>()];
        ShiftSolution {
            qx,
            qy,
            sx,
            sy,
            shift: raw.shift,
            force,
            stick,
            disc_residual: residual,
            status: raw.status,
            iterations: raw.iterations,
            seconds: start.elapsed().as_secs_f64(),
            message: raw.message,
        }
    }
}

/// The outcome of a force no admissible shears carry.
fn gross(f: [f64; 2], capacity: f64, set: &str) -> Raw {
    let message = format!("gross sliding: |F| = {:e} exceeds what {set} carries (μP = {capacity:e})", norm(f));
    Raw { q: Vec::new(), shift: [0.0; 2], status: DenseStatus::GrossSliding, iterations: 0, message }
}

/// clarabel's solution `(x, z, status, iterations)` of `min ½xᵀPx + cᵀx`, `Ax + s = b`, `s ∈ cones`; a setup error
/// or a panic as a message.
fn run_clarabel(
    p: &CscMatrix<f64>,
    c: &[f64],
    a: &CscMatrix<f64>,
    b: &[f64],
    cones: &[SupportedConeT<f64>],
    s: &ConeSettings,
) -> Result<(Vec<f64>, Vec<f64>, SolverStatus, u32), String> {
    let qp = QpSettings { tolerance: s.tolerance, max_iter: s.max_iter, polish: false };
    let settings = clarabel_qp::clarabel_settings(&qp)?;
    let run = catch_unwind(AssertUnwindSafe(|| {
        let mut solver = DefaultSolver::new(p, c, a, b, cones, settings).map_err(|e| format!("clarabel setup: {e}"))?;
        solver.solve();
        let sol = &solver.solution;
        Ok::<_, String>((sol.x.clone(), sol.z.clone(), sol.status, sol.iterations))
    }));
    run.unwrap_or_else(|_| Err("clarabel panicked".into()))
}

/// The unit vector of vertex `j` of the regular `k`-gon: angle `2πj/k`.
fn vertex(j: usize, k: usize) -> [f64; 2] {
    let t = 2.0 * PI * j as f64 / k as f64;
    [t.cos(), t.sin()]
}

/// The gauge of `q` in the regular `k`-gon of circumradius `r` with a vertex on `+x` (module docs, 2b): the largest
/// `n_m · q/(r cos(π/k))` over the facet normals `n_m` at angles `(2m + 1)π/k`; ≤ 1 inside. `+∞` for `r = 0`, `q ≠ 0`.
fn polygon_gauge(q: [f64; 2], r: f64, k: usize) -> f64 {
    let inradius = r * (PI / k as f64).cos();
    let support = (0..k).fold(f64::NEG_INFINITY, |m, j| {
        let t = (2 * j + 1) as f64 * PI / k as f64;
        m.max(t.cos() * q[0] + t.sin() * q[1])
    });
    if support <= 0.0 {
        0.0
    } else {
        support / inradius
    }
}

fn norm(v: [f64; 2]) -> f64 {
    v[0].hypot(v[1])
}

fn dot(a: &[f64], b: &[f64]) -> f64 {
    a.iter().zip(b).map(|(x, y)| x * y).sum()
}

fn positive_or(v: f64, fallback: f64) -> f64 {
    if v > 0.0 && v.is_finite() {
        v
    } else {
        fallback
    }
}

fn check_finite(function: &'static str, argument: &'static str, v: f64) -> Result<(), ArgumentError> {
    if v.is_finite() {
        Ok(())
    } else {
        Err(ArgumentError::new(function, argument, format!("must be finite, got {v}")))
    }
}

fn check_field(function: &'static str, argument: &'static str, v: &[f64], n: usize) -> Result<(), ArgumentError> {
    if v.len() != n {
        return Err(ArgumentError::new(function, argument, format!("has {} values, the grid {n} elements", v.len())));
    }
    match v.iter().find(|x| !x.is_finite()) {
        Some(x) => Err(ArgumentError::new(function, argument, format!("must be finite everywhere, got {x}"))),
        None => Ok(()),
    }
}

fn check_drive(function: &'static str, drive: NormalDrive) -> Result<(), ArgumentError> {
    match drive {
        NormalDrive::Approach(d) => check_finite(function, "drive", d),
        NormalDrive::Load(p) => check_finite(function, "drive", p),
    }
}

fn check_shift_drive(function: &'static str, drive: ShiftDrive) -> Result<(), ArgumentError> {
    match drive {
        ShiftDrive::Shift(v) | ShiftDrive::Force(v) => {
            check_finite(function, "drive", v[0])?;
            check_finite(function, "drive", v[1])
        }
    }
}

#[cfg(test)]
mod tests;
