//! # Elastic half-space: surface influence coefficients of uniformly loaded rectangles
//!
//! Kalker's (and CONTACT's) 3D discretisation of a contact area: rectangles `DX × DY` carrying piecewise-constant
//! tractions, displacements at the element centres. This module gives the nine influence coefficients of ONE
//! rectangle at ANY surface point, in closed form, for one half-space or for a pair of them, and the kernel of a
//! uniform grid as a function of the index offsets only (block-Toeplitz: a later 2D FFT product needs nothing else).
//! It generalises the centre-line integrals of [`crate::halfplane`]'s "Strip of half-spaces" (`I1`, `I2`, `I3`) to
//! an arbitrary observation point.
//!
//! ## Axes, signs, units
//!
//! The body occupies `z > 0`: `x`, `y` run along the surface, `z` is the depth INTO the body (as in
//! [`crate::halfplane`]). Tractions act ON the body: pressure `p` along `+z` (pushing into it), shears `q_x`, `q_y`
//! along `+x`, `+y`. Displacements `u_x`, `u_y` along `+x`, `+y` and `u_z` along `+z` (into the body). A coefficient
//! `C_ab` is the displacement `u_a` at the observation point per unit uniform traction `b` on the rectangle
//! (`a, b ∈ {x, y, z}`, traction `z` = pressure): units of length per unit stress (m/Pa with lengths in m and
//! stresses in Pa). So `u_x = C_xx q_x + C_xy q_y + C_xz p`, `u_y = C_yx q_x + C_yy q_y + C_yz p`,
//! `u_z = C_zx q_x + C_zy q_y + C_zz p`. Displacements are absolute: they vanish far from the load (no datum, unlike
//! plane strain).
//!
//! ## Point loads (Boussinesq, Cerruti)
//!
//! With `G = E/(2(1+ν))`, `K = 1/(2πG) = (1+ν)/(πE)`, a point force at the surface point `(ξ, η)` and the
//! observation point `(x, y)` on the surface, `X = x − ξ`, `Y = y − η`, `ρ² = X² + Y²`:
//!
//! ```text
//! pressure P:   u_z = (1−ν) K P / ρ,                u_x = −(1−2ν) K P X/(2ρ²),   u_y = −(1−2ν) K P Y/(2ρ²)
//! shear Q_x:    u_x = K Q_x [(1−ν)/ρ + ν X²/ρ³],    u_y = ν K Q_x XY/ρ³,         u_z = +(1−2ν) K Q_x X/(2ρ²)
//! shear Q_y:    u_y = K Q_y [(1−ν)/ρ + ν Y²/ρ³],    u_x = ν K Q_y XY/ρ³,         u_z = +(1−2ν) K Q_y Y/(2ρ²)
//! ```
//!
//! Where each comes from (K.L. Johnson, *Contact Mechanics*, CUP 1985, ch. 3; the equation numbers are those
//! [`crate::halfplane`] cites): Boussinesq's normal force, eq. 3.19 — `u_z = (1−ν²)P/(πEρ) = (1−ν)KP/ρ` and the
//! radial `u_r = −(1−2ν)(1+ν)P/(2πEρ) = −(1−2ν)KP/(2ρ)`, whose components are `u_r X/ρ`, `u_r Y/ρ` (surface points
//! move TOWARDS the load). Cerruti's tangential force, eqs. 3.86–3.87, at `z = 0`:
//! `u_x = Q/(4πG)·[1/ρ + X²/ρ³ + (1−2ν)(1/ρ − X²/ρ³)]`, `u_y = Q/(4πG)·[XY/ρ³ − (1−2ν)XY/ρ³]`,
//! `u_z = Q/(4πG)·(1−2ν)X/ρ²`, which are the lines above. The signs agree with [`crate::halfplane`]'s strip section
//! (its `C_zx = −C_xz = (1−2ν)K I3/2`) and with Betti's theorem: the `u_x` at A of a pressure at B equals the `u_z` at
//! B of a shear `Q_x` at A (`X` changes sign between the two), and `Q_y`'s field is `Q_x`'s with `x ↔ y`.
//!
//! ## Rectangles
//!
//! Rectangle `[x1, x2] × [y1, y2]`, centre `(x_c, y_c)`, half-sides `α = (x2−x1)/2`, `β = (y2−y1)/2`; observation
//! point `(x, y)`, `x0 = x − x_c`, `y0 = y − y_c`. Over the rectangle `X = x − ξ` runs over `[a2, a1]` and `Y` over
//! `[b2, b1]`, with `a1 = x0 + α`, `a2 = x0 − α`, `b1 = y0 + β`, `b2 = y0 − β`. An antiderivative `F` with
//! `∂²F/∂X∂Y = f` integrates `f` over the rectangle as the double difference
//! `ΔΔF = F(a1,b1) − F(a2,b1) − F(a1,b2) + F(a2,b2)`; a term of `F` depending on `X` alone or on `Y` alone drops out.
//! The five integrals and their antiderivatives (each checked by differentiation):
//!
//! ```text
//! J_xx = ∬ X²/ρ³   F = Y asinh(X/|Y|)                 (∂_Y(Y/ρ) = X²/ρ³, ∫ Y/ρ dX = Y ln(X+ρ), minus Y ln|Y|)
//! J_yy = ∬ Y²/ρ³   F = X asinh(Y/|X|)
//! I1   = ∬ 1/ρ     = J_xx + J_yy,   F = X asinh(Y/|X|) + Y asinh(X/|Y|)   (= X ln(Y+ρ) + Y ln(X+ρ) − X ln|X| − Y ln|Y|)
//! J_xy = ∬ XY/ρ³   F = −ρ
//! K_x  = ∬ X/ρ²    F = Y ln ρ + X atan(Y/X)           (∂_X F = atan(Y/X); the −Y of ∫ ln ρ dY dropped)
//! K_y  = ∬ Y/ρ²    F = X ln ρ + Y atan(X/Y)
//! ```
//!
//! (`F` is continuous everywhere: `0·ln 0 = 0`, `X asinh(Y/|X|) → 0` and `X atan(Y/X) → 0` as `X → 0`, so edges and
//! corners need no special case in the mathematics, only in the arithmetic.) On the centre line of a strip
//! (`y0 = 0`, `β = w/2`) they are [`crate::halfplane`]'s `I1 = I1`, `I2 = J_xx`, `I3 = K_x`. The coefficients of one
//! body:
//!
//! ```text
//! C_zz = (1−ν)K I1,   C_xx = (1−ν)K I1 + νK J_xx,   C_yy = (1−ν)K I1 + νK J_yy,   C_xy = C_yx = νK J_xy,
//! C_zx = −C_xz = (1−2ν)K K_x / 2,                    C_zy = −C_yz = (1−2ν)K K_y / 2.
//! ```
//!
//! At the centre of the rectangle `I1 = 4[α asinh(β/α) + β asinh(α/β)]`, so
//! `u_z = (1−ν²)p/(πE) · [2L1 ln((L2 + √(L1²+L2²))/L1) + 2L2 ln((L1 + √(L1²+L2²))/L2)]` for SIDES `L1 = 2α`,
//! `L2 = 2β`: Love's (1929) centre deflection, `1.1222 (1−ν²) p L/E` for a square of side `L` (tested).
//!
//! ## Evaluation without cancellation
//!
//! Parity first: `I1`, `J_xx`, `J_yy` are even in `x0` and in `y0`, `J_xy` odd in both, `K_x` odd in `x0` and even in
//! `y0`, `K_y` the reverse. They are evaluated at `(|x0|, |y0|)` and the signs applied after, so the coefficients
//! have these symmetries exactly. Lengths are divided by a power of two near `max(α, β)` (exact) so that no
//! intermediate over- or underflows. Then, with `x0, y0 ≥ 0`, `a1 > 0` and `b1 > 0` always.
//!
//! The plain double difference of `F` loses `(R/size)²` of its digits at a distance `R`: the four values are of
//! order `R ln R`, the result of order `αβ/R`. Here each one-dimensional difference that can cancel is done
//! analytically instead, using only the exact data `a1 − a2 = 2α`, `a1 + a2 = 2x0`, `a1² − a2² = 4αx0` (and the same
//! in `y`), never the rounded difference of two nearly equal values. "Far in x" below means `x0 ≥ 3α` (the point
//! lies at least one element length beyond the element's `x` range; the identities hold whenever `a2 > 0`, the
//! margin keeps every denominator away from zero); nearer, the plain differences lose at most a factor ~3.
//!
//! - `J_xx`. With `D_k = asinh(a1/|b_k|) − asinh(a2/|b_k|)`, `J_xx = b1 D1 − b2 D2`. Far in x, by
//!   `asinh u − asinh v = asinh(u√(1+v²) − v√(1+u²))`: `D_k = asinh(4αx0/d_k)`, `d_k = a1 ρ(a2,b_k) + a2 ρ(a1,b_k)`.
//!   Far in y: `J_xx = β(D1 + D2) + y0 (D1 − D2)`, with `D1 − D2` again one `asinh`: far in x from
//!   `u1 − u2 = 4αx0 (d2 − d1)/(d1 d2)`, `d2 − d1 = −4βy0 [a1/(ρ(a2,b1) + ρ(a2,b2)) + a2/(ρ(a1,b1) + ρ(a1,b2))]`;
//!   otherwise as `e(a1) − e(a2)`, `e(t) = asinh(t/b1) − asinh(t/b2) = asinh(−4βy0 t/((ρ(t,b1) + ρ(t,b2)) b1 b2))`.
//!   `b·asinh(a/|b|)` is `0` at `b = 0` and taken as `b(ln 2 + ln|a| − ln|b|)` where `a/b` could overflow.
//!   `J_yy` is `J_xx` with `x ↔ y`.
//! - `J_xy = 16αβ x0 y0 [1/(ρ11 + ρ21) + 1/(ρ12 + ρ22)] / ((ρ11 + ρ12)(ρ21 + ρ22))`, `ρ_ik = ρ(a_i, b_k)`, from
//!   `ρ_i1 − ρ_i2 = 4βy0/(ρ_i1 + ρ_i2)` and the same in `x`: every term positive, exact everywhere (no case).
//! - `K_x = T1 + T2`, `T1 = ΔΔ[Y ln ρ] = b1 λ1 − b2 λ2`, `λ_k = ln(ρ1k/ρ2k) = ½ ln_1p(4αx0/ρ2k²)` (the plain
//!   ratio where that argument exceeds ½); far in y `T1 = β(λ1 + λ2) + y0 (λ1 − λ2)`,
//!   `λ1 − λ2 = ½ ln_1p(−16αβ x0 y0/(ρ21 ρ12)²)` (from `ρ11²ρ22² − ρ21²ρ12² = −(a1² − a2²)(b1² − b2²)`).
//!   `T2 = ΔΔ[X atan(Y/X)] = H(a1) − H(a2)`, `H(t) = |t| φ(|t|)`, `φ(t) = atan2(2βt, t² + b1 b2)` (the angle the
//!   segment `b2..b1` subtends; `H(0) = 0`); far in x `T2 = α(φ1 + φ2) + x0 (φ1 − φ2)` with
//!   `φ1 − φ2 = atan2(4αβ (b1 b2 − a1 a2), (a1² + b1 b2)(a2² + b1 b2) + 4β² a1 a2)` (the argument of
//!   `(a1² + b1b2 + 2iβa1)·conj(a2² + b1b2 + 2iβa2)`). `K_y` is `K_x` with `x ↔ y`.
//!
//! The terms that remain to be added can still partly cancel, but only where the result is small against the
//! coefficient's natural scale `S = αβ/R` (e.g. `J_xx ≈ 4αβ x0²/R³` straight above the element): the absolute error
//! is then a few ulps of `S`, not of the result. Beyond `R = 10⁸ max(α, β)` the point load times the area is used:
//! the next term of the expansion, `(α² ∂²_X + β² ∂²_Y) f/6` relative, is below `10⁻¹⁶` there.
//!
//! ## A pair of half-spaces
//!
//! Body 1 occupies `z > 0` as above; body 2 (the counter-body) occupies `z < 0` and is described by the same
//! formulas in its mirrored frame `x' = x`, `y' = y`, `z' = −z` (isotropic elasticity is invariant under the
//! reflection; the point-load fields contain no cross product). Newton's third law: body 2 receives
//! `(−q_x, −q_y, −p)` in global components, i.e. shears `q' = −q` and pressure `p' = +p` (still pushing into it) in
//! its frame; its displacement in global components is `(u'_x, u'_y, −u'_z)`. As in [`crate::halfplane`]'s
//! counter-body section, slip `s = u_t,1 − u_t,2` and gap change `g = u_z,1 + u'_z,2` (both surfaces moving away
//! from each other open the gap) give
//!
//! ```text
//! s_x = (C_xx + C'_xx) q_x + (C_xy + C'_xy) q_y + (C_xz − C'_xz) p        (and s_y alike)
//! g   = (C_zx − C'_zx) q_x + (C_zy − C'_zy) q_y + (C_zz + C'_zz) p
//! ```
//!
//! So the direct coefficients add and the coupling ones subtract: the pair is this module's formulas with the
//! constants `k_d = (1−ν1)K1 + (1−ν2)K2` (of `I1`), `k_ν = ν1 K1 + ν2 K2` (of `J`) and
//! `k_c = [(1−2ν1)K1 − (1−2ν2)K2]/2 = [(1−2ν1)/G1 − (1−2ν2)/G2]/(4π)` (of `K_x`, `K_y`): the Dundurs-type factor,
//! `k_c = β k_d` with Dundurs' `β` ([`crate::material::dundurs_beta`], body 1 first). Identical materials give
//! `k_c = 0` exactly, hence coupling coefficients exactly `0`. One body alone is the pair with a rigid counter-body
//! (`K2 = 0`); a rigid body (`E = ∞`) has `K = 0` and no displacement.
//!
//! ## A uniform grid
//!
//! `MX × MY` elements `DX × DY`; element `(ix, iy)` has its centre at `(ix·DX, iy·DY)` plus a common origin. The
//! coefficient of element `j` at the centre of element `i` depends on the offsets `di = ix_i − ix_j`,
//! `dj = iy_i − iy_j` only: `x0 = di·DX`, `y0 = dj·DY`, `α = DX/2`, `β = DY/2` ([`UniformGrid::kernel`]). That is
//! the block-Toeplitz structure: `(2MX−1)(2MY−1)` values per coefficient, which the parities above reduce to the
//! `MX·MY` of one quadrant ([`KernelTable`]). `x0 = di·DX` is one rounding of exact data and `α = DX/2` is exact,
//! so the kernel is as accurate as the integrals themselves.
//!
//! ## Accuracy and cost (measured; tests in this file)
//!
//! Against an independent adaptive Gauss–Legendre quadrature of the point-load formulas (inside, on edges, at
//! corners, near and up to 10⁴ element sizes away; aspects 1/10..10; ν = 0, 0.3, 0.5), every coefficient agrees to
//! ≤ 3e-14 of the natural scale `S` (the largest direct coefficient at that point), and to ≤ 1e-13 relative where
//! it is not small against `S`. The plain double difference of `F` would lose 2e-8 of `S` at 10⁴ sizes. Building the
//! kernel quadrant of a 100 × 100 grid (10⁴ offsets, 6 coefficients each) is the criterion
//! benchmark `halfspace/kernel_table_100x100` (`benches/physics.rs`).
//!
//! ## References
//!
//! K.L. Johnson, *Contact Mechanics*, CUP 1985, ch. 3 (Boussinesq and Cerruti point loads). A.E.H. Love, "The
//! stress produced in a semi-infinite solid by pressure on part of the boundary", Phil. Trans. R. Soc. A 228 (1929)
//! 377–420 (the uniformly loaded rectangle). J.J. Kalker, *Three-Dimensional Elastic Bodies in Rolling Contact*,
//! Kluwer 1990 (the discretisation by rectangles, collocation at the element centres).

use crate::error::ArgumentError;
use std::f64::consts::{LN_2, PI};

/// The nine surface influence coefficients of one uniformly loaded rectangle at one surface point: the displacement
/// `u_a` per unit traction `b`, in length per unit stress (e.g. m/Pa). First letter the displacement, second the
/// traction (`z`: the pressure, positive INTO the body; `x`, `y`: the shears along `+x`, `+y`); module docs, "Axes,
/// signs, units". For a pair of bodies ([`HalfSpace::pair`]) the displacements are body 1's relative to body 2's:
/// slip `u_x`, `u_y` and gap change `u_z` (positive when the surfaces move apart).
#[derive(Clone, Copy, Debug, PartialEq, Default)]
#[non_exhaustive]
pub struct Coefficients {
    /// `u_x` per unit shear `q_x`.
    pub xx: f64,
    /// `u_x` per unit shear `q_y` (equal to `yx`).
    pub xy: f64,
    /// `u_x` per unit pressure `p` (`= −zx`).
    pub xz: f64,
    /// `u_y` per unit shear `q_x` (equal to `xy`).
    pub yx: f64,
    /// `u_y` per unit shear `q_y`.
    pub yy: f64,
    /// `u_y` per unit pressure `p` (`= −zy`).
    pub yz: f64,
    /// `u_z` per unit shear `q_x` (`= (1−2ν)K K_x/2` for one body).
    pub zx: f64,
    /// `u_z` per unit shear `q_y`.
    pub zy: f64,
    /// `u_z` per unit pressure `p` (`= (1−ν)K I1` for one body).
    pub zz: f64,
}

impl Coefficients {
    /// The coefficients as a 3 × 3 matrix: rows the displacements `(u_x, u_y, u_z)`, columns the tractions
    /// `(q_x, q_y, p)`, so that `u = M t`.
    pub fn matrix(&self) -> [[f64; 3]; 3] {
        [[self.xx, self.xy, self.xz], [self.yx, self.yy, self.yz], [self.zx, self.zy, self.zz]]
    }
}

/// An isotropic linear elastic half-space `z > 0` (module docs): Young's modulus `E` (stress; `+∞` for a rigid
/// body, which does not deform) and Poisson's ratio `ν ∈ [0, 0.5]`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct HalfSpace {
    e: f64,
    nu: f64,
}

impl HalfSpace {
    /// A half-space of Young's modulus `e` (`> 0`, any stress unit; `f64::INFINITY` = rigid) and Poisson's ratio
    /// `nu ∈ [0, 0.5]`. Another value (NaN included) is refused, naming the argument.
    pub fn new(e: f64, nu: f64) -> Result<HalfSpace, ArgumentError> {
        const F: &str = "HalfSpace::new";
        if e.is_nan() || e <= 0.0 {
            return Err(ArgumentError::new(F, "e", format!("(Young's modulus) must be > 0 (+inf: rigid), got {e}")));
        }
        if !(0.0..=0.5).contains(&nu) {
            return Err(ArgumentError::new(F, "nu", format!("(Poisson's ratio) must lie in [0, 0.5], got {nu}")));
        }
        Ok(HalfSpace { e, nu })
    }

    /// Young's modulus `E` (stress; infinite for a rigid body).
    pub fn youngs_modulus(&self) -> f64 {
        self.e
    }

    /// Poisson's ratio `ν`.
    pub fn poisson_ratio(&self) -> f64 {
        self.nu
    }

    /// Shear modulus `G = E/(2(1+ν))` (stress; infinite for a rigid body).
    pub fn shear_modulus(&self) -> f64 {
        self.e / (2.0 * (1.0 + self.nu))
    }

    /// `K = 1/(2πG) = (1+ν)/(πE)` (1/stress; 0 for a rigid body).
    fn k(&self) -> f64 {
        if self.e.is_infinite() {
            0.0
        } else {
            (1.0 + self.nu) / (PI * self.e)
        }
    }

    /// The constants of this body alone (on a rigid counter-body): `k_d = (1−ν)K`, `k_ν = νK`, `k_c = (1−2ν)K/2`.
    pub fn compliance(&self) -> Compliance {
        let k = self.k();
        Compliance { direct: (1.0 - self.nu) * k, poisson: self.nu * k, coupling: 0.5 * (1.0 - 2.0 * self.nu) * k }
    }

    /// The constants of this body (body 1, `z > 0`) pressed on `counter` (body 2, `z < 0`, mirrored; module docs,
    /// "A pair of half-spaces"): the direct constants add, the coupling constant is the difference
    /// `[(1−2ν1)/G1 − (1−2ν2)/G2]/(4π)`, exactly 0 for identical materials.
    pub fn pair(&self, counter: &HalfSpace) -> Compliance {
        let (one, two) = (self.compliance(), counter.compliance());
        Compliance {
            direct: one.direct + two.direct,
            poisson: one.poisson + two.poisson,
            coupling: one.coupling - two.coupling,
        }
    }

    /// The nine coefficients of this body's rectangle `[x1, x2] × [y1, y2]` at the surface point `(x, y)` (any point:
    /// inside, on an edge or a corner, or away), per unit traction. Same as
    /// `self.compliance().rectangle(..)`; refused as [`Compliance::rectangle`].
    pub fn rectangle(&self, x1: f64, x2: f64, y1: f64, y2: f64, x: f64, y: f64) -> Result<Coefficients, ArgumentError> {
        self.compliance().rectangle(x1, x2, y1, y2, x, y)
    }
}

/// The three material constants of the coefficients (module docs), of one body ([`HalfSpace::compliance`]) or of a
/// pair ([`HalfSpace::pair`]); all in 1/stress.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Compliance {
    direct: f64,
    poisson: f64,
    coupling: f64,
}

impl Compliance {
    /// `k_d`: the constant of `I1 = ∬ 1/ρ` in `C_zz`, `C_xx`, `C_yy` (`(1−ν)K` per body, summed over a pair).
    pub fn direct(&self) -> f64 {
        self.direct
    }

    /// `k_ν`: the constant of `J_xx`, `J_yy`, `J_xy` in `C_xx`, `C_yy`, `C_xy` (`νK` per body, summed over a pair).
    pub fn poisson(&self) -> f64 {
        self.poisson
    }

    /// `k_c`: `C_zx = −C_xz = k_c K_x`, `C_zy = −C_yz = k_c K_y` (`(1−2ν)K/2` for one body; body 1's minus body 2's
    /// for a pair, `= β k_d` with Dundurs' `β`).
    pub fn coupling(&self) -> f64 {
        self.coupling
    }

    /// The nine coefficients of the rectangle `[x1, x2] × [y1, y2]` at the surface point `(x, y)` (same length unit
    /// throughout), per unit traction. Refused when a value is not finite or the rectangle is empty or reversed
    /// (`x1 < x2`, `y1 < y2` required) or its sides overflow.
    pub fn rectangle(&self, x1: f64, x2: f64, y1: f64, y2: f64, x: f64, y: f64) -> Result<Coefficients, ArgumentError> {
        const F: &str = "Compliance::rectangle";
        for (name, v) in [("x1", x1), ("x2", x2), ("y1", y1), ("y2", y2), ("x", x), ("y", y)] {
            if !v.is_finite() {
                return Err(ArgumentError::new(F, name, format!("must be finite, got {v}")));
            }
        }
        let (al, be) = (0.5 * (x2 - x1), 0.5 * (y2 - y1));
        for (name, h, lo, hi) in [("x2", al, x1, x2), ("y2", be, y1, y2)] {
            if !(h > 0.0 && h.is_finite()) {
                return Err(ArgumentError::new(F, name, format!("must exceed the lower end finitely: {lo} .. {hi}")));
            }
        }
        let x0 = 0.5 * ((x - x1) + (x - x2));
        let y0 = 0.5 * ((y - y1) + (y - y2));
        Ok(self.coefficients(&integrals(x0, y0, al, be)))
    }

    /// The coefficients from the integrals (module docs, "Rectangles"). `0.0 + v` and `0.0 − v` turn a zero of
    /// either sign into `+0`, so identical materials give coupling coefficients of exactly `+0`.
    fn coefficients(&self, n: &Integrals) -> Coefficients {
        let direct = self.normal(n.i1);
        let xy = self.poisson * n.jxy;
        let (zx, zy) = (0.0 + self.coupling * n.kx, 0.0 + self.coupling * n.ky);
        Coefficients {
            xx: direct + self.poisson * n.jxx,
            xy,
            xz: 0.0 - zx,
            yx: xy,
            yy: direct + self.poisson * n.jyy,
            yz: 0.0 - zy,
            zx,
            zy,
            zz: direct,
        }
    }
}

impl Compliance {
    /// `C_zz` from the integral `I₁` (the direct term; [`Compliance::coefficients`] takes the same product).
    fn normal(&self, i1: f64) -> f64 {
        self.direct * i1
    }
}

/// `I₁` alone, exactly (bit for bit) as [`integrals`] computes it.
fn normal_integral(x0: f64, y0: f64, al: f64, be: f64) -> f64 {
    let (ax, ay) = (x0.abs(), y0.abs());
    let r = ax.hypot(ay);
    if r >= 1e8 * al.max(be) {
        return 4.0 * (al / r) * be;
    }
    let s = al.max(be).log2().floor().exp2();
    let (x, y, a, b) = (ax / s, ay / s, al / s, be / s);
    s * j_xx(x, y, a, b) + s * j_xx(y, x, b, a)
}

/// The five integrals of a rectangle (module docs), in units of length; `i1 = jxx + jyy`.
#[derive(Clone, Copy, Debug)]
struct Integrals {
    i1: f64,
    jxx: f64,
    jyy: f64,
    jxy: f64,
    kx: f64,
    ky: f64,
}

/// `v`, or `0 − v` (a zero of either sign becoming `+0`) when `negate`.
fn flip(v: f64, negate: bool) -> f64 {
    if negate {
        0.0 - v
    } else {
        v
    }
}

/// The integrals of the rectangle of half-sides `al`, `be` (`> 0`, finite) centred at `(−x0, −y0)` relative to the
/// observation point: parity, exact scaling by a power of two, then [`j_xx`], [`j_xy`], [`k_x`] at `x0, y0 ≥ 0`.
fn integrals(x0: f64, y0: f64, al: f64, be: f64) -> Integrals {
    let (ax, ay) = (x0.abs(), y0.abs());
    let (sx, sy) = (x0 < 0.0, y0 < 0.0);
    let r = ax.hypot(ay);
    if r >= 1e8 * al.max(be) {
        return point_load_limit(ax, ay, r, al, be, sx, sy);
    }
    let s = al.max(be).log2().floor().exp2();
    let (x, y, a, b) = (ax / s, ay / s, al / s, be / s);
    let (jxx, jyy) = (s * j_xx(x, y, a, b), s * j_xx(y, x, b, a));
    Integrals {
        i1: jxx + jyy,
        jxx,
        jyy,
        jxy: flip(s * j_xy(x, y, a, b), sx != sy),
        kx: flip(s * k_x(x, y, a, b), sx),
        ky: flip(s * k_x(y, x, b, a), sy),
    }
}

/// Far beyond the rectangle (`r = ρ(x0, y0) ≥ 10⁸ max(α, β)`): the point-load values times the area `4αβ`, whose
/// relative error `(α² ∂²_X + β² ∂²_Y) f/(6 f)` is below `10⁻¹⁶` there. Written so that nothing overflows.
fn point_load_limit(ax: f64, ay: f64, r: f64, al: f64, be: f64, sx: bool, sy: bool) -> Integrals {
    let (cx, cy) = (ax / r, ay / r);
    let i1 = 4.0 * (al / r) * be;
    Integrals {
        i1,
        jxx: i1 * cx * cx,
        jyy: i1 * cy * cy,
        jxy: flip(i1 * cx * cy, sx != sy),
        kx: flip(i1 * cx, sx),
        ky: flip(i1 * cy, sy),
    }
}

/// `y·asinh(x/|y|)`: `0` at `y = 0` (or `x = 0`); by `asinh u = ln 2 + ln u + O(u⁻²)` where `|x/y|` could overflow.
fn y_asinh(y: f64, x: f64) -> f64 {
    if y == 0.0 || x == 0.0 {
        return 0.0;
    }
    let u = x / y.abs();
    if u.abs() < 1e150 {
        y * u.asinh()
    } else {
        y * u.signum() * (LN_2 + x.abs().ln() - y.abs().ln())
    }
}

/// `J_xx = ∬ X²/ρ³` over `X ∈ [x−a, x+a]`, `Y ∈ [y−b, y+b]`, for `x, y ≥ 0` (module docs, "Evaluation without
/// cancellation").
fn j_xx(x: f64, y: f64, a: f64, b: f64) -> f64 {
    let (a1, a2, b1, b2) = (x + a, x - a, y + b, y - b);
    let (far_x, far_y) = (x >= 3.0 * a, y >= 3.0 * b);
    let ax4 = 4.0 * a * x; // a1² − a2²
                           // d_k = a1 ρ(a2, b_k) + a2 ρ(a1, b_k), far in x: D_k = asinh(4ax/d_k).
    let d = |bk: f64| a1 * a2.hypot(bk) + a2 * a1.hypot(bk);
    if far_y {
        let (d1, d2, dd) = if far_x {
            let (d1, d2) = (d(b1), d(b2));
            let (u1, u2) = (ax4 / d1, ax4 / d2);
            let d_diff = -4.0 * b * y * (a1 / (a2.hypot(b1) + a2.hypot(b2)) + a2 / (a1.hypot(b1) + a1.hypot(b2)));
            let u_diff = ax4 * d_diff / (d1 * d2);
            let dd = (u_diff * (u1 + u2) / (u1 * u2.hypot(1.0) + u2 * u1.hypot(1.0))).asinh();
            (u1.asinh(), u2.asinh(), dd)
        } else {
            let e = |t: f64| (-4.0 * b * y * t / ((t.hypot(b1) + t.hypot(b2)) * b1 * b2)).asinh();
            let dk = |bk: f64| (a1 / bk).asinh() - (a2 / bk).asinh();
            (dk(b1), dk(b2), e(a1) - e(a2))
        };
        b * (d1 + d2) + y * dd
    } else {
        let t = |bk: f64| {
            if bk == 0.0 {
                0.0
            } else if far_x {
                bk * (ax4 / d(bk)).asinh()
            } else {
                y_asinh(bk, a1) - y_asinh(bk, a2)
            }
        };
        t(b1) - t(b2)
    }
}

/// `J_xy = ∬ XY/ρ³ = ΔΔ[−ρ]` over the rectangle, `x, y ≥ 0`: one expression of positive terms (module docs).
fn j_xy(x: f64, y: f64, a: f64, b: f64) -> f64 {
    let (a1, a2, b1, b2) = (x + a, x - a, y + b, y - b);
    let (r11, r12, r21, r22) = (a1.hypot(b1), a1.hypot(b2), a2.hypot(b1), a2.hypot(b2));
    16.0 * a * b * x * y * (1.0 / (r11 + r21) + 1.0 / (r12 + r22)) / ((r11 + r12) * (r21 + r22))
}

/// `ln(p/q)` for `p, q > 0` given `p² − q² = dsq` exactly: `½ ln_1p(dsq/q²)` when that argument is at most ½ in
/// magnitude (the ratio near 1), the plain ratio otherwise.
fn ln_ratio(p: f64, q: f64, dsq: f64) -> f64 {
    let arg = dsq / (q * q);
    if arg.abs() <= 0.5 {
        0.5 * arg.ln_1p()
    } else {
        (p / q).ln()
    }
}

/// `K_x = ∬ X/ρ² = ΔΔ[Y ln ρ] + ΔΔ[X atan(Y/X)]` over the rectangle, `x, y ≥ 0` (module docs).
fn k_x(x: f64, y: f64, a: f64, b: f64) -> f64 {
    let (a1, a2, b1, b2) = (x + a, x - a, y + b, y - b);
    let (far_x, far_y) = (x >= 3.0 * a, y >= 3.0 * b);
    let ax4 = 4.0 * a * x;
    // λ_k = ln(ρ(a1, b_k)/ρ(a2, b_k)); only called where ρ(a2, b_k) > 0.
    let lambda = |bk: f64| ln_ratio(a1.hypot(bk), a2.hypot(bk), ax4);
    let t1 = if far_y {
        let (r11, r12, r21, r22) = (a1.hypot(b1), a1.hypot(b2), a2.hypot(b1), a2.hypot(b2));
        let p = r21 * r12;
        let arg = -ax4 * 4.0 * b * y / (p * p);
        let dl = if arg.abs() <= 0.5 { 0.5 * arg.ln_1p() } else { ((r11 / r21) * (r22 / r12)).ln() };
        b * (lambda(b1) + lambda(b2)) + y * dl
    } else {
        let t = |bk: f64| if bk == 0.0 { 0.0 } else { bk * lambda(bk) };
        t(b1) - t(b2)
    };
    let bb = b1 * b2;
    let phi = |t: f64| (2.0 * b * t).atan2(t * t + bb);
    let t2 = if far_x {
        let dphi = (4.0 * a * b * (bb - a1 * a2)).atan2((a1 * a1 + bb) * (a2 * a2 + bb) + 4.0 * b * b * a1 * a2);
        a * (phi(a1) + phi(a2)) + x * dphi
    } else {
        let h = |t: f64| if t == 0.0 { 0.0 } else { t.abs() * phi(t.abs()) };
        h(a1) - h(a2)
    };
    t1 + t2
}

/// A uniform grid of `mx × my` rectangular elements `dx × dy` (module docs, "A uniform grid") with the material
/// constants of one body or a pair: the influence of element `j` on the centre of element `i` depends on the index
/// offsets only ([`UniformGrid::kernel`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct UniformGrid {
    compliance: Compliance,
    mx: usize,
    my: usize,
    dx: f64,
    dy: f64,
}

impl UniformGrid {
    /// A grid of `mx × my` elements (`≥ 1` each) of sides `dx`, `dy` (finite, `> 0`, any length unit) with the
    /// constants `compliance` ([`HalfSpace::compliance`] or [`HalfSpace::pair`]). Refused, naming the argument,
    /// otherwise, or when the `mx·my` offsets of one kernel quadrant cannot be held in memory.
    pub fn new(compliance: Compliance, mx: usize, my: usize, dx: f64, dy: f64) -> Result<UniformGrid, ArgumentError> {
        const F: &str = "UniformGrid::new";
        for (name, m) in [("mx", mx), ("my", my)] {
            if m == 0 || m > isize::MAX as usize {
                return Err(ArgumentError::new(F, name, format!("(elements) must be ≥ 1 (and fit an isize), got {m}")));
            }
        }
        for (name, h) in [("dx", dx), ("dy", dy)] {
            if !(h > 0.0 && h.is_finite()) {
                return Err(ArgumentError::new(F, name, format!("(element side) must be finite and > 0, got {h}")));
            }
        }
        let fits = mx.checked_mul(my).is_some_and(|n| n <= isize::MAX as usize / (6 * std::mem::size_of::<f64>()));
        if !fits {
            return Err(ArgumentError::new(F, "my", format!("{mx} × {my} kernel offsets do not fit in memory")));
        }
        Ok(UniformGrid { compliance, mx, my, dx, dy })
    }

    /// Elements along `x`.
    pub fn mx(&self) -> usize {
        self.mx
    }

    /// Elements along `y`.
    pub fn my(&self) -> usize {
        self.my
    }

    /// Element side along `x` (length).
    pub fn dx(&self) -> f64 {
        self.dx
    }

    /// Element side along `y` (length).
    pub fn dy(&self) -> f64 {
        self.dy
    }

    /// The material constants.
    pub fn compliance(&self) -> Compliance {
        self.compliance
    }

    /// The coefficients of element `j` at the centre of element `i`, per unit traction on `j`, for the index
    /// offsets `di = ix_i − ix_j ∈ −(mx−1) ..= mx−1` (along `x`) and `dj = iy_i − iy_j ∈ −(my−1) ..= my−1` (along
    /// `y`): the rectangle of half-sides `dx/2`, `dy/2` seen from `(di·dx, dj·dy)`. Refused for an offset outside
    /// its range.
    pub fn kernel(&self, di: isize, dj: isize) -> Result<Coefficients, ArgumentError> {
        const F: &str = "UniformGrid::kernel";
        for (name, d, m) in [("di", di, self.mx), ("dj", dj, self.my)] {
            if d.unsigned_abs() >= m {
                return Err(ArgumentError::new(F, name, format!("must lie in −{0} ..= {0}, got {d}", m - 1)));
            }
        }
        Ok(self.kernel_unchecked(di, dj))
    }

    /// `C_zz` at any offset `(di, dj)`, also beyond the grid (the closed form holds everywhere): for embeddings
    /// that need the kernel's periodic images ([`crate::toeplitz2d::Toeplitz2d::circulant_even`]).
    pub(crate) fn normal_at(&self, di: usize, dj: usize) -> f64 {
        let (x, y) = (di as f64 * self.dx, dj as f64 * self.dy);
        self.compliance.normal(normal_integral(x, y, 0.5 * self.dx, 0.5 * self.dy))
    }

    /// `(C_xx, C_yy)` at any offset `(di, dj)`, also beyond the grid (as [`UniformGrid::normal_at`]): for the
    /// tangential problem's FFT preconditioner.
    pub(crate) fn tangential_at(&self, di: usize, dj: usize) -> (f64, f64) {
        let c = self.kernel_unchecked(di as isize, dj as isize);
        (c.xx, c.yy)
    }

    fn kernel_unchecked(&self, di: isize, dj: isize) -> Coefficients {
        let n = integrals(di as f64 * self.dx, dj as f64 * self.dy, 0.5 * self.dx, 0.5 * self.dy);
        self.compliance.coefficients(&n)
    }

    /// The kernel at the offsets `0 ≤ di < mx`, `0 ≤ dj < my` (one quadrant; the others follow by parity,
    /// [`KernelTable::get`]): `6·mx·my` values, computed once each.
    pub fn kernel_table(&self) -> KernelTable {
        let n = self.mx * self.my; // checked by `new`
        let mut t = KernelTable {
            mx: self.mx,
            my: self.my,
            zz: Vec::with_capacity(n),
            xx: Vec::with_capacity(n),
            yy: Vec::with_capacity(n),
            xy: Vec::with_capacity(n),
            zx: Vec::with_capacity(n),
            zy: Vec::with_capacity(n),
        };
        for dj in 0..self.my {
            for di in 0..self.mx {
                let c = self.kernel_unchecked(di as isize, dj as isize);
                t.zz.push(c.zz);
                t.xx.push(c.xx);
                t.yy.push(c.yy);
                t.xy.push(c.xy);
                t.zx.push(c.zx);
                t.zy.push(c.zy);
            }
        }
        t
    }

    /// The normal coefficient `C_zz` alone at the quadrant's offsets (as [`UniformGrid::kernel_table`], without
    /// the tangential and coupling integrals, which a frictionless problem never reads): about half the work
    /// (measured: 0.157 s against ... on 575 × 647). [`KernelTable::get`] of this table reads `NaN` for every
    /// other coefficient, so that a use of them is loud, never a silent zero.
    pub fn normal_table(&self) -> KernelTable {
        let n = self.mx * self.my; // checked by `new`
        let mut zz = Vec::with_capacity(n);
        for dj in 0..self.my {
            for di in 0..self.mx {
                zz.push(self.normal_at(di, dj));
            }
        }
        let none = Vec::new;
        KernelTable { mx: self.mx, my: self.my, zz, xx: none(), yy: none(), xy: none(), zx: none(), zy: none() }
    }
}

/// One quadrant of a uniform grid's kernel ([`UniformGrid::kernel_table`]): the coefficients at the offsets
/// `0 ≤ di < mx`, `0 ≤ dj < my`, each stored row-major `[dj·mx + di]` (shape `(my, mx)`). The other quadrants
/// follow by parity: `zz`, `xx`, `yy` are even in `di` and in `dj`; `xy = yx` is odd in both; `zx = −xz` is odd in
/// `di`, even in `dj`; `zy = −yz` the reverse ([`KernelTable::get`] applies this).
#[derive(Clone, Debug, PartialEq)]
pub struct KernelTable {
    mx: usize,
    my: usize,
    zz: Vec<f64>,
    xx: Vec<f64>,
    yy: Vec<f64>,
    xy: Vec<f64>,
    zx: Vec<f64>,
    zy: Vec<f64>,
}

impl KernelTable {
    /// Elements along `x` of the grid (the quadrant's row length).
    pub fn mx(&self) -> usize {
        self.mx
    }

    /// Elements along `y` of the grid (the quadrant's rows).
    pub fn my(&self) -> usize {
        self.my
    }

    /// `C_zz` at `[dj·mx + di]`, `di, dj ≥ 0`.
    pub fn zz(&self) -> &[f64] {
        &self.zz
    }

    /// `C_xx` at `[dj·mx + di]`, `di, dj ≥ 0`.
    pub fn xx(&self) -> &[f64] {
        &self.xx
    }

    /// `C_yy` at `[dj·mx + di]`, `di, dj ≥ 0`.
    pub fn yy(&self) -> &[f64] {
        &self.yy
    }

    /// `C_xy = C_yx` at `[dj·mx + di]`, `di, dj ≥ 0`.
    pub fn xy(&self) -> &[f64] {
        &self.xy
    }

    /// `C_zx = −C_xz` at `[dj·mx + di]`, `di, dj ≥ 0`.
    pub fn zx(&self) -> &[f64] {
        &self.zx
    }

    /// `C_zy = −C_yz` at `[dj·mx + di]`, `di, dj ≥ 0`.
    pub fn zy(&self) -> &[f64] {
        &self.zy
    }

    /// Whether the table holds every coefficient ([`UniformGrid::kernel_table`]) rather than `C_zz` alone
    /// ([`UniformGrid::normal_table`]).
    pub fn has_tangential(&self) -> bool {
        !self.xx.is_empty()
    }

    /// The coefficients at any offset `(di, dj)` of the grid, by parity from the quadrant: equal (bit for bit) to
    /// [`UniformGrid::kernel`]`(di, dj)`. `None` outside `|di| < mx`, `|dj| < my`. A table of `C_zz` alone
    /// ([`UniformGrid::normal_table`]) gives `NaN` for every other coefficient.
    pub fn get(&self, di: isize, dj: isize) -> Option<Coefficients> {
        let (i, j) = (di.unsigned_abs(), dj.unsigned_abs());
        if i >= self.mx || j >= self.my {
            return None;
        }
        let k = j * self.mx + i;
        if !self.has_tangential() {
            let nan = f64::NAN;
            let zz = self.zz[k];
            return Some(Coefficients { xx: nan, xy: nan, xz: nan, yx: nan, yy: nan, yz: nan, zx: nan, zy: nan, zz });
        }
        let (sx, sy) = (di < 0, dj < 0);
        let xy = flip(*self.xy.get(k)?, sx != sy);
        let zx = flip(*self.zx.get(k)?, sx);
        let zy = flip(*self.zy.get(k)?, sy);
        Some(Coefficients {
            xx: *self.xx.get(k)?,
            xy,
            xz: 0.0 - zx,
            yx: xy,
            yy: *self.yy.get(k)?,
            yz: 0.0 - zy,
            zx,
            zy,
            zz: *self.zz.get(k)?,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::halfplane::HalfPlane;

    // ------------------------------------------------------------------------------------------------------------
    // Independent reference: the point-load formulas (Johnson ch. 3, written out again here) integrated over the
    // rectangle by tensor Gauss–Legendre on a quadtree refined towards the observation point. Nothing is shared with
    // the closed forms above.
    // ------------------------------------------------------------------------------------------------------------

    /// Gauss–Legendre nodes and weights on [−1, 1].
    struct Gl {
        x: Vec<f64>,
        w: Vec<f64>,
    }

    impl Gl {
        /// The n-point rule of [`crate::bem::quadrature::gauss_legendre`] (tested there: exact for monomials;
        /// nothing in it is shared with the closed forms under test here).
        fn new(n: usize) -> Gl {
            let rule = crate::bem::quadrature::gauss_legendre(n).unwrap();
            Gl { x: rule.points, w: rule.weights }
        }

        /// Tensor rule on the rectangle `r = [x1, x2, y1, y2]`.
        fn rect(&self, f: &dyn Fn(f64, f64) -> [f64; 9], r: [f64; 4]) -> [f64; 9] {
            let (cx, hx, cy, hy) = (0.5 * (r[0] + r[1]), 0.5 * (r[1] - r[0]), 0.5 * (r[2] + r[3]), 0.5 * (r[3] - r[2]));
            let mut s = [0.0; 9];
            for (xi, wi) in self.x.iter().zip(&self.w) {
                for (yj, wj) in self.x.iter().zip(&self.w) {
                    let v = f(cx + hx * xi, cy + hy * yj);
                    s.iter_mut().zip(v).for_each(|(a, b)| *a += wi * wj * hx * hy * b);
                }
            }
            s
        }

        /// ∬ f over `r`, `f` singular (like 1/ρ) at `p`: a leaf at least its longer side away from `p` takes the
        /// tensor rule (16 points: the nearest singularity then lies outside a Bernstein ellipse of parameter
        /// ≥ 4.2, error < 1e-19 relative); a nearer cell is split (halved across its long side when elongated), down
        /// to a side of `min_side` (kept well above the coordinates' ulp, or a midpoint would not split), below which
        /// the cells at the point (integral ≤ 4·side·max|ρf|) are dropped.
        fn adaptive(&self, f: &dyn Fn(f64, f64) -> [f64; 9], r: [f64; 4], p: (f64, f64), min_side: f64) -> [f64; 9] {
            let (w, h) = (r[1] - r[0], r[3] - r[2]);
            let s = w.max(h);
            let dx = (r[0] - p.0).max(p.0 - r[1]).max(0.0);
            let dy = (r[2] - p.1).max(p.1 - r[3]).max(0.0);
            if dx.hypot(dy) >= s {
                return self.rect(f, r);
            }
            if s < min_side {
                return [0.0; 9];
            }
            let (xm, ym) = (0.5 * (r[0] + r[1]), 0.5 * (r[2] + r[3]));
            let cells: Vec<[f64; 4]> = if w > 2.0 * h {
                vec![[r[0], xm, r[2], r[3]], [xm, r[1], r[2], r[3]]]
            } else if h > 2.0 * w {
                vec![[r[0], r[1], r[2], ym], [r[0], r[1], ym, r[3]]]
            } else {
                vec![[r[0], xm, r[2], ym], [xm, r[1], r[2], ym], [r[0], xm, ym, r[3]], [xm, r[1], ym, r[3]]]
            };
            let mut sum = [0.0; 9];
            for c in cells {
                let v = self.adaptive(f, c, p, min_side);
                sum.iter_mut().zip(v).for_each(|(a, b)| *a += b);
            }
            sum
        }
    }

    /// Point-load surface displacements at `(X, Y)` from the load (Boussinesq, Cerruti; module docs), in the order
    /// [xx, xy, xz, yx, yy, yz, zx, zy, zz] (displacement, then force: z = the normal force into the body).
    fn point(k: f64, nu: f64, x: f64, y: f64) -> [f64; 9] {
        let r2 = x * x + y * y;
        let r = r2.sqrt();
        let r3 = r2 * r;
        let c = (1.0 - 2.0 * nu) * k / (2.0 * r2);
        let xy = k * nu * x * y / r3;
        [
            k * ((1.0 - nu) / r + nu * x * x / r3),
            xy,
            -c * x,
            xy,
            k * ((1.0 - nu) / r + nu * y * y / r3),
            -c * y,
            c * x,
            c * y,
            (1.0 - nu) * k / r,
        ]
    }

    fn arr(c: &Coefficients) -> [f64; 9] {
        [c.xx, c.xy, c.xz, c.yx, c.yy, c.yz, c.zx, c.zy, c.zz]
    }

    const NAMES: [&str; 9] = ["xx", "xy", "xz", "yx", "yy", "yz", "zx", "zy", "zz"];

    /// The reference coefficients of one body `(E, ν)` for the rectangle `r` at `p`, by the adaptive quadrature.
    fn reference(gl: &Gl, e: f64, nu: f64, r: [f64; 4], p: (f64, f64)) -> [f64; 9] {
        let k = (1.0 + nu) / (PI * e);
        let f = |xi: f64, eta: f64| point(k, nu, p.0 - xi, p.1 - eta);
        gl.adaptive(&f, r, p, 1e-15 * (r[1] - r[0]).max(r[3] - r[2]))
    }

    /// Worst errors of `got` against `exp`: (relative error over the coefficients not small against the scale S =
    /// the largest direct coefficient, error in units of S over all).
    fn errors(got: &[f64; 9], exp: &[f64; 9]) -> (f64, f64) {
        let s = exp[0].abs().max(exp[4].abs()).max(exp[8].abs());
        let (mut rel, mut of_s) = (0.0_f64, 0.0_f64);
        for (g, x) in got.iter().zip(exp) {
            let err = (g - x).abs();
            of_s = of_s.max(err / s);
            if x.abs() >= 1e-3 * s {
                rel = rel.max(err / x.abs());
            }
        }
        (rel, of_s)
    }

    /// Observation points of the rectangle `r` (sides w, h; longer side L): (label, x, y). Inside, on each edge, at
    /// each corner, just outside (1e-2 .. 1e-7 of a side), and 3, 10, 100, 1e3, 1e4 L from the centre in five
    /// directions (along both axes, and off them).
    fn points(r: [f64; 4]) -> Vec<(String, f64, f64)> {
        let (w, h) = (r[1] - r[0], r[3] - r[2]);
        let at = |u: f64, v: f64| (r[0] + u * w, r[2] + v * h);
        let mut out = Vec::new();
        let rel = [
            ("centre", 0.5, 0.5),
            ("inside", 0.3, 0.8),
            ("edge x1", 0.0, 0.4),
            ("edge x2", 1.0, 0.7),
            ("edge y1", 0.25, 0.0),
            ("edge y2", 0.6, 1.0),
            ("corner 11", 0.0, 0.0),
            ("corner 21", 1.0, 0.0),
            ("corner 12", 0.0, 1.0),
            ("corner 22", 1.0, 1.0),
            ("near", 1.01, 0.5),
            ("near corner", -0.003, 1.002),
            ("near edge", 0.5, 1.0 + 1e-6),
            ("nearer edge", 1.0 + 1e-7, 0.3),
        ];
        for (name, u, v) in rel {
            let (x, y) = at(u, v);
            out.push((name.to_string(), x, y));
        }
        let (cx, cy, l) = (0.5 * (r[0] + r[1]), 0.5 * (r[2] + r[3]), w.max(h));
        for dist in [3.0, 10.0, 100.0, 1e3, 1e4, 1e6] {
            for th in [0.0, 0.4, 0.5 * PI, 2.5, 4.0] {
                out.push((format!("far {dist} L at {th}"), cx + dist * l * th.cos(), cy + dist * l * th.sin()));
            }
        }
        out
    }

    /// Item 1: every coefficient against the quadrature of the point loads, for rectangles of aspect 1/10 .. 10 and
    /// ν = 0, 0.3, 0.5. Tolerance: 1e-10 relative for a coefficient not small against the point's scale S (the
    /// largest direct coefficient), and an absolute floor of 1e-13·S for all (a coefficient ~0, e.g. `C_xz` on the
    /// element's centre line, is held to that floor). Within 100 L the bound is 1e-10 relative; beyond (1e3, 1e4,
    /// 1e6 L) the quadrature is a single smooth tensor rule and both are held to 1e-12 relative, which the plain
    /// double difference of the antiderivatives (loss ~ε(R/L)²: `I1` off by 3e-9 at 1e3 L, 4e-7 at 1e4 L) fails.
    #[test]
    fn every_coefficient_matches_quadrature_of_the_point_loads() {
        let gl = Gl::new(16);
        let e = 2.5;
        let (mut worst_rel, mut worst_s, mut worst_far) = (0.0_f64, 0.0_f64, 0.0_f64);
        for aspect in [0.1, 0.3, 1.0, 3.0, 10.0_f64] {
            let (w, h) = (0.7 * aspect.sqrt(), 0.7 / aspect.sqrt());
            let r = [0.13, 0.13 + w, -0.41, -0.41 + h];
            for nu in [0.0, 0.3, 0.5] {
                let hs = HalfSpace::new(e, nu).unwrap();
                for (label, x, y) in points(r) {
                    let got = arr(&hs.rectangle(r[0], r[1], r[2], r[3], x, y).unwrap());
                    let exp = reference(&gl, e, nu, r, (x, y));
                    let (rel, of_s) = errors(&got, &exp);
                    let far = label.starts_with("far 1000")
                        || label.starts_with("far 10000")
                        || label.starts_with("far 1000000");
                    let tol = if far { 1e-12 } else { 1e-10 };
                    for c in 0..9 {
                        let s = exp[0].abs().max(exp[4].abs()).max(exp[8].abs());
                        let err = (got[c] - exp[c]).abs();
                        assert!(
                            err <= (tol * exp[c].abs()).max(1e-13 * s),
                            "aspect {aspect} nu {nu} {label}: C_{} = {:e}, quadrature {:e} (err {err:.1e}, S {s:.1e})",
                            NAMES[c],
                            got[c],
                            exp[c]
                        );
                    }
                    if far {
                        worst_far = worst_far.max(rel);
                    } else {
                        worst_rel = worst_rel.max(rel);
                    }
                    worst_s = worst_s.max(of_s);
                }
            }
        }
        eprintln!(
            "rectangles vs quadrature: worst relative {worst_rel:.1e} (≤ 100 L), {worst_far:.1e} (1e3 .. 1e6 L); \
             worst {worst_s:.1e} of S"
        );
    }

    /// Item 2: Love's uniformly loaded rectangle (A.E.H. Love, Phil. Trans. R. Soc. A 228, 1929; the formula also in
    /// [`crate::halfplane`]'s test, after Timoshenko & Goodier §138): at the centre of a rectangle of SIDES L1 × L2,
    /// `u_z = (1−ν²) p/(πE) · [2 L1 ln((L2 + √(L1²+L2²))/L1) + 2 L2 ln((L1 + √(L1²+L2²))/L2)]` (for half-sides a, b:
    /// `4(1−ν²) p/(πE) [a asinh(b/a) + b asinh(a/b)]`); a square of side L: the classical `1.1222 (1−ν²) p L/E`. At a
    /// corner: a quarter of the centre value of the rectangle 2L1 × 2L2 (four such rectangles meet at its centre),
    /// i.e. half the centre value of L1 × L2 (the integral is homogeneous of degree 1 in the lengths).
    #[test]
    fn centre_deflection_is_loves() {
        for (e, nu) in [(210e9, 0.3), (1.0, 0.0), (3.0, 0.5)] {
            let hs = HalfSpace::new(e, nu).unwrap();
            for (l1, l2) in [(1.0_f64, 1.0_f64), (2.0, 0.5), (0.1, 3.0), (1e-3, 7e-3)] {
                let d = (l1 * l1 + l2 * l2).sqrt();
                let love =
                    (1.0 - nu * nu) / (PI * e) * (2.0 * l1 * ((l2 + d) / l1).ln() + 2.0 * l2 * ((l1 + d) / l2).ln());
                let (cx, cy) = (0.3, -1.1);
                let c = hs.rectangle(cx - 0.5 * l1, cx + 0.5 * l1, cy - 0.5 * l2, cy + 0.5 * l2, cx, cy).unwrap();
                assert!((c.zz - love).abs() <= 1e-14 * love, "E {e} nu {nu} {l1} x {l2}: {} vs Love {love}", c.zz);
                let corner = hs.rectangle(0.0, l1, 0.0, l2, 0.0, 0.0).unwrap().zz;
                assert!((corner - 0.5 * love).abs() <= 1e-14 * love, "corner {corner} vs {}", 0.5 * love);
            }
        }
        let square = HalfSpace::new(1.0, 0.0).unwrap().rectangle(-0.5, 0.5, -0.5, 0.5, 0.0, 0.0).unwrap().zz;
        assert!((square - 1.1222).abs() < 5e-5, "square: {square}");
    }

    /// Item 3: one row of rectangles of width w is [`crate::halfplane`]'s strip of half-spaces (its closed forms on
    /// the centre line, derived separately there and checked there against their own quadrature): `C_xz`, `C_zz`,
    /// `C_xx`, `C_zx` agree to 1e-12 relative (floor 1e-14 of the scale for the `C_xz = 0` at the element's centre)
    /// within 20 element lengths (the strip's own tested range); the y-coupling vanishes exactly on the centre line
    /// (parity). And the uniform blocks of a strip are this module's kernel of a one-row grid (`MY = 1`, `DY = w`).
    /// Beyond, 1e3 lengths from a strip 1e-3 wide, the strip's closed forms lose ~1e-12 (their documented
    /// `ε·|X|/size`); there this module's values are held against 60-digit arithmetic of the antiderivatives
    /// (mpmath, `ΔΔF` of the module docs), to 1e-15.
    #[test]
    fn one_row_is_the_strip_of_half_spaces() {
        for (e, nu) in [(3.0e3, 0.28), (1.0, 0.0), (2.0, 0.5)] {
            let hs = HalfSpace::new(e, nu).unwrap();
            for &(x1, x2, width) in &[(-0.4, 0.6, 0.5), (-0.02, 0.02, 200.0), (0.3, 1.3, 3.0), (0.0, 1.0, 1e-3)] {
                let hp = HalfPlane::new(e, nu, 1.0).and_then(|h| h.strip(width)).unwrap();
                for t in [0.5, 0.3, 0.0, 1.0, -0.5, 3.0, -20.0, 21.0] {
                    let x = x1 + t * (x2 - x1);
                    let c = hs.rectangle(x1, x2, -0.5 * width, 0.5 * width, x, 0.0).unwrap();
                    let up = hp.strip_surface_displacement(x1, x2, 1.0, 0.0, x);
                    let uq = hp.strip_surface_displacement(x1, x2, 0.0, 1.0, x);
                    let s = c.zz.abs().max(c.xx.abs());
                    for (name, ours, strip) in
                        [("xz", c.xz, up.ux), ("zz", c.zz, up.uz), ("xx", c.xx, uq.ux), ("zx", c.zx, uq.uz)]
                    {
                        let err = (ours - strip).abs();
                        assert!(
                            err <= (1e-12 * strip.abs()).max(1e-14 * s),
                            "nu {nu} [{x1}, {x2}] w {width} x {x}: C_{name} {ours:e} vs strip {strip:e}"
                        );
                    }
                    assert!(c.xy == 0.0 && c.yz == 0.0 && c.zy == 0.0, "y-coupling on the centre line: {c:?}");
                }
            }
            if (e, nu) == (3.0e3, 0.28) {
                // 60 digits: C_zz, C_xx, C_zx of [0, 1] × [−5e-4, 5e-4] at (1000, 0).
                let c = hs.rectangle(0.0, 1.0, -5e-4, 5e-4, 1000.0, 0.0).unwrap();
                for (ours, exact) in [
                    (c.zz, 9.783_372_205_357_236e-11),
                    (c.xx, 1.358_801_695_188_473_3e-10),
                    (c.zx, 2.989_363_729_414_586_4e-11),
                ] {
                    assert!((ours - exact).abs() <= 1e-15 * exact, "1e3 lengths away: {ours:e} vs 60 digits {exact:e}");
                }
            }
            let (x0, h, n, width) = (-1.05, 0.04, 25, 0.3);
            let hp = HalfPlane::new(e, nu, 1.0).and_then(|h| h.strip(width)).unwrap();
            let blocks = hp.influence_blocks_uniform(x0, h, n).unwrap();
            let grid = UniformGrid::new(hs.compliance(), n, 1, h, width).unwrap();
            for i in 0..n {
                for j in 0..n {
                    let c = grid.kernel(i as isize - j as isize, 0).unwrap();
                    let ij = i * n + j;
                    let s = c.zz.abs();
                    for (ours, strip) in
                        [(c.xx, blocks.cxx[ij]), (c.xz, blocks.cxz[ij]), (c.zx, blocks.czx[ij]), (c.zz, blocks.czz[ij])]
                    {
                        assert!(
                            (ours - strip).abs() <= (1e-12 * strip.abs()).max(1e-14 * s),
                            "{i} {j}: {ours} vs {strip}"
                        );
                    }
                }
            }
        }
    }

    /// Item 4: Betti's reciprocal theorem on a uniform grid (elements of one shape, centres as collocation points):
    /// the displacement `a` at centre i of a unit traction `b` on element j equals the displacement `b` at centre j
    /// of a unit traction `a` on element i, `C_ab(i←j) = +C_ba(j←i)` — in particular `C_xz(i←j) = +C_zx(j←i)` with a
    /// PLUS sign. The minus signs belong to one and the same pair, `C_xz(i←j) = −C_zx(i←j)` (exact by
    /// construction), and to the offset, `C_zx(i←j) = −C_zx(j←i)` (odd). Computed with the general rectangle formula
    /// on a grid with non-dyadic coordinates: their rounding (~1e-15 of a side) bounds the agreement, hence 1e-14 of
    /// the scale S (the largest direct coefficient of the pair).
    #[test]
    fn betti_reciprocity_and_symmetries() {
        let hs = HalfSpace::new(7.0, 0.27).unwrap();
        let (ox, oy, dx, dy, mx, my) = (0.137, -0.291, 0.113, 0.071, 5usize, 4usize);
        let m = |i: (usize, usize), j: (usize, usize)| {
            let (x, y) = (ox + (i.0 as f64 + 0.5) * dx, oy + (i.1 as f64 + 0.5) * dy);
            let (x1, y1) = (ox + j.0 as f64 * dx, oy + j.1 as f64 * dy);
            hs.rectangle(x1, ox + (j.0 + 1) as f64 * dx, y1, oy + (j.1 + 1) as f64 * dy, x, y).unwrap()
        };
        let cells: Vec<(usize, usize)> = (0..my).flat_map(|iy| (0..mx).map(move |ix| (ix, iy))).collect();
        let mut plus_checked = false;
        for &i in &cells {
            for &j in &cells {
                let (cij, cji) = (m(i, j), m(j, i));
                let (a, b) = (cij.matrix(), cji.matrix());
                let s = a[0][0].abs().max(a[1][1].abs()).max(a[2][2].abs());
                for p in 0..3 {
                    for q in 0..3 {
                        assert!(
                            (a[p][q] - b[q][p]).abs() <= 1e-14 * s,
                            "{i:?} <- {j:?}: C[{p}][{q}] {} vs {}",
                            a[p][q],
                            b[q][p]
                        );
                    }
                }
                assert!(cij.xz == -cij.zx && cij.yz == -cij.zy && cij.xy == cij.yx, "{cij:?}");
                if cij.xz.abs() > 1e-2 * s {
                    assert!(cij.xz.signum() == cji.zx.signum() && cij.zx.signum() == -cji.zx.signum());
                    plus_checked = true;
                }
            }
        }
        assert!(plus_checked, "no pair with a coupling large enough to show the sign");
    }

    /// Item 4: the uniform grid's kernel is the general rectangle formula (bit for bit on a dyadic grid, whose
    /// coordinates and offsets are exact; to the coordinates' rounding, 1e-14 of the scale, on another), and the
    /// quadrant table gives exactly the kernel at every offset. A pair's constants, to cover them too.
    #[test]
    fn grid_kernel_is_the_rectangle_formula() {
        let pair = HalfSpace::new(1.0, 0.2).unwrap().pair(&HalfSpace::new(3.0, 0.45).unwrap());
        for (dx, dy, ox, oy, exact) in [(0.25, 0.375, 0.0, 0.0, true), (0.1, 0.07, 0.0123, -0.77, false)] {
            let (mx, my) = (6usize, 5usize);
            let grid = UniformGrid::new(pair, mx, my, dx, dy).unwrap();
            for (iy, jy) in (0..my).flat_map(|a| (0..my).map(move |b| (a, b))) {
                for (ix, jx) in (0..mx).flat_map(|a| (0..mx).map(move |b| (a, b))) {
                    let (xj, yj) = (ox + jx as f64 * dx, oy + jy as f64 * dy);
                    let r = pair
                        .rectangle(
                            xj - 0.5 * dx,
                            xj + 0.5 * dx,
                            yj - 0.5 * dy,
                            yj + 0.5 * dy,
                            ox + ix as f64 * dx,
                            oy + iy as f64 * dy,
                        )
                        .unwrap();
                    let k = grid.kernel(ix as isize - jx as isize, iy as isize - jy as isize).unwrap();
                    let s = r.zz.abs().max(r.xx.abs()).max(r.yy.abs());
                    for (a, b) in arr(&r).iter().zip(arr(&k)) {
                        if exact {
                            assert_eq!(a.to_bits(), b.to_bits(), "dyadic grid ({ix},{iy}) <- ({jx},{jy}): {a} vs {b}");
                        } else {
                            assert!((a - b).abs() <= 1e-14 * s, "({ix},{iy}) <- ({jx},{jy}): {a} vs {b}");
                        }
                    }
                }
            }
            let table = grid.kernel_table();
            for di in -(mx as isize - 1)..mx as isize {
                for dj in -(my as isize - 1)..my as isize {
                    let (k, t) = (grid.kernel(di, dj).unwrap(), table.get(di, dj).unwrap());
                    assert!(arr(&k).iter().zip(arr(&t)).all(|(a, b)| a.to_bits() == b.to_bits()), "{di} {dj}");
                }
            }
            assert!(table.get(mx as isize, 0).is_none() && table.get(0, -(my as isize)).is_none());
            assert_eq!(table.zz().len(), mx * my);
        }
    }

    /// Item 5: far away the coefficients tend to the point-load values times the area, A f(X0, Y0), with a relative
    /// error of second order in (size/R): the next term of the Taylor expansion of f over the rectangle,
    /// `(A/24)(w² f_XX + h² f_YY)` (f's second derivatives by central differences of the point-load formulas, step
    /// 1e-4 R), leaves a remainder of fourth order, bounded by 0.1 (L/R)⁴ of the scale A·K/R (the fourth-order
    /// coefficients of 1/ρ-like kernels are ≤ ~0.02); the relative error A f falls by 4 (±10 %) per doubling of R.
    #[test]
    fn far_field_tends_to_the_point_load_times_the_area() {
        let (e, nu) = (1.0, 0.3);
        let k = (1.0 + nu) / (PI * e);
        let hs = HalfSpace::new(e, nu).unwrap();
        let (w, h, cx, cy, th) = (1.0, 0.4, 0.2, -0.1, 0.7_f64);
        let area = w * h;
        let mut prev: Option<[f64; 9]> = None;
        for r in [25.0, 50.0, 100.0, 200.0] {
            let (x0, y0) = (r * th.cos(), r * th.sin());
            let c =
                arr(&hs.rectangle(cx - 0.5 * w, cx + 0.5 * w, cy - 0.5 * h, cy + 0.5 * h, cx + x0, cy + y0).unwrap());
            let f = point(k, nu, x0, y0);
            let d = 1e-4 * r;
            let (fxp, fxm) = (point(k, nu, x0 + d, y0), point(k, nu, x0 - d, y0));
            let (fyp, fym) = (point(k, nu, x0, y0 + d), point(k, nu, x0, y0 - d));
            let scale = area * k / r;
            let mut rel = [0.0; 9];
            for i in 0..9 {
                let fxx = (fxp[i] - 2.0 * f[i] + fxm[i]) / (d * d);
                let fyy = (fyp[i] - 2.0 * f[i] + fym[i]) / (d * d);
                let second = area / 24.0 * (w * w * fxx + h * h * fyy);
                let rest = (c[i] - area * f[i] - second).abs();
                assert!(rest <= 0.1 * (w / r).powi(4) * scale, "R {r} C_{}: remainder {rest:e}", NAMES[i]);
                rel[i] = (c[i] / (area * f[i]) - 1.0).abs();
                assert!(rel[i] <= (w / r).powi(2), "R {r} C_{}: {:e}", NAMES[i], rel[i]);
            }
            if let Some(p) = prev {
                for i in 0..9 {
                    let ratio = p[i] / rel[i];
                    assert!((3.6..=4.4).contains(&ratio), "R {r} C_{}: error ratio {ratio} for a doubling", NAMES[i]);
                }
            }
            prev = Some(rel);
        }
    }

    /// The pair (module docs, "A pair of half-spaces"): identical materials give coupling coefficients of exactly
    /// +0 and direct ones of exactly twice one body's; otherwise the pair equals the explicit mirror mapping (body 2
    /// loaded by q' = −q, p' = +p in its own frame; slip u1 − u2, gap change u1_z + u'_z) evaluated from the two
    /// single bodies, and its coupling constant is Dundurs' β (from [`crate::material::dundurs_beta`], computed
    /// there independently) times its direct one. A rigid body has no displacement.
    #[test]
    fn pair_adds_direct_and_subtracts_coupling() {
        let r = [0.13, 0.83, -0.41, -0.11];
        let pts = [(0.5, -0.2), (0.83, -0.3), (2.0, 1.5), (-3.0, 0.2), (0.13, -0.41)];
        let steel = HalfSpace::new(210e9, 0.3).unwrap();
        let same = steel.pair(&steel);
        assert_eq!(same.coupling().to_bits(), 0);
        for &(x, y) in &pts {
            let (one, two) = (
                steel.rectangle(r[0], r[1], r[2], r[3], x, y).unwrap(),
                same.rectangle(r[0], r[1], r[2], r[3], x, y).unwrap(),
            );
            for v in [two.xz, two.zx, two.yz, two.zy] {
                assert_eq!(v.to_bits(), 0, "coupling of identical materials not +0: {two:?}");
            }
            for (a, b) in [(one.xx, two.xx), (one.yy, two.yy), (one.zz, two.zz), (one.xy, two.xy), (one.yx, two.yx)] {
                assert_eq!((2.0 * a).to_bits(), b.to_bits());
            }
        }
        let t = [0.3, -0.7, 1.1]; // (q_x, q_y, p) on body 1
        let inf = f64::INFINITY;
        for ((e1, n1), (e2, n2)) in [
            ((1.0, 0.2), (0.4, 0.45)),
            ((70.0, 0.33), (210.0, 0.3)),
            ((1.0, 0.1), (inf, 0.3)),
            ((5.0, 0.5), (1.0, 0.0)),
        ] {
            let (b1, b2) = (HalfSpace::new(e1, n1).unwrap(), HalfSpace::new(e2, n2).unwrap());
            let pair = b1.pair(&b2);
            let beta = crate::material::dundurs_beta(
                &crate::material::Material::new(e1, n1),
                &crate::material::Material::new(e2, n2),
            );
            assert!((pair.coupling() - beta * pair.direct()).abs() <= 1e-15 * pair.direct(), "beta {beta}");
            for &(x, y) in &pts {
                let (m1, m2) = (
                    b1.rectangle(r[0], r[1], r[2], r[3], x, y).unwrap().matrix(),
                    b2.rectangle(r[0], r[1], r[2], r[3], x, y).unwrap().matrix(),
                );
                let mp = pair.rectangle(r[0], r[1], r[2], r[3], x, y).unwrap().matrix();
                let t2 = [-t[0], -t[1], t[2]];
                let apply = |m: &[[f64; 3]; 3], v: &[f64; 3]| -> [f64; 3] {
                    std::array::from_fn(|i| (0..3).map(|j| m[i][j] * v[j]).sum())
                };
                let (u1, u2, up) = (apply(&m1, &t), apply(&m2, &t2), apply(&mp, &t));
                let expect = [u1[0] - u2[0], u1[1] - u2[1], u1[2] + u2[2]];
                let s = m1[2][2].abs() + m2[2][2].abs();
                for i in 0..3 {
                    assert!(
                        (up[i] - expect[i]).abs() <= 1e-14 * s,
                        "({x}, {y}) component {i}: {} vs {}",
                        up[i],
                        expect[i]
                    );
                }
            }
        }
        let rigid = HalfSpace::new(inf, 0.3).unwrap().rectangle(r[0], r[1], r[2], r[3], 0.5, -0.2).unwrap();
        assert!(arr(&rigid).iter().all(|&v| v == 0.0));
    }

    /// Edges and corners: the coefficients are finite there and continuous across (the values 1e-12 away, in eight
    /// directions, differ by the continuity modulus ~δ ln δ, bounded by 1e-9 of the scale); extreme units: the
    /// coefficients are homogeneous of degree 1 in the lengths, exactly so for a power-of-two scale factor (2^±500)
    /// and to rounding for 1e-9 and 1e9; and the far point-load limit (beyond 1e8 sizes) joins the closed forms.
    #[test]
    fn finite_continuous_and_homogeneous() {
        let hs = HalfSpace::new(1.0, 0.3).unwrap();
        let r = [0.13, 0.83, -0.41, -0.11];
        let on = [
            (r[0], r[2]),
            (r[1], r[3]),
            (r[0], r[3]),
            (r[1], r[2]),
            (r[0], -0.3),
            (0.4, r[3]),
            (r[1], -0.2),
            (0.5, r[2]),
        ];
        for &(x, y) in &on {
            let c0 = arr(&hs.rectangle(r[0], r[1], r[2], r[3], x, y).unwrap());
            assert!(c0.iter().all(|v| v.is_finite()), "{c0:?}");
            let s = c0[0].abs().max(c0[8].abs());
            for (ex, ey) in
                [(1.0, 0.0), (-1.0, 0.0), (0.0, 1.0), (0.0, -1.0), (1.0, 1.0), (-1.0, 1.0), (1.0, -1.0), (-1.0, -1.0)]
            {
                let c = arr(&hs.rectangle(r[0], r[1], r[2], r[3], x + 1e-12 * ex, y + 1e-12 * ey).unwrap());
                for i in 0..9 {
                    assert!((c[i] - c0[i]).abs() <= 1e-9 * s, "({x}, {y}) + 1e-12 ({ex}, {ey}): C_{} jumps", NAMES[i]);
                }
            }
        }
        let pts = [(0.5, -0.2), (0.83, -0.3), (2.0, 1.5), (-3.0, 0.2), (0.13, -0.41), (40.0, -7.0)];
        for &(x, y) in &pts {
            let c = arr(&hs.rectangle(r[0], r[1], r[2], r[3], x, y).unwrap());
            for lam in [2f64.powi(500), 2f64.powi(-500)] {
                let g = arr(&hs.rectangle(lam * r[0], lam * r[1], lam * r[2], lam * r[3], lam * x, lam * y).unwrap());
                assert!(c.iter().zip(g).all(|(a, b)| (lam * a).to_bits() == b.to_bits()), "2^k scaling: {c:?} {g:?}");
            }
            for lam in [1e-9, 1e9] {
                let g = arr(&hs.rectangle(lam * r[0], lam * r[1], lam * r[2], lam * r[3], lam * x, lam * y).unwrap());
                let s = c[0].abs().max(c[8].abs());
                assert!(c.iter().zip(g).all(|(a, b)| (lam * a - b).abs() <= 1e-13 * lam * s), "{lam}: {c:?} {g:?}");
            }
        }
        // Across r = 1e8 max(α, β): the closed forms below, the point load times the area above.
        let (al, be) = (0.35, 0.15);
        for th in [0.3, 1.2_f64] {
            let r0 = 1e8 * al;
            // 1e-14 below the switch: the values themselves differ by ~1e-14 relative.
            let (lo, hi) = (
                integrals(r0 * (1.0 - 1e-14) * th.cos(), r0 * (1.0 - 1e-14) * th.sin(), al, be),
                integrals(r0 * th.cos(), r0 * th.sin(), al, be),
            );
            for (a, b) in [(lo.i1, hi.i1), (lo.jxy, hi.jxy), (lo.kx, hi.kx), (lo.ky, hi.ky), (lo.jxx, hi.jxx)] {
                assert!((a - b).abs() <= 1e-13 * hi.i1, "switch to the point load at {th}: {a:e} vs {b:e}");
            }
        }
    }

    /// Every public constructor and function refuses a value outside its documented domain with an error naming the
    /// function and the argument (no panic), and accepts the edges of the domain.
    #[test]
    fn bad_arguments_are_refused() {
        let named = |e: ArgumentError| (e.function, e.argument);
        for (e, nu, arg) in [
            (0.0, 0.3, "e"),
            (-1.0, 0.3, "e"),
            (f64::NAN, 0.3, "e"),
            (1.0, -0.1, "nu"),
            (1.0, 0.51, "nu"),
            (1.0, f64::NAN, "nu"),
        ] {
            assert_eq!(named(HalfSpace::new(e, nu).unwrap_err()), ("HalfSpace::new", arg));
        }
        assert!(HalfSpace::new(f64::INFINITY, 0.0).is_ok() && HalfSpace::new(1e-300, 0.5).is_ok());
        let hs = HalfSpace::new(1.0, 0.3).unwrap();
        let nan = f64::NAN;
        let bad = [
            ([nan, 1.0, 0.0, 1.0, 0.5, 0.5], "x1"),
            ([0.0, 1.0, 0.0, f64::INFINITY, 0.5, 0.5], "y2"),
            ([0.0, 1.0, 0.0, 1.0, nan, 0.5], "x"),
            ([0.0, 1.0, 0.0, 1.0, 0.5, -f64::INFINITY], "y"),
            ([1.0, 1.0, 0.0, 1.0, 0.5, 0.5], "x2"),
            ([1.0, 0.0, 0.0, 1.0, 0.5, 0.5], "x2"),
            ([0.0, 1.0, 0.0, -1.0, 0.5, 0.5], "y2"),
            ([-f64::MAX, f64::MAX, 0.0, 1.0, 0.5, 0.5], "x2"),
        ];
        for (v, arg) in bad {
            assert_eq!(
                named(hs.rectangle(v[0], v[1], v[2], v[3], v[4], v[5]).unwrap_err()),
                ("Compliance::rectangle", arg),
                "{v:?}"
            );
        }
        let c = hs.compliance();
        for (mx, my, dx, dy, arg) in [
            (0, 3, 1.0, 1.0, "mx"),
            (3, 0, 1.0, 1.0, "my"),
            (3, 3, 0.0, 1.0, "dx"),
            (3, 3, 1.0, nan, "dy"),
            (3, 3, f64::INFINITY, 1.0, "dx"),
            (usize::MAX / 2, 4, 1.0, 1.0, "my"),
        ] {
            assert_eq!(named(UniformGrid::new(c, mx, my, dx, dy).unwrap_err()), ("UniformGrid::new", arg));
        }
        let grid = UniformGrid::new(c, 3, 2, 0.1, 0.2).unwrap();
        for (di, dj, arg) in [(3, 0, "di"), (-3, 0, "di"), (0, 2, "dj"), (0, -2, "dj"), (isize::MIN, 0, "di")] {
            assert_eq!(named(grid.kernel(di, dj).unwrap_err()), ("UniformGrid::kernel", arg));
        }
        assert!(grid.kernel(-2, 1).is_ok() && grid.kernel(2, -1).is_ok());
    }
}
